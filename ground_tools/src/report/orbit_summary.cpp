// The orbit in engineering terms (tolip_ground/report.hpp; issue 10 part 5).
#include <cmath>
#include <limits>

#include "tolip/earth/earth_model.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {

const char* path_class_name(PathClass path) {
  switch (path) {
    case PathClass::kOrbit: return "orbit";
    case PathClass::kSuborbital: return "suborbital";
    case PathClass::kEscape: return "escape";
  }
  return "unknown";
}

OrbitSummary summarize_orbit(const Constants& constants, const OrbitElements& orbit) {
  OrbitSummary s;
  const double sin_latitude = std::sin(orbit.inclination_rad) * std::sin(orbit.argument_of_perigee_rad);
  s.perigee_latitude_rad = std::asin(std::fmax(-1.0, std::fmin(1.0, sin_latitude)));
  s.perigee_altitude_ft = orbit.perigee_radius_ft - oblate_radius_ft(constants, s.perigee_latitude_rad);
  s.apogee_altitude_ft = orbit.has_semi_major_axis
                             ? orbit.apogee_radius_ft - oblate_radius_ft(constants, -s.perigee_latitude_rad)
                             : std::numeric_limits<double>::quiet_NaN();
  if (!orbit.has_semi_major_axis) {
    s.path = PathClass::kEscape;
  } else if (s.perigee_altitude_ft < 0.0) {
    s.path = PathClass::kSuborbital;
  }
  s.perigee_in_atmosphere = s.perigee_altitude_ft >= 0.0 && s.perigee_altitude_ft < constants.haero_ft;
  return s;
}

}  // namespace tolip::ground
