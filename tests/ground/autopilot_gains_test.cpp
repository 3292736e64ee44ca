// Issue 16 end to end: autopilot gains designed along the final nominal of the reference deck
// (data block 33 words 21-30, [body_dynamics] autopilot_*), delivered in the table image (format
// version 3) and flown by the flight-side executor; the 6D re-linearization (IP(6) = 1) with the
// designed stage-1 schedule meets its constraints (payoff against the constant gains printed);
// bad requests exit 2 naming the stage and the key.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"
#include "tolip_ground/autopilot_run.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::test {
namespace {

// The reference deck with lines replaced (each `from` must occur).
std::string edited_deck(const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = read_text_file(reference_deck());
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

const std::pair<std::string, std::string> kDesigned = {
    "[body_dynamics]  # data block 33, DA6D (6D simulation; body stations in inches)\n",
    "[body_dynamics]  # data block 33, DA6D (6D simulation; body stations in "
    "inches)\nautopilot_designed_gains = 1\n"};

std::filesystem::path write_deck(const ScratchDirectory& dir, const std::string& name,
                                 const std::string& text) {
  const std::filesystem::path path = dir.path() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(AutopilotGains, Issue16_SixDRelinearizationMeetsItsConstraintsWithDesignedGains) {
  auto mission = std::make_unique<Mission>();
  auto extras = std::make_unique<ground::DeckExtras>();
  ground::DeckError error;
  ASSERT_TRUE(ground::load_toml_deck(reference_deck(), mission.get(), extras.get(), &error))
      << error.to_string();
  ASSERT_EQ(mission->options.body_dynamics_6d(), 1);
  mission->options.ip[3] = 0;  // no exchange ratios: only the linearization matters here
  ground::AutopilotPlan plan;
  std::string message;
  ASSERT_TRUE(ground::plan_autopilot_design(*mission, *extras, &plan, &message)) << message;

  ground::OptimizationRun constant;
  ground::run_optimization(*mission, nullptr, &constant);
  ASSERT_EQ(constant.linearization.status, Status::kOk);
  ASSERT_TRUE(constant.linearization.result->body_dynamics);
  auto workspace = std::make_unique<LinearizationWorkspace>();
  auto result = std::make_unique<LinearizationResult>();
  ground::SixDAutopilotGains hook(plan);
  const Status status = linearize_pitch_program(*constant.workspace, workspace.get(), result.get(), &hook);
  ASSERT_TRUE(hook.called());
  ASSERT_EQ(hook.status(), Status::kOk);
  EXPECT_EQ(status, Status::kOk);
  EXPECT_TRUE(result->body_dynamics);
  EXPECT_TRUE(result->constraints_met);
  EXPECT_TRUE(result->rate_limits_met);
  EXPECT_GT(workspace->mission.body_dynamics.stage1_schedule_count, 1);
  const LinearizationResult& c = *constant.linearization.result;
  std::printf(
      "6D re-linearized payoff: constant gains %.6f lb (%d forward runs), designed gains %.6f lb (%d forward "
      "runs), difference %+.6f lb\n",
      c.payoff, c.forward_runs, result->payoff, result->forward_runs, result->payoff - c.payoff);
  // The designed gains do change the 6D flight (the schedule is flown, not ignored).
  EXPECT_NE(result->payoff, c.payoff);
}

struct Exported {
  CommandResult run;
  std::vector<std::uint8_t> image;
};

TEST(AutopilotGains, Issue16_ExportDeliversTheScheduleAndTheExecutorFliesIt) {
  ScratchDirectory dir("autopilot_export");
  const auto deck = write_deck(dir, "designed.toml", edited_deck({kDesigned}));
  const auto image_path = dir.path() / "table.bin";
  const CommandResult run =
      run_tolip_executable({"export", deck.string(), "--out", image_path.string(), "--created-unix-s", "0"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("designed gain schedule points"), std::string::npos) << run.out;
  const std::string bytes = read_text_file(image_path);
  ASSERT_EQ(bytes.size(), kTableImageSize);
  static GuidanceTableService service;
  ASSERT_EQ(service.load(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), Status::kOk);
  const GuidanceTable& table = *service.active();
  ASSERT_GE(table.schedule_count, 12);
  int stage1 = 0;
  for (int i = 0; i < table.schedule_count; ++i) {
    const GainSchedulePoint& p = table.schedule[i];
    if (p.stage_code == 1) ++stage1;
    // The executor's output fields carry the record's gains at the record's time (what a bench flies).
    const StageGains g = scheduled_gains(table, p.stage_code, p.stage_time_s);
    EXPECT_EQ(g.k_theta, p.k_theta);
    EXPECT_EQ(g.k_q_s, p.k_q_s);
  }
  EXPECT_EQ(stage1, 6);
  // The constant-gain export is the version-3 image without records: the deck's DA6D(1-6).
  const auto plain_path = dir.path() / "plain.bin";
  const CommandResult plain = run_tolip_executable(
      {"export", reference_deck(), "--out", plain_path.string(), "--created-unix-s", "0"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const std::string plain_bytes = read_text_file(plain_path);
  GuidanceTable constant;
  ASSERT_EQ(decode_table_image(reinterpret_cast<const std::uint8_t*>(plain_bytes.data()), plain_bytes.size(),
                               &constant),
            Status::kOk);
  EXPECT_EQ(constant.schedule_count, 0);
  EXPECT_EQ(constant.gains[0].k_theta, 1.2);
}

TEST(AutopilotGains, Issue16_OptimizeReportsTheScheduleInJsonAndPlotsIt) {
  ScratchDirectory dir("autopilot_optimize");
  const auto deck = write_deck(dir, "designed.toml",
                               edited_deck({kDesigned,
                                            {"exchange_ratios = true", "exchange_ratios = false"},
                                            {"dispersions = true", "dispersions = false"},
                                            {"hardover = true", "hardover = false"},
                                            {"impact = true", "impact = false"},
                                            {"radar = true", "radar = false"},
                                            {"print_input = true", "print_input = false"}}));
  const CommandResult run = run_tolip_executable({"optimize", deck.string(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out);
  ASSERT_TRUE(document.contains("autopilot"));
  const nlohmann::json& a = document["autopilot"];
  EXPECT_TRUE(a["computed"].get<bool>());
  EXPECT_TRUE(a["six_d_scheduled"].get<bool>());
  EXPECT_EQ(a["trajectory"], "linearized program");
  ASSERT_GE(a["points"].size(), 12u);
  for (const nlohmann::json& p : a["points"]) {
    // The closed-loop poles of the reported gains, from the reported model (per unit inertia).
    const double inertia = p["pitch_inertia_slug_ft2"].get<double>();
    const double a_s2 = p["m_alpha_lbf_ft_per_rad"].get<double>() / inertia;
    const double b_s2 = p["m_delta_lbf_ft_per_rad"].get<double>() / inertia;
    const double c_s = p["m_q_lbf_ft_s_per_rad"].get<double>() / inertia;
    Eigen::Matrix2d A;
    A << 0.0, 1.0, -(p["k_theta"].get<double>() * b_s2 - a_s2), -(p["k_q_s"].get<double>() * b_s2 - c_s);
    const std::complex<double> s = Eigen::EigenSolver<Eigen::Matrix2d>(A).eigenvalues()(0);
    const double w = 2.75;  // the deck default
    EXPECT_NEAR(std::abs(s), w, w * 1e-6);
    EXPECT_NEAR(-s.real() / std::abs(s), 0.7, 0.7e-6);  // and 0.7
    EXPECT_NEAR(std::hypot(p["closed_loop_poles"][0]["re"].get<double>(),
                           p["closed_loop_poles"][0]["im"].get<double>()),
                w, w * 1e-6);
  }
  const ground::DocumentFigures figures = ground::figures_for_document(document);
  int found = 0;
  for (const ground::Figure& f : figures.figures)
    found += (f.name == "autopilot_gains" || f.name == "autopilot_margins");
  EXPECT_EQ(found, 2);
}

// Bad requests: exit 2, the stage and the key named, nothing written.
TEST(AutopilotGains, Issue16_BadRequestsExit2NamingStageAndKey) {
  ScratchDirectory dir("autopilot_bad");
  const auto out = dir.path() / "table.bin";
  struct Case {
    std::vector<std::pair<std::string, std::string>> edits;
    std::vector<std::string> named;
  };
  const std::pair<std::string, std::string> no_linearization = {"linearization = true",
                                                                "linearization = false"};
  const std::vector<Case> cases = {
      {{kDesigned,
        {"autopilot_designed_gains = 1\n",
         "autopilot_designed_gains = 1\nautopilot_damping_ratio = [0.7, 0.0, 0.7]\n"}},
       {"body_dynamics.autopilot_damping_ratio[1]", "(stage 2)", "damping"}},
      {{kDesigned,
        {"autopilot_designed_gains = 1\n",
         "autopilot_designed_gains = 1\nautopilot_damping_ratio = [-0.2, 0.7, 0.7]\n"}},
       {"body_dynamics.autopilot_damping_ratio[0]", "(stage 1)"}},
      {{kDesigned,
        {"autopilot_designed_gains = 1\n", "autopilot_designed_gains = 1\nautopilot_points_per_stage = 9\n"}},
       {"body_dynamics.autopilot_points_per_stage", "holds 8 per stage"}},
      {{kDesigned,
        no_linearization,
        {"body_dynamics_6d = 1", "body_dynamics_6d = 0"},
        {"autopilot_designed_gains = 1\n",
         "autopilot_designed_gains = 1\nautopilot_natural_frequency_rad_s = [60.0, 2.0, 2.0]\n"}},
       {"body_dynamics.autopilot_natural_frequency_rad_s[0]", "stage 1",
        "kAutopilotFrequencyBeyondDeflection"}},
      // The same request with the 6D re-linearization: the design along the accepted point-mass
      // program (SixDAutopilotGains) fails before any body dynamics fly.
      {{kDesigned,
        {"autopilot_designed_gains = 1\n",
         "autopilot_designed_gains = 1\nautopilot_natural_frequency_rad_s = [60.0, 2.0, 2.0]\n"}},
       {"data block 33, body_dynamics.autopilot_natural_frequency_rad_s[0] (stage 1, along the point-mass "
        "linearized program trajectory): kAutopilotFrequencyBeyondDeflection"}},
  };
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const auto deck = write_deck(dir, "bad" + std::to_string(k) + ".toml", edited_deck(cases[k].edits));
    const CommandResult run = run_tolip_executable({"export", deck.string(), "--out", out.string()});
    EXPECT_EQ(run.exit_code, 2) << run.err;
    for (const std::string& name : cases[k].named)
      EXPECT_NE(run.err.find(name), std::string::npos) << name << "\n" << run.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  // optimize stops on the 6D design's failure with the same words (one message for both commands).
  const auto deck =
      write_deck(dir, "bad" + std::to_string(cases.size() - 1) + ".toml", edited_deck(cases.back().edits));
  const CommandResult optimize = run_tolip_executable({"optimize", deck.string(), "--json"});
  EXPECT_EQ(optimize.exit_code, 2) << optimize.err;
  EXPECT_NE(optimize.err.find(cases.back().named[0]), std::string::npos) << optimize.err;
}

}  // namespace
}  // namespace tolip::test
