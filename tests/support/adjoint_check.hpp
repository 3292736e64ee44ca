// Checks of the adjoint (manual Sec. 5, 9) against central finite differences of forward runs,
// shared by the backward-run tests: six terminal quantities of the final state (the reference's
// constraints altitude, gamma_I, V_I - V_circ, and V, psi, tau), their partials for the backward
// run, the central difference of a change, the agreement rule, and the checks built on them (state
// injections at a point, pitch changes over chosen points, a payload change).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

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

// A case flown with a per-point pitch program and the backward run of the terminal quantities
// along that flight: what the checks below read. `perturbed` holds each changed flight.
struct AdjointCase {
  Mission mission;
  PreparedCase prepared;
  ControlProgram program;
  Trajectory nominal;
  Trajectory perturbed;
  BackwardRun backward;
};

// Prepares and flies the case with its data block 40 table, takes the flight's per-point pitch
// values as its program and runs the backward run of the terminal quantities along it.
inline void fly_nominal_and_run_backward(AdjointCase* c) {
  EXPECT_EQ(prepare_case(c->mission, &c->prepared), Status::kOk);
  EXPECT_EQ(fly_trajectory(c->mission, c->prepared, &c->nominal), Status::kOk);
  c->program.point_count = c->nominal.point_count;
  for (int i = 0; i < c->nominal.point_count; ++i) c->program.theta_rad[i] = c->nominal.points[i].theta_rad;
  ConstraintTerminal terminals[kTerminalCount];
  terminal_partials(c->mission.constants, c->nominal, terminals);
  EXPECT_EQ(run_backward(c->mission, c->prepared, c->nominal, kTerminalCount, terminals, &c->backward),
            Status::kOk);
}

// Central difference of every terminal quantity for a change of the case flown by
// `fly(sign, perturbed)`.
template <typename Fly>
void central_difference(AdjointCase* c, const Fly& fly, double out[kTerminalCount]) {
  central_difference(c->mission.constants, fly, &c->perturbed, out);
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

// One change of each state component (V ft/s, gamma rad, r ft, psi rad, lambda rad, tau rad):
// large enough to stand above the forward runs' round-off, small enough to stay linear.
inline constexpr double kStateInjectionSizes[6] = {0.5, 1e-4, 50.0, 1e-4, 1e-6, 1e-6};

// The adjoint at `point` against central differences for each state component injected there;
// `label` names the point in the printout and the messages ("<label> dX[i]").
inline void expect_state_injections_match(AdjointCase* c, int point, const char* label) {
  for (int i = 0; i < 6; ++i) {
    FlightInputs inputs;
    inputs.program = &c->program;
    inputs.injection_point = point;
    double fd[kTerminalCount], predicted[kTerminalCount];
    central_difference(
        c,
        [&](double sign, Trajectory* out) {
          inputs.injection = StateVector::Zero();
          inputs.injection[i] = sign * kStateInjectionSizes[i];
          return fly_trajectory(c->mission, c->prepared, inputs, out);
        },
        fd);
    for (int j = 0; j < kTerminalCount; ++j)
      predicted[j] = c->backward.lambda[point](i, j) * kStateInjectionSizes[i];
    char what[80];
    std::snprintf(what, sizeof what, "%s dX[%d]", label, i);
    expect_agreement(what, predicted, fd);
  }
}

// The summed pitch gradient against central differences for theta moved by `d_theta_rad` at every
// point `moved(i)` selects; the differences are left in `fd` for the caller's own checks.
template <typename Moved>
void expect_theta_change_matches(AdjointCase* c, const Moved& moved, double d_theta_rad, const char* what,
                                 double fd[kTerminalCount]) {
  double predicted[kTerminalCount] = {};
  for (int i = 0; i < c->nominal.point_count; ++i) {
    if (!moved(i)) continue;
    for (int j = 0; j < kTerminalCount; ++j) predicted[j] += c->backward.theta_gradient[i](j) * d_theta_rad;
  }
  static ControlProgram changed;  // static: a program is too large for the test's stack
  central_difference(
      c,
      [&](double sign, Trajectory* out) {
        changed = c->program;
        for (int i = 0; i < c->nominal.point_count; ++i) {
          if (moved(i)) changed.theta_rad[i] += sign * d_theta_rad;
        }
        return fly_trajectory(c->mission, c->prepared, changed, out);
      },
      fd);
  expect_agreement(what, predicted, fd);
}

// The payload sensitivity against central differences for a payload change of `d_payload_lb`; the
// thrust tables stay those of the case (Sec. 14 runs once per case).
inline void expect_payload_change_matches(AdjointCase* c, double d_payload_lb, const char* what) {
  static Mission heavier;  // static: a mission is too large for the test's stack
  double fd[kTerminalCount], predicted[kTerminalCount];
  central_difference(
      c,
      [&](double sign, Trajectory* out) {
        heavier = c->mission;
        heavier.vehicle.payload_lb += sign * d_payload_lb;
        return fly_trajectory(heavier, c->prepared, c->program, out);
      },
      fd);
  for (int j = 0; j < kTerminalCount; ++j) predicted[j] = c->backward.payload(j) * d_payload_lb;
  expect_agreement(what, predicted, fd);
}

}  // namespace tolip::test
