// Manual Sec. 4 oblate Earth: surface radius, geodetic latitude, delta-lambda and J2 gravity,
// against the oracle, the exact ellipsoid and the geopotential.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "support/reference_data.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"

namespace tolip {
namespace {

TEST(Sec4OblateEarth, RadiusAndGeodeticLatitudeMatchOracle) {
  const Constants constants;
  double max_rel_radius = 0.0;
  double max_abs_lat_deg = 0.0;
  for (const auto& v : test::oracle_test_vectors().at("oblate_radius")) {
    const double lat_gc = v.at("geocentric_lat_deg").get<double>() * kDegToRad;
    const double radius_truth = v.at("r_oblate_ft").get<double>();
    const double geodetic_truth_deg = v.at("geodetic_lat_deg").get<double>();
    const double radius = oblate_radius_ft(constants, lat_gc);
    const double geodetic_deg = geodetic_from_geocentric_rad(constants, lat_gc) * kRadToDeg;
    const double rel = std::fabs(radius - radius_truth) / radius_truth;
    const double dlat = std::fabs(geodetic_deg - geodetic_truth_deg);
    EXPECT_LT(rel, 1e-13) << "lat_gc " << v.at("geocentric_lat_deg");
    EXPECT_LT(dlat, 1e-11) << "lat_gc " << v.at("geocentric_lat_deg");
    max_rel_radius = std::max(max_rel_radius, rel);
    max_abs_lat_deg = std::max(max_abs_lat_deg, dlat);
  }
  std::printf("[ figures  ] Sec4 oblate radius max rel err %.2e, geodetic latitude max err %.2e deg\n",
              max_rel_radius, max_abs_lat_deg);
}

// Independent of the manual's reduced-latitude construction: the polar form of an ellipse with
// semi-axes a and b = a (1 - 1/f) at geocentric latitude phi is a b / sqrt((b cos)^2 + (a sin)^2).
TEST(Sec4OblateEarth, RadiusIsThePolarFormOfTheEllipse) {
  const Constants constants;
  const double a = constants.earth_equatorial_radius_ft;
  const double b = a * (1.0 - 1.0 / constants.inverse_flattening);
  for (double deg = -90.0; deg <= 90.0; deg += 7.5) {
    const double phi = deg * kDegToRad;
    const double polar = a * b / std::hypot(b * std::cos(phi), a * std::sin(phi));
    EXPECT_NEAR(oblate_radius_ft(constants, phi), polar, 1e-7) << deg;
  }
  EXPECT_NEAR(oblate_radius_ft(constants, 0.5 * kPi), b, 1e-7);
  EXPECT_NEAR(oblate_altitude_ft(constants, a + 1000.0, 0.0), 1000.0, 1e-8);
}

// The model evaluation's radius from the case's OblateFigure is the atan form of Sec. 4 (the
// figure's products are the polar form's), the sphere's is R_eq exactly, and a figure no case
// prepared gives NaN rather than a plausible radius (the flight then stops, never flies on it).
TEST(Sec4OblateEarth, TheCaseFigureGivesTheSec4RadiusAndAnUnpreparedOneGivesNaN) {
  const Constants constants;
  const OblateFigure figure = oblate_figure(constants);
  for (double deg = -90.0; deg <= 90.0; deg += 7.5) {
    const double phi = deg * kDegToRad;
    EXPECT_NEAR(oblate_radius_ft(figure, std::sin(phi), std::cos(phi)), oblate_radius_ft(constants, phi),
                1e-7)
        << deg;
  }
  Constants sphere;
  sphere.inverse_flattening = 0.0;
  EXPECT_EQ(oblate_radius_ft(oblate_figure(sphere), 0.6, 0.8), sphere.earth_equatorial_radius_ft);
  EXPECT_TRUE(std::isnan(oblate_radius_ft(OblateFigure{}, 0.6, 0.8)));
}

// Purcell-Cowan is a series for the surface ellipsoid: tan(phi_d) = (f / (f - 1))^2 tan(phi_c).
// The series' first coefficient (3.372672e-3) is not the ellipsoid's (k-1)/(k+1) = 3.3573e-3, so
// they differ by up to 0.0013 deg (4.7 arcsec) near 60 deg, 0.0005 deg at Wallops (the reference
// README's figure); the bound catches a wrong sign, coefficient or argument in the series.
TEST(Sec4OblateEarth, PurcellCowanSeriesIsCloseToTheExactEllipsoid) {
  const double f = Constants{}.inverse_flattening;
  const double k = std::pow(f / (f - 1.0), 2);
  for (double deg = -85.0; deg <= 85.0; deg += 5.0) {
    const double phi_c = deg * kDegToRad;
    const double exact_deg = std::atan(k * std::tan(phi_c)) * kRadToDeg;
    EXPECT_NEAR(geodetic_from_geocentric_rad(Constants{}, phi_c) * kRadToDeg, exact_deg, 1.5e-3) << deg;
  }
}

TEST(Sec4OblateEarth, GeocentricFromGeodeticInvertsTheSeries) {
  const Constants k;
  double max_err = 0.0;
  for (double deg = -90.0; deg <= 90.0; deg += 0.5) {
    const double geodetic = deg * kDegToRad;
    const double geocentric = geocentric_from_geodetic_rad(k, geodetic);
    const double back = geodetic_from_geocentric_rad(k, geocentric);
    max_err = std::max(max_err, std::fabs(back - geodetic));
    EXPECT_NEAR(back, geodetic, 1e-15) << deg;
    // And the other way round.
    EXPECT_NEAR(geocentric_from_geodetic_rad(k, geodetic_from_geocentric_rad(k, geodetic)), geodetic, 1e-15)
        << deg;
  }
  std::printf("[ figures  ] Sec4 geodetic<->geocentric round trip max err %.2e rad\n", max_err);
}

TEST(Sec4OblateEarth, WallopsLaunchPointMatchesOracle) {
  const Constants constants;
  const auto& launch = test::oracle_test_vectors().at("launch");
  const auto& mission = test::scout_reference().at("mission");
  const auto& block21 = mission.at("initial_conditions_block21");
  const double geodetic = mission.at("launch").at("geodetic_latitude_deg").get<double>() * kDegToRad;
  const double pad_altitude_ft = block21.at("altitude_ft").get<double>();

  // The deck (block 21) carries the geocentric latitude rounded to 1e-9 deg; the oracle starts
  // from that value, and the inverse series must reproduce it within the rounding.
  const double lat_gc_deck = block21.at("geocentric_latitude_deg").get<double>() * kDegToRad;
  EXPECT_NEAR(lat_gc_deck, launch.at("lat_gc_rad").get<double>(), 1e-15);
  const double lat_gc = geocentric_from_geodetic_rad(constants, geodetic);
  EXPECT_NEAR(lat_gc * kRadToDeg, block21.at("geocentric_latitude_deg").get<double>(), 6e-10);

  const double r0 = oblate_radius_ft(constants, lat_gc_deck) + pad_altitude_ft;
  const double r0_truth = launch.at("r0_ft").get<double>();
  EXPECT_NEAR(r0, r0_truth, 1e-12 * r0_truth);

  const double dl = delta_lambda_rad(constants, lat_gc_deck, r0);
  const double dl_truth = launch.at("delta_lambda_rad").get<double>();
  EXPECT_LT(std::fabs(dl - dl_truth) / dl_truth, 1e-13);
  std::printf(
      "[ figures  ] Sec4 launch: lat_gc (inverse series) err %.2e deg, r0 rel err %.2e, "
      "delta-lambda rel err %.2e\n",
      std::fabs(lat_gc * kRadToDeg - block21.at("geocentric_latitude_deg").get<double>()),
      std::fabs(r0 - r0_truth) / r0_truth, std::fabs(dl - dl_truth) / dl_truth);
}

TEST(Sec4OblateEarth, DeltaLambdaMatchesOracleExample) {
  const auto& ex = test::oracle_test_vectors().at("delta_lambda_example");
  const double dl =
      delta_lambda_rad(Constants{}, ex.at("lat_gc_rad").get<double>(), ex.at("r_ft").get<double>());
  const double truth = ex.at("delta_lambda_rad").get<double>();
  EXPECT_LT(std::fabs(dl - truth) / truth, 1e-13);
  // It vanishes at the equator and the poles and is odd in latitude.
  EXPECT_EQ(delta_lambda_rad(Constants{}, 0.0, 2.09e7), 0.0);
  EXPECT_NEAR(delta_lambda_rad(Constants{}, -0.6, 2.09e7), -dl, 1e-8);
}

// ---- The Earth taken from the deck (issue 17): CT1(12) = 0 is a sphere; the 1966 numbers only
// for the manual's constants, the exact relations of the deck's constants otherwise. -----------

Constants spherical_non_rotating_earth() {
  Constants c;
  c.inverse_flattening = 0.0;
  c.j2 = 0.0;
  c.earth_rotation_rate_rad_s = 0.0;
  return c;
}

// CT1(12) = 0: the figure is a sphere of radius CT1(3) (the eta form would divide by zero).
TEST(Sec4Earth, SphericalEarthHasTheEquatorialRadiusAtEveryLatitude) {
  Constants sphere;
  sphere.inverse_flattening = 0.0;
  ASSERT_TRUE(is_spherical_earth(sphere));
  ASSERT_FALSE(is_spherical_earth(Constants{}));
  const double a = sphere.earth_equatorial_radius_ft;
  for (double deg = -90.0; deg <= 90.0; deg += 2.5) {
    const double lat = deg * kDegToRad;
    EXPECT_EQ(oblate_radius_ft(sphere, lat), a) << deg;
    EXPECT_EQ(oblate_radius_ft(sphere, std::sin(lat), std::cos(lat)), a) << deg;
    EXPECT_EQ(oblate_altitude_ft(sphere, a + 1234.5, lat), 1234.5) << deg;
    EXPECT_EQ(oblate_radius_latitude_derivative_ft_per_rad(sphere, lat), 0.0) << deg;
  }
  EXPECT_EQ(polar_radius_ft(sphere), a);
  EXPECT_EQ(polar_radius_ft(Constants{}), a * (298.3 - 1.0) / 298.3);
}

// Purcell-Cowan as printed in Sec. 4, written out here independently of the core.
double printed_purcell_cowan_rad(double lat_c) {
  return lat_c + 3.372672e-3 * std::sin(2.0 * lat_c) + -5.6873e-6 * std::sin(4.0 * lat_c);
}

TEST(Sec4Earth, SphericalNonRotatingEarthHasNoTiltAndGeodeticEqualsGeocentric) {
  const Constants sphere = spherical_non_rotating_earth();
  ASSERT_TRUE(is_spherical_earth(sphere));
  const double a = sphere.earth_equatorial_radius_ft;
  for (double deg = -90.0; deg <= 90.0; deg += 2.5) {
    const double lat = deg * kDegToRad;
    EXPECT_EQ(delta_lambda_rad(sphere, lat, a + 10.0), 0.0) << deg;
    EXPECT_EQ(geodetic_from_geocentric_rad(sphere, lat), lat) << deg;
    EXPECT_EQ(geocentric_from_geodetic_rad(sphere, lat), lat) << deg;
  }
  // [B'] is then only the azimuth rotation: the platform vertical is the geocentric one.
  const double azimuth = 100.0 * kDegToRad;
  EXPECT_TRUE(platform_to_geocentric(azimuth, delta_lambda_rad(sphere, 37.65 * kDegToRad, a)) ==
              platform_to_geocentric(azimuth, 0.0));
}

// On the sphere the figure is gone but a deck's J2 and rotation still deflect the plumb line
// (the manual's delta-lambda is a property of the gravity field): each term alone tilts it.
TEST(Sec4Earth, SphericalFigureKeepsTheTiltOfTheDecksJ2AndRotation) {
  Constants rotating = spherical_non_rotating_earth();
  rotating.earth_rotation_rate_rad_s = 7.29211e-5;
  Constants j2_only = spherical_non_rotating_earth();
  j2_only.j2 = 1.0e-3;
  const double lat = 0.6, r = 2.09e7;
  const double g = rotating.gravitational_parameter_ft3_s2 / (r * r);
  const double w = rotating.earth_rotation_rate_rad_s;
  EXPECT_DOUBLE_EQ(delta_lambda_rad(rotating, lat, r), w * w * r / (2.0 * g) * std::sin(2.0 * lat));
  EXPECT_DOUBLE_EQ(delta_lambda_rad(j2_only, lat, r), 1.5e-3 * std::sin(2.0 * lat));
}

// For the manual's constants the 1966 numbers are kept bit for bit (the oracle tests above and
// the bundled example's payload depend on them).
TEST(Sec4Earth, ManualConstantsKeepThePrintedSeriesAndSixSigmaBitForBit) {
  const Constants manual;
  ASSERT_TRUE(uses_purcell_cowan_series(manual));
  EXPECT_EQ(figure_deflection_coefficient(manual), 0.001638);
  for (double deg = -90.0; deg <= 90.0; deg += 3.7) {
    const double lat = deg * kDegToRad;
    EXPECT_EQ(geodetic_from_geocentric_rad(manual, lat), printed_purcell_cowan_rad(lat)) << deg;
    const double r = 2.0925e7, g = manual.gravitational_parameter_ft3_s2 / (r * r);
    const double w = manual.earth_rotation_rate_rad_s;
    EXPECT_EQ(delta_lambda_rad(manual, lat, r), (0.001638 + w * w * r / (2.0 * g)) * std::sin(2.0 * lat))
        << deg;
  }
}

// The exact ellipsoid relation the core uses for other flattenings agrees with the series for
// the manual's Earth to the series' own accuracy (0.0013 deg, see PurcellCowanSeries... above),
// and its inverse is exact.
TEST(Sec4Earth, ExactEllipsoidLatitudeAgreesWithPurcellCowanToTheSeriesAccuracyForTheManualsEarth) {
  const Constants manual;
  double max_deg = 0.0, max_round_trip = 0.0;
  for (double deg = -90.0; deg <= 90.0; deg += 0.5) {
    const double lat = deg * kDegToRad;
    const double exact = ellipsoid_geodetic_from_geocentric_rad(manual, lat);
    max_deg = std::max(max_deg, std::fabs(exact - printed_purcell_cowan_rad(lat)) * kRadToDeg);
    max_round_trip =
        std::max(max_round_trip, std::fabs(ellipsoid_geocentric_from_geodetic_rad(manual, exact) - lat));
  }
  EXPECT_LT(max_deg, 1.5e-3);
  EXPECT_GT(max_deg, 1.0e-4);  // they are different relations (C1 is not the ellipsoid's)
  EXPECT_LT(max_round_trip, 1e-15);
  std::printf(
      "[ figures  ] Sec4 exact ellipsoid vs Purcell-Cowan (f = 298.3) max %.2e deg; "
      "exact inverse round trip %.2e rad\n",
      max_deg, max_round_trip);
}

TEST(Sec4Earth, GeodeticLatitudeFollowsTheDecksFlattening) {
  Constants flatter;
  flatter.inverse_flattening = 150.0;
  ASSERT_FALSE(uses_purcell_cowan_series(flatter));
  const double k = std::pow(150.0 / 149.0, 2);
  double max_round_trip = 0.0;
  for (double deg = -85.0; deg <= 85.0; deg += 5.0) {
    const double lat = deg * kDegToRad;
    const double geodetic = geodetic_from_geocentric_rad(flatter, lat);
    EXPECT_NEAR(std::tan(geodetic), k * std::tan(lat), 1e-14 * (1.0 + std::fabs(k * std::tan(lat)))) << deg;
    max_round_trip =
        std::max(max_round_trip, std::fabs(geocentric_from_geodetic_rad(flatter, geodetic) - lat));
  }
  EXPECT_LT(max_round_trip, 1e-15);
  // Twice the manual's flattening: about twice its geodetic-geocentric difference at 45 deg.
  const double lat = 45.0 * kDegToRad;
  EXPECT_NEAR((geodetic_from_geocentric_rad(flatter, lat) - lat) /
                  (geodetic_from_geocentric_rad(Constants{}, lat) - lat),
              2.0, 0.03);
  EXPECT_DOUBLE_EQ(geodetic_from_geocentric_rad(flatter, 0.5 * kPi), 0.5 * kPi);
}

// The tilt derived from the deck's J2 and rotation is the angle between the plumb line (J2 gravity
// plus centrifugal acceleration) and the geocentric radial, to the manual's approximations
// (r = r_e in the figure term, the J2 and centrifugal parts of g_r neglected: relative O(m)).
TEST(Sec4Earth, DerivedTiltIsTheAngleOfThePlumbLineForTheDecksJ2AndRotation) {
  Constants deck;
  deck.j2 = 2.0e-3;
  deck.earth_rotation_rate_rad_s = 1.0e-4;
  ASSERT_EQ(figure_deflection_coefficient(deck), 1.5 * deck.j2);
  const double r = deck.earth_equatorial_radius_ft;
  for (double deg = -80.0; deg <= 80.0; deg += 10.0) {
    const double lat = deg * kDegToRad;
    const Gravity g = j2_gravity(deck, r, lat);
    const double w2r = deck.earth_rotation_rate_rad_s * deck.earth_rotation_rate_rad_s * r;
    // Inward radial and southward components of gravity minus the centrifugal acceleration.
    const double inward = g.radial_ft_s2 - w2r * std::cos(lat) * std::cos(lat);
    const double south = -g.north_ft_s2 + w2r * std::sin(lat) * std::cos(lat);
    const double plumb = std::atan2(south, inward);
    EXPECT_NEAR(delta_lambda_rad(deck, lat, r), plumb, 1.2e-2 * std::fabs(plumb) + 1e-15) << deg;
  }
  // The printed 6 sigma = 0.001638 is 3/2 J2 of J2 = 1.092e-3 (Melsen's era), not of CT1(11)'s
  // 1.0827e-3: the derived term differs from the printed one by 0.9 %, 1.4e-5 rad at most.
  Constants near_manual;
  near_manual.j2 = 1.092e-3;
  EXPECT_NEAR(figure_deflection_coefficient(near_manual), 0.001638, 1e-15);
  std::printf("[ figures  ] Sec4 printed 6 sigma 0.001638 vs 3/2 J2 (J2 = 1.0827e-3) %.6e: %.2e rad\n",
              1.5 * kManualJ2, 0.001638 - 1.5 * kManualJ2);
}

// Geopotential of the J2 Earth (the function the manual says the gravity model differentiates):
// U = mu / r [1 - J2/2 (re/r)^2 (3 sin^2(lat) - 1)]; acceleration = grad U.
double geopotential_ft2_s2(const Constants& c, double r, double lat) {
  const double s = std::sin(lat);
  const double q = c.earth_equatorial_radius_ft / r;
  return c.gravitational_parameter_ft3_s2 / r * (1.0 - 0.5 * c.j2 * q * q * (3.0 * s * s - 1.0));
}

TEST(Sec4J2Gravity, ComponentsAreTheGradientOfTheGeopotential) {
  const Constants constants;
  double max_rel = 0.0;
  for (double r : {2.09e7, 2.1e7, 2.3e7, 4.0e7}) {
    for (double deg = -85.0; deg <= 85.0; deg += 10.0) {
      const double lat = deg * kDegToRad;
      const Gravity g = j2_gravity(constants, r, lat);
      const double dr = 10.0;
      const double dlat = 1e-6;
      const double du_dr =
          (geopotential_ft2_s2(constants, r + dr, lat) - geopotential_ft2_s2(constants, r - dr, lat)) /
          (2 * dr);
      const double du_dlat =
          (geopotential_ft2_s2(constants, r, lat + dlat) - geopotential_ft2_s2(constants, r, lat - dlat)) /
          (2 * dlat);
      // Inward radial component is -dU/dr; northward component is (1/r) dU/dlat.
      const double radial_fd = -du_dr;
      const double north_fd = du_dlat / r;
      const double rel_r = std::fabs(g.radial_ft_s2 - radial_fd) / std::fabs(radial_fd);
      EXPECT_LT(rel_r, 1e-9) << r << " " << deg;
      // The north component is J2-small; compare to the size of g.
      EXPECT_NEAR(g.north_ft_s2, north_fd, 1e-8 * g.spherical_ft_s2) << r << " " << deg;
      EXPECT_DOUBLE_EQ(g.spherical_ft_s2, constants.gravitational_parameter_ft3_s2 / (r * r));
      max_rel = std::max(max_rel, rel_r);
    }
  }
  std::printf("[ figures  ] Sec4 J2 radial vs -dU/dr max rel err %.2e\n", max_rel);
}

// The sign of the J2/2 term: at the equator oblateness adds to the inward pull, at the poles it
// reduces it (the printed minus in equation F would invert both).
TEST(Sec4J2Gravity, OblatenessStrengthensEquatorialAndWeakensPolarGravity) {
  const Constants constants;
  const double r = constants.earth_equatorial_radius_ft;
  const Gravity equator = j2_gravity(constants, r, 0.0);
  const Gravity pole = j2_gravity(constants, r, 0.5 * kPi);
  EXPECT_NEAR(equator.radial_ft_s2 / equator.spherical_ft_s2, 1.0 + 1.5 * constants.j2, 1e-15);
  EXPECT_NEAR(pole.radial_ft_s2 / pole.spherical_ft_s2, 1.0 - 3.0 * constants.j2, 1e-15);
  // Northern hemisphere: the bulge pulls toward the equator (southward).
  EXPECT_LT(j2_gravity(constants, r, 0.6).north_ft_s2, 0.0);
  EXPECT_GT(j2_gravity(constants, r, -0.6).north_ft_s2, 0.0);
}

}  // namespace
}  // namespace tolip
