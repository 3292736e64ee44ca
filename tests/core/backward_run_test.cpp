// Sec. 5: adjoint predictions of constraint changes agree with central finite differences of
// forward runs (state perturbations at several times, theta over short windows, payload, the
// spun stage-4 attitude and the coast-8 duration) on the reference mission.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>

#include "support/reference_mission.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/orbit/orbit_elements.hpp"

namespace tolip {
namespace {

// The terminal quantities of the reference mission (data block 8 codes 7, 2, 3) and the final
// velocity, flight-path angle and longitude, as functions of the final state.
constexpr int kTerminalCount = 6;
const char* const kTerminalNames[kTerminalCount] = {"altitude", "gamma_I", "V_I - V_circ", "V", "psi", "tau"};

double terminal(const Constants& k, const StateVector& x, int which) {
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

struct Fixture {
  Mission mission;
  PreparedCase prepared;
  ControlProgram program;
  Trajectory nominal;
  Trajectory perturbed;
  BackwardRun backward;
};

Fixture& fixture() {
  static Fixture* f = [] {
    static Fixture fx;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &fx.mission);
    EXPECT_EQ(prepare_case(fx.mission, &fx.prepared), Status::kOk);
    EXPECT_EQ(fly_trajectory(fx.mission, fx.prepared, &fx.nominal), Status::kOk);
    fx.program.point_count = fx.nominal.point_count;
    for (int i = 0; i < fx.nominal.point_count; ++i) fx.program.theta_rad[i] = fx.nominal.points[i].theta_rad;
    // The terminals' partials by central differences of the functions above.
    ConstraintTerminal terminals[kTerminalCount];
    const StateVector xf = fx.nominal.final_point().state;
    const double steps[6] = {1e-3, 1e-8, 1e-2, 1e-8, 1e-8, 1e-8};
    for (int j = 0; j < kTerminalCount; ++j) {
      terminals[j].point = fx.nominal.point_count - 1;
      for (int i = 0; i < 6; ++i) {
        StateVector xp = xf, xm = xf;
        xp[i] += steps[i];
        xm[i] -= steps[i];
        terminals[j].partials[i] =
            (terminal(fx.mission.constants, xp, j) - terminal(fx.mission.constants, xm, j)) / (2.0 * steps[i]);
      }
    }
    EXPECT_EQ(run_backward(fx.mission, fx.prepared, fx.nominal, kTerminalCount, terminals, &fx.backward),
              Status::kOk);
    return &fx;
  }();
  return *f;
}

// Central difference of every terminal quantity for a change applied by `apply(sign)`.
void central_difference(const std::function<Status(double sign, Trajectory*)>& fly, double out[kTerminalCount]) {
  Fixture& f = fixture();
  double plus[kTerminalCount], minus[kTerminalCount];
  ASSERT_EQ(fly(+1.0, &f.perturbed), Status::kOk);
  for (int j = 0; j < kTerminalCount; ++j) plus[j] = terminal(f.mission.constants, f.perturbed.final_point().state, j);
  ASSERT_EQ(fly(-1.0, &f.perturbed), Status::kOk);
  for (int j = 0; j < kTerminalCount; ++j) minus[j] = terminal(f.mission.constants, f.perturbed.final_point().state, j);
  for (int j = 0; j < kTerminalCount; ++j) out[j] = (plus[j] - minus[j]) / 2.0;
}

// |predicted - fd| within 1% of the largest sensitivity magnitude in this family, per quantity.
void expect_agreement(const char* what, const double predicted[kTerminalCount], const double fd[kTerminalCount]) {
  for (int j = 0; j < kTerminalCount; ++j) {
    const double error = std::fabs(predicted[j] - fd[j]);
    std::printf("%-28s %-14s adjoint % .6e  fd % .6e  rel %.1e\n", what, kTerminalNames[j], predicted[j], fd[j],
                error / std::fmax(std::fabs(fd[j]), 1e-300));
    EXPECT_LE(error, 0.01 * std::fabs(fd[j]) + 1e-12) << what << " " << kTerminalNames[j];
  }
}

TEST(Sec5Adjoint, StatePerturbationsAtSeveralTimesMatchCentralDifferences) {
  Fixture& f = fixture();
  // Points in stage 1 (kick, zero-alpha window), coast 6, stage 2, stage 3, coast 8 (RK start and
  // Adams region) and stage 4.
  const double times[] = {8.0, 20.0, 46.25, 60.0, 110.0, 151.1, 400.0, 560.0};
  const double sizes[6] = {0.5, 1e-4, 50.0, 1e-4, 1e-6, 1e-6};
  for (double t : times) {
    int point = 0;
    for (int i = 1; i < f.nominal.point_count; ++i) {
      if (std::fabs(f.nominal.points[i].time_s - t) < std::fabs(f.nominal.points[point].time_s - t)) point = i;
    }
    for (int i = 0; i < 6; ++i) {
      FlightInputs inputs;
      inputs.program = &f.program;
      inputs.injection_point = point;
      double fd[kTerminalCount], predicted[kTerminalCount];
      central_difference([&](double sign, Trajectory* out) {
        inputs.injection = StateVector::Zero();
        inputs.injection[i] = sign * sizes[i];
        return fly_trajectory(f.mission, f.prepared, inputs, out);
      }, fd);
      for (int j = 0; j < kTerminalCount; ++j) predicted[j] = f.backward.lambda[point](i, j) * sizes[i];
      char what[64];
      std::snprintf(what, sizeof what, "t=%.2f dX[%d]", f.nominal.points[point].time_s, i);
      expect_agreement(what, predicted, fd);
    }
  }
}

TEST(Sec5Adjoint, ThetaOverShortWindowsMatchesCentralDifferences) {
  Fixture& f = fixture();
  const double windows[][2] = {{5.0, 8.0}, {46.0, 49.0}, {55.0, 58.0}, {80.0, 86.0}, {100.0, 104.0}, {125.0, 130.0}};
  const double d_theta = 1e-3;  // rad
  for (const auto& w : windows) {
    double predicted[kTerminalCount] = {};
    for (int i = 0; i < f.nominal.point_count; ++i) {
      const double t = f.nominal.points[i].time_s;
      if (t < w[0] || t > w[1]) continue;
      for (int j = 0; j < kTerminalCount; ++j) predicted[j] += f.backward.theta_gradient[i](j) * d_theta;
    }
    static ControlProgram changed;
    double fd[kTerminalCount];
    central_difference([&](double sign, Trajectory* out) {
      changed = f.program;
      for (int i = 0; i < f.nominal.point_count; ++i) {
        const double t = f.nominal.points[i].time_s;
        if (t >= w[0] && t <= w[1]) changed.theta_rad[i] += sign * d_theta;
      }
      return fly_trajectory(f.mission, f.prepared, changed, out);
    }, fd);
    char what[64];
    std::snprintf(what, sizeof what, "theta %.0f-%.0f s", w[0], w[1]);
    expect_agreement(what, predicted, fd);
  }
}

TEST(Sec9Adjoint, PayloadSpunAttitudeAndCoastSensitivitiesMatchCentralDifferences) {
  Fixture& f = fixture();
  static Mission changed;
  static PreparedCase changed_prepared;
  double fd[kTerminalCount], predicted[kTerminalCount];

  // Payload (lb): the thrust tables stay those of the case (Sec. 14 runs once per case).
  const double d_payload = 1.0;
  central_difference([&](double sign, Trajectory* out) {
    changed = f.mission;
    changed.vehicle.payload_lb += sign * d_payload;
    return fly_trajectory(changed, f.prepared, f.program, out);
  }, fd);
  for (int j = 0; j < kTerminalCount; ++j) predicted[j] = f.backward.payload(j) * d_payload;
  expect_agreement("payload 1 lb", predicted, fd);

  const double d_theta4 = 1e-3;
  central_difference([&](double sign, Trajectory* out) {
    changed = f.mission;
    changed.misc.stage4_theta_rad += sign * d_theta4;
    return fly_trajectory(changed, f.prepared, f.program, out);
  }, fd);
  for (int j = 0; j < kTerminalCount; ++j) predicted[j] = f.backward.spun_theta(j) * d_theta4;
  expect_agreement("stage-4 theta 1 mrad", predicted, fd);

  const double d_coast = 0.5;
  central_difference([&](double sign, Trajectory* out) {
    changed = f.mission;
    changed.vehicle.stages[stage_index(8)].duration_s += sign * d_coast;
    changed_prepared = f.prepared;
    Status s = rebuild_timeline(changed, &changed_prepared);
    if (!ok(s)) return s;
    return fly_trajectory(changed, changed_prepared, f.program, out);
  }, fd);
  for (int j = 0; j < kTerminalCount; ++j) predicted[j] = f.backward.coast_duration[stage_index(8)](j) * d_coast;
  expect_agreement("coast 8 +0.5 s", predicted, fd);
}

}  // namespace
}  // namespace tolip
