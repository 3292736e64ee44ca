// Deck vocabulary shared by both deck formats (deck_common.hpp).
#include "deck_common.hpp"

#include <cmath>

#include "field_description.hpp"
#include "tolip/core/constants.hpp"
#include "tolip_ground/capped_read.hpp"

namespace tolip::ground::deck_detail {

SegmentBoundary decode_coded_time(double coded) {
  SegmentBoundary boundary;
  const double stage = std::floor(coded / 100.0);
  // Beyond any int (or not a number): no stage; the time keeps the value for the message.
  if (!(std::fabs(stage) <= 1.0e6)) {
    boundary.stage = -1;
    boundary.time_from_ignition_s = coded;
    return boundary;
  }
  boundary.stage = static_cast<int>(stage);
  boundary.time_from_ignition_s = coded - 100.0 * stage;
  return boundary;
}

double coded_time(const SegmentBoundary& boundary) {
  return 100.0 * boundary.stage + boundary.time_from_ignition_s;
}

bool constraint_unit(int code, ConstraintUnit* unit) {
  static const ConstraintUnit kTerminal[] = {
      {"lb", 1.0, "payload"},
      {"ft_s", 1.0, "inertial velocity"},
      {"deg", kDegToRad, "inertial flight-path angle"},
      {"ft_s", 1.0, "V_I minus local circular velocity"},
      {"ft", 1.0, "radius"},
      {"ft_s", 1.0, "aerodynamic velocity"},
      {"deg", kDegToRad, "aerodynamic flight-path angle"},
      {"ft", 1.0, "altitude"},
      {"nmi", 1.0, "downrange distance"},
      {"ft2_s2", 1.0, "2E = V_I^2 - 2 mu / r"},
      {"deg", kDegToRad, "orbit inclination"},
      {"ft", 1.0, "perigee radius"},
      {"deg", kDegToRad, "longitude of the ascending node"},
      {"deg", kDegToRad, "argument of perigee"},
      {"btu_ft2", 1.0, "total heating"},
  };
  static const ConstraintUnit kStagePoint[] = {
      {"ft_s", 1.0, "aerodynamic velocity"},
      {"deg", kDegToRad, "aerodynamic flight-path angle"},
      {"ft", 1.0, "altitude"},
      {"nmi", 1.0, "downrange distance"},
      {"lb_ft2", 1.0, "dynamic pressure"},
  };
  static const ConstraintUnit kAsymptote[] = {
      {"ft_s", 1.0, "hyperbolic excess velocity"},
      {"deg", kDegToRad, "right ascension of the outward radial"},
      {"deg", kDegToRad, "declination of the outward radial"},
  };
  if (code >= 0 && code <= 14) {
    *unit = kTerminal[code];
    return true;
  }
  if (code >= 15 && code <= 99 && code % 10 >= 5) {
    *unit = kStagePoint[code % 10 - 5];
    return true;
  }
  if (code >= 100 && code <= 102) {
    *unit = kAsymptote[code - 100];
    return true;
  }
  return false;
}

const char* dispersion_name(int code) {
  const DispersionCodes* codes = find_dispersion(code);  // the one code -> data mapping
  return codes != nullptr ? codes->name : nullptr;
}

bool read_deck_file(const std::string& path, std::string* text, DeckError* error) {
  std::string reason;
  if (!read_file_capped(path, kMaxDeckFileBytes, "deck file", text, &reason)) {
    if (error != nullptr) {
      *error = DeckError{};
      error->file = path;
      error->message = reason;
    }
    return false;
  }
  return true;
}

}  // namespace tolip::ground::deck_detail
