// Monte Carlo casing impacts (issue 11: "dispersion ellipses (99.7 %) ... of stage impact points";
// manual Sec. 17 data block 43; docs/theory/dispersions.md "Monte Carlo"): a sample's casing impact
// is fly_to_impact() from that sample's own burnout state, recomputed here independently; with every
// source at zero each sample's casing lands where the impact locus about the same nominal puts it;
// 1, 2 and 3 threads give the same casing records bit for bit; the shared 99.7 % ellipse holds
// 99.7 % of a bivariate normal. Nominal: the reference mission (tests/reference).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "support/dispersion_sources.hpp"
#include "support/reference_impact.hpp"
#include "support/reference_mission.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip_ground/monte_carlo_report.hpp"
#include "tolip_ground/monte_carlo_run.hpp"

namespace tolip::test {
namespace {

using ground::dispersion_ellipse;
using ground::DispersionEllipse;
using ground::MonteCarloSamples;
using ground::run_monte_carlo;

constexpr double kDeg = kPi / 180.0;

struct Case : ReferenceDispersionCase {
  ImpactLocusData impact;
  MonteCarloImpactRequest request;
};

// The reference scalar sources (weights of stages 1-3 among them: the casing weights move) at
// `scale`, and the casings of stages 1-3.
std::unique_ptr<Case> make_case(double scale) {
  auto c = std::make_unique<Case>();
  make_reference_dispersion_case(scale, {9, 11, 13, 17, 24, 27, 33, 34}, c.get());
  build_reference_impact_data(&c->impact);
  c->request.data = &c->impact;
  for (bool& stage : c->request.stages) stage = true;
  bool stages[kImpactStages] = {true, true, true};
  ImpactFault fault;
  EXPECT_EQ(validate_casing_data(c->mission, c->impact, stages, &fault), Status::kOk) << fault.field;
  return c;
}

// Sample i's casing of every stage against fly_to_impact() called here from the sample's burnout
// point (flown again in a workspace of its own), with the casing weight plus the sample's jettison
// weight increment and the ranges of Sec. 4 from the launch site and the nominal's azimuth.
TEST(MonteCarloImpacts, Sec17SampleCasingImpactIsFlyToImpactFromThatSamplesBurnout) {
  auto c = make_case(1.0);
  MonteCarloSamples mc;
  const int n = 5;
  ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 2026, n, 2, &mc, {}, c->request), Status::kOk);
  ASSERT_EQ(mc.impacts.size(), static_cast<std::size_t>(n));
  auto ws = std::make_unique<DispersionWorkspace>();
  ASSERT_EQ(prepare_monte_carlo(c->nominal, ws.get()), Status::kOk);
  StageData scratch;
  const LaunchConditions& launch = c->mission.launch;
  for (int i = 0; i < n; ++i) {
    DispersedTrajectory record;
    ASSERT_EQ(fly_monte_carlo_sample(c->nominal, c->data, 2026, static_cast<std::uint64_t>(i), mc.nominal,
                                     ws.get(), &record),
              Status::kOk);
    const MonteCarloImpacts& got = mc.impacts[static_cast<std::size_t>(i)];
    ASSERT_EQ(got.status, Status::kOk) << i;
    ASSERT_EQ(got.count, 3);
    for (int stage = 1; stage <= 3; ++stage) {
      const ImpactCase& casing = got.casings[stage - 1];
      ASSERT_EQ(casing.stage, stage);
      const StageEvent* event = nullptr;
      for (int k = 0; k < ws->dispersed.stage_count; ++k) {
        if (ws->dispersed.stages[k].code == stage) event = &ws->dispersed.stages[k];
      }
      ASSERT_NE(event, nullptr);
      const TrajectoryPoint& burnout = ws->dispersed.points[event->last_point];
      const double increment_lb = ws->mission.vehicle.stages[stage_index(stage)].jettison_weight_lb -
                                  c->mission.vehicle.stages[stage_index(stage)].jettison_weight_lb;
      EXPECT_NE(increment_lb, 0.0);  // codes 9, 11, 13 drawn
      const double weight = c->impact.expended_casing[stage - 1].casing_weight_lb + increment_lb;
      ImpactFlight flight;
      ASSERT_EQ(fly_to_impact(ws->mission, ws->prepared, c->impact.expended_casing[stage - 1], weight,
                              burnout.time_s, burnout.state, c->impact.steps, &scratch, &flight),
                Status::kOk);
      const double lambda = flight.impact_state[kStateLambda];
      const double longitude =
          std::remainder(flight.impact_state[kStateTau] -
                             c->mission.constants.earth_rotation_rate_rad_s * flight.impact_time_s,
                         2.0 * kPi);
      EXPECT_EQ(casing.weight_lb, weight);
      EXPECT_EQ(casing.failure_time_s, burnout.time_s);
      EXPECT_EQ(casing.impact_time_s, flight.impact_time_s) << i << " stage " << stage;
      EXPECT_EQ(casing.geocentric_latitude_rad, lambda);
      EXPECT_EQ(casing.geodetic_latitude_rad, geodetic_from_geocentric_rad(c->mission.constants, lambda));
      EXPECT_EQ(casing.longitude_rad, longitude);
      EXPECT_EQ(casing.downrange_rad,
                downrange_angle_rad(launch.geocentric_latitude_rad, launch.longitude_rad, lambda, longitude));
      EXPECT_EQ(casing.crossrange_rad,
                launch_crossrange_angle_rad(launch.geocentric_latitude_rad, launch.longitude_rad,
                                            launch.azimuth_rad, lambda, longitude));
      // Dispersed: not the nominal's impact.
      EXPECT_NE(casing.impact_time_s, mc.nominal_impacts.casings[stage - 1].impact_time_s);
    }
  }
}

// Every source at zero: every sample is the nominal, and each casing lands where the impact locus
// about the same nominal (compute_impact_locus, prepared and flown here) puts that casing.
TEST(MonteCarloImpacts, Sec17ZeroSourcesLandEveryCasingAtTheLocusImpactPoint) {
  auto c = make_case(0.0);
  auto prepared = std::make_unique<PreparedCase>();
  auto nominal = std::make_unique<Trajectory>();
  auto workspace = std::make_unique<ImpactWorkspace>();
  auto locus = std::make_unique<ImpactLocus>();
  ASSERT_EQ(prepare_case(c->mission, prepared.get()), Status::kOk);
  // Flown as the analyses fly their nominal (dispersion_flight_inputs: the same flight numerics).
  ASSERT_EQ(fly_trajectory(c->mission, *prepared, dispersion_flight_inputs(c->nominal), nominal.get()),
            Status::kOk);
  ImpactLocusData full;
  build_reference_impact_data(&full);
  ASSERT_EQ(compute_impact_locus(c->mission, *prepared, *nominal, full, workspace.get(), locus.get()),
            Status::kOk);
  MonteCarloSamples mc;
  ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 7, 4, 1, &mc, {}, c->request), Status::kOk);
  for (int stage = 1; stage <= 3; ++stage) {
    const ImpactCase* expected = nullptr;
    for (int k = 0; k < locus->count; ++k) {
      const ImpactCase& e = locus->cases[k];
      if (e.kind == ImpactKind::kExpendedCasing && e.stage == stage) expected = &e;
    }
    ASSERT_NE(expected, nullptr);
    std::printf("stage %d casing: locus impact %.6f deg, %.6f deg, %.4f n.mi. downrange at %.3f s\n", stage,
                expected->geodetic_latitude_rad / kDeg, expected->longitude_rad / kDeg,
                expected->downrange_rad * kNauticalMilesPerRadian, expected->impact_time_s);
    const ImpactCase& nominal_casing = mc.nominal_impacts.casings[stage - 1];
    EXPECT_EQ(nominal_casing.impact_time_s, expected->impact_time_s);
    EXPECT_EQ(nominal_casing.longitude_rad, expected->longitude_rad);
    for (std::size_t i = 0; i < mc.impacts.size(); ++i) {
      const ImpactCase& got = mc.impacts[i].casings[stage - 1];
      ASSERT_EQ(got.status, Status::kOk);
      EXPECT_EQ(got.weight_lb, expected->weight_lb);
      EXPECT_NEAR(got.impact_time_s, expected->impact_time_s, 1e-9) << i;
      EXPECT_NEAR(got.geodetic_latitude_rad, expected->geodetic_latitude_rad, 1e-12) << i;
      EXPECT_NEAR(got.longitude_rad, expected->longitude_rad, 1e-12) << i;
      EXPECT_NEAR(got.downrange_rad, expected->downrange_rad, 1e-12) << i;
      EXPECT_NEAR(got.crossrange_rad, expected->crossrange_rad, 1e-12) << i;
    }
  }
}

// Which thread flies a sample does not change its casings (counter draws, per-worker workspaces).
TEST(MonteCarloImpacts, OneTwoAndThreeThreadsGiveTheSameCasingImpactsBitForBit) {
  auto c = make_case(1.0);
  MonteCarloSamples runs[3];
  const int n = 9;
  for (int t = 0; t < 3; ++t) {
    ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 31, n, t + 1, &runs[t], {}, c->request), Status::kOk);
  }
  for (int t = 1; t < 3; ++t) {
    for (int i = 0; i < n; ++i) {
      const MonteCarloImpacts& a = runs[0].impacts[static_cast<std::size_t>(i)];
      const MonteCarloImpacts& b = runs[t].impacts[static_cast<std::size_t>(i)];
      ASSERT_EQ(a.count, b.count);
      for (int k = 0; k < a.count; ++k) {
        EXPECT_EQ(a.casings[k].status, b.casings[k].status);
        EXPECT_EQ(a.casings[k].impact_time_s, b.casings[k].impact_time_s) << t + 1 << " threads, " << i;
        EXPECT_EQ(a.casings[k].geodetic_latitude_rad, b.casings[k].geodetic_latitude_rad);
        EXPECT_EQ(a.casings[k].longitude_rad, b.casings[k].longitude_rad);
        EXPECT_EQ(a.casings[k].downrange_rad, b.casings[k].downrange_rad);
        EXPECT_EQ(a.casings[k].crossrange_rad, b.casings[k].crossrange_rad);
        EXPECT_EQ(a.casings[k].steps, b.casings[k].steps);
      }
    }
  }
}

// The one ellipse computation (the burnout point's and the casings'): of 20,000 points of a
// correlated bivariate normal (sigmas 3 and 1 n.mi., correlation 0.6), the 99.7 % ellipse holds
// 99.7 % within 3 binomial standard errors, its axes those of the true covariance.
TEST(MonteCarloImpacts, EllipseHolds99_7PercentOfABivariateNormal) {
  const int n = 20000;
  std::vector<double> x, y;
  const double sx = 3.0, sy = 1.0, rho = 0.6;
  for (int i = 0; i < n; ++i) {
    const double z1 = counter_normal(5, static_cast<std::uint64_t>(i), 1);
    const double z2 = counter_normal(5, static_cast<std::uint64_t>(i), 2);
    x.push_back(10.0 + sx * z1);
    y.push_back(-2.0 + sy * (rho * z1 + std::sqrt(1.0 - rho * rho) * z2));
  }
  const DispersionEllipse e = dispersion_ellipse(x, y);
  std::printf("ellipse of %d normal points: %.5f inside, semi-axes %.4f, %.4f, angle %.3f deg\n", n,
              e.fraction_inside, e.semi_major_nmi, e.semi_minor_nmi, e.major_axis_angle_deg);
  EXPECT_NEAR(e.fraction_inside, 0.997, 3.0 * std::sqrt(0.997 * 0.003 / n));
  // The true covariance [[9, 1.8], [1.8, 1]]: eigenvalues 5 +- sqrt(16 + 3.24), angle atan2(3.6, 8) / 2.
  const double k = std::sqrt(-2.0 * std::log(0.003));
  const double root = std::sqrt(16.0 + 3.24);
  EXPECT_NEAR(e.semi_major_nmi, k * std::sqrt(5.0 + root), 0.02 * k * std::sqrt(5.0 + root));
  EXPECT_NEAR(e.semi_minor_nmi, k * std::sqrt(5.0 - root), 0.02 * k * std::sqrt(5.0 - root));
  EXPECT_NEAR(e.major_axis_angle_deg, 0.5 * std::atan2(3.6, 8.0) / kDeg, 1.0);
  EXPECT_NEAR(e.center_downrange_nmi, 10.0, 3.0 * sx / std::sqrt(n));
  EXPECT_NEAR(e.center_crossrange_nmi, -2.0, 3.0 * sy / std::sqrt(n));
}

}  // namespace
}  // namespace tolip::test
