// `tolip plot` (tolip_ground/plot.hpp): figures drawn by gnuplot from simulate/optimize JSON, as
// PNG and SVG; malformed results, a missing gnuplot and an unwritable directory give named errors
// and leave the output directory as it was. Tests that need gnuplot skip when it is not installed
// (scripts/setup.sh installs gnuplot-nox).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::vector<std::string> kFigures = {"altitude_downrange", "velocity_time", "dynamic_pressure_time",
                                           "theta_time"};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool gnuplot_installed() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

#define REQUIRE_GNUPLOT()                                                               \
  do {                                                                                  \
    if (!gnuplot_installed()) GTEST_SKIP() << "gnuplot is not installed (gnuplot-nox)"; \
  } while (false)

json point(double t, double range, double altitude, double velocity, json qbar, double theta) {
  return json{{"time_s", t},
              {"range_nmi", range},
              {"altitude_ft", altitude},
              {"velocity_ft_s", velocity},
              {"inertial_velocity_ft_s", velocity + 1000.0},
              {"dynamic_pressure_lbf_ft2", std::move(qbar)},
              {"theta_deg", theta}};
}

// A small result in the optimize --json schema, with a linearized program.
json small_result(const std::string& title) {
  json document = {{"program", "tolip"}, {"title", title}, {"iterations", json::array()}};
  document["stage_events"] = json::array({json{{"stage", 1}, {"end_time_s", 30.0}}});
  document["trajectory"] = json::array({point(0, 0, 0, 0, 0.0, 90), point(10, 1, 5000, 800, 400.0, 80),
                                        point(20, 4, 20000, 2000, nullptr, 60), point(30, 10, 50000, 4000, 100.0, 45)});
  document["linearized"] = {
      {"segments", json::array({json{{"stage", 1}, {"start_stage_time_s", 0.0}, {"start_time_s", 0.0},
                                     {"theta_deg", 90.0}, {"rate_deg_s", -1.0}},
                                json{{"stage", 1}, {"start_stage_time_s", 10.0}, {"start_time_s", 10.0},
                                     {"theta_deg", 80.0}, {"rate_deg_s", -1.75}}})},
      {"constraints_met", true},
      {"rate_limits_met", false},
      {"payoff", 300.0}};
  return document;
}

std::string write_file(const ScratchDirectory& scratch, const std::string& name, const std::string& text) {
  const std::string path = (scratch / name).string();
  std::ofstream(path) << text;
  return path;
}

void expect_images(const fs::path& dir, const std::string& suffix) {
  for (const std::string& figure : kFigures) {
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

  const ground::Figure& qbar = result.figures[2];
  EXPECT_EQ(qbar.name, "dynamic_pressure_time");
  ASSERT_EQ(qbar.series.size(), 1u);
  EXPECT_TRUE(std::isnan(qbar.series[0].y[2])) << "a null is a gap";

  // theta: the optimum, then the linearized program, segment by segment, the last one to the end
  // of its stage (no end_time_s given).
  const ground::Figure& theta = result.figures[3];
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
  EXPECT_EQ(ground::figures_for_document(with_end).figures[3].series[1].x[3], 25.0);
}

TEST(PlotCatalogue, AbsentDataSkipsThePlotOnly) {
  json simulate = small_result("");
  simulate.erase("linearized");
  simulate.erase("iterations");
  const ground::DocumentFigures result = ground::figures_for_document(simulate);
  ASSERT_EQ(result.figures.size(), kFigures.size());
  EXPECT_EQ(result.figures[3].series.size(), 1u) << "no overlay without 'linearized'";
  EXPECT_EQ(result.figures[3].series[0].title, "theta");

  const ground::DocumentFigures empty = ground::figures_for_document(json{{"trajectory", json::array()}});
  EXPECT_TRUE(empty.figures.empty());
  ASSERT_EQ(empty.skipped.size(), kFigures.size());
  EXPECT_EQ(empty.skipped[0], "altitude_downrange ('trajectory' is empty)");
  EXPECT_EQ(ground::figures_for_document(json::object()).skipped[0], "altitude_downrange (no member 'trajectory')");
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

TEST(PlotCommand, SimulateResultGivesEveryFigureAsPngAndSvg) {
  REQUIRE_GNUPLOT();
  ScratchDirectory scratch("plot_simulate");
  const CommandResult simulate =
      run_tolip_executable({"simulate", std::string(TOLIP_EXAMPLES_DIR) + "/scout/mission.toml", "--json"});
  ASSERT_EQ(simulate.exit_code, 0) << simulate.err;
  const std::string result = write_file(scratch, "result.json", simulate.out);
  const fs::path out = scratch / "figures";  // made by the command

  const CommandResult plot = run_tolip_executable({"plot", result, "--out", out.string()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  EXPECT_EQ(plot.err, "");
  expect_images(out, "");
  EXPECT_EQ(entry_count(out), 2 * kFigures.size()) << "no data, scripts or temporary files left";
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

TEST(PlotCommand, ArrayOfCasesGivesFilesPerCase) {
  REQUIRE_GNUPLOT();
  ScratchDirectory scratch("plot_cases");
  const json cases = json::array({small_result("ONE"), small_result("TWO")});
  const std::string result = write_file(scratch, "cases.json", cases.dump());
  const fs::path out = scratch / "out";
  const CommandResult plot = run_tolip_executable({"plot", result, "--out", out.string()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  expect_images(out, ".case1");
  expect_images(out, ".case2");
  EXPECT_EQ(entry_count(out), 4 * kFigures.size());
}

TEST(PlotCommand, MalformedJsonIsNamedAndNothingIsWritten) {
  ScratchDirectory scratch("plot_malformed");
  const fs::path out = scratch / "out";
  const std::string broken = write_file(scratch, "broken.json", "{\"trajectory\": [\n  {\"time_s\": x}]}");
  CommandResult plot = run_tolip_executable({"plot", broken, "--out", out.string()});
  EXPECT_EQ(plot.exit_code, 2);
  EXPECT_EQ(plot.err, "tolip: " + broken +
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
  EXPECT_EQ(plot.err, "tolip: " + nothing + ": nothing to plot: altitude_downrange (no member 'trajectory')\n");

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
  EXPECT_TRUE(contains(plot.err, "tolip: cannot run gnuplot ('/nonexistent/gnuplot'): No such file or directory; "
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
    document["trajectory"].push_back(json{{"time_s", 10.0 * i},
                                          {"range_nmi", 1.0 * i},
                                          {"altitude_ft", altitude},
                                          {"velocity_ft_s", 100.0 * i},
                                          {"inertial_velocity_ft_s", 100.0 * i + 1000.0},
                                          {"dynamic_pressure_lbf_ft2", 50.0 * i},
                                          {"theta_deg", 90.0 - i}});
  }
  return document;
}

TEST(PlotCatalogue, FigureWithoutAFiniteValueIsSkippedWithANote) {
  for (const json& altitude : {json(nullptr), json(1e308), json(-1e308)}) {
    const tolip::ground::DocumentFigures figures = tolip::ground::figures_for_document(result_with_altitudes(altitude));
    std::set<std::string> names;
    for (const tolip::ground::Figure& figure : figures.figures) names.insert(figure.name);
    EXPECT_EQ(names, (std::set<std::string>{"velocity_time", "dynamic_pressure_time", "theta_time"})) << altitude;
    ASSERT_EQ(figures.notes.size(), 1u) << altitude;
    EXPECT_EQ(figures.notes[0],
              "figure altitude_downrange skipped: no finite value to draw (every value null, or beyond 1e30 in "
              "magnitude)");
  }
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
    EXPECT_EQ(result.err,
              "tolip: " + source +
                  ": figure altitude_downrange skipped: no finite value to draw (every value null, or beyond 1e30 "
                  "in magnitude)\n");
    EXPECT_FALSE(fs::exists(out / "altitude_downrange.png"));
    EXPECT_TRUE(fs::exists(out / "velocity_time.png"));
    EXPECT_TRUE(fs::exists(out / "theta_time.svg"));
  }
}

}  // namespace
}  // namespace tolip::test
