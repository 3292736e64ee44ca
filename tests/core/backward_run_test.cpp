// Sec. 5: adjoint predictions of constraint changes agree with central finite differences of
// forward runs (state perturbations at several times, theta over short windows, payload, the
// spun stage-4 attitude and the coast-8 duration) on the reference mission.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/adjoint_check.hpp"
#include "support/reference_mission.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/orbit/orbit_elements.hpp"

namespace tolip {
namespace {

using test::expect_agreement;
using test::kTerminalCount;
using test::kTerminalNames;
using test::terminal;

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
    ConstraintTerminal terminals[kTerminalCount];
    test::terminal_partials(fx.mission.constants, fx.nominal, terminals);
    EXPECT_EQ(run_backward(fx.mission, fx.prepared, fx.nominal, kTerminalCount, terminals, &fx.backward),
              Status::kOk);
    return &fx;
  }();
  return *f;
}

// Central difference of every terminal quantity for a change flown by `fly(sign, perturbed)`.
template <typename Fly>
void central_difference(const Fly& fly, double out[kTerminalCount]) {
  Fixture& f = fixture();
  test::central_difference(f.mission.constants, fly, &f.perturbed, out);
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
      if (std::fabs(f.nominal.points[i].time_s - t) < std::fabs(f.nominal.points[point].time_s - t))
        point = i;
    }
    for (int i = 0; i < 6; ++i) {
      FlightInputs inputs;
      inputs.program = &f.program;
      inputs.injection_point = point;
      double fd[kTerminalCount], predicted[kTerminalCount];
      central_difference(
          [&](double sign, Trajectory* out) {
            inputs.injection = StateVector::Zero();
            inputs.injection[i] = sign * sizes[i];
            return fly_trajectory(f.mission, f.prepared, inputs, out);
          },
          fd);
      for (int j = 0; j < kTerminalCount; ++j) predicted[j] = f.backward.lambda[point](i, j) * sizes[i];
      char what[64];
      std::snprintf(what, sizeof what, "t=%.2f dX[%d]", f.nominal.points[point].time_s, i);
      expect_agreement(what, predicted, fd);
    }
  }
}

TEST(Sec5Adjoint, ThetaOverShortWindowsMatchesCentralDifferences) {
  Fixture& f = fixture();
  const double windows[][2] = {{5.0, 8.0},   {46.0, 49.0},   {55.0, 58.0},
                               {80.0, 86.0}, {100.0, 104.0}, {125.0, 130.0}};
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
    central_difference(
        [&](double sign, Trajectory* out) {
          changed = f.program;
          for (int i = 0; i < f.nominal.point_count; ++i) {
            const double t = f.nominal.points[i].time_s;
            if (t >= w[0] && t <= w[1]) changed.theta_rad[i] += sign * d_theta;
          }
          return fly_trajectory(f.mission, f.prepared, changed, out);
        },
        fd);
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
  central_difference(
      [&](double sign, Trajectory* out) {
        changed = f.mission;
        changed.vehicle.payload_lb += sign * d_payload;
        return fly_trajectory(changed, f.prepared, f.program, out);
      },
      fd);
  for (int j = 0; j < kTerminalCount; ++j) predicted[j] = f.backward.payload(j) * d_payload;
  expect_agreement("payload 1 lb", predicted, fd);

  const double d_theta4 = 1e-3;
  central_difference(
      [&](double sign, Trajectory* out) {
        changed = f.mission;
        changed.misc.stage4_theta_rad += sign * d_theta4;
        return fly_trajectory(changed, f.prepared, f.program, out);
      },
      fd);
  for (int j = 0; j < kTerminalCount; ++j) predicted[j] = f.backward.spun_theta(j) * d_theta4;
  expect_agreement("stage-4 theta 1 mrad", predicted, fd);

  const double d_coast = 0.5;
  central_difference(
      [&](double sign, Trajectory* out) {
        changed = f.mission;
        changed.vehicle.stages[stage_index(8)].duration_s += sign * d_coast;
        changed_prepared = f.prepared;
        Status s = rebuild_timeline(changed, &changed_prepared);
        if (!ok(s)) return s;
        return fly_trajectory(changed, changed_prepared, f.program, out);
      },
      fd);
  for (int j = 0; j < kTerminalCount; ++j)
    predicted[j] = f.backward.coast_duration[stage_index(8)](j) * d_coast;
  expect_agreement("coast 8 +0.5 s", predicted, fd);
}

}  // namespace
}  // namespace tolip
