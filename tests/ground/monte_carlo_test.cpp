// Monte Carlo dispersions (issue 11 "Beyond the manual", in part): the counter-based draws are
// uniform and normal; a sample is the same for 1, 2 and 3 threads (bit for bit, and so the
// statistics); the mean of symmetric sources stays at the nominal; in the linear regime (every
// source at 10 % of the deck's size) the Monte Carlo sigma agrees with the manual's RSS sigma of
// the same sources (Sec. 15 three-sigma / 3). Nominal: the reference mission (tests/reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "support/dispersion_sources.hpp"
#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/core/constants.hpp"
#include "tolip_ground/monte_carlo_run.hpp"

namespace tolip::test {
namespace {

using ground::monte_carlo_statistic;
using ground::MonteCarloSamples;
using ground::MonteCarloStatistic;
using ground::run_monte_carlo;

constexpr double kDeg = kPi / 180.0;
constexpr int kFinal = 3;

TEST(MonteCarlo, CounterDrawsAreUniformAndNormalWhateverTheOrder) {
  const int n = 20000;
  double sum_u = 0.0, sum_z = 0.0, sum_z2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = counter_uniform(7, static_cast<std::uint64_t>(i), 3);
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum_u += u;
    const double z = counter_normal(7, static_cast<std::uint64_t>(i), 5);
    sum_z += z;
    sum_z2 += z * z;
  }
  EXPECT_NEAR(sum_u / n, 0.5, 3.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(sum_z / n, 0.0, 3.0 / std::sqrt(n));
  EXPECT_NEAR(sum_z2 / n, 1.0, 3.0 * std::sqrt(2.0 / n));
  // A draw depends on its counter only: again, backwards, the same bits; another seed or stream differs.
  for (int i = n - 1; i >= n - 10; --i) {
    EXPECT_EQ(counter_normal(7, static_cast<std::uint64_t>(i), 5),
              counter_normal(7, static_cast<std::uint64_t>(i), 5));
    EXPECT_NE(counter_normal(7, static_cast<std::uint64_t>(i), 5),
              counter_normal(8, static_cast<std::uint64_t>(i), 5));
    EXPECT_NE(counter_normal(7, static_cast<std::uint64_t>(i), 5),
              counter_normal(7, static_cast<std::uint64_t>(i), 6));
  }
}

using Case = ReferenceDispersionCase;

// The scalar sources of the reference data (high codes and yaw codes), scaled.
std::unique_ptr<Case> make_case(double scale) {
  auto c = std::make_unique<Case>();
  make_reference_dispersion_case(scale, {9, 11, 13, 15, 17, 24, 26, 27, 29, 30, 32, 33, 34}, c.get());
  return c;
}

TEST(MonteCarlo, OneTwoAndThreeThreadsGiveTheSameSamplesBitForBit) {
  auto c = make_case(1.0);
  MonteCarloSamples runs[3];
  for (int t = 0; t < 3; ++t) {
    ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 2026, 24, t + 1, &runs[t]), Status::kOk);
    ASSERT_EQ(runs[t].samples.size(), 24u);
  }
  for (int t = 1; t < 3; ++t) {
    for (std::size_t i = 0; i < 24; ++i) {
      const DispersedTrajectory& a = runs[0].samples[i];
      const DispersedTrajectory& b = runs[t].samples[i];
      ASSERT_EQ(a.status, Status::kOk) << i;
      EXPECT_EQ(std::memcmp(a.values, b.values, sizeof a.values), 0) << t + 1 << " threads, sample " << i;
      EXPECT_EQ(std::memcmp(a.orbit, b.orbit, sizeof a.orbit), 0) << i;
    }
    const MonteCarloStatistic s0 = monte_carlo_statistic(runs[0], kFinal, StagingVariable::kAltitude);
    const MonteCarloStatistic s1 = monte_carlo_statistic(runs[t], kFinal, StagingVariable::kAltitude);
    EXPECT_EQ(s0.mean, s1.mean);
    EXPECT_EQ(s0.standard_deviation, s1.standard_deviation);
    EXPECT_EQ(s0.p99865, s1.p99865);
  }
  EXPECT_NE(runs[0].samples[0].values[kFinal][0], runs[0].samples[1].values[kFinal][0]);  // samples differ
}

// Linear regime: the Monte Carlo sigma of the burnout altitude and crossrange against the RSS of
// the deterministic dispersions (each the source's three-sigma value: sigma = value / 3); the mean
// within 3 standard errors of the nominal.
TEST(MonteCarlo, SigmaAgreesWithTheRssSigmaInTheLinearRegime) {
  auto c = make_case(0.1);
  auto workspace = std::make_unique<DispersionWorkspace>();
  auto result = std::make_unique<DispersionResult>();
  ASSERT_EQ(run_dispersions(c->nominal, c->data, workspace.get(), result.get()), Status::kOk);
  MonteCarloSamples mc;
  const int n = 400;
  ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 11, n, 2, &mc), Status::kOk);
  for (StagingVariable v : {StagingVariable::kAltitude, StagingVariable::kCrossrange}) {
    double rss = 0.0;
    for (int k = 0; k < result->count; ++k) {
      ASSERT_EQ(result->trajectories[k].status, Status::kOk);
      const double d = result->trajectories[k].dispersions[kFinal][static_cast<int>(v)] / 3.0;
      rss += d * d;
    }
    rss = std::sqrt(rss);
    const MonteCarloStatistic s = monte_carlo_statistic(mc, kFinal, v);
    ASSERT_EQ(s.count, n);
    std::printf("final %s: Monte Carlo sigma %.6g, RSS sigma %.6g, mean %.4g\n",
                v == StagingVariable::kAltitude ? "altitude ft" : "crossrange n.mi.", s.standard_deviation,
                rss, s.mean);
    EXPECT_NEAR(s.standard_deviation / rss, 1.0, 0.15)
        << static_cast<int>(v) << " mc " << s.standard_deviation << " rss " << rss;
    EXPECT_LT(std::fabs(s.mean), 3.0 * s.standard_deviation / std::sqrt(n)) << static_cast<int>(v);
    EXPECT_LT(s.p00135, s.p50);
    EXPECT_LT(s.p50, s.p99865);
  }
}

// The table sources at about 10 % of the reference data's size, built here from the nominal's own
// tables: thrust high of stages 1-4 (thrust x 1.003, every time / 1.003: the same impulse, the
// 3 % of the reference scaled to 0.3 %; stage 1 linear since the block 40 table is read on the
// program clock of a changed burn time, Sec15Dispersions.Stage1ThrustResponseIsLinearForSmallChanges),
// C_M_alpha forward (x 1.02) and the reference winds (high headwind and yaw crosswind) at 10 % of their
// speed. Nominal with body dynamics (C_M_alpha acts through it).
std::unique_ptr<Case> make_table_case() {
  auto c = std::make_unique<Case>();
  build_reference_mission(ReferenceProgram::kOptimum, &c->mission);
  const auto add = [&](int code) -> DispersionSource& { return add_dispersion_source(&c->data, code); };
  for (int stage = 1; stage <= 4; ++stage) {
    DispersionSource& s = add(2 * stage - 1);
    const StageData& n = c->mission.vehicle.stages[stage_index(stage)];
    for (int i = 0; i < n.vacuum_thrust_lbf.size(); ++i) {
      EXPECT_EQ(
          s.vacuum_thrust_lbf.append(n.vacuum_thrust_lbf.x(i) / 1.003, n.vacuum_thrust_lbf.y(i) * 1.003),
          Status::kOk);
      EXPECT_EQ(n.consumable_weight_lb.x(i), n.vacuum_thrust_lbf.x(i));
      EXPECT_EQ(
          s.consumable_weight_lb.append(n.consumable_weight_lb.x(i) / 1.003, n.consumable_weight_lb.y(i)),
          Status::kOk);
    }
    EXPECT_EQ(s.vacuum_thrust_lbf.finalize(), Status::kOk);
    EXPECT_EQ(s.consumable_weight_lb.finalize(), Status::kOk);
  }
  DispersionSource& cm = add(19);
  const AeroTable& cm_n = c->mission.body_dynamics.pitching_moment_per_rad;
  for (int i = 0; i < cm_n.size(); ++i)
    EXPECT_EQ(cm.pitching_moment_per_rad.append(cm_n.x(i), cm_n.y(i) * 1.02), Status::kOk);
  EXPECT_EQ(cm.pitching_moment_per_rad.finalize(), Status::kOk);
  const nlohmann::json& w = scout_reference()["dispersions"]["codes_36_38_winds"];
  const char* keys[] = {"code_36_high_headwind", "code_38_yaw_crosswind"};
  for (int which = 0; which < 2; ++which) {
    DispersionSource& s = add(which == 0 ? 36 : 38);
    for (std::size_t i = 0; i < w["block53_altitude_ft"].size(); ++i) {
      const double h = w["block53_altitude_ft"][i].get<double>();
      EXPECT_EQ(s.wind.speed_ft_s.append(h, 0.1 * w["block53_wind_speed_ft_per_s"][i].get<double>()),
                Status::kOk);
      EXPECT_EQ(s.wind.azimuth_rad.append(
                    h, w["block54_wind_vector_azimuth_deg"][keys[which]][i].get<double>() * kDeg),
                Status::kOk);
    }
    EXPECT_EQ(s.wind.speed_ft_s.finalize(), Status::kOk);
    EXPECT_EQ(s.wind.azimuth_rad.finalize(), Status::kOk);
  }
  c->nominal.mission = &c->mission;  // the block 40 table
  c->nominal.body_dynamics = true;
  return c;
}

// One draw per table source: the burn time is the nominal's plus c times the code's change (c the
// draw / 3), the thrust at the middle of the burn blended alike, the C_M_alpha table likewise,
// and a lone wind profile's speed scaled by |c| (a negative draw reverses the wind vector).
TEST(MonteCarlo, TableSourcesAreBlendedByTheirOneDraw) {
  auto c = make_table_case();
  auto ws = std::make_unique<DispersionWorkspace>();
  ASSERT_EQ(prepare_monte_carlo(c->nominal, ws.get()), Status::kOk);
  for (std::uint64_t sample = 0; sample < 6; ++sample) {
    ASSERT_EQ(build_monte_carlo_case(c->nominal, ws->nominal_prepared, c->data, 99, sample, ws.get()),
              Status::kOk);
    for (int stage = 1; stage <= 4; ++stage) {
      const double draw = counter_normal(99, sample, static_cast<std::uint32_t>(2 * stage - 1)) / 3.0;
      const StageData& n = c->mission.vehicle.stages[stage_index(stage)];
      const StageData& d = ws->mission.vehicle.stages[stage_index(stage)];
      const double bn = n.duration_s;
      const double bs = n.vacuum_thrust_lbf.last_x() / 1.003;
      const double b = bn + draw * (bs - bn);
      EXPECT_NEAR(d.duration_s, b, 1e-12 * b) << stage;
      const double tn = n.vacuum_thrust_lbf(0.5 * bn);
      const double ts =
          n.vacuum_thrust_lbf(0.5 * bn) * 1.003;  // the same normalized time of the code's table
      EXPECT_NEAR(d.vacuum_thrust_lbf(0.5 * b), tn + draw * (ts - tn), 1e-9 * tn) << stage;
      EXPECT_NEAR(d.consumable_weight_lb(0.5 * b), n.consumable_weight_lb(0.5 * bn),
                  1e-9 * n.consumable_weight_lb(0.5 * bn))
          << stage;
    }
    const double draw19 = counter_normal(99, sample, 19u) / 3.0;
    const AeroTable& cm_n = c->mission.body_dynamics.pitching_moment_per_rad;
    const double mach = 0.5 * (cm_n.x(1) + cm_n.x(2));
    EXPECT_NEAR(ws->mission.body_dynamics.pitching_moment_per_rad(mach), cm_n(mach) * (1.0 + 0.02 * draw19),
                1e-12 * std::fabs(cm_n(mach)));
    ASSERT_NE(ws->perturbation.wind, nullptr);
  }
  // A lone wind profile: speed x |c|, azimuth turned by pi for a negative draw.
  DispersionData wind_only;
  wind_only.count = 1;
  wind_only.sources[0] = c->data.sources[6];  // code 38
  ASSERT_EQ(wind_only.sources[0].code, 38);
  int signs = 0;
  for (std::uint64_t sample = 0; sample < 8; ++sample) {
    ASSERT_EQ(build_monte_carlo_case(c->nominal, ws->nominal_prepared, wind_only, 5, sample, ws.get()),
              Status::kOk);
    const double draw = counter_normal(5, sample, 38u) / 3.0;
    const WindProfile& given = wind_only.sources[0].wind;
    const WindProfile& flown = *ws->perturbation.wind;
    for (double h : {3000.0, 42000.0, 120000.0}) {
      EXPECT_DOUBLE_EQ(flown.speed_ft_s(h), std::fabs(draw) * given.speed_ft_s(h));
      EXPECT_DOUBLE_EQ(flown.azimuth_rad(h), given.azimuth_rad(h) + (draw < 0.0 ? kPi : 0.0));
    }
    signs += draw < 0.0 ? 1 : 0;
  }
  EXPECT_GT(signs, 0);
  EXPECT_LT(signs, 8);
}

// Linear regime of the table sources: the Monte Carlo sigma against the RSS of the deterministic
// dispersions of the same tables (each a three-sigma change), the mean within 3 standard errors,
// and 1 and 3 threads bit for bit.
TEST(MonteCarlo, TableSourcesSigmaAgreesWithTheRssSigmaInTheLinearRegime) {
  auto c = make_table_case();
  auto workspace = std::make_unique<DispersionWorkspace>();
  auto result = std::make_unique<DispersionResult>();
  ASSERT_EQ(run_dispersions(c->nominal, c->data, workspace.get(), result.get()), Status::kOk);
  int code_fault = -1;
  ASSERT_EQ(check_monte_carlo_data(c->nominal, c->data, &code_fault), Status::kOk) << code_fault;
  MonteCarloSamples mc;
  const int n = 400;
  ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 17, n, 2, &mc), Status::kOk);
  for (StagingVariable v :
       {StagingVariable::kAltitude, StagingVariable::kVelocity, StagingVariable::kCrossrange}) {
    double rss = 0.0;
    for (int k = 0; k < result->count; ++k) {
      ASSERT_EQ(result->trajectories[k].status, Status::kOk) << result->trajectories[k].code;
      const double d = result->trajectories[k].dispersions[kFinal][static_cast<int>(v)] / 3.0;
      rss += d * d;
    }
    rss = std::sqrt(rss);
    const MonteCarloStatistic s = monte_carlo_statistic(mc, kFinal, v);
    ASSERT_EQ(s.count, n);
    std::printf("tables, final variable %d: Monte Carlo sigma %.6g, RSS sigma %.6g (ratio %.3f), mean %.4g\n",
                static_cast<int>(v), s.standard_deviation, rss, s.standard_deviation / rss, s.mean);
    EXPECT_NEAR(s.standard_deviation / rss, 1.0, 0.15) << static_cast<int>(v);
    EXPECT_LT(std::fabs(s.mean), 3.0 * s.standard_deviation / std::sqrt(n)) << static_cast<int>(v);
  }
  MonteCarloSamples one, three;
  ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 17, 12, 1, &one), Status::kOk);
  ASSERT_EQ(run_monte_carlo(c->nominal, c->data, 17, 12, 3, &three), Status::kOk);
  for (std::size_t i = 0; i < 12; ++i) {
    ASSERT_EQ(one.samples[i].status, Status::kOk);
    EXPECT_EQ(std::memcmp(one.samples[i].values, three.samples[i].values, sizeof one.samples[i].values), 0)
        << i;
    EXPECT_EQ(std::memcmp(one.samples[i].values, mc.samples[i].values, sizeof one.samples[i].values), 0) << i;
  }
}

// The Monte Carlo plan (prepare_monte_carlo with the data, MonteCarloPlan): samples built and
// flown with it are bit for bit those of a workspace without one, every table and weight of the
// case and every recorded value; low partners (a negative draw flies the low table) included. Data
// changed in place and prepared again are planned again; another data object is not flown with
// the plan of the first.
TEST(MonteCarlo, PlannedSamplesEqualUnplannedSamplesBitForBit) {
  auto c = make_table_case();
  // Low partners of the stage 2 thrust and of C_M_alpha: their high tables scaled back.
  DispersionSource& low_thrust = add_dispersion_source(&c->data, 4);
  const StageData& n2 = c->mission.vehicle.stages[stage_index(2)];
  for (int i = 0; i < n2.vacuum_thrust_lbf.size(); ++i) {
    ASSERT_EQ(low_thrust.vacuum_thrust_lbf.append(n2.vacuum_thrust_lbf.x(i) * 1.002,
                                                  n2.vacuum_thrust_lbf.y(i) / 1.002),
              Status::kOk);
    ASSERT_EQ(low_thrust.consumable_weight_lb.append(n2.consumable_weight_lb.x(i) * 1.002,
                                                     n2.consumable_weight_lb.y(i)),
              Status::kOk);
  }
  ASSERT_EQ(low_thrust.vacuum_thrust_lbf.finalize(), Status::kOk);
  ASSERT_EQ(low_thrust.consumable_weight_lb.finalize(), Status::kOk);
  DispersionSource& low_moment = add_dispersion_source(&c->data, 20);
  const AeroTable& cm_n = c->mission.body_dynamics.pitching_moment_per_rad;
  for (int i = 0; i < cm_n.size(); ++i)
    ASSERT_EQ(low_moment.pitching_moment_per_rad.append(cm_n.x(i), cm_n.y(i) * 0.99), Status::kOk);
  ASSERT_EQ(low_moment.pitching_moment_per_rad.finalize(), Status::kOk);
  // add_dispersion_source appends: back into increasing code order.
  std::sort(c->data.sources, c->data.sources + c->data.count,
            [](const DispersionSource& a, const DispersionSource& b) { return a.code < b.code; });
  const auto source_of = [&](int code) -> DispersionSource& {
    int k = 0;
    while (k + 1 < c->data.count && c->data.sources[k].code != code) ++k;
    return c->data.sources[k];
  };
  ASSERT_EQ(source_of(4).code, 4);
  ASSERT_EQ(c->data.sources[c->data.count - 1].code, 38);
  auto planned = std::make_unique<DispersionWorkspace>();
  auto plain = std::make_unique<DispersionWorkspace>();
  ASSERT_EQ(prepare_monte_carlo(c->nominal, c->data, planned.get()), Status::kOk);
  ASSERT_EQ(prepare_monte_carlo(c->nominal, plain.get()), Status::kOk);
  auto nominal_values = std::make_unique<DispersedTrajectory>();
  ASSERT_EQ(record_dispersed_trajectory(c->mission, plain->nominal_prepared, plain->nominal, plain->nominal,
                                        nullptr, nominal_values.get()),
            Status::kOk);
  auto a = std::make_unique<DispersedTrajectory>();
  auto b = std::make_unique<DispersedTrajectory>();
  const auto same_samples = [&](std::uint64_t seed) {
    int low_draws = 0;
    for (std::uint64_t sample = 0; sample < 8; ++sample) {
      SCOPED_TRACE(sample);
      ASSERT_EQ(
          fly_monte_carlo_sample(c->nominal, c->data, seed, sample, *nominal_values, planned.get(), a.get()),
          Status::kOk);
      ASSERT_EQ(
          fly_monte_carlo_sample(c->nominal, c->data, seed, sample, *nominal_values, plain.get(), b.get()),
          Status::kOk);
      EXPECT_EQ(std::memcmp(a->values, b->values, sizeof a->values), 0);
      EXPECT_EQ(std::memcmp(a->orbit, b->orbit, sizeof a->orbit), 0);
      EXPECT_EQ(a->max_qbar_alpha_lbf_rad_ft2, b->max_qbar_alpha_lbf_rad_ft2);
      for (int k = 0; k < kMaxStages; ++k) {
        const StageData& x = planned->mission.vehicle.stages[k];
        const StageData& y = plain->mission.vehicle.stages[k];
        EXPECT_EQ(x.duration_s, y.duration_s) << k;
        ASSERT_EQ(x.vacuum_thrust_lbf.size(), y.vacuum_thrust_lbf.size()) << k;
        for (int i = 0; i < x.vacuum_thrust_lbf.size(); ++i) {
          EXPECT_EQ(x.vacuum_thrust_lbf.x(i), y.vacuum_thrust_lbf.x(i)) << k << " " << i;
          EXPECT_EQ(x.vacuum_thrust_lbf.y(i), y.vacuum_thrust_lbf.y(i)) << k << " " << i;
          EXPECT_EQ(x.consumable_weight_lb.y(i), y.consumable_weight_lb.y(i)) << k << " " << i;
        }
      }
      const AeroTable& x = planned->mission.body_dynamics.pitching_moment_per_rad;
      const AeroTable& y = plain->mission.body_dynamics.pitching_moment_per_rad;
      ASSERT_EQ(x.size(), y.size());
      for (int i = 0; i < x.size(); ++i) EXPECT_EQ(x.y(i), y.y(i)) << i;
      ASSERT_NE(planned->perturbation.wind, nullptr);
      const WindProfile& wx = *planned->perturbation.wind;
      const WindProfile& wy = *plain->perturbation.wind;
      ASSERT_EQ(wx.speed_ft_s.size(), wy.speed_ft_s.size());
      for (int i = 0; i < wx.speed_ft_s.size(); ++i) {
        EXPECT_EQ(wx.speed_ft_s.y(i), wy.speed_ft_s.y(i)) << i;
        EXPECT_EQ(wx.azimuth_rad.y(i), wy.azimuth_rad.y(i)) << i;
      }
      low_draws += counter_normal(seed, sample, 3u) < 0.0 ? 1 : 0;
    }
    EXPECT_GT(low_draws, 0);  // the low partner flew
    EXPECT_LT(low_draws, 8);
  };
  same_samples(99);
  // The low stage-2 table changed in place, planned again.
  ThrustTable& low_table = source_of(4).vacuum_thrust_lbf;
  for (int i = 0; i < low_table.size(); ++i) low_table.set_y(i, low_table.y(i) * 0.999);
  ASSERT_EQ(low_table.finalize(), Status::kOk);
  ASSERT_EQ(prepare_monte_carlo(c->nominal, c->data, planned.get()), Status::kOk);
  same_samples(99);
  // Another data object: its own case, not the plan's.
  DispersionData wind_only;
  wind_only.count = 1;
  wind_only.sources[0] = c->data.sources[c->data.count - 1];  // code 38
  ASSERT_EQ(build_monte_carlo_case(c->nominal, planned->nominal_prepared, wind_only, 5, 1, planned.get()),
            Status::kOk);
  EXPECT_EQ(planned->mission.vehicle.stages[stage_index(2)].duration_s, n2.duration_s);
  EXPECT_EQ(planned->mission.body_dynamics.pitching_moment_per_rad.y(0), cm_n.y(0));
}

// The threads take the next sample not yet flown, so a workspace flies samples in no fixed order:
// a sample must not depend on what its workspace flew before it. Every sample of the table case
// (thrust, C_M_alpha and wind tables edited in the workspace's mission and restored between
// samples) flown by one workspace in a scrambled order equals, bit for bit, the same sample flown
// by a workspace of its own.
TEST(MonteCarlo, ASampleIsTheSameWhateverItsWorkspaceFlewBeforeIt) {
  auto c = make_table_case();
  constexpr std::uint64_t kSeed = 31;
  constexpr int kSamples = 8;
  auto shared = std::make_unique<DispersionWorkspace>();
  ASSERT_EQ(prepare_monte_carlo(c->nominal, c->data, shared.get()), Status::kOk);
  auto nominal_values = std::make_unique<DispersedTrajectory>();
  ASSERT_EQ(record_dispersed_trajectory(c->mission, shared->nominal_prepared, shared->nominal,
                                        shared->nominal, nullptr, nominal_values.get()),
            Status::kOk);
  std::vector<std::unique_ptr<DispersedTrajectory>> alone(kSamples);
  for (int i = 0; i < kSamples; ++i) {
    auto own = std::make_unique<DispersionWorkspace>();
    ASSERT_EQ(prepare_monte_carlo(c->nominal, c->data, own.get()), Status::kOk);
    alone[i] = std::make_unique<DispersedTrajectory>();
    ASSERT_EQ(fly_monte_carlo_sample(c->nominal, c->data, kSeed, static_cast<std::uint64_t>(i),
                                     *nominal_values, own.get(), alone[i].get()),
              Status::kOk)
        << i;
  }
  auto flown = std::make_unique<DispersedTrajectory>();
  int differing_neighbours = 0;
  const int order[kSamples] = {7, 0, 5, 2, 6, 1, 4, 3};
  for (int k = 0; k < kSamples; ++k) {
    const int i = order[k];
    ASSERT_EQ(fly_monte_carlo_sample(c->nominal, c->data, kSeed, static_cast<std::uint64_t>(i),
                                     *nominal_values, shared.get(), flown.get()),
              Status::kOk)
        << i;
    const DispersedTrajectory& a = *alone[i];
    EXPECT_EQ(std::memcmp(a.values, flown->values, sizeof a.values), 0) << "sample " << i;
    EXPECT_EQ(std::memcmp(a.orbit, flown->orbit, sizeof a.orbit), 0) << "sample " << i;
    EXPECT_EQ(a.max_qbar_alpha_lbf_rad_ft2, flown->max_qbar_alpha_lbf_rad_ft2) << "sample " << i;
    if (k > 0) {
      const DispersedTrajectory& before = *alone[order[k - 1]];
      differing_neighbours += (before.values[kFinal][0] != a.values[kFinal][0]) ? 1 : 0;
    }
  }
  EXPECT_EQ(differing_neighbours, kSamples - 1);  // every sample followed one that flew otherwise
}

}  // namespace
}  // namespace tolip::test
