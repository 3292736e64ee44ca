// Oblate Earth of manual Sec. 4: flattening 1/f (f = CT1(12) = 298.3), J2 gravity, the angle
// between geodetic and geocentric verticals, geodetic latitude for output.
//
// CT1(12) = 0 means a spherical Earth (no flattening; see docs/deck-format.md).
#pragma once

#include "tolip/core/constants.hpp"

namespace tolip {

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

// Altitude above the oblate surface, h = r - R_OBL(lambda).
double oblate_altitude_ft(const Constants& constants, double radius_ft, double geocentric_latitude_rad);

// Geodetic latitude for output (Purcell and Cowan): lambda_d = lambda_c + C1 sin 2 lambda_c
// + C2 sin 4 lambda_c, C1 = 3.372672e-3, C2 = -5.6873e-6.
double geodetic_from_geocentric_rad(double geocentric_latitude_rad);

// Inverse of geodetic_from_geocentric_rad (Newton iteration on the same series), for decks that
// give a launch site's geodetic latitude.
double geocentric_from_geodetic_rad(double geodetic_latitude_rad);

// Angle between the geodetic and geocentric verticals (Sec. 4):
// delta_lambda = (0.001638 + omega^2 r / (2 g)) sin 2 lambda, g = mu / r^2.
double delta_lambda_rad(const Constants& constants, double geocentric_latitude_rad, double radius_ft);

// J2 gravity (Sec. 4, derived from the geopotential; see docs/theory/equations-of-motion.md).
struct Gravity {
  double spherical_ft_s2 = 0.0;  // g = mu / r^2
  // Inward radial acceleration g (1 + J2/2 (re/r)^2 (3 - 9 sin^2 lambda)).
  double radial_ft_s2 = 0.0;
  // Northward acceleration -3 g J2 (re/r)^2 sin lambda cos lambda.
  double north_ft_s2 = 0.0;
};
Gravity j2_gravity(const Constants& constants, double radius_ft, double geocentric_latitude_rad);
Gravity j2_gravity(const Constants& constants, double radius_ft, double sin_latitude,
                   double cos_latitude);

}  // namespace tolip
