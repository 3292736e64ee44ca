// Fixed-capacity piecewise-linear table with stored slopes (the manual's LOOK / LOOKUP).
//
// Abscissae strictly increase. Between points the table is linear; outside the first and last
// abscissa it holds the end value (slope zero), which is what a thrust, weight or aerodynamic
// table means past its ends. Slopes are computed once by finalize(), so a look-up is a search
// plus one multiply-add.
#pragma once

#include <cmath>

#include "tolip/core/status.hpp"

namespace tolip {

template <int Capacity>
class Table {
 public:
  static constexpr int kCapacity = Capacity;

  // Appends one point; fails (and leaves the table unchanged) when full or x is not finite.
  Status append(double x, double y) {
    if (count_ >= Capacity) return Status::kTooManyTablePoints;
    if (!std::isfinite(x) || !std::isfinite(y)) return Status::kValueNotFinite;
    x_[count_] = x;
    y_[count_] = y;
    ++count_;
    finalized_ = false;
    return Status::kOk;
  }

  // Checks monotonic abscissae and stores the slopes. Must succeed before the first look-up.
  Status finalize() {
    if (count_ == 0) return Status::kTableEmpty;
    for (int i = 0; i + 1 < count_; ++i) {
      if (!(x_[i + 1] > x_[i])) return Status::kTableNotMonotonic;
      slope_[i] = (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]);
    }
    slope_[count_ - 1] = 0.0;
    finalized_ = true;
    return Status::kOk;
  }

  void clear() {
    count_ = 0;
    finalized_ = false;
  }

  // Linear interpolation; end values held outside the table.
  double operator()(double x) const {
    const int i = interval(x);
    if (i < 0) return y_[0];
    return y_[i] + slope_[i] * (x - x_[i]);
  }

  // The same with a search hint: *hint is the interval of an earlier look-up (any int; -1 at the
  // start). The interval holding x is tried first, then the next one, then the search; *hint
  // becomes the interval used. The interval, and so the value, is the one the plain look-up finds,
  // bit for bit: the hint only spares the search when consecutive look-ups stay close (the
  // integration's stage times and Mach numbers).
  double operator()(double x, int* hint) const {
    const int i = hinted_interval(x, hint);
    if (i < 0) return y_[0];
    return y_[i] + slope_[i] * (x - x_[i]);
  }

  // Value and dy/dx (zero outside the table).
  double value_and_slope(double x, double* slope) const {
    const int i = interval(x);
    if (i < 0) {
      *slope = 0.0;
      return y_[0];
    }
    *slope = slope_[i];
    return y_[i] + slope_[i] * (x - x_[i]);
  }

  int size() const { return count_; }
  bool empty() const { return count_ == 0; }
  bool finalized() const { return finalized_; }
  double x(int i) const { return x_[i]; }
  double y(int i) const { return y_[i]; }
  double first_x() const { return x_[0]; }
  double last_x() const { return x_[count_ - 1]; }
  double last_y() const { return y_[count_ - 1]; }
  void set_y(int i, double y) {
    y_[i] = y;
    finalized_ = false;
  }

 private:
  // Index i of the interval [x_i, x_{i+1}) holding x; the last index when x >= last abscissa;
  // -1 below the first abscissa.
  int interval(double x) const {
    if (x < x_[0]) return -1;
    if (x >= x_[count_ - 1]) return count_ - 1;
    int lo = 0;
    int hi = count_ - 1;  // invariant: x_[lo] <= x < x_[hi]
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      if (x_[mid] <= x) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    return lo;
  }

  int hinted_interval(double x, int* hint) const {
    const int h = *hint;
    if (h >= 0 && h + 1 < count_) {
      if (x_[h] <= x && x < x_[h + 1]) return h;
      if (h + 2 < count_ && x_[h + 1] <= x && x < x_[h + 2]) return *hint = h + 1;
    }
    return *hint = interval(x);
  }

  double x_[Capacity] = {};
  double y_[Capacity] = {};
  double slope_[Capacity] = {};
  int count_ = 0;
  bool finalized_ = false;
};

}  // namespace tolip
