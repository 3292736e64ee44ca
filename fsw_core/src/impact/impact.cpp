#include "tolip/impact/impact.hpp"

#include <cmath>

#include "tolip/dynamics/vertical_flight.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/integrator/rkad.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"

namespace tolip {
namespace {

// The stage code the bodies fly as: the manual's "coast stage 6 nomenclature".
constexpr int kImpactStageCode = 6;
// The crossing is converged when the altitude is within this of the surface, or the step bracket
// is this short.
constexpr double kCrossingAltitudeFt = 1e-3;
constexpr double kCrossingTimeS = 1e-9;
constexpr int kMaxCrossingIterations = 60;
// A descending vacuum step ends this long after the predicted crossing of HAERO, so that the drag
// is switched on at the start of a step (with its drag-limited length), never inside a long one.
constexpr double kPastHaeroS = 0.05;
// The density scale height of the lower atmosphere (the 1962 ARDC troposphere): the descending
// step limit and the terminal-velocity test.
constexpr double kDensityScaleHeightFt = 23000.0;

const char* const kFailureTableNames[kImpactStages] = {"CD1F", "CD2F", "CD3F"};
const char* const kCasingTableNames[kImpactStages] = {"CD1E", "CD2E", "CD3E"};
const char* const kStepRateWords[kImpactStages] = {"DA6D(17)", "DA6D(18)", "DA6D(19)"};

Status fault_at(ImpactFault* fault, Status status, int block, int stage, const char* field, double value,
                const char* expected) {
  if (fault != nullptr) {
    fault->data_block = block;
    fault->stage = stage;
    fault->field = field;
    fault->value = value;
    fault->expected = expected;
  }
  return status;
}

Status check_body(const ImpactBody& body, int block, int stage, const char* name, bool casing,
                  ImpactFault* fault) {
  if (!body.present || body.drag_coefficient.empty()) {
    return fault_at(fault, Status::kImpactDataMissing, block, stage, name, 0.0, "a drag table (Mach, C_D)");
  }
  if (!body.drag_coefficient.finalized()) {
    return fault_at(fault, Status::kTableNotMonotonic, block, stage, name, 0.0,
                    "Mach numbers strictly increasing");
  }
  if (body.drag_coefficient.first_x() != 0.0) {
    return fault_at(fault, Status::kImpactDragTableNotFromMach0, block, stage, name,
                    body.drag_coefficient.first_x(), "the table to start at Mach 0");
  }
  for (int i = 0; i < body.drag_coefficient.size(); ++i) {
    const double cd = body.drag_coefficient.y(i);
    if (!(std::isfinite(cd) && cd >= 0.0)) {
      return fault_at(fault, Status::kImpactDragCoefficientInvalid, block, stage, name, cd,
                      "C_D finite and >= 0");
    }
  }
  if (!(std::isfinite(body.reference_area_ft2) && body.reference_area_ft2 > 0.0)) {
    return fault_at(fault, Status::kImpactReferenceAreaNotPositive, block, stage, "reference area",
                    body.reference_area_ft2, "a reference area > 0 ft^2");
  }
  if (casing && !(std::isfinite(body.casing_weight_lb) && body.casing_weight_lb > 0.0)) {
    return fault_at(fault, Status::kImpactCasingWeightNotPositive, block, stage, "casing weight",
                    body.casing_weight_lb, "a casing weight > 0 lb");
  }
  return Status::kOk;
}

// The body as the manual's coast stage 6: its drag curve and area, no lift, no thrust.
void load_body_stage(const ImpactBody& body, StageData* stage) {
  stage->in_sequence = true;
  stage->drag_coefficient = body.drag_coefficient;
  stage->reference_area_ft2 = body.reference_area_ft2;
  stage->uses_lift_table = false;
  stage->nozzle_exit_area_ft2 = 0.0;
  stage->jettison_weight_lb = 0.0;
  stage->vacuum_thrust_lbf.clear();
  stage->consumable_weight_lb.clear();
}

// Everything one impact trajectory integrates with.
class BallisticFlight {
 public:
  BallisticFlight(const Mission& mission, const PreparedCase& prepared, const StageContext& stage)
      : mission_(mission), prepared_(prepared), stage_(stage) {
    command_.mode = AttitudeMode::kHeld;  // no thrust: the attitude acts on nothing
    command_.theta_start_rad = 0.0;
    command_.theta_end_rad = 0.0;
  }

  void evaluate(double t, const StateVector& x, Evaluation* out) const {
    evaluate_flight(mission_, prepared_, stage_, command_, t, x, 0.0, out);
  }

  // One Runge-Kutta step of dt from (t, x) whose derivative there is f0; within 5 deg of the
  // vertical in the regular coordinates of vertical_flight.hpp, as the trajectory does (a failure
  // just after the lift-off goes straight up and falls back through gamma = 90 deg).
  StateVector step(double t, const StateVector& x, const StateVector& f0, double dt) const {
    const auto derivative = [this](double time, const StateVector& y) {
      Evaluation e;
      evaluate(time, y, &e);
      return e.derivative;
    };
    if (starts_near_vertical(x)) {
      const double heading_rad = x[kStatePsi];
      const auto vertical = [&](double time, const StateVector& y) {
        const StateVector state = from_vertical_coordinates(y, heading_rad);
        return vertical_derivative(state, derivative(time, state));
      };
      const StateVector y1 =
          runge_kutta4_step(vertical, t, to_vertical_coordinates(x), vertical_derivative(x, f0), dt);
      return from_vertical_coordinates(y1, heading_rad);
    }
    return runge_kutta4_step(derivative, t, x, f0, dt);
  }

  double altitude_ft(const StateVector& x) const {
    return oblate_altitude_ft(mission_.constants, x[kStateR], x[kStateLambda]);
  }

 private:
  const Mission& mission_;
  const PreparedCase& prepared_;
  const StageContext& stage_;
  StepCommand command_;
};

// The limits of INTPIM's steps, all finite and > 0.
Status check_steps(const ImpactStepSizes& s, ImpactFault* fault) {
  const double positive[] = {s.in_atmosphere_s,
                             s.out_of_atmosphere_s,
                             s.reentered_s,
                             s.terminal_velocity_s,
                             s.max_drag_velocity_fraction,
                             s.min_step_s,
                             s.terminal_velocity_tolerance,
                             s.max_flight_s};
  const char* const names[] = {"in_atmosphere_s",
                               "out_of_atmosphere_s",
                               "reentered_s",
                               "terminal_velocity_s",
                               "max_drag_velocity_fraction",
                               "min_step_s",
                               "terminal_velocity_tolerance",
                               "max_flight_s"};
  for (int i = 0; i < static_cast<int>(sizeof(positive) / sizeof(positive[0])); ++i) {
    if (!(std::isfinite(positive[i]) && positive[i] > 0.0)) {
      return fault_at(fault, Status::kImpactStepSizeNotPositive, 0, 0, names[i], positive[i], "> 0");
    }
  }
  return Status::kOk;
}

Status check_casing(const ImpactLocusData& data, int stage, ImpactFault* fault) {
  const int k = stage - 1;
  return check_body(data.expended_casing[k], 43, stage, kCasingTableNames[k], true, fault);
}

}  // namespace

Status validate_casing_data(const Mission& mission, const ImpactLocusData& data,
                            const bool (&stages)[kImpactStages], ImpactFault* fault) {
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    if (!stages[stage - 1] || !mission.vehicle.stages[stage_index(stage)].in_sequence) {
      continue;
    }
    const Status status = check_casing(data, stage, fault);
    if (!ok(status)) {
      return status;
    }
  }
  return check_steps(data.steps, fault);
}

Status validate_impact_data(const Mission& mission, const ImpactLocusData& data, ImpactFault* fault) {
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    const StageData& flown = mission.vehicle.stages[stage_index(stage)];
    if (!flown.in_sequence) continue;
    const int k = stage - 1;
    Status status = check_body(data.failure_mode[k], 42, stage, kFailureTableNames[k], false, fault);
    if (!ok(status)) return status;
    status = check_casing(data, stage, fault);
    if (!ok(status)) return status;
    const int n = data.every_nth_point[k];
    if (n < 1 || n > flown.integration_steps) {
      return fault_at(fault, Status::kImpactEveryNthPointOutOfRange, 33, stage, kStepRateWords[k], n,
                      "n between 1 and the stage's integration steps (data block 16): a larger n puts "
                      "the first failure point after the lift-off past the end of the stage");
    }
  }
  return check_steps(data.steps, fault);
}

Status fly_to_impact(const Mission& mission, const PreparedCase& prepared, const ImpactBody& body,
                     double weight_lb, double t0_s, const StateVector& state0, const ImpactStepSizes& steps,
                     StageData* scratch, ImpactFlight* out) {
  *out = ImpactFlight{};
  if (!(weight_lb > 0.0) || !state0.allFinite() || !std::isfinite(t0_s)) {
    return out->status = Status::kImpactStartInvalid;
  }
  load_body_stage(body, scratch);
  StageContext stage;
  stage.code = kImpactStageCode;
  stage.start_s = t0_s;
  stage.data = scratch;
  stage.thrust = nullptr;
  stage.weight_above_consumable_lb = weight_lb;
  EvaluationScratch memo;  // the drag table's interval, the held attitude's sine and cosine
  stage.scratch = &memo;
  const BallisticFlight flight(mission, prepared, stage);
  const double g0 = mission.constants.g0_ft_s2;
  const double mass_slug = weight_lb / g0;
  const double haero_ft = mission.constants.haero_ft;

  double t = t0_s;
  StateVector x = state0;
  Evaluation eval;
  flight.evaluate(t, x, &eval);
  if (!eval.derivative.allFinite()) return out->status = Status::kNonFiniteState;
  if (eval.altitude_ft < 0.0) return out->status = Status::kImpactStartBelowSurface;
  out->max_altitude_ft = eval.altitude_ft;
  bool left_atmosphere = false;
  bool terminal = false;

  while (t - t0_s < steps.max_flight_s) {
    // INTPIM's regime at the start of the step, from the altitude and the drag acceleration.
    const double v = x[kStateV];
    const double drag_accel = eval.drag_lbf / mass_slug;
    if (eval.altitude_ft > haero_ft) left_atmosphere = true;
    const bool in_air = eval.altitude_ft <= haero_ft;
    const bool descending = x[kStateGamma] < 0.0;
    // Terminal velocity: drag balancing gravity, and quasi-steady - the relaxation time V / g short
    // against the time to fall through a density scale height, V^2 < 0.1 g0 H (the balance passed
    // through at re-entry speed is not one).
    if (in_air && descending && drag_accel > 0.5 * g0 && v * v < 0.1 * g0 * kDensityScaleHeightFt &&
        std::fabs(eval.derivative[kStateV]) < steps.terminal_velocity_tolerance * g0) {
      terminal = true;  // MTERMG: once at terminal velocity, it stays (the air only thickens)
    }
    ImpactRegime regime = !in_air           ? ImpactRegime::kOutOfAtmosphere
                          : terminal        ? ImpactRegime::kTerminalVelocity
                          : left_atmosphere ? ImpactRegime::kReentered
                                            : ImpactRegime::kInAtmosphere;
    double dt = 0.0;
    switch (regime) {
      case ImpactRegime::kInAtmosphere: dt = steps.in_atmosphere_s; break;
      case ImpactRegime::kReentered: dt = steps.reentered_s; break;
      case ImpactRegime::kTerminalVelocity: dt = steps.terminal_velocity_s; break;
      case ImpactRegime::kOutOfAtmosphere: {
        dt = steps.out_of_atmosphere_s;
        // Descending: end the step just below HAERO, so that the drag does not switch on deep
        // inside a long vacuum step.
        const double sink_ft_s = -v * std::sin(x[kStateGamma]);
        if (sink_ft_s > 0.0) dt = std::fmin(dt, (eval.altitude_ft - haero_ft) / sink_ft_s + kPastHaeroS);
        break;
      }
    }
    if (regime == ImpactRegime::kInAtmosphere || regime == ImpactRegime::kReentered) {
      dt = std::fmin(dt, steps.max_drag_velocity_fraction * v / std::fmax(drag_accel, g0));
      // The density, and the drag with it, changes e-fold per scale height: a step falls, or climbs
      // while the drag still matters, at most a quarter of one.
      const double climb_ft_s = v * std::sin(x[kStateGamma]);
      if (climb_ft_s < 0.0 || drag_accel > 1e-3 * g0) {
        dt = std::fmin(dt, 0.25 * kDensityScaleHeightFt / std::fmax(std::fabs(climb_ft_s), 1.0));
      }
      // Climbing out: end the step just above HAERO, where the drag switches off (as on the way in).
      if (climb_ft_s > 0.0) dt = std::fmin(dt, (haero_ft - eval.altitude_ft) / climb_ft_s + kPastHaeroS);
    }
    dt = std::fmax(dt, steps.min_step_s);

    const StateVector x1 = flight.step(t, x, eval.derivative, dt);
    if (!x1.allFinite()) return out->status = Status::kNonFiniteState;
    const double h1 = flight.altitude_ft(x1);
    ++out->steps;
    ++out->regime_steps[static_cast<int>(regime)];
    if (h1 > 0.0) {
      t += dt;
      x = x1;
      flight.evaluate(t, x, &eval);
      if (!eval.derivative.allFinite()) return out->status = Status::kNonFiniteState;
      out->max_altitude_ft = std::fmax(out->max_altitude_ft, eval.altitude_ft);
      continue;
    }

    // The surface lies inside this step: the step length tau with h(step(tau)) = 0, by regula
    // falsi (Illinois) on the bracket [0 (h0 > 0), dt (h1 <= 0)], each trial a fresh step of length
    // tau from the step's start, so the crossing is a point of the integrated flight.
    double lo = 0.0, f_lo = eval.altitude_ft;  // f: the Illinois-weighted altitudes
    double hi = dt, f_hi = h1;
    double h_hit = h1;  // the altitude of x_hit, the trial at `hi`
    StateVector x_hit = x1;
    int side = 0;
    for (int i = 0;
         i < kMaxCrossingIterations && std::fabs(h_hit) > kCrossingAltitudeFt && hi - lo > kCrossingTimeS;
         ++i) {
      double tau = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
      if (!(tau > lo && tau < hi)) tau = 0.5 * (lo + hi);
      const StateVector trial = flight.step(t, x, eval.derivative, tau);
      if (!trial.allFinite()) return out->status = Status::kNonFiniteState;
      const double h = flight.altitude_ft(trial);
      if (h > 0.0) {
        lo = tau;
        f_lo = h;
        if (side == -1) f_hi *= 0.5;
        side = -1;
      } else {
        hi = tau;
        f_hi = h;
        h_hit = h;
        x_hit = trial;
        if (side == 1) f_lo *= 0.5;
        side = 1;
      }
      if (std::fabs(h) <= kCrossingAltitudeFt) {  // converged from above: take that trial
        hi = tau;
        h_hit = h;
        x_hit = trial;
      }
    }
    out->impact_time_s = t + hi;
    out->impact_state = x_hit;
    out->reached_terminal_velocity = terminal;
    return out->status = Status::kOk;
  }
  return out->status = Status::kImpactNotReached;
}

double launch_crossrange_angle_rad(double launch_latitude_rad, double launch_longitude_rad,
                                   double launch_azimuth_rad, double latitude_rad, double longitude_rad) {
  // Spherical cross-track distance: sin(XT) = sin(DR) sin(beta - psi0), beta the initial bearing
  // from the launch point to the point, psi0 the launch azimuth (both east of north).
  const double d_lon = longitude_rad - launch_longitude_rad;
  const double bearing =
      std::atan2(std::sin(d_lon) * std::cos(latitude_rad),
                 std::cos(launch_latitude_rad) * std::sin(latitude_rad) -
                     std::sin(launch_latitude_rad) * std::cos(latitude_rad) * std::cos(d_lon));
  const double range =
      downrange_angle_rad(launch_latitude_rad, launch_longitude_rad, latitude_rad, longitude_rad);
  const double s = std::sin(range) * std::sin(bearing - launch_azimuth_rad);
  return std::asin(std::fmax(-1.0, std::fmin(1.0, s)));
}

Status fly_impact_case(const Mission& mission, const PreparedCase& prepared,
                       const LaunchConditions& range_origin, const Trajectory& flight, ImpactKind kind,
                       int stage, int point, const ImpactBody& body, double weight_lb,
                       const ImpactStepSizes& steps, ImpactWorkspace* workspace, ImpactCase* out) {
  const Constants& constants = mission.constants;
  const TrajectoryPoint& p = flight.points[point];
  ImpactCase& c = *out;
  c = ImpactCase{};
  c.kind = kind;
  c.stage = stage;
  c.nominal_point = point;
  c.failure_time_s = p.time_s;
  c.weight_lb = weight_lb;
  ImpactFlight body_flight;
  c.status = fly_to_impact(mission, prepared, body, weight_lb, p.time_s, p.state, steps,
                           &workspace->body_stage, &body_flight);
  c.steps = body_flight.steps;
  c.max_altitude_ft = body_flight.max_altitude_ft;
  if (!ok(c.status)) {
    return c.status;
  }
  const StateVector& x = body_flight.impact_state;
  c.impact_time_s = body_flight.impact_time_s;
  c.geocentric_latitude_rad = x[kStateLambda];
  c.geodetic_latitude_rad = geodetic_from_geocentric_rad(constants, x[kStateLambda]);
  c.longitude_rad = std::remainder(
      x[kStateTau] - constants.earth_rotation_rate_rad_s * body_flight.impact_time_s, 2.0 * kPi);
  c.downrange_rad = downrange_angle_rad(range_origin.geocentric_latitude_rad, range_origin.longitude_rad,
                                        c.geocentric_latitude_rad, c.longitude_rad);
  c.crossrange_rad =
      launch_crossrange_angle_rad(range_origin.geocentric_latitude_rad, range_origin.longitude_rad,
                                  range_origin.azimuth_rad, c.geocentric_latitude_rad, c.longitude_rad);
  c.impact_velocity_ft_s = x[kStateV];
  c.impact_flight_path_angle_rad = x[kStateGamma];
  c.reached_terminal_velocity = body_flight.reached_terminal_velocity;
  return c.status;
}

namespace {

// The events of stages 1-3 in `flight` (null: not flown).
void stage_events(const Trajectory& flight, const StageEvent* (&events)[kImpactStages]) {
  for (const StageEvent*& e : events) {
    e = nullptr;
  }
  for (int k = 0; k < flight.stage_count; ++k) {
    const StageEvent& e = flight.stages[k];
    if (e.code >= 1 && e.code <= kImpactStages) {
      events[e.code - 1] = &e;
    }
  }
}

}  // namespace

Status fly_expended_casings(const Mission& mission, const PreparedCase& prepared,
                            const LaunchConditions& range_origin, const Trajectory& flight,
                            const ImpactLocusData& data, const bool (&stages)[kImpactStages],
                            const double* weight_change_lb, ImpactWorkspace* workspace,
                            ImpactCase (&cases)[kImpactStages], int* count) {
  *count = 0;
  const StageEvent* events[kImpactStages];
  stage_events(flight, events);
  Status first_failure = Status::kOk;
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    if (!stages[stage - 1]) {
      continue;
    }
    const StageEvent* e = events[stage - 1];
    if (e == nullptr || !e->completed) {
      if (ok(first_failure)) {
        first_failure = Status::kImpactNominalStageIncomplete;
      }
      continue;
    }
    const ImpactBody& body = data.expended_casing[stage - 1];
    const double weight_lb =
        body.casing_weight_lb + (weight_change_lb != nullptr ? weight_change_lb[stage - 1] : 0.0);
    const Status status =
        fly_impact_case(mission, prepared, range_origin, flight, ImpactKind::kExpendedCasing, stage,
                        e->last_point, body, weight_lb, data.steps, workspace, &cases[(*count)++]);
    if (!ok(status) && ok(first_failure)) {
      first_failure = status;
    }
  }
  return first_failure;
}

Status compute_impact_locus(const Mission& mission, const PreparedCase& prepared, const Trajectory& nominal,
                            const ImpactLocusData& data, ImpactWorkspace* workspace, ImpactLocus* locus) {
  locus->count = 0;
  Status status = validate_impact_data(mission, data, nullptr);
  if (!ok(status)) {
    return locus->status = status;
  }
  if (!ok(nominal.status)) {
    return locus->status = Status::kImpactNominalFailed;
  }

  const Constants& constants = mission.constants;
  const LaunchConditions& launch = mission.launch;
  const StageEvent* events[kImpactStages];
  stage_events(nominal, events);
  bool flown[kImpactStages] = {};
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    if (!mission.vehicle.stages[stage_index(stage)].in_sequence) {
      continue;
    }
    const StageEvent* e = events[stage - 1];
    if (e == nullptr || !e->completed) {
      return locus->status = Status::kImpactNominalStageIncomplete;
    }
  }
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    flown[stage - 1] = events[stage - 1] != nullptr;
  }

  // Thrust failures: every n-th integration point of the stage, from its first point (stage 1: from
  // the end of the vertical lift-off: the pad point has no flight to fail), up to the last step's
  // start (the end point is the burnout).
  Status first_failure = Status::kOk;
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    const StageEvent* e = events[stage - 1];
    if (e == nullptr) {
      continue;
    }
    int first = e->first_point;
    if (stage == 1) {
      while (first < e->last_point &&
             nominal.points[first].time_s + 0.5 * constants.time_epsilon_s < launch.liftoff_duration_s) {
        ++first;
      }
    }
    const int n = data.every_nth_point[stage - 1];
    for (int point = first; point < e->last_point && locus->count < kMaxImpactCases; point += n) {
      status = fly_impact_case(mission, prepared, launch, nominal, ImpactKind::kThrustFailure, stage, point,
                               data.failure_mode[stage - 1], nominal.points[point].weight_lb, data.steps,
                               workspace, &locus->cases[locus->count++]);
      if (!ok(status) && ok(first_failure)) {
        first_failure = status;
      }
    }
  }
  // The expended casings, from their stages' burnout points (as the Monte Carlo flies its samples').
  ImpactCase casings[kImpactStages];
  int casing_count = 0;
  status = fly_expended_casings(mission, prepared, launch, nominal, data, flown, nullptr, workspace, casings,
                                &casing_count);
  if (!ok(status) && ok(first_failure)) {
    first_failure = status;
  }
  for (int k = 0; k < casing_count && locus->count < kMaxImpactCases; ++k) {
    locus->cases[locus->count++] = casings[k];
  }
  return locus->status = first_failure;
}

}  // namespace tolip
