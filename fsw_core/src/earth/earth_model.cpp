// Oblate Earth of manual Sec. 4 (see docs/theory/atmosphere-earth-orbit.md).
#include "tolip/earth/earth_model.hpp"

#include <cmath>

namespace tolip {

namespace {

// Purcell-Cowan series coefficients as printed in Sec. 4 (for the flattening 1/298.3).
constexpr double kPurcellCowanC1 = 3.372672e-3;
constexpr double kPurcellCowanC2 = -5.6873e-6;

// "6 sigma" of Sec. 4: the oblate-figure part of the deflection of the vertical, as printed (it
// belongs to the manual's Earth, J2 = 1.0827e-3).
constexpr double kFigureDeflectionCoefficient = 0.001638;

double purcell_cowan_geodetic_rad(double geocentric_latitude_rad) {
  return geocentric_latitude_rad + kPurcellCowanC1 * std::sin(2.0 * geocentric_latitude_rad) +
         kPurcellCowanC2 * std::sin(4.0 * geocentric_latitude_rad);
}

// (b / a)^2 = ((f - 1) / f)^2 of the deck's ellipsoid.
double axis_ratio_squared(const Constants& constants) {
  const double f = constants.inverse_flattening;
  const double ratio = (f - 1.0) / f;
  return ratio * ratio;
}

}  // namespace

bool is_spherical_earth(const Constants& constants) { return constants.inverse_flattening == 0.0; }

double polar_radius_ft(const Constants& constants) {
  const double a = constants.earth_equatorial_radius_ft;
  if (is_spherical_earth(constants)) return a;
  return a * (constants.inverse_flattening - 1.0) / constants.inverse_flattening;
}

double oblate_radius_ft(const Constants& constants, double geocentric_latitude_rad) {
  if (is_spherical_earth(constants)) return constants.earth_equatorial_radius_ft;
  const double f = constants.inverse_flattening;
  // atan2 rather than the printed atan(tan) so the poles need no special case; the result is
  // the same reduced latitude eta everywhere else.
  const double eta =
      std::atan2(f * std::sin(geocentric_latitude_rad), (f - 1.0) * std::cos(geocentric_latitude_rad));
  const double z = (f - 1.0) / f * std::sin(eta);
  const double x = std::cos(eta);
  return constants.earth_equatorial_radius_ft * std::sqrt(x * x + z * z);
}

double oblate_altitude_ft(const Constants& constants, double radius_ft, double geocentric_latitude_rad) {
  return radius_ft - oblate_radius_ft(constants, geocentric_latitude_rad);
}

bool uses_purcell_cowan_series(const Constants& constants) {
  return constants.inverse_flattening == kManualInverseFlattening;
}

double ellipsoid_geodetic_from_geocentric_rad(const Constants& constants, double geocentric_latitude_rad) {
  if (is_spherical_earth(constants)) return geocentric_latitude_rad;
  // tan lambda_d = (a / b)^2 tan lambda_c, with atan2 so the poles map onto themselves.
  return std::atan2(std::sin(geocentric_latitude_rad),
                    axis_ratio_squared(constants) * std::cos(geocentric_latitude_rad));
}

double ellipsoid_geocentric_from_geodetic_rad(const Constants& constants, double geodetic_latitude_rad) {
  if (is_spherical_earth(constants)) return geodetic_latitude_rad;
  return std::atan2(axis_ratio_squared(constants) * std::sin(geodetic_latitude_rad),
                    std::cos(geodetic_latitude_rad));
}

double geodetic_from_geocentric_rad(const Constants& constants, double geocentric_latitude_rad) {
  if (uses_purcell_cowan_series(constants)) return purcell_cowan_geodetic_rad(geocentric_latitude_rad);
  return ellipsoid_geodetic_from_geocentric_rad(constants, geocentric_latitude_rad);
}

double geocentric_from_geodetic_rad(const Constants& constants, double geodetic_latitude_rad) {
  if (!uses_purcell_cowan_series(constants)) {
    return ellipsoid_geocentric_from_geodetic_rad(constants, geodetic_latitude_rad);
  }
  // Newton on the forward series so that the round trip is exact to round-off (the closed-form
  // ellipsoid inverse differs from the series by ~5e-4 deg, enough to shift the launch point).
  // The series' slope is 1 +- 0.007, so convergence is quadratic from the geodetic value and
  // four iterations reach round-off; the fixed bound keeps the loop's cost known.
  constexpr int kMaxIterations = 8;
  double geocentric_rad = geodetic_latitude_rad;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const double residual_rad = purcell_cowan_geodetic_rad(geocentric_rad) - geodetic_latitude_rad;
    const double slope = 1.0 + 2.0 * kPurcellCowanC1 * std::cos(2.0 * geocentric_rad) +
                         4.0 * kPurcellCowanC2 * std::cos(4.0 * geocentric_rad);
    const double step_rad = residual_rad / slope;
    geocentric_rad -= step_rad;
    if (std::fabs(step_rad) <= 1e-16) break;
  }
  return geocentric_rad;
}

double figure_deflection_coefficient(const Constants& constants) {
  if (constants.j2 == kManualJ2) return kFigureDeflectionCoefficient;
  return 1.5 * constants.j2;
}

double delta_lambda_rad(const Constants& constants, double geocentric_latitude_rad, double radius_ft) {
  const double omega = constants.earth_rotation_rate_rad_s;
  const double g_ft_s2 = constants.gravitational_parameter_ft3_s2 / (radius_ft * radius_ft);
  return (figure_deflection_coefficient(constants) + omega * omega * radius_ft / (2.0 * g_ft_s2)) *
         std::sin(2.0 * geocentric_latitude_rad);
}

Vector3 geodetic_to_earth_fixed_ft(const Constants& constants, double geodetic_latitude_rad,
                                   double longitude_rad, double altitude_ft) {
  const double a = constants.earth_equatorial_radius_ft;
  const double b = polar_radius_ft(constants);
  const double sin_lat = std::sin(geodetic_latitude_rad);
  const double cos_lat = std::cos(geodetic_latitude_rad);
  // tan RA = (b / a) tan lambda_d, written with atan2 of the scaled sine and cosine.
  const double reduced_rad = std::atan2(b * sin_lat, a * cos_lat);
  const double z_ft = b * std::sin(reduced_rad) + altitude_ft * sin_lat;
  const double xy_ft = a * std::cos(reduced_rad) + altitude_ft * cos_lat;
  return Vector3(xy_ft * std::cos(longitude_rad), xy_ft * std::sin(longitude_rad), z_ft);
}

Vector3 geocentric_to_earth_fixed_ft(double radius_ft, double geocentric_latitude_rad, double longitude_rad) {
  const double xy_ft = radius_ft * std::cos(geocentric_latitude_rad);
  return Vector3(xy_ft * std::cos(longitude_rad), xy_ft * std::sin(longitude_rad),
                 radius_ft * std::sin(geocentric_latitude_rad));
}

Gravity j2_gravity(const Constants& constants, double radius_ft, double geocentric_latitude_rad) {
  return j2_gravity(constants, radius_ft, std::sin(geocentric_latitude_rad),
                    std::cos(geocentric_latitude_rad));
}

double oblate_radius_ft(const Constants& constants, double sin_latitude, double cos_latitude) {
  return oblate_radius_ft(oblate_figure(constants), sin_latitude, cos_latitude);
}

OblateFigure oblate_figure(const Constants& constants) {
  OblateFigure figure;
  const double a = constants.earth_equatorial_radius_ft;
  figure.spherical = is_spherical_earth(constants);
  figure.equatorial_radius_ft = a;
  const double b =
      figure.spherical ? a : a * (constants.inverse_flattening - 1.0) / constants.inverse_flattening;
  figure.ab_ft2 = a * b;
  figure.b_squared_ft2 = b * b;
  figure.a_squared_ft2 = a * a;
  return figure;
}

double oblate_radius_ft(const OblateFigure& figure, double sin_latitude, double cos_latitude) {
  if (figure.spherical) return figure.equatorial_radius_ft;
  // a b / sqrt(b^2 cos^2 + a^2 sin^2), evaluated in the order the products were written before.
  return figure.ab_ft2 / std::sqrt(figure.b_squared_ft2 * cos_latitude * cos_latitude +
                                   figure.a_squared_ft2 * sin_latitude * sin_latitude);
}

Gravity j2_gravity(const Constants& constants, double radius_ft, double sin_lat, double cos_lat) {
  Gravity g;
  g.spherical_ft_s2 = constants.gravitational_parameter_ft3_s2 / (radius_ft * radius_ft);
  const double re_over_r = constants.earth_equatorial_radius_ft / radius_ft;
  const double j2_scaled = constants.j2 * re_over_r * re_over_r;
  // Sign of the J2/2 term follows the geopotential (reference README Sec. 6 item 2): the
  // printed minus in equation F contradicts the i_z component of F_G.
  g.radial_ft_s2 = g.spherical_ft_s2 * (1.0 + 0.5 * j2_scaled * (3.0 - 9.0 * sin_lat * sin_lat));
  g.north_ft_s2 = -3.0 * g.spherical_ft_s2 * j2_scaled * sin_lat * cos_lat;
  return g;
}

}  // namespace tolip
