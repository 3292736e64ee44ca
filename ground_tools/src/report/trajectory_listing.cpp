// Manual-style trajectory listing (Sec. 22 "OUTPUT FORMAT"): page titles from data blocks 1-3,
// the trajectory columns in two line groups of 12 columns of 11 characters (132 columns, the
// width of the 1966 line printer), the stage events and the terminal conditions.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "listing_pager.hpp"
#include "number_format.hpp"
#include "tolip/body/body_dynamics.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/impact_report.hpp"
#include "tolip_ground/radar_report.hpp"
#include "tolip_ground/report.hpp"
#include "tolip_ground/version.hpp"

namespace tolip::ground {
namespace {

using report_detail::card_text;
using report_detail::fixed_cell;
using report_detail::right_aligned;

constexpr int kCellWidth = 11;
constexpr int kDefaultLinesPerPage = 54;

double deg(double radians) { return radians * kRadToDeg; }

struct ListingColumn {
  const char* heading;
  const char* unit;
  int decimals;
  double (*value)(const TrajectoryPoint& point);
};

// First line group: the state and the vehicle.
constexpr ListingColumn kLine1[] = {
    {"TIME", "SEC", 3, [](const TrajectoryPoint& p) { return p.time_s; }},
    {"VEL", "FT/SEC", 2, [](const TrajectoryPoint& p) { return p.state[kStateV]; }},
    {"GAMMA", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.state[kStateGamma]); }},
    {"PSI", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.state[kStatePsi]); }},
    {"ALTITUDE", "FT", 1, [](const TrajectoryPoint& p) { return p.altitude_ft; }},
    {"GEOC LAT", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.state[kStateLambda]); }},
    {"TAU", "DEG E", 4,
     [](const TrajectoryPoint& p) { return wrap_degrees_180(deg(p.earth_longitude_rad)); }},
    {"QBAR", "LB/FT2", 2, [](const TrajectoryPoint& p) { return p.dynamic_pressure_lbf_ft2; }},
    {"THRUST", "LB", 1, [](const TrajectoryPoint& p) { return p.net_thrust_lbf; }},
    {"WEIGHT", "LB", 2, [](const TrajectoryPoint& p) { return p.weight_lb; }},
    {"GEOD LAT", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.geodetic_latitude_rad); }},
    {"RADIUS", "FT", 1, [](const TrajectoryPoint& p) { return p.state[kStateR]; }},
};

// Second line group: inertial velocity, aerodynamics, range.
constexpr ListingColumn kLine2[] = {
    {"STG TIME", "SEC", 3, [](const TrajectoryPoint& p) { return p.stage_time_s; }},
    {"HEAT RATE", "BTU/FT2S", 4, [](const TrajectoryPoint& p) { return p.heating_rate_btu_ft2_s; }},
    {"THETA", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.theta_rad); }},
    {"VI", "FT/SEC", 2, [](const TrajectoryPoint& p) { return p.inertial.velocity_ft_s; }},
    {"GAMI", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.inertial.flight_path_angle_rad); }},
    {"PSII", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.inertial.azimuth_rad); }},
    {"MACH", "", 3, [](const TrajectoryPoint& p) { return p.mach; }},
    {"ALPHA", "DEG", 4, [](const TrajectoryPoint& p) { return deg(p.alpha_rad); }},
    {"DRAG", "LB", 1, [](const TrajectoryPoint& p) { return p.drag_lbf; }},
    {"LIFT", "LB", 1, [](const TrajectoryPoint& p) { return p.lift_lbf; }},
    {"QALPHA", "LB-DEG/FT2", 1,
     [](const TrajectoryPoint& p) { return p.dynamic_pressure_lbf_ft2 * deg(p.alpha_rad); }},
    {"RANGE", "N.MI.", 3, [](const TrajectoryPoint& p) { return p.downrange_rad * kNauticalMilesPerRadian; }},
};

// Third line group (`optimize --listing-level full|runs`): the Sec. 22 columns the two groups above
// leave out. Their values need more than the point (the step's command, the reference trajectory,
// the launch frame), so point_extras() computes them.
constexpr ListingColumn kLine3[] = {
    {"CHI", "DEG", 4, nullptr},          {"BETA6D", "DEG", 4, nullptr}, {"THETAC", "DEG", 4, nullptr},
    {"THETADOT", "DEG/SEC", 4, nullptr}, {"DTHETA", "DEG", 4, nullptr}, {"DELTA", "DEG", 4, nullptr},
};

template <std::size_t N>
std::string heading_line(const ListingColumn (&columns)[N], bool units) {
  std::string line;
  for (const ListingColumn& column : columns)
    line += right_aligned(units ? column.unit : column.heading, kCellWidth);
  return line;
}

template <std::size_t N>
std::string value_line(const ListingColumn (&columns)[N], const TrajectoryPoint& point) {
  std::string line;
  for (const ListingColumn& column : columns) {
    line += fixed_cell(column.value(point), column.decimals, kCellWidth);
  }
  return line;
}

std::string stage_name(int code) {
  if (is_powered_stage(code)) return "STAGE " + std::to_string(code);
  if (is_coast_stage(code)) return "COAST AFTER STAGE " + std::to_string(code - 5);
  return "STAGE CODE " + std::to_string(code);
}

std::string format(const char* pattern, double value) {
  if (!std::isfinite(value)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

}  // namespace

// ---- Pager (listing_pager.hpp) ---------------------------------------------------------------

namespace report_detail {

Pager::Pager(std::ostream& out, const DeckListingOptions* listing) : out_(out) {
  const double lines = listing != nullptr ? listing->lines_per_page : DeckListingOptions{}.lines_per_page;
  lines_per_page_ = (std::isfinite(lines) && lines >= 20.0 && lines <= 1000.0) ? static_cast<int>(lines)
                                                                               : kDefaultLinesPerPage;
  if (listing == nullptr) return;
  title_ = card_text(listing->title);
  heading_ = card_text(listing->case_heading);
  date_ = card_text(listing->date);
}

void Pager::new_page(const std::string& section, bool columns) {
  section_ = section;
  columns_ = columns;
  if (page_ > 0) out_ << '\n';
  ++page_;
  line_ = 0;
  emit(title_);
  emit(heading_);
  std::string third = date_;
  const std::string tag =
      "TOLIP " + std::string(version_string()) + "   " + section_ + "   PAGE " + std::to_string(page_);
  const int width = kCellWidth * 12;
  if (static_cast<int>(third.size() + tag.size()) + 1 < width) {
    third += std::string(static_cast<std::size_t>(width) - third.size() - tag.size(), ' ');
  } else {
    third += ' ';
  }
  emit(third + tag);
  emit("");
  if (columns_) {
    emit(heading_line(kLine1, false));
    emit(heading_line(kLine1, true));
    emit(heading_line(kLine2, false));
    emit(heading_line(kLine2, true));
    if (all_columns_) {
      emit(heading_line(kLine3, false));
      emit(heading_line(kLine3, true));
    }
    emit("");
  }
}

void Pager::reserve(int count) {
  if (page_ == 0 || line_ + count > lines_per_page_) new_page(section_, columns_);
}

void Pager::emit(const std::string& text) {
  std::string trimmed = text;
  while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
  out_ << trimmed << '\n';
  ++line_;
}

}  // namespace report_detail

namespace {

using report_detail::Pager;

// Data block 9's n for stage `code` on a trajectory of `kind` (1 outside the stage codes).
int every_nth(const OutputFrequency& output, int code, TrajectoryKind kind) {
  if (code < 1 || code > kMaxStages) return 1;
  const std::size_t slot = static_cast<std::size_t>(stage_index(code));
  switch (kind) {
    case TrajectoryKind::kInitial: return output.initial[slot];
    case TrajectoryKind::kIntermediate: return output.intermediate[slot];
    case TrajectoryKind::kFinal: return output.final_trajectory[slot];
  }
  return 1;
}

// Points past the last recorded stage event (the stage a failed run stopped in): the same rule as
// is_output_point, every n-th point of the stage plus its first and last point, and always the
// last point flown.
bool listed_after_events(const OutputFrequency& output, const Trajectory& trajectory, int index,
                         int run_start, TrajectoryKind kind) {
  const int count = stored_point_count(trajectory);
  const int code = trajectory.points[index].stage_code;
  if (index == run_start || index == count - 1) return true;
  if (trajectory.points[index + 1].stage_code != code) return true;
  const int every = every_nth(output, code, kind);
  return every <= 1 || (index - run_start) % every == 0;
}

// The third line group's values of every point (NaN, printed "-", where a column has none):
//   CHI      the flown yaw attitude (platform frame);
//   BETA6D   the out-of-plane angle of attack of the flown attitude, CONTRL's beta (Sec. 11),
//            from the point's velocity in the launch platform frame;
//   THETAC   the commanded pitch attitude (the program's theta_c; THETA but for 6D points);
//   THETADOT the commanded pitch rate of the step starting at the point: (theta_end -
//            theta_start) / step for a linear step, 0 when held; none in the zero-alpha window
//            (re-solved at every evaluation, no program rate) or where no step starts (a stage's
//            end point);
//   DTHETA   THETA - THETA of the reference ("change in theta from current nominal trajectory",
//            Sec. 22) at the same point; none without a reference or off its grid;
//   DELTA    the 6D steady-state deflection of eq. 7-3, on 6D points only.
class PointExtras {
 public:
  PointExtras(const Mission& mission, const Trajectory& trajectory, const Trajectory* reference)
      : trajectory_(trajectory), reference_(reference),
        rate_deg_s_(static_cast<std::size_t>(stored_point_count(trajectory)),
                    std::numeric_limits<double>::quiet_NaN()) {
    auto prepared = std::make_unique<PreparedCase>();
    if (ok(prepare_case(mission, prepared.get()))) {
      platform_to_inertial_ = prepared->platform_to_inertial;
      has_platform_ = true;
    }
    for (int s = 0; s < std::clamp(trajectory.step_count, 0, kMaxTrajectoryPoints); ++s) {
      const StepRecord& step = trajectory.steps[s];
      if (step.point < 0 || step.point >= static_cast<int>(rate_deg_s_.size())) continue;
      const StepCommand& c = step.command;
      double rate = std::numeric_limits<double>::quiet_NaN();
      if (c.mode == AttitudeMode::kLinear) rate = deg(c.theta_end_rad - c.theta_start_rad) / c.step_s;
      if (c.mode == AttitudeMode::kHeld) rate = 0.0;
      rate_deg_s_[static_cast<std::size_t>(step.point)] = rate;
    }
  }

  std::string line(int index) const {
    const TrajectoryPoint& p = trajectory_.points[index];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double beta = nan;
    if (has_platform_) {
      beta = deg(
          body_angles_of_attack(p.theta_rad, p.chi_rad, inertial_to_local(p.state) * platform_to_inertial_)
              .beta_rad);
    }
    double dtheta = nan;
    if (reference_ != nullptr && index < stored_point_count(*reference_) &&
        reference_->points[index].stage_code == p.stage_code &&
        reference_->points[index].time_s == p.time_s) {
      dtheta = deg(p.theta_rad - reference_->points[index].theta_rad);
    }
    const double values[] = {deg(p.chi_rad),
                             beta,
                             deg(static_cast<double>(p.theta_command_rad)),
                             rate_deg_s_[static_cast<std::size_t>(index)],
                             dtheta,
                             p.body_dynamics ? deg(static_cast<double>(p.control_deflection_rad)) : nan};
    std::string text;
    for (std::size_t k = 0; k < std::size(kLine3); ++k)
      text += fixed_cell(values[k], kLine3[k].decimals, kCellWidth);
    return text;
  }

 private:
  const Trajectory& trajectory_;
  const Trajectory* reference_;
  std::vector<double> rate_deg_s_;
  Matrix3 platform_to_inertial_ = Matrix3::Identity();
  bool has_platform_ = false;
};

void write_points(Pager& pager, const OutputFrequency& output, const Trajectory& trajectory,
                  TrajectoryKind kind, const PointExtras* extras) {
  const int count = stored_point_count(trajectory);
  int covered_until = -1;  // last point index inside a recorded stage event
  for (int s = 0; s < std::clamp(trajectory.stage_count, 0, kMaxStages); ++s) {
    covered_until = std::max(covered_until, trajectory.stages[s].last_point);
  }
  int previous_stage = -1;
  int run_start = 0;  // first index of the current stage among uncovered points
  for (int i = 0; i < count; ++i) {
    if (i > covered_until && (i == covered_until + 1 || i == 0 ||
                              trajectory.points[i].stage_code != trajectory.points[i - 1].stage_code)) {
      run_start = i;
    }
    const bool listed = i <= covered_until ? is_output_point(output, trajectory, i, kind)
                                           : listed_after_events(output, trajectory, i, run_start, kind);
    if (!listed) continue;
    const TrajectoryPoint& point = trajectory.points[i];
    const int lines = extras != nullptr ? 4 : 3;
    if (point.stage_code != previous_stage) {
      pager.reserve(lines + 1);
      std::string label(" ");
      label.append(stage_name(point.stage_code));
      if (is_powered_stage(point.stage_code)) label.append(" (POWERED)");
      pager.emit(label);
      previous_stage = point.stage_code;
    } else {
      pager.reserve(lines);
    }
    pager.emit(value_line(kLine1, point));
    pager.emit(value_line(kLine2, point));
    if (extras != nullptr) pager.emit(extras->line(i));
    pager.emit("");
  }
}

std::string point_value(const Trajectory& trajectory, int index, const char* pattern,
                        double (*value)(const TrajectoryPoint&)) {
  if (index < 0 || index >= stored_point_count(trajectory)) return "-";
  return format(pattern, value(trajectory.points[index]));
}

// The stage events that happened: every stage that ended (with its jettison), then the stage a
// failed run stopped in (STOPPED: it jettisoned nothing), then the stages of the sequence the run
// never reached (NOT REACHED).
void write_stage_events(Pager& pager, const Mission& mission, const Trajectory& trajectory) {
  const int count = std::clamp(trajectory.stage_count, 0, kMaxStages);
  const int sequence_count = std::clamp(mission.vehicle.sequence.count, 0, kMaxStages);
  pager.reserve(4 + std::max(count, sequence_count));
  pager.emit(" STAGE EVENTS");
  pager.emit(
      "                             START TIME    END TIME  START WEIGHT   END WEIGHT"
      "    JETTISONED  WEIGHT AFTER");
  pager.emit(
      "                                    SEC         SEC            LB           LB"
      "            LB            LB");
  for (int s = 0; s < count; ++s) {
    const StageEvent& event = trajectory.stages[s];
    std::string name = stage_name(event.code);
    name.resize(26, ' ');
    const auto time = [](const TrajectoryPoint& p) { return p.time_s; };
    const auto weight = [](const TrajectoryPoint& p) { return p.weight_lb; };
    std::string line = " " + name;
    line += right_aligned(point_value(trajectory, event.first_point, "%.3f", time), 12);
    line += right_aligned(point_value(trajectory, event.last_point, "%.3f", time), 12);
    line += right_aligned(point_value(trajectory, event.first_point, "%.2f", weight), 14);
    line += right_aligned(format("%.2f", event.burnout_weight_lb), 13);
    if (event.completed) {
      line += right_aligned(format("%.2f", event.burnout_weight_lb - event.weight_after_jettison_lb), 14);
      line += right_aligned(format("%.2f", event.weight_after_jettison_lb), 14);
    } else {
      line += right_aligned("STOPPED", 14);
      line += right_aligned("-", 14);
    }
    pager.emit(line);
  }
  // The sequence's stages after the last one flown.
  int reached = 0;
  for (int s = 0; s < count; ++s) {
    for (int k = 0; k < sequence_count; ++k) {
      if (mission.vehicle.sequence.codes[k] == trajectory.stages[s].code) reached = std::max(reached, k + 1);
    }
  }
  if (count > 0 && !trajectory.stages[count - 1].completed) {
    for (int k = reached; k < sequence_count; ++k) {
      std::string name = stage_name(mission.vehicle.sequence.codes[k]);
      name.resize(26, ' ');
      pager.emit(" " + name + right_aligned("NOT REACHED", 12));
    }
  }
  pager.emit("");
}

// The deck's descriptions of its stages ([stage.N] name, TOML only), when it gives any.
void write_stage_names(Pager& pager, const DeckListingOptions& listing) {
  int given = 0;
  for (const std::string& name : listing.stage_names) given += name.empty() ? 0 : 1;
  if (given == 0) return;
  pager.reserve(2 + given);
  pager.emit(" STAGE NAMES (THE DECK'S DESCRIPTIONS)");
  for (int code = 1; code <= kMaxStages; ++code) {
    const std::string& name = listing.stage_names[static_cast<std::size_t>(stage_index(code))];
    if (name.empty()) continue;
    std::string label = stage_name(code);
    label.resize(26, ' ');
    pager.emit(" " + label + name);
  }
  pager.emit("");
}

std::string labelled(const std::string& label, const std::string& value, const std::string& unit) {
  std::string text = "   " + label;
  text.resize(20, ' ');
  text += "= " + right_aligned(value, 20);
  if (!unit.empty()) text += " " + unit;
  return text;
}

void write_terminal_conditions(Pager& pager, const SimulationReport& report) {
  const Trajectory& trajectory = *report.trajectory;
  const int count = stored_point_count(trajectory);
  pager.reserve(12);
  if (!ok(report.status)) {
    pager.emit(std::string(" TRAJECTORY TERMINATED: ") + status_name(report.status) + ": " +
               status_message(report.status));
    pager.emit("");
  }
  if (count == 0) return;
  const TrajectoryPoint& last = trajectory.points[count - 1];
  pager.reserve(14);
  pager.emit(" TERMINAL CONDITIONS AT TIME " + format("%.3f", last.time_s) + " SEC, " +
             stage_name(last.stage_code));
  pager.emit(labelled("ALTITUDE", format("%.3f", last.altitude_ft), "FT"));
  pager.emit(labelled("VEL", format("%.4f", last.state[kStateV]), "FT/SEC"));
  pager.emit(labelled("GAMMA", format("%.6f", deg(last.state[kStateGamma])), "DEG"));
  pager.emit(labelled("PSI", format("%.6f", deg(last.state[kStatePsi])), "DEG"));
  pager.emit(labelled("GEOC LAT", format("%.6f", deg(last.state[kStateLambda])), "DEG"));
  pager.emit(labelled("GEOD LAT", format("%.6f", deg(last.geodetic_latitude_rad)), "DEG"));
  pager.emit(labelled("TAU", format("%.6f", wrap_degrees_180(deg(last.earth_longitude_rad))), "DEG EAST"));
  pager.emit(labelled("RADIUS", format("%.3f", last.state[kStateR]), "FT"));
  pager.emit(labelled("WEIGHT", format("%.3f", last.weight_lb), "LB"));
  pager.emit(labelled("RANGE", format("%.3f", last.downrange_rad * kNauticalMilesPerRadian), "N.MI."));
  const InertialVelocity& inertial = report.has_orbit ? report.orbit.inertial : last.inertial;
  pager.emit(labelled("VI", format("%.4f", inertial.velocity_ft_s), "FT/SEC"));
  pager.emit(labelled("GAMI", format("%.6f", deg(inertial.flight_path_angle_rad)), "DEG"));
  pager.emit(labelled("PSII", format("%.6f", deg(inertial.azimuth_rad)), "DEG"));
  pager.emit("");
  if (!report.has_orbit) return;

  const OrbitElements& orbit = report.orbit;
  const char* type = orbit.type == OrbitType::kElliptic    ? "ELLIPTIC"
                     : orbit.type == OrbitType::kParabolic ? "PARABOLIC"
                                                           : "HYPERBOLIC";
  pager.reserve(14);
  pager.emit(std::string(" ORBIT ELEMENTS (") + type + ", SPHERICAL EARTH)");
  pager.emit(labelled("TWOE", format("%.9E", orbit.twice_energy_ft2_s2), "FT2/SEC2"));
  pager.emit(labelled("EH", format("%.9E", orbit.angular_momentum_ft2_s), "FT2/SEC"));
  pager.emit(labelled("RP", format("%.3f", orbit.perigee_radius_ft), "FT"));
  pager.emit(labelled("EYE", format("%.6f", deg(orbit.inclination_rad)), "DEG"));
  pager.emit(labelled("BETAP", format("%.6f", deg(orbit.argument_of_perigee_rad)), "DEG"));
  pager.emit(labelled("ECCENTRICITY", format("%.9f", orbit.eccentricity), ""));
  if (orbit.has_semi_major_axis) {
    pager.emit(labelled("RALPHA", format("%.3f", orbit.semi_major_axis_ft), "FT"));
    pager.emit(labelled("PERIOD", format("%.5f", orbit.period_s / 60.0), "MIN"));
  } else {
    pager.emit(labelled("RALPHA", "NOT DEFINED", "(2E >= 0)"));
    pager.emit(labelled("PERIOD", "NOT DEFINED", "(2E >= 0)"));
  }
  pager.emit(labelled("OMEGAE", format("%.6f", deg(orbit.node_longitude_rad)), "DEG"));
  if (orbit.has_asymptote) {
    pager.emit(labelled("VH", format("%.4f", orbit.hyperbolic_excess_velocity_ft_s), "FT/SEC"));
    pager.emit(labelled("ASYMPTOTE RA", format("%.6f", deg(orbit.asymptote_right_ascension_rad)), "DEG"));
    pager.emit(labelled("ASYMPTOTE DECL", format("%.6f", deg(orbit.asymptote_declination_rad)), "DEG"));
  }
  pager.emit("");

  // The same orbit in engineering terms (altitudes above the oblate Earth at their latitudes).
  const OrbitSummary summary = summarize_orbit(report.mission->constants, orbit);
  pager.reserve(5);
  pager.emit(" ORBIT SUMMARY");
  const char* path = summary.path == PathClass::kOrbit        ? "ORBIT"
                     : summary.path == PathClass::kSuborbital ? "SUBORBITAL: PERIGEE BELOW THE SURFACE"
                                                              : "ESCAPE: 2E >= 0";
  pager.emit(labelled("PATH", path, ""));
  pager.emit(labelled("PERIGEE ALTITUDE", format("%.3f", summary.perigee_altitude_ft / kFeetPerNauticalMile),
                      std::string("N.MI. AT GEOC LAT ") + format("%.3f", deg(summary.perigee_latitude_rad)) +
                          " DEG" + (summary.perigee_in_atmosphere ? ", BELOW HAERO" : "")));
  if (orbit.has_semi_major_axis) {
    pager.emit(labelled("APOGEE ALTITUDE", format("%.3f", summary.apogee_altitude_ft / kFeetPerNauticalMile),
                        "N.MI."));
  }
  pager.emit("");
}

}  // namespace

void report_detail::write_trajectory_pages(Pager& pager, const SimulationReport& report) {
  const Mission& mission = *report.mission;
  const Trajectory& trajectory = *report.trajectory;
  std::unique_ptr<PointExtras> extras;
  if (report.all_columns) extras = std::make_unique<PointExtras>(mission, trajectory, report.reference);
  pager.set_all_columns(report.all_columns);
  pager.new_page(report.section, true);
  write_points(pager, report.listing != nullptr ? report.listing->output : OutputFrequency{}, trajectory,
               report.kind, extras.get());
  pager.set_all_columns(false);
  pager.new_page("TERMINAL CONDITIONS", false);
  write_stage_events(pager, mission, trajectory);
  if (report.listing != nullptr) write_stage_names(pager, *report.listing);
  write_terminal_conditions(pager, report);
  write_constraint_table(
      pager, report.constraints,
      " CONSTRAINTS OF DATA BLOCK 8 ON THIS TRAJECTORY (DATA BLOCK 19 UNITS, DEADBANDS OF DATA BLOCK 29)");
}

bool is_output_point(const OutputFrequency& output, const Trajectory& trajectory, int index,
                     TrajectoryKind kind) {
  for (int k = 0; k < trajectory.stage_count; ++k) {
    const StageEvent& event = trajectory.stages[k];
    if (index < event.first_point || index > event.last_point) continue;
    if (index == event.first_point || index == event.last_point) return true;
    const int every = every_nth(output, event.code, kind);
    return every <= 1 || (index - event.first_point) % every == 0;
  }
  return index == 0;  // the pad point
}

void write_trajectory_listing(std::ostream& out, const SimulationReport& report) {
  Pager pager(out, report.listing);
  report_detail::write_trajectory_pages(pager, report);
  if (report.impact != nullptr) report_detail::write_impact_pages(pager, *report.impact);
  if (report.hardover != nullptr) report_detail::write_hardover_pages(pager, *report.hardover);
  if (report.radar != nullptr) report_detail::write_radar_pages(pager, *report.radar);
}

}  // namespace tolip::ground
