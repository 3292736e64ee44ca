// The Sec. 15 quantities as every dispersion report names them (private to ground_tools/src/report):
// the staging variables and orbit elements of `tolip dispersions` and of the `dispersion` member of
// `tolip optimize`, and the same quantities' statistics in `tolip montecarlo`. One table, so a
// listing label, a JSON / CSV key or a unit conversion is written once for all of them
// (docs/cli.md documents the keys).
#pragma once

#include "tolip/core/constants.hpp"
#include "tolip/dispersion/dispersion.hpp"

namespace tolip::ground::report_detail {

struct DispersionQuantity {
  const char* label;  // listing
  const char* key;    // JSON / CSV
  double scale;       // core unit -> reported unit (angles in degrees)
  int decimals;       // fixed decimals in a listing
};

// Indexed by StagingVariable.
inline constexpr DispersionQuantity kStagingQuantities[kStagingVariables] = {
    {"ALTITUDE FT", "altitude_ft", 1.0, 1},
    {"VELOCITY FT/S", "velocity_ft_s", 1.0, 2},
    {"GAMMA DEG", "flight_path_angle_deg", kRadToDeg, 4},
    {"DOWNRANGE NMI", "downrange_nmi", 1.0, 3},
    {"CROSSRANGE NMI", "crossrange_nmi", 1.0, 3},
};

// Indexed as DispersedTrajectory::orbit: TWOE, EH, RP, EYE, BETAP, OMEGAE.
inline constexpr DispersionQuantity kOrbitQuantities[kOrbitDispersionElements] = {
    {"TWOE FT2/S2", "twoe_ft2_s2", 1.0, 0},
    {"EH FT2/S", "eh_ft2_s", 1.0, 0},
    {"RP FT", "rp_ft", 1.0, 1},
    {"EYE DEG", "eye_deg", kRadToDeg, 4},
    {"BETAP DEG", "betap_deg", kRadToDeg, 4},
    {"OMEGAE DEG", "omegae_deg", kRadToDeg, 4},
};

}  // namespace tolip::ground::report_detail
