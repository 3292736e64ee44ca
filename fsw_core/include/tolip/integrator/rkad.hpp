// The RKAD integrator of manual Sec. 19: a fixed step per stage; classical fourth-order
// Runge-Kutta in powered stages; in coasts Runge-Kutta for the first steps, then fourth-order
// Adams-Bashforth dy = (55 f1 - 59 f2 + 37 f3 - 9 f4) dt / 24 with the derivatives at the current
// and three previous points. Each stage restarts with Runge-Kutta.
//
// Templates over the derivative function (a callable (t, y) -> dy/dt), so nothing is allocated.
#pragma once

namespace tolip {

// Number of Runge-Kutta steps a coast takes before switching to Adams-Bashforth.
inline constexpr int kRkadStartSteps = 4;

// One RK4 step from (t, y) with derivative f0 = f(t, y) already evaluated.
template <typename Vector, typename Derivative>
Vector runge_kutta4_step(const Derivative& f, double t, const Vector& y, const Vector& f0, double dt) {
  const double half = 0.5 * dt;
  const Vector k2 = f(t + half, Vector(y + half * f0));
  const Vector k3 = f(t + half, Vector(y + half * k2));
  const Vector k4 = f(t + dt, Vector(y + dt * k3));
  return y + (dt / 6.0) * (f0 + 2.0 * k2 + 2.0 * k3 + k4);
}

// One Adams-Bashforth 4 step: f1 at the current point, f2..f4 one, two, three points back.
template <typename Vector>
Vector adams_bashforth4_step(const Vector& y, const Vector& f1, const Vector& f2, const Vector& f3,
                             const Vector& f4, double dt) {
  return y + (dt / 24.0) * (55.0 * f1 - 59.0 * f2 + 37.0 * f3 - 9.0 * f4);
}

// Derivative history for the Adams steps of one coast: the last four derivatives, newest first.
template <typename Vector>
class DerivativeHistory {
 public:
  DerivativeHistory() { clear(); }
  void clear() {
    for (Vector& f : f_) f.setZero();
    count_ = 0;
  }
  void push(const Vector& f) {
    for (int i = 3; i > 0; --i) f_[i] = f_[i - 1];
    f_[0] = f;
    if (count_ < 4) ++count_;
  }
  bool full() const { return count_ == 4; }
  const Vector& back(int i) const { return f_[i]; }  // 0 = newest

 private:
  Vector f_[4];
  int count_ = 0;
};

}  // namespace tolip
