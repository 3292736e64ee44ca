// The report writers (tolip_ground/report.hpp) in process: a hand-made trajectory checks the
// formats (no NaN anywhere, every point in CSV/JSON, listing sections), and the reference Scout
// mission flown by the core checks the numbers (needs prepare_case and fly_trajectory).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "support/reference_mission.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::test {
namespace {

using ground::SimulationReport;

int count_lines(const std::string& text) {
  int lines = 0;
  for (char c : text) lines += c == '\n' ? 1 : 0;
  return lines;
}

// Three points of stage 1 then two of coast 6; the drag of point 1 is NaN (never printed).
void fill_synthetic(Mission* mission, ground::DeckListingOptions* listing, Trajectory* trajectory) {
  listing->title = "SYNTHETIC REPORT TEST";
  listing->case_heading = "CASE 1";
  listing->date = "01 JUL 1966";
  mission->launch.launch_space_age_date_days = 2373.625;
  trajectory->status = Status::kOk;
  trajectory->point_count = 5;
  for (int i = 0; i < 5; ++i) {
    TrajectoryPoint& p = trajectory->points[i];
    p.time_s = 10.0 * i;
    p.stage_code = i < 3 ? 1 : 6;
    p.stage_time_s = i < 3 ? 10.0 * i : 10.0 * (i - 3);
    p.state << 1000.0 + i, 0.5, 20.9e6 + 1000.0 * i, 1.7, 0.65, -1.3;
    p.altitude_ft = 1000.0 * i;
    p.earth_longitude_rad = 190.0 * kDegToRad;  // wraps to -170 deg
    p.weight_lb = 30000.0 - 1000.0 * i;
    p.alpha_rad = 2.0 * kDegToRad;
    p.dynamic_pressure_lbf_ft2 = 100.0;
    p.downrange_rad = 0.001 * i;
  }
  trajectory->points[1].drag_lbf = std::numeric_limits<double>::quiet_NaN();
  trajectory->stage_count = 2;
  trajectory->stages[0] = StageEvent{1, 0, 2, 27000.0, 22000.0, true};
  trajectory->stages[1] = StageEvent{6, 3, 4, 22000.0, 22000.0, true};
}

struct SyntheticCase {
  std::unique_ptr<Mission> mission = std::make_unique<Mission>();
  std::unique_ptr<Trajectory> trajectory = std::make_unique<Trajectory>();
  ground::DeckListingOptions listing;
  SimulationReport report;
  SyntheticCase() {
    fill_synthetic(mission.get(), &listing, trajectory.get());
    report.mission = mission.get();
    report.listing = &listing;
    report.trajectory = trajectory.get();
    report.status = Status::kOk;
    report.deck_path = "synthetic.toml";
  }
};

TEST(ReportFormat, WrapDegrees) {
  EXPECT_DOUBLE_EQ(ground::wrap_degrees_180(0.0), 0.0);
  EXPECT_DOUBLE_EQ(ground::wrap_degrees_180(180.0), 180.0);
  EXPECT_DOUBLE_EQ(ground::wrap_degrees_180(-180.0), 180.0);
  EXPECT_DOUBLE_EQ(ground::wrap_degrees_180(190.0), -170.0);
  EXPECT_DOUBLE_EQ(ground::wrap_degrees_180(-190.0), 170.0);
  EXPECT_DOUBLE_EQ(ground::wrap_degrees_180(540.0), 180.0);
  EXPECT_DOUBLE_EQ(ground::wrap_degrees_180(-75.48), -75.48);
}

TEST(ReportFormat, ColumnNamesAreUniqueSnakeCase) {
  std::set<std::string> names;
  for (const ground::PointColumn& column : ground::trajectory_point_columns()) {
    const std::string name = column.name;
    EXPECT_TRUE(names.insert(name).second) << name;
    for (char c : name) EXPECT_TRUE((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_') << name;
  }
  const auto columns = ground::trajectory_point_columns();
  ASSERT_GE(columns.size(), 5u);
  EXPECT_STREQ(columns[0].name, "time_s");
  EXPECT_STREQ(columns[1].name, "stage");
  EXPECT_STREQ(columns[2].name, "stage_time_s");
  EXPECT_STREQ(columns[3].name, "velocity_ft_s");
  EXPECT_STREQ(columns[4].name, "gamma_deg");
  for (const char* required : {"altitude_ft", "longitude_deg", "weight_lb", "range_nmi", "mach",
                               "qalpha_lbf_deg_ft2", "inertial_velocity_ft_s"}) {
    EXPECT_EQ(names.count(required), 1u) << required;
  }
}

TEST(ReportFormat, CsvHasEveryPointAndNoNan) {
  SyntheticCase test_case;
  std::ostringstream csv;
  ground::write_trajectory_csv(csv, test_case.report);
  const std::string text = csv.str();
  EXPECT_EQ(count_lines(text), 1 + 5);
  EXPECT_EQ(text.rfind("time_s,stage,stage_time_s,velocity_ft_s,gamma_deg,", 0), 0u) << text;
  EXPECT_EQ(text.find("nan"), std::string::npos) << text;
  EXPECT_EQ(text.find("inf"), std::string::npos) << text;
  // Full precision: the radius 20901000 and velocity 1001 read back exactly.
  EXPECT_NE(text.find("\n10,1,10,1001,"), std::string::npos) << text;
}

TEST(ReportFormat, JsonHasEveryPointAndNullForNan) {
  SyntheticCase test_case;
  const std::string text = ground::dump_json(ground::trajectory_json(test_case.report));
  EXPECT_EQ(text.find("NaN"), std::string::npos);
  EXPECT_EQ(text.find("nan"), std::string::npos);
  const nlohmann::json document = nlohmann::json::parse(text);
  EXPECT_EQ(document["status"], "kOk");
  EXPECT_EQ(document["title"], "SYNTHETIC REPORT TEST");
  EXPECT_EQ(document["launch_space_age_date_days"].get<double>(), 2373.625);
  ASSERT_EQ(document["trajectory"].size(), 5u);
  EXPECT_TRUE(document["trajectory"][1]["drag_lbf"].is_null());
  EXPECT_EQ(document["trajectory"][4]["stage"], 6);
  EXPECT_EQ(document["trajectory"][0]["heading_hold"], false);
  const nlohmann::json& burnout = document["burnout"];
  EXPECT_EQ(burnout["time_s"].get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(burnout["longitude_deg"].get<double>(), -170.0);
  EXPECT_EQ(burnout["weight_lb"].get<double>(), 26000.0);
  EXPECT_TRUE(document["orbit"].is_null());  // has_orbit false
  ASSERT_EQ(document["stage_events"].size(), 2u);
  EXPECT_EQ(document["stage_events"][0]["stage"], 1);
  EXPECT_EQ(document["stage_events"][0]["kind"], "powered");
  EXPECT_EQ(document["stage_events"][0]["jettison_weight_lb"].get<double>(), 5000.0);
  EXPECT_EQ(document["stage_events"][1]["kind"], "coast");
  // The CSV header and the JSON point keys are the same names in the same order.
  std::size_t index = 0;
  const auto columns = ground::trajectory_point_columns();
  const nlohmann::ordered_json ordered = ground::trajectory_json(test_case.report);
  for (const auto& item : ordered["trajectory"][0].items()) {
    ASSERT_LT(index, columns.size());
    EXPECT_EQ(item.key(), columns[index].name);
    ++index;
  }
  EXPECT_EQ(index, columns.size());
}

TEST(ReportFormat, JsonOfAFailedRunKeepsThePointsFlown) {
  SyntheticCase test_case;
  test_case.trajectory->status = Status::kAltitudeBelowSurface;
  test_case.trajectory->point_count = 2;
  test_case.report.status = Status::kAltitudeBelowSurface;
  const nlohmann::json document =
      nlohmann::json::parse(ground::dump_json(ground::trajectory_json(test_case.report)));
  EXPECT_EQ(document["status"], "kAltitudeBelowSurface");
  EXPECT_EQ(document["trajectory"].size(), 2u);
  EXPECT_EQ(document["burnout"]["time_s"].get<double>(), 10.0);
  EXPECT_TRUE(document["orbit"].is_null());
  // Stage events that point past the points flown give null values, not garbage.
  EXPECT_TRUE(document["stage_events"][0]["end_time_s"].is_null());
}

TEST(ReportFormat, JsonOfARunWithoutPoints) {
  SyntheticCase test_case;
  test_case.trajectory->point_count = 0;
  test_case.trajectory->stage_count = 0;
  test_case.report.status = Status::kTooManyCoastSteps;
  const nlohmann::json document =
      nlohmann::json::parse(ground::dump_json(ground::trajectory_json(test_case.report)));
  EXPECT_EQ(document["status"], "kTooManyCoastSteps");
  EXPECT_TRUE(document["burnout"].is_null());
  EXPECT_TRUE(document["trajectory"].empty());
}

TEST(ReportFormat, ListingHasTitlesColumnsAndTerminalConditions) {
  SyntheticCase test_case;
  OrbitElements& orbit = test_case.report.orbit;
  orbit.type = OrbitType::kHyperbolic;
  orbit.twice_energy_ft2_s2 = 1.0e8;
  orbit.has_semi_major_axis = false;
  orbit.has_asymptote = true;
  orbit.hyperbolic_excess_velocity_ft_s = 10000.0;
  test_case.report.has_orbit = true;
  std::ostringstream listing;
  ground::write_trajectory_listing(listing, test_case.report);
  const std::string text = listing.str();
  for (const char* part : {"SYNTHETIC REPORT TEST",
                           "CASE 1",
                           "01 JUL 1966",
                           "TIME",
                           "VEL",
                           "GAMMA",
                           "PSI",
                           "ALTITUDE",
                           "GEOC LAT",
                           "TAU",
                           "QBAR",
                           "THRUST",
                           "WEIGHT",
                           "GEOD LAT",
                           "RADIUS",
                           "HEAT RATE",
                           "THETA",
                           "VI",
                           "GAMI",
                           "PSII",
                           "MACH",
                           "ALPHA",
                           "DRAG",
                           "LIFT",
                           "QALPHA",
                           "RANGE",
                           "STAGE EVENTS",
                           "TERMINAL CONDITIONS",
                           "TWOE",
                           "EH",
                           "RP",
                           "EYE",
                           "BETAP",
                           "ECCENTRICITY",
                           "RALPHA",
                           "PERIOD",
                           "OMEGAE",
                           "HYPERBOLIC",
                           "VH",
                           "ASYMPTOTE RA",
                           "ASYMPTOTE DECL",
                           "COAST AFTER STAGE 1"}) {
    EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
  }
  EXPECT_EQ(text.find("nan"), std::string::npos) << text;
  // No line is wider than the 132-column printer.
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) EXPECT_LE(line.size(), 132u) << line;
}

TEST(ReportFormat, ListingOfAFailedRunSaysWhy) {
  SyntheticCase test_case;
  test_case.report.status = Status::kAltitudeBelowSurface;
  std::ostringstream listing;
  ground::write_trajectory_listing(listing, test_case.report);
  EXPECT_NE(listing.str().find("TRAJECTORY TERMINATED: kAltitudeBelowSurface"), std::string::npos);
}

// ---- the reference Scout mission flown by the core ---------------------------------------------

struct FlownReference {
  std::unique_ptr<Mission> mission = std::make_unique<Mission>();
  std::unique_ptr<PreparedCase> prepared = std::make_unique<PreparedCase>();
  std::unique_ptr<Trajectory> trajectory = std::make_unique<Trajectory>();
  SimulationReport report;
  Status status = Status::kNotPrepared;
  FlownReference() {
    build_reference_mission(ReferenceProgram::kOptimum, mission.get());
    report.mission = mission.get();
    report.trajectory = trajectory.get();
    status = prepare_case(*mission, prepared.get());
    if (ok(status)) status = fly_trajectory(*mission, *prepared, trajectory.get());
    if (ok(status)) {
      status = compute_orbit_elements(mission->constants, trajectory->final_point().state,
                                      mission->launch.launch_space_age_date_days, &report.orbit);
      report.has_orbit = ok(status);
    }
    report.status = status;
  }
};

// Data block 9: every n-th point of a stage, and always its first and last point.
TEST(Sec22Output, ThinsPointsPerStageKeepingStageEnds) {
  FlownReference flown;
  ASSERT_TRUE(ok(flown.status)) << status_name(flown.status);
  const Trajectory& trajectory = *flown.trajectory;
  ground::OutputFrequency output;
  output.final_trajectory.fill(5);
  using ground::TrajectoryKind;
  int listed = 0;
  for (int i = 0; i < trajectory.point_count; ++i) {
    listed += ground::is_output_point(output, trajectory, i, TrajectoryKind::kFinal) ? 1 : 0;
  }
  for (int k = 0; k < trajectory.stage_count; ++k) {
    EXPECT_TRUE(ground::is_output_point(output, trajectory, trajectory.stages[k].first_point,
                                        TrajectoryKind::kFinal));
    EXPECT_TRUE(
        ground::is_output_point(output, trajectory, trajectory.stages[k].last_point, TrajectoryKind::kFinal));
  }
  EXPECT_LT(listed, trajectory.point_count / 3);
  EXPECT_GT(listed, trajectory.point_count / 6);
  EXPECT_TRUE(ground::is_output_point(output, trajectory, 0, TrajectoryKind::kIntermediate));  // pad point
}

TEST(ReportReference, JsonBurnoutAndOrbitMatchTheOracle) {
  FlownReference flown;
  ASSERT_TRUE(ok(flown.status)) << status_name(flown.status);
  const nlohmann::json document =
      nlohmann::json::parse(ground::dump_json(ground::trajectory_json(flown.report)));
  EXPECT_EQ(document["status"], "kOk");
  EXPECT_NEAR(document["burnout"]["altitude_ft"].get<double>(), 1822834.647, 100.0);
  EXPECT_NEAR(document["burnout"]["longitude_deg"].get<double>(), -51.1687579167, 0.01);
  EXPECT_NEAR(document["inertial"]["velocity_ft_s"].get<double>(), 24886.3026613, 1.0);
  EXPECT_NEAR(document["orbit"]["inclination_deg"].get<double>(), 38.7995658682, 0.001);
  EXPECT_NEAR(document["orbit"]["node_longitude_deg"].get<double>(), 323.404399324, 0.01);
  EXPECT_NEAR(document["orbit"]["period_min"].get<double>(), 95.6463476257, 0.01);
  EXPECT_EQ(document["trajectory"].size(), static_cast<std::size_t>(flown.trajectory->point_count));
}

TEST(ReportReference, CsvHasARowPerPoint) {
  FlownReference flown;
  ASSERT_TRUE(ok(flown.status)) << status_name(flown.status);
  std::ostringstream csv;
  ground::write_trajectory_csv(csv, flown.report);
  EXPECT_EQ(count_lines(csv.str()), 1 + flown.trajectory->point_count);
  EXPECT_EQ(csv.str().find("nan"), std::string::npos);
}

TEST(ReportReference, ListingShowsTheSelectedPoints) {
  FlownReference flown;
  ASSERT_TRUE(ok(flown.status)) << status_name(flown.status);
  std::ostringstream listing;
  ground::write_trajectory_listing(listing, flown.report);
  const std::string text = listing.str();
  EXPECT_NE(text.find("ORBIT ELEMENTS (ELLIPTIC"), std::string::npos);
  EXPECT_NE(text.find("COAST AFTER STAGE 3"), std::string::npos);
  EXPECT_EQ(text.find("TRAJECTORY TERMINATED"), std::string::npos);
  EXPECT_EQ(text.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace tolip::test
