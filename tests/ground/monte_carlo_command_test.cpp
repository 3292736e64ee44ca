// `tolip montecarlo` end to end on examples/scout/mission.toml (issue 11 "Beyond the manual" and
// "Proof"; docs/cli.md "tolip montecarlo"): the same seed gives the same JSON and CSV bytes on 1, 2
// and 3 threads; with every source at 10 % of the deck's size (the linear regime) the mean stays
// within 3 standard errors of the nominal and the Monte Carlo three-sigma within 15 % of the
// manual's linear RSS three-sigma (Sec. 15) recomputed here from `tolip optimize`'s deterministic
// dispersions; the burnout ellipse holds about 99.7 % of the samples; bad input exits 2 naming the
// field, with nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "support/reference_data.hpp"
#include "support/repository_paths.hpp"

namespace tolip::test {
namespace {

TEST(MonteCarloCommand, SameSeedGivesTheSameJsonAndCsvOnOneTwoAndThreeThreads) {
  ScratchDirectory scratch("montecarlo_threads");
  std::string json[3];
  std::string csv[3];
  for (int t = 0; t < 3; ++t) {
    const std::string csv_path = (scratch / ("samples" + std::to_string(t + 1) + ".csv")).string();
    const CommandResult run =
        run_tolip_executable({"montecarlo", mission_deck(), "--samples", "30", "--seed", "2026", "--threads",
                              std::to_string(t + 1), "--json", "--csv", csv_path});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    json[t] = run.out;
    csv[t] = read_text_file(csv_path);
  }
  const nlohmann::json document = nlohmann::json::parse(json[0], nullptr, false);
  ASSERT_TRUE(document.is_object()) << json[0];
  EXPECT_EQ(document["samples"], 30);
  EXPECT_EQ(document["flown"], 30);
  EXPECT_EQ(document["nominal_kind"], "linearized program");
  EXPECT_EQ(document["staging_points"].size(), 4u);
  // The example sets IP(23): the casing impacts are in both outputs, and so compared too.
  ASSERT_EQ(document["impact_ellipses"].size(), 3u);
  EXPECT_EQ(document["impact_ellipses"][2]["impacted"], 30);
  EXPECT_NE(csv[0].find(",casing3_crossrange_nmi\n"), std::string::npos);
  for (int t = 1; t < 3; ++t) {
    EXPECT_EQ(json[0], json[t]) << t + 1 << " threads";
    EXPECT_EQ(csv[0], csv[t]) << t + 1 << " threads";
  }
  // 30 rows after the header, and another seed gives other samples.
  EXPECT_EQ(std::count(csv[0].begin(), csv[0].end(), '\n'), 31);
  const CommandResult other =
      run_tolip_executable({"montecarlo", mission_deck(), "--samples", "30", "--seed", "2027", "--json"});
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.out, json[0]);
}

// --progress forces the status line onto stderr (a terminal shows it by default); stdout is the
// same bytes as without it.
TEST(MonteCarloCommand, ProgressGoesToStderrOnlyAndChangesNoOutput) {
  const CommandResult quiet =
      run_tolip_executable({"montecarlo", mission_deck(), "--samples", "12", "--seed", "5", "--json"});
  const CommandResult shown = run_tolip_executable(
      {"montecarlo", mission_deck(), "--samples", "12", "--seed", "5", "--json", "--progress"});
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_EQ(quiet.out, shown.out);
  EXPECT_NE(shown.err.find("sample 12/12 (100%)"), std::string::npos) << shown.err;
  EXPECT_NE(shown.err.find("forward run"), std::string::npos) << shown.err;
  EXPECT_EQ(quiet.err.find("sample "), std::string::npos) << quiet.err;
}

// The example deck with every scalar source (blocks 47-52) at `scale` of its value and the table
// sources (thrust 1-8, C_M_alpha 19-20, winds 36-38) left out: their linear regime is proved on the
// reference data (MonteCarlo.TableSourcesSigmaAgreesWithTheRssSigmaInTheLinearRegime).
std::string scaled_deck(const ScratchDirectory& scratch, double scale) {
  const std::regex value(
      "^(weight_increment_lb|drag_variation_fraction|misalignment_deg|deadband_deg|tipoff_deg|"
      "launch_azimuth_change_deg|launch_attitude_change_deg) = (-?[0-9.]+)(.*)$");
  const std::regex table_code("^code = ([1-8]|19|20|36|37|38)$");
  // Cut the [[dispersion]] entries of the table codes (each runs to the next [[dispersion]]).
  std::string deck = read_text_file(mission_deck());
  std::string kept;
  int dropped = 0;
  for (std::size_t at = 0; at < deck.size();) {
    const std::size_t next = deck.find("[[dispersion]]", at + 1);
    const std::string entry = deck.substr(at, next == std::string::npos ? std::string::npos : next - at);
    std::istringstream entry_lines(entry);
    bool table = false;
    for (std::string line; std::getline(entry_lines, line);)
      table = table || std::regex_match(line, table_code);
    if (table && entry.rfind("[[dispersion]]", 0) == 0) {
      ++dropped;
    } else {
      kept += entry;
    }
    at = (next == std::string::npos) ? deck.size() : next;
  }
  EXPECT_EQ(dropped, 13);
  std::istringstream lines(kept);
  std::string text;
  int edited = 0;
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (std::regex_match(line, m, value)) {
      std::ostringstream number;
      number.precision(17);
      number << std::stod(m[2].str()) * scale;
      line = m[1].str() + " = " + number.str() + m[3].str();
      ++edited;
    }
    text += line + "\n";
  }
  EXPECT_EQ(edited, 25);  // codes 9-18 and 21-35 of the example
  const std::string path = (scratch / "scaled.toml").string();
  std::ofstream(path) << text;
  return path;
}

// Linear regime (every source at 10 %): the Monte Carlo against the manual's RSS, both from the
// command and recomputed from the deterministic dispersions of `tolip optimize` on the same deck.
TEST(MonteCarloCommand, Sec15SigmaAgreesWithTheRssSigmaInTheLinearRegime) {
  ScratchDirectory scratch("montecarlo_linear");
  const std::string deck = scaled_deck(scratch, 0.1);
  const int n = 400;
  const CommandResult run = run_tolip_executable(
      {"montecarlo", deck, "--samples", std::to_string(n), "--seed", "11", "--threads", "2", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json mc = nlohmann::json::parse(run.out, nullptr, false);
  ASSERT_TRUE(mc.is_object());
  ASSERT_EQ(mc["flown"], n);
  const CommandResult linear = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(linear.exit_code, 0) << linear.err;
  const nlohmann::json d = nlohmann::json::parse(linear.out, nullptr, false)["dispersions"];
  ASSERT_EQ(d["status"], "kOk");
  const nlohmann::json& final_point = mc["staging_points"][3];
  ASSERT_EQ(final_point["point"], "final_point");
  for (const char* key :
       {"altitude_ft", "velocity_ft_s", "flight_path_angle_deg", "downrange_nmi", "crossrange_nmi"}) {
    // RSS over the codes the Monte Carlo draws (one per high/low pair, each yaw code).
    double squares = 0.0;
    int members = 0;
    for (const nlohmann::json& code : mc["sampled_codes"]) {
      for (const nlohmann::json& t : d["trajectories"]) {
        if (t["code"] != code) continue;
        ASSERT_EQ(t["status"], "kOk") << code;
        const double x = t["dispersions"][3][key].get<double>();
        squares += x * x;
        ++members;
      }
    }
    ASSERT_EQ(members, static_cast<int>(mc["sampled_codes"].size()));
    const double rss = std::sqrt(squares);
    const nlohmann::json& q = final_point[key];
    EXPECT_NEAR(q["rss_3sigma"].get<double>(), rss, 1e-9 * rss) << key;
    const double sigma = q["standard_deviation"].get<double>();
    std::printf("final %s: Monte Carlo 3-sigma %.6g, RSS 3-sigma %.6g (ratio %.3f), mean %.4g\n", key,
                3.0 * sigma, rss, 3.0 * sigma / rss, q["mean"].get<double>());
    EXPECT_NEAR(3.0 * sigma / rss, 1.0, 0.15) << key;
    // Symmetric sources: the mean dispersion within 3 standard errors of the nominal (zero).
    EXPECT_LT(std::fabs(q["mean"].get<double>()), 3.0 * sigma / std::sqrt(n)) << key;
    EXPECT_LT(q["p00135"].get<double>(), q["p50"].get<double>()) << key;
    EXPECT_LT(q["p50"].get<double>(), q["p99865"].get<double>()) << key;
  }
  // The 99.7 % ellipse of the burnout point holds about 99.7 % of the samples (of 400: at most a
  // handful outside), and every sample reaches orbit.
  const nlohmann::json& e = mc["burnout_ellipse"];
  EXPECT_GT(e["fraction_inside"].get<double>(), 0.985);
  EXPECT_GT(e["semi_major_nmi"].get<double>(), e["semi_minor_nmi"].get<double>());
  EXPECT_EQ(mc["fraction_reaching_orbit"], 1.0);
}

// Casing impacts (Sec. 17, data block 43) in the linear regime: on by default under IP(23) = 1, each
// stage's nominal impact is the casing line of `tolip optimize`'s impact locus about the same
// nominal, every sample's casing impacts, and the 99.7 % ellipse of the impact points holds about
// 99.7 % of them (of 300: at most a handful outside); the listing and the CSV carry them too.
TEST(MonteCarloCommand, Sec17CasingImpactEllipsesHoldAbout99_7PercentInTheLinearRegime) {
  ScratchDirectory scratch("montecarlo_impacts");
  const std::string deck = scaled_deck(scratch, 0.1);
  const int n = 300;
  const std::string csv = (scratch / "impacts.csv").string();
  const CommandResult run = run_tolip_executable({"montecarlo", deck, "--samples", std::to_string(n),
                                                  "--seed", "13", "--threads", "2", "--json", "--csv", csv});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json mc = nlohmann::json::parse(run.out, nullptr, false);
  ASSERT_TRUE(mc.is_object());
  ASSERT_EQ(mc["flown"], n);
  const CommandResult optimize = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(optimize.exit_code, 0) << optimize.err;
  const nlohmann::json locus = nlohmann::json::parse(optimize.out, nullptr, false)["impact"]["cases"];
  ASSERT_TRUE(locus.is_array());
  ASSERT_EQ(mc["impact_ellipses"].size(), 3u);
  for (int stage = 1; stage <= 3; ++stage) {
    const nlohmann::json& c = mc["impact_ellipses"][stage - 1];
    EXPECT_EQ(c["stage"], stage);
    EXPECT_EQ(c["impacted"], n);
    EXPECT_EQ(c["not_impacted"], 0);
    const nlohmann::json* line = nullptr;
    for (const nlohmann::json& row : locus) {
      if (row["kind"] == "expended_casing" && row["stage"] == stage) line = &row;
    }
    ASSERT_NE(line, nullptr) << stage;
    for (const char* key :
         {"impact_time_s", "geodetic_latitude_deg", "longitude_deg", "downrange_nmi", "crossrange_nmi"}) {
      EXPECT_EQ(c["nominal"][key], (*line)[key]) << stage << " " << key;
    }
    const nlohmann::json& e = c["ellipse"];
    std::printf(
        "stage %d casing: nominal %.3f n.mi. downrange; ellipse %.4f x %.4f n.mi. at %.2f deg, %.4f "
        "inside\n",
        stage, c["nominal"]["downrange_nmi"].get<double>(), e["semi_major_nmi"].get<double>(),
        e["semi_minor_nmi"].get<double>(), e["major_axis_angle_deg"].get<double>(),
        e["fraction_inside"].get<double>());
    EXPECT_GT(e["fraction_inside"].get<double>(), 0.985) << stage;
    EXPECT_GT(e["semi_major_nmi"].get<double>(), e["semi_minor_nmi"].get<double>());
    EXPECT_GT(e["semi_minor_nmi"].get<double>(), 0.0);
    // Symmetric sources: the mean impact within 3 standard errors (the ellipse's axes / 3.41 are
    // sigmas) of the nominal.
    const double sigma = e["semi_major_nmi"].get<double>() / std::sqrt(-2.0 * std::log(0.003));
    EXPECT_LT(std::hypot(e["center_downrange_nmi"].get<double>(), e["center_crossrange_nmi"].get<double>()),
              3.0 * sigma / std::sqrt(n) * std::sqrt(2.0))
        << stage;
  }
  const std::string rows = read_text_file(csv);
  EXPECT_NE(rows.find(",casing1_status,casing1_impact_time_s,casing1_geodetic_latitude_deg,"),
            std::string::npos);
  EXPECT_NE(rows.find(",casing3_crossrange_nmi\n"), std::string::npos);
  const CommandResult listing =
      run_tolip_executable({"montecarlo", deck, "--samples", "6", "--seed", "13", "--no-progress"});
  ASSERT_EQ(listing.exit_code, 0) << listing.err;
  EXPECT_NE(listing.out.find(" STAGE 2 CASING 1650.0 LB  NOMINAL IMPACT:"), std::string::npos) << listing.out;
  EXPECT_NE(listing.out.find("   99.7 % ELLIPSE (DISPERSION FROM THE NOMINAL IMPACT)"), std::string::npos);
}

// Off (--no-impacts, or a deck without IP(23) and no --impacts): the JSON and CSV of before the
// casing impacts, byte for byte the same either way; --impact-stages flies only the stages named.
TEST(MonteCarloCommand, Sec17NoImpactsLeavesTheOutputsAsWithoutTheImpactAnalysis) {
  ScratchDirectory scratch("montecarlo_no_impacts");
  const std::string off_deck =
      edited_example_deck(scratch, "ip23_off.toml", {{"impact = true ", "impact = false "}});
  const std::string csv_a = (scratch / "a.csv").string();
  const std::string csv_b = (scratch / "b.csv").string();
  const CommandResult a = run_tolip_executable({"montecarlo", mission_deck(), "--samples", "6", "--seed", "4",
                                                "--json", "--no-impacts", "--csv", csv_a});
  const CommandResult b = run_tolip_executable(
      {"montecarlo", off_deck, "--samples", "6", "--seed", "4", "--json", "--csv", csv_b});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(a.out.find("impact_ellipses"), std::string::npos);
  EXPECT_EQ(read_text_file(csv_a).find("casing"), std::string::npos);
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(read_text_file(csv_a), read_text_file(csv_b));
  const nlohmann::json jb = nlohmann::json::parse(b.out, nullptr, false);
  // Asked for on the deck without IP(23): the casings of stages 1 and 3 only.
  const CommandResult some = run_tolip_executable(
      {"montecarlo", off_deck, "--samples", "6", "--seed", "4", "--json", "--impact-stages", "1,3"});
  ASSERT_EQ(some.exit_code, 0) << some.err;
  const nlohmann::json js = nlohmann::json::parse(some.out, nullptr, false);
  ASSERT_EQ(js["impact_ellipses"].size(), 2u);
  EXPECT_EQ(js["impact_ellipses"][0]["stage"], 1);
  EXPECT_EQ(js["impact_ellipses"][1]["stage"], 3);
  EXPECT_EQ(js["staging_points"], jb["staging_points"]);  // the samples themselves are unchanged
}

// A perigee threshold above every sample's perigee: no sample reaches orbit; the listing says so.
TEST(MonteCarloCommand, OrbitThresholdIsTheCommandLines) {
  const CommandResult run = run_tolip_executable(
      {"montecarlo", mission_deck(), "--samples", "8", "--seed", "3", "--orbit-perigee-nmi", "5000"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("REACHING ORBIT (PERIGEE ABOVE 5000.000 NMI): 0 OF 8"), std::string::npos)
      << run.out;
  EXPECT_NE(run.out.find("FINAL POINT"), std::string::npos);
}

TEST(MonteCarloCommand, PlotsAreDrawnIntoTheDirectory) {
  ScratchDirectory scratch("montecarlo_plots");
  const std::string dir = (scratch / "plots").string();
  const CommandResult run =
      run_tolip_executable({"montecarlo", mission_deck(), "--samples", "20", "--seed", "1", "--plots", dir});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name :
       {"montecarlo_burnout_altitude", "montecarlo_burnout_velocity", "montecarlo_burnout_flight_path_angle",
        "montecarlo_perigee_apogee", "montecarlo_rss_comparison", "montecarlo_burnout_point",
        "montecarlo_stage1_casing_impacts", "montecarlo_stage2_casing_impacts",
        "montecarlo_stage3_casing_impacts"}) {
    for (const char* extension : {".png", ".svg"}) {
      const std::filesystem::path file = std::filesystem::path(dir) / (std::string(name) + extension);
      EXPECT_TRUE(std::filesystem::exists(file)) << file;
    }
  }
}

// The casing impact and burnout point figures put downrange and crossrange, both n.mi., at equal axis scale
// (gnuplot `set size ratio -1`), so that the 99.7 % ellipse is drawn with its true shape; the histograms keep
// the terminal's shape. The script is caught by a stand-in gnuplot that copies it and fails.
TEST(MonteCarloCommand, Sec17CasingImpactAndBurnoutPointFiguresAreDrawnAtEqualAxisScale) {
  ScratchDirectory scratch("montecarlo_equal_axes");
  const std::filesystem::path caught = scratch / "caught.gp";
  const std::string fake = (scratch / "fake_gnuplot.sh").string();
  std::ofstream(fake) << "#!/bin/sh\ncp \"$1\" " << shell_quote(caught.string()) << "\nexit 3\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const CommandResult run =
      run_tolip_executable({"montecarlo", mission_deck(), "--samples", "8", "--seed", "1", "--plots",
                            (scratch / "plots").string(), "--gnuplot", fake});
  EXPECT_EQ(run.exit_code, 1) << "the stand-in gnuplot fails: " << run.err;
  const std::string script = read_text_file(caught);
  // Each figure's commands run from its `set output` to the next `unset output`.
  const auto commands_of = [&script](const std::string& output) {
    const std::size_t from = script.find("set output \"" + output + "\"");
    if (from == std::string::npos) return std::string();
    return script.substr(from, script.find("unset output", from) - from);
  };
  for (const char* figure : {"montecarlo_stage1_casing_impacts", "montecarlo_stage2_casing_impacts",
                             "montecarlo_stage3_casing_impacts", "montecarlo_burnout_point"}) {
    for (const char* extension : {".png", ".svg"}) {
      const std::string name = std::string(figure) + extension;
      const std::string commands = commands_of(name);
      ASSERT_FALSE(commands.empty()) << name << " not in the script";
      EXPECT_NE(commands.find("\nset size ratio -1\n"), std::string::npos) << name;
    }
  }
  const std::string histogram = commands_of("montecarlo_burnout_altitude.png");
  ASSERT_FALSE(histogram.empty());
  EXPECT_EQ(histogram.find("set size ratio"), std::string::npos);
}

// Bad input: exit 2, the field named, nothing on stdout, no CSV and no plot directory.
void expect_bad_input(const ScratchDirectory& scratch, std::vector<std::string> arguments,
                      const std::string& message) {
  const std::string csv = (scratch / "never.csv").string();
  const std::string plots = (scratch / "never_plots").string();
  arguments.insert(arguments.end(), {"--csv", csv, "--plots", plots});
  std::string command = shell_quote(tolip::repository_paths::tolip_executable());
  for (const std::string& argument : arguments) command += " " + shell_quote(argument);
  const std::filesystem::path err_path = stderr_path("tolip_mc_stderr_");
  const CommandResult run = run_capturing(command + " 2>" + shell_quote(err_path.string()), err_path);
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(csv));
  EXPECT_FALSE(std::filesystem::exists(plots));
}

TEST(MonteCarloCommand, BadInputExitsTwoNamingTheFieldAndWritesNothing) {
  ScratchDirectory scratch("montecarlo_bad");
  const std::string deck = mission_deck();
  expect_bad_input(scratch, {"montecarlo", deck, "--samples", "0", "--seed", "1"},
                   "--samples 0: expected 1 to 100000 samples");
  expect_bad_input(scratch, {"montecarlo", deck, "--samples", "100001", "--seed", "1"},
                   "--samples 100001: expected 1 to 100000 samples");
  expect_bad_input(scratch, {"montecarlo", deck, "--samples", "many", "--seed", "1"}, "--samples");
  expect_bad_input(scratch, {"montecarlo", deck, "--samples", "5"}, "--seed");
  expect_bad_input(scratch, {"montecarlo", deck, "--samples", "5", "--seed", "1", "--threads", "0"},
                   "--threads 0: expected 1 to 256");
  expect_bad_input(scratch,
                   {"montecarlo", deck, "--samples", "5", "--seed", "1", "--orbit-perigee-nmi", "-1"},
                   "--orbit-perigee-nmi -1: expected 0 to 100000 n.mi.");
  // A high code with a negative value: a negative sigma, named by block, code and key.
  const std::string negative = edited_example_deck(
      scratch, "negative.toml", {{"weight_increment_lb = 150.0 ", "weight_increment_lb = -150.0 "}});
  expect_bad_input(scratch, {"montecarlo", negative, "--samples", "5", "--seed", "1"},
                   "data block 47, dispersion code 9 (weight increment high, stage 1), "
                   "dispersion[8].weight_increment_lb = -150: a negative Monte Carlo sigma (-50 lb)");
  // A low code with a positive value: the same rule.
  const std::string low =
      edited_example_deck(scratch, "low.toml", {{"deadband_deg = -0.5 ", "deadband_deg = 0.5 "}});
  expect_bad_input(scratch, {"montecarlo", low, "--samples", "5", "--seed", "1"},
                   "data block 50, dispersion code 25 (control system deadband low, stage 2)");
  // An unknown code (39 is not in the manual's table).
  const std::string unknown = edited_example_deck(scratch, "unknown.toml", {{"code = 40", "code = 39"}});
  expect_bad_input(scratch, {"montecarlo", unknown, "--samples", "5", "--seed", "1"},
                   "unknown dispersion code 39");
  // A replacement table that breaks the block 38 rules (the remaining weight rises): named at the
  // boundary by block, code and key, not reported after the flights as "the nominal did not fly".
  const std::string code1_weights =
      "  42.233, 42.8155, 43.301, 43.6893,\n]\nremaining_lb = [\n  20200.0, 20186.468,";  // code 1's (times
                                                                                          // / 1.03)
  std::string rising_weights = code1_weights;
  rising_weights.replace(rising_weights.find("20186.468"), 9, "20286.468");
  const std::string rising = edited_example_deck(scratch, "rising.toml", {{code1_weights, rising_weights}});
  expect_bad_input(scratch, {"montecarlo", rising, "--samples", "5", "--seed", "1"},
                   "data block 38, dispersion code 1, dispersion[0].consumable_weight: "
                   "kConsumableWeightIncreases: ");
  // A code without its data block.
  const std::string missing =
      edited_example_deck(scratch, "missing.toml", {{"weight_increment_lb = 150.0 ", "# "}});
  expect_bad_input(scratch, {"montecarlo", missing, "--samples", "5", "--seed", "1"}, "data block 47");
  // No dispersion data at all: every [[dispersion]] removed (and IP(21) off, which requires them).
  std::string text = read_text_file(deck);
  text.erase(text.find("[[dispersion]]"));
  const std::size_t ip21 = text.find("dispersions = true");
  ASSERT_NE(ip21, std::string::npos);
  text.replace(ip21, 18, "dispersions = false");
  const std::string none = (scratch / "none.toml").string();
  std::ofstream(none) << text;
  expect_bad_input(scratch, {"montecarlo", none, "--samples", "5", "--seed", "1"},
                   "data block 46: no dispersion source the Monte Carlo draws");
}

// Casings asked for without their data: exit 2 naming data block 43, the table and the deck field;
// no [impact] at all; a stage outside 1-3; --impacts with --no-impacts.
TEST(MonteCarloCommand, Sec17ImpactsWithoutBlock43DataAreBadInputNamingTheBlock) {
  ScratchDirectory scratch("montecarlo_impacts_bad");
  // IP(23) off (it would require every table), then the stage-2 casing table cut from the deck.
  const std::string ip23_off =
      read_text_file(edited_example_deck(scratch, "ip23_off.toml", {{"impact = true ", "impact = false "}}));
  const auto cut = [&](const std::string& from, const std::string& to, const std::string& name) {
    std::string text = ip23_off;
    const std::size_t a = text.find(from);
    const std::size_t b = text.find(to);
    EXPECT_NE(a, std::string::npos);
    EXPECT_NE(b, std::string::npos);
    text.erase(a, b - a);
    const std::string path = (scratch / name).string();
    std::ofstream(path) << text;
    return path;
  };
  const std::string no_stage2 = cut("[impact.casing_drag.2]", "[impact.casing_drag.3]", "no_cd2e.toml");
  expect_bad_input(scratch, {"montecarlo", no_stage2, "--samples", "5", "--seed", "1", "--impacts"},
                   "data block 43, CD2E (impact.casing_drag.2): missing: --impacts needs the data block 43 "
                   "drag table of stage 2");
  const std::string none = cut("[impact.failure_drag.1]", "# Data blocks 44-45", "no_impact.toml");
  expect_bad_input(
      scratch, {"montecarlo", none, "--samples", "5", "--seed", "1", "--impact-stages", "1,3"},
      "data block 43 (impact.casing_drag): --impact-stages needs the expended-casing drag tables");
  expect_bad_input(scratch,
                   {"montecarlo", mission_deck(), "--samples", "5", "--seed", "1", "--impact-stages", "4"},
                   "--impact-stages 4: expected stages 1 to 3");
  expect_bad_input(
      scratch, {"montecarlo", mission_deck(), "--samples", "5", "--seed", "1", "--impacts", "--no-impacts"},
      "--impacts");
}

}  // namespace
}  // namespace tolip::test
