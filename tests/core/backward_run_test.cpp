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

using test::central_difference;
using test::expect_agreement;
using test::kTerminalCount;

// The reference optimum flown with its own per-point program, and its backward run.
test::AdjointCase& fixture() {
  static test::AdjointCase* f = [] {
    static test::AdjointCase c;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &c.mission);
    test::fly_nominal_and_run_backward(&c);
    return &c;
  }();
  return *f;
}

TEST(Sec5Adjoint, StatePerturbationsAtSeveralTimesMatchCentralDifferences) {
  test::AdjointCase& f = fixture();
  // Points in stage 1 (kick, zero-alpha window), coast 6, stage 2, stage 3, coast 8 (RK start and
  // Adams region) and stage 4.
  const double times[] = {8.0, 20.0, 46.25, 60.0, 110.0, 151.1, 400.0, 560.0};
  for (double t : times) {
    int point = 0;
    for (int i = 1; i < f.nominal.point_count; ++i) {
      if (std::fabs(f.nominal.points[i].time_s - t) < std::fabs(f.nominal.points[point].time_s - t))
        point = i;
    }
    char label[32];
    std::snprintf(label, sizeof label, "t=%.2f", f.nominal.points[point].time_s);
    test::expect_state_injections_match(&f, point, label);
  }
}

TEST(Sec5Adjoint, ThetaOverShortWindowsMatchesCentralDifferences) {
  test::AdjointCase& f = fixture();
  const double windows[][2] = {{5.0, 8.0},   {46.0, 49.0},   {55.0, 58.0},
                               {80.0, 86.0}, {100.0, 104.0}, {125.0, 130.0}};
  const double d_theta = 1e-3;  // rad
  for (const auto& w : windows) {
    const auto inside = [&](int i) {
      const double t = f.nominal.points[i].time_s;
      return t >= w[0] && t <= w[1];
    };
    char what[64];
    std::snprintf(what, sizeof what, "theta %.0f-%.0f s", w[0], w[1]);
    double fd[kTerminalCount];
    test::expect_theta_change_matches(&f, inside, d_theta, what, fd);
  }
}

TEST(Sec9Adjoint, PayloadSpunAttitudeAndCoastSensitivitiesMatchCentralDifferences) {
  test::AdjointCase& f = fixture();
  static Mission changed;
  static PreparedCase changed_prepared;
  double fd[kTerminalCount], predicted[kTerminalCount];

  // Payload (lb): the thrust tables stay those of the case (Sec. 14 runs once per case).
  test::expect_payload_change_matches(&f, 1.0, "payload 1 lb");

  const double d_theta4 = 1e-3;
  central_difference(
      &f,
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
      &f,
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
