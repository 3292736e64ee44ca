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
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "cli_runner.hpp"

namespace tolip::test {
namespace {

std::string mission_deck() { return std::string(TOLIP_EXAMPLES_DIR) + "/scout/mission.toml"; }

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
        "montecarlo_perigee_apogee", "montecarlo_rss_comparison"}) {
    for (const char* extension : {".png", ".svg"}) {
      const std::filesystem::path file = std::filesystem::path(dir) / (std::string(name) + extension);
      EXPECT_TRUE(std::filesystem::exists(file)) << file;
    }
  }
}

// Bad input: exit 2, the field named, nothing on stdout, no CSV and no plot directory.
void expect_bad_input(const ScratchDirectory& scratch, std::vector<std::string> arguments,
                      const std::string& message) {
  const std::string csv = (scratch / "never.csv").string();
  const std::string plots = (scratch / "never_plots").string();
  arguments.insert(arguments.end(), {"--csv", csv, "--plots", plots});
  std::string command = shell_quote(TOLIP_EXECUTABLE);
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

}  // namespace
}  // namespace tolip::test
