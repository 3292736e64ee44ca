// INER inertial variables, Sec. 4 orbit elements, Addendum H asymptote, range equations and the
// Sec. 13 heating rate (see docs/theory/atmosphere-earth-orbit.md).
//
// Every printed arctangent is evaluated as atan2 of the two signed quantities whose ratio the
// manual prints (each numerator and denominator is a positive multiple of the sine and cosine of
// the angle), so the angles land in the manual's stated ranges without quadrant logic.
#include "tolip/orbit/orbit_elements.hpp"

#include <cmath>
#include <limits>

namespace tolip {

namespace {

constexpr double kTwoPi = 2.0 * kPi;

double wrap_two_pi(double angle_rad) {
  double wrapped = std::fmod(angle_rad, kTwoPi);
  if (wrapped < 0.0) wrapped += kTwoPi;
  // fmod of a tiny negative angle plus 2 pi rounds to exactly 2 pi, outside [0, 2 pi).
  if (wrapped >= kTwoPi) wrapped = 0.0;
  return wrapped;
}

bool all_finite(const OrbitElements& e) {
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
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

}  // namespace

InertialVelocity inertial_velocity(const Constants& constants, const StateVector& state) {
  const double gamma = state(kStateGamma);
  const double psi = state(kStatePsi);
  return inertial_velocity(constants, state, std::sin(gamma), std::cos(gamma), std::sin(psi), std::cos(psi),
                           std::cos(state(kStateLambda)));
}

InertialVelocity inertial_velocity(const Constants& constants, const StateVector& state, double sin_gamma,
                                   double cos_gamma, double sin_psi, double cos_psi, double cos_lambda) {
  const double v = state(kStateV);
  const double r = state(kStateR);
  // Local up / north / east components; the Earth's rotation adds omega r cos(lambda) eastward.
  // Same quantities as the INER formulas, but V_I from its components avoids the cancellation
  // of the printed sum when the relative velocity is nearly westward.
  const double up_ft_s = v * sin_gamma;
  const double north_ft_s = v * cos_gamma * cos_psi;
  const double east_ft_s = v * cos_gamma * sin_psi + constants.earth_rotation_rate_rad_s * r * cos_lambda;
  const double horizontal_ft_s = std::hypot(north_ft_s, east_ft_s);
  InertialVelocity out;
  out.velocity_ft_s = std::hypot(horizontal_ft_s, up_ft_s);
  out.flight_path_angle_rad = std::atan2(up_ft_s, horizontal_ft_s);
  out.azimuth_rad = wrap_two_pi(std::atan2(east_ft_s, north_ft_s));
  return out;
}

double launch_greenwich_right_ascension_rad(double launch_space_age_date_days) {
  const double t_g = launch_space_age_date_days;
  const double time_of_day_fraction = t_g - std::floor(t_g);
  const double angle_deg = std::fmod(99.659967 + 0.98564743 * t_g + 360.0 * time_of_day_fraction, 360.0);
  return wrap_two_pi(angle_deg * kDegToRad);
}

Status compute_orbit_elements(const Constants& constants, const StateVector& state,
                              double launch_space_age_date_days, OrbitElements* out) {
  if (out == nullptr) return Status::kOutputPointerNull;
  if (!state.allFinite()) return Status::kNonFiniteState;
  if (!std::isfinite(launch_space_age_date_days)) return Status::kValueNotFinite;
  const double mu = constants.gravitational_parameter_ft3_s2;
  const double r = state(kStateR);
  const double lambda = state(kStateLambda);
  const double tau = state(kStateTau);
  if (!(r > 0.0)) return Status::kZeroVelocity;

  OrbitElements e;
  e.inertial = inertial_velocity(constants, state);
  const double v_i = e.inertial.velocity_ft_s;
  // Below a micro-foot per second the direction of V_I, and every angle derived from it, is the
  // round-off of cancelling relative and rotation velocities, not a property of the trajectory.
  constexpr double kMinimumInertialSpeed_ft_s = 1e-6;
  if (!(v_i > kMinimumInertialSpeed_ft_s)) return Status::kZeroVelocity;
  const double gamma_i = e.inertial.flight_path_angle_rad;
  const double psi_i = e.inertial.azimuth_rad;

  e.twice_energy_ft2_s2 = v_i * v_i - 2.0 * mu / r;
  // The manual prints cos(psi_I); the nomenclature (EH = V_I R cos gamma_I) and the definition of
  // angular momentum both say gamma_I.
  const double h = r * v_i * std::cos(gamma_i);
  e.angular_momentum_ft2_s = h;
  // mu^2 e^2 = mu^2 + 2E H^2; the printed r_p = H / (mu/H + sqrt(2E + (mu/H)^2)) multiplied through
  // by H, so that a radial (H = 0) trajectory gives r_p = 0 instead of 0/0.
  const double mu_e_squared = std::fmax(mu * mu + e.twice_energy_ft2_s2 * h * h, 0.0);
  const double mu_e = std::sqrt(mu_e_squared);
  e.perigee_radius_ft = h * h / (mu + mu_e);

  // Orientation on the unit sphere: sin i = sqrt(sin^2 lambda + cos^2 lambda cos^2 psi_I) >= 0,
  // sin(nu) sin(i) = sin(lambda) sin(psi_I), cos(nu) sin(i) = cos(psi_I),
  // sin(beta) sin(i) = sin(lambda), cos(beta) sin(i) = cos(lambda) cos(psi_I).
  const double sin_lat = std::sin(lambda);
  const double cos_lat = std::cos(lambda);
  const double sin_psi_i = std::sin(psi_i);
  const double cos_psi_i = std::cos(psi_i);
  const double cos_i = cos_lat * sin_psi_i;
  const double sin_i = std::hypot(sin_lat, cos_lat * cos_psi_i);
  e.inclination_rad = std::atan2(sin_i, cos_i);  // = acos(cos lambda sin psi_I), accurate near 0
  e.right_ascension_rad = wrap_two_pi(launch_greenwich_right_ascension_rad(launch_space_age_date_days) + tau);
  e.nu_rad = wrap_two_pi(std::atan2(sin_lat * sin_psi_i, cos_psi_i));
  e.node_longitude_rad = wrap_two_pi(e.right_ascension_rad - e.nu_rad);
  e.in_plane_angle_from_node_rad = wrap_two_pi(std::atan2(sin_lat, cos_lat * cos_psi_i));

  // True anomaly from e sin(zeta) = H V_I sin(gamma_I) / mu and e cos(zeta) = H^2 / (mu r) - 1;
  // the printed tan(gamma_I) / (1 - mu r / H^2) is their ratio.
  const double e_sin_zeta = h * v_i * std::sin(gamma_i) / mu;
  const double e_cos_zeta = h * h / (mu * r) - 1.0;
  e.true_anomaly_rad = wrap_two_pi(std::atan2(e_sin_zeta, e_cos_zeta));
  e.argument_of_perigee_rad = wrap_two_pi(e.in_plane_angle_from_node_rad - e.true_anomaly_rad);

  // 2E is the difference of two nearly equal terms near escape; within its own round-off the
  // orbit is called parabolic, where neither a semi-major axis nor an asymptote exists.
  const double parabolic_band_ft2_s2 = 16.0 * std::numeric_limits<double>::epsilon() * v_i * v_i;
  if (e.twice_energy_ft2_s2 < -parabolic_band_ft2_s2) {
    e.type = OrbitType::kElliptic;
    e.has_semi_major_axis = true;
    e.semi_major_axis_ft = -mu / e.twice_energy_ft2_s2;
    e.period_s = 2.0 * kPi * e.semi_major_axis_ft * std::sqrt(e.semi_major_axis_ft / mu);
    e.apogee_radius_ft = 2.0 * e.semi_major_axis_ft - e.perigee_radius_ft;
    e.eccentricity = 1.0 - e.perigee_radius_ft / e.semi_major_axis_ft;
  } else if (e.twice_energy_ft2_s2 > parabolic_band_ft2_s2) {
    e.type = OrbitType::kHyperbolic;
    e.eccentricity = mu_e / mu;
    // Addendum H: the outgoing asymptote is the direction of the position at the limiting true
    // anomaly zeta_H = pi - atan(H v_H / mu) = acos(-1/e).
    e.has_asymptote = true;
    e.hyperbolic_excess_velocity_ft_s = std::sqrt(e.twice_energy_ft2_s2);
    const double zeta_h = kPi - std::atan(h * e.hyperbolic_excess_velocity_ft_s / mu);
    const double beta_h = e.argument_of_perigee_rad + zeta_h;
    e.asymptote_declination_rad = std::asin(std::fmax(-1.0, std::fmin(1.0, sin_i * std::sin(beta_h))));
    const double nu_h = wrap_two_pi(std::atan2(cos_i * std::sin(beta_h), std::cos(beta_h)));
    e.asymptote_right_ascension_rad = wrap_two_pi(e.node_longitude_rad + nu_h);
  } else {
    e.type = OrbitType::kParabolic;
    e.eccentricity = mu_e / mu;
  }

  if (!all_finite(e)) return Status::kNonFiniteState;
  *out = e;
  return Status::kOk;
}

double downrange_angle_rad(double launch_latitude_rad, double launch_longitude_rad, double latitude_rad,
                           double longitude_rad) {
  // The manual's cos(DR) = sin lambda0 sin lambda + cos lambda0 cos lambda cos(dtau), evaluated as
  // atan2(|n0 x n|, n0 . n): acos loses half the digits near lift-off, where DR is tiny.
  return downrange_angle_rad(std::sin(launch_latitude_rad), std::cos(launch_latitude_rad),
                             std::sin(latitude_rad), std::cos(latitude_rad),
                             longitude_rad - launch_longitude_rad);
}

double downrange_angle_rad(double sin_lat0, double cos_lat0, double sin_lat, double cos_lat, double d_lon) {
  const double cos_d_lon = std::cos(d_lon);
  const double dot = sin_lat0 * sin_lat + cos_lat0 * cos_lat * cos_d_lon;
  const double cross_x = cos_lat * std::sin(d_lon);
  const double cross_y = cos_lat0 * sin_lat - sin_lat0 * cos_lat * cos_d_lon;
  return std::atan2(std::hypot(cross_x, cross_y), dot);
}

double crossrange_angle_rad(double nominal_latitude_rad, double nominal_longitude_rad,
                            double nominal_azimuth_rad, double dispersed_latitude_rad,
                            double dispersed_longitude_rad) {
  // Sec. 4 small-angle form: tan Q = dtau / dlambda, slant = hypot, crossrange = -slant sin(psi - Q).
  // The longitude difference is scaled by cos(lambda_n) so that it is an arc (the printed form
  // omits the factor and overstates east-west offsets by 1 / cos(lambda); see the theory note).
  const double d_lat_rad = dispersed_latitude_rad - nominal_latitude_rad;
  const double d_lon_rad = std::remainder(dispersed_longitude_rad - nominal_longitude_rad, 2.0 * kPi);
  const double d_east_rad = d_lon_rad * std::cos(nominal_latitude_rad);
  const double slant_rad = std::hypot(d_lat_rad, d_east_rad);
  const double q_rad = std::atan2(d_east_rad, d_lat_rad);
  return -slant_rad * std::sin(nominal_azimuth_rad - q_rad);
}

double stagnation_heating_rate(double nose_radius_ft, double density_slug_ft3,
                               double sea_level_density_slug_ft3, double velocity_ft_s) {
  return 20800.0 / std::sqrt(nose_radius_ft) * std::sqrt(density_slug_ft3 / sea_level_density_slug_ft3) *
         std::pow(velocity_ft_s / 10000.0, 3.25);
}

Status stagnation_heating_rate_checked(double nose_radius_ft, double density_slug_ft3,
                                       double sea_level_density_slug_ft3, double velocity_ft_s,
                                       double* heating_rate_btu_ft2_s) {
  if (heating_rate_btu_ft2_s == nullptr) return Status::kOutputPointerNull;
  if (!std::isfinite(nose_radius_ft) || !std::isfinite(density_slug_ft3) ||
      !std::isfinite(sea_level_density_slug_ft3) || !std::isfinite(velocity_ft_s)) {
    return Status::kValueNotFinite;
  }
  if (!(nose_radius_ft > 0.0)) return Status::kNoseRadiusNotPositive;
  if (!(sea_level_density_slug_ft3 > 0.0)) return Status::kSeaLevelDensityNotPositive;
  if (density_slug_ft3 < 0.0 || velocity_ft_s < 0.0) return Status::kHeatingStateNegative;
  *heating_rate_btu_ft2_s =
      stagnation_heating_rate(nose_radius_ft, density_slug_ft3, sea_level_density_slug_ft3, velocity_ft_s);
  return Status::kOk;
}

}  // namespace tolip
