// The map figures of `tolip plot` (the ground track, the impact locus): longitude east on x,
// geodetic latitude north on y, drawn at true shape. What both maps do alike is written once here:
// the text of a place, the bounds of what is drawn and the framing of the map around them.
// Private to ground_tools/src/plot.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tolip_ground/plot.hpp"

namespace tolip::ground::plot_map {

// `value` with `decimals` digits after the point ("28.47").
inline std::string fixed(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// "28.47 N, 80.55 W": a place as a label gives it.
inline std::string place_text(double latitude_deg, double longitude_deg) {
  return fixed(std::fabs(latitude_deg), 2) + (latitude_deg < 0 ? " S, " : " N, ") +
         fixed(std::fabs(longitude_deg), 2) + (longitude_deg < 0 ? " W" : " E");
}

// The longitudes and latitudes a map must show; empty until a point on the Earth is added.
struct MapBounds {
  double lon_low_deg = HUGE_VAL;
  double lon_high_deg = -HUGE_VAL;
  double lat_low_deg = HUGE_VAL;
  double lat_high_deg = -HUGE_VAL;

  // Takes in a point; a gap (NaN) or a value off the Earth's grid is passed over.
  void extend(double lon_deg, double lat_deg) {
    if (!(std::fabs(lon_deg) <= 360.0) || !(std::fabs(lat_deg) <= 90.0)) return;
    lon_low_deg = std::min(lon_low_deg, lon_deg);
    lon_high_deg = std::max(lon_high_deg, lon_deg);
    lat_low_deg = std::min(lat_low_deg, lat_deg);
    lat_high_deg = std::max(lat_high_deg, lat_deg);
  }
  bool empty() const { return !(lon_low_deg <= lon_high_deg); }
};

// Sets the ranges and the height / width of `figure` to a map of true shape (a degree of longitude
// cos(latitude) as long as one of latitude) around `bounds`: padded on every side by the larger of
// 1 deg and pad_fraction times the larger span, so that what is drawn does not touch the frame,
// and the latitudes widened around the middle to a height at least 0.45 of the width, so that an
// east-west track does not sit in a thin strip. Nothing when `bounds` is empty.
inline void frame_map(MapBounds bounds, double pad_fraction, Figure* figure) {
  if (bounds.empty()) return;
  double lon_low = bounds.lon_low_deg, lon_high = bounds.lon_high_deg;
  double lat_low = bounds.lat_low_deg, lat_high = bounds.lat_high_deg;
  const double pad = std::max(1.0, pad_fraction * std::max(lon_high - lon_low, lat_high - lat_low));
  lon_low -= pad;
  lon_high += pad;
  lat_low -= pad;
  lat_high += pad;
  const double mid = 0.5 * (lat_low + lat_high) * 3.14159265358979323846 / 180.0;
  // Poleward of about 78 deg the true shape would be too narrow to read: at most 5 : 1.
  const double scale = std::max(0.2, std::cos(mid));
  const double wanted = 0.45 * (lon_high - lon_low) * scale;
  if (lat_high - lat_low < wanted) {
    const double grow = 0.5 * (wanted - (lat_high - lat_low));
    lat_low -= grow;
    lat_high += grow;
  }
  lat_low = std::max(lat_low, -90.0);
  lat_high = std::min(lat_high, 90.0);
  figure->x_min = lon_low;
  figure->x_max = lon_high;
  figure->y_min = lat_low;
  figure->y_max = lat_high;
  figure->aspect_ratio = (lat_high - lat_low) / ((lon_high - lon_low) * scale);
}

}  // namespace tolip::ground::plot_map
