// Reports of the radar tracking (tolip_ground/radar_report.hpp).
#include "tolip_ground/radar_report.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "case_document.hpp"
#include "listing_pager.hpp"
#include "number_format.hpp"
#include "tolip/core/constants.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;
using report_detail::json_number;

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

// JSON has no NaN: a non-finite value is null (the core stores none; this is a guard).
std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

std::string station_label(const RadarStation& station) {
  return station.name.empty() ? station.id : station.id + "  " + station.name;
}

}  // namespace

std::string degrees_minutes(double angle_deg) {
  if (!std::isfinite(angle_deg)) return "nan";
  // Rounded to 0.01 minute first, so 59.999 minutes carries into the degrees.
  const double total_hundredths = std::round(std::fabs(angle_deg) * 6000.0);
  const double whole_deg = std::floor(total_hundredths / 6000.0);
  const double minutes = (total_hundredths - whole_deg * 6000.0) / 100.0;
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%s%.0f %05.2f", angle_deg < 0.0 && total_hundredths > 0.0 ? "-" : "",
                whole_deg, minutes);
  return buffer;
}

namespace report_detail {

void write_radar_pages(Pager& pager, const RadarStep& step) {
  if (step.outcome == StepOutcome::kNotRequested) return;
  if (step.outcome == StepOutcome::kSkipped || !ok(step.status) || step.result == nullptr) {
    pager.new_page("RADAR TRACKING", false);
    pager.emit(" RADAR TRACKING COORDINATES (SEC. 18, DATA BLOCK 41) NOT COMPUTED: " +
               std::string(status_name(step.status)) + ": " + status_message(step.status));
    if (step.result != nullptr && step.result->failed_station >= 0 &&
        step.result->failed_station < static_cast<int>(step.deck_stations.size())) {
      pager.emit(" STATION " + station_label(step.deck_stations[step.result->failed_station]));
    }
    return;
  }
  const RadarResult& r = *step.result;
  for (int s = 0; s < r.station_count; ++s) {
    const RadarStation& station = step.deck_stations[static_cast<std::size_t>(s)];
    const std::string section = "RADAR " + station.id;
    // Every page of a station starts with the station and the column headings.
    const auto page_start = [&] {
      pager.new_page(section, false);
      pager.emit(" RADAR TRACKING COORDINATES (SEC. 18)   STATION " + station_label(station));
      pager.emit(" GEODETIC LATITUDE " + format("%12.6f", station.geodetic_latitude_rad * kRadToDeg) +
                 " DEG   LONGITUDE " + format("%12.6f", station.longitude_rad * kRadToDeg) +
                 " DEG   ALTITUDE " + format("%10.1f", station.altitude_ft) + " FT");
      pager.emit(" THE " + upper(step.trajectory_kind) +
                 " TRAJECTORY FROM LAUNCH THROUGH THE LAST BURNOUT (THE IBM OCTAL COLUMNS ARE LEFT OUT)");
      pager.emit("");
      pager.emit(
          "      TIME  STAGE          RANGE     ---------- AZIMUTH ----------    --------- ELEVATION "
          "---------");
      pager.emit(
          "       SEC                   YDS          DEG    DEG MIN       MILS         DEG    DEG MIN       "
          "MILS");
    };
    page_start();
    for (int i = 0; i < r.point_count; ++i) {
      if (!pager.fits(1)) page_start();
      const LookAngles& look = r.look[s][i];
      const double az_deg = look.azimuth_rad * kRadToDeg;
      const double el_deg = look.elevation_rad * kRadToDeg;
      char line[200];
      std::snprintf(line, sizeof line, "%10.3f %6d %14.1f %12.5f %10s %10.2f %11.5f %10s %10.2f", r.time_s[i],
                    r.stage_code[i], look.slant_range_ft / kFeetPerYard, az_deg,
                    degrees_minutes(az_deg).c_str(), az_deg * kMilsPerDegree, el_deg,
                    degrees_minutes(el_deg).c_str(), el_deg * kMilsPerDegree);
      pager.emit(line);
    }
  }
}

}  // namespace report_detail

json radar_json(const RadarStep& step) {
  json radar = json::object();
  radar["computed"] = step.outcome == StepOutcome::kRun && ok(step.status) && step.result != nullptr;
  radar["status"] = status_name(step.status);
  radar["status_message"] = status_message(step.status);
  radar["trajectory"] = step.trajectory_kind;
  json stations = json::array();
  const RadarResult* r = radar["computed"].get<bool>() ? step.result.get() : nullptr;
  for (std::size_t s = 0; s < step.deck_stations.size(); ++s) {
    const RadarStation& deck = step.deck_stations[s];
    json station = json::object();
    station["id"] = deck.id;
    station["name"] = deck.name;
    station["geodetic_latitude_deg"] = json_number(deck.geodetic_latitude_rad * kRadToDeg);
    station["longitude_deg"] = json_number(deck.longitude_rad * kRadToDeg);
    station["altitude_ft"] = json_number(deck.altitude_ft);
    json points = json::array();
    if (r != nullptr && static_cast<int>(s) < r->station_count) {
      for (int i = 0; i < r->point_count; ++i) {
        const LookAngles& look = r->look[s][i];
        json point = json::object();
        point["time_s"] = json_number(r->time_s[i]);
        point["stage"] = r->stage_code[i];
        point["slant_range_ft"] = json_number(look.slant_range_ft);
        point["slant_range_yd"] = json_number(look.slant_range_ft / kFeetPerYard);
        point["azimuth_deg"] = json_number(look.azimuth_rad * kRadToDeg);
        point["azimuth_mils"] = json_number(look.azimuth_rad * kRadToDeg * kMilsPerDegree);
        point["elevation_deg"] = json_number(look.elevation_rad * kRadToDeg);
        point["elevation_mils"] = json_number(look.elevation_rad * kRadToDeg * kMilsPerDegree);
        points.push_back(std::move(point));
      }
    }
    station["points"] = std::move(points);
    stations.push_back(std::move(station));
  }
  radar["stations"] = std::move(stations);
  return radar;
}

void write_radar_listing(std::ostream& out, const DeckListingOptions* listing, const RadarStep& step) {
  report_detail::Pager pager(out, listing);
  report_detail::write_radar_pages(pager, step);
}

json radar_document(const DeckListingOptions& listing, const std::string& deck_path, Status trajectory_status,
                    const RadarStep& step) {
  json document = report_detail::case_document(deck_path, listing, trajectory_status);
  document["radar"] = radar_json(step);
  return document;
}

void write_radar_csv(std::ostream& out, const RadarStep& step) {
  out << "station,time_s,stage,slant_range_ft,slant_range_yd,azimuth_deg,azimuth_mils,elevation_deg,"
         "elevation_mils\n";
  if (step.outcome != StepOutcome::kRun || !ok(step.status) || step.result == nullptr) return;
  const RadarResult& r = *step.result;
  char line[256];
  for (int s = 0; s < r.station_count; ++s) {
    for (int i = 0; i < r.point_count; ++i) {
      const LookAngles& look = r.look[s][i];
      const double az_deg = look.azimuth_rad * kRadToDeg, el_deg = look.elevation_rad * kRadToDeg;
      std::snprintf(line, sizeof line, ",%.17g,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", r.time_s[i],
                    r.stage_code[i], look.slant_range_ft, look.slant_range_ft / kFeetPerYard, az_deg,
                    az_deg * kMilsPerDegree, el_deg, el_deg * kMilsPerDegree);
      out << step.deck_stations[static_cast<std::size_t>(s)].id << line;
    }
  }
}

}  // namespace tolip::ground
