// The plots of `tolip plot` (plot.hpp): each a small function of one result document, keyed on
// the member it needs. Field names and units are those of docs/cli.md (simulate/optimize --json).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "impact_plot.hpp"
#include "plot_json.hpp"
#include "plot_map.hpp"
#include "tolip/optimizer/constraint_set.hpp"
#include "tolip_ground/plot.hpp"
#include "tolip_ground/units.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::json;

constexpr double kGap = std::numeric_limits<double>::quiet_NaN();

// ---- reading the document, every fault named by its field path ----------------------------------

using plot_json::fail;
// The member `key` of an object, or null when absent.
const json* member(const json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// A number; null gives a gap (JSON has no NaN; the reports write null for a non-finite value).
double number_or_gap(const json& value, const std::string& field) {
  if (value.is_null()) return kGap;
  if (!value.is_number()) fail(field, "a number or null", value);
  return value.get<double>();
}

double required_number(const json& object, const char* key, const std::string& field) {
  const json* value = member(object, key);
  if (value == nullptr) throw PlotDataError(field + ": no member '" + key + "'");
  return number_or_gap(*value, field + "." + key);
}

// The array member `key`, or null when absent; anything but an array is an error.
const json* array_member(const json& document, const char* key) {
  const json* value = member(document, key);
  if (value == nullptr || value->is_null()) return nullptr;
  if (!value->is_array()) fail(key, "an array", *value);
  return value;
}

// Two columns of a curve.
struct Columns {
  std::vector<double> x;
  std::vector<double> y;
};

PlotSeries lines(std::string title, Columns columns) {
  PlotSeries series;
  series.title = std::move(title);
  series.x = std::move(columns.x);
  series.y = std::move(columns.y);
  return series;
}

// An optimize document carries the optimizer's results; its trajectory is the optimum.
bool is_optimization(const json& document) { return member(document, "iterations") != nullptr; }

Figure make_figure(std::string name, std::string title, std::string x_label, std::string y_label) {
  Figure figure;
  figure.name = std::move(name);
  figure.title = std::move(title);
  figure.x_label = std::move(x_label);
  figure.y_label = std::move(y_label);
  return figure;
}

using plot_map::fixed;

// A boolean member of a trajectory point.
bool required_flag(const json& object, const char* key, const std::string& field) {
  const json* value = member(object, key);
  if (value == nullptr) throw PlotDataError(field + ": no member '" + key + "'");
  if (!value->is_boolean()) fail(field + "." + key, "true or false", *value);
  return value->get<bool>();
}

// An integer member, or `fallback` when absent or null.
long integer_or(const json& object, const char* key, const std::string& field, long fallback) {
  const json* value = member(object, key);
  if (value == nullptr || value->is_null()) return fallback;
  if (!value->is_number_integer()) fail(field + "." + key, "an integer or null", *value);
  return value->get<long>();
}

// One column of trajectory[] (the document's trajectory is checked non-empty by the caller).
std::vector<double> column(const json& points, const char* key) {
  std::vector<double> values;
  values.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string field = "trajectory[" + std::to_string(i) + "]";
    const json& point = points[i];
    if (!point.is_object()) fail(field, "an object", point);
    values.push_back(required_number(point, key, field));
  }
  return values;
}

// A stage of stage_events[].
struct StageEvent {
  long stage = 0;
  bool powered = false;
  double start_s = kGap;
  double end_s = kGap;
  long first_point = -1;  // -1: null or outside the points flown
  long last_point = -1;
};

std::vector<StageEvent> stage_events(const json& document, std::size_t point_count) {
  std::vector<StageEvent> events;
  const json* list = array_member(document, "stage_events");
  if (list == nullptr) return events;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string field = "stage_events[" + std::to_string(i) + "]";
    const json& event = (*list)[i];
    if (!event.is_object()) fail(field, "an object", event);
    StageEvent parsed;
    parsed.stage = integer_or(event, "stage", field, 0);
    const json* kind = member(event, "kind");
    if (kind != nullptr && !kind->is_string()) fail(field + ".kind", "a string", *kind);
    parsed.powered =
        kind != nullptr ? kind->get<std::string>() == "powered" : parsed.stage >= 1 && parsed.stage <= 5;
    if (member(event, "start_time_s") != nullptr)
      parsed.start_s = required_number(event, "start_time_s", field);
    if (member(event, "end_time_s") != nullptr) parsed.end_s = required_number(event, "end_time_s", field);
    const auto index = [&](const char* key) {
      const long value = integer_or(event, key, field, -1);
      return value >= 0 && static_cast<std::size_t>(value) < point_count ? value : -1;
    };
    parsed.first_point = index("first_point");
    parsed.last_point = index("last_point");
    events.push_back(parsed);
  }
  return events;
}

// What the figures of one document share: its trajectory's columns, the staging, the max-q point
// and the ascent window, each read once.
struct Flight {
  const json* points = nullptr;
  std::vector<double> time;
  std::vector<StageEvent> events;
  std::size_t max_q = 0;  // index of the largest dynamic pressure
  bool has_max_q = false;
  double ascent_end_s = kGap;  // the burnout before the last coast; NaN: no such coast
  long ascent_stage = 0;       // the stage burning out there
};

// The flight of a document, or nullopt without a trajectory.
std::optional<Flight> flight_of(const json& document) {
  const json* points = array_member(document, "trajectory");
  if (points == nullptr || points->empty()) return std::nullopt;
  Flight flight;
  flight.points = points;
  flight.time = column(*points, "time_s");
  flight.events = stage_events(document, points->size());
  const std::vector<double> q = column(*points, "dynamic_pressure_lbf_ft2");
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (std::fabs(q[i]) <= kMaxPlotMagnitude && std::isfinite(flight.time[i]) &&
        (!flight.has_max_q || q[i] > q[flight.max_q])) {
      flight.max_q = i;
      flight.has_max_q = true;
    }
  }
  // The ascent: through the burnout of the powered stage that the last coast before a powered
  // stage follows (Scout: stage 3, before the long coast to the stage-4 ignition).
  for (std::size_t i = 1; i + 1 < flight.events.size(); ++i) {
    const StageEvent& coast = flight.events[i];
    if (!coast.powered && flight.events[i + 1].powered && flight.events[i - 1].powered) {
      flight.ascent_end_s = flight.events[i - 1].end_s;
      flight.ascent_stage = flight.events[i - 1].stage;
    }
  }
  return flight;
}

std::string stage_name(long stage) { return "S" + std::to_string(stage); }

// Ignition and burnout of every powered stage as vertical markers against time. The first stage
// ignites at lift-off: the first point, which belongs to it (its stage event starts after the
// lift-off step).
std::vector<XMarker> staging_markers(const Flight& flight) {
  std::vector<XMarker> markers;
  bool first_powered = true;
  for (const StageEvent& event : flight.events) {
    if (!event.powered) continue;
    double ignition = event.start_s;
    if (first_powered && std::isfinite(flight.time.front()))
      ignition = std::min(ignition, flight.time.front());
    first_powered = false;
    if (std::isfinite(ignition)) markers.push_back({ignition, stage_name(event.stage) + " ign", 0});
    if (std::isfinite(event.end_s)) markers.push_back({event.end_s, stage_name(event.stage) + " bo", 0});
  }
  return markers;
}

// The same events as labelled points of a curve y(x) drawn against another column (altitude vs
// downrange): the stage's first and last point.
std::vector<PointMarker> staging_points(const Flight& flight, const std::vector<double>& x,
                                        const std::vector<double>& y) {
  std::vector<PointMarker> points;
  bool first_powered = true;
  for (const StageEvent& event : flight.events) {
    if (!event.powered) continue;
    const long ignition = first_powered ? 0 : event.first_point;
    first_powered = false;
    if (ignition > 0)  // the first powered stage ignites at the pad point: no marker there
      points.push_back({x[ignition], y[ignition], stage_name(event.stage) + " ign", 0});
    if (event.last_point >= 0) {
      points.push_back({x[event.last_point], y[event.last_point], stage_name(event.stage) + " bo", 0});
    }
  }
  return points;
}

// The zero-alpha window: the integration steps that start at a point flagged alpha_zero.
std::vector<XBand> alpha_zero_bands(const Flight& flight) {
  std::vector<XBand> bands;
  const json& points = *flight.points;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    if (!required_flag(points[i], "alpha_zero", "trajectory[" + std::to_string(i) + "]")) continue;
    const double from = flight.time[i];
    const double to = flight.time[i + 1];
    if (!std::isfinite(from) || !std::isfinite(to)) continue;
    if (!bands.empty() && bands.back().to >= from) {
      bands.back().to = std::max(bands.back().to, to);
    } else {
      bands.push_back({from, to});
    }
  }
  return bands;
}

constexpr const char* kStagingTitle = "staging: Sn ign = stage n ignition, Sn bo = burnout";
constexpr const char* kZeroAlphaTitle = "zero-alpha window (theta set for alpha = 0)";

std::string max_q_label(const Flight& flight) {
  const double q = (*flight.points)[flight.max_q]["dynamic_pressure_lbf_ft2"].get<double>();
  return "max q " + fixed(q, 0) + " lbf/ft^2 at " + fixed(flight.time[flight.max_q], 1) + " s";
}

// A time figure over the ascent (NaN end: the whole flight): the points after it left out.
void limit_to_ascent(const Flight& flight, Figure* figure) {
  if (!std::isfinite(flight.ascent_end_s)) return;
  figure->x_min = std::isfinite(flight.time.front()) ? flight.time.front() : kGap;
  figure->x_max = flight.ascent_end_s;
  figure->title += ", ascent through " + stage_name(flight.ascent_stage) + " burnout";
}

// A time figure with the staging markers, and optionally the zero-alpha window.
Figure time_figure(const Flight& flight, const char* name, std::string title, const char* y_label,
                   bool zero_alpha) {
  Figure figure = make_figure(name, std::move(title), "time from launch (s)", y_label);
  figure.x_markers = staging_markers(flight);
  if (!figure.x_markers.empty()) {
    figure.key_entries.push_back({kStagingTitle, SeriesStyle::kLines, kMarkerGrey, 3, 7});
  }
  if (zero_alpha) {
    figure.bands = alpha_zero_bands(flight);
    figure.band_title = kZeroAlphaTitle;
  }
  return figure;
}

PlotSeries time_series(const Flight& flight, std::string title, const char* key) {
  return lines(std::move(title), Columns{flight.time, column(*flight.points, key)});
}

// The points with x <= x_max (a monotonic x: time, downrange) of a series.
void cut_after(double x_max, PlotSeries* series) {
  if (!std::isfinite(x_max)) return;
  std::size_t keep = 0;
  while (keep < series->x.size() && !(series->x[keep] > x_max)) ++keep;
  series->x.resize(keep);
  series->y.resize(keep);
}

// ---- the plots ----------------------------------------------------------------------------------

// Altitude (n.mi.) vs downrange (n.mi.), the staging points and max q labelled; `ascent` limits it
// to the ascent window.
std::optional<Figure> altitude_downrange_figure(const json& document, bool ascent) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  std::vector<double> range = column(*flight->points, "range_nmi");
  std::vector<double> altitude = column(*flight->points, "altitude_ft");
  for (double& h : altitude) h /= kFeetPerNauticalMile;
  Figure figure = make_figure(ascent ? "altitude_downrange_ascent" : "altitude_downrange",
                              "Altitude vs downrange", "downrange (n.mi.)", "altitude (n.mi.)");
  figure.points = staging_points(*flight, range, altitude);
  if (flight->has_max_q) {
    figure.points.push_back({range[flight->max_q], altitude[flight->max_q], "max q", 0});
  }
  PlotSeries series = lines("altitude", Columns{range, altitude});
  if (ascent && std::isfinite(flight->ascent_end_s)) {
    // The downrange of the ascent's end: its last point at or before the burnout.
    double end_range = kGap;
    for (std::size_t i = 0; i < range.size(); ++i) {
      if (flight->time[i] <= flight->ascent_end_s && std::isfinite(range[i])) end_range = range[i];
    }
    figure.title += ", ascent through " + stage_name(flight->ascent_stage) + " burnout";
    if (std::isfinite(end_range)) {
      figure.x_min = std::isfinite(range.front()) ? range.front() : kGap;
      figure.x_max = end_range;
      cut_after(end_range, &series);
    }
  } else if (!ascent) {
    figure.title += ", full flight";
  }
  figure.series.push_back(std::move(series));
  return figure;
}

std::optional<Figure> altitude_downrange_ascent(const json& document) {
  return altitude_downrange_figure(document, true);
}
std::optional<Figure> altitude_downrange(const json& document) {
  return altitude_downrange_figure(document, false);
}

std::optional<Figure> velocity_time(const json& document) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  Figure figure = time_figure(*flight, "velocity_time", "Velocity vs time", "velocity (ft/s)", false);
  figure.series.push_back(time_series(*flight, "VEL, Earth-relative", "velocity_ft_s"));
  PlotSeries inertial = time_series(*flight, "VI, inertial", "inertial_velocity_ft_s");
  inertial.dashed = true;
  figure.series.push_back(std::move(inertial));
  return figure;
}

std::optional<Figure> flight_path_angle_time(const json& document) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  Figure figure = time_figure(*flight, "flight_path_angle_time", "Flight-path angle vs time",
                              "flight-path angle (deg)", true);
  figure.series.push_back(time_series(*flight, "GAMMA, Earth-relative", "gamma_deg"));
  PlotSeries inertial = time_series(*flight, "GAMI, inertial", "inertial_gamma_deg");
  inertial.dashed = true;
  figure.series.push_back(std::move(inertial));
  return figure;
}

std::optional<Figure> dynamic_pressure_time(const json& document) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  Figure figure =
      time_figure(*flight, "dynamic_pressure_time", "Dynamic pressure vs time", "q-bar (lbf/ft^2)", true);
  figure.series.push_back(time_series(*flight, "q-bar", "dynamic_pressure_lbf_ft2"));
  limit_to_ascent(*flight, &figure);
  cut_after(figure.x_max, &figure.series.back());
  if (flight->has_max_q) {
    figure.points.push_back({flight->time[flight->max_q],
                             (*flight->points)[flight->max_q]["dynamic_pressure_lbf_ft2"].get<double>(),
                             max_q_label(*flight), 0});
  }
  return figure;
}

// Angle of attack and q-bar x alpha over the ascent (both vanish out of the atmosphere), max q
// marked by a vertical line.
std::optional<Figure> ascent_time_figure(const json& document, const char* name, const char* title,
                                         const char* y_label, const char* curve, const char* key,
                                         int peak_decimals) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  Figure figure = time_figure(*flight, name, title, y_label, true);
  figure.series.push_back(time_series(*flight, curve, key));
  limit_to_ascent(*flight, &figure);
  cut_after(figure.x_max, &figure.series.back());
  if (flight->has_max_q) figure.x_markers.push_back({flight->time[flight->max_q], "max q", 2});
  // The peak magnitude of the curve, labelled.
  const PlotSeries& curve_series = figure.series.back();
  std::size_t peak = curve_series.y.size();
  for (std::size_t i = 0; i < curve_series.y.size(); ++i) {
    if (std::fabs(curve_series.y[i]) <= kMaxPlotMagnitude &&
        (peak == curve_series.y.size() || std::fabs(curve_series.y[i]) > std::fabs(curve_series.y[peak]))) {
      peak = i;
    }
  }
  if (peak < curve_series.y.size() && curve_series.y[peak] != 0.0) {
    figure.points.push_back({curve_series.x[peak], curve_series.y[peak],
                             std::string("peak |") + curve + "| " +
                                 fixed(std::fabs(curve_series.y[peak]), peak_decimals) + " at " +
                                 fixed(curve_series.x[peak], 1) + " s",
                             0});
  }
  return figure;
}

std::optional<Figure> alpha_time(const json& document) {
  return ascent_time_figure(document, "alpha_time", "Angle of attack vs time", "alpha (deg)", "ALPHA",
                            "alpha_deg", 1);
}

std::optional<Figure> qalpha_time(const json& document) {
  return ascent_time_figure(document, "qalpha_time", "q-bar x alpha vs time", "q-bar x alpha (lbf deg/ft^2)",
                            "QALPHA", "qalpha_lbf_deg_ft2", 0);
}

std::optional<Figure> weight_time(const json& document) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  Figure figure = time_figure(*flight, "weight_time", "Weight vs time", "weight (lb, log scale)", false);
  figure.y_log = true;
  PlotSeries weight = time_series(*flight, "WEIGHT", "weight_lb");
  for (double& w : weight.y) {
    if (!(w > 0.0)) w = kGap;  // a log axis draws no zero
  }
  figure.series.push_back(std::move(weight));
  return figure;
}

// Geodetic latitude vs Earth-fixed longitude, the launch site and the last point marked; the
// track is broken where it crosses the 180 deg meridian.
std::optional<Figure> ground_track(const json& document) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  std::vector<double> longitude = column(*flight->points, "longitude_deg");
  std::vector<double> latitude = column(*flight->points, "geodetic_latitude_deg");
  Figure figure =
      make_figure("ground_track", "Ground track", "longitude (deg east)", "geodetic latitude (deg north)");
  PlotSeries track;
  track.title = "ground track";
  for (std::size_t i = 0; i < longitude.size(); ++i) {
    if (i > 0 && std::fabs(longitude[i] - longitude[i - 1]) > 180.0) {
      track.x.push_back(kGap);
      track.y.push_back(kGap);
    }
    track.x.push_back(longitude[i]);
    track.y.push_back(latitude[i]);
  }
  figure.points.push_back({longitude.front(), latitude.front(),
                           "launch site " + plot_map::place_text(latitude.front(), longitude.front()), 0});
  figure.points.push_back({longitude.back(), latitude.back(),
                           "end " + fixed(flight->time.back(), 1) + " s " +
                               plot_map::place_text(latitude.back(), longitude.back()),
                           0});
  // A map of true shape around the track.
  plot_map::MapBounds bounds;
  for (std::size_t i = 0; i < track.x.size(); ++i) bounds.extend(track.x[i], track.y[i]);
  plot_map::frame_map(bounds, 0.08, &figure);
  figure.series.push_back(std::move(track));
  return figure;
}

// The end of the stage with code `stage` from stage_events[], or NaN.
double stage_end_time(const json& document, long stage) {
  const json* events = array_member(document, "stage_events");
  if (events == nullptr) return kGap;
  for (std::size_t i = 0; i < events->size(); ++i) {
    const std::string field = "stage_events[" + std::to_string(i) + "]";
    const json& event = (*events)[i];
    if (!event.is_object()) fail(field, "an object", event);
    const json* code = member(event, "stage");
    if (code != nullptr && code->is_number_integer() && code->get<long>() == stage) {
      return required_number(event, "end_time_s", field);
    }
  }
  return kGap;
}

// The linearized pitch program (member "linearized" of optimize --json): each segment a straight
// line theta_deg + rate_deg_s (t - start_time_s) from its start to the next segment's start; the
// last to the program's end_time_s (else the end of its stage in stage_events, else the last
// trajectory point).
std::optional<PlotSeries> linearized_program(const json& document, double last_time_s) {
  const json* linearized = member(document, "linearized");
  if (linearized == nullptr || linearized->is_null()) return std::nullopt;
  if (!linearized->is_object()) fail("linearized", "an object", *linearized);
  const json* segments = member(*linearized, "segments");
  if (segments == nullptr) throw PlotDataError("linearized: no member 'segments'");
  if (!segments->is_array()) fail("linearized.segments", "an array", *segments);
  if (segments->empty()) return std::nullopt;

  struct Segment {
    double start_s, theta_deg, rate_deg_s;
    long stage;
  };
  std::vector<Segment> parsed;
  for (std::size_t i = 0; i < segments->size(); ++i) {
    const std::string field = "linearized.segments[" + std::to_string(i) + "]";
    const json& segment = (*segments)[i];
    if (!segment.is_object()) fail(field, "an object", segment);
    const json* stage = member(segment, "stage");
    if (stage == nullptr) throw PlotDataError(field + ": no member 'stage'");
    if (!stage->is_number_integer()) fail(field + ".stage", "an integer", *stage);
    parsed.push_back({required_number(segment, "start_time_s", field),
                      required_number(segment, "theta_deg", field),
                      required_number(segment, "rate_deg_s", field), stage->get<long>()});
  }

  PlotSeries series;
  series.title = "linearized program";
  const json* constraints_met = member(*linearized, "constraints_met");
  const json* rate_limits_met = member(*linearized, "rate_limits_met");
  if (constraints_met != nullptr && constraints_met->is_boolean()) {
    series.title += constraints_met->get<bool>() ? ", constraints met" : ", constraints not met";
  }
  if (rate_limits_met != nullptr && rate_limits_met->is_boolean()) {
    series.title += rate_limits_met->get<bool>() ? ", rate limits met" : ", rate limits not met";
  }
  // The program's end: "end_time_s" when the document gives it, else the end of the last
  // segment's stage, else the last point flown.
  double program_end_s = kGap;
  if (member(*linearized, "end_time_s") != nullptr) {
    program_end_s = required_number(*linearized, "end_time_s", "linearized");
  }
  if (!std::isfinite(program_end_s)) program_end_s = stage_end_time(document, parsed.back().stage);
  if (!std::isfinite(program_end_s)) program_end_s = last_time_s;
  for (std::size_t i = 0; i < parsed.size(); ++i) {
    const Segment& s = parsed[i];
    const double end_s = i + 1 < parsed.size() ? parsed[i + 1].start_s : program_end_s;
    series.x.push_back(s.start_s);
    series.y.push_back(s.theta_deg);
    series.x.push_back(end_s);
    series.y.push_back(s.theta_deg + s.rate_deg_s * (end_s - s.start_s));
  }
  return series;
}

std::optional<Figure> theta_figure(const json& document, bool ascent) {
  const auto flight = flight_of(document);
  if (!flight) return std::nullopt;
  double last_time_s = kGap;
  for (double t : flight->time) {
    if (std::isfinite(t)) last_time_s = t;
  }
  const bool optimum = is_optimization(document);
  Figure figure = time_figure(*flight, ascent ? "theta_time_ascent" : "theta_time",
                              "Pitch attitude theta vs time", "theta (deg)", true);
  figure.series.push_back(time_series(*flight, optimum ? "theta, optimum" : "theta", "theta_deg"));
  if (auto linear = linearized_program(document, last_time_s)) {
    figure.title += ": optimum and linearized program";
    linear->dashed = true;
    figure.series.push_back(std::move(*linear));
  }
  if (ascent) {
    limit_to_ascent(*flight, &figure);
    for (PlotSeries& series : figure.series) cut_after(figure.x_max, &series);
  } else {
    figure.title += ", full flight";
  }
  return figure;
}

std::optional<Figure> theta_time_ascent(const json& document) { return theta_figure(document, true); }
std::optional<Figure> theta_time(const json& document) { return theta_figure(document, false); }

// Optimizer convergence (member "iterations" of optimize --json): the payoff of every forward run,
// successful runs filled, unsuccessful open; and on a log axis each constraint's error scaled by
// its deadband, |desired - achieved| / tolerance (an inequality: only its excess), 1 = the deadband.
std::optional<Figure> convergence(const json& document) {
  const json* iterations = array_member(document, "iterations");
  if (iterations == nullptr || iterations->empty()) return std::nullopt;
  struct Constraint {
    std::string name;
    double tolerance;
    bool inequality;
  };
  std::vector<Constraint> constraints;
  if (const json* list = array_member(document, "constraints")) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string field = "constraints[" + std::to_string(i) + "]";
      const json& constraint = (*list)[i];
      if (!constraint.is_object()) fail(field, "an object", constraint);
      const json* name = member(constraint, "name");
      if (name != nullptr && !name->is_string()) fail(field + ".name", "a string", *name);
      const json* inequality = member(constraint, "inequality");
      constraints.push_back(
          {name != nullptr ? name->get<std::string>() : "constraint " + std::to_string(i + 1),
           required_number(constraint, "tolerance", field),
           inequality != nullptr && inequality->is_boolean() && inequality->get<bool>()});
    }
  }
  std::string unit;
  if (const json* payoff = member(document, "payoff"); payoff != nullptr && payoff->is_object()) {
    const json* text = member(*payoff, "unit");
    if (text != nullptr && text->is_string()) unit = text->get<std::string>();
  }
  Figure figure = make_figure("convergence", "Optimizer convergence", "forward run",
                              unit.empty() ? "payoff" : "payoff (" + unit + ")");
  figure.y2_label = "constraint error / deadband (log scale)";
  figure.y2_log = true;
  PlotSeries payoff;
  payoff.title = "payoff (left axis)";
  PlotSeries successful;
  successful.title = "successful run";
  successful.style = SeriesStyle::kPoints;
  successful.point_type = 7;
  PlotSeries unsuccessful;
  unsuccessful.title = "unsuccessful run";
  unsuccessful.style = SeriesStyle::kPoints;
  unsuccessful.point_type = 6;
  successful.color = unsuccessful.color = payoff.color = 7;  // black: the payoff
  std::vector<PlotSeries> errors(constraints.size());
  for (std::size_t c = 0; c < constraints.size(); ++c) {
    errors[c].title = constraints[c].name + (constraints[c].inequality ? " excess" : "") + " (right axis)";
    errors[c].style = SeriesStyle::kLinesPoints;
    errors[c].point_type = 5 + 2 * static_cast<int>(c % 3);
    errors[c].second_axis = true;
    errors[c].color = static_cast<int>(c % 6) + 1;
  }
  for (std::size_t i = 0; i < iterations->size(); ++i) {
    const std::string field = "iterations[" + std::to_string(i) + "]";
    const json& record = (*iterations)[i];
    if (!record.is_object()) fail(field, "an object", record);
    const double run = required_number(record, "forward_run", field);
    const double value = required_number(record, "payoff", field);
    payoff.x.push_back(run);
    payoff.y.push_back(value);
    const json* ok = member(record, "successful");
    if (ok != nullptr && !ok->is_boolean()) fail(field + ".successful", "true or false", *ok);
    PlotSeries& marks = ok != nullptr && ok->get<bool>() ? successful : unsuccessful;
    marks.x.push_back(run);
    marks.y.push_back(value);
    const json* corrections = member(record, "constraint_corrections");
    if (corrections == nullptr || corrections->is_null()) continue;
    if (!corrections->is_array()) fail(field + ".constraint_corrections", "an array", *corrections);
    for (std::size_t c = 0; c < constraints.size() && c < corrections->size(); ++c) {
      const double correction =
          number_or_gap((*corrections)[c], field + ".constraint_corrections[" + std::to_string(c) + "]");
      // d psi = desired - achieved, judged by the core's inequality rule (constraint_set.hpp).
      const double error = std::fabs(counted_correction(constraints[c].inequality, correction));
      errors[c].x.push_back(run);
      errors[c].y.push_back(error > 0.0 && constraints[c].tolerance > 0.0 ? error / constraints[c].tolerance
                                                                          : kGap);
    }
  }
  figure.series.push_back(std::move(payoff));
  if (!successful.x.empty()) figure.series.push_back(std::move(successful));
  if (!unsuccessful.x.empty()) figure.series.push_back(std::move(unsuccessful));
  for (PlotSeries& series : errors) figure.series.push_back(std::move(series));
  if (!constraints.empty()) figure.y_lines.push_back({1.0, true, "deadband (right axis: 1)"});
  return figure;
}

// Planned, with their analyses (plot.hpp): dispersion summary ("dispersion"), impact locus on a
// map grid ("impact"), radar azimuth/elevation vs time ("radar").
constexpr PlotKind kCatalogue[] = {
    {"altitude_downrange_ascent", "trajectory",
     "altitude (n.mi.) vs downrange (n.mi.) through the burnout before the last coast (Scout: stage 3), "
     "staging points and max q marked",
     altitude_downrange_ascent},
    {"altitude_downrange", "trajectory",
     "altitude (n.mi.) vs downrange (n.mi.), the full flight, staging points and max q marked",
     altitude_downrange},
    {"velocity_time", "trajectory", "Earth-relative and inertial velocity (ft/s) vs time (s), staging marked",
     velocity_time},
    {"flight_path_angle_time", "trajectory",
     "Earth-relative and inertial flight-path angle (deg) vs time (s), staging marked, zero-alpha window "
     "shaded",
     flight_path_angle_time},
    {"dynamic_pressure_time", "trajectory",
     "dynamic pressure q-bar (lbf/ft^2) vs time (s) over the ascent, max q marked", dynamic_pressure_time},
    {"alpha_time", "trajectory", "angle of attack (deg) vs time (s) over the ascent, max q marked",
     alpha_time},
    {"qalpha_time", "trajectory", "q-bar x alpha (lbf deg/ft^2) vs time (s) over the ascent, max q marked",
     qalpha_time},
    {"theta_time_ascent", "trajectory",
     "pitch attitude theta (deg) vs time (s) over the ascent: the optimum (optimize --json) or the program "
     "flown, "
     "the linearized program over it when the document has 'linearized'",
     theta_time_ascent},
    {"theta_time", "trajectory", "the same over the full flight", theta_time},
    {"weight_time", "trajectory", "vehicle weight (lb, log scale) vs time (s), staging marked", weight_time},
    {"ground_track", "trajectory", "geodetic latitude vs longitude (deg), launch site and last point marked",
     ground_track},
    {"impact_locus", "impact",
     "impact points of the thrust failures (circles) and expended casings (triangles) of stages 1-3, a "
     "colour per stage, on a latitude/longitude grid with the nominal ground track and the launch site",
     plot_detail::impact_locus_figure},
    {"convergence", "iterations",
     "payoff and constraint error / deadband per forward run (optimize --json only)", convergence},
};

// Values gnuplot cannot draw become gaps; true when the series keeps at least one point.
bool keep_drawable_points(PlotSeries* series) {
  bool any = false;
  const std::size_t n = std::min(series->x.size(), series->y.size());
  for (std::size_t i = 0; i < n; ++i) {
    double& x = series->x[i];
    double& y = series->y[i];
    if (!(std::fabs(x) <= kMaxPlotMagnitude) || !(std::fabs(y) <= kMaxPlotMagnitude)) {
      x = kGap;
      y = kGap;
    } else {
      any = true;
    }
  }
  return any;
}

const char* const kNoDrawableValue =
    "no finite value to draw (every value null, or beyond 1e30 in magnitude)";

}  // namespace

std::span<const PlotKind> plot_catalogue() { return kCatalogue; }

std::string run_status_text(const nlohmann::json& document) {
  const auto text = [&](const char* key) {
    const json* value = member(document, key);
    return value != nullptr && value->is_string() ? value->get<std::string>() : std::string();
  };
  const std::string status = text("status").empty() ? "status unknown" : text("status");
  const json* converged = member(document, "converged");
  if (converged == nullptr || !converged->is_boolean()) return "simulated, " + status;
  std::string result = (converged->get<bool>() ? "converged, " : "not converged, ") + status;
  const std::string case_status = text("case_status");
  if (!case_status.empty() && case_status != status && case_status != "kOk") {
    const std::string step = text("case_failed_step");
    result += "; case failed: " + (step.empty() ? "" : step + ": ") + case_status;
  }
  return result;
}

namespace {

std::string trimmed(std::string text) {
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string string_member(const json& document, const char* key) {
  const json* value = member(document, key);
  return value != nullptr && value->is_string() ? trimmed(value->get<std::string>()) : std::string();
}

// The case heading (data block 2) and the run status: "HEADING - converged, kOk".
std::string heading_and_status(const json& document) {
  const std::string heading = string_member(document, "case_heading");
  return (heading.empty() ? "" : heading + " - ") + run_status_text(document);
}

}  // namespace

DocumentFigures figures_for_document(const nlohmann::json& document) {
  if (!document.is_object()) {
    throw PlotDataError(
        std::string("expected a JSON object (the output of tolip simulate --json or tolip optimize "
                    "--json), found ") +
        document.type_name());
  }
  DocumentFigures result;
  // A figure joins the result with its drawable curves only (notes name what was left out, by the
  // figure's own name: a name passed beside the moved figure would be read after the move).
  const auto add = [&](Figure figure) {
    const std::string& name = figure.name;
    std::vector<PlotSeries> drawable;
    for (PlotSeries& series : figure.series) {
      if (keep_drawable_points(&series)) {
        drawable.push_back(std::move(series));
      } else {
        result.notes.push_back("figure " + name + ": curve '" + series.title +
                               "' left out: " + kNoDrawableValue);
      }
    }
    if (drawable.empty()) {
      // The curve notes say no more than this one.
      result.notes.resize(result.notes.size() - figure.series.size());
      result.notes.push_back("figure " + name + " skipped: " + kNoDrawableValue);
      return;
    }
    figure.series = std::move(drawable);
    figure.subtitle = {string_member(document, "title"), heading_and_status(document)};
    result.figures.push_back(std::move(figure));
  };
  for (const PlotKind& kind : plot_catalogue()) {
    std::optional<Figure> figure = kind.build(document);
    if (figure) {
      add(std::move(*figure));
    } else {
      const json* data = member(document, kind.member);
      result.skipped.push_back(std::string(kind.name) +
                               (data == nullptr || data->is_null()
                                    ? " (no member '" + std::string(kind.member) + "')"
                                    : " ('" + std::string(kind.member) + "' is empty)"));
    }
  }
  // One figure per radar station (member "radar"; radar_plots.cpp).
  for (Figure& figure : hardover_figures(document)) add(std::move(figure));
  for (Figure& figure : hil_figures(document)) add(std::move(figure));
  for (Figure& figure : autopilot_figures(document)) add(std::move(figure));
  for (Figure& figure : radar_figures(document)) add(std::move(figure));
  return result;
}

DocumentFigures figures_for_cases(const std::vector<const nlohmann::json*>& documents) {
  if (documents.size() == 1) return figures_for_document(*documents.front());
  std::vector<DocumentFigures> cases;
  for (std::size_t d = 0; d < documents.size(); ++d) {
    try {
      cases.push_back(figures_for_document(*documents[d]));
    } catch (const PlotDataError& e) {
      throw PlotDataError("case " + std::to_string(d + 1) + ": " + e.what());
    }
  }
  DocumentFigures result;
  for (std::size_t d = 0; d < cases.size(); ++d) {
    const std::string which = std::to_string(d + 1);
    for (const std::string& skipped : cases[d].skipped)
      result.skipped.push_back(skipped + " in case " + which);
    for (const std::string& note : cases[d].notes) result.notes.push_back("case " + which + ": " + note);
  }
  // The common title (data block 1) of the cases, when they share one.
  std::string title = string_member(*documents.front(), "title");
  for (const json* document : documents) {
    if (string_member(*document, "title") != title) title = "cases of different titles";
  }
  // The catalogue's figures, then those of a variable count (a radar station each) in the order
  // the cases first have them.
  std::vector<std::string> names;
  for (const PlotKind& kind : plot_catalogue()) names.push_back(kind.name);
  for (const DocumentFigures& figures : cases) {
    for (const Figure& figure : figures.figures) {
      if (std::find(names.begin(), names.end(), figure.name) == names.end()) names.push_back(figure.name);
    }
  }
  for (const std::string& name : names) {
    Figure merged;
    bool any = false;
    std::vector<KeyEntry> quantities;  // the curves of a case by title: one legend entry each
    for (std::size_t d = 0; d < cases.size(); ++d) {
      const auto it = std::find_if(cases[d].figures.begin(), cases[d].figures.end(),
                                   [&](const Figure& figure) { return figure.name == name; });
      if (it == cases[d].figures.end()) continue;
      Figure& figure = *it;
      const int color = static_cast<int>(d % 8) + 1;
      if (!any) {
        merged = figure;
        merged.series.clear();
        merged.x_markers.clear();
        merged.points.clear();
        merged.bands.clear();
        merged.subtitle = {title, std::to_string(documents.size()) + " cases overlaid, a colour per case"};
        any = true;
      } else {
        // The widest x range of the cases.
        if (std::isfinite(figure.x_min) && std::isfinite(merged.x_min))
          merged.x_min = std::min(merged.x_min, figure.x_min);
        if (std::isfinite(figure.x_max) && std::isfinite(merged.x_max))
          merged.x_max = std::max(merged.x_max, figure.x_max);
      }
      merged.key_entries.push_back(
          {"case " + std::to_string(d + 1) + ": " + heading_and_status(*documents[d]), SeriesStyle::kLines,
           color, 1, 7});
      for (std::size_t i = 0; i < figure.series.size(); ++i) {
        PlotSeries series = std::move(figure.series[i]);
        auto place = std::find_if(quantities.begin(), quantities.end(),
                                  [&](const KeyEntry& entry) { return entry.title == series.title; });
        if (place == quantities.end()) {
          // A new quantity: the next dash type among the curves drawn with lines.
          int lines_before = 0;
          for (const KeyEntry& entry : quantities)
            lines_before += entry.style != SeriesStyle::kPoints ? 1 : 0;
          quantities.push_back({series.title, series.style, 0,
                                series.style == SeriesStyle::kPoints ? 1 : lines_before % 5 + 1,
                                series.point_type});
          place = quantities.end() - 1;
        }
        series.title.clear();
        series.color = color;
        series.dash_type = place->dash_type;
        merged.series.push_back(std::move(series));
      }
      // The first case's markers labelled; the others' in their colour, unlabelled.
      for (XMarker marker : figure.x_markers) {
        if (d > 0) {
          marker.label.clear();
          marker.color = color;
        }
        merged.x_markers.push_back(std::move(marker));
      }
      for (PointMarker point : figure.points) {
        point.color = color;
        if (d > 0) point.label.clear();
        merged.points.push_back(std::move(point));
      }
      merged.bands.insert(merged.bands.end(), figure.bands.begin(), figure.bands.end());
    }
    if (!any) continue;
    // One legend entry per quantity when a case has several curves: black, by dash type (points
    // by point type).
    if (quantities.size() > 1)
      merged.key_entries.insert(merged.key_entries.end(), quantities.begin(), quantities.end());
    result.figures.push_back(std::move(merged));
  }
  return result;
}

}  // namespace tolip::ground
