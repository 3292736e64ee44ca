// `tolip simulate` end to end on examples/scout/reference_optimum.toml. These need the deck
// reader, prepare_case and fly_trajectory all working.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace tolip::test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// The reference deck with the text from `from` through `until` (or just `from` when `until` is
// empty) replaced, at its first occurrence after `anchor`; written to the scratch directory.
std::string edited_reference_deck(const ScratchDirectory& scratch, const std::string& name,
                                  const std::string& anchor, const std::string& from,
                                  const std::string& until, const std::string& replacement) {
  std::string text = read_text_file(reference_deck());
  const std::size_t at = text.find(anchor);
  EXPECT_NE(at, std::string::npos) << anchor;
  const std::size_t begin = text.find(from, at);
  EXPECT_NE(begin, std::string::npos) << from;
  if (at == std::string::npos || begin == std::string::npos) return {};
  std::size_t end = begin + from.size();
  if (!until.empty()) {
    const std::size_t found = text.find(until, end);
    EXPECT_NE(found, std::string::npos) << until;
    if (found == std::string::npos) return {};
    end = found + until.size();
  }
  text.replace(begin, end - begin, replacement);
  const std::string path = (scratch / name).string();
  std::ofstream(path) << text;
  return path;
}

// Points in a listing: lines of 12 numeric cells, two per point.
int listed_points(const std::string& listing) {
  int numeric_lines = 0;
  for (const std::string& line : lines_of(listing)) {
    std::istringstream cells(line);
    std::string cell;
    int count = 0;
    bool numeric = true;
    while (cells >> cell) {
      ++count;
      char* end = nullptr;
      std::strtod(cell.c_str(), &end);
      if (end == cell.c_str() || *end != '\0') numeric = false;
    }
    if (numeric && count == 12) ++numeric_lines;
  }
  return numeric_lines / 2;
}

TEST(SimulateCommand, JsonOfTheReferenceOptimum) {
  const CommandResult result = run_tolip_executable({"simulate", reference_deck(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_FALSE(contains(result.out, "NaN"));
  const nlohmann::json document = nlohmann::json::parse(result.out);
  for (const char* key : {"status", "launch_space_age_date_days", "burnout", "inertial", "orbit",
                          "stage_events", "trajectory"}) {
    EXPECT_TRUE(document.contains(key)) << key;
  }
  EXPECT_EQ(document["status"], "kOk");
  EXPECT_NEAR(document["launch_space_age_date_days"].get<double>(), 2373.625, 1e-9);

  const nlohmann::json& burnout = document["burnout"];
  for (const char* key : {"time_s", "velocity_ft_s", "gamma_deg", "psi_deg", "radius_ft", "altitude_ft",
                          "geocentric_latitude_deg", "longitude_deg", "weight_lb"}) {
    ASSERT_TRUE(burnout.contains(key)) << key;
    EXPECT_TRUE(burnout[key].is_number()) << key;
  }
  EXPECT_NEAR(burnout["altitude_ft"].get<double>(), 1822834.647, 100.0);
  const double longitude = burnout["longitude_deg"].get<double>();
  EXPECT_GT(longitude, -180.0);
  EXPECT_LE(longitude, 180.0);

  for (const char* key : {"velocity_ft_s", "gamma_deg", "psi_deg"}) {
    EXPECT_TRUE(document["inertial"][key].is_number()) << key;
  }
  const nlohmann::json& orbit = document["orbit"];
  for (const char* key : {"twoe_ft2_s2", "angular_momentum_ft2_s", "perigee_radius_ft", "inclination_deg",
                          "argument_of_perigee_deg", "node_longitude_deg", "semi_major_axis_ft", "period_min",
                          "eccentricity", "type"}) {
    ASSERT_TRUE(orbit.contains(key)) << key;
  }
  EXPECT_EQ(orbit["type"], "elliptic");
  EXPECT_TRUE(orbit["semi_major_axis_ft"].is_number());
  EXPECT_NEAR(orbit["period_min"].get<double>(), 95.646, 0.05);

  ASSERT_FALSE(document["stage_events"].empty());
  EXPECT_EQ(document["stage_events"][0]["stage"], 1);
  const nlohmann::json& points = document["trajectory"];
  ASSERT_FALSE(points.empty());
  EXPECT_EQ(points.size(), document["point_count"].get<std::size_t>());
  for (const char* key : {"time_s", "stage", "stage_time_s", "velocity_ft_s", "gamma_deg", "altitude_ft",
                          "longitude_deg", "range_nmi"}) {
    EXPECT_TRUE(points[0].contains(key)) << key;
  }
}

TEST(SimulateCommand, CsvHasARowPerPointAndIsWrittenAtomically) {
  ScratchDirectory scratch("simulate_csv");
  const std::string csv = (scratch / "trajectory.csv").string();
  {
    std::ofstream old(csv);
    old << "old contents\n";
  }
  const CommandResult result = run_tolip_executable({"simulate", reference_deck(), "--json", "--csv", csv});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(result.out);
  const std::vector<std::string> rows = lines_of(read_text_file(csv));
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(rows[0].rfind("time_s,stage,stage_time_s,velocity_ft_s,gamma_deg,", 0), 0u) << rows[0];
  EXPECT_EQ(rows.size(), 1 + document["trajectory"].size());
  EXPECT_EQ(rows.size(), 1 + document["point_count"].get<std::size_t>());
  EXPECT_FALSE(scratch.has_temp_file());
  EXPECT_EQ(scratch.entries().size(), 1u);
}

TEST(SimulateCommand, CsvWriteFailureExitsOneAndLeavesTheTarget) {
  ScratchDirectory scratch("simulate_csv_fail");
  const std::filesystem::path target = scratch / "occupied";
  std::filesystem::create_directories(target);
  {
    std::ofstream keep(target / "keep.txt");
    keep << "keep\n";
  }
  const CommandResult result = run_tolip_executable({"simulate", reference_deck(), "--csv", target.string()});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(result.err.rfind("tolip: ", 0), 0u) << result.err;
  EXPECT_TRUE(contains(result.err, target.string())) << result.err;
  EXPECT_TRUE(std::filesystem::is_directory(target));
  EXPECT_EQ(read_text_file(target / "keep.txt"), "keep\n");
  EXPECT_FALSE(scratch.has_temp_file());
}

TEST(SimulateCommand, ListingShowsTrajectoryStagesAndTerminalConditions) {
  const CommandResult result = run_tolip_executable({"simulate", reference_deck()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* part :
       {"TIME", "GEOC LAT", "QALPHA", "RANGE", "STAGE EVENTS", "TERMINAL CONDITIONS", "TWOE", "EH", "RP",
        "EYE", "BETAP", "ECCENTRICITY", "RALPHA", "PERIOD", "OMEGAE", "VI", "GAMI", "PSII"}) {
    EXPECT_TRUE(contains(result.out, part)) << part;
  }
  EXPECT_FALSE(contains(result.out, "nan"));
  for (const std::string& line : lines_of(result.out)) EXPECT_LE(line.size(), 132u) << line;
}

TEST(SimulateCommand, ListingIsThinnedByTheOutputFrequency) {
  ScratchDirectory scratch("simulate_thinned");
  const CommandResult every = run_tolip_executable({"simulate", reference_deck(), "--json"});
  ASSERT_EQ(every.exit_code, 0) << every.err;
  const int points = nlohmann::json::parse(every.out)["point_count"].get<int>();
  const CommandResult full = run_tolip_executable({"simulate", reference_deck()});
  ASSERT_EQ(full.exit_code, 0) << full.err;
  EXPECT_EQ(listed_points(full.out), points);

  const std::string deck =
      edited_reference_deck(scratch, "thinned.toml", "[output_frequency]", "final = 1", "", "final = 5");
  ASSERT_FALSE(deck.empty());
  const std::string csv = (scratch / "thinned.csv").string();
  const CommandResult thinned = run_tolip_executable({"simulate", deck, "--csv", csv});
  ASSERT_EQ(thinned.exit_code, 0) << thinned.err;
  const int listed = listed_points(thinned.out);
  EXPECT_LT(listed, points / 2);
  EXPECT_GE(listed, 14);  // at least the first and last point of each of the 7 stages
  EXPECT_TRUE(contains(thinned.out, "580.834")) << "the final point is always listed";
  // The CSV is never thinned.
  EXPECT_EQ(static_cast<int>(lines_of(read_text_file(csv)).size()), 1 + points);
}

TEST(SimulateCommand, FailedTrajectoryStillReportsThePointsFlown) {
  // A pitch program that points the vehicle at the ground right after lift-off.
  ScratchDirectory scratch("simulate_crash");
  const std::string deck = edited_reference_deck(
      scratch, "crash.toml", "[pitch_program]", "theta_deg = [", "]",
      "theta_deg = [90.0, 90.0, -80.0, -80.0, -80.0, -80.0, -80.0, -80.0, -80.0, -80.0, -80.0]");
  ASSERT_FALSE(deck.empty());
  const std::string csv = (scratch / "crash.csv").string();
  const CommandResult result = run_tolip_executable({"simulate", deck, "--json", "--csv", csv});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(without_input_warnings(result.err).rfind("tolip: k", 0), 0u) << result.err;
  EXPECT_FALSE(contains(result.out, "NaN"));
  const nlohmann::json document = nlohmann::json::parse(result.out);
  EXPECT_NE(document["status"], "kOk");
  EXPECT_TRUE(contains(result.err, document["status"].get<std::string>())) << result.err;
  EXPECT_TRUE(document["orbit"].is_null());
  const std::size_t flown = document["trajectory"].size();
  EXPECT_GT(flown, 1u);
  EXPECT_EQ(document["point_count"].get<std::size_t>(), flown);
  EXPECT_EQ(document["burnout"]["time_s"], document["trajectory"][flown - 1]["time_s"]);
  EXPECT_EQ(lines_of(read_text_file(csv)).size(), 1 + flown);

  const CommandResult listing = run_tolip_executable({"simulate", deck});
  EXPECT_EQ(listing.exit_code, 1);
  EXPECT_TRUE(contains(listing.out, "TRAJECTORY TERMINATED: " + document["status"].get<std::string>()))
      << listing.out;
  EXPECT_EQ(listed_points(listing.out), static_cast<int>(flown));
}

// Issue 17: a deck may say the Earth is a sphere (CT1(12) inverse_flattening = 0, Sec. 4's oblate
// figure turned off); with J2 = 0 and no rotation as well the case flies end to end, the launch
// vertical is the geocentric one and every point's geodetic latitude is its geocentric latitude,
// its altitude the radius less CT1(3).
TEST(SimulateCommand, Sec4Earth_DeckWithASphericalNonRotatingEarthSimulates) {
  ScratchDirectory scratch("simulate_sphere");
  const std::string deck =
      edited_reference_deck(scratch, "sphere.toml", "[constants]", "earth_rotation_rate_rad_s = 7.29211e-05",
                            "inverse_flattening = 298.3",
                            "earth_rotation_rate_rad_s = 0.0\n"
                            "gravitational_parameter_ft3_s2 = 1.407735e+16\n"
                            "earth_equatorial_radius_ft = 20925696.0\n"
                            "j2 = 0.0\n"
                            "inverse_flattening = 0  # a spherical Earth");
  ASSERT_FALSE(deck.empty());
  const CommandResult result = run_tolip_executable({"simulate", deck, "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(result.out);
  EXPECT_EQ(document["status"], "kOk");
  const nlohmann::json& points = document["trajectory"];
  ASSERT_GT(points.size(), 100u);
  for (const nlohmann::json& point : points) {
    EXPECT_EQ(point["geodetic_latitude_deg"].get<double>(), point["geocentric_latitude_deg"].get<double>())
        << point["time_s"];
    EXPECT_NEAR(point["altitude_ft"].get<double>(), point["radius_ft"].get<double>() - 20925696.0, 1e-6)
        << point["time_s"];
  }
  // The spherical Earth flies a different case from the oblate one (same deck otherwise).
  const CommandResult oblate = run_tolip_executable({"simulate", reference_deck(), "--json"});
  ASSERT_EQ(oblate.exit_code, 0) << oblate.err;
  const nlohmann::json oblate_document = nlohmann::json::parse(oblate.out);
  EXPECT_NE(oblate_document["burnout"]["altitude_ft"].get<double>(),
            document["burnout"]["altitude_ft"].get<double>());
  std::printf(
      "[ figures  ] spherical non-rotating Earth: %zu points, burnout altitude %.1f ft (oblate %.1f ft)\n",
      points.size(), document["burnout"]["altitude_ft"].get<double>(),
      oblate_document["burnout"]["altitude_ft"].get<double>());
}

}  // namespace
}  // namespace tolip::test
