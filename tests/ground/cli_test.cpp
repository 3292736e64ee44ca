// The `tolip` program end to end (run as a child process): help, exit codes, `atmosphere`, and
// the deck errors of `simulate`. None of these needs a working trajectory.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace tolip::test {
namespace {

TEST(TolipCli, HelpListsTheSubcommandsAndExitCodes) {
  const CommandResult result = run_tolip_executable({"--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_TRUE(contains(result.out, "atmosphere")) << result.out;
  EXPECT_TRUE(contains(result.out, "simulate")) << result.out;
  EXPECT_TRUE(contains(result.out, "Exit codes")) << result.out;
  EXPECT_TRUE(result.err.empty()) << result.err;
}

TEST(TolipCli, SubcommandHelpListsItsOptions) {
  const CommandResult simulate = run_tolip_executable({"simulate", "--help"});
  EXPECT_EQ(simulate.exit_code, 0);
  EXPECT_TRUE(contains(simulate.out, "--csv")) << simulate.out;
  EXPECT_TRUE(contains(simulate.out, "--json")) << simulate.out;
  EXPECT_TRUE(contains(simulate.out, "DECK")) << simulate.out;

  const CommandResult atmosphere = run_tolip_executable({"atmosphere", "--help"});
  EXPECT_EQ(atmosphere.exit_code, 0);
  EXPECT_TRUE(contains(atmosphere.out, "--altitude-ft")) << atmosphere.out;
  EXPECT_TRUE(contains(atmosphere.out, "--json")) << atmosphere.out;
}

TEST(TolipCli, VersionPrintsTheVersion) {
  const CommandResult result = run_tolip_executable({"--version"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_TRUE(contains(result.out, "tolip ")) << result.out;
}

TEST(TolipCli, NoSubcommandIsBadInput) {
  const CommandResult result = run_tolip_executable({});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err.rfind("tolip: ", 0), 0u) << result.err;
}

TEST(TolipCli, UnknownOptionIsBadInput) {
  const CommandResult result = run_tolip_executable({"atmosphere", "--altitude-ft", "0", "--bogus"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err.rfind("tolip: ", 0), 0u) << result.err;
  EXPECT_TRUE(result.out.empty());
}

TEST(TolipCli, AtmosphereMissingAltitudeIsBadInput) {
  const CommandResult result = run_tolip_executable({"atmosphere"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(contains(result.err, "--altitude-ft")) << result.err;
}

TEST(TolipCli, AtmosphereJsonAtSeaLevel) {
  const CommandResult result = run_tolip_executable({"atmosphere", "--altitude-ft", "0", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(result.out);
  for (const char* key : {"altitude_ft", "geopotential_altitude_ft", "density_slug_ft3", "pressure_lbf_ft2",
                          "speed_of_sound_ft_s", "temperature_R"}) {
    ASSERT_TRUE(document.contains(key)) << key;
    ASSERT_TRUE(document[key].is_number()) << key;
  }
  EXPECT_EQ(document["altitude_ft"].get<double>(), 0.0);
  EXPECT_EQ(document["geopotential_altitude_ft"].get<double>(), 0.0);
  EXPECT_NEAR(document["density_slug_ft3"].get<double>(), 0.0023769, 1e-10);
  EXPECT_NEAR(document["pressure_lbf_ft2"].get<double>(), 2116.2, 0.1);
  EXPECT_NEAR(document["temperature_R"].get<double>(), 518.69, 1e-9);
  // a = sqrt(1.4 R* T) with R* = 1716.4827 ft^2/s^2/R.
  EXPECT_NEAR(document["speed_of_sound_ft_s"].get<double>(), std::sqrt(1.4 * 1716.4827 * 518.69), 1e-6);
}

TEST(TolipCli, AtmosphereGeopotentialAltitudeUsesTheEquatorialRadius) {
  const CommandResult result = run_tolip_executable({"atmosphere", "--altitude-ft", "100000", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(result.out);
  const double radius = 20925696.0;  // CT1(3)
  EXPECT_NEAR(document["geopotential_altitude_ft"].get<double>(), radius * 100000.0 / (radius + 100000.0),
              1e-6);
  EXPECT_EQ(document["earth_radius_ft"].get<double>(), radius);
}

TEST(TolipCli, AtmosphereAcceptsANegativeAltitude) {
  const CommandResult result = run_tolip_executable({"atmosphere", "--altitude-ft=-1000", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(result.out);
  EXPECT_GT(document["density_slug_ft3"].get<double>(), 0.0023769);
}

TEST(TolipCli, AtmosphereTextNamesEveryQuantity) {
  const CommandResult result = run_tolip_executable({"atmosphere", "--altitude-ft", "0"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* label : {"DENSITY", "PRESSURE", "SPEED OF SOUND", "TEMPERATURE", "GEOPOTENTIAL ALTITUDE",
                            "SLUG/FT3", "DEG R"}) {
    EXPECT_TRUE(contains(result.out, label)) << label << "\n" << result.out;
  }
}

TEST(TolipCli, AtmosphereRejectsNonFiniteAltitude) {
  for (const char* value : {"nan", "inf", "-inf", "1e999"}) {
    const CommandResult result =
        run_tolip_executable({"atmosphere", std::string("--altitude-ft=") + value, "--json"});
    EXPECT_EQ(result.exit_code, 2) << value << ": " << result.out;
    EXPECT_TRUE(result.out.empty()) << value << ": " << result.out;
    EXPECT_EQ(result.err.rfind("tolip: ", 0), 0u) << result.err;
    EXPECT_FALSE(contains(result.out, "nan"));
  }
}

TEST(TolipCli, AtmosphereRejectsAltitudeBelowTheEarthCentre) {
  const CommandResult result = run_tolip_executable({"atmosphere", "--altitude-ft=-3e7"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err.rfind("tolip: ", 0), 0u) << result.err;
}

TEST(TolipCli, SimulateMissingDeckIsBadInputNamingTheFile) {
  ScratchDirectory scratch("missing_deck");
  const std::string deck = (scratch / "no_such_deck.toml").string();
  const CommandResult result = run_tolip_executable({"simulate", deck});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err.rfind("tolip: ", 0), 0u) << result.err;
  EXPECT_TRUE(contains(result.err, deck)) << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
}

TEST(TolipCli, SimulateMissingDeckWritesNoCsvAndNoJson) {
  ScratchDirectory scratch("missing_deck_csv");
  const std::string deck = (scratch / "absent.toml").string();
  const std::string csv = (scratch / "out.csv").string();
  const CommandResult result = run_tolip_executable({"simulate", deck, "--csv", csv, "--json"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_TRUE(scratch.entries().empty());
}

TEST(TolipCli, SimulateWithoutDeckIsBadInput) {
  const CommandResult result = run_tolip_executable({"simulate"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(contains(result.err, "DECK")) << result.err;
}

}  // namespace
}  // namespace tolip::test
