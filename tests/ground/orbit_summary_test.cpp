// The result in an engineer's terms (issue 10 part 5): perigee and apogee altitude above the oblate
// Earth, the path class, and the deck's constraints achieved against desired in `simulate`.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "cli_runner.hpp"
#include "tolip/core/constants.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::test {
namespace {

// The oblate Earth (an ellipse of equatorial radius a and flattening f) at geocentric latitude,
// written here from its definition: r = a (1 - f) / sqrt(1 - (2 f - f^2) cos^2(latitude)).
double ellipse_radius_ft(double latitude_rad) {
  const Constants k;
  const double f = 1.0 / k.inverse_flattening;
  const double c = std::cos(latitude_rad);
  return k.earth_equatorial_radius_ft * (1.0 - f) / std::sqrt(1.0 - (2.0 * f - f * f) * c * c);
}

// Perigee and apogee altitude from the document's own orbit elements: the perigee's latitude is
// asin(sin EYE sin BETAP), the apogee's its negative.
void expect_altitudes_from_the_elements(const nlohmann::json& orbit) {
  const double i = orbit["inclination_deg"].get<double>() * kDegToRad;
  const double w = orbit["argument_of_perigee_deg"].get<double>() * kDegToRad;
  const double latitude = std::asin(std::sin(i) * std::sin(w));
  EXPECT_NEAR(orbit["perigee_geocentric_latitude_deg"].get<double>(), latitude * kRadToDeg, 1e-9);
  const double perigee_ft = orbit["perigee_radius_ft"].get<double>() - ellipse_radius_ft(latitude);
  const double apogee_ft = orbit["apogee_radius_ft"].get<double>() - ellipse_radius_ft(-latitude);
  EXPECT_NEAR(orbit["perigee_altitude_ft"].get<double>(), perigee_ft, 0.5);
  EXPECT_NEAR(orbit["apogee_altitude_ft"].get<double>(), apogee_ft, 0.5);
  // The international nautical mile: 1852 m.
  EXPECT_NEAR(orbit["perigee_altitude_nmi"].get<double>(), perigee_ft * 0.3048 / 1852.0, 1e-6);
  EXPECT_NEAR(orbit["apogee_altitude_nmi"].get<double>(), apogee_ft * 0.3048 / 1852.0, 1e-6);
}

TEST(OrbitSummary, TheOptimumIsAnOrbitNearThe300NmiTarget) {
  const CommandResult run = run_tolip_executable({"optimize", scout_example("mission.toml"), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json orbit = nlohmann::json::parse(run.out)["orbit"];
  EXPECT_EQ(orbit["path"], "orbit");
  EXPECT_EQ(orbit["perigee_below_haero"], false);
  expect_altitudes_from_the_elements(orbit);
  // 300 n.mi. at burnout (31 deg N) over the oblate Earth: the near-circular orbit is a few n.mi.
  // lower over the bulge at the equator, where its perigee lies.
  EXPECT_NEAR(orbit["perigee_altitude_nmi"].get<double>(), 300.0, 5.0);
  EXPECT_NEAR(orbit["apogee_altitude_nmi"].get<double>(), 300.0, 5.0);

  const CommandResult listing = run_tolip_executable({"optimize", scout_example("mission.toml")});
  EXPECT_TRUE(
      std::regex_search(listing.out, std::regex("\\n ORBIT SUMMARY\\n   PATH +=  +ORBIT\\n   PERIGEE "
                                                "ALTITUDE += +29[0-9]\\.[0-9]{3} N\\.MI\\. AT GEOC LAT")))
      << listing.out.substr(listing.out.find("ORBIT SUMMARY"), 300);
}

// The crude initial program: its perigee lies 104 n.mi. below the surface.
TEST(OrbitSummary, TheCrudeProgramIsSuborbitalAndSimulateSaysWhichConstraintsItMisses) {
  const CommandResult run = run_tolip_executable({"simulate", scout_example("mission.toml"), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out);
  EXPECT_EQ(d["orbit"]["path"], "suborbital");
  EXPECT_LT(d["orbit"]["perigee_altitude_nmi"].get<double>(), 0.0);
  expect_altitudes_from_the_elements(d["orbit"]);
  // Achieved against desired, as the optimizer evaluates them: the altitude is the burnout's.
  ASSERT_EQ(d["constraints"].size(), 3u);
  const nlohmann::json& altitude = d["constraints"][0];
  EXPECT_EQ(altitude["code"], 7);
  EXPECT_EQ(altitude["desired"].get<double>(), 1822834.647);
  EXPECT_DOUBLE_EQ(altitude["achieved"].get<double>(), d["burnout"]["altitude_ft"].get<double>());
  EXPECT_EQ(altitude["tolerance"].get<double>(), 20000.0);
  for (const nlohmann::json& c : d["constraints"]) EXPECT_EQ(c["met"], false) << c["code"];

  const CommandResult listing = run_tolip_executable({"simulate", scout_example("mission.toml")});
  EXPECT_TRUE(std::regex_search(listing.out, std::regex("PATH += SUBORBITAL: PERIGEE BELOW THE SURFACE")));
  EXPECT_TRUE(
      std::regex_search(listing.out, std::regex(" CONSTRAINTS OF DATA BLOCK 8 ON THIS TRAJECTORY.*\\n.*\\n "
                                                "+1 +7  ALTITUDE +1822834\\.647 +2646108\\.516 .* NO\\n")));
}

// The reference optimum meets its own constraints in `simulate` too.
TEST(OrbitSummary, SimulateOfTheReferenceOptimumMeetsItsConstraints) {
  const CommandResult run =
      run_tolip_executable({"simulate", scout_example("reference_optimum.toml"), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out);
  EXPECT_EQ(d["orbit"]["path"], "orbit");
  for (const nlohmann::json& c : d["constraints"]) EXPECT_EQ(c["met"], true) << c["code"];
}

TEST(OrbitSummary, PathClassesOfEscapeAndOrbit) {
  const Constants k;
  OrbitElements escape;
  escape.has_semi_major_axis = false;
  escape.perigee_radius_ft = k.earth_equatorial_radius_ft + 1e6;
  EXPECT_EQ(ground::summarize_orbit(k, escape).path, ground::PathClass::kEscape);
  EXPECT_TRUE(std::isnan(ground::summarize_orbit(k, escape).apogee_altitude_ft));
  OrbitElements low = escape;
  low.has_semi_major_axis = true;
  low.apogee_radius_ft = low.perigee_radius_ft;
  low.perigee_radius_ft = k.earth_equatorial_radius_ft + 1e5;  // 100,000 ft: below HAERO (250,000 ft)
  EXPECT_EQ(ground::summarize_orbit(k, low).path, ground::PathClass::kOrbit);
  EXPECT_TRUE(ground::summarize_orbit(k, low).perigee_in_atmosphere);
}

}  // namespace
}  // namespace tolip::test
