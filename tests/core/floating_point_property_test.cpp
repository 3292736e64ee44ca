// Floating-point hygiene of fsw_core's public functions (issue 14; docs/verification/README.md):
// property tests over seeded random VALID inputs prove that no NaN or infinity comes out, and
// over non-finite inputs that the functions which check their inputs return a status instead of
// a number. Truth is the property itself and, where one exists, an identity the test computes
// independently (orthonormal frames, the Kepler relations between the orbit elements).
// Verifies: REQ-FSW-005
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/table/control_law.hpp"
#include "tolip/table/guidance_executor.hpp"

namespace tolip {
namespace {

constexpr int kSamples = 20000;
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

// One seeded generator per test: the same inputs on every run and machine (mt19937_64 is fully
// specified; the distributions are not, so values are drawn from the raw 64-bit output).
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed) {}
  double uniform(double low, double high) {
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    return low + (high - low) * unit;
  }
  double log_uniform(double low, double high) { return std::exp(uniform(std::log(low), std::log(high))); }

 private:
  std::mt19937_64 engine_;
};

bool all_finite(const Matrix3& m) { return m.allFinite(); }

// A state over the range the core flies: below the surface to beyond escape, any angle.
StateVector random_state(Draw& d, const Constants& k) {
  StateVector x;
  x[kStateV] = d.log_uniform(1.0, 60000.0);
  x[kStateGamma] = d.uniform(-kPi / 2, kPi / 2);
  x[kStateR] = k.earth_equatorial_radius_ft + d.uniform(-50000.0, 5.0e8);
  x[kStatePsi] = d.uniform(-2 * kPi, 2 * kPi);
  x[kStateLambda] = d.uniform(-kPi / 2, kPi / 2);
  x[kStateTau] = d.uniform(-4 * kPi, 4 * kPi);
  return x;
}

TEST(FloatingPoint, Sec19_AtmosphereIsFiniteAtRandomAltitudesAndNonFiniteInputIsAStatus) {
  Draw d(0x5EED0001);
  const AtmosphereTable table;
  const Constants k;
  int below_earth_centre = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double h = i % 2 == 0 ? d.uniform(-20000.0, 400000.0) : d.log_uniform(1.0, 1.0e9);
    const double radius = d.uniform(1.0e6, 3.0e7);
    AtmosphereSample s;
    const Status status = evaluate_atmosphere(table, k, h, radius, &s);
    if (status != Status::kOk) {
      ++below_earth_centre;
      continue;
    }
    ASSERT_TRUE(std::isfinite(s.geopotential_altitude_ft) && std::isfinite(s.density_slug_ft3) &&
                std::isfinite(s.pressure_lbf_ft2) && std::isfinite(s.speed_of_sound_ft_s) &&
                std::isfinite(s.temperature_R) && std::isfinite(s.ddensity_dh) &&
                std::isfinite(s.dpressure_dh) && std::isfinite(s.dspeed_of_sound_dh))
        << "h = " << h << " ft, radius " << radius;
    ASSERT_GE(s.density_slug_ft3, 0.0);
    ASSERT_GT(s.speed_of_sound_ft_s, 0.0);
  }
  EXPECT_EQ(below_earth_centre, 0);  // every altitude drawn lies above the Earth's centre
  for (const double bad : {kNaN, kInf, -kInf}) {
    AtmosphereSample s;
    EXPECT_EQ(evaluate_atmosphere(table, k, bad, k.earth_equatorial_radius_ft, &s), Status::kValueNotFinite);
    EXPECT_EQ(evaluate_atmosphere(table, k, 1000.0, bad, &s), Status::kValueNotFinite);
  }
}

TEST(FloatingPoint, Sec4_EarthModelAndJ2GravityAreFiniteOverRandomPositions) {
  Draw d(0x5EED0002);
  const Constants k;
  for (int i = 0; i < kSamples; ++i) {
    const double lat = d.uniform(-kPi / 2, kPi / 2);
    const double r = k.earth_equatorial_radius_ft * d.uniform(0.9, 60.0);
    const double geodetic = geodetic_from_geocentric_rad(k, lat);
    const Gravity g = j2_gravity(k, r, lat);
    const double values[] = {oblate_radius_ft(k, lat),
                             oblate_altitude_ft(k, r, lat),
                             geodetic,
                             geocentric_from_geodetic_rad(k, geodetic),
                             ellipsoid_geodetic_from_geocentric_rad(k, lat),
                             delta_lambda_rad(k, lat, r),
                             g.spherical_ft_s2,
                             g.radial_ft_s2,
                             g.north_ft_s2};
    for (const double v : values)
      ASSERT_TRUE(std::isfinite(v)) << "latitude " << lat << " rad, r " << r << " ft";
    ASSERT_TRUE(
        geodetic_to_earth_fixed_ft(k, geodetic, d.uniform(-kPi, kPi), d.uniform(-1e4, 1e6)).allFinite());
    ASSERT_LE(std::fabs(geodetic), kPi / 2 + 1e-12);
  }
}

TEST(FloatingPoint, Sec4_FramesAreFiniteAndOrthonormalAtRandomStates) {
  Draw d(0x5EED0003);
  const Constants k;
  double worst = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    const StateVector x = random_state(d, k);
    const Matrix3 a = inertial_to_local(x);
    ASSERT_TRUE(all_finite(a));
    worst = std::max(worst, (a * a.transpose() - Matrix3::Identity()).cwiseAbs().maxCoeff());
    const Matrix3 b =
        geocentric_to_inertial(d.uniform(-kPi, kPi), d.uniform(-kPi / 2, kPi / 2), d.uniform(-kPi, kPi));
    const Matrix3 c = platform_to_geocentric(d.uniform(-kPi, kPi), d.uniform(-0.01, 0.01));
    ASSERT_TRUE(all_finite(b) && all_finite(c));
    const Vector3 axis = thrust_axis_platform(d.uniform(-kPi, kPi), d.uniform(-kPi, kPi));
    ASSERT_TRUE(axis.allFinite());
    ASSERT_NEAR(axis.norm(), 1.0, 1e-12);
    const double alpha = angle_of_attack_rad(a * b * c * axis);
    ASSERT_TRUE(std::isfinite(alpha));
    ASSERT_TRUE(all_finite(earth_fixed_to_topocentric(d.uniform(-kPi / 2, kPi / 2), d.uniform(-kPi, kPi))));
  }
  EXPECT_LT(worst, 1e-14);
}

TEST(FloatingPoint, Sec4_OrbitElementsAreFiniteOrAStatusAtRandomStates) {
  Draw d(0x5EED0004);
  const Constants k;
  int elliptic = 0;
  int hyperbolic = 0;
  for (int i = 0; i < kSamples; ++i) {
    const StateVector x = random_state(d, k);
    OrbitElements e;
    const Status status = compute_orbit_elements(k, x, d.uniform(0.0, 4000.0), &e);
    ASSERT_EQ(status, Status::kOk) << "V " << x[kStateV] << " r " << x[kStateR];
    const double values[] = {e.inertial.velocity_ft_s,
                             e.inertial.flight_path_angle_rad,
                             e.inertial.azimuth_rad,
                             e.twice_energy_ft2_s2,
                             e.angular_momentum_ft2_s,
                             e.perigee_radius_ft,
                             e.inclination_rad,
                             e.right_ascension_rad,
                             e.nu_rad,
                             e.node_longitude_rad,
                             e.in_plane_angle_from_node_rad,
                             e.true_anomaly_rad,
                             e.argument_of_perigee_rad,
                             e.eccentricity,
                             e.semi_major_axis_ft,
                             e.period_s,
                             e.apogee_radius_ft,
                             e.hyperbolic_excess_velocity_ft_s,
                             e.asymptote_right_ascension_rad,
                             e.asymptote_declination_rad};
    for (const double v : values) ASSERT_TRUE(std::isfinite(v)) << "V " << x[kStateV] << " r " << x[kStateR];
    // Independent identity: H^2 = mu r_p (1 + e) for every conic (r_p from the same H and 2E).
    const double h2 = e.angular_momentum_ft2_s * e.angular_momentum_ft2_s;
    if (e.type != OrbitType::kParabolic && e.perigee_radius_ft > 1.0)
      ASSERT_NEAR(k.gravitational_parameter_ft3_s2 * e.perigee_radius_ft * (1.0 + e.eccentricity) / h2, 1.0,
                  1e-6);
    (e.type == OrbitType::kElliptic ? elliptic : hyperbolic) += 1;
  }
  EXPECT_GT(elliptic, 1000);  // both kinds of orbit were drawn
  EXPECT_GT(hyperbolic, 1000);
  StateVector x = random_state(d, k);
  for (int j = 0; j < 6; ++j) {
    StateVector bad = x;
    bad[j] = kNaN;
    OrbitElements e;
    EXPECT_EQ(compute_orbit_elements(k, bad, 0.0, &e), Status::kNonFiniteState) << "state word " << j;
  }
}

TEST(FloatingPoint, Sec10_ControlLawIsFiniteOnRandomInputAndNonFiniteInputIsNeutralAndNamed) {
  Draw d(0x5EED0005);
  for (int i = 0; i < kSamples; ++i) {
    GuidanceCommand command;
    command.mode = GuidanceMode::kSegment;
    command.theta_rad = d.uniform(-kPi, kPi);
    command.theta_dot_rad_s = d.uniform(-0.1, 0.1);
    command.k_theta = d.log_uniform(1e-3, 100.0);
    command.k_q_s = d.log_uniform(1e-4, 10.0);
    ControlDeflection out;
    ASSERT_EQ(attitude_control_deflection(command, d.uniform(-kPi, kPi), d.uniform(-1.0, 1.0), &out),
              Status::kOk);
    ASSERT_TRUE(std::isfinite(out.deflection_rad) && std::isfinite(out.unlimited_rad));
  }
  for (const double bad : {kNaN, kInf, -kInf}) {
    GuidanceCommand command;
    command.k_theta = 1.0;
    command.k_q_s = 0.1;
    ControlDeflection out;
    EXPECT_EQ(attitude_control_deflection(command, bad, 0.0, &out), Status::kValueNotFinite);
    EXPECT_EQ(out.deflection_rad, 0.0);
    EXPECT_EQ(attitude_control_deflection(command, 0.0, bad, &out), Status::kValueNotFinite);
    EXPECT_EQ(out.deflection_rad, 0.0);
    command.theta_rad = bad;
    EXPECT_EQ(attitude_control_deflection(command, 0.0, 0.0, &out), Status::kValueNotFinite);
    EXPECT_EQ(out.deflection_rad, 0.0);
  }
}

TEST(FloatingPoint, Sec13_HeatingRateIsFiniteOnRandomInputAndBadInputIsAStatus) {
  Draw d(0x5EED0006);
  for (int i = 0; i < kSamples; ++i) {
    double q = kNaN;
    ASSERT_EQ(stagnation_heating_rate_checked(d.log_uniform(0.01, 100.0), d.log_uniform(1e-15, 3e-3),
                                              0.0023769, d.uniform(0.0, 60000.0), &q),
              Status::kOk);
    ASSERT_TRUE(std::isfinite(q));
    ASSERT_GE(q, 0.0);
  }
  double q = 0.0;
  for (const double bad : {kNaN, kInf})
    EXPECT_EQ(stagnation_heating_rate_checked(1.0, bad, 0.0023769, 1000.0, &q), Status::kValueNotFinite);
  EXPECT_EQ(stagnation_heating_rate_checked(0.0, 1e-3, 0.0023769, 1000.0, &q),
            Status::kNoseRadiusNotPositive);
  EXPECT_EQ(stagnation_heating_rate_checked(1.0, -1e-3, 0.0023769, 1000.0, &q),
            Status::kHeatingStateNegative);
}

}  // namespace
}  // namespace tolip
