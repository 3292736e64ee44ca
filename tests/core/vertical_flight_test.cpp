// Near-vertical flight after the closed-form lift-off (Sec. 4 equations G, H; issue 10 part 2):
// the regular coordinates of tolip/dynamics/vertical_flight.hpp, the trajectory's near-vertical
// steps against a fine integration of an independent inertial model, and their adjoint against
// central differences. The mission is the reference flown as a heritage deck, without this
// project's heading hold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "support/adjoint_check.hpp"
#include "support/cartesian_model.hpp"
#include "support/reference_mission.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/dynamics/equations_of_motion.hpp"
#include "tolip/dynamics/vertical_flight.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

StateVector random_state(std::mt19937& rng, double max_angle_from_vertical_rad) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  StateVector x;
  x << 200.0 + 5000.0 * (1.0 + u(rng)), (0.5 * kPi) - max_angle_from_vertical_rad * (1.0 + u(rng)) / 2.0,
      2.09e7 + 1e5 * (1.0 + u(rng)), 3.0 * u(rng), 1.2 * u(rng), 3.0 * u(rng);
  return x;
}

TEST(Sec4VerticalFlight, CoordinatesRoundTripAndTheirJacobiansAreInverseAndExact) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const StateVector x = random_state(rng, 0.09);
    const StateVector back = from_vertical_coordinates(to_vertical_coordinates(x), x[kStatePsi] + 0.3);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(back[i], x[i], 1e-9 * (1.0 + std::fabs(x[i]))) << i;
    const Eigen::Matrix<double, 6, 6> j = vertical_jacobian(x);
    const Eigen::Matrix<double, 6, 6> inverse = state_jacobian_from_vertical(x);
    EXPECT_LT((j * inverse - Eigen::Matrix<double, 6, 6>::Identity()).cwiseAbs().maxCoeff(), 1e-9);
    // Each column against a central difference of the conversion.
    const double steps[6] = {1e-3, 1e-7, 1.0, 1e-7, 1e-7, 1e-7};
    for (int c = 0; c < 6; ++c) {
      StateVector xp = x, xm = x;
      xp[c] += steps[c];
      xm[c] -= steps[c];
      const StateVector fd = (to_vertical_coordinates(xp) - to_vertical_coordinates(xm)) / (2.0 * steps[c]);
      for (int r = 0; r < 6; ++r)
        EXPECT_NEAR(j(r, c), fd[r], 1e-6 * (1.0 + std::fabs(fd[r]))) << r << "," << c;
    }
  }
}

// At gamma = 90 deg exactly the printed H is ~1e12 rad/s; the regular derivative is the limit of
// its values as gamma approaches the vertical (continuity across the singular point).
TEST(Sec4VerticalFlight, RegularDerivativeIsContinuousAtTheVertical) {
  const Constants k;
  AppliedForces forces;
  forces.mass_slug = 1200.0;
  forces.thrust_local_lbf = Vector3(0.0, 120000.0, 2000.0);
  forces.drag_lbf = 30.0;
  StateVector x;
  x << 170.0, (0.5 * kPi), 2.09e7, 100.0 * kDegToRad, 0.657, 0.0;
  const StateVector at_vertical = vertical_derivative(x, state_derivative(k, x, forces));
  EXPECT_GT(std::fabs(state_derivative(k, x, forces)[kStatePsi]), 1e8);  // the singular H
  for (double offset : {1e-4, 1e-6, 1e-8}) {
    StateVector near = x;
    near[kStateGamma] -= offset;
    const StateVector d = vertical_derivative(near, state_derivative(k, near, forces));
    for (int i : {kVerticalUp, kVerticalNorth, kVerticalEast}) {
      // Linear convergence: the local frame turns with gamma, so d moves by about T/m per rad.
      EXPECT_NEAR(d[i], at_vertical[i], 200.0 * offset) << "component " << i << " offset " << offset;
    }
  }
}

using HeritageFlight = test::AdjointCase;

// The reference optimum flown without the heading hold (a heritage deck).
HeritageFlight& heritage_flight() {
  static HeritageFlight* flight = [] {
    static HeritageFlight f;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &f.mission);
    f.mission.launch.heading_hold_until_s = 0.0;
    EXPECT_EQ(prepare_case(f.mission, &f.prepared), Status::kOk);
    EXPECT_EQ(fly_trajectory(f.mission, f.prepared, &f.nominal), Status::kOk);
    f.program.point_count = f.nominal.point_count;
    for (int i = 0; i < f.nominal.point_count; ++i) f.program.theta_rad[i] = f.nominal.points[i].theta_rad;
    return &f;
  }();
  return *flight;
}

// The near-vertical steps from the end of the lift-off, flown with the case's 1 s steps in the
// regular coordinates, against the same forces integrated in the independent inertial model with
// 1 ms Runge-Kutta steps. Before issue 10 the first step left psi at -1.7e14 deg; the heading hold
// (the reference oracle's remedy) is off the same truth by degrees, the regular steps by
// hundredths of one. Measured (t = 4, 5, 6 s): psi 0.094, 0.025, 0.011 deg; gamma 3.7e-3 deg at
// most; V 1.5e-3 ft/s; the hold's psi 2.7, 1.3, 0.6 deg. (Elsewhere the 1 s steps agree with the
// same truth to about 1e-5 deg in gamma and 1e-2 ft/s in V.)
TEST(Sec4VerticalFlight, StepsFromTheLiftOffMatchAFineInertialIntegration) {
  const HeritageFlight& f = heritage_flight();
  const Constants& k = f.mission.constants;
  int first = -1, last = -1;
  for (int s = 0; s < f.nominal.step_count; ++s) {
    if (!f.nominal.steps[s].command.vertical_flight) continue;
    if (first < 0) first = s;
    last = s;
  }
  ASSERT_GE(first, 0) << "no near-vertical step";
  EXPECT_EQ(f.nominal.points[f.nominal.steps[first].point].time_s, f.mission.launch.liftoff_duration_s);
  ASSERT_GE(last - first, 2);
  // The same program flown with the heading hold of the reference deck (5 s).
  static Trajectory held;
  Mission with_hold = f.mission;
  with_hold.launch.heading_hold_until_s = 5.0;
  ASSERT_EQ(fly_trajectory(with_hold, f.prepared, f.program, &held), Status::kOk);

  const StageContext stage = make_stage_context(f.mission, f.prepared, f.prepared.timeline[0]);
  test::Cartesian c = test::to_cartesian(k, f.nominal.points[f.nominal.steps[first].point].state);
  double heading = f.nominal.points[f.nominal.steps[first].point].state[kStatePsi];
  const auto acceleration = [&](const StepCommand& command, double t, const test::Cartesian& at) {
    StateVector x = test::from_cartesian(k, at);
    if (!(std::fabs(std::cos(x[kStateGamma])) > 1e-12)) x[kStatePsi] = heading;  // undefined heading
    Evaluation e;
    evaluate_flight(f.mission, f.prepared, stage, command, t, x, 0.0, &e);
    const Vector3 local(e.net_thrust_lbf * e.thrust_axis_local.x(),
                        e.net_thrust_lbf * e.thrust_axis_local.y() - e.drag_lbf,
                        e.net_thrust_lbf * e.thrust_axis_local.z() + e.lift_lbf);
    const double mass_slug = e.weight_lb / f.mission.constants.g0_ft_s2;
    return Vector3(test::j2_acceleration(k, at.r) + inertial_to_local(x).transpose() * local / mass_slug);
  };
  for (int s = first; s <= last; ++s) {
    const StepRecord& step = f.nominal.steps[s];
    const int substeps = 1000;
    const double h = step.command.step_s / substeps;
    for (int i = 0; i < substeps; ++i) {
      const double t = step.command.step_start_s + i * h;
      const auto deriv = [&](double time, const test::Cartesian& at) {
        return test::Cartesian{at.v, acceleration(step.command, time, at)};
      };
      const test::Cartesian k1 = deriv(t, c);
      const test::Cartesian k2 = deriv(t + h / 2, {c.r + h / 2 * k1.r, c.v + h / 2 * k1.v});
      const test::Cartesian k3 = deriv(t + h / 2, {c.r + h / 2 * k2.r, c.v + h / 2 * k2.v});
      const test::Cartesian k4 = deriv(t + h, {c.r + h * k3.r, c.v + h * k3.v});
      c.r += h / 6 * (k1.r + 2 * k2.r + 2 * k3.r + k4.r);
      c.v += h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
    }
    const StateVector truth = test::from_cartesian(k, c);
    const StateVector& flown = f.nominal.points[step.point + 1].state;
    const StateVector& with_hold_flown = held.points[step.point + 1].state;
    heading = flown[kStatePsi];
    const double psi_error = std::fabs(std::remainder(flown[kStatePsi] - truth[kStatePsi], 2 * kPi));
    const double hold_psi_error =
        std::fabs(std::remainder(with_hold_flown[kStatePsi] - truth[kStatePsi], 2 * kPi));
    std::printf("t=%5.1f  V %.6f/%.6f ft/s  gamma %.6f/%.6f deg  psi %.4f/%.4f deg (held %.4f)\n",
                step.command.step_start_s + step.command.step_s, flown[kStateV], truth[kStateV],
                flown[kStateGamma] * kRadToDeg, truth[kStateGamma] * kRadToDeg, flown[kStatePsi] * kRadToDeg,
                truth[kStatePsi] * kRadToDeg, with_hold_flown[kStatePsi] * kRadToDeg);
    EXPECT_NEAR(flown[kStateV], truth[kStateV], 3e-3);
    EXPECT_NEAR(flown[kStateGamma], truth[kStateGamma], 1e-4);
    EXPECT_NEAR(flown[kStateR], truth[kStateR], 5e-3);
    EXPECT_LT(psi_error, 2e-3);
    EXPECT_LT(psi_error, 0.1 * hold_psi_error);
  }
}

// The discrete adjoint of the near-vertical steps: theta changes over windows that start at the
// lift-off's end, and state injections at the first points after it, against central differences.
TEST(Sec5Adjoint, NearVerticalStepsWithoutTheHoldMatchCentralDifferences) {
  HeritageFlight& f = heritage_flight();
  const Constants& k = f.mission.constants;
  const auto terminal = [&](const Trajectory& t, int which) {
    const StateVector& x = t.final_point().state;
    const InertialVelocity iv = inertial_velocity(k, x);
    return which == 0   ? x[kStateR] - oblate_radius_ft(k, x[kStateLambda])
           : which == 1 ? iv.flight_path_angle_rad
                        : iv.velocity_ft_s;
  };
  ConstraintTerminal terminals[3];
  const StateVector xf = f.nominal.final_point().state;
  const double steps[6] = {1e-3, 1e-8, 1e-2, 1e-8, 1e-8, 1e-8};
  for (int j = 0; j < 3; ++j) {
    terminals[j].point = f.nominal.point_count - 1;
    for (int i = 0; i < 6; ++i) {
      StateVector xp = xf, xm = xf;
      xp[i] += steps[i];
      xm[i] -= steps[i];
      Trajectory& t = f.perturbed;
      t.point_count = 1;
      t.points[0].state = xp;
      const double plus = terminal(t, j);
      t.points[0].state = xm;
      terminals[j].partials[i] = (plus - terminal(t, j)) / (2.0 * steps[i]);
    }
  }
  ASSERT_EQ(run_backward(f.mission, f.prepared, f.nominal, 3, terminals, &f.backward), Status::kOk);

  const auto check = [&](const char* what, const double predicted[3], const auto& fly) {
    double fd[3];
    ASSERT_EQ(fly(+1.0), Status::kOk);
    double plus[3];
    for (int j = 0; j < 3; ++j) plus[j] = terminal(f.perturbed, j);
    ASSERT_EQ(fly(-1.0), Status::kOk);
    for (int j = 0; j < 3; ++j) fd[j] = (plus[j] - terminal(f.perturbed, j)) / 2.0;
    for (int j = 0; j < 3; ++j) {
      std::printf("%-24s terminal %d  adjoint % .6e  fd % .6e\n", what, j, predicted[j], fd[j]);
      EXPECT_LE(std::fabs(predicted[j] - fd[j]), 1e-3 * std::fabs(fd[j]) + 1e-12)
          << what << " terminal " << j;
    }
  };

  const double windows[][2] = {{3.0, 4.0}, {3.0, 6.0}, {5.0, 8.0}};
  // Small: near the vertical the response to theta is already nonlinear at 1e-3 rad (1% at 3-4 s).
  const double d_theta = 1e-4;
  for (const auto& w : windows) {
    double predicted[3] = {};
    for (int i = 0; i < f.nominal.point_count; ++i) {
      const double t = f.nominal.points[i].time_s;
      if (t < w[0] - 1e-9 || t > w[1] + 1e-9 || i == 0) continue;
      for (int j = 0; j < 3; ++j) predicted[j] += f.backward.theta_gradient[i](j) * d_theta;
    }
    static ControlProgram changed;
    char what[48];
    std::snprintf(what, sizeof what, "theta %.0f-%.0f s", w[0], w[1]);
    check(what, predicted, [&](double sign) {
      changed = f.program;
      for (int i = 1; i < f.nominal.point_count; ++i) {
        const double t = f.nominal.points[i].time_s;
        if (t >= w[0] - 1e-9 && t <= w[1] + 1e-9) changed.theta_rad[i] += sign * d_theta;
      }
      return fly_trajectory(f.mission, f.prepared, changed, &f.perturbed);
    });
  }

  // State injections at the points 4 and 5 s after launch (inside and after the near-vertical steps).
  const double* const sizes = test::kStateInjectionSizes;
  for (double time : {4.0, 5.0}) {
    int point = 0;
    while (point < f.nominal.point_count && std::fabs(f.nominal.points[point].time_s - time) > 1e-9) ++point;
    ASSERT_LT(point, f.nominal.point_count);
    for (int i = 0; i < 6; ++i) {
      double predicted[3];
      for (int j = 0; j < 3; ++j) predicted[j] = f.backward.lambda[point](i, j) * sizes[i];
      char what[48];
      std::snprintf(what, sizeof what, "t=%.0f dX[%d]", time, i);
      check(what, predicted, [&](double sign) {
        FlightInputs inputs;
        inputs.program = &f.program;
        inputs.injection_point = point;
        inputs.injection = StateVector::Zero();
        inputs.injection[i] = sign * sizes[i];
        return fly_trajectory(f.mission, f.prepared, inputs, &f.perturbed);
      });
    }
  }
}

}  // namespace
}  // namespace tolip
