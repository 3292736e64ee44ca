// `tolip plot` (tolip_ground/plot.hpp): figures drawn by gnuplot from simulate/optimize JSON, as
// PNG and SVG; malformed results, a missing gnuplot and an unwritable directory give named errors
// and leave the output directory as it was. Tests that need gnuplot skip when it is not installed
// (scripts/setup.sh installs gnuplot-nox).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string> kFigures = {"altitude_downrange_ascent",
                                           "altitude_downrange",
                                           "velocity_time",
                                           "flight_path_angle_time",
                                           "dynamic_pressure_time",
                                           "alpha_time",
                                           "qalpha_time",
                                           "theta_time_ascent",
                                           "theta_time",
                                           "weight_time",
                                           "ground_track",
                                           "impact_locus",
                                           "convergence"};
// The figures of a simulate result (no 'iterations': no convergence figure).
const std::vector<std::string> kTrajectoryFigures(kFigures.begin(), kFigures.end() - 1);

constexpr double kFeetPerNauticalMile = 1852.0 / 0.3048;

bool gnuplot_installed() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

#define REQUIRE_GNUPLOT()                                                               \
  do {                                                                                  \
    if (!gnuplot_installed()) GTEST_SKIP() << "gnuplot is not installed (gnuplot-nox)"; \
  } while (false)

// A trajectory point with every column the figures read; the others follow from these.
json point(double t, int stage, double range, double altitude, double velocity, json qbar, double theta,
           bool alpha_zero = false) {
  return json{{"time_s", t},
              {"stage", stage},
              {"range_nmi", range},
              {"altitude_ft", altitude},
              {"velocity_ft_s", velocity},
              {"inertial_velocity_ft_s", velocity + 1000.0},
              {"gamma_deg", theta - 2.0},
              {"inertial_gamma_deg", theta - 3.0},
              {"dynamic_pressure_lbf_ft2", std::move(qbar)},
              {"alpha_deg", t < 40 ? -0.1 * t : 0.0},
              {"qalpha_lbf_deg_ft2", t < 40 ? -10.0 * t : 0.0},
              {"theta_deg", theta},
              {"weight_lb", 10000.0 - 50.0 * t},
              {"longitude_deg", -75.0 + 0.1 * t},
              {"geodetic_latitude_deg", 37.8 - 0.05 * t},
              {"alpha_zero", alpha_zero}};
}

// A small result in the optimize --json schema, with a linearized program: stage 1 from 0 to 30 s,
// a coast to 100 s, stage 2 to 110 s; max q (400) at 10 s; alpha = 0 on the steps from 10 to 30 s.
json small_result(const std::string& title) {
  json document = {
      {"program", "tolip"}, {"title", title},       {"case_heading", "HEADING"},  {"status", "kOk"},
      {"converged", true},  {"case_status", "kOk"}, {"iterations", json::array()}};
  document["stage_events"] = json::array({
      json{{"stage", 1},
           {"kind", "powered"},
           {"first_point", 1},
           {"last_point", 3},
           {"start_time_s", 10.0},
           {"end_time_s", 30.0}},
      json{{"stage", 6},
           {"kind", "coast"},
           {"first_point", 4},
           {"last_point", 6},
           {"start_time_s", 30.0},
           {"end_time_s", 100.0}},
      json{{"stage", 2},
           {"kind", "powered"},
           {"first_point", 7},
           {"last_point", 8},
           {"start_time_s", 100.0},
           {"end_time_s", 110.0}},
  });
  document["trajectory"] =
      json::array({point(0, 1, 0, 0, 0, 0.0, 90), point(10, 1, 1, 5000, 800, 400.0, 80, true),
                   point(20, 1, 4, 20000, 2000, nullptr, 60, true), point(30, 1, 10, 50000, 4000, 100.0, 45),
                   point(30, 6, 10, 50000, 4000, 100.0, 45), point(65, 6, 60, 300000, 3800, 0.0, 45),
                   point(100, 6, 110, 400000, 3600, 0.0, 45), point(100, 2, 110, 400000, 3600, 0.0, 20),
                   point(110, 2, 130, 410000, 9000, 0.0, 20)});
  document["linearized"] = {{"segments", json::array({json{{"stage", 1},
                                                           {"start_stage_time_s", 0.0},
                                                           {"start_time_s", 0.0},
                                                           {"theta_deg", 90.0},
                                                           {"rate_deg_s", -1.0}},
                                                      json{{"stage", 1},
                                                           {"start_stage_time_s", 10.0},
                                                           {"start_time_s", 10.0},
                                                           {"theta_deg", 80.0},
                                                           {"rate_deg_s", -1.75}}})},
                            {"constraints_met", true},
                            {"rate_limits_met", false},
                            {"payoff", 300.0}};
  document["impact"] = {
      {"launch_site", {{"geodetic_latitude_deg", 37.84}, {"longitude_deg", -75.48}}},
      {"cases",
       json::array({json{{"kind", "thrust_failure"},
                         {"stage", 1},
                         {"longitude_deg", -75.0},
                         {"geodetic_latitude_deg", 37.7}},
                    json{{"kind", "expended_casing"},
                         {"stage", 1},
                         {"longitude_deg", -74.9},
                         {"geodetic_latitude_deg", 37.6}},
                    json{{"kind", "thrust_failure"}, {"stage", 2}, {"status", "kImpactNotReached"}}})}};
  document["payoff"] = {{"kind", "payload"}, {"unit", "lb"}};
  document["constraints"] =
      json::array({json{{"name", "altitude"}, {"tolerance", 20000.0}, {"inequality", false}},
                   json{{"name", "total_heating"}, {"tolerance", 10.0}, {"inequality", true}}});
  document["iterations"] = json::array({json{{"forward_run", 1},
                                             {"successful", false},
                                             {"payoff", 250.0},
                                             {"constraint_corrections", {-40000.0, 0.0}}},
                                        json{{"forward_run", 2},
                                             {"successful", true},
                                             {"payoff", 260.0},
                                             {"constraint_corrections", {0.0, -5.0}}},
                                        json{{"forward_run", 3},
                                             {"successful", true},
                                             {"payoff", 270.0},
                                             {"constraint_corrections", {1000.0, 30.0}}}});
  return document;
}

// The figure of that name (a failed test when there is none).
const ground::Figure& figure_named(const ground::DocumentFigures& figures, const std::string& name) {
  for (const ground::Figure& figure : figures.figures) {
    if (figure.name == name) return figure;
  }
  ADD_FAILURE() << "no figure " << name;
  static const ground::Figure none;
  return none;
}

std::string write_file(const ScratchDirectory& scratch, const std::string& name, const std::string& text) {
  const std::string path = (scratch / name).string();
  std::ofstream(path) << text;
  return path;
}

void expect_images(const fs::path& dir, const std::string& suffix,
                   const std::vector<std::string>& figures = kFigures) {
  for (const std::string& figure : figures) {
    const fs::path png = dir / (figure + suffix + ".png");
    const fs::path svg = dir / (figure + suffix + ".svg");
    ASSERT_TRUE(fs::exists(png)) << png;
    ASSERT_TRUE(fs::exists(svg)) << svg;
    const std::string png_bytes = read_text_file(png);
    const std::string svg_text = read_text_file(svg);
    EXPECT_GT(png_bytes.size(), 1000u) << png;
    EXPECT_EQ(png_bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << png;
    EXPECT_TRUE(contains(svg_text, "<svg")) << svg;
    EXPECT_TRUE(contains(svg_text, "</svg>")) << svg;
  }
}

std::size_t entry_count(const fs::path& dir) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++count;
  return count;
}

// ---- the catalogue, without gnuplot --------------------------------------------------------------

TEST(PlotCatalogue, EveryPlotHasAUniqueNameAndAMember) {
  std::set<std::string> names;
  for (const ground::PlotKind& kind : ground::plot_catalogue()) {
    EXPECT_TRUE(names.insert(kind.name).second) << kind.name;
    EXPECT_NE(std::string(kind.member), "");
    EXPECT_NE(kind.build, nullptr);
  }
  EXPECT_EQ(names, std::set<std::string>(kFigures.begin(), kFigures.end()));
}

TEST(PlotCatalogue, FiguresFromADocument) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result("TEST CASE"));
  ASSERT_EQ(result.figures.size(), kFigures.size());
  EXPECT_TRUE(result.skipped.empty());

  const ground::Figure& qbar = figure_named(result, "dynamic_pressure_time");
  ASSERT_EQ(qbar.series.size(), 1u);
  EXPECT_TRUE(std::isnan(qbar.series[0].y[2])) << "a null is a gap";

  // theta: the optimum, then the linearized program, segment by segment, the last one to the end
  // of its stage (no end_time_s given).
  const ground::Figure& theta = figure_named(result, "theta_time");
  ASSERT_EQ(theta.series.size(), 2u);
  const ground::PlotSeries& linear = theta.series[1];
  EXPECT_TRUE(contains(linear.title, "constraints met"));
  EXPECT_TRUE(contains(linear.title, "rate limits not met"));
  ASSERT_EQ(linear.x.size(), 4u);
  EXPECT_EQ(linear.x[1], 10.0);
  EXPECT_EQ(linear.y[1], 80.0);
  EXPECT_EQ(linear.x[3], 30.0);
  EXPECT_EQ(linear.y[3], 80.0 - 1.75 * 20.0);

  // The lead's end_time_s, when given, ends the last segment.
  json with_end = small_result("");
  with_end["linearized"]["end_time_s"] = 25.0;
  EXPECT_EQ(figure_named(ground::figures_for_document(with_end), "theta_time").series[1].x[3], 25.0);
}

TEST(PlotCatalogue, StagingMarkersAtEveryIgnitionAndBurnout) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result(""));
  // Against time: a vertical line per event; stage 1 ignites at lift-off, the first point.
  for (const char* name : {"velocity_time", "flight_path_angle_time", "theta_time", "weight_time"}) {
    std::vector<std::pair<double, std::string>> markers;
    for (const ground::XMarker& marker : figure_named(result, name).x_markers)
      markers.emplace_back(marker.x, marker.label);
    EXPECT_EQ(markers, (std::vector<std::pair<double, std::string>>{
                           {0.0, "S1 ign"}, {30.0, "S1 bo"}, {100.0, "S2 ign"}, {110.0, "S2 bo"}}))
        << name;
    EXPECT_TRUE(contains(figure_named(result, name).key_entries.at(0).title, "staging")) << name;
  }
  // Against downrange: labelled points on the curve (the stage's first and last point).
  std::vector<std::string> labels;
  for (const ground::PointMarker& point : figure_named(result, "altitude_downrange").points) {
    if (point.label == "S1 bo") {
      EXPECT_EQ(point.x, 10.0);
      EXPECT_EQ(point.y, 50000.0 / kFeetPerNauticalMile);
    }
    labels.push_back(point.label);
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"S1 bo", "S2 ign", "S2 bo", "max q"}));
}

TEST(PlotCatalogue, MaxQIsMarked) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result(""));
  const ground::Figure& qbar = figure_named(result, "dynamic_pressure_time");
  ASSERT_EQ(qbar.points.size(), 1u);
  EXPECT_EQ(qbar.points[0].x, 10.0);
  EXPECT_EQ(qbar.points[0].y, 400.0);
  EXPECT_EQ(qbar.points[0].label, "max q 400 lbf/ft^2 at 10.0 s");
  const auto has_max_q_line = [](const ground::Figure& figure) {
    for (const ground::XMarker& marker : figure.x_markers) {
      if (marker.label == "max q" && marker.x == 10.0) return true;
    }
    return false;
  };
  EXPECT_TRUE(has_max_q_line(figure_named(result, "alpha_time")));
  EXPECT_TRUE(has_max_q_line(figure_named(result, "qalpha_time")));
  const ground::Figure& qalpha = figure_named(result, "qalpha_time");
  ASSERT_FALSE(qalpha.points.empty());
  EXPECT_EQ(qalpha.points.back().label, "peak |QALPHA| 300 at 30.0 s");
}

TEST(PlotCatalogue, AscentViewsEndAtTheBurnoutBeforeTheLastCoast) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result(""));
  const ground::Figure& ascent = figure_named(result, "altitude_downrange_ascent");
  EXPECT_EQ(ascent.x_max, 10.0) << "the downrange at the stage 1 burnout";
  EXPECT_TRUE(contains(ascent.title, "ascent through S1 burnout"));
  for (const double x : ascent.series.at(0).x) EXPECT_LE(x, 10.0);
  for (const char* name : {"dynamic_pressure_time", "alpha_time", "qalpha_time", "theta_time_ascent"}) {
    const ground::Figure& figure = figure_named(result, name);
    EXPECT_EQ(figure.x_min, 0.0) << name;
    EXPECT_EQ(figure.x_max, 30.0) << name;
    for (const ground::PlotSeries& series : figure.series) {
      for (const double x : series.x) {
        if (std::isfinite(x)) EXPECT_LE(x, 30.0) << name;  // a null is a gap
      }
    }
  }
  // The full-flight views keep everything.
  const ground::Figure& full = figure_named(result, "altitude_downrange");
  EXPECT_TRUE(std::isnan(full.x_max));
  EXPECT_EQ(full.series.at(0).x.back(), 130.0);
  EXPECT_EQ(figure_named(result, "theta_time").series.at(0).x.back(), 110.0);
}

TEST(PlotCatalogue, AltitudeIsInNauticalMiles) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result(""));
  const ground::Figure& altitude = figure_named(result, "altitude_downrange");
  EXPECT_EQ(altitude.y_label, "altitude (n.mi.)");
  EXPECT_DOUBLE_EQ(altitude.series.at(0).y[3], 50000.0 / 6076.115485564304);
}

TEST(PlotCatalogue, ZeroAlphaWindowIsShaded) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result(""));
  for (const char* name :
       {"theta_time", "alpha_time", "qalpha_time", "dynamic_pressure_time", "flight_path_angle_time"}) {
    const ground::Figure& figure = figure_named(result, name);
    ASSERT_EQ(figure.bands.size(), 1u) << name;
    EXPECT_EQ(figure.bands[0].from, 10.0) << "the steps starting at the flagged points 10 and 20 s";
    EXPECT_EQ(figure.bands[0].to, 30.0);
    EXPECT_TRUE(contains(figure.band_title, "zero-alpha")) << name;
  }
  EXPECT_TRUE(figure_named(result, "velocity_time").bands.empty());
}

TEST(PlotCatalogue, TitleNamesTheCaseHeadingAndRunStatus) {
  json document = small_result("THE TITLE");
  EXPECT_EQ(figure_named(ground::figures_for_document(document), "velocity_time").subtitle,
            (std::vector<std::string>{"THE TITLE", "HEADING - converged, kOk"}));
  document["converged"] = false;
  document["status"] = "kGuidanceDidNotConverge";
  document["case_status"] = "kGuidanceDidNotConverge";
  EXPECT_EQ(ground::run_status_text(document), "not converged, kGuidanceDidNotConverge");
  document["converged"] = true;
  document["status"] = "kOk";
  document["case_status"] = "kLinearizationDidNotConverge";
  document["case_failed_step"] = "linearization";
  EXPECT_EQ(ground::run_status_text(document),
            "converged, kOk; case failed: linearization: kLinearizationDidNotConverge");
  document.erase("converged");
  document["status"] = "kAltitudeBelowSurface";
  EXPECT_EQ(ground::run_status_text(document), "simulated, kAltitudeBelowSurface");
}

TEST(PlotCatalogue, NewFiguresDrawTheirColumns) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result(""));
  const ground::Figure& gamma = figure_named(result, "flight_path_angle_time");
  ASSERT_EQ(gamma.series.size(), 2u);
  EXPECT_EQ(gamma.series[0].y[1], 78.0);
  EXPECT_EQ(gamma.series[1].y[1], 77.0);
  EXPECT_EQ(figure_named(result, "alpha_time").series.at(0).y[2], -2.0);
  EXPECT_EQ(figure_named(result, "qalpha_time").series.at(0).y[2], -200.0);
  const ground::Figure& weight = figure_named(result, "weight_time");
  EXPECT_TRUE(weight.y_log);
  EXPECT_EQ(weight.series.at(0).y[1], 9500.0);
}

TEST(PlotCatalogue, GroundTrackMarksTheLaunchSiteAndBreaksAtTheDateLine) {
  json document = small_result("");
  const ground::DocumentFigures result = ground::figures_for_document(document);
  const ground::Figure& track = figure_named(result, "ground_track");
  EXPECT_EQ(track.x_label, "longitude (deg east)");
  EXPECT_EQ(track.series.at(0).x[0], -75.0);
  EXPECT_EQ(track.series.at(0).y[0], 37.8);
  ASSERT_FALSE(track.points.empty());
  EXPECT_EQ(track.points[0].label, "launch site 37.80 N, 75.00 W");
  EXPECT_TRUE(std::isfinite(track.aspect_ratio));
  EXPECT_LT(track.x_min, -75.0);

  document["trajectory"][5]["longitude_deg"] = 179.5;
  document["trajectory"][6]["longitude_deg"] = -179.5;
  const ground::DocumentFigures crossed = ground::figures_for_document(document);
  const ground::Figure& crossing = figure_named(crossed, "ground_track");
  const std::vector<double>& x = crossing.series.at(0).x;
  const auto east = std::find(x.begin(), x.end(), 179.5);
  ASSERT_TRUE(east != x.end() && east + 2 < x.end());
  EXPECT_TRUE(std::isnan(*(east + 1))) << "a gap between 179.5 and -179.5";
  EXPECT_EQ(*(east + 2), -179.5);
}

TEST(PlotCatalogue, ConvergenceScalesConstraintErrorsByTheirDeadbands) {
  const ground::DocumentFigures result = ground::figures_for_document(small_result(""));
  const ground::Figure& convergence = figure_named(result, "convergence");
  EXPECT_EQ(convergence.y_label, "payoff (lb)");
  EXPECT_TRUE(convergence.y2_log);
  ASSERT_EQ(convergence.y_lines.size(), 1u);
  EXPECT_EQ(convergence.y_lines[0].y, 1.0) << "the deadband";
  std::vector<std::string> titles;
  for (const ground::PlotSeries& series : convergence.series) titles.push_back(series.title);
  EXPECT_EQ(titles, (std::vector<std::string>{"payoff (left axis)", "successful run", "unsuccessful run",
                                              "altitude (right axis)", "total_heating excess (right axis)"}));
  EXPECT_EQ(convergence.series[0].y, (std::vector<double>{250.0, 260.0, 270.0}));
  EXPECT_EQ(convergence.series[1].x, (std::vector<double>{2.0, 3.0}));
  EXPECT_EQ(convergence.series[2].x, (std::vector<double>{1.0}));
  const ground::PlotSeries& altitude = convergence.series[3];
  EXPECT_TRUE(altitude.second_axis);
  EXPECT_EQ(altitude.y[0], 2.0) << "|-40000| / 20000";
  EXPECT_TRUE(std::isnan(altitude.y[1])) << "no error: nothing on a log axis";
  EXPECT_EQ(altitude.y[2], 0.05);
  const ground::PlotSeries& heating = convergence.series[4];
  EXPECT_TRUE(std::isnan(heating.y[0]));
  EXPECT_EQ(heating.y[1], 0.5) << "an inequality: the excess (desired - achieved = -5) over the deadband";
  EXPECT_TRUE(std::isnan(heating.y[2])) << "within its limit: no error";

  json simulate = small_result("");
  simulate.erase("iterations");
  const ground::DocumentFigures without = ground::figures_for_document(simulate);
  EXPECT_EQ(without.skipped, (std::vector<std::string>{"convergence (no member 'iterations')"}));
}

TEST(PlotCatalogue, CasesAreOverlaidWithALegendPerCase) {
  json one = small_result("SAME TITLE");
  json two = small_result("SAME TITLE");
  two["case_heading"] = "SECOND";
  two["converged"] = false;
  two["status"] = "kGuidanceDidNotConverge";
  two.erase("linearized");
  const ground::DocumentFigures result = ground::figures_for_cases({&one, &two});
  ASSERT_EQ(result.figures.size(), kFigures.size()) << "one figure per name, not one per case";
  const ground::Figure& velocity = figure_named(result, "velocity_time");
  ASSERT_EQ(velocity.series.size(), 4u);
  EXPECT_EQ(velocity.series[0].color, 1);
  EXPECT_EQ(velocity.series[1].color, 1);
  EXPECT_EQ(velocity.series[2].color, 2);
  EXPECT_EQ(velocity.series[1].dash_type, velocity.series[3].dash_type) << "VI dashed alike in both cases";
  EXPECT_NE(velocity.series[0].dash_type, velocity.series[1].dash_type);
  std::vector<std::string> legend;
  for (const ground::KeyEntry& entry : velocity.key_entries) legend.push_back(entry.title);
  EXPECT_EQ(legend, (std::vector<std::string>{"staging: Sn ign = stage n ignition, Sn bo = burnout",
                                              "case 1: HEADING - converged, kOk",
                                              "case 2: SECOND - not converged, kGuidanceDidNotConverge",
                                              "VEL, Earth-relative", "VI, inertial"}));
  EXPECT_EQ(velocity.subtitle,
            (std::vector<std::string>{"SAME TITLE", "2 cases overlaid, a colour per case"}));
  // A figure of one curve a case has a legend entry per case only.
  std::size_t entries = 0;
  for (const ground::KeyEntry& entry : figure_named(result, "weight_time").key_entries) {
    entries += contains(entry.title, "case ") ? 1 : 0;
  }
  EXPECT_EQ(entries, 2u);
  EXPECT_EQ(figure_named(result, "weight_time").key_entries.size(), 3u);
  EXPECT_EQ(figure_named(result, "theta_time").series.size(), 3u) << "case 2 has no linearized program";
}

TEST(PlotCatalogue, AbsentDataSkipsThePlotOnly) {
  json simulate = small_result("");
  simulate.erase("linearized");
  simulate.erase("iterations");
  const ground::DocumentFigures result = ground::figures_for_document(simulate);
  ASSERT_EQ(result.figures.size(), kTrajectoryFigures.size());
  EXPECT_EQ(figure_named(result, "theta_time").series.size(), 1u) << "no overlay without 'linearized'";
  EXPECT_EQ(figure_named(result, "theta_time").series[0].title, "theta");

  const ground::DocumentFigures empty = ground::figures_for_document(json{{"trajectory", json::array()}});
  EXPECT_TRUE(empty.figures.empty());
  ASSERT_EQ(empty.skipped.size(), kFigures.size());
  EXPECT_EQ(empty.skipped[0], "altitude_downrange_ascent ('trajectory' is empty)");
  EXPECT_EQ(empty.skipped.back(), "convergence (no member 'iterations')");
  EXPECT_EQ(ground::figures_for_document(json::object()).skipped[0],
            "altitude_downrange_ascent (no member 'trajectory')");
}

TEST(PlotCatalogue, MalformedFieldsAreNamed) {
  const auto message = [](const json& document) -> std::string {
    try {
      ground::figures_for_document(document);
    } catch (const ground::PlotDataError& e) {
      return e.what();
    }
    return "no error";
  };
  json bad = small_result("");
  bad["trajectory"][1]["altitude_ft"] = "high";
  EXPECT_EQ(message(bad), "trajectory[1].altitude_ft: expected a number or null, found string");
  bad = small_result("");
  bad["trajectory"][2].erase("time_s");
  EXPECT_EQ(message(bad), "trajectory[2]: no member 'time_s'");
  bad = small_result("");
  bad["trajectory"] = 5;
  EXPECT_EQ(message(bad), "trajectory: expected an array, found number");
  bad = small_result("");
  bad["linearized"]["segments"][1]["rate_deg_s"] = true;
  EXPECT_EQ(message(bad), "linearized.segments[1].rate_deg_s: expected a number or null, found boolean");
  EXPECT_TRUE(contains(message(json::array()), "expected a JSON object"));
}

// ---- the command ---------------------------------------------------------------------------------

TEST(PlotCommand, HelpAndDocsNameEveryFigure) {
  const CommandResult help = run_tolip_executable({"plot", "--help"});
  ASSERT_EQ(help.exit_code, 0);
  const std::string docs =
      read_text_file(std::string(tolip::repository_paths::source_dir()) + "/docs/cli.md");
  const std::string guide =
      read_text_file(std::string(tolip::repository_paths::source_dir()) + "/docs/user-guide.md");
  for (const ground::PlotKind& kind : ground::plot_catalogue()) {
    EXPECT_TRUE(contains(help.out, kind.name)) << kind.name;
    EXPECT_TRUE(contains(docs, std::string("| `") + kind.name + "` |")) << "docs/cli.md lacks " << kind.name;
    EXPECT_TRUE(contains(guide, std::string("`") + kind.name + "`"))
        << "docs/user-guide.md lacks " << kind.name;
  }
  EXPECT_FALSE(contains(docs, "NAME.caseN")) << "no per-case figures any more";
}

TEST(PlotCommand, SimulateResultGivesEveryFigureAsPngAndSvg) {
  REQUIRE_GNUPLOT();
  ScratchDirectory scratch("plot_simulate");
  const CommandResult simulate = run_tolip_executable(
      {"simulate", std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml", "--json"});
  ASSERT_EQ(simulate.exit_code, 0) << simulate.err;
  const std::string result = write_file(scratch, "result.json", simulate.out);
  const fs::path out = scratch / "figures";  // made by the command

  const CommandResult plot = run_tolip_executable({"plot", result, "--out", out.string()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  EXPECT_EQ(plot.err, "");
  expect_images(out, "", kTrajectoryFigures);
  // The example asks for radar tracking (IP(24)): a figure per station of data block 41 besides.
  for (const char* station : {"wallops", "bermuda", "canaveral", "grandturk", "antigua", "ascension"}) {
    EXPECT_TRUE(fs::exists(out / ("radar_" + std::string(station) + ".png"))) << station;
    EXPECT_TRUE(fs::exists(out / ("radar_" + std::string(station) + ".svg"))) << station;
  }
  // And hardover turns (IP(22)): one figure of every turn's change in gamma.
  EXPECT_TRUE(fs::exists(out / "hardover_gamma.png"));
  EXPECT_EQ(entry_count(out), 2 * (kTrajectoryFigures.size() + 6 + 1))
      << "no data, scripts or temporary files left";
  EXPECT_TRUE(contains(plot.out, "skipped convergence (no member 'iterations')"));
  // The title carries the case heading and the run status.
  EXPECT_TRUE(contains(read_text_file(out / "velocity_time.svg"), "simulated, kOk"));
  EXPECT_TRUE(contains(plot.out, "wrote " + (out / "theta_time.svg").string()));
}

TEST(PlotCommand, LinearizedProgramIsOverlaid) {
  REQUIRE_GNUPLOT();
  ScratchDirectory scratch("plot_linearized");
  const std::string result = write_file(scratch, "result.json", small_result("CASE \"A\" ^_@ {x}").dump());
  const CommandResult plot = run_tolip_executable({"plot", result, "--out", scratch.path().string()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  expect_images(scratch.path(), "");
  const std::string svg = read_text_file(scratch / "theta_time.svg");
  EXPECT_TRUE(contains(svg, "linearized program, constraints met, rate limits not met"));
  EXPECT_TRUE(contains(svg, "theta, optimum"));
}

TEST(PlotCommand, ArrayOfCasesIsOverlaidOnOneSetOfFigures) {
  REQUIRE_GNUPLOT();
  ScratchDirectory scratch("plot_cases");
  json two = small_result("TWO");
  two["case_heading"] = "SECOND HEADING";
  const json cases = json::array({small_result("ONE"), two});
  const std::string result = write_file(scratch, "cases.json", cases.dump());
  const fs::path out = scratch / "out";
  const CommandResult plot = run_tolip_executable({"plot", result, "--out", out.string()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  expect_images(out, "");
  EXPECT_EQ(entry_count(out), 2 * kFigures.size()) << "no per-case files";
  const std::string svg = read_text_file(out / "altitude_downrange.svg");
  EXPECT_TRUE(contains(svg, "case 1: HEADING - converged, kOk"));
  EXPECT_TRUE(contains(svg, "case 2: SECOND HEADING - converged, kOk"));
}

TEST(PlotCommand, FiguresShowStagingMaxQAndTheZeroAlphaWindow) {
  REQUIRE_GNUPLOT();
  ScratchDirectory scratch("plot_marks");
  const std::string result = write_file(scratch, "result.json", small_result("MARKS").dump());
  const CommandResult plot = run_tolip_executable({"plot", result, "--out", scratch.path().string()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  const std::string svg = read_text_file(scratch / "dynamic_pressure_time.svg");
  EXPECT_TRUE(contains(svg, "max q 400 lbf/ft^2 at 10.0 s"));
  EXPECT_TRUE(contains(svg, "S1 bo"));
  EXPECT_TRUE(contains(svg, "zero-alpha window"));
  EXPECT_TRUE(contains(svg, "HEADING - converged, kOk"));
  EXPECT_TRUE(contains(read_text_file(scratch / "convergence.svg"), "deadband"));
}

TEST(PlotScript, MarkersCloseTogetherShareOneLabel) {
  ScratchDirectory scratch("plot_script");
  ground::Figure figure;
  figure.name = "f";
  figure.title = "T";
  ground::PlotSeries series;
  series.x = {0.0, 600.0};
  series.y = {0.0, 1.0};
  figure.series.push_back(series);
  figure.x_markers = {{45.0, "S1 bo", 0}, {50.0, "S2 ign", 0}, {300.0, "S2 bo", 0}, {900.0, "far away", 0}};
  figure.bands = {{10.0, 20.0}, {550.0, 700.0}};
  figure.band_title = "window";
  std::vector<ground::PlotOutput> outputs;
  const std::string name = ground::write_gnuplot_files({figure}, scratch.path().string(), &outputs);
  const std::string script = read_text_file(scratch / name);
  EXPECT_TRUE(contains(script, "\"S1 bo, S2 ign\" at first 45"));
  EXPECT_TRUE(contains(script, "\"S2 bo\" at first 300"));
  EXPECT_FALSE(contains(script, "far away")) << "a marker beyond the data is not drawn";
  EXPECT_TRUE(contains(script, "rectangle from first 550, graph 0 to first 600,"))
      << "a band clipped to the data";
  EXPECT_TRUE(contains(script, "keyentry with boxes"));
  EXPECT_EQ(outputs.size(), 2u);
}

// equal_axis_scale gives gnuplot's equal-unit shape (size ratio -1) and takes the place of any
// height / width ratio; without it a finite aspect_ratio is written as that ratio.
TEST(PlotScript, EqualAxisScaleIsSizeRatioMinusOne) {
  ScratchDirectory scratch("plot_equal_axes");
  ground::Figure figure;
  figure.name = "scatter";
  figure.title = "T";
  ground::PlotSeries series;
  series.x = {0.0, 10.0};
  series.y = {0.0, 1.0};
  figure.series.push_back(series);
  figure.aspect_ratio = 0.5;
  figure.equal_axis_scale = true;
  ground::Figure map = figure;
  map.name = "map";
  map.equal_axis_scale = false;
  std::vector<ground::PlotOutput> outputs;
  const std::string script =
      read_text_file(scratch / ground::write_gnuplot_files({figure, map}, scratch.path().string(), &outputs));
  const std::size_t map_from = script.find("set output \"map.png\"");
  ASSERT_NE(map_from, std::string::npos);
  const std::string scatter_commands = script.substr(0, map_from);
  const std::string map_commands = script.substr(map_from);
  EXPECT_TRUE(contains(scatter_commands, "\nset size ratio -1\n"));
  EXPECT_FALSE(contains(scatter_commands, "set size ratio 0.5"));
  EXPECT_TRUE(contains(map_commands, "\nset size ratio 0.5\n"));
  EXPECT_FALSE(contains(map_commands, "set size ratio -1"));
}

TEST(PlotCommand, MalformedJsonIsNamedAndNothingIsWritten) {
  ScratchDirectory scratch("plot_malformed");
  const fs::path out = scratch / "out";
  const std::string broken = write_file(scratch, "broken.json", "{\"trajectory\": [\n  {\"time_s\": x}]}");
  CommandResult plot = run_tolip_executable({"plot", broken, "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_EQ(plot.err,
            "tolip: " + broken +
                ": not valid JSON: parse error at line 2, column 14: syntax error while parsing value - "
                "invalid literal; last read: '\"time_s\": x'\n");
  EXPECT_EQ(plot.out, "");
  EXPECT_FALSE(fs::exists(out)) << "the output directory is not even made";

  json second = small_result("");
  second["trajectory"][3]["velocity_ft_s"] = json::array();
  const std::string bad_field =
      write_file(scratch, "bad_field.json", json::array({small_result(""), second}).dump());
  plot = run_tolip_executable({"plot", bad_field, "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_EQ(plot.err, "tolip: " + bad_field +
                          ": case 2: trajectory[3].velocity_ft_s: expected a number or null, found array\n");

  const std::string nothing = write_file(scratch, "nothing.json", "{\"program\": \"tolip\"}");
  plot = run_tolip_executable({"plot", nothing, "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_EQ(plot.err,
            "tolip: " + nothing + ": nothing to plot: altitude_downrange_ascent (no member 'trajectory')\n");

  // The Monte Carlo and dispersion documents: what to run instead, not a missing 'trajectory'.
  const std::string statistics =
      write_file(scratch, "montecarlo.json",
                 R"({"seed": 7, "samples": 10, "sampled_codes": [1], "staging_points": []})");
  plot = run_tolip_executable({"plot", statistics, "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_EQ(plot.err, "tolip: " + statistics +
                          ": nothing to plot: a 'tolip montecarlo' document holds the statistics, not the "
                          "samples its figures need: they are drawn by 'tolip montecarlo DECK --samples N "
                          "--seed S --plots DIR'\n");
  const std::string tables =
      write_file(scratch, "dispersions.json", R"({"case": 1, "optimizer_status": "kOk", "dispersions": {}})");
  plot = run_tolip_executable({"plot", tables, "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_NE(plot.err.find("a 'tolip dispersions' document holds the dispersion tables"), std::string::npos)
      << plot.err;
  EXPECT_FALSE(fs::exists(out));

  plot = run_tolip_executable({"plot", (scratch / "absent.json").string(), "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_EQ(plot.err, "tolip: " + (scratch / "absent.json").string() +
                          ": cannot open the result file: No such file or directory\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(PlotCommand, MissingGnuplotIsExplainedAndLeavesTheDirectoryAlone) {
  ScratchDirectory scratch("plot_no_gnuplot");
  const std::string result = write_file(scratch, "result.json", small_result("").dump());
  const fs::path out = scratch / "out";
  fs::create_directories(out);
  std::ofstream(out / "theta_time.png") << "old";

  CommandResult plot =
      run_tolip_executable({"plot", result, "--out", out.string(), "--gnuplot", "/nonexistent/gnuplot"});
  EXPECT_EQ(plot.exit_code, 1);
  EXPECT_TRUE(contains(plot.err,
                       "tolip: cannot run gnuplot ('/nonexistent/gnuplot'): No such file or directory; "
                       "install the Debian package gnuplot-nox"))
      << plot.err;
  EXPECT_EQ(plot.out, "");

  // A gnuplot that fails: still nothing written.
  plot = run_tolip_executable({"plot", result, "--out", out.string(), "--gnuplot", "false"});
  EXPECT_EQ(plot.exit_code, 1);
  EXPECT_TRUE(contains(plot.err, "tolip: gnuplot ('false') failed (exit code 1)")) << plot.err;

  EXPECT_EQ(read_text_file(out / "theta_time.png"), "old");
  EXPECT_EQ(entry_count(out), 1u);
}

TEST(PlotCommand, UnwritableDirectoryIsNamed) {
  ScratchDirectory scratch("plot_unwritable");
  const std::string result = write_file(scratch, "result.json", small_result("").dump());
  const std::string file = write_file(scratch, "plain_file", "not a directory");

  CommandResult plot = run_tolip_executable({"plot", result, "--out", file});
  EXPECT_EQ(plot.exit_code, 1);
  EXPECT_EQ(plot.err, "tolip: cannot write to '" + file + "': not a directory\n");

  plot = run_tolip_executable({"plot", result, "--out", file + "/sub"});
  EXPECT_EQ(plot.exit_code, 1);
  EXPECT_TRUE(contains(plot.err, "tolip: cannot create the output directory '" + file + "/sub'")) << plot.err;
  EXPECT_EQ(read_text_file(file), "not a directory");
}

// A figure whose data hold no finite value (all null, or absurd magnitudes) is skipped with a note
// naming it, the others drawn (not a raw gnuplot error).
json result_with_altitudes(const json& altitude) {
  json document = {{"program", "tolip"}, {"title", "HOSTILE"}};
  document["trajectory"] = json::array();
  for (int i = 0; i < 4; ++i) {
    json p = point(10.0 * i, 1, 1.0 * i, 0.0, 100.0 * i, 50.0 * i, 90.0 - i);
    p["altitude_ft"] = altitude;
    document["trajectory"].push_back(std::move(p));
  }
  return document;
}

TEST(PlotCatalogue, FigureWithoutAFiniteValueIsSkippedWithANote) {
  for (const json& altitude : {json(nullptr), json(1e308), json(-1e308)}) {
    const tolip::ground::DocumentFigures figures =
        tolip::ground::figures_for_document(result_with_altitudes(altitude));
    std::set<std::string> names;
    for (const tolip::ground::Figure& figure : figures.figures) names.insert(figure.name);
    std::set<std::string> expected(kTrajectoryFigures.begin(), kTrajectoryFigures.end());
    expected.erase("altitude_downrange_ascent");
    expected.erase("altitude_downrange");
    expected.erase("impact_locus");  // the document has no member "impact"
    EXPECT_EQ(names, expected) << altitude;
    ASSERT_EQ(figures.notes.size(), 2u) << altitude;
    EXPECT_EQ(
        figures.notes[1],
        "figure altitude_downrange skipped: no finite value to draw (every value null, or beyond 1e30 in "
        "magnitude)");
  }
}

// The per-station, hardover, HIL and autopilot figures are named in their notes too: the note of a
// radar station whose every point is null names its figure (radar_wallops), as the catalogue's do.
TEST(PlotCatalogue, SkippedRadarFigureIsNamedInItsNote) {
  json document = result_with_altitudes(json(1000.0));
  json points = json::array();
  for (int i = 0; i < 3; ++i) {
    points.push_back({{"time_s", nullptr}, {"azimuth_deg", nullptr}, {"elevation_deg", nullptr}});
  }
  document["radar"] = {{"stations", json::array({{{"id", "WALLOPS"}, {"points", points}}})}};
  const tolip::ground::DocumentFigures figures = tolip::ground::figures_for_document(document);
  for (const tolip::ground::Figure& figure : figures.figures) EXPECT_NE(figure.name, "radar_wallops");
  ASSERT_FALSE(figures.notes.empty());
  EXPECT_EQ(figures.notes.back(),
            "figure radar_wallops skipped: no finite value to draw (every value null, or beyond 1e30 in "
            "magnitude)");
}

TEST(PlotCommand, AltitudeAllNullOrHugeSkipsThatFigureAndDrawsTheRest) {
  if (!gnuplot_installed()) GTEST_SKIP() << "gnuplot is not installed (gnuplot-nox)";
  ScratchDirectory scratch("hostile_plot_null");
  for (const json& altitude : {json(nullptr), json(1e308)}) {
    const std::string source = (scratch / "result.json").string();
    std::ofstream(source) << result_with_altitudes(altitude).dump();
    const fs::path out = scratch / "plots";
    fs::remove_all(out);
    const CommandResult result = run_tolip_executable({"plot", source, "--out", out.string()});
    EXPECT_EQ(result.exit_code, 0) << altitude << ": " << result.err;
    EXPECT_EQ(
        result.err,
        "tolip: " + source +
            ": figure altitude_downrange_ascent skipped: no finite value to draw (every value null, or "
            "beyond "
            "1e30 in magnitude)\n"
            "tolip: " +
            source +
            ": figure altitude_downrange skipped: no finite value to draw (every value null, or beyond 1e30 "
            "in magnitude)\n");
    EXPECT_FALSE(fs::exists(out / "altitude_downrange.png"));
    EXPECT_TRUE(fs::exists(out / "velocity_time.png"));
    EXPECT_TRUE(fs::exists(out / "theta_time.svg"));
  }
}

}  // namespace
}  // namespace tolip::test
