// The flight image's embedded inputs (host build): the generated mission sources rebuild the decks'
// cases exactly (the flown case, and the optimization case whose full optimization the demo runs),
// and the host flight demo runs to its end.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::flight {
Status build_embedded_mission(Mission* mission);            // generated
Status build_embedded_optimization_case(Mission* mission);  // generated
extern const char build_embedded_mission_title[];           // generated beside them: data blocks 1-3
extern const char build_embedded_mission_case_heading[];
extern const char build_embedded_mission_date[];
extern const char build_embedded_optimization_case_case_heading[];
}  // namespace tolip::flight

namespace tolip {
namespace {

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

template <std::size_t N>
void expect_same(const double (&a)[N], const double (&b)[N], const char* what) {
  for (std::size_t i = 0; i < N; ++i) EXPECT_EQ(bits(a[i]), bits(b[i])) << what << "[" << i << "]";
}
template <std::size_t N>
void expect_same(const int (&a)[N], const int (&b)[N], const char* what) {
  for (std::size_t i = 0; i < N; ++i) EXPECT_EQ(a[i], b[i]) << what << "[" << i << "]";
}

TEST(EmbeddedMission, RebuildsTheDeckCaseFieldByField) {
  auto deck = std::make_unique<Mission>();
  ground::DeckExtras extras;
  ground::DeckError error;
  ASSERT_TRUE(ground::load_toml_deck(TOLIP_FLIGHT_DECK, deck.get(), &extras, &error)) << error.to_string();
  auto embedded = std::make_unique<Mission>();
  ASSERT_EQ(flight::build_embedded_mission(embedded.get()), Status::kOk);

  EXPECT_EQ(std::string(flight::build_embedded_mission_title), extras.listing.title);
  EXPECT_EQ(std::string(flight::build_embedded_mission_case_heading), extras.listing.case_heading);
  EXPECT_EQ(std::string(flight::build_embedded_mission_date), extras.listing.date);
  expect_same(embedded->options.ip, deck->options.ip, "ip");
  EXPECT_EQ(embedded->constraints.count, deck->constraints.count);
  expect_same(embedded->constraints.codes, deck->constraints.codes, "constraint codes");
  expect_same(embedded->constraints.desired, deck->constraints.desired, "desired");
  expect_same(embedded->constraints.deadband_optimization, deck->constraints.deadband_optimization,
              "deadband");
  expect_same(embedded->constraints.deadband_linearization, deck->constraints.deadband_linearization,
              "deadband");
  EXPECT_EQ(embedded->adjustable.count, deck->adjustable.count);
  expect_same(embedded->adjustable.codes, deck->adjustable.codes, "adjustable codes");
  expect_same(embedded->adjustable.weights, deck->adjustable.weights, "adjustable weights");
  EXPECT_EQ(embedded->linearization.segment_count, deck->linearization.segment_count);
  for (int i = 0; i <= kMaxLinearSegments; ++i) {
    EXPECT_EQ(embedded->linearization.boundaries[i].stage, deck->linearization.boundaries[i].stage) << i;
    EXPECT_EQ(bits(embedded->linearization.boundaries[i].time_from_ignition_s),
              bits(deck->linearization.boundaries[i].time_from_ignition_s))
        << "TLIN " << i;
  }
  expect_same(embedded->linearization.segment_weights, deck->linearization.segment_weights, "ETALIN");
  EXPECT_EQ(bits(embedded->convergence.initial_payoff_improvement),
            bits(deck->convergence.initial_payoff_improvement));
  EXPECT_EQ(bits(embedded->convergence.stop_improvement), bits(deck->convergence.stop_improvement));
  EXPECT_EQ(embedded->convergence.max_forward_trajectories, deck->convergence.max_forward_trajectories);
  EXPECT_EQ(embedded->convergence.max_linearization_iterations,
            deck->convergence.max_linearization_iterations);
  EXPECT_EQ(bits(embedded->misc.stage4_theta_rad), bits(deck->misc.stage4_theta_rad));
  EXPECT_EQ(bits(embedded->misc.nose_radius_ft), bits(deck->misc.nose_radius_ft));
  EXPECT_EQ(bits(embedded->control.max_pitch_rate_rad_s), bits(deck->control.max_pitch_rate_rad_s));
  EXPECT_EQ(bits(embedded->launch.geocentric_latitude_rad), bits(deck->launch.geocentric_latitude_rad));
  EXPECT_EQ(bits(embedded->vehicle.payload_lb), bits(deck->vehicle.payload_lb));
  ASSERT_EQ(embedded->pitch_program_rad.size(), deck->pitch_program_rad.size());
  for (int i = 0; i < deck->pitch_program_rad.size(); ++i) {
    EXPECT_EQ(bits(embedded->pitch_program_rad.y(i)), bits(deck->pitch_program_rad.y(i))) << i;
  }
}

TEST(EmbeddedMission, FliesEveryTrajectoryPointBitForBitLikeTheDeck) {
  auto deck = std::make_unique<Mission>();
  ground::DeckError error;
  ASSERT_TRUE(ground::load_toml_deck(TOLIP_FLIGHT_DECK, deck.get(), &error)) << error.to_string();
  auto embedded = std::make_unique<Mission>();
  ASSERT_EQ(flight::build_embedded_mission(embedded.get()), Status::kOk);
  auto prepared_deck = std::make_unique<PreparedCase>();
  auto prepared_embedded = std::make_unique<PreparedCase>();
  ASSERT_EQ(prepare_case(*deck, prepared_deck.get()), Status::kOk);
  ASSERT_EQ(prepare_case(*embedded, prepared_embedded.get()), Status::kOk);
  auto a = std::make_unique<Trajectory>();
  auto b = std::make_unique<Trajectory>();
  ASSERT_EQ(fly_trajectory(*deck, *prepared_deck, a.get()), Status::kOk);
  ASSERT_EQ(fly_trajectory(*embedded, *prepared_embedded, b.get()), Status::kOk);
  ASSERT_EQ(a->point_count, b->point_count);
  ASSERT_GT(a->point_count, 190);
  for (int i = 0; i < a->point_count; ++i) {
    EXPECT_EQ(bits(a->points[i].time_s), bits(b->points[i].time_s)) << i;
    EXPECT_EQ(bits(a->points[i].theta_rad), bits(b->points[i].theta_rad)) << i;
    EXPECT_EQ(bits(a->points[i].weight_lb), bits(b->points[i].weight_lb)) << i;
    for (int k = 0; k < 6; ++k)
      ASSERT_EQ(bits(a->points[i].state[k]), bits(b->points[i].state[k])) << i << " " << k;
  }
}

TEST(EmbeddedOptimizationCase, OptimizesBitForBitLikeTheDeck) {
  auto deck = std::make_unique<Mission>();
  ground::DeckExtras extras;
  ground::DeckError error;
  ASSERT_TRUE(ground::load_toml_deck(TOLIP_FLIGHT_OPTIMIZATION_DECK, deck.get(), &extras, &error))
      << error.to_string();
  auto embedded = std::make_unique<Mission>();
  ASSERT_EQ(flight::build_embedded_optimization_case(embedded.get()), Status::kOk);
  EXPECT_EQ(std::string(flight::build_embedded_optimization_case_case_heading), extras.listing.case_heading);
  EXPECT_EQ(bits(embedded->vehicle.payload_lb), bits(deck->vehicle.payload_lb));

  auto workspace = std::make_unique<OptimizerWorkspace>();
  auto from_deck = std::make_unique<OptimizerResult>();
  auto from_embedded = std::make_unique<OptimizerResult>();
  ASSERT_EQ(optimize_trajectory(*deck, workspace.get(), from_deck.get()), Status::kOk);
  const TrajectoryPoint deck_final = workspace->nominal.final_point();
  ASSERT_EQ(optimize_trajectory(*embedded, workspace.get(), from_embedded.get()), Status::kOk);
  const TrajectoryPoint& embedded_final = workspace->nominal.final_point();
  EXPECT_TRUE(from_embedded->converged);
  EXPECT_EQ(from_embedded->forward_runs, from_deck->forward_runs);
  EXPECT_EQ(from_embedded->backward_runs, from_deck->backward_runs);
  EXPECT_EQ(bits(from_embedded->payload_lb), bits(from_deck->payload_lb));
  EXPECT_EQ(bits(from_embedded->corrected_payoff), bits(from_deck->corrected_payoff));
  EXPECT_GT(from_embedded->payload_lb, 300.0);  // from 250 lb (docs/target.md: 307.68 lb)
  for (int k = 0; k < 6; ++k) EXPECT_EQ(bits(embedded_final.state[k]), bits(deck_final.state[k])) << k;
  EXPECT_EQ(bits(embedded_final.time_s), bits(deck_final.time_s));
}

TEST(FlightDemo, HostProgramRunsTheWholeTimelineAndEndsOk) {
  FILE* pipe = ::popen(TOLIP_FLIGHT_DEMO, "r");
  ASSERT_NE(pipe, nullptr);
  std::string out;
  char buffer[65536];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, got);
  const int status = ::pclose(pipe);
  EXPECT_EQ(status, 0);
  EXPECT_NE(out.find("EXEC load embedded image: kOk"), std::string::npos) << out.substr(0, 2000);
  EXPECT_NE(out.find("EXEC reject upload with one flipped bit: kTableImageCrcMismatch"), std::string::npos);
  EXPECT_NE(out.find("EXEC reject truncated upload: kTableImageTruncated"), std::string::npos);
  EXPECT_NE(out.find("unchanged, commits 1"), std::string::npos);
  EXPECT_NE(out.find("EXEC event stage 4"), std::string::npos);
  EXPECT_NE(out.find("failures 0"), std::string::npos);
  EXPECT_NE(out.find("TRAJ fly_trajectory: kOk"), std::string::npos);
  EXPECT_NE(out.find("OPT optimize_trajectory: kOk"), std::string::npos);
  EXPECT_NE(out.find("OPT converged yes forward_runs "), std::string::npos);
  EXPECT_NE(out.find("OPT final_velocity_ft_s "), std::string::npos);
  EXPECT_NE(out.find("EXEC END OK\n"), std::string::npos);
  EXPECT_EQ(out.find("TARGET "), std::string::npos);  // target-only lines
}

}  // namespace
}  // namespace tolip
