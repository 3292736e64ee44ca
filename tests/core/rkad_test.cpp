// Sec. 19 RKAD: fourth-order convergence of both the Runge-Kutta and the Adams-Bashforth parts on
// a problem with a closed-form solution, and conservation of energy and angular momentum on a
// coast with the Earth's rotation and J2 set to zero.
#include <gtest/gtest.h>

#include <cmath>

#include "tolip/dynamics/equations_of_motion.hpp"
#include "tolip/integrator/rkad.hpp"

namespace tolip {
namespace {

using Vec1 = Eigen::Matrix<double, 1, 1>;

// y' = y cos t, y(0) = 1 has y = exp(sin t).
Vec1 f(double t, const Vec1& y) { return y * std::cos(t); }

double integrate(double t_end, int steps, bool adams) {
  const double dt = t_end / steps;
  Vec1 y = Vec1::Constant(1.0);
  DerivativeHistory<Vec1> history;
  const auto derivative = [](double t, const Vec1& x) { return f(t, x); };
  for (int i = 0; i < steps; ++i) {
    const double t = i * dt;
    const Vec1 f0 = f(t, y);
    if (!adams || i < kRkadStartSteps) {
      y = runge_kutta4_step(derivative, t, y, f0, dt);
    } else {
      y = adams_bashforth4_step(y, f0, history.back(0), history.back(1), history.back(2), dt);
    }
    history.push(f0);
  }
  return y[0];
}

TEST(Sec19Rkad, RungeKuttaConvergesAtFourthOrder) {
  const double exact = std::exp(std::sin(3.0));
  const double e1 = std::fabs(integrate(3.0, 40, false) - exact);
  const double e2 = std::fabs(integrate(3.0, 80, false) - exact);
  const double order = std::log2(e1 / e2);
  EXPECT_NEAR(order, 4.0, 0.15);
}

TEST(Sec19Rkad, AdamsBashforthAfterRungeKuttaStartConvergesAtFourthOrder) {
  const double exact = std::exp(std::sin(3.0));
  const double e1 = std::fabs(integrate(3.0, 80, true) - exact);
  const double e2 = std::fabs(integrate(3.0, 160, true) - exact);
  const double order = std::log2(e1 / e2);
  EXPECT_NEAR(order, 4.0, 0.2);
  // And it is a genuinely different method from RK4 (the test could not pass by accident).
  EXPECT_GT(std::fabs(integrate(3.0, 80, true) - integrate(3.0, 80, false)), 1e-9);
}

// A coast of the equations of motion with omega = 0 and J2 = 0 is a Kepler orbit: 2E and H are
// invariants. Integrated with RKAD (RK4 start, then Adams-Bashforth) at 10 s steps, as coast 8.
TEST(Sec19Rkad, CoastConservesEnergyAndAngularMomentumWithoutRotationAndJ2) {
  Constants k;
  k.earth_rotation_rate_rad_s = 0.0;
  k.j2 = 0.0;
  StateVector x;
  x << 24000.0, 0.05, 2.13e7, 1.9, 0.5, -1.0;  // an elliptic orbit
  const auto invariants = [&](const StateVector& s, double* energy, double* momentum) {
    *energy = s[0] * s[0] - 2.0 * k.gravitational_parameter_ft3_s2 / s[2];
    *momentum = s[2] * s[0] * std::cos(s[1]);
  };
  double e0, h0;
  invariants(x, &e0, &h0);
  AppliedForces coast;
  coast.mass_slug = 30.0;
  const auto derivative = [&](double, const StateVector& s) { return state_derivative(k, s, coast); };
  DerivativeHistory<StateVector> history;
  const double dt = 10.0;
  for (int i = 0; i < 300; ++i) {  // 3000 s, about half an orbit
    const StateVector f0 = derivative(i * dt, x);
    x = (i < kRkadStartSteps)
            ? runge_kutta4_step(derivative, i * dt, x, f0, dt)
            : adams_bashforth4_step(x, f0, history.back(0), history.back(1), history.back(2), dt);
    history.push(f0);
  }
  double e1, h1;
  invariants(x, &e1, &h1);
  EXPECT_LT(std::fabs(e1 / e0 - 1.0), 1e-7);
  EXPECT_LT(std::fabs(h1 / h0 - 1.0), 1e-7);
  EXPECT_GT(std::fabs(x[1] - 0.05), 0.01);  // the orbit really moved (gamma changed)
}

}  // namespace
}  // namespace tolip
