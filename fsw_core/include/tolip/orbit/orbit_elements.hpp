// Inertial variables (subroutine INER), terminal orbit elements (Sec. 4), the hyperbolic
// asymptote elements of Addendum H, range equations and the stagnation heating rate (Sec. 13).
//
// Orbit elements assume a spherical Earth (as the manual says) and are valid for elliptic,
// parabolic and hyperbolic orbits: the perigee radius uses the form H / (mu/H + sqrt(2E + (mu/H)^2)),
// and the semi-major axis and period are reported only where they exist (2E < 0).
#pragma once

#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"

namespace tolip {

// Velocity relative to a non-rotating Earth (Sec. 4, INER).
struct InertialVelocity {
  double velocity_ft_s = 0.0;          // V_I
  double flight_path_angle_rad = 0.0;  // gamma_I
  double azimuth_rad = 0.0;            // psi_I, east of north
};
InertialVelocity inertial_velocity(const Constants& constants, const StateVector& state);
// The same with the sines and cosines of the state's gamma, psi and lambda already at hand (a
// trajectory point's, from its derivative evaluation): the same result, bit for bit.
InertialVelocity inertial_velocity(const Constants& constants, const StateVector& state, double sin_gamma,
                                   double cos_gamma, double sin_psi, double cos_psi, double cos_lambda);

enum class OrbitType : int { kElliptic, kParabolic, kHyperbolic };

struct OrbitElements {
  OrbitType type = OrbitType::kElliptic;
  InertialVelocity inertial;
  double twice_energy_ft2_s2 = 0.0;     // 2E = V_I^2 - 2 mu / r
  double angular_momentum_ft2_s = 0.0;  // H = r V_I cos gamma_I
  double perigee_radius_ft = 0.0;       // r_p
  double inclination_rad = 0.0;         // i = acos(cos lambda sin psi_I)
  double right_ascension_rad = 0.0;     // alpha_e of the vehicle position, [0, 2 pi)
  // Inertial longitude angle from the node, [0, 2 pi). The manual prints [0, pi], but a point
  // south of the equator before its ascending node lies at nu in (pi, 2 pi); the oracle agrees.
  double nu_rad = 0.0;
  double node_longitude_rad = 0.0;            // Omega_e = alpha_e - nu, [0, 2 pi)
  double in_plane_angle_from_node_rad = 0.0;  // beta, [0, 2 pi)
  double true_anomaly_rad = 0.0;              // zeta, [0, 2 pi)
  double argument_of_perigee_rad = 0.0;       // beta_p = beta - zeta, [0, 2 pi)
  double eccentricity = 0.0;                  // e = 1 - r_p / r_a (elliptic); from H and 2E otherwise
  bool has_semi_major_axis = false;           // only for 2E < 0
  double semi_major_axis_ft = 0.0;            // r_a = -mu / 2E
  double period_s = 0.0;                      // 2 pi r_a sqrt(r_a / mu)
  double apogee_radius_ft = 0.0;              // 2 r_a - r_p (elliptic only)
  // Addendum H, hyperbolic orbits only (2E > 0).
  bool has_asymptote = false;
  double hyperbolic_excess_velocity_ft_s = 0.0;  // v_H = sqrt(2E)
  double asymptote_right_ascension_rad = 0.0;    // alpha_eH = Omega_e + nu_H, [0, 2 pi)
  double asymptote_declination_rad = 0.0;        // delta_eH = asin(sin i sin beta_H)
};

// Right ascension of the inertial x axis (Greenwich at lift-off), [0, 2 pi): the tau-free part
// of alpha_e, 99.659967 + 0.98564743 tG + 360 frac(tG) deg (Herget, as printed in Sec. 4).
double launch_greenwich_right_ascension_rad(double launch_space_age_date_days);

// Elements of the state at time t from launch. launch_space_age_date_days is DA5(2); the right
// ascension is alpha_e = 99.659967 + 0.98564743 tG + 360 frac(tG) + tau (deg), tau inertial.
// Fails with kNonFiniteState, kValueNotFinite (date) or kZeroVelocity (V_I below 1e-6 ft/s, or r <= 0).
Status compute_orbit_elements(const Constants& constants, const StateVector& state,
                              double launch_space_age_date_days, OrbitElements* out);

// Great-circle central angle between the launch point and the vehicle (Sec. 4 range equations),
// both given by geocentric latitude and EARTH-FIXED longitude.
double downrange_angle_rad(double launch_latitude_rad, double launch_longitude_rad, double latitude_rad,
                           double longitude_rad);
// The same from the sines and cosines of both latitudes and the longitude difference
// longitude - launch longitude (a flight's launch point is fixed, its point's latitude is at hand).
double downrange_angle_rad(double sin_launch_latitude, double cos_launch_latitude, double sin_latitude,
                           double cos_latitude, double longitude_difference_rad);
// Small-angle crossrange of a dispersed point relative to the nominal point and azimuth psi_n
// (positive to the right looking downrange), as a central angle.
double crossrange_angle_rad(double nominal_latitude_rad, double nominal_longitude_rad,
                            double nominal_azimuth_rad, double dispersed_latitude_rad,
                            double dispersed_longitude_rad);
// 60 n.mi. per degree of arc, as the manual converts.
inline constexpr double kNauticalMilesPerRadian = 60.0 * 180.0 / kPi;

// Stagnation heating rate (Sec. 13), Btu/ft^2/s:
// Qdot = 20800 / sqrt(R_nose) sqrt(rho / rho_SL) (V / 10000)^3.25.
// Precondition: nose radius and sea-level density positive, density and velocity non-negative
// (stagnation_heating_rate_checked enforces it).
double stagnation_heating_rate(double nose_radius_ft, double density_slug_ft3,
                               double sea_level_density_slug_ft3, double velocity_ft_s);
// The same with its inputs checked: kValueNotFinite, kNoseRadiusNotPositive,
// kSeaLevelDensityNotPositive, or kHeatingStateNegative (a negative density or velocity).
Status stagnation_heating_rate_checked(double nose_radius_ft, double density_slug_ft3,
                                       double sea_level_density_slug_ft3, double velocity_ft_s,
                                       double* heating_rate_btu_ft2_s);

}  // namespace tolip
