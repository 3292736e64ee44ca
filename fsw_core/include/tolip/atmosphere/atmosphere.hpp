// The 1962 ARDC standard atmosphere exactly as tabulated in manual Sec. 19 (data blocks 11-14).
//
// Geopotential altitude H* = R h / (R + h), with R the Earth radius the caller passes (the local
// oblate radius on trajectories; CT1(3) for `tolip atmosphere`). Type I layers (L = 0) are
// isothermal-exponential, type II layers have a linear molecular temperature. The table's base
// densities are used as printed (they are not exactly continuous between layers). Derivatives
// follow Sec. 19: d()/dh is taken equal to d()/dH*.
#pragma once

#include "tolip/core/constants.hpp"
#include "tolip/core/status.hpp"

namespace tolip {

struct AtmosphereSample {
  double geopotential_altitude_ft = 0.0;  // H*, ft'
  double density_slug_ft3 = 0.0;          // rho
  double pressure_lbf_ft2 = 0.0;          // p = rho R* T_M
  double speed_of_sound_ft_s = 0.0;       // a = sqrt(1.4 R* T_M)
  double temperature_R = 0.0;             // T_M, molecular-scale temperature
  double ddensity_dh = 0.0;               // slug/ft^3 per ft
  double dpressure_dh = 0.0;              // lbf/ft^2 per ft
  double dspeed_of_sound_dh = 0.0;        // 1/s
};

// Below the first base altitude the first layer is extended; above the last, the last layer.
// Fails with kValueNotFinite for a non-finite altitude or radius, kAtmosphereRadiusNotPositive for a
// point at or below the Earth's centre (or a non-positive radius), kAtmosphereTemperatureNotPositive
// where a layer's temperature falls to zero, kOutputPointerNull for a null `out`.
Status evaluate_atmosphere(const AtmosphereTable& table, const Constants& constants, double altitude_ft,
                           double earth_radius_ft, AtmosphereSample* out);
// The same values (bit for bit) with the three derivatives left 0: what a flight needs.
Status evaluate_atmosphere_without_derivatives(const AtmosphereTable& table, const Constants& constants,
                                               double altitude_ft, double earth_radius_ft,
                                               AtmosphereSample* out);

// Checks a (possibly user-overridden) table: increasing base altitudes, positive temperatures
// and densities, finite values, no layer whose temperature reaches zero before the next base.
Status validate_atmosphere_table(const AtmosphereTable& table);

}  // namespace tolip
