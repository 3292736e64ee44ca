// Manual Sec. 4 (INER inertial variables, terminal orbit elements, range equations), Sec. 13
// (heating rate) and Addendum H (hyperbolic asymptote), against the oracle, analytic orbits and
// an independent Cartesian (Earth-centred inertial) computation written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "support/reference_data.hpp"
#include "tolip/orbit/orbit_elements.hpp"

namespace tolip {
namespace {

constexpr double kTwoPi = 2.0 * kPi;
// The oracle's nautical mile: 1852 m rounded to 6076.11549 ft (its altitude keys reproduce this).
constexpr double kFeetPerNauticalMile = 6076.11549;

using test::state_from_json;

// Smallest difference of two angles, radians.
double angle_diff(double a, double b) { return std::fabs(std::remainder(a - b, kTwoPi)); }

// ---- Independent Cartesian model -------------------------------------------------------------
// Frame: inertial x through Greenwich at lift-off, z north (reference README Sec. 1); tau is the
// inertial longitude, so the position needs no time.
struct Cartesian {
  Vector3 r_ft;
  Vector3 v_inertial_ft_s;
};

Cartesian to_cartesian(const Constants& c, const StateVector& x) {
  const double v = x(kStateV), gam = x(kStateGamma), r = x(kStateR), psi = x(kStatePsi),
               lat = x(kStateLambda), tau = x(kStateTau);
  const Vector3 up(std::cos(lat) * std::cos(tau), std::cos(lat) * std::sin(tau), std::sin(lat));
  const Vector3 east(-std::sin(tau), std::cos(tau), 0.0);
  const Vector3 north = up.cross(east);
  Cartesian out;
  out.r_ft = r * up;
  const Vector3 v_rel =
      v * (std::sin(gam) * up + std::cos(gam) * std::cos(psi) * north + std::cos(gam) * std::sin(psi) * east);
  const Vector3 omega(0.0, 0.0, c.earth_rotation_rate_rad_s);
  out.v_inertial_ft_s = v_rel + omega.cross(out.r_ft);
  return out;
}

// The state whose inertial velocity is (V_I, gamma_I, psi_I) at the given position: subtract the
// Earth's rotation from the eastward component.
StateVector state_from_inertial(const Constants& c, double r, double lat, double tau, double v_i,
                                double gamma_i, double psi_i) {
  const double up = v_i * std::sin(gamma_i);
  const double north = v_i * std::cos(gamma_i) * std::cos(psi_i);
  const double east =
      v_i * std::cos(gamma_i) * std::sin(psi_i) - c.earth_rotation_rate_rad_s * r * std::cos(lat);
  StateVector x;
  x << std::sqrt(up * up + north * north + east * east), std::atan2(up, std::hypot(north, east)), r,
      std::atan2(east, north), lat, tau;
  return x;
}

// Right ascension of the frame's x axis, written out from the Sec. 4 formula (Herget).
double greenwich_ra_at_launch_rad(double t_g) {
  return (99.659967 + 0.98564743 * t_g + 360.0 * (t_g - std::floor(t_g))) * kDegToRad;
}

struct TextbookElements {
  double twice_energy, h, a, e, i, raan, arg_perigee, true_anomaly, rp, ra_position;
  Vector3 e_vec, h_vec;
};

TextbookElements textbook(const Constants& c, const Cartesian& s, double t_g) {
  const double mu = c.gravitational_parameter_ft3_s2;
  const Vector3& r = s.r_ft;
  const Vector3& v = s.v_inertial_ft_s;
  TextbookElements t;
  t.h_vec = r.cross(v);
  t.h = t.h_vec.norm();
  t.twice_energy = v.squaredNorm() - 2.0 * mu / r.norm();
  t.a = -mu / t.twice_energy;
  t.e_vec = ((v.squaredNorm() - mu / r.norm()) * r - r.dot(v) * v) / mu;
  t.e = t.e_vec.norm();
  t.i = std::acos(t.h_vec.z() / t.h);
  const Vector3 node = Vector3::UnitZ().cross(t.h_vec);
  const double gmst = greenwich_ra_at_launch_rad(t_g);
  t.raan = std::atan2(node.y(), node.x()) + gmst;
  const Vector3 h_hat = t.h_vec / t.h;
  t.arg_perigee = std::atan2(node.cross(t.e_vec).dot(h_hat), node.dot(t.e_vec));
  t.true_anomaly = std::atan2(t.e_vec.cross(r).dot(h_hat), t.e_vec.dot(r));
  t.rp = t.h * t.h / mu / (1.0 + t.e);
  t.ra_position = std::atan2(r.y(), r.x()) + gmst;
  return t;
}

// ---- Oracle ----------------------------------------------------------------------------------

TEST(Sec4OrbitElements, MatchesOracleForAllThreeStates) {
  const Constants constants;
  const auto& cases = test::oracle_test_vectors().at("orbit_elements");
  ASSERT_EQ(cases.size(), 3u);
  double max_rel_magnitude = 0.0;
  double max_angle_err_deg = 0.0;
  for (std::size_t n = 0; n < cases.size(); ++n) {
    const auto& c = cases[n];
    const StateVector x = state_from_json(c.at("state"));
    OrbitElements e;
    ASSERT_EQ(compute_orbit_elements(constants, x, c.at("launch_space_age_date").get<double>(), &e),
              Status::kOk);
    const auto& want = c.at("elements");
    // The burnout orbit is circular to round-off: its true anomaly and argument of perigee are
    // the angle of a 1e-16 eccentricity vector, meaningless (reference README Sec. 4).
    const bool circular = n == 0;

    auto magnitude = [&](const char* key, double got, double abs_floor = 0.0) {
      const double truth = want.at(key).get<double>();
      const double err = std::fabs(got - truth);
      const double rel = err / std::max(std::fabs(truth), 1e-300);
      EXPECT_TRUE(err <= abs_floor || rel < 1e-10)
          << "case " << n << " " << key << ": " << got << " vs " << truth;
      if (abs_floor == 0.0) max_rel_magnitude = std::max(max_rel_magnitude, rel);
    };
    auto angle_deg = [&](const char* key, double got_rad) {
      const double truth_deg = want.at(key).get<double>();
      const double err_deg = angle_diff(got_rad, truth_deg * kDegToRad) * kRadToDeg;
      EXPECT_LT(err_deg, 1e-9) << "case " << n << " " << key << ": " << got_rad * kRadToDeg << " vs "
                               << truth_deg;
      max_angle_err_deg = std::max(max_angle_err_deg, err_deg);
    };

    magnitude("VI_fps", e.inertial.velocity_ft_s);
    angle_deg("gammaI_deg", e.inertial.flight_path_angle_rad);
    angle_deg("psiI_deg", e.inertial.azimuth_rad);
    magnitude("twoE_ft2_per_s2", e.twice_energy_ft2_s2);
    magnitude("angular_momentum_ft2_per_s", e.angular_momentum_ft2_s);
    magnitude("perigee_radius_ft", e.perigee_radius_ft);
    angle_deg("inclination_deg", e.inclination_rad);
    angle_deg("right_ascension_deg", e.right_ascension_rad);
    angle_deg("nu_deg", e.nu_rad);
    angle_deg("longitude_of_node_deg", e.node_longitude_rad);
    angle_deg("in_plane_angle_from_node_deg", e.in_plane_angle_from_node_rad);
    if (!circular) {
      angle_deg("true_anomaly_deg", e.true_anomaly_rad);
      angle_deg("argument_of_perigee_deg", e.argument_of_perigee_rad);
    }
    ASSERT_TRUE(e.has_semi_major_axis);
    EXPECT_EQ(e.type, OrbitType::kElliptic);
    magnitude("semi_major_axis_ft", e.semi_major_axis_ft);
    magnitude("period_min", e.period_s / 60.0);
    magnitude("eccentricity", e.eccentricity, 1e-12);
    magnitude("apogee_radius_ft", e.apogee_radius_ft);
    magnitude("perigee_altitude_nmi_spherical",
              (e.perigee_radius_ft - constants.earth_equatorial_radius_ft) / kFeetPerNauticalMile);
    magnitude("apogee_altitude_nmi_spherical",
              (e.apogee_radius_ft - constants.earth_equatorial_radius_ft) / kFeetPerNauticalMile, 1e-6);
    EXPECT_FALSE(e.has_asymptote);

    const auto& inertial = c.at("inertial");
    EXPECT_LT(
        std::fabs(e.inertial.velocity_ft_s - inertial.at("VI_fps").get<double>()) / e.inertial.velocity_ft_s,
        1e-13);
    EXPECT_NEAR(e.inertial.flight_path_angle_rad, inertial.at("gammaI_rad").get<double>(), 1e-12);
    EXPECT_NEAR(e.inertial.azimuth_rad, inertial.at("psiI_rad").get<double>(), 1e-12);
  }
  std::printf(
      "[ figures  ] Sec4 orbit elements vs oracle: max rel err (magnitudes) %.2e, max angle err %.2e deg\n",
      max_rel_magnitude, max_angle_err_deg);
}

// ---- INER ------------------------------------------------------------------------------------

TEST(Sec4InertialVariables, MatchThePrintedInerFormulas) {
  const Constants c;
  const double w = c.earth_rotation_rate_rad_s;
  StateVector x;
  x << 7000.0, 0.4, 2.1e7, 1.2, 0.5, -1.0;
  const InertialVelocity iv = inertial_velocity(c, x);
  const double v = x(0), gam = x(1), r = x(2), psi = x(3), lat = x(4);
  const double wr = w * r * std::cos(lat);  // "ur cos lambda" of the scan
  const double vi = std::sqrt(v * v + 2.0 * (v * std::cos(gam) * std::sin(psi)) * wr + wr * wr);
  const double gi = std::atan(v * std::sin(gam) / std::sqrt(vi * vi - std::pow(v * std::sin(gam), 2)));
  const double pi_ =
      std::atan((v * std::cos(gam) * std::sin(psi) + wr) / (v * std::cos(gam) * std::cos(psi)));
  EXPECT_NEAR(iv.velocity_ft_s, vi, 1e-10);
  EXPECT_NEAR(iv.flight_path_angle_rad, gi, 1e-13);
  EXPECT_NEAR(iv.azimuth_rad, pi_, 1e-13);  // first quadrant here, where the printed atan is valid
}

TEST(Sec4InertialVariables, AzimuthIsQuadrantCorrectForSouthwardFlight) {
  const Constants c;
  StateVector x;
  x << 5000.0, 0.1, 2.1e7, 200.0 * kDegToRad, 0.3, 0.0;  // south-southwest
  const Cartesian s = to_cartesian(c, x);
  const Vector3 up = s.r_ft.normalized();
  const Vector3 east = Vector3::UnitZ().cross(up).normalized();
  const Vector3 north = up.cross(east);
  const double psi_truth = std::atan2(s.v_inertial_ft_s.dot(east), s.v_inertial_ft_s.dot(north)) + kTwoPi;
  EXPECT_NEAR(inertial_velocity(c, x).azimuth_rad, psi_truth, 1e-12);
}

TEST(Sec4InertialVariables, MatchOracleEarthCentredInertialExample) {
  const Constants c;
  const auto& ex = test::oracle_test_vectors().at("eci_example");
  const StateVector x = state_from_json(ex.at("state"));
  const Cartesian s = to_cartesian(c, x);
  double max_rel = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double r_truth =
        ex.at("r_eci_ft_launch_greenwich_frame").at(static_cast<std::size_t>(k)).get<double>();
    const double v_truth = ex.at("v_inertial_fps").at(static_cast<std::size_t>(k)).get<double>();
    EXPECT_NEAR(s.r_ft(k), r_truth, 1e-12 * s.r_ft.norm());
    EXPECT_NEAR(s.v_inertial_ft_s(k), v_truth, 1e-12 * s.v_inertial_ft_s.norm());
    max_rel = std::max({max_rel, std::fabs(s.r_ft(k) - r_truth) / s.r_ft.norm(),
                        std::fabs(s.v_inertial_ft_s(k) - v_truth) / s.v_inertial_ft_s.norm()});
  }
  const InertialVelocity iv = inertial_velocity(c, x);
  EXPECT_NEAR(iv.velocity_ft_s, s.v_inertial_ft_s.norm(), 1e-9);
  EXPECT_NEAR(iv.flight_path_angle_rad,
              std::asin(s.r_ft.dot(s.v_inertial_ft_s) / (s.r_ft.norm() * s.v_inertial_ft_s.norm())), 1e-12);
  std::printf("[ figures  ] Sec4 ECI position/velocity vs oracle max rel err %.2e\n", max_rel);
}

// ---- Elements against the Cartesian textbook formulas -------------------------------------------

void expect_matches_textbook(const Constants& c, const StateVector& x, double t_g, bool check_perigee_angles,
                             const std::string& label) {
  OrbitElements e;
  ASSERT_EQ(compute_orbit_elements(c, x, t_g, &e), Status::kOk) << label;
  const TextbookElements t = textbook(c, to_cartesian(c, x), t_g);
  EXPECT_NEAR(e.twice_energy_ft2_s2, t.twice_energy, 1e-11 * std::fabs(t.twice_energy)) << label;
  EXPECT_NEAR(e.angular_momentum_ft2_s, t.h, 1e-12 * t.h) << label;
  EXPECT_NEAR(e.eccentricity, t.e, 1e-11) << label;
  EXPECT_NEAR(e.perigee_radius_ft, t.rp, 1e-11 * t.rp) << label;
  EXPECT_NEAR(e.inclination_rad, t.i, 1e-12) << label;
  EXPECT_LT(angle_diff(e.node_longitude_rad, t.raan), 1e-12) << label;
  EXPECT_LT(angle_diff(e.right_ascension_rad, t.ra_position), 1e-12) << label;
  if (e.has_semi_major_axis) {
    EXPECT_NEAR(e.semi_major_axis_ft, t.a, 1e-11 * t.a) << label;
  }
  if (check_perigee_angles) {
    EXPECT_LT(angle_diff(e.argument_of_perigee_rad, t.arg_perigee), 1e-9) << label;
    EXPECT_LT(angle_diff(e.true_anomaly_rad, t.true_anomaly), 1e-9) << label;
  }
}

TEST(Sec4OrbitElements, AgreeWithCartesianTextbookElementsForOracleStates) {
  const Constants c;
  const auto& cases = test::oracle_test_vectors().at("orbit_elements");
  for (std::size_t n = 0; n < cases.size(); ++n) {
    expect_matches_textbook(c, state_from_json(cases[n].at("state")),
                            cases[n].at("launch_space_age_date").get<double>(), n != 0,
                            "oracle case " + std::to_string(n));
  }
}

TEST(Sec4OrbitElements, AgreeWithCartesianTextbookElementsOverAGridOfStates) {
  const Constants c;
  int count = 0;
  for (double lat_deg : {-60.0, -20.0, 0.5, 35.0, 70.0}) {
    for (double psi_deg : {10.0, 80.0, 135.0, 200.0, 290.0, 350.0}) {
      for (double gam_deg : {-15.0, 0.0, 7.0, 30.0}) {
        for (double v : {18000.0, 25000.0}) {
          StateVector x;
          x << v, gam_deg * kDegToRad, 2.15e7, psi_deg * kDegToRad, lat_deg * kDegToRad, 2.5;
          expect_matches_textbook(c, x, 2373.625, true,
                                  "lat " + std::to_string(lat_deg) + " psi " + std::to_string(psi_deg) +
                                      " gamma " + std::to_string(gam_deg) + " V " + std::to_string(v));
          ++count;
        }
      }
    }
  }
  EXPECT_EQ(count, 240);
}

// ---- Analytic orbits ---------------------------------------------------------------------------

TEST(Sec4OrbitElements, CircularOrbitHasZeroEccentricityAndKeplerPeriod) {
  const Constants c;
  const double mu = c.gravitational_parameter_ft3_s2;
  const double r = 2.2e7;
  const double lat = 0.4, psi_i = 70.0 * kDegToRad;
  const StateVector x = state_from_inertial(c, r, lat, 0.3, std::sqrt(mu / r), 0.0, psi_i);
  OrbitElements e;
  ASSERT_EQ(compute_orbit_elements(c, x, 2373.625, &e), Status::kOk);
  EXPECT_EQ(e.type, OrbitType::kElliptic);
  EXPECT_NEAR(e.inertial.velocity_ft_s, std::sqrt(mu / r), 1e-9);
  EXPECT_NEAR(e.inertial.flight_path_angle_rad, 0.0, 1e-14);
  EXPECT_NEAR(e.eccentricity, 0.0, 1e-13);
  EXPECT_NEAR(e.perigee_radius_ft, r, 1e-6);
  EXPECT_NEAR(e.apogee_radius_ft, r, 1e-6);
  EXPECT_NEAR(e.semi_major_axis_ft, r, 1e-6);
  EXPECT_NEAR(e.period_s, 2.0 * kPi * std::sqrt(r * r * r / mu), 1e-9);
  EXPECT_NEAR(e.inclination_rad, std::acos(std::cos(lat) * std::sin(psi_i)), 1e-14);
  EXPECT_NEAR(e.twice_energy_ft2_s2, -mu / r, 1e-6);
}

TEST(Sec4OrbitElements, EllipseBuiltAtPerigeeApogeeAndMidFlightGivesItsElements) {
  const Constants c;
  const double mu = c.gravitational_parameter_ft3_s2;
  const double rp = 2.15e7, ra = 3.6e7;
  const double a = 0.5 * (rp + ra);
  const double ecc = (ra - rp) / (ra + rp);
  const double p = a * (1.0 - ecc * ecc);
  const double period = 2.0 * kPi * std::sqrt(a * a * a / mu);
  // true anomaly, radius, radial and transverse velocity from the conic
  for (double zeta_deg : {0.0, 50.0, 180.0, 250.0}) {
    const double zeta = zeta_deg * kDegToRad;
    const double r = p / (1.0 + ecc * std::cos(zeta));
    const double v_radial = std::sqrt(mu / p) * ecc * std::sin(zeta);
    const double v_transverse = std::sqrt(mu / p) * (1.0 + ecc * std::cos(zeta));
    const StateVector x = state_from_inertial(c, r, -0.2, 1.0, std::hypot(v_radial, v_transverse),
                                              std::atan2(v_radial, v_transverse), 40.0 * kDegToRad);
    OrbitElements e;
    ASSERT_EQ(compute_orbit_elements(c, x, 2373.625, &e), Status::kOk);
    EXPECT_NEAR(e.perigee_radius_ft, rp, 1e-6) << zeta_deg;
    EXPECT_NEAR(e.apogee_radius_ft, ra, 1e-6) << zeta_deg;
    EXPECT_NEAR(e.semi_major_axis_ft, a, 1e-6) << zeta_deg;
    EXPECT_NEAR(e.eccentricity, ecc, 1e-13) << zeta_deg;
    EXPECT_NEAR(e.eccentricity,
                std::sqrt(1.0 + e.twice_energy_ft2_s2 * std::pow(e.angular_momentum_ft2_s / mu, 2)), 1e-12);
    EXPECT_NEAR(e.period_s, period, 1e-8) << zeta_deg;
    EXPECT_LT(angle_diff(e.true_anomaly_rad, zeta), 1e-12) << zeta_deg;
    EXPECT_GE(e.true_anomaly_rad, 0.0);
    EXPECT_LT(e.true_anomaly_rad, kTwoPi);
  }
}

// ---- Addendum H ------------------------------------------------------------------------------------

TEST(AddendumHAsymptote, ExcessVelocityEccentricityAndAsymptoteMatchCartesian) {
  const Constants c;
  const double mu = c.gravitational_parameter_ft3_s2;
  const double t_g = 2373.625;
  double max_err = 0.0;
  int count = 0;
  for (double lat_deg : {-50.0, -10.0, 28.5, 60.0}) {
    for (double psi_deg : {30.0, 95.0, 160.0, 250.0, 330.0}) {
      for (double gam_deg : {-10.0, 0.0, 20.0}) {
        const double r = 2.2e7;
        const double v_escape = std::sqrt(2.0 * mu / r);
        const StateVector x = state_from_inertial(c, r, lat_deg * kDegToRad, -0.7, 1.25 * v_escape,
                                                  gam_deg * kDegToRad, psi_deg * kDegToRad);
        OrbitElements e;
        ASSERT_EQ(compute_orbit_elements(c, x, t_g, &e), Status::kOk);
        ASSERT_EQ(e.type, OrbitType::kHyperbolic);
        ASSERT_TRUE(e.has_asymptote);
        EXPECT_FALSE(e.has_semi_major_axis);

        const Cartesian s = to_cartesian(c, x);
        const TextbookElements t = textbook(c, s, t_g);
        EXPECT_NEAR(e.hyperbolic_excess_velocity_ft_s,
                    std::sqrt(s.v_inertial_ft_s.squaredNorm() - 2.0 * mu / r), 1e-9);
        EXPECT_NEAR(e.hyperbolic_excess_velocity_ft_s, std::sqrt(e.twice_energy_ft2_s2), 1e-12);
        EXPECT_GT(e.eccentricity, 1.0);
        EXPECT_NEAR(e.eccentricity, t.e, 1e-12);

        // Outgoing asymptote: the position direction at true anomaly acos(-1/e),
        // d = cos(zeta_inf) e_hat + sin(zeta_inf) (h_hat x e_hat).
        const Vector3 e_hat = t.e_vec / t.e;
        const Vector3 h_hat = t.h_vec / t.h;
        const Vector3 d = (-1.0 / t.e) * e_hat + (std::sqrt(t.e * t.e - 1.0) / t.e) * h_hat.cross(e_hat);
        const double dec = std::asin(d.z());
        const double ra = std::atan2(d.y(), d.x()) + greenwich_ra_at_launch_rad(t_g);
        EXPECT_NEAR(e.asymptote_declination_rad, dec, 1e-11);
        EXPECT_LT(angle_diff(e.asymptote_right_ascension_rad, ra), 1e-11);
        EXPECT_GE(e.asymptote_declination_rad, -0.5 * kPi);
        EXPECT_LE(e.asymptote_declination_rad, 0.5 * kPi);
        EXPECT_GE(e.asymptote_right_ascension_rad, 0.0);
        EXPECT_LT(e.asymptote_right_ascension_rad, kTwoPi);
        max_err = std::max({max_err, std::fabs(e.asymptote_declination_rad - dec),
                            angle_diff(e.asymptote_right_ascension_rad, ra)});
        ++count;
      }
    }
  }
  EXPECT_EQ(count, 60);
  std::printf("[ figures  ] AddendumH asymptote RA/declination vs Cartesian max err %.2e rad\n", max_err);
}

TEST(AddendumHAsymptote, EscapeEnergyIsParabolicWithoutAsymptote) {
  const Constants c;
  const double mu = c.gravitational_parameter_ft3_s2;
  const double r = 2.2e7;
  const StateVector x = state_from_inertial(c, r, 0.3, 0.0, std::sqrt(2.0 * mu / r), 0.2, 1.0);
  OrbitElements e;
  ASSERT_EQ(compute_orbit_elements(c, x, 2373.625, &e), Status::kOk);
  EXPECT_EQ(e.type, OrbitType::kParabolic);
  EXPECT_FALSE(e.has_semi_major_axis);
  EXPECT_FALSE(e.has_asymptote);
  EXPECT_NEAR(e.eccentricity, 1.0, 1e-7);
  // r_p = H^2 / (2 mu) for a parabola.
  EXPECT_NEAR(e.perigee_radius_ft, e.angular_momentum_ft2_s * e.angular_momentum_ft2_s / (2.0 * mu), 1e-3);
}

TEST(Sec4OrbitElements, FailsWithStatusOnNonFiniteStateOrZeroVelocity) {
  const Constants c;
  OrbitElements e;
  StateVector x;
  x << 7000.0, 0.1, 2.1e7, 1.0, 0.5, 0.0;
  x(2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(compute_orbit_elements(c, x, 2373.625, &e), Status::kNonFiniteState);
  // Flying west at exactly the ground speed of the equator: zero inertial velocity.
  x << c.earth_rotation_rate_rad_s * 2.1e7, 0.0, 2.1e7, 1.5 * kPi, 0.0, 0.0;
  EXPECT_EQ(compute_orbit_elements(c, x, 2373.625, &e), Status::kZeroVelocity);
  x << 7000.0, 0.1, 0.0, 1.0, 0.5, 0.0;
  EXPECT_EQ(compute_orbit_elements(c, x, 2373.625, &e), Status::kZeroVelocity);
}

// ---- Range equations ---------------------------------------------------------------------------------

double haversine_rad(double lat0, double lon0, double lat, double lon) {
  const double s_lat = std::sin(0.5 * (lat - lat0));
  const double s_lon = std::sin(0.5 * (lon - lon0));
  return 2.0 * std::asin(std::sqrt(s_lat * s_lat + std::cos(lat0) * std::cos(lat) * s_lon * s_lon));
}

TEST(Sec4RangeEquations, DownrangeMatchesHaversineAndThePrintedCosineLaw) {
  const double lat0 = 0.657173006126963, lon0 = -1.31737451940532;  // Wallops, geocentric
  double max_err = 0.0;
  for (double dlat : {-0.5, -1e-6, 0.0, 3e-4, 0.2, 1.0}) {
    for (double dlon : {-2.0, -1e-5, 0.0, 1e-7, 0.05, 1.5, 3.0}) {
      const double lat = std::clamp(lat0 + dlat, -0.5 * kPi, 0.5 * kPi);
      const double got = downrange_angle_rad(lat0, lon0, lat, lon0 + dlon);
      const double hav = haversine_rad(lat0, lon0, lat, lon0 + dlon);
      EXPECT_NEAR(got, hav, 1e-14) << dlat << " " << dlon;
      max_err = std::max(max_err, std::fabs(got - hav));
      if (hav > 0.1) {
        const double printed =
            std::acos(std::sin(lat0) * std::sin(lat) + std::cos(lat0) * std::cos(lat) * std::cos(dlon));
        EXPECT_NEAR(got, printed, 1e-12);
      }
    }
  }
  // One degree of arc is 60 n.mi.
  EXPECT_NEAR(downrange_angle_rad(0.0, 0.0, 0.0, kDegToRad) * kNauticalMilesPerRadian, 60.0, 1e-12);
  std::printf("[ figures  ] Sec4 downrange vs haversine max err %.2e rad\n", max_err);
}

// Exact spherical cross-track angle of the dispersed point from the great circle through the
// nominal point along its azimuth: asin(sin d sin(bearing - psi)), positive to the right.
TEST(Sec4RangeEquations, CrossrangeIsTheCrossTrackAngleForSmallDispersions) {
  const double lat_n = 0.66, lon_n = -1.2;
  for (double psi_deg : {0.0, 45.0, 100.0, 190.0, 300.0}) {
    const double psi = psi_deg * kDegToRad;
    for (double d_lat : {-8e-4, 0.0, 5e-4}) {
      for (double d_lon : {-1e-3, 0.0, 7e-4}) {
        if (d_lat == 0.0 && d_lon == 0.0) continue;
        const double lat_d = lat_n + d_lat, lon_d = lon_n + d_lon;
        const double d = haversine_rad(lat_n, lon_n, lat_d, lon_d);
        const double bearing = std::atan2(
            std::sin(d_lon) * std::cos(lat_d),
            std::cos(lat_n) * std::sin(lat_d) - std::sin(lat_n) * std::cos(lat_d) * std::cos(d_lon));
        const double exact = std::asin(std::sin(d) * std::sin(bearing - psi));
        const double got = crossrange_angle_rad(lat_n, lon_n, psi, lat_d, lon_d);
        // Small-angle error is second order in the ~1e-3 rad offsets.
        EXPECT_NEAR(got, exact, 2e-6) << psi_deg << " " << d_lat << " " << d_lon;
      }
    }
  }
  // Heading north, a point to the east is to the right: positive.
  EXPECT_GT(crossrange_angle_rad(0.5, 0.0, 0.0, 0.5, 1e-4), 0.0);
  EXPECT_LT(crossrange_angle_rad(0.5, 0.0, 0.0, 0.5, -1e-4), 0.0);
}

// ---- Sec. 13 heating --------------------------------------------------------------------------------

TEST(Sec13Heating, RateMatchesTheFormulaByHand) {
  // R = 0.5 ft, rho = 1e-5, rho_SL = 0.0023769, V = 15000 ft/s:
  // 20800 / sqrt(0.5) = 29415.6421; sqrt(1e-5 / 0.0023769) = 0.0648626286; 1.5^3.25 = 3.73505148
  // product 7126.38809 Btu/ft^2/s.
  EXPECT_NEAR(stagnation_heating_rate(0.5, 1.0e-5, 0.0023769, 15000.0), 7126.388087770833, 1e-8);
  EXPECT_EQ(stagnation_heating_rate(0.5, 0.0, 0.0023769, 15000.0), 0.0);  // above HAERO
}

TEST(Sec13Heating, PrintedPartialDerivativesMatchFiniteDifferences) {
  const double rn = 0.5, rho_sl = 0.0023769, rho = 2e-6, v = 18000.0;
  const double k = 20800.0 / (std::sqrt(rn) * std::pow(10000.0, 3.25) * std::sqrt(rho_sl));
  const double dq_dv = 3.25 * k * std::sqrt(rho) * std::pow(v, 2.25);
  const double dq_drho = 0.5 * k * std::pow(v, 3.25) / std::sqrt(rho);  // times drho/dh in the manual
  const double fd_v = (stagnation_heating_rate(rn, rho, rho_sl, v + 1.0) -
                       stagnation_heating_rate(rn, rho, rho_sl, v - 1.0)) /
                      2.0;
  const double fd_rho = (stagnation_heating_rate(rn, rho * (1 + 1e-6), rho_sl, v) -
                         stagnation_heating_rate(rn, rho * (1 - 1e-6), rho_sl, v)) /
                        (2e-6 * rho);
  EXPECT_NEAR(dq_dv, fd_v, 1e-7 * std::fabs(dq_dv));
  EXPECT_NEAR(dq_drho, fd_rho, 1e-7 * std::fabs(dq_drho));
}

TEST(Sec13Heating, CheckedVariantRejectsBadInputs) {
  double q = -1.0;
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, 0.0023769, 15000.0, &q), Status::kOk);
  EXPECT_NEAR(q, 7126.388087770833, 1e-8);
  EXPECT_EQ(stagnation_heating_rate_checked(0.0, 1e-5, 0.0023769, 15000.0, &q),
            Status::kNoseRadiusNotPositive);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, -1e-5, 0.0023769, 15000.0, &q),
            Status::kHeatingStateNegative);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, 0.0023769, -1.0, &q), Status::kHeatingStateNegative);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, 0.0, 15000.0, &q),
            Status::kSeaLevelDensityNotPositive);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, 0.0023769, 15000.0, nullptr),
            Status::kOutputPointerNull);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, std::nan(""), 0.0023769, 1.0, &q), Status::kValueNotFinite);
  // Each input on its own (Sec. 13 eq. for q-dot needs R_N > 0 and rho_0 > 0), and no output.
  EXPECT_EQ(stagnation_heating_rate_checked(HUGE_VAL, 1e-5, 0.0023769, 1.0, &q), Status::kValueNotFinite);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, std::nan(""), 1.0, &q), Status::kValueNotFinite);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, 0.0023769, -HUGE_VAL, &q), Status::kValueNotFinite);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, 0.0, 15000.0, &q),
            Status::kSeaLevelDensityNotPositive);
  EXPECT_EQ(stagnation_heating_rate_checked(0.5, 1e-5, 0.0023769, 15000.0, nullptr),
            Status::kOutputPointerNull);
  EXPECT_NEAR(q, 7126.388087770833, 1e-8) << "a refused input leaves the output as it was";
}

}  // namespace
}  // namespace tolip
