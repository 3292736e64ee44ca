// Oblate Earth of manual Sec. 4: flattening 1/f (f = CT1(12) = 298.3), J2 gravity, the angle
// between geodetic and geocentric verticals, geodetic latitude for output.
//
// The figure follows the deck: CT1(12) = 0 means a spherical Earth (no flattening; see
// docs/deck-format.md). The geodetic/geocentric conversions and the tilt of the launch vertical
// use the manual's printed 1966 numbers (the Purcell-Cowan series, 6 sigma = 0.001638) only when
// the deck's constants are the manual's ones they belong to, and the exact relations derived
// from the deck's constants otherwise (docs/theory/atmosphere-earth-orbit.md).
#pragma once

#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"

namespace tolip {

// The manual's J2 and flattening (the defaults of CT1(11), CT1(12) in tolip::Constants): the
// Earth its printed Purcell-Cowan series and figure-deflection term 6 sigma = 0.001638 belong to.
inline constexpr double kManualJ2 = 1.0827e-3;
inline constexpr double kManualInverseFlattening = 298.3;
static_assert(Constants{}.j2 == kManualJ2 && Constants{}.inverse_flattening == kManualInverseFlattening,
              "the manual's Earth is the default of data block 10");

// CT1(12) = 0: the Earth is a sphere of radius CT1(3).
bool is_spherical_earth(const Constants& constants);

// Polar semi-axis b = R_eq (f - 1) / f; R_eq for the sphere.
double polar_radius_ft(const Constants& constants);

// Surface radius at geocentric latitude lambda_c (Sec. 4 "Oblate Earth model"):
// eta = atan(f/(f-1) tan lambda_c), R = R_eq sqrt(cos^2 eta + ((f-1)/f)^2 sin^2 eta); R_eq for
// the sphere.
double oblate_radius_ft(const Constants& constants, double geocentric_latitude_rad);

// The same radius from the latitude's sine and cosine, in the ellipse's polar form
// R = a b / sqrt(b^2 cos^2 + a^2 sin^2) (b = a (f - 1) / f), which equals the manual's eta form
// exactly; used on the integration path where the sine and cosine are already at hand.
double oblate_radius_ft(const Constants& constants, double sin_latitude, double cos_latitude);

// The polar form's constant products, formed once per case (PreparedCase::oblate_figure) so that
// a model evaluation pays no division for b: the same radius bit for bit. A default (unprepared)
// figure gives NaN, never a plausible radius.
struct OblateFigure {
  bool spherical = false;
  double equatorial_radius_ft = 0.0;  // a
  double ab_ft2 = 0.0;                // a b
  double b_squared_ft2 = 0.0;
  double a_squared_ft2 = 0.0;
};
OblateFigure oblate_figure(const Constants& constants);
double oblate_radius_ft(const OblateFigure& figure, double sin_latitude, double cos_latitude);

// Altitude above the oblate surface, h = r - R_OBL(lambda).
double oblate_altitude_ft(const Constants& constants, double radius_ft, double geocentric_latitude_rad);

// True when the Purcell-Cowan series of Sec. 4 applies: the deck's flattening is the manual's
// 1/298.3 (the series' coefficients belong to that Earth).
bool uses_purcell_cowan_series(const Constants& constants);

// Geodetic latitude of the surface ellipsoid of the deck's flattening, exactly:
// tan lambda_d = (f / (f - 1))^2 tan lambda_c; lambda_d = lambda_c on the sphere.
double ellipsoid_geodetic_from_geocentric_rad(const Constants& constants, double geocentric_latitude_rad);
// Its exact inverse, tan lambda_c = ((f - 1) / f)^2 tan lambda_d.
double ellipsoid_geocentric_from_geodetic_rad(const Constants& constants, double geodetic_latitude_rad);

// Geodetic latitude for output. The manual's Earth (uses_purcell_cowan_series): Purcell and
// Cowan, lambda_d = lambda_c + C1 sin 2 lambda_c + C2 sin 4 lambda_c, C1 = 3.372672e-3,
// C2 = -5.6873e-6. Any other flattening: ellipsoid_geodetic_from_geocentric_rad (the identity on
// the sphere).
double geodetic_from_geocentric_rad(const Constants& constants, double geocentric_latitude_rad);

// Inverse of geodetic_from_geocentric_rad (Newton iteration on the series for the manual's Earth,
// the exact ellipsoid inverse otherwise), for decks that give a launch site's geodetic latitude.
double geocentric_from_geodetic_rad(const Constants& constants, double geodetic_latitude_rad);

// 6 sigma of Sec. 4, the oblate-figure part of the deflection of the vertical, g_lambda / g_r
// = 6 sigma sin 2 lambda. The gravity field of CT1(11) gives g_lambda / g_r = 3/2 J2 sin 2 lambda
// (r = r_e, the second term of g_r neglected, as the manual does), so 6 sigma = 3/2 J2; for the
// manual's J2 = 1.0827e-3 it is the printed 1.638e-3 (Melsen's 1958 figure, kept so that the
// manual's case is reproduced).
double figure_deflection_coefficient(const Constants& constants);

// Angle between the geodetic and geocentric verticals (Sec. 4):
// delta_lambda = (6 sigma + omega^2 r / (2 g)) sin 2 lambda, g = mu / r^2; 0 with J2 = 0 and
// omega = 0.
double delta_lambda_rad(const Constants& constants, double geocentric_latitude_rad, double radius_ft);

// Earth-fixed rectangular coordinates (x, y in the equator, x through Greenwich, z north) of a
// point given by geodetic latitude, longitude (east) and altitude above the deck's ellipsoid
// (Sec. 18): tan RA = ((f - 1) / f) tan lambda_d, z = R_eq (f - 1) / f sin RA + ALT sin lambda_d,
// xy = R_eq cos RA + ALT cos lambda_d. RA (the reduced latitude) by atan2, so the poles need no
// special case; on the sphere (CT1(12) = 0) RA = lambda_d.
Vector3 geodetic_to_earth_fixed_ft(const Constants& constants, double geodetic_latitude_rad,
                                   double longitude_rad, double altitude_ft);

// The same for a point given by geocentric radius, geocentric latitude and longitude (a
// trajectory point: r, lambda and the Earth-fixed longitude tau - omega t).
Vector3 geocentric_to_earth_fixed_ft(double radius_ft, double geocentric_latitude_rad, double longitude_rad);

// J2 gravity (Sec. 4, derived from the geopotential; see docs/theory/equations-of-motion.md).
struct Gravity {
  double spherical_ft_s2 = 0.0;  // g = mu / r^2
  // Inward radial acceleration g (1 + J2/2 (re/r)^2 (3 - 9 sin^2 lambda)).
  double radial_ft_s2 = 0.0;
  // Northward acceleration -3 g J2 (re/r)^2 sin lambda cos lambda.
  double north_ft_s2 = 0.0;
};
Gravity j2_gravity(const Constants& constants, double radius_ft, double geocentric_latitude_rad);
Gravity j2_gravity(const Constants& constants, double radius_ft, double sin_latitude, double cos_latitude);

}  // namespace tolip
