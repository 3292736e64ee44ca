// Listing, JSON and CSV of the impact locus (tolip_ground/impact_report.hpp).
#include "tolip_ground/impact_report.hpp"

#include <cmath>
#include <string>

#include "listing_pager.hpp"
#include "number_format.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/orbit/orbit_elements.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;
using report_detail::fixed_cell;
using report_detail::json_number;
using report_detail::left_aligned;
using report_detail::right_aligned;
using report_detail::round_trip;

const char* outcome_name(StepOutcome outcome) {
  return outcome == StepOutcome::kRun       ? "run"
         : outcome == StepOutcome::kSkipped ? "skipped"
                                            : "not requested";
}

bool has_locus(const ImpactStep& step) {
  return step.outcome == StepOutcome::kRun && step.locus != nullptr && step.mission != nullptr &&
         step.locus->count > 0;
}

}  // namespace

const char* impact_kind_key(ImpactKind kind) {
  return kind == ImpactKind::kThrustFailure ? "thrust_failure" : "expended_casing";
}

namespace report_detail {

void write_impact_pages(Pager& pager, const ImpactStep& step) {
  pager.new_page("NOMINAL IMPACT LOCUS", false);
  pager.emit(" NOMINAL IMPACT LOCUS (SEC. 17): THRUST FAILURE IN STAGES 1-3 AND THE EXPENDED CASINGS");
  pager.emit("   DRAG INCLUDED THROUGHOUT, NO THRUST, IMPACT ON THE GEODETIC (OBLATE) EARTH");
  if (step.outcome != StepOutcome::kRun || !ok(step.status)) {
    if (!has_locus(step)) {
      pager.emit(std::string("   NOT COMPUTED: ") + status_name(step.status) + ": " +
                 status_message(step.status));
      return;
    }
  }
  const Mission& m = *step.mission;
  const ImpactLocusData& d = *step.data;
  const LaunchConditions& launch = m.launch;
  const std::string about = step.nominal_kind == "optimum" ? "THE OPTIMUM"
                            : step.nominal_kind == "linearized program"
                                ? "THE LINEARIZED PROGRAM"
                                : "THE DECK'S PITCH PROGRAM (DATA BLOCK 40)";
  pager.emit("   ABOUT " + about);
  pager.emit("   LAUNCH SITE  GEODETIC LAT" +
             fixed_cell(geodetic_from_geocentric_rad(m.constants, launch.geocentric_latitude_rad) * kRadToDeg,
                        4, 10) +
             " DEG   LONGITUDE" + fixed_cell(launch.longitude_rad * kRadToDeg, 4, 10) + " DEG   AZIMUTH" +
             fixed_cell(launch.azimuth_rad * kRadToDeg, 3, 9) + " DEG");
  const ImpactStepSizes& s = d.steps;
  pager.emit("   INTPIM STEPS  IN ATMOSPHERE" + fixed_cell(s.in_atmosphere_s, 2, 6) + " S   OUT OF IT" +
             fixed_cell(s.out_of_atmosphere_s, 2, 7) + " S   RE-ENTERED" + fixed_cell(s.reentered_s, 2, 6) +
             " S   TERMINAL VELOCITY" + fixed_cell(s.terminal_velocity_s, 2, 6) + " S");
  pager.emit("   FAILURE AT EVERY N-TH INTEGRATION POINT, N = " + std::to_string(d.every_nth_point[0]) + " " +
             std::to_string(d.every_nth_point[1]) + " " + std::to_string(d.every_nth_point[2]) +
             " (DA6D(17-19), STAGES 1-3)");
  pager.emit("");
  const std::string head1 =
      "  STAGE  MODE               FAILURE     IMPACT   GEODETIC  LONGITUDE  DOWNRANGE CROSSRANGE GEOCENTRIC"
      "     WEIGHT IMPACT VEL";
  const std::string head2 =
      "                             TIME S     TIME S    LAT DEG        DEG      N.MI.      N.MI.    LAT DEG"
      "         LB       FT/S";
  pager.reserve(4);
  pager.emit(head1);
  pager.emit(head2);
  const ImpactLocus& locus = *step.locus;
  ImpactKind previous = locus.cases[0].kind;
  for (int i = 0; i < locus.count; ++i) {
    const ImpactCase& c = locus.cases[i];
    if (c.kind != previous) {
      pager.emit("");
      previous = c.kind;
    }
    std::string line =
        right_aligned(std::to_string(c.stage), 7) + "  " +
        left_aligned(c.kind == ImpactKind::kThrustFailure ? "THRUST FAILURE" : "EXPENDED CASING", 16) +
        fixed_cell(c.failure_time_s, 3, 11);
    if (!ok(c.status)) {
      pager.emit(line + "   NOT COMPUTED: " + status_name(c.status) + ": " + status_message(c.status));
      continue;
    }
    line += fixed_cell(c.impact_time_s, 3, 11) + fixed_cell(c.geodetic_latitude_rad * kRadToDeg, 4, 11) +
            fixed_cell(c.longitude_rad * kRadToDeg, 4, 11) +
            fixed_cell(c.downrange_rad * kNauticalMilesPerRadian, 3, 11) +
            fixed_cell(c.crossrange_rad * kNauticalMilesPerRadian, 3, 11) +
            fixed_cell(c.geocentric_latitude_rad * kRadToDeg, 4, 11) + fixed_cell(c.weight_lb, 1, 11) +
            fixed_cell(c.impact_velocity_ft_s, 1, 11) + (c.reached_terminal_velocity ? " TV" : "");
    pager.emit(line);
  }
  pager.emit("");
  pager.emit(
      "   TV: THE BODY REACHED TERMINAL VELOCITY.  DOWNRANGE: GREAT-CIRCLE ARC FROM THE LAUNCH SITE, 60 "
      "N.MI.");
  pager.emit(
      "   PER DEGREE (SEC. 4).  CROSSRANGE: FROM THE GREAT CIRCLE OF THE LAUNCH AZIMUTH, + TO THE RIGHT.");
  if (!ok(step.status)) {
    pager.emit(std::string("   STATUS: ") + status_name(step.status) + ": " + status_message(step.status));
  }
}

}  // namespace report_detail

void write_impact_listing(std::ostream& out, const DeckListingOptions* listing, const ImpactStep& step) {
  report_detail::Pager pager(out, listing);
  report_detail::write_impact_pages(pager, step);
}

json impact_json(const ImpactStep& step) {
  json out = json::object();
  out["status"] = status_name(step.status);
  out["status_message"] = status_message(step.status);
  out["outcome"] = outcome_name(step.outcome);
  out["nominal_kind"] = step.nominal_kind;
  if (!has_locus(step)) return out;
  const Mission& m = *step.mission;
  const ImpactLocusData& d = *step.data;
  out["launch_site"] = json{
      {"geodetic_latitude_deg",
       json_number(geodetic_from_geocentric_rad(m.constants, m.launch.geocentric_latitude_rad) * kRadToDeg)},
      {"geocentric_latitude_deg", json_number(m.launch.geocentric_latitude_rad * kRadToDeg)},
      {"longitude_deg", json_number(m.launch.longitude_rad * kRadToDeg)},
      {"azimuth_deg", json_number(m.launch.azimuth_rad * kRadToDeg)}};
  out["every_nth_point"] = json::array({d.every_nth_point[0], d.every_nth_point[1], d.every_nth_point[2]});
  out["step_sizes_s"] = json{{"in_atmosphere", d.steps.in_atmosphere_s},
                             {"out_of_atmosphere", d.steps.out_of_atmosphere_s},
                             {"reentered", d.steps.reentered_s},
                             {"terminal_velocity", d.steps.terminal_velocity_s}};
  json cases = json::array();
  const ImpactLocus& locus = *step.locus;
  for (int i = 0; i < locus.count; ++i) {
    const ImpactCase& c = locus.cases[i];
    json row = json::object();
    row["kind"] = impact_kind_key(c.kind);
    row["stage"] = c.stage;
    row["status"] = status_name(c.status);
    row["failure_time_s"] = json_number(c.failure_time_s);
    row["weight_lb"] = json_number(c.weight_lb);
    if (ok(c.status)) {
      row["impact_time_s"] = json_number(c.impact_time_s);
      row["geodetic_latitude_deg"] = json_number(c.geodetic_latitude_rad * kRadToDeg);
      row["geocentric_latitude_deg"] = json_number(c.geocentric_latitude_rad * kRadToDeg);
      row["longitude_deg"] = json_number(c.longitude_rad * kRadToDeg);
      row["downrange_nmi"] = json_number(c.downrange_rad * kNauticalMilesPerRadian);
      row["crossrange_nmi"] = json_number(c.crossrange_rad * kNauticalMilesPerRadian);
      row["impact_velocity_ft_s"] = json_number(c.impact_velocity_ft_s);
      row["impact_flight_path_angle_deg"] = json_number(c.impact_flight_path_angle_rad * kRadToDeg);
      row["max_altitude_ft"] = json_number(c.max_altitude_ft);
      row["terminal_velocity"] = c.reached_terminal_velocity;
      row["steps"] = c.steps;
    } else {
      row["status_message"] = status_message(c.status);
    }
    cases.push_back(std::move(row));
  }
  out["cases"] = std::move(cases);
  return out;
}

void add_impact_member(json* document, const ImpactStep& step) {
  json out = json::object();
  bool placed = false;
  for (auto it = document->begin(); it != document->end(); ++it) {
    if (it.key() == "trajectory" && !placed) {
      out["impact"] = impact_json(step);
      placed = true;
    }
    if (it.key() != "impact") out[it.key()] = it.value();
  }
  if (!placed) out["impact"] = impact_json(step);
  *document = std::move(out);
}

void write_impact_csv(std::ostream& out, const ImpactStep& step) {
  out << "kind,stage,status,failure_time_s,impact_time_s,geodetic_latitude_deg,geocentric_latitude_deg,"
         "longitude_deg,downrange_nmi,crossrange_nmi,weight_lb,impact_velocity_ft_s,"
         "impact_flight_path_angle_deg,max_altitude_ft,terminal_velocity\n";
  if (!has_locus(step)) return;
  const ImpactLocus& locus = *step.locus;
  for (int i = 0; i < locus.count; ++i) {
    const ImpactCase& c = locus.cases[i];
    out << impact_kind_key(c.kind) << ',' << c.stage << ',' << status_name(c.status) << ','
        << round_trip(c.failure_time_s);
    if (!ok(c.status)) {
      out << ",,,,,,," << round_trip(c.weight_lb) << ",,,,\n";
      continue;
    }
    out << ',' << round_trip(c.impact_time_s) << ',' << round_trip(c.geodetic_latitude_rad * kRadToDeg) << ','
        << round_trip(c.geocentric_latitude_rad * kRadToDeg) << ',' << round_trip(c.longitude_rad * kRadToDeg)
        << ',' << round_trip(c.downrange_rad * kNauticalMilesPerRadian) << ','
        << round_trip(c.crossrange_rad * kNauticalMilesPerRadian) << ',' << round_trip(c.weight_lb) << ','
        << round_trip(c.impact_velocity_ft_s) << ',' << round_trip(c.impact_flight_path_angle_rad * kRadToDeg)
        << ',' << round_trip(c.max_altitude_ft) << ',' << (c.reached_terminal_velocity ? "true" : "false")
        << '\n';
  }
}

}  // namespace tolip::ground
