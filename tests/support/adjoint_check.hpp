// Checks of the adjoint (manual Sec. 5, 9) against central finite differences of forward runs,
// shared by the backward-run tests: six terminal quantities of the final state (the reference's
// constraints altitude, gamma_I, V_I - V_circ, and V, psi, tau), their partials for the backward
// run, the central difference of a change, and the agreement rule.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip::test {

inline constexpr int kTerminalCount = 6;
inline const char* const kTerminalNames[kTerminalCount] = {"altitude", "gamma_I", "V_I - V_circ",
                                                           "V",        "psi",     "tau"};

inline double terminal(const Constants& k, const StateVector& x, int which) {
  const InertialVelocity iv = inertial_velocity(k, x);
  switch (which) {
    case 0: return x[kStateR] - oblate_radius_ft(k, x[kStateLambda]);
    case 1: return iv.flight_path_angle_rad;
    case 2: return iv.velocity_ft_s - std::sqrt(k.gravitational_parameter_ft3_s2 / x[kStateR]);
    case 3: return x[kStateV];
    case 4: return x[kStatePsi];
    default: return x[kStateTau];
  }
}

// The final-state partials of the terminal quantities, by central differences.
inline void terminal_partials(const Constants& k, const Trajectory& t,
                              ConstraintTerminal terminals[kTerminalCount]) {
  const StateVector xf = t.final_point().state;
  const double steps[6] = {1e-3, 1e-8, 1e-2, 1e-8, 1e-8, 1e-8};
  for (int j = 0; j < kTerminalCount; ++j) {
    terminals[j].point = t.point_count - 1;
    for (int i = 0; i < 6; ++i) {
      StateVector xp = xf, xm = xf;
      xp[i] += steps[i];
      xm[i] -= steps[i];
      terminals[j].partials[i] = (terminal(k, xp, j) - terminal(k, xm, j)) / (2.0 * steps[i]);
    }
  }
}

// Central difference of every terminal quantity for a change flown by `fly(sign, perturbed)`.
template <typename Fly>
void central_difference(const Constants& k, const Fly& fly, Trajectory* perturbed,
                        double out[kTerminalCount]) {
  double plus[kTerminalCount], minus[kTerminalCount];
  ASSERT_EQ(fly(+1.0, perturbed), Status::kOk);
  for (int j = 0; j < kTerminalCount; ++j) plus[j] = terminal(k, perturbed->final_point().state, j);
  ASSERT_EQ(fly(-1.0, perturbed), Status::kOk);
  for (int j = 0; j < kTerminalCount; ++j) minus[j] = terminal(k, perturbed->final_point().state, j);
  for (int j = 0; j < kTerminalCount; ++j) out[j] = (plus[j] - minus[j]) / 2.0;
}

// |predicted - fd| within 1% of |fd| per quantity, with each pair printed.
inline void expect_agreement(const char* what, const double predicted[kTerminalCount],
                             const double fd[kTerminalCount]) {
  for (int j = 0; j < kTerminalCount; ++j) {
    const double error = std::fabs(predicted[j] - fd[j]);
    std::printf("%-30s %-14s adjoint % .6e  fd % .6e  rel %.1e\n", what, kTerminalNames[j], predicted[j],
                fd[j], error / std::fmax(std::fabs(fd[j]), 1e-300));
    EXPECT_LE(error, 0.01 * std::fabs(fd[j]) + 1e-12) << what << " " << kTerminalNames[j];
  }
}

}  // namespace tolip::test
