// 1962 ARDC atmosphere of manual Sec. 19 (see docs/theory/atmosphere-earth-orbit.md).
#include "tolip/atmosphere/atmosphere.hpp"

#include <cmath>

namespace tolip {

namespace {

// Index of the layer that holds H*: the last base at or below it. Below the first base the first
// layer is extended (Sec. 19 gives no layer under sea level); above the last base the last layer.
int layer_index(const AtmosphereTable& table, double geopotential_altitude_ft) {
  int index = 0;
  for (int b = 1; b < kAtmosphereLayers; ++b) {
    if (geopotential_altitude_ft >= table.base_geopotential_altitude_ft[b]) index = b;
  }
  return index;
}

bool all_finite(const AtmosphereSample& s, bool with_derivatives) {
  const bool values = std::isfinite(s.geopotential_altitude_ft) && std::isfinite(s.density_slug_ft3) &&
                      std::isfinite(s.pressure_lbf_ft2) && std::isfinite(s.speed_of_sound_ft_s) &&
                      std::isfinite(s.temperature_R);
  return values && (!with_derivatives || (std::isfinite(s.ddensity_dh) && std::isfinite(s.dpressure_dh) &&
                                          std::isfinite(s.dspeed_of_sound_dh)));
}

// The one evaluation; the derivatives (the q-bar and heating constraints' partials need them, a
// flight does not) only when asked for.
template <bool kWithDerivatives>
Status evaluate(const AtmosphereTable& table, const Constants& constants, double altitude_ft,
                double earth_radius_ft, AtmosphereSample* out) {
  if (out == nullptr) return Status::kOutputPointerNull;
  if (!std::isfinite(altitude_ft) || !std::isfinite(earth_radius_ft)) return Status::kValueNotFinite;
  const double radius_sum_ft = earth_radius_ft + altitude_ft;
  if (!(radius_sum_ft > 0.0) || !(earth_radius_ft > 0.0)) return Status::kAtmosphereRadiusNotPositive;

  const double r_gas = constants.gas_constant_ft2_s2_R;
  const double g0 = constants.g0_ft_s2;

  AtmosphereSample s;
  // R h / (R + h) written so that a huge R (1e30, "no curvature") returns h exactly, keeping a
  // base altitude in its own layer.
  s.geopotential_altitude_ft = altitude_ft / (1.0 + altitude_ft / earth_radius_ft);
  const int b = layer_index(table, s.geopotential_altitude_ft);
  const double base_altitude_ft = table.base_geopotential_altitude_ft[b];
  const double base_temperature_R = table.base_molecular_temperature_R[b];
  const double lapse_R_per_ft = table.lapse_rate_R_per_ft[b];
  const double base_density = table.base_density_slug_ft3[b];
  const double above_base_ft = s.geopotential_altitude_ft - base_altitude_ft;

  if (lapse_R_per_ft == 0.0) {
    // Type I: isothermal, density falls exponentially with scale height R* T_b / g0.
    s.temperature_R = base_temperature_R;
    s.density_slug_ft3 = base_density * std::exp(-g0 * above_base_ft / (r_gas * base_temperature_R));
    s.pressure_lbf_ft2 = s.density_slug_ft3 * r_gas * base_temperature_R;
    s.speed_of_sound_ft_s = std::sqrt(1.4 * r_gas * base_temperature_R);
    if (kWithDerivatives) {
      s.ddensity_dh = -s.density_slug_ft3 * g0 / (r_gas * base_temperature_R);
      s.dpressure_dh = r_gas * base_temperature_R * s.ddensity_dh;
      s.dspeed_of_sound_dh = 0.0;
    }
  } else {
    // Type II: linear T_M. The scanned density formula lost its exponent; the hydrostatic
    // equation with p = rho R* T_M gives rho = rho_b X^-(1 + g0 / (R* L)), X = T_M / T_b.
    const double temperature_ratio = 1.0 + lapse_R_per_ft * above_base_ft / base_temperature_R;
    // An extended layer (or a user table) can drive T_M through zero: no atmosphere exists there.
    if (!(temperature_ratio > 0.0)) return Status::kAtmosphereTemperatureNotPositive;
    const double exponent = 1.0 + g0 / (r_gas * lapse_R_per_ft);
    s.temperature_R = base_temperature_R + lapse_R_per_ft * above_base_ft;
    s.density_slug_ft3 = base_density * std::pow(temperature_ratio, -exponent);
    s.pressure_lbf_ft2 = s.density_slug_ft3 * r_gas * s.temperature_R;
    s.speed_of_sound_ft_s = std::sqrt(1.4 * r_gas * s.temperature_R);
    if (kWithDerivatives) {
      s.ddensity_dh =
          -s.density_slug_ft3 * exponent * (lapse_R_per_ft / base_temperature_R) / temperature_ratio;
      s.dpressure_dh = r_gas * (s.temperature_R * s.ddensity_dh + s.density_slug_ft3 * lapse_R_per_ft);
      s.dspeed_of_sound_dh = 0.7 * r_gas * lapse_R_per_ft / s.speed_of_sound_ft_s;
    }
  }

  if (!all_finite(s, kWithDerivatives)) return Status::kValueNotFinite;
  *out = s;
  return Status::kOk;
}

}  // namespace

Status evaluate_atmosphere(const AtmosphereTable& table, const Constants& constants, double altitude_ft,
                           double earth_radius_ft, AtmosphereSample* out) {
  return evaluate<true>(table, constants, altitude_ft, earth_radius_ft, out);
}

Status evaluate_atmosphere_without_derivatives(const AtmosphereTable& table, const Constants& constants,
                                               double altitude_ft, double earth_radius_ft,
                                               AtmosphereSample* out) {
  return evaluate<false>(table, constants, altitude_ft, earth_radius_ft, out);
}

Status validate_atmosphere_table(const AtmosphereTable& table) {
  // Every word finite first: a layer's thickness reads the next layer's base, whose NaN is a
  // value that is not finite, not a table out of order.
  for (int b = 0; b < kAtmosphereLayers; ++b) {
    if (!std::isfinite(table.base_geopotential_altitude_ft[b]) ||
        !std::isfinite(table.base_molecular_temperature_R[b]) ||
        !std::isfinite(table.lapse_rate_R_per_ft[b]) || !std::isfinite(table.base_density_slug_ft3[b])) {
      return Status::kValueNotFinite;
    }
  }
  for (int b = 0; b < kAtmosphereLayers; ++b) {
    if (!(table.base_molecular_temperature_R[b] > 0.0) || !(table.base_density_slug_ft3[b] > 0.0)) {
      return Status::kAtmosphereTableInvalid;
    }
    if (b + 1 < kAtmosphereLayers) {
      const double thickness_ft =
          table.base_geopotential_altitude_ft[b + 1] - table.base_geopotential_altitude_ft[b];
      if (!(thickness_ft > 0.0)) return Status::kAtmosphereTableInvalid;
      const double top_temperature_R =
          table.base_molecular_temperature_R[b] + table.lapse_rate_R_per_ft[b] * thickness_ft;
      if (!(top_temperature_R > 0.0)) return Status::kAtmosphereTableInvalid;
    }
  }
  return Status::kOk;
}

}  // namespace tolip
