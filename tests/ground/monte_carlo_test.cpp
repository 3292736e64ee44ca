// Monte Carlo dispersions (issue 11 "Beyond the manual", in part): the counter-based draws are
// uniform and normal; a sample is the same for 1, 2 and 3 threads (bit for bit, and so the
// statistics); the mean of symmetric sources stays at the nominal; in the linear regime (every
// source at 10 % of the deck's size) the Monte Carlo sigma agrees with the manual's RSS sigma of
// the same sources (Sec. 15 three-sigma / 3). Nominal: the reference mission (tests/reference).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

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

struct Case {
  Mission mission;
  DispersionData data;
  DispersionNominal nominal;
};

// The scalar sources of the reference data (high codes and yaw codes), scaled.
std::unique_ptr<Case> make_case(double scale) {
  auto c = std::make_unique<Case>();
  build_reference_mission(ReferenceProgram::kOptimum, &c->mission);
  const auto add = [&](int code) -> DispersionSource& {
    DispersionSource& s = c->data.sources[c->data.count++];
    s = DispersionSource{};
    s.code = code;
    DispersionCodeInfo info;
    EXPECT_TRUE(dispersion_code_info(code, &info));
    s.stage = info.stage;
    return s;
  };
  add(9).weight_increment_lb = 150.0 * scale;
  add(11).weight_increment_lb = 50.0 * scale;
  add(13).weight_increment_lb = 15.0 * scale;
  add(15).weight_increment_lb = 5.0 * scale;
  add(17).drag_variation_fraction = 0.1 * scale;
  add(24).deadband_rad = 0.5 * kDeg * scale;
  add(26).deadband_rad = 0.5 * kDeg * scale;
  add(27).deadband_rad = 0.5 * kDeg * scale;
  add(29).deadband_rad = 0.5 * kDeg * scale;
  DispersionSource& tipoff = add(30);
  tipoff.stage = 4;
  tipoff.tipoff_rad = 2.0 * kDeg * scale;
  DispersionSource& yaw_tipoff = add(32);
  yaw_tipoff.stage = 4;
  yaw_tipoff.tipoff_rad = 2.0 * kDeg * scale;
  add(33).launch_change_rad = 0.5 * kDeg * scale;
  add(34).launch_change_rad = 0.3 * kDeg * scale;
  c->nominal.mission = &c->mission;  // the block 40 table, point mass
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

}  // namespace
}  // namespace tolip::test
