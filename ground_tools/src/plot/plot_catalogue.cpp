// The plots of `tolip plot` (plot.hpp): each a small function of one result document, keyed on
// the member it needs. Field names and units are those of docs/cli.md (simulate/optimize --json).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tolip_ground/plot.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::json;

constexpr double kGap = std::numeric_limits<double>::quiet_NaN();

// ---- reading the document, every fault named by its field path ----------------------------------

[[noreturn]] void fail(const std::string& field, const std::string& expected, const json& found) {
  throw PlotDataError(field + ": expected " + expected + ", found " + found.type_name());
}

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

// The points of `trajectory[]` as two columns, or nothing when there is no trajectory.
struct Columns {
  std::vector<double> x;
  std::vector<double> y;
};
std::optional<Columns> trajectory_columns(const json& document, const char* x_key, const char* y_key) {
  const json* points = array_member(document, "trajectory");
  if (points == nullptr || points->empty()) return std::nullopt;
  Columns columns;
  columns.x.reserve(points->size());
  columns.y.reserve(points->size());
  for (std::size_t i = 0; i < points->size(); ++i) {
    const std::string field = "trajectory[" + std::to_string(i) + "]";
    const json& point = (*points)[i];
    if (!point.is_object()) fail(field, "an object", point);
    columns.x.push_back(required_number(point, x_key, field));
    columns.y.push_back(required_number(point, y_key, field));
  }
  return columns;
}

PlotSeries lines(std::string title, Columns columns) {
  PlotSeries series;
  series.title = std::move(title);
  series.x = std::move(columns.x);
  series.y = std::move(columns.y);
  return series;
}

// An optimize document carries the optimizer's results; its trajectory is the optimum.
bool is_optimization(const json& document) { return member(document, "iterations") != nullptr; }

// ---- the plots ----------------------------------------------------------------------------------

std::optional<Figure> altitude_downrange(const json& document) {
  auto columns = trajectory_columns(document, "range_nmi", "altitude_ft");
  if (!columns) return std::nullopt;
  Figure figure{"altitude_downrange", "Altitude vs downrange", "downrange (n.mi.)", "altitude (ft)", {}};
  figure.series.push_back(lines("altitude", std::move(*columns)));
  return figure;
}

std::optional<Figure> velocity_time(const json& document) {
  auto relative = trajectory_columns(document, "time_s", "velocity_ft_s");
  if (!relative) return std::nullopt;
  Figure figure{"velocity_time", "Velocity vs time", "time from launch (s)", "velocity (ft/s)", {}};
  figure.series.push_back(lines("VEL, Earth-relative", std::move(*relative)));
  PlotSeries inertial = lines("VI, inertial", *trajectory_columns(document, "time_s", "inertial_velocity_ft_s"));
  inertial.dashed = true;
  figure.series.push_back(std::move(inertial));
  return figure;
}

std::optional<Figure> dynamic_pressure_time(const json& document) {
  auto columns = trajectory_columns(document, "time_s", "dynamic_pressure_lbf_ft2");
  if (!columns) return std::nullopt;
  Figure figure{"dynamic_pressure_time", "Dynamic pressure vs time", "time from launch (s)",
                "q-bar (lbf/ft^2)", {}};
  figure.series.push_back(lines("q-bar", std::move(*columns)));
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
    parsed.push_back({required_number(segment, "start_time_s", field), required_number(segment, "theta_deg", field),
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

std::optional<Figure> theta_time(const json& document) {
  auto columns = trajectory_columns(document, "time_s", "theta_deg");
  if (!columns) return std::nullopt;
  double last_time_s = kGap;
  for (double t : columns->x) {
    if (std::isfinite(t)) last_time_s = t;
  }
  const bool optimum = is_optimization(document);
  Figure figure{"theta_time", "Pitch attitude theta vs time", "time from launch (s)", "theta (deg)", {}};
  figure.series.push_back(lines(optimum ? "theta, optimum" : "theta", std::move(*columns)));
  if (auto linear = linearized_program(document, last_time_s)) {
    figure.title += ": optimum and linearized program";
    linear->dashed = true;
    figure.series.push_back(std::move(*linear));
  }
  return figure;
}

// Planned, with their analyses (plot.hpp): dispersion summary ("dispersion"), impact locus on a
// map grid ("impact"), radar azimuth/elevation vs time ("radar").
constexpr PlotKind kCatalogue[] = {
    {"altitude_downrange", "trajectory", "altitude (ft) vs downrange (n.mi.)", altitude_downrange},
    {"velocity_time", "trajectory", "Earth-relative and inertial velocity (ft/s) vs time (s)", velocity_time},
    {"dynamic_pressure_time", "trajectory", "dynamic pressure q-bar (lbf/ft^2) vs time (s)", dynamic_pressure_time},
    {"theta_time", "trajectory",
     "pitch attitude theta (deg) vs time (s); with optimize --json the optimum, overlaid by the linearized "
     "program when the document has 'linearized'",
     theta_time},
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

const char* const kNoDrawableValue = "no finite value to draw (every value null, or beyond 1e30 in magnitude)";

}  // namespace

std::span<const PlotKind> plot_catalogue() { return kCatalogue; }

DocumentFigures figures_for_document(const nlohmann::json& document) {
  if (!document.is_object()) {
    throw PlotDataError(std::string("expected a JSON object (the output of tolip simulate --json or tolip optimize "
                                    "--json), found ") +
                        document.type_name());
  }
  DocumentFigures result;
  for (const PlotKind& kind : plot_catalogue()) {
    std::optional<Figure> figure = kind.build(document);
    if (figure) {
      std::vector<PlotSeries> drawable;
      for (PlotSeries& series : figure->series) {
        if (keep_drawable_points(&series)) {
          drawable.push_back(std::move(series));
        } else {
          result.notes.push_back("figure " + std::string(kind.name) + ": curve '" + series.title + "' left out: " +
                                 kNoDrawableValue);
        }
      }
      if (drawable.empty()) {
        // The curve notes say no more than this one.
        result.notes.resize(result.notes.size() - figure->series.size());
        result.notes.push_back("figure " + std::string(kind.name) + " skipped: " + kNoDrawableValue);
        continue;
      }
      figure->series = std::move(drawable);
      result.figures.push_back(std::move(*figure));
    } else {
      const json* data = member(document, kind.member);
      result.skipped.push_back(std::string(kind.name) + (data == nullptr || data->is_null()
                                                             ? " (no member '" + std::string(kind.member) + "')"
                                                             : " ('" + std::string(kind.member) + "' is empty)"));
    }
  }
  return result;
}

}  // namespace tolip::ground
