// `tolip optimize` with IP(21) = 1 (manual Sec. 15, Sec. 22 "Output format - Dispersion analysis")
// end to end on examples/scout/mission.toml: every code 1-38 flown about the linearized 6D program,
// the three-sigma groups recomputed here from the individual dispersions, the listing pages, the
// CSV, and a table the core cannot hold rejected as bad input. One run is shared (static cache).
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "support/pinned_figures.hpp"
#include "support/reference_data.hpp"

namespace tolip::test {
namespace {

struct Runs {
  ScratchDirectory scratch{"dispersions"};
  std::string csv_path;
  CommandResult json_run;
  CommandResult listing_run;
  nlohmann::json document;
};

const Runs& runs() {
  static const std::unique_ptr<Runs> r = [] {
    auto x = std::make_unique<Runs>();
    x->csv_path = (x->scratch / "dispersions.csv").string();
    x->json_run =
        run_tolip_executable({"optimize", mission_deck(), "--json", "--dispersions-csv", x->csv_path});
    x->listing_run = run_tolip_executable({"optimize", mission_deck()});
    x->document = nlohmann::json::parse(x->json_run.out, nullptr, false);
    return x;
  }();
  return *r;
}

const nlohmann::json& dispersions() { return runs().document["dispersions"]; }

TEST(Sec15DispersionCommand, ExampleFliesEveryCodeAboutTheLinearizedProgram) {
  ASSERT_EQ(runs().json_run.exit_code, 0) << runs().json_run.err;
  const nlohmann::json& d = dispersions();
  ASSERT_TRUE(d.is_object());
  EXPECT_EQ(d["status"], "kOk");
  EXPECT_EQ(d["nominal_kind"], "linearized program");
  EXPECT_EQ(d["staging_points"], nlohmann::json::array({"stage_2_ignition", "stage_3_ignition",
                                                        "stage_4_ignition", "final_point"}));
  ASSERT_EQ(d["trajectories"].size(), 38u);
  for (std::size_t k = 0; k < 38; ++k) {
    const nlohmann::json& t = d["trajectories"][k];
    EXPECT_EQ(t["code"], static_cast<int>(k) + 1);
    EXPECT_EQ(t["status"], "kOk") << t["code"];
  }
  // IP(21) acts now: no "asked for but not computed" warning names it.
  EXPECT_EQ(runs().json_run.err.find("IP(21)"), std::string::npos) << runs().json_run.err;
  // The pinned optimization is untouched by the analysis after it.
  EXPECT_EQ(runs().document["payload_lb"].get<double>(), tolip::test::kPinnedReferencePayloadLb);
}

// The analysis' nominal is the linearized trajectory (re-prepared at the optimized payload, the
// one rule of docs/theory/dispersions.md): its burnout altitude against the linearization's.
TEST(Sec15DispersionCommand, ExampleNominalIsTheLinearizedTrajectory) {
  const nlohmann::json& d = dispersions();
  const double nominal_altitude = d["nominal"]["values"][3]["altitude_ft"].get<double>();
  const nlohmann::json& constraints = runs().document["linearized"]["constraints"];
  ASSERT_EQ(constraints[0]["code"], 7);
  const double linearized_altitude = constraints[0]["achieved"].get<double>();
  EXPECT_LT(std::fabs(nominal_altitude - linearized_altitude), 5.0)
      << nominal_altitude << " " << linearized_altitude;
  EXPECT_EQ(d["nominal"]["values"][3]["crossrange_nmi"].get<double>(), 0.0);
}

// Sums and RSS recomputed here from the individual dispersions; the sign rule of every member.
TEST(Sec15DispersionCommand, ThreeSigmaGroupsEqualAnIndependentRecomputation) {
  const nlohmann::json& d = dispersions();
  const nlohmann::json& groups = d["three_sigma"];
  ASSERT_TRUE(groups.is_object());
  const char* keys[] = {"altitude_ft", "velocity_ft_s", "flight_path_angle_deg", "downrange_nmi",
                        "crossrange_nmi"};
  const auto trajectory = [&](int code) -> const nlohmann::json& { return d["trajectories"][code - 1]; };
  for (const char* group : {"yaw", "high", "low", "high_with_winds", "low_with_winds"}) {
    const nlohmann::json& g = groups[group];
    for (int column = 0; column < 4; ++column) {
      for (const char* key : keys) {
        double sum = 0.0, squares = 0.0;
        for (const nlohmann::json& code : g["codes"]) {
          const double x = trajectory(code.get<int>())["dispersions"][column][key].get<double>();
          sum += x;
          squares += x * x;
        }
        const double tolerance = 1e-9 * (std::fabs(sum) + std::sqrt(squares) + 1e-12);
        EXPECT_NEAR(g["sum"][column][key].get<double>(), sum, tolerance)
            << group << " " << column << " " << key;
        EXPECT_NEAR(g["rss"][column][key].get<double>(), std::sqrt(squares), tolerance)
            << group << " " << key;
      }
    }
  }
  // Yaw codes only in the yaw group; winds 36-37 only with winds; high = positive final altitude.
  EXPECT_EQ(groups["yaw"]["codes"], nlohmann::json::array({23, 26, 29, 32, 33, 38}));
  for (const char* group : {"high", "low", "high_with_winds", "low_with_winds"}) {
    const bool high = std::string(group).rfind("high", 0) == 0;
    const bool winds = std::string(group).find("winds") != std::string::npos;
    int wind_codes = 0;
    for (const nlohmann::json& code : groups[group]["codes"]) {
      const int c = code.get<int>();
      EXPECT_NE(trajectory(c)["plane"], "yaw") << c;
      if (c == 36 || c == 37) ++wind_codes;
      const double altitude = trajectory(c)["dispersions"][3]["altitude_ft"].get<double>();
      EXPECT_EQ(altitude > 0.0, high) << group << " " << c;
    }
    EXPECT_EQ(wind_codes, winds ? 1 : 0) << group;
  }
  EXPECT_EQ(groups["high"]["codes"].size() + groups["low"]["codes"].size(), 30u);  // 38 - 6 yaw - 2 winds
}

TEST(Sec15DispersionCommand, ListingPagesAndCsv) {
  const CommandResult& listing = runs().listing_run;
  ASSERT_EQ(listing.exit_code, 0) << listing.err;
  for (const char* part : {"DISPERSION ANALYSIS (SEC. 15", "NOMINAL TRAJECTORY (GIANT PLANE 40)",
                           "DISPERSED TRAJECTORY  CODE 36  WINDS HIGH", "SUMMARY OF INDIVIDUAL DISPERSIONS",
                           "THREE-SIGMA VARIATIONS", "YAW DISPERSIONS  CODES: 23 26 29 32 33 38",
                           "HIGH, WITH WINDS", "MAX QBAR*ALPHA", "STAGE 4 IGNITION"}) {
    EXPECT_NE(listing.out.find(part), std::string::npos) << part;
  }
  const std::string csv = read_text_file(runs().csv_path);
  std::istringstream lines(csv);
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header.rfind("code,title,status,staging_point,altitude_ft,", 0), 0u) << header;
  int rows = 0;
  for (std::string line; std::getline(lines, line);) ++rows;
  EXPECT_EQ(rows, 39 * 4);  // the nominal and 38 codes, 4 staging points each
}

TEST(Sec15DispersionCommand, WindTableLongerThanTheCoreHoldsIsBadInputNamingTheBlock) {
  ScratchDirectory scratch("dispersions_bad");
  std::string text = read_text_file(mission_deck());
  const std::size_t from = text.find("[dispersion.wind_speed]");
  const std::size_t to = text.find("[dispersion.wind_azimuth]", from);
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  std::string table = "[dispersion.wind_speed]\naltitude_ft = [";
  for (int i = 0; i < 40; ++i) table += std::to_string(i * 1000) + ".0, ";
  table += "]\nspeed_ft_s = [";
  for (int i = 0; i < 40; ++i) table += "10.0, ";
  table += "]\n\n";
  text.replace(from, to - from, table);
  const std::string deck = (scratch / "long_wind.toml").string();
  std::ofstream(deck) << text;
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("data block 53, dispersion code 36"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("40 points; the core holds at most 32"), std::string::npos) << run.err;
}

// One rule (tolip_ground/deck_table.hpp) hands every deck table of blocks 33-55 to the core; one
// point past the core's capacity is bad input naming the block and the field, for each reader.
TEST(Sec22DeckTables, OnePointPastTheCoreCapacityIsBadInputNamingBlockAndField) {
  ScratchDirectory scratch("deck_table_capacity");
  struct Case {
    const char* section;  // replaced up to the next blank line
    const char* x_key;
    const char* y_key;
    int points;
    std::vector<std::string> named;
  };
  const std::vector<Case> cases = {
      {"[body_dynamics.cg.1]",
       "stage_time_s",
       "station_in",
       11,
       {"data block 37", "body_dynamics.cg.1", "has 11 points; the core holds at most 10"}},
      {"[impact.failure_drag.1]",
       "mach",
       "cd",
       21,
       {"data block 42", "impact.failure_drag.1", "the drag table has 21 points; the core holds at most 20"}},
      {"[hardover.pitch_inertia.1]",
       "stage_time_s",
       "iyy_slug_ft2",
       11,
       {"data block 44", "hardover.pitch_inertia", "the table has 11 points; the core holds at most 10"}},
  };
  for (const Case& c : cases) {
    std::string text = read_text_file(mission_deck());
    const std::size_t from = text.find(c.section);
    ASSERT_NE(from, std::string::npos) << c.section;
    const std::size_t to = text.find("\n\n", from);
    ASSERT_NE(to, std::string::npos) << c.section;
    std::string table = std::string(c.section) + "\n";
    if (std::string(c.section).rfind("[impact", 0) == 0) table += "reference_area_ft2 = 8.7266\n";
    table += std::string(c.x_key) + " = [";
    for (int i = 0; i < c.points; ++i) table += std::to_string(i) + ".0, ";
    table += "]\n" + std::string(c.y_key) + " = [";
    for (int i = 0; i < c.points; ++i) table += "400.0, ";
    table += "]";
    text.replace(from, to - from, table);
    const std::string deck = (scratch / "long.toml").string();
    std::ofstream(deck) << text;
    const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
    EXPECT_EQ(run.exit_code, 2) << c.section << ": " << run.err;
    EXPECT_TRUE(run.out.empty()) << c.section;
    for (const std::string& name : c.named) {
      EXPECT_NE(run.err.find(name), std::string::npos) << c.section << ": " << name << "\n" << run.err;
    }
  }
}

// IP(7) = 0: the dispersions are about the optimum (point mass); the codes that act through the
// body dynamics are named, not skipped.
TEST(Sec15DispersionCommand, OptimumIsTheNominalWithoutLinearization) {
  ScratchDirectory scratch("dispersions_optimum");
  const std::string deck = edited_example_deck(scratch, "optimum.toml",
                                               {{"linearization = true ", "linearization = false "},
                                                {"body_dynamics_6d = 1 ", "body_dynamics_6d = 0 "}});
  ASSERT_FALSE(deck.empty());
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out, nullptr, false);
  const nlohmann::json& d = document["dispersions"];
  EXPECT_EQ(d["status"], "kOk");
  EXPECT_EQ(d["nominal_kind"], "optimum");
  for (const nlohmann::json& t : d["trajectories"]) {
    const int code = t["code"].get<int>();
    EXPECT_EQ(t["status"], (code >= 19 && code <= 23) ? "kDispersionNeedsBodyDynamics" : "kOk") << code;
  }
  // The nominal against the optimizer's final trajectory (docs/theory/dispersions.md).
  const nlohmann::json& last = document["trajectory"].back();
  EXPECT_LT(
      std::fabs(d["nominal"]["values"][3]["altitude_ft"].get<double>() - last["altitude_ft"].get<double>()),
      50.0);
  EXPECT_LT(std::fabs(d["nominal"]["values"][3]["velocity_ft_s"].get<double>() -
                      last["velocity_ft_s"].get<double>()),
            1.0);
  // The three-sigma groups leave the codes that did not fly out.
  EXPECT_EQ(d["three_sigma"]["high"]["codes"].size() + d["three_sigma"]["low"]["codes"].size(), 26u);
}

// Five stages without the manual's squeeze (docs/theory/dispersions.md): the example with an
// illustrative spun kick stage 5 (IP(9) = 1: on stage 4's attitudes) after a coast 9, its own
// dispersions given with `stage = 5` on codes 7 (thrust high: stage 5's tables, thrust x 1.03 and
// every time / 1.03) and 16 (weight increment low), and a stage-5 tip-off. Every stage's ignition is a
// column; stage 5's thrust and tip-off leave the columns before stage 5 ignition untouched, its
// lighter jettison weight speeds every stage, and each moves the final point with the expected sign; the card
// deck converted from it gives the same dispersions.
// The example with an illustrative spun kick stage 5 (IP(9) = 1: on stage 4's attitudes) after a
// coast 9 of 6 s, without its dispersion cases (the caller appends its own).
std::string five_stage_deck_text() {
  std::string text = read_text_file(mission_deck());
  const auto edit = [&text](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
  };
  edit("sequence = [1, 6, 2, 7, 3, 8, 4] ", "sequence = [1, 6, 2, 7, 3, 8, 4, 9, 5] ");
  edit("[launch]  # data blocks 20 and 21",
       "[stage.9]\nduration_s = 6.0\nintegration_steps = 3\njettison_weight_lb = 0.0\nreference_area_ft2 = "
       "0.0\n\n"
       "[stage.5]\nname = \"illustrative kick motor\"\nduration_s = 15.0\nintegration_steps = 12\n"
       "jettison_weight_lb = 30.0\nreference_area_ft2 = 1.0\nnozzle_exit_area_ft2 = 0.3\n\n"
       "[stage.5.thrust]\ntime_s = [0.0, 0.2, 14.8, 15.0]\nvacuum_thrust_lbf = [0.0, 1500.0, 1500.0, 0.0]\n\n"
       "[stage.5.consumable_weight]\ntime_s = [0.0, 0.2, 14.8, 15.0]\nremaining_lb = [80.0, 79.99, 0.01, "
       "0.0]\n\n"
       "[launch]  # data blocks 20 and 21");
  text.erase(text.find("[[dispersion]]"));
  return text;
}

TEST(Sec15DispersionCommand, FiveStageVehicleDispersesStage5WithoutTheSqueeze) {
  ScratchDirectory scratch("dispersions_five_stages");
  std::string text = five_stage_deck_text();
  text +=
      "\n[[dispersion]]\ncode = 7\ntitle = \"THRUST HI S5\"\nstage = 5\n"
      "[dispersion.thrust]\ntime_s = [0.0, 0.19417475728155337, 14.368932038834952, 14.563106796116505]\n"
      "vacuum_thrust_lbf = [0.0, 1545.0, 1545.0, 0.0]\n"
      "[dispersion.consumable_weight]\ntime_s = [0.0, 0.19417475728155337, 14.368932038834952, "
      "14.563106796116505]\nremaining_lb = [80.0, 79.99, 0.01, 0.0]\n\n"
      "[[dispersion]]\ncode = 16\ntitle = \"WEIGHT LO S5\"\nstage = 5\nweight_increment_lb = -3.0\n\n"
      "[[dispersion]]\ncode = 30\ntitle = \"TIPOFF HI S5\"\nstage = 5\ntipoff_deg = 2.0\n\n"
      "[[dispersion]]\ncode = 40\ntitle = \"NOMINAL TRAJ\"\n";
  const std::string deck = (scratch / "five_stages.toml").string();
  std::ofstream(deck) << text;
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out, nullptr, false)["dispersions"];
  ASSERT_EQ(d["status"], "kOk") << d.dump();
  ASSERT_EQ(d["staging_points"],
            nlohmann::json::array({"stage_2_ignition", "stage_3_ignition", "stage_4_ignition",
                                   "stage_5_ignition", "final_point"}));
  ASSERT_EQ(d["trajectories"].size(), 3u);
  for (const nlohmann::json& t : d["trajectories"]) {
    ASSERT_EQ(t["status"], "kOk") << t.dump();
    for (int j = 0; j < 4; ++j) {
      if (t["code"] == 16) {
        // Stage 5's jettison weight rides from the pad: lighter, faster at every ignition.
        EXPECT_GT(t["dispersions"][j]["velocity_ft_s"].get<double>(), 0.0) << " column " << j;
        continue;
      }
      for (const char* key : {"altitude_ft", "velocity_ft_s", "downrange_nmi"})
        EXPECT_EQ(t["dispersions"][j][key].get<double>(), 0.0) << t["code"] << " column " << j << " " << key;
    }
  }
  // Stage 5's thrust moves the final point; a lighter stage 5 is faster at burnout.
  EXPECT_NE(d["trajectories"][0]["dispersions"][4]["velocity_ft_s"].get<double>(), 0.0);
  EXPECT_GT(d["trajectories"][1]["dispersions"][4]["velocity_ft_s"].get<double>(), 0.0);
  EXPECT_NE(d["trajectories"][2]["dispersions"][4]["flight_path_angle_deg"].get<double>(), 0.0);

  const std::string cards = (scratch / "five_stages.dat").string();
  const CommandResult converted = run_tolip_executable({"convert", deck, "--to", cards});
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  const CommandResult card_run = run_tolip_executable({"optimize", cards, "--json"});
  ASSERT_EQ(card_run.exit_code, 0) << card_run.err;
  const nlohmann::json c = nlohmann::json::parse(card_run.out, nullptr, false)["dispersions"];
  ASSERT_EQ(c["trajectories"].size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const double a = d["trajectories"][k]["dispersions"][4]["velocity_ft_s"].get<double>();
    const double b = c["trajectories"][k]["dispersions"][4]["velocity_ft_s"].get<double>();
    EXPECT_NEAR(a, b, 1e-3 * std::fabs(a) + 1e-6) << k;
  }
}

// Manual page 22-30 and data block 55: the stacked five-stage form of codes 7-8 - stage 4's and
// stage 5's thrust and weight tables both in the stage-4 tables of blocks 30 and 38, the coast
// between them "input arbitrarily as two seconds", block 55 the two durations - flies through
// `tolip dispersions`, from TOML and from the card deck converted from it (the heritage form):
// code 7 stacks stage 4 high (the example's code-7 table: thrust x 1.03, time / 1.03) with stage 5
// high (restarting at stage time 0), code 8 stage 4 nominal with stage 5 high (continuing at
// 28 + 2 s). Code 8's stage 5 alone leaves every column before stage 5 ignition as the nominal's;
// code 7 moves stage 5 ignition. A block 55 duration that is not its part's final time is bad
// input: exit 2 naming data block 55 and the code, nothing flown.
TEST(Sec15DispersionCommand, StackedStage45TablesFlyFromTomlAndCards) {
  ScratchDirectory scratch("dispersions_stacked");
  const std::string high4_t =
      "0.0, 0.0971, 0.2427, 0.4854, 1.9417, 4.8544, 8.7379, 12.6214, 16.5049, 19.4175, 21.8447, 23.301, "
      "24.2718, 25.2427, 26.0194, 26.6019, 27.1845";
  const std::string high4_f =
      "0.0, 3159.5, 6003.1, 6319.2, 6192.8, 6129.5, 6192.8, 6319.2, 6382.3, 6319.2, 6129.5, 5687.1, 4739.3, "
      "3033.1, 1390.2, 442.4, 0.0";
  const std::string high4_w =
      "560.0, 559.448, 557.048, 551.669, 518.897, 454.347, 368.279, 280.888, 192.172, 125.636, 71.292, "
      "40.341, 22.135, 8.562, 2.383, 0.463, 0.0";
  const std::string nominal4_t =
      "0.0, 0.1, 0.25, 0.5, 2.0, 5.0, 9.0, 13.0, 17.0, 20.0, 22.5, 24.0, 25.0, 26.0, 26.8, 27.4, 28.0";
  const std::string nominal4_f =
      "0.0, 3067.5, 5828.3, 6135.1, 6012.4, 5951.0, 6012.4, 6135.1, 6196.4, 6135.1, 5951.0, 5521.5, 4601.3, "
      "2944.8, 1349.7, 429.5, 0.0";
  const std::string high5_t = "0.0, 0.19417475728155337, 14.368932038834952, 14.563106796116505";
  const std::string high5_f = "0.0, 1545.0, 1545.0, 0.0";
  const std::string high5_w = "80.0, 79.99, 0.01, 0.0";
  // Stage 4's nominal weights: the example's own block 38 table.
  std::string text = five_stage_deck_text();
  const std::size_t w4 = text.find("[stage.4.consumable_weight]");
  ASSERT_NE(w4, std::string::npos);
  const std::size_t w4_from = text.find("remaining_lb = [", w4) + 16;
  std::string nominal4_w = text.substr(w4_from, text.find(']', w4_from) - w4_from);
  while (!nominal4_w.empty() &&
         (std::isspace(static_cast<unsigned char>(nominal4_w.back())) != 0 || nominal4_w.back() == ','))
    nominal4_w.pop_back();
  const auto stacked = [](int code, const std::string& title, const std::string& t, const std::string& f,
                          const std::string& w, const std::string& durations) {
    return "\n[[dispersion]]\ncode = " + std::to_string(code) + "\ntitle = \"" + title +
           "\"\nstage_durations_s = [" + durations + "]\n[dispersion.thrust]\ntime_s = [" + t +
           "]\nvacuum_thrust_lbf = [" + f + "]\n[dispersion.consumable_weight]\ntime_s = [" + t +
           "]\nremaining_lb = [" + w + "]\n";
  };
  // Code 7: restarting (stage 4, coast 0-2 s, stage 5); code 8: continuing (stage 5 from 30 s).
  std::string continuing_t, continuing_t5;
  for (const double t : {0.0, 0.19417475728155337, 14.368932038834952, 14.563106796116505}) {
    std::ostringstream v;
    v.precision(17);
    v << 30.0 + t;
    continuing_t5 += (continuing_t5.empty() ? "" : ", ") + v.str();
  }
  text += stacked(7, "STACKED HI", high4_t + ", 0.0, 2.0, " + high5_t, high4_f + ", 0.0, 0.0, " + high5_f,
                  high4_w + ", 0.0, 0.0, " + high5_w, "27.1845, 14.563106796116505");
  const std::string code8 =
      stacked(8, "STACKED S5", nominal4_t + ", " + continuing_t5, nominal4_f + ", " + high5_f,
              nominal4_w + ", " + high5_w, "28.0, 14.563106796116505");
  const std::string deck = (scratch / "stacked.toml").string();
  std::ofstream(deck) << text + code8;
  const std::string cards = (scratch / "stacked.dat").string();
  const CommandResult converted = run_tolip_executable({"convert", deck, "--to", cards});
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  nlohmann::json results[2];
  for (int form = 0; form < 2; ++form) {
    SCOPED_TRACE(form == 0 ? "TOML" : "cards");
    const CommandResult run = run_tolip_executable({"dispersions", form == 0 ? deck : cards, "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const nlohmann::json d = nlohmann::json::parse(run.out, nullptr, false)["dispersions"];
    ASSERT_EQ(d["status"], "kOk") << d.dump();
    ASSERT_EQ(d["staging_points"].size(), 5u);
    ASSERT_EQ(d["trajectories"].size(), 2u);
    for (const nlohmann::json& t : d["trajectories"]) ASSERT_EQ(t["status"], "kOk") << t.dump();
    const nlohmann::json& both = d["trajectories"][0]["dispersions"];
    const nlohmann::json& stage5 = d["trajectories"][1]["dispersions"];
    EXPECT_NE(both[3]["velocity_ft_s"].get<double>(), 0.0);  // stage 4 high: stage 5 ignition moves
    for (int j = 0; j < 4; ++j) EXPECT_EQ(stage5[j]["velocity_ft_s"].get<double>(), 0.0) << j;
    EXPECT_NE(stage5[4]["velocity_ft_s"].get<double>(), 0.0);
    results[form] = d;
  }
  for (std::size_t k = 0; k < 2; ++k) {
    const double a = results[0]["trajectories"][k]["dispersions"][4]["velocity_ft_s"].get<double>();
    const double b = results[1]["trajectories"][k]["dispersions"][4]["velocity_ft_s"].get<double>();
    EXPECT_NEAR(a, b, 1e-3 * std::fabs(a) + 1e-6) << k;
  }

  // Block 55's stage 5 duration not the final time of stage 5's part: exit 2, block 55 and code 8
  // named, from TOML and from cards.
  const std::string bad = (scratch / "stacked_bad.toml").string();
  std::string bad_code8 = code8;
  bad_code8.replace(bad_code8.find("28.0, 14.563106796116505"), 24, "28.0, 14.0");
  std::ofstream(bad) << text + bad_code8;
  const std::string bad_cards = (scratch / "stacked_bad.dat").string();
  ASSERT_EQ(run_tolip_executable({"convert", bad, "--to", bad_cards}).exit_code, 0);
  for (const std::string& path : {bad, bad_cards}) {
    const CommandResult run = run_tolip_executable({"dispersions", path, "--json"});
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_TRUE(run.out.empty());
    EXPECT_NE(run.err.find("data block 55, dispersion code 8"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("kDispersionStageDurationsMismatch"), std::string::npos) << run.err;
  }

  // The stacked tables without block 55: the refilled weight is named with the form it needs, before
  // anything is optimized (dispersions and optimize alike), not as a failure of the analysis.
  const std::string unsplit = (scratch / "stacked_no55.toml").string();
  std::string no55_code8 = code8;
  const std::string block55 = "stage_durations_s = [28.0, 14.563106796116505]\n";
  no55_code8.replace(no55_code8.find(block55), block55.size(), "");
  std::ofstream(unsplit) << text + no55_code8;
  for (const char* command : {"dispersions", "optimize"}) {
    const CommandResult run = run_tolip_executable({command, unsplit, "--json"});
    EXPECT_EQ(run.exit_code, 2) << command << ": " << run.err;
    EXPECT_TRUE(run.out.empty()) << command;
    EXPECT_NE(run.err.find(unsplit + ": data block 38, dispersion code 8, dispersion[1].consumable_weight: "
                                     "kConsumableWeightIncreases: "),
              std::string::npos)
        << command << ": " << run.err;
    EXPECT_NE(run.err.find("it needs data block 55, stage_durations_s"), std::string::npos) << run.err;
  }
}

// `tolip dispersions` (the analysis alone, whatever IP(21) says) computes exactly what optimize's
// IP(21) = 1 step does: the same member, to the bit, and its CSV is optimize's --dispersions-csv.
TEST(Sec15DispersionsCommand, StandaloneAnalysisEqualsTheOptimizeStepBitForBit) {
  ScratchDirectory scratch("dispersions_standalone");
  const std::string csv = (scratch / "standalone.csv").string();
  const CommandResult run = run_tolip_executable({"dispersions", mission_deck(), "--json", "--csv", csv});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out);
  EXPECT_EQ(d["optimizer_status"], "kOk");
  ASSERT_TRUE(runs().document.contains("dispersions"));
  EXPECT_EQ(d["dispersions"], runs().document["dispersions"]);
  EXPECT_EQ(read_text_file(csv), read_text_file(runs().csv_path));
  const CommandResult listing = run_tolip_executable({"dispersions", mission_deck()});
  ASSERT_EQ(listing.exit_code, 0) << listing.err;
  EXPECT_NE(listing.out.find("THREE-SIGMA VARIATIONS"), std::string::npos);
  EXPECT_EQ(listing.out.find("ITERATION"), std::string::npos);  // the analysis alone
}

// A deck without data block 46 is bad input for the standalone command: exit 2, the block named,
// nothing on stdout and no CSV.
TEST(Sec15DispersionsCommand, DeckWithoutBlock46IsBadInputNamingTheBlock) {
  ScratchDirectory scratch("dispersions_none");
  const std::string csv = (scratch / "none.csv").string();
  const CommandResult run =
      run_tolip_executable({"dispersions", example_path("strapon/mission.toml"), "--csv", csv});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("data block 46 (dispersion)"), std::string::npos) << run.err;
  EXPECT_FALSE(std::ifstream(csv).good());
}

}  // namespace
}  // namespace tolip::test
