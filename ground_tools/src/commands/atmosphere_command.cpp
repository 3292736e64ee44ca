// `tolip atmosphere`: the Sec. 19 ARDC 1962 atmosphere at one geometric altitude.
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {
namespace {

std::string line(const char* label, const char* pattern, double value, const char* unit) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%-24s", label);
  std::string text = buffer;
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return text + buffer + "  " + unit + "\n";
}

}  // namespace

int run_atmosphere_command(const AtmosphereCommandOptions& options, std::ostream& out, std::ostream& err) {
  const Constants constants;                                      // data block 10 defaults
  const AtmosphereTable table;                                    // data blocks 11-14 defaults (Sec. 19)
  const double radius_ft = constants.earth_equatorial_radius_ft;  // CT1(3)
  const double altitude_ft = options.altitude_ft;
  if (!std::isfinite(altitude_ft)) {
    err << "tolip: --altitude-ft must be a finite number of feet\n";
    return kExitBadInput;
  }
  if (!(altitude_ft >= kAtmosphereLowestAltitude_ft && altitude_ft <= kAtmosphereHighestAltitude_ft)) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "%.15g ft is outside the model's range: expected %.15g <= altitude <= %.15g", altitude_ft,
                  kAtmosphereLowestAltitude_ft, kAtmosphereHighestAltitude_ft);
    err << "tolip: --altitude-ft = " << text
        << " ft (the 1962 standard atmosphere starts at -5 km; above 1,000,000 ft the extended last layer"
        << " of Sec. 19 describes no atmosphere)\n";
    return kExitBadInput;
  }

  AtmosphereSample sample;
  const Status status = evaluate_atmosphere(table, constants, altitude_ft, radius_ft, &sample);
  if (!ok(status)) {
    err << "tolip: " << status_name(status) << ": " << status_message(status) << '\n';
    return kExitFailure;
  }

  if (options.json) {
    nlohmann::ordered_json document = {
        {"altitude_ft", altitude_ft},
        {"geopotential_altitude_ft", sample.geopotential_altitude_ft},
        {"earth_radius_ft", radius_ft},
        {"density_slug_ft3", sample.density_slug_ft3},
        {"pressure_lbf_ft2", sample.pressure_lbf_ft2},
        {"speed_of_sound_ft_s", sample.speed_of_sound_ft_s},
        {"temperature_R", sample.temperature_R},
    };
    // A non-finite result (never expected) becomes null rather than invalid JSON.
    for (auto& item : document.items()) {
      if (!std::isfinite(item.value().get<double>())) item.value() = nullptr;
    }
    out << dump_json(document);
    return kExitOk;
  }

  out << "1962 ARDC STANDARD ATMOSPHERE (TOLIP SEC. 19), EARTH RADIUS CT1(3) = "
      << std::to_string(static_cast<long long>(radius_ft)) << " FT\n";
  out << line("ALTITUDE", "%18.3f", altitude_ft, "FT");
  out << line("GEOPOTENTIAL ALTITUDE", "%18.3f", sample.geopotential_altitude_ft, "FT'");
  out << line("DENSITY", "%18.8E", sample.density_slug_ft3, "SLUG/FT3");
  out << line("PRESSURE", "%18.8E", sample.pressure_lbf_ft2, "LB/FT2");
  out << line("SPEED OF SOUND", "%18.4f", sample.speed_of_sound_ft_s, "FT/SEC");
  out << line("TEMPERATURE", "%18.4f", sample.temperature_R, "DEG R");
  return kExitOk;
}

}  // namespace tolip::ground
