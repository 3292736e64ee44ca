// Sec. 22 "OUTPUT FORMAT": `tolip optimize --listing-level final|full|runs` (docs/cli.md "Listing
// levels"). Every column of the third line group is checked against a computation that does not
// go through it: CHI against the JSON trajectory, THETADOT against finite differences of THETAC in
// the same listing (on the linearized trajectory, flown without the optimizer's closed loop), DTHETA
// of the linearized trajectory against its THETA minus the final
// trajectory's THETA at the same time and stage, DELTA present on 6D points only; data block 9's
// frequencies against the points of the initial nominal (simulate --json of the same deck), by
// time and stage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"

namespace tolip::test {
namespace {

constexpr int kCell = 11;

// A cell of a value line: NaN for "-" (and for a blank cell).
double cell(const std::string& line, int k) {
  const std::size_t at = static_cast<std::size_t>(k * kCell);
  if (at >= line.size()) return std::nan("");
  std::string text = line.substr(at, kCell);
  text.erase(0, text.find_first_not_of(' '));
  if (text.empty() || text == "-") return std::nan("");
  return std::strtod(text.c_str(), nullptr);
}

bool numeric_line(const std::string& line) {
  if (line.empty()) return false;
  static const std::regex numbers(R"(^( *(-?[0-9]+\.[0-9]+|-))+$)");
  return std::regex_match(line, numbers);
}

// One listed point: its value lines (2, or 3 with all columns) and its stage label.
struct ListedPoint {
  std::string stage_label;
  std::vector<std::string> lines;
  double time() const { return cell(lines[0], 0); }
  double theta() const { return cell(lines[1], 2); }
  double column3(int k) const { return lines.size() > 2 ? cell(lines[2], k) : std::nan(""); }
};

// The listed points of every section (the page header's section name) of a listing.
std::map<std::string, std::vector<ListedPoint>> listed_points(const std::string& listing) {
  static const std::regex header(R"(TOLIP \S+   (.+)   PAGE [0-9]+$)");
  std::map<std::string, std::vector<ListedPoint>> out;
  std::istringstream in(listing);
  std::string section;
  std::string stage;
  ListedPoint point;
  const auto flush = [&]() {
    if (!point.lines.empty()) out[section].push_back(point);
    point = ListedPoint{};
  };
  for (std::string line; std::getline(in, line);) {
    std::smatch match;
    if (std::regex_search(line, match, header)) {
      flush();
      section = match[1];
      continue;
    }
    if (line.rfind(" STAGE ", 0) == 0 || line.rfind(" COAST AFTER STAGE ", 0) == 0) {
      flush();
      stage = line;
      continue;
    }
    if (numeric_line(line)) {
      if (point.lines.empty()) point.stage_label = stage;
      point.lines.push_back(line);
    } else {
      flush();
    }
  }
  flush();
  return out;
}

struct Runs {
  CommandResult final_level;
  CommandResult default_level;
  CommandResult full_level;
  CommandResult json;
  CommandResult json_full;
};

const Runs& example_runs() {
  static Runs* runs = nullptr;
  if (runs == nullptr) {
    runs = new Runs;
    const std::string deck = std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml";
    runs->final_level = run_tolip_executable({"optimize", deck, "--no-progress", "--listing-level", "final"});
    runs->default_level = run_tolip_executable({"optimize", deck, "--no-progress"});
    runs->full_level = run_tolip_executable({"optimize", deck, "--no-progress", "--listing-level", "full"});
    runs->json = run_tolip_executable({"optimize", deck, "--no-progress", "--json"});
    runs->json_full =
        run_tolip_executable({"optimize", deck, "--no-progress", "--json", "--listing-level", "full"});
  }
  return *runs;
}

TEST(ListingLevel, Sec22_DefaultIsTheFinalLevelAndTheJsonIgnoresTheLevel) {
  const Runs& r = example_runs();
  ASSERT_EQ(r.final_level.exit_code, 0) << r.final_level.err;
  EXPECT_EQ(r.default_level.out, r.final_level.out);
  EXPECT_EQ(r.json_full.out, r.json.out);
  // The default has two line groups: no page carries the third group's headings.
  EXPECT_EQ(r.final_level.out.find("BETA6D"), std::string::npos);
  EXPECT_NE(r.full_level.out.find("BETA6D"), std::string::npos);
  const CommandResult bad = run_tolip_executable(
      {"optimize", std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml",
       "--listing-level", "all"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(contains(bad.err, "--listing-level")) << bad.err;
}

// The upper stage numbers of a stage label (" STAGE 4 (POWERED)" 4, " COAST AFTER STAGE 3" 8).
int stage_code_of(const std::string& label) {
  static const std::regex number(R"(STAGE ([0-9]+))");
  std::smatch match;
  if (!std::regex_search(label, match, number)) return 0;
  const int n = std::stoi(match[1]);
  return label.rfind(" COAST", 0) == 0 ? n + 5 : n;
}

// THETADOT against (THETAC[i+1] - THETAC[i]) / (TIME[i+1] - TIME[i]) where both points start a
// step of the program (a numeric THETADOT) in the same stage, with the printed precision: THETAC
// to 1e-4 deg, TIME to 1e-3 s. Returns the points checked.
int check_rates(const std::vector<ListedPoint>& points, const char* name) {
  int checked = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const ListedPoint& p = points[i];
    const ListedPoint& q = points[i + 1];
    if (q.stage_label != p.stage_label || std::isnan(p.column3(3)) || std::isnan(q.column3(3))) continue;
    const double dt = q.time() - p.time();
    const double difference = (q.column3(2) - p.column3(2)) / dt;
    const double tolerance = 1.1e-4 / dt + std::fabs(difference) * 1.1e-3 / dt + 1e-4;
    EXPECT_NEAR(p.column3(3), difference, tolerance) << name << ": THETADOT at t = " << p.time();
    ++checked;
  }
  return checked;
}

// CHI against the JSON trajectory (time matched); THETAC = THETA on the point-mass final
// trajectory; DELTA "-" there; BETA6D within the pitch plane's tilt (the geodetic - geocentric
// vertical, 0.18 deg at the pad) while stages 1-3 fly chi = 0, and beyond it in the spun stage 4
// and the coast before it, whose attitude is held while the velocity turns.
TEST(ListingLevel, Sec22_FinalTrajectoryColumnsAgreeWithIndependentComputation) {
  const Runs& r = example_runs();
  ASSERT_EQ(r.full_level.exit_code, 0) << r.full_level.err;
  const auto sections = listed_points(r.full_level.out);
  ASSERT_TRUE(sections.count("FINAL TRAJECTORY"));
  const std::vector<ListedPoint>& points = sections.at("FINAL TRAJECTORY");
  const nlohmann::json document = nlohmann::json::parse(r.json.out);
  const nlohmann::json& trajectory = document.at("trajectory");
  ASSERT_EQ(points.size(), trajectory.size());
  double beta_lower = 0.0;
  double beta_upper = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ListedPoint& p = points[i];
    ASSERT_EQ(p.lines.size(), 3u) << i;
    const nlohmann::json& j = trajectory[i];
    ASSERT_NEAR(p.time(), j.at("time_s").get<double>(), 5e-4) << i;
    ASSERT_EQ(stage_code_of(p.stage_label), j.at("stage").get<int>()) << i;
    EXPECT_NEAR(p.column3(0), j.at("chi_deg").get<double>(), 5.1e-5) << i;  // CHI, 4 decimals
    EXPECT_NEAR(p.column3(2), p.theta(), 1.1e-4) << i;                      // THETAC = THETA
    EXPECT_TRUE(std::isnan(p.column3(5))) << i;                             // no DELTA
    ASSERT_FALSE(std::isnan(p.column3(1))) << i;
    const int code = stage_code_of(p.stage_label);
    double& beta = (code == 4 || code == 8) ? beta_upper : beta_lower;
    beta = std::fmax(beta, std::fabs(p.column3(1)));
  }
  EXPECT_LT(beta_lower, 0.5);
  EXPECT_GT(beta_upper, 0.5);
}

// The linearized trajectory (6D with the example's IP(6) = 1): DTHETA = its THETA minus the final
// trajectory's at the same time and stage; DELTA printed exactly on stage 1 and coast 6 points
// after lift-off; the linearization runs' programs, one per forward linearization run.
TEST(ListingLevel, Sec22_LinearizedTrajectoryListedWithDthetaAgainstTheOptimum) {
  const Runs& r = example_runs();
  const auto sections = listed_points(r.full_level.out);
  ASSERT_TRUE(sections.count("LINEARIZED TRAJECTORY (6D)")) << "sections: " << sections.size();
  const std::vector<ListedPoint>& linearized = sections.at("LINEARIZED TRAJECTORY (6D)");
  std::map<std::pair<std::string, long long>, double> optimum_theta;
  for (const ListedPoint& p : sections.at("FINAL TRAJECTORY")) {
    optimum_theta[{p.stage_label, std::llround(p.time() * 1000.0)}] = p.theta();
  }
  int matched = 0;
  int six_d = 0;
  for (const ListedPoint& p : linearized) {
    const auto it = optimum_theta.find({p.stage_label, std::llround(p.time() * 1000.0)});
    if (it != optimum_theta.end() && !std::isnan(p.column3(4))) {
      EXPECT_NEAR(p.column3(4), p.theta() - it->second, 2.1e-4) << "DTHETA at t = " << p.time();
      ++matched;
    }
    const bool stage1 = p.stage_label.rfind(" STAGE 1 ", 0) == 0 || p.stage_label == " COAST AFTER STAGE 1";
    if (!std::isnan(p.column3(5))) {
      EXPECT_TRUE(stage1) << p.stage_label << " t = " << p.time();
      ++six_d;
    }
  }
  EXPECT_GT(matched, 200);
  EXPECT_GT(six_d, 40);
  // Flown with the program alone (no closed loop rewriting it between steps, as the optimizer's
  // runs do), so THETAC at the next point is the step's end command.
  EXPECT_GT(check_rates(linearized, "linearized"), 150);
  const nlohmann::json document = nlohmann::json::parse(r.json.out);
  const int runs = document.at("linearized").at("forward_runs").get<int>();
  ASSERT_GT(runs, 0);
  int printed = 0;
  for (std::size_t at = r.full_level.out.find(" LINEARIZATION RUN "); at != std::string::npos;
       at = r.full_level.out.find(" LINEARIZATION RUN ", at + 1)) {
    ++printed;
  }
  EXPECT_EQ(printed, runs);
}

// Sec. 14: per powered stage, A, B and the scale A/B as printed agree.
TEST(ListingLevel, Sec14_ThrustModificationPageListsIdealVelocitiesAndTables) {
  const Runs& r = example_runs();
  std::istringstream in(r.full_level.out);
  static const std::regex number(R"(=\s*(-?[0-9.]+))");
  std::vector<double> a;
  std::vector<double> b;
  std::vector<double> scale;
  for (std::string line; std::getline(in, line);) {
    std::smatch match;
    if (!std::regex_search(line, match, number)) continue;
    const double value = std::stod(match[1]);
    if (contains(line, "INPUT TABLE       A =")) a.push_back(value);
    if (contains(line, "INTERPOLATED TABLE B =")) b.push_back(value);
    if (contains(line, "SCALE A/B")) scale.push_back(value);
  }
  ASSERT_EQ(a.size(), 4u);  // the example's four powered stages
  ASSERT_EQ(b.size(), 4u);
  ASSERT_EQ(scale.size(), 4u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_GT(a[k], 1000.0);
    EXPECT_NEAR(scale[k], a[k] / b[k], 1e-8 + 1e-4 / b[k]) << k;
  }
}

// Data block 9: a deck whose initial and intermediate frequencies are not 1 lists the initial
// nominal and every forward run by default (the runs level), thinned: every n-th point of each
// stage plus its first and last. The initial nominal is the deck's program flown point mass, the
// trajectory of simulate --json of the same deck: the listed (time, stage) pairs must be that rule
// applied to its points.
TEST(ListingLevel, Sec22_Block9FrequenciesThinTheInitialAndIntermediateRuns) {
  ScratchDirectory scratch("listing_level");
  const std::string deck = edited_example_deck(
      scratch, "thinned.toml", {{"initial = 1\nintermediate = 1", "initial = 3\nintermediate = 4"}});
  const CommandResult listing = run_tolip_executable({"optimize", deck, "--no-progress"});
  ASSERT_EQ(listing.exit_code, 0) << listing.err;
  EXPECT_EQ(without_input_warnings(listing.err), "");
  EXPECT_FALSE(contains(listing.err, "data block 9")) << listing.err;
  const nlohmann::json simulated =
      nlohmann::json::parse(run_tolip_executable({"simulate", deck, "--json"}).out);
  const nlohmann::json& points = simulated.at("trajectory");
  const auto sections = listed_points(listing.out);
  ASSERT_TRUE(sections.count("INITIAL NOMINAL TRAJECTORY"));
  // The pad point, then per stage event its first and last point and every third from the first.
  std::set<std::pair<int, long long>> expected;
  const auto expect_point = [&](std::size_t i) {
    expected.insert(
        {points[i].at("stage").get<int>(), std::llround(points[i].at("time_s").get<double>() * 1000.0)});
  };
  expect_point(0);
  for (const nlohmann::json& event : simulated.at("stage_events")) {
    const std::size_t first = event.at("first_point").get<std::size_t>();
    const std::size_t last = event.at("last_point").get<std::size_t>();
    for (std::size_t i = first; i <= last; ++i) {
      if (i == first || i == last || (i - first) % 3 == 0) expect_point(i);
    }
  }
  std::set<std::pair<int, long long>> listed;
  for (const ListedPoint& p : sections.at("INITIAL NOMINAL TRAJECTORY")) {
    listed.insert({stage_code_of(p.stage_label), std::llround(p.time() * 1000.0)});
  }
  EXPECT_EQ(listed, expected);
  EXPECT_LT(listed.size(), points.size() / 2);
  // One listing per forward run after the initial nominal, at the intermediate frequency (fewer
  // points than the final trajectory at frequency 1).
  const nlohmann::json result =
      nlohmann::json::parse(run_tolip_executable({"optimize", deck, "--no-progress", "--json"}).out);
  const int forward_runs = result.at("forward_runs").get<int>();
  int run_sections = 0;
  for (const auto& [name, section_points] : sections) {
    if (name.rfind("FORWARD RUN ", 0) != 0) continue;
    ++run_sections;
    EXPECT_LT(section_points.size(), sections.at("FINAL TRAJECTORY").size() / 2) << name;
  }
  EXPECT_EQ(run_sections, forward_runs - 1);
  // The command line overrides the deck: the final level lists no run.
  const CommandResult final_level =
      run_tolip_executable({"optimize", deck, "--no-progress", "--listing-level", "final"});
  EXPECT_FALSE(contains(final_level.out, "INITIAL NOMINAL TRAJECTORY"));
}

}  // namespace
}  // namespace tolip::test
