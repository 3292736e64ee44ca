// Reports of the radar tracking (manual Sec. 18, Sec. 22 "Output format - Radar"): a listing page
// per station (time, slant range in yards, azimuth and elevation in degrees, degrees-minutes and
// mils; the IBM octal columns of the 1966 listing are left out), the JSON member `radar`
// (docs/cli.md) and the CSV of `tolip radar --csv`.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "tolip_ground/radar_run.hpp"

namespace tolip::ground {

namespace report_detail {
class Pager;
// The radar pages, continuing the pager's page numbers.
void write_radar_pages(Pager& pager, const RadarStep& step);
}  // namespace report_detail

// Yards and mils of the listing: 3 ft to the yard, 6400 mils to the circle.
inline constexpr double kFeetPerYard = 3.0;
inline constexpr double kMilsPerDegree = 6400.0 / 360.0;

// An angle in degrees as the listing's degrees and minutes, "-5 12.05" (sign, whole degrees,
// minutes to 0.01).
std::string degrees_minutes(double angle_deg);

nlohmann::ordered_json radar_json(const RadarStep& step);

// `tolip radar`: the radar pages alone (page titles from data blocks 1-3, CT1(8) lines per page;
// `listing` null: the nominal layout), and the JSON document of a case: program, version, deck,
// title, case_heading, the trajectory's status and status_message, and `radar`.
void write_radar_listing(std::ostream& out, const DeckListingOptions* listing, const RadarStep& step);
nlohmann::ordered_json radar_document(const DeckListingOptions& listing, const std::string& deck_path,
                                      Status trajectory_status, const RadarStep& step);

// One row per station and tracked point: station, time, stage, slant range (ft, yd), azimuth and
// elevation (deg, mils).
void write_radar_csv(std::ostream& out, const RadarStep& step);

}  // namespace tolip::ground
