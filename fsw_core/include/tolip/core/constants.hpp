// Nominal constants of data block 10 (CT1) and the atmosphere table of data blocks 11-14.
//
// Defaults are the manual's (Sec. 22, Sec. 19). Every field may be overridden per case by the
// deck. Units are the manual's internal units: ft, s, slug, lbf, rad, deg R.
#pragma once

namespace tolip {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kDegToRad = kPi / 180.0;  // exact; the deck's CT1(9) is only echoed
inline constexpr double kRadToDeg = 180.0 / kPi;

// Data block 10, CT1(1..13).
struct Constants {
  double earth_rotation_rate_rad_s = 7.29211e-5;        // CT1(1) omega
  double gravitational_parameter_ft3_s2 = 1.407735e16;  // CT1(2) mu
  double earth_equatorial_radius_ft = 20925696.0;       // CT1(3) r_e
  // CT1(4). Sec. 19 prints 1715.4827, an OCR error; 1716.4827 is the gas constant of air.
  double gas_constant_ft2_s2_R = 1716.4827;
  double g0_ft_s2 = 32.174;                    // CT1(5) weight-to-mass factor
  double sea_level_pressure_lbf_ft2 = 2116.2;  // CT1(6)
  double haero_ft = 250000.0;                  // CT1(7) aerodynamics bypassed above
  // CT1(8) lines per page and CT1(9) the printed degree-to-radian factor lay out the listing: the
  // ground tools keep them (DeckListingOptions), the core never reads them.
  double time_epsilon_s = 0.02;       // CT1(10) TIMEP
  double j2 = 1.0827e-3;              // CT1(11)
  double inverse_flattening = 298.3;  // CT1(12) f
  double ct1_13 = 1.0;                // CT1(13)
};

// Data blocks 11-14: the 1962 ARDC model at its eight base altitudes (Sec. 19).
inline constexpr int kAtmosphereLayers = 8;
struct AtmosphereTable {
  double base_geopotential_altitude_ft[kAtmosphereLayers] = {0.0,        36089.239,  82020.997,  154199.475,
                                                             173884.514, 259186.352, 295275.591, 344488.189};
  double base_molecular_temperature_R[kAtmosphereLayers] = {518.69,  389.988, 389.988, 508.788,
                                                            508.788, 298.188, 298.188, 406.188};
  double lapse_rate_R_per_ft[kAtmosphereLayers] = {-3.56616e-3, 0.0, 1.646592e-3, 0.0,
                                                   -2.46888e-3, 0.0, 2.19456e-3,  1.09728e-2};
  double base_density_slug_ft3[kAtmosphereLayers] = {2.3769e-3, 7.0547e-4, 7.7615e-5, 2.8829e-6,
                                                     1.3964e-6, 4.1123e-8, 4.2560e-9, 2.2243e-10};
};

}  // namespace tolip
