// `tolip optimize` end to end on examples/scout/mission.toml (the crude initial pitch program),
// plus the report's fallback when the optimizer stops before its summary. One optimization run
// takes about 0.1 s; the JSON and listing runs are made once and shared (static cache).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/optimization_report.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::test {
namespace {

// One `optimize --json --csv FILE` run and one listing run of the example, shared by the tests.
struct CachedRuns {
  ScratchDirectory scratch{"optimize_cache"};
  std::string csv_path;
  CommandResult json_run;
  CommandResult listing_run;
  nlohmann::json document;
  bool parsed = false;
};

const CachedRuns& cached_runs() {
  static const std::unique_ptr<CachedRuns> runs = [] {
    auto r = std::make_unique<CachedRuns>();
    r->csv_path = (r->scratch / "final.csv").string();
    r->json_run = run_tolip_executable({"optimize", mission_deck(), "--json", "--csv", r->csv_path});
    r->listing_run = run_tolip_executable({"optimize", mission_deck()});
    try {
      r->document = nlohmann::json::parse(r->json_run.out);
      r->parsed = true;
    } catch (const nlohmann::json::exception&) {
      r->parsed = false;
    }
    return r;
  }();
  return *runs;
}

const nlohmann::json& optimized_document() {
  const CachedRuns& runs = cached_runs();
  EXPECT_EQ(runs.json_run.exit_code, 0) << runs.json_run.err;
  EXPECT_TRUE(runs.parsed) << runs.json_run.out.substr(0, 400);
  return runs.document;
}

TEST(OptimizeCommand, ConvergesWithEveryConstraintInsideItsDeadband) {
  const nlohmann::json& document = optimized_document();
  ASSERT_TRUE(document.is_object());
  EXPECT_EQ(document["status"], "kOk");
  EXPECT_EQ(document["status_message"], "success");
  EXPECT_EQ(document["converged"], true);
  EXPECT_GE(document["forward_runs"].get<int>(), 2);
  EXPECT_GE(document["backward_runs"].get<int>(), 1);
  EXPECT_LE(document["forward_runs"].get<int>(), 30);  // data block 28 DA13(3) of the deck

  const nlohmann::json& constraints = document["constraints"];
  ASSERT_EQ(constraints.size(), 3u);  // altitude, inertial path angle, V_I - circular (block 8)
  const int codes[] = {7, 2, 3};
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const nlohmann::json& c = constraints[i];
    EXPECT_EQ(c["code"].get<int>(), codes[i]);
    ASSERT_TRUE(c["desired"].is_number());
    ASSERT_TRUE(c["achieved"].is_number());
    ASSERT_TRUE(c["tolerance"].is_number());
    const double error = c["achieved"].get<double>() - c["desired"].get<double>();
    EXPECT_LE(std::fabs(error), c["tolerance"].get<double>()) << "constraint code " << c["code"];
    EXPECT_NEAR(c["error"].get<double>(), error, 1e-9 * (1.0 + std::fabs(error)));
    EXPECT_EQ(c["met"], true);
  }
  // Data block 19 units: the path angle in radians, its 1 deg deadband as 0.01745 rad.
  EXPECT_EQ(constraints[1]["unit"], "rad");
  EXPECT_NEAR(constraints[1]["tolerance"].get<double>(), 0.0174532925199, 1e-12);
  EXPECT_EQ(constraints[0]["unit"], "ft");
  EXPECT_EQ(constraints[2]["unit"], "ft/s");

  const nlohmann::json& partials = document["payoff_partials"];
  ASSERT_EQ(partials.size(), constraints.size());
  for (const nlohmann::json& p : partials) EXPECT_TRUE(p.is_number());
}

TEST(OptimizeCommand, PayloadIsNoWorseThanTheReferenceOptimumByMoreThanHalfAPercent) {
  std::unique_ptr<Mission> reference = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(ground::load_toml_deck(reference_deck(), reference.get(), &error)) << error.to_string();
  const double reference_payload_lb = reference->vehicle.payload_lb;
  EXPECT_NEAR(reference_payload_lb, 283.405, 1e-3);

  const nlohmann::json& document = optimized_document();
  ASSERT_TRUE(document["payload_lb"].is_number());
  const double payload = document["payload_lb"].get<double>();
  EXPECT_GE(payload, 0.995 * reference_payload_lb);
  EXPECT_EQ(document["initial_payload_lb"].get<double>(), 250.0);  // the deck's starting guess
  const nlohmann::json& payoff = document["payoff"];
  EXPECT_EQ(payoff["kind"], "payload");
  EXPECT_EQ(payoff["unit"], "lb");
  EXPECT_EQ(payoff["code"], 0);
  EXPECT_DOUBLE_EQ(payoff["value"].get<double>(), payload);  // the payload payoff is the payload
  EXPECT_TRUE(payoff["corrected_value"].is_number());
}

TEST(OptimizeCommand, KeepsTheSimulateSchemaForTheFinalTrajectory) {
  const nlohmann::json& document = optimized_document();
  std::vector<std::string> keys;
  for (auto it = document.begin(); it != document.end(); ++it) keys.push_back(it.key());
  for (const char* key : {"program",
                          "version",
                          "deck",
                          "title",
                          "case_heading",
                          "date",
                          "status",
                          "status_message",
                          "launch_space_age_date_days",
                          "point_count",
                          "heat_integral_btu_ft2",
                          "burnout",
                          "inertial",
                          "orbit",
                          "stage_events",
                          "converged",
                          "forward_runs",
                          "backward_runs",
                          "payoff",
                          "payload_lb",
                          "constraints",
                          "payoff_partials",
                          "adjustable",
                          "theta_history",
                          "iterations",
                          "trajectory"}) {
    EXPECT_TRUE(document.contains(key)) << key;
  }
  EXPECT_EQ(document["deck"], mission_deck());
  EXPECT_TRUE(document["burnout"].is_object());
  ASSERT_TRUE(document["orbit"].is_object());
  EXPECT_EQ(document["orbit"]["type"], "elliptic");
  // The final trajectory reaches the altitude constraint (data block 19) within its deadband.
  EXPECT_NEAR(document["burnout"]["altitude_ft"].get<double>(), 1822834.647, 20000.0);
  ASSERT_FALSE(document["stage_events"].empty());
  const nlohmann::json& points = document["trajectory"];
  ASSERT_FALSE(points.empty());
  EXPECT_EQ(points.size(), document["point_count"].get<std::size_t>());
  // The final weight of the trajectory includes the optimized payload.
  EXPECT_GT(document["burnout"]["weight_lb"].get<double>(), document["payload_lb"].get<double>());
  EXPECT_FALSE(contains(cached_runs().json_run.out, "NaN"));
  EXPECT_FALSE(contains(cached_runs().json_run.out, "nan"));
}

TEST(OptimizeCommand, ThetaHistoryIsThePitchAttitudeOfEveryPointStartingVertical) {
  const nlohmann::json& document = optimized_document();
  const nlohmann::json& history = document["theta_history"];
  const nlohmann::json& points = document["trajectory"];
  ASSERT_FALSE(history.empty());
  ASSERT_EQ(history.size(), points.size());
  EXPECT_DOUBLE_EQ(history[0][0].get<double>(), 0.0);
  EXPECT_NEAR(history[0][1].get<double>(), 90.0, 1e-9);  // vertical at lift-off
  double previous_time = -1.0;
  for (std::size_t i = 0; i < history.size(); ++i) {
    ASSERT_EQ(history[i].size(), 2u);
    const double time = history[i][0].get<double>();
    EXPECT_GE(time, previous_time);
    previous_time = time;
    EXPECT_DOUBLE_EQ(time, points[i]["time_s"].get<double>());
    EXPECT_DOUBLE_EQ(history[i][1].get<double>(), points[i]["theta_deg"].get<double>());
  }
}

TEST(OptimizeCommand, ReportsTheIterationHistoryAndTheAdjustableParameters) {
  const nlohmann::json& document = optimized_document();
  const nlohmann::json& iterations = document["iterations"];
  ASSERT_GE(iterations.size(), 2u);
  EXPECT_EQ(iterations.front()["kind"], "initial_nominal");
  EXPECT_EQ(iterations.back()["kind"], "final_guidance");
  EXPECT_EQ(iterations.back()["forward_run"].get<int>(), document["forward_runs"].get<int>());
  const std::size_t constraint_count = document["constraints"].size();
  bool any_optimization = false;
  int previous_run = 0;
  for (const nlohmann::json& record : iterations) {
    const int run = record["forward_run"].get<int>();
    EXPECT_GT(run, previous_run);
    previous_run = run;
    const std::string kind = record["kind"].get<std::string>();
    EXPECT_TRUE(kind == "initial_nominal" || kind == "guidance" || kind == "optimization" ||
                kind == "final_guidance")
        << kind;
    if (kind == "optimization") {
      any_optimization = true;
      EXPECT_GT(record["attempted_payoff_improvement"].get<double>(), 0.0);
    }
    EXPECT_TRUE(record["successful"].is_boolean());
    for (const char* key : {"payoff", "corrected_payoff", "payload_lb", "payload_increment_lb"}) {
      EXPECT_TRUE(record[key].is_number()) << key;
    }
    EXPECT_EQ(record["constraint_corrections"].size(), constraint_count);
    EXPECT_EQ(record["payoff_partials"].size(), constraint_count);
  }
  EXPECT_TRUE(any_optimization);
  // The initial nominal's corrections are desired - achieved on the crude program.
  EXPECT_LT(iterations.front()["constraint_corrections"][0].get<double>(), -1000.0);

  const nlohmann::json& adjustable = document["adjustable"];
  ASSERT_EQ(adjustable.size(), 2u);
  EXPECT_EQ(adjustable[0]["code"], 1);
  EXPECT_EQ(adjustable[0]["unit"], "deg");
  EXPECT_DOUBLE_EQ(adjustable[0]["initial_value"].get<double>(), -20.0);
  EXPECT_GT(adjustable[0]["value"].get<double>(), -90.0);
  EXPECT_LT(adjustable[0]["value"].get<double>(), 90.0);
  EXPECT_EQ(adjustable[1]["code"], 3);
  EXPECT_EQ(adjustable[1]["unit"], "s");
  EXPECT_DOUBLE_EQ(adjustable[1]["initial_value"].get<double>(), 450.0);
  EXPECT_GE(adjustable[1]["value"].get<double>(), 0.0);
  // The coast after stage 3 the final trajectory flew is the optimized one.
  for (const nlohmann::json& event : document["stage_events"]) {
    if (event["stage"] == 8) {
      EXPECT_NEAR(event["end_time_s"].get<double>() - event["start_time_s"].get<double>(),
                  adjustable[1]["value"].get<double>(), 1e-6);
    }
  }
}

TEST(OptimizeCommand, CsvHoldsEveryPointOfTheFinalTrajectory) {
  const CachedRuns& runs = cached_runs();
  const nlohmann::json& document = optimized_document();
  const std::string csv = read_text_file(runs.csv_path);
  ASSERT_FALSE(csv.empty());
  std::istringstream in(csv);
  std::string line;
  std::size_t lines = 0;
  while (std::getline(in, line)) ++lines;
  EXPECT_EQ(lines, document["point_count"].get<std::size_t>() + 1);
  EXPECT_EQ(csv.rfind("time_s,stage,stage_time_s,", 0), 0u);
}

TEST(OptimizeCommand, ListingHasTheIterationTablesTheFinalTrajectoryAndTheSummary) {
  const CommandResult& run = cached_runs().listing_run;
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(without_input_warnings(run.err).empty()) << run.err;
  const std::string& text = run.out;
  for (const char* heading : {"OPTIMIZATION HISTORY",
                              "OPTIMIZATION PROBLEM",
                              "ITERATION HISTORY",
                              "NOMINAL PAYOFF INCR",
                              "CORRECTED PAYOFF",
                              "PAYLOAD INCREMENT",
                              "FORWARD RUN 1   INITIAL NOMINAL",
                              "CONSTRAINT CORRECTIONS (DESIRED - ACHIEVED)",
                              "D PAYOFF/D CONSTRAINT",
                              "NOMINAL PAYOFF INCREMENT",
                              "FINAL GUIDANCE",
                              "FINAL TRAJECTORY",
                              "TERMINAL CONDITIONS",
                              "STAGE EVENTS",
                              "ORBIT ELEMENTS",
                              "OPTIMIZATION SUMMARY",
                              "CONSTRAINTS ON THE FINAL TRAJECTORY",
                              "ADJUSTABLE PARAMETERS",
                              "STAGE 4 THETA (SPUN)",
                              "COAST AFTER STAGE 3",
                              "LB/RAD"}) {
    EXPECT_TRUE(contains(text, heading)) << heading;
  }
  EXPECT_TRUE(contains(text, "CONVERGED                  =                  YES"));
  EXPECT_FALSE(contains(text, "nan"));
  EXPECT_FALSE(contains(text, "TRAJECTORY TERMINATED"));
  // Pages are numbered in one sequence through the history, the trajectory and the summary.
  EXPECT_TRUE(contains(text, "OPTIMIZATION HISTORY   PAGE 1\n"));
  EXPECT_FALSE(contains(text, "FINAL TRAJECTORY   PAGE 1\n"));
  for (const std::string& line : [&text] {
         std::vector<std::string> lines;
         std::istringstream in(text);
         std::string l;
         while (std::getline(in, l)) lines.push_back(l);
         return lines;
       }()) {
    EXPECT_LE(line.size(), 132u) << line;
  }
}

TEST(OptimizeCommand, NotConvergedExitsOneAndStillReportsTheBestTrajectory) {
  ScratchDirectory scratch("optimize_budget");
  // A forward-run budget of 2: the initial nominal and one guidance run leave V_I - V_circ outside.
  const std::string deck = edited_example_deck(
      scratch, "budget.toml", {{"max_forward_trajectories = 30", "max_forward_trajectories = 2"}});
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_TRUE(contains(run.err, "tolip: optimization: kGuidanceDidNotConverge: ")) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out);
  EXPECT_EQ(document["status"], "kGuidanceDidNotConverge");
  EXPECT_EQ(document["case_status"], "kGuidanceDidNotConverge");
  EXPECT_EQ(document["optimization_stop"], "not_reached");
  EXPECT_EQ(document["optimization_runs"].get<int>(), 0);
  EXPECT_EQ(document["converged"], false);
  EXPECT_EQ(document["forward_runs"].get<int>(), 2);
  EXPECT_FALSE(document["trajectory"].empty());
  EXPECT_TRUE(document["orbit"].is_object());
  bool any_unmet = false;
  for (const nlohmann::json& c : document["constraints"]) {
    ASSERT_TRUE(c["achieved"].is_number());
    if (c["met"] == false) any_unmet = true;
  }
  EXPECT_TRUE(any_unmet);
  EXPECT_FALSE(contains(run.out, "NaN"));

  const CommandResult listing = run_tolip_executable({"optimize", deck});
  EXPECT_EQ(listing.exit_code, 1);
  EXPECT_TRUE(contains(listing.out, "OPTIMIZATION ENDED: kGuidanceDidNotConverge"));
  EXPECT_TRUE(contains(listing.out, "FINAL TRAJECTORY"));
  // The trajectory itself completed: no termination line in its listing.
  EXPECT_FALSE(contains(listing.out, "TRAJECTORY TERMINATED"));
}

TEST(OptimizeCommand, BadInputExitsTwoWithNothingOnStdout) {
  ScratchDirectory scratch("optimize_bad");
  // IP(1) = 1 (velocity) but the payoff entry of data block 8 is the payload (code 0).
  const std::string mismatch =
      edited_example_deck(scratch, "mismatch.toml", {{"payoff = 0 ", "payoff = 1 "}});
  CommandResult run = run_tolip_executable({"optimize", mismatch, "--json"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());
  EXPECT_TRUE(contains(run.err, "data block 8")) << run.err;

  run = run_tolip_executable({"optimize", (scratch / "missing.toml").string()});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());
  EXPECT_TRUE(contains(run.err, "tolip: ")) << run.err;

  run = run_tolip_executable({"optimize"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());

  run = run_tolip_executable({"optimize", mission_deck(), "--no-such-option"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty());
}

TEST(OptimizeCommand, HelpDescribesTheOptions) {
  const CommandResult run = run_tolip_executable({"optimize", "--help"});
  EXPECT_EQ(run.exit_code, 0);
  for (const char* part : {"DECK", "--json", "--csv", "converged", "theta_history"}) {
    EXPECT_TRUE(contains(run.out, part)) << part;
  }
  const CommandResult top = run_tolip_executable({"--help"});
  EXPECT_TRUE(contains(top.out, "optimize"));
}

// The optimizer fills its summary only when it finishes; after an early stop the report evaluates
// the constraints on the best trajectory itself and prints null, never NaN, for the partials.
TEST(OptimizeReport, EvaluatesTheConstraintsItselfWhenTheOptimizerStoppedEarly) {
  std::unique_ptr<Mission> mission = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(ground::load_toml_deck(reference_deck(), mission.get(), &error)) << error.to_string();
  auto prepared = std::make_unique<PreparedCase>();
  auto trajectory = std::make_unique<Trajectory>();
  ASSERT_EQ(prepare_case(*mission, prepared.get()), Status::kOk);
  ASSERT_EQ(fly_trajectory(*mission, *prepared, trajectory.get()), Status::kOk);
  auto result = std::make_unique<OptimizerResult>();  // constraint_count 0: no summary
  result->forward_runs = 1;
  result->status = Status::kSteeringMatrixSingular;

  ground::OptimizationReport report;
  report.initial_mission = mission.get();
  report.result = result.get();
  report.final_trajectory.mission = mission.get();
  report.final_trajectory.trajectory = trajectory.get();
  report.final_trajectory.status = Status::kOk;
  report.status = Status::kSteeringMatrixSingular;

  const std::vector<ground::ConstraintSummary> constraints = ground::constraint_summaries(report);
  ASSERT_EQ(constraints.size(), 3u);
  const TrajectoryPoint& last = trajectory->final_point();
  EXPECT_EQ(constraints[0].code, 7);
  EXPECT_NEAR(constraints[0].achieved, last.altitude_ft, 1e-6);
  for (const ground::ConstraintSummary& c : constraints) {
    EXPECT_TRUE(std::isfinite(c.achieved));
    EXPECT_TRUE(c.met) << c.code;  // the reference optimum meets its constraints
    EXPECT_TRUE(std::isnan(c.payoff_partial));
  }
  const ground::PayoffSummary payoff = ground::payoff_summary(report);
  EXPECT_DOUBLE_EQ(payoff.value, mission->vehicle.payload_lb);
  EXPECT_TRUE(std::isnan(payoff.corrected));

  const std::string text = ground::dump_json(ground::optimization_json(report));
  EXPECT_FALSE(contains(text, "NaN"));
  const nlohmann::json document = nlohmann::json::parse(text);
  EXPECT_EQ(document["status"], "kSteeringMatrixSingular");
  EXPECT_TRUE(document["payoff_partials"][0].is_null());
  EXPECT_TRUE(document["payoff"]["corrected_value"].is_null());
  EXPECT_TRUE(document["constraints"][0]["achieved"].is_number());
  EXPECT_TRUE(document["iterations"].empty());

  std::ostringstream listing;
  ground::write_optimization_listing(listing, report);
  EXPECT_TRUE(contains(listing.str(), "OPTIMIZATION ENDED: kSteeringMatrixSingular"));
  EXPECT_FALSE(contains(listing.str(), "nan"));
}

}  // namespace
}  // namespace tolip::test
