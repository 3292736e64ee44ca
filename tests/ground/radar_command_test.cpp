// Sec. 18, 22: `tolip radar`, and the radar tracking that simulate adds with IP(24) = 1: a listing
// page per station in the manual's units, the JSON member `radar`, the CSV, the plots, and bad
// input (no data block 41, latitudes beyond +-90 deg, a bad station count) rejected with the field
// named and nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "support/reference_data.hpp"
#include "support/text_match.hpp"
#include "tolip_ground/plot.hpp"
#include "tolip_ground/radar_report.hpp"

namespace tolip::test {
namespace {

using json = nlohmann::json;

std::size_t count_of(const std::string& text, const std::string& needle) {
  std::size_t count = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++count;
  return count;
}

TEST(Sec18RadarCommand, ListsAPagePerStationInYardsDegreesDegreesMinutesAndMils) {
  const CommandResult result = run_tolip_executable({"radar", reference_deck()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* id : {"WALLOPS", "BERMUDA", "CANAVERAL", "GRANDTURK", "ANTIGUA", "ASCENSION"}) {
    EXPECT_TRUE(contains(result.out, std::string("STATION ") + id)) << id;
    EXPECT_TRUE(contains(result.out, std::string("RADAR ") + id + "   PAGE")) << id;
  }
  EXPECT_TRUE(contains(result.out, "YDS"));
  EXPECT_TRUE(contains(result.out, "DEG MIN"));
  EXPECT_TRUE(contains(result.out, "MILS"));
  EXPECT_TRUE(contains(result.out, "IBM OCTAL COLUMNS ARE LEFT OUT"));
  EXPECT_FALSE(contains(without_input_warnings(result.err), "tolip:")) << result.err;
  EXPECT_FALSE(contains(result.err, "IP(24)")) << "radar is computed: no unused-input warning";
}

// docs/cli.md: every case document opens with the same members, in the same order (one place
// writes them: report_detail::case_document), whichever command printed it.
TEST(Sec18RadarCommand, RadarHardoverAndSimulateDocumentsOpenWithTheSameCaseMembers) {
  const char* const kHead[] = {"program", "title", "case_heading", "date", "status", "status_message"};
  const std::vector<std::string> expected = {"program",      "version", "deck",   "title",
                                             "case_heading", "date",    "status", "status_message"};
  nlohmann::ordered_json first;
  for (const char* command : {"radar", "hardover", "simulate"}) {
    const CommandResult result = run_tolip_executable({command, reference_deck(), "--json"});
    ASSERT_EQ(result.exit_code, 0) << command << ": " << result.err;
    const nlohmann::ordered_json document = nlohmann::ordered_json::parse(result.out);
    std::vector<std::string> keys;
    for (auto it = document.begin(); it != document.end() && keys.size() < expected.size(); ++it) {
      keys.push_back(it.key());
    }
    EXPECT_EQ(keys, expected) << command;
    EXPECT_EQ(document["date"], "1966-07-01") << command << ": data block 3 of the reference deck";
    if (first.is_null()) {
      first = document;
      continue;
    }
    for (const char* key : kHead) EXPECT_EQ(document[key], first[key]) << command << " " << key;
  }
}

TEST(Sec18RadarCommand, JsonUnitsAreConsistentAndSimulateCarriesTheSameTracking) {
  const CommandResult radar = run_tolip_executable({"radar", reference_deck(), "--json"});
  ASSERT_EQ(radar.exit_code, 0) << radar.err;
  const json document = json::parse(radar.out);
  EXPECT_EQ(document["status"], "kOk");
  const json& r = document["radar"];
  EXPECT_EQ(r["computed"], true);
  EXPECT_EQ(r["trajectory"], "simulated");
  ASSERT_EQ(r["stations"].size(), 6u);

  const CommandResult simulate = run_tolip_executable({"simulate", reference_deck(), "--json"});
  ASSERT_EQ(simulate.exit_code, 0) << simulate.err;
  const json flown = json::parse(simulate.out);
  ASSERT_TRUE(flown.contains("radar"));
  EXPECT_EQ(flown["radar"], r) << "one computation for both commands";
  const std::size_t points = flown["trajectory"].size();
  for (const json& station : r["stations"]) {
    ASSERT_EQ(station["points"].size(), points) << "launch through stage-4 burnout: every point";
    for (const json& p : station["points"]) {
      EXPECT_DOUBLE_EQ(p["slant_range_yd"].get<double>() * 3.0, p["slant_range_ft"].get<double>());
      EXPECT_NEAR(p["azimuth_mils"].get<double>(), p["azimuth_deg"].get<double>() * 6400.0 / 360.0, 1e-9);
      EXPECT_NEAR(p["elevation_mils"].get<double>(), p["elevation_deg"].get<double>() * 6400.0 / 360.0, 1e-9);
      EXPECT_GE(p["azimuth_deg"].get<double>(), 0.0);
      EXPECT_LT(p["azimuth_deg"].get<double>(), 360.0);
    }
    EXPECT_EQ(station["points"][0]["time_s"], 0.0);
  }
  // Wallops sees the launch 2 km away, nearly level; Ascension (6,000 n.mi.) far below its horizon.
  EXPECT_LT(r["stations"][0]["points"][0]["slant_range_ft"].get<double>(), 20000.0);
  EXPECT_LT(r["stations"][5]["points"][0]["elevation_deg"].get<double>(), -30.0);
}

TEST(Sec18RadarCommand, CsvHoldsARowPerStationAndPoint) {
  ScratchDirectory scratch("radar_csv");
  const std::string csv = (scratch / "radar.csv").string();
  const CommandResult result = run_tolip_executable({"radar", reference_deck(), "--csv", csv, "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const json document = json::parse(result.out);
  const std::string text = read_text_file(csv);
  const std::size_t points = document["radar"]["stations"][0]["points"].size();
  EXPECT_EQ(count_of(text, "\n"), 1 + 6 * points);
  EXPECT_EQ(text.rfind("station,time_s,stage,slant_range_ft", 0), 0u);
  EXPECT_TRUE(contains(text, "\nASCENSION,"));
}

// simulate --radar-csv / --hardover-csv write the bytes of `tolip radar --csv` / `tolip hardover
// --csv` (the same trajectory); optimize writes those of its final nominal (rows matching its JSON);
// a CSV that cannot be written exits 1 with nothing on stdout and no partial file.
TEST(Sec18RadarCommand, SimulateAndOptimizeWriteTheRadarAndHardoverCsvAtomically) {
  ScratchDirectory scratch("case_csv");
  const std::string radar_alone = (scratch / "radar_alone.csv").string();
  const std::string hardover_alone = (scratch / "hardover_alone.csv").string();
  ASSERT_EQ(run_tolip_executable({"radar", reference_deck(), "--csv", radar_alone}).exit_code, 0);
  ASSERT_EQ(run_tolip_executable({"hardover", reference_deck(), "--csv", hardover_alone}).exit_code, 0);
  const std::string radar = (scratch / "radar.csv").string();
  const std::string hardover = (scratch / "hardover.csv").string();
  const CommandResult simulate = run_tolip_executable(
      {"simulate", reference_deck(), "--json", "--radar-csv", radar, "--hardover-csv", hardover});
  ASSERT_EQ(simulate.exit_code, 0) << simulate.err;
  EXPECT_EQ(read_text_file(radar), read_text_file(radar_alone));
  EXPECT_EQ(read_text_file(hardover), read_text_file(hardover_alone));

  const std::string radar_opt = (scratch / "radar_opt.csv").string();
  const std::string hardover_opt = (scratch / "hardover_opt.csv").string();
  const CommandResult optimize = run_tolip_executable(
      {"optimize", reference_deck(), "--json", "--radar-csv", radar_opt, "--hardover-csv", hardover_opt});
  ASSERT_EQ(optimize.exit_code, 0) << optimize.err;
  const json document = json::parse(optimize.out);
  const std::string text = read_text_file(radar_opt);
  EXPECT_EQ(text.rfind("station,time_s,stage,slant_range_ft", 0), 0u);
  EXPECT_EQ(count_of(text, "\n"), 1 + 6 * document["radar"]["stations"][0]["points"].size());
  std::size_t rows = 0;
  for (const json& turn : document["hardover"]["turns"]) rows += turn["samples"].size();
  const std::string turns = read_text_file(hardover_opt);
  EXPECT_EQ(turns.rfind("stage,mode,failure_time_s,time_s,change_in_gamma_deg", 0), 0u);
  EXPECT_EQ(count_of(turns, "\n"), rows + 1);

  // Into a directory that does not exist: exit 1, stdout empty, nothing written.
  const std::string nowhere = (scratch / "missing" / "radar.csv").string();
  for (const std::string& command : {std::string("simulate"), std::string("optimize")}) {
    for (const std::string& option : {std::string("--radar-csv"), std::string("--hardover-csv")}) {
      const CommandResult failed = run_tolip_executable({command, reference_deck(), option, nowhere});
      EXPECT_EQ(failed.exit_code, 1) << command << " " << option << "\n" << failed.err;
      EXPECT_EQ(failed.out, "") << command << " " << option;
      EXPECT_FALSE(std::filesystem::exists(nowhere));
    }
  }
}

TEST(Sec18RadarCommand, DegreesAndMinutesCarryAndKeepTheSign) {
  EXPECT_EQ(ground::degrees_minutes(130.5), "130 30.00");
  EXPECT_EQ(ground::degrees_minutes(-5.2), "-5 12.00");
  EXPECT_EQ(ground::degrees_minutes(-0.25), "-0 15.00");
  EXPECT_EQ(ground::degrees_minutes(12.99999999), "13 00.00");
  EXPECT_EQ(ground::degrees_minutes(0.0), "0 00.00");
}

// Bad input: exit 2, the block and field named, nothing on stdout, no CSV.
void expect_rejected(const std::string& deck, const std::string& command, const std::string& needle) {
  ScratchDirectory scratch("radar_rejected");
  const std::string csv = (scratch / "out.csv").string();
  const CommandResult result = run_tolip_executable({command, deck, "--csv", csv});
  EXPECT_EQ(result.exit_code, 2) << command << ": " << result.err;
  EXPECT_TRUE(contains(result.err, needle)) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_FALSE(std::filesystem::exists(csv));
}

TEST(Sec18RadarCommand, OptionWithoutDataBlock41IsRejectedNamingTheBlock) {
  ScratchDirectory scratch("radar_no_block");
  std::string text = read_text_file(reference_deck());
  const std::size_t from = text.find("[[radar_station]]");
  ASSERT_NE(from, std::string::npos);
  std::size_t to = text.find("\n# ", from);
  if (to == std::string::npos) to = text.size();
  // Everything from the first station card to the next commented group goes.
  std::string without = text.substr(0, from) + text.substr(to);
  ASSERT_FALSE(contains(without, "[[radar_station]]"));
  const std::string deck = (scratch / "no_radar.toml").string();
  std::ofstream(deck) << without;
  for (const char* command : {"radar", "simulate", "optimize"})
    expect_rejected(deck, command, "data block 41");
  // Without IP(24) the deck is fine, but `tolip radar` itself still needs the stations.
  const std::string off = (scratch / "no_radar_off.toml").string();
  std::ofstream(off) << [&] {
    std::string t = without;
    t.replace(t.find("radar = true"), 12, "radar = false");
    return t;
  }();
  expect_rejected(off, "radar", "data block 41, radar_station");
}

TEST(Sec18RadarCommand, LatitudeBeyondNinetyDegreesIsRejectedNamingTheField) {
  ScratchDirectory scratch("radar_latitude");
  std::string text = read_text_file(reference_deck());
  const std::size_t at = text.find("geodetic_latitude_deg = 32.35");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 29, "geodetic_latitude_deg = 90.5");
  const std::string deck = (scratch / "latitude.toml").string();
  std::ofstream(deck) << text;
  for (const char* command : {"radar", "simulate"}) {
    expect_rejected(deck, command, "geodetic_latitude_deg");
    expect_rejected(deck, command, "data block 41");
  }
}

TEST(Sec18RadarCommand, StationCountOutsideOneToTwentyIsRejected) {
  ScratchDirectory scratch("radar_count");
  std::string text = read_text_file(reference_deck());
  const std::size_t from = text.find("[[radar_station]]");
  const std::size_t end = text.find("\n\n", text.find("altitude_ft", from));
  const std::string card = text.substr(from, end - from + 2);
  std::string many = text;
  for (int i = 0; i < 15; ++i) many.insert(from, card);  // 21 stations
  const std::string deck = (scratch / "many.toml").string();
  std::ofstream(deck) << many;
  expect_rejected(deck, "radar", "too many radar stations (21)");
  // A card deck's header counts the station cards: 0 is no count.
  const std::string cards = (scratch / "cards.dat").string();
  const CommandResult converted = run_tolip_executable({"convert", reference_deck(), "--to", cards});
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  std::string card_text = read_text_file(cards);
  const std::size_t header = card_text.find("\n 41  1  5  6");
  ASSERT_NE(header, std::string::npos)
      << card_text.substr(card_text.size() > 2000 ? card_text.size() - 2000 : 0);
  card_text.replace(header, 13, "\n 41  1  5  0");
  std::ofstream(cards) << card_text;
  expect_rejected(cards, "radar", "data block 41");
}

TEST(Sec18RadarPlot, OneFigurePerStationWithTheBelowHorizonPartDashed) {
  const CommandResult radar = run_tolip_executable({"radar", reference_deck(), "--json"});
  ASSERT_EQ(radar.exit_code, 0) << radar.err;
  const json document = json::parse(radar.out);
  const ground::DocumentFigures figures = ground::figures_for_document(document);
  int radar_figures = 0;
  for (const ground::Figure& figure : figures.figures) {
    if (figure.name.rfind("radar_", 0) != 0) continue;
    ++radar_figures;
    ASSERT_FALSE(figure.y_lines.empty());
    EXPECT_EQ(figure.y_lines[0].y, 0.0) << "the horizon";
    bool below = false;
    for (const ground::PlotSeries& series : figure.series) {
      if (contains(series.title, "below the horizon")) {
        below = true;
        EXPECT_TRUE(series.second_axis);
        EXPECT_NE(series.dash_type, 0);
        for (double y : series.y) EXPECT_FALSE(y > 0.0) << figure.name;
      }
    }
    if (figure.name == "radar_ascension") {
      EXPECT_TRUE(below) << "Ascension never sees the ascent";
    }
  }
  EXPECT_EQ(radar_figures, 6);
  const ground::DocumentFigures without = ground::figures_for_document(json{{"trajectory", json::array()}});
  EXPECT_TRUE(without.figures.empty());
}

}  // namespace
}  // namespace tolip::test
