// Failure-mode hardover turns, manual Sec. 16 (docs/theory/hardover.md).
#include "tolip/hardover/hardover.hpp"

#include <cmath>

#include "tolip/body/body_dynamics.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/stage_codes.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"

namespace tolip {

namespace {

constexpr double kTurnLimit_s = 10.0;           // "until ten seconds has elapsed"
constexpr double kAfterQbarAlphaLimit_s = 1.0;  // "stops one second after (q-bar alpha)max"
constexpr double kTumblingAlpha_rad = 0.5 * kPi;
constexpr double kMinimumSpeed_ft_s = 1.0;  // the pad point does not move: no turn from it
// Times closer than this are one time (an output or a limit reached by a clamped step).
constexpr double kTimeTolerance_s = 1e-9;

bool finite_stage(const HardoverStage& s) {
  return std::isfinite(s.max_attitude_step_rad) && std::isfinite(s.max_step_s) &&
         std::isfinite(s.min_step_s) && std::isfinite(s.thrust_misalignment_rad) &&
         std::isfinite(s.thrust_station_ft) && std::isfinite(s.single_jet_force_lbf) &&
         std::isfinite(s.pitch_yaw_jet_force_lbf) && std::isfinite(s.control_jet_station_ft);
}

// Block 45 word of stage k's entry (words 1-6 for stage 1, 21-26 for the upper stages).
int stage_word(int stage, int stage1_word, int upper_word) { return stage == 1 ? stage1_word : upper_word; }

Status fail(HardoverFault* fault, Status status, int block, int word, int stage) {
  if (fault != nullptr) *fault = HardoverFault{block, word, stage};
  return status;
}

bool in_sequence(const Mission& mission, int code) {
  return mission.vehicle.stages[stage_index(code)].in_sequence;
}

int timeline_slot(const PreparedCase& prepared, int code) {
  for (int i = 0; i < prepared.stage_count; ++i) {
    if (prepared.timeline[i].code == code) return i;
  }
  return -1;
}

}  // namespace

const char* hardover_stop_name(HardoverStop stop) {
  switch (stop) {
    case HardoverStop::kTimeLimit: return "TIME LIMIT";
    case HardoverStop::kQbarAlphaLimit: return "QBAR-ALPHA MAX";
    case HardoverStop::kTumbling: return "TUMBLING";
    case HardoverStop::kEndOfStage: return "END OF STAGE";
    case HardoverStop::kStepLimit: return "STEP LIMIT";
  }
  return "UNKNOWN";
}

Status validate_hardover_data(const Mission& mission, const HardoverData& data, HardoverFault* fault) {
  if (!std::isfinite(data.max_qbar_alpha_lbf_rad_ft2) || !std::isfinite(data.fin_vane_deflection_rad) ||
      !std::isfinite(data.output_interval_s)) {
    return fail(fault, Status::kHardoverValueNotFinite, 45, 0, 0);
  }
  if (!(data.max_qbar_alpha_lbf_rad_ft2 > 0.0)) {
    return fail(fault, Status::kHardoverQbarAlphaLimitInvalid, 45, 2, 1);
  }
  if (!(data.output_interval_s * (kMaxHardoverSamples - 2) >= kTurnLimit_s - kTimeTolerance_s)) {
    return fail(fault, Status::kHardoverOutputIntervalTooSmall, 45, 20, 0);
  }
  const BodyDynamicsBlocks& body = mission.body_dynamics;
  for (int stage = 1; stage <= 3; ++stage) {
    if (!in_sequence(mission, stage)) continue;
    const HardoverStage& s = data.stages[stage - 1];
    if (!finite_stage(s)) return fail(fault, Status::kHardoverValueNotFinite, 45, 0, stage);
    if (s.every_nth_step < 1) {
      return fail(fault, Status::kHardoverEveryNthStepInvalid, 45, stage == 1 ? 1 : 19 + stage, stage);
    }
    if (!(s.min_step_s > 0.0) || !(s.max_step_s >= s.min_step_s)) {
      return fail(fault, Status::kHardoverStepLimitsInvalid, 45, stage_word(stage, 5, 25), stage);
    }
    if (!(s.max_attitude_step_rad > 0.0)) {
      return fail(fault, Status::kHardoverAttitudeStepInvalid, 45, stage_word(stage, 3, 23), stage);
    }
    if (s.max_steps_per_turn < 1) {
      return fail(fault, Status::kHardoverMaxStepsInvalid, 45, stage_word(stage, 6, 26), stage);
    }
    if (s.pitch_inertia_slug_ft2.empty() || !s.pitch_inertia_slug_ft2.finalized()) {
      return fail(fault, Status::kHardoverInertiaMissing, 44, 0, stage);
    }
    for (int i = 0; i < s.pitch_inertia_slug_ft2.size(); ++i) {
      if (!(s.pitch_inertia_slug_ft2.y(i) > 0.0)) {
        return fail(fault, Status::kHardoverInertiaNotPositive, 44, 0, stage);
      }
    }
    if (body.cg_station_ft[stage - 1].empty()) {
      return fail(fault, Status::kHardoverBodyDataMissing, 37, 0, stage);
    }
  }
  if (in_sequence(mission, 1)) {
    if (data.pitch_damping_per_rad.empty() || !data.pitch_damping_per_rad.finalized()) {
      return fail(fault, Status::kHardoverDampingTableMissing, 44, 0, 4);
    }
    if (!body.present || !(body.reference_length_ft > 0.0) || !(body.reference_area_ft2 > 0.0)) {
      return fail(fault, Status::kHardoverBodyDataMissing, 33, 16, 1);
    }
  }
  return Status::kOk;
}

RigidBodyMoment rigid_body_moment(const Mission& mission, const HardoverData& data, const Evaluation& ev,
                                  const RigidBodyInputs& in) {
  RigidBodyMoment out;
  const int code = in.body_stage;
  const HardoverStage& stage = data.stages[code - 1];
  const BodyDynamicsBlocks& body = mission.body_dynamics;
  const Constants& constants = mission.constants;
  const bool stage1 = code == 1;
  double consumable_slope_lb_s = 0.0;
  if (in.flown != nullptr && !in.flown->consumable_weight_lb.empty()) {
    (void)in.flown->consumable_weight_lb.value_and_slope(in.flown_stage_time_s, &consumable_slope_lb_s);
  }
  const double mass_rate_slug_s = consumable_slope_lb_s / constants.g0_ft_s2;
  double inertia_rate = 0.0;
  const double inertia_slug_ft2 =
      stage.pitch_inertia_slug_ft2.value_and_slope(in.body_stage_time_s, &inertia_rate);
  const double alpha_rad = in.alpha_rad;
  const double thrust_lbf = ev.net_thrust_lbf;
  const double alpha_t_rad = in.misalignment_rad;
  const double delta_rad = in.deflection_rad;
  const double jet_force_lbf = in.jet_force_lbf;
  const double eta_rate_rad_s = in.rate_rad_s;
  const double v_ft_s = in.speed_ft_s;

  // Atmosphere (stage 1 only): q, drag, lift, restoring and damping moments.
  const double q_lbf_ft2 = stage1 ? ev.dynamic_pressure_lbf_ft2 : 0.0;
  MomentConditions conditions;
  conditions.stage = code;
  conditions.cg_stage_time_s = in.body_stage_time_s;
  conditions.mach = ev.mach;
  conditions.dynamic_pressure_lbf_ft2 = q_lbf_ft2;
  conditions.vacuum_thrust_lbf = ev.vacuum_thrust_lbf;
  const bool lift = stage1 && in.flown != nullptr && q_lbf_ft2 > 0.0 && in.flown->uses_lift_table &&
                    !mission.vehicle.lift_curve_slope_per_rad.empty();
  const double c_l_alpha = lift ? mission.vehicle.lift_curve_slope_per_rad(ev.mach) : 0.0;
  conditions.normal_force_slope_per_rad = c_l_alpha;
  const UnitMoments moments = unit_moments(body, conditions);
  const double x_cg_ft = moments.cg_station_ft;

  double normal_force_lbf = 0.0;  // FORCEN
  double moment_lbf_ft = 0.0;
  double lift_lbf = 0.0;
  if (stage1) {
    lift_lbf = q_lbf_ft2 * in.flown->reference_area_ft2 * c_l_alpha * alpha_rad;
    const double fin_force_lbf =
        q_lbf_ft2 > 0.0 ? body.fin_normal_force_per_rad(ev.mach) * q_lbf_ft2 * body.reference_area_ft2 : 0.0;
    normal_force_lbf = -thrust_lbf * alpha_t_rad -
                       delta_rad * body.control_surfaces_per_plane *
                           (fin_force_lbf + ev.vacuum_thrust_lbf * body.jet_vane_effectiveness_per_rad);
    const double l_ref = body.reference_length_ft;
    const double pitch_damping = q_lbf_ft2 > 0.0 ? aerodynamic_pitch_damping_moment(
                                                       data.pitch_damping_per_rad(ev.mach), eta_rate_rad_s,
                                                       l_ref, q_lbf_ft2, body.reference_area_ft2, v_ft_s)
                                                 : 0.0;
    moment_lbf_ft = delta_rad * moments.m_delta_lbf_ft_per_rad +                      // 1. control deflection
                    thrust_lbf * alpha_t_rad * (stage.thrust_station_ft - x_cg_ft) +  // 2. misalignment
                    alpha_rad * moments.m_alpha_lbf_ft_per_rad +                      // 3. angle of attack
                    pitch_damping;                                                    // 4. pitch damping
  } else {
    // Modes 1-3 (Sec. 16) take one of the two terms; the bench may apply both (a misaligned stage
    // steered by its jets). A term whose force is zero adds an exact zero.
    normal_force_lbf = -thrust_lbf * alpha_t_rad - jet_force_lbf;
    moment_lbf_ft = thrust_lbf * alpha_t_rad * (stage.thrust_station_ft - x_cg_ft) +  // 2. misalignment
                    jet_force_lbf * (stage.control_jet_station_ft - x_cg_ft);         // 6. control jets
  }
  // 5. jet damping, every stage.
  const double jet_arm_ft = x_cg_ft - stage.thrust_station_ft;
  moment_lbf_ft += jet_damping_moment(eta_rate_rad_s, mass_rate_slug_s, jet_arm_ft, inertia_rate);

  out.moment_lbf_ft = moment_lbf_ft;
  out.normal_force_lbf = normal_force_lbf;
  out.lift_lbf = lift_lbf;
  out.dynamic_pressure_lbf_ft2 = q_lbf_ft2;
  out.inertia_slug_ft2 = inertia_slug_ft2;
  out.cg_station_ft = x_cg_ft;
  return out;
}

Status compute_hardover_turn(const Mission& mission, const PreparedCase& prepared,
                             const Trajectory& trajectory, const HardoverData& data, int point,
                             HardoverMode mode, HardoverDirection direction, HardoverTurn* turn) {
  turn->sample_count = 0;
  turn->steps = 0;
  if (point < 0 || point >= trajectory.point_count) return Status::kHardoverPointInvalid;
  const TrajectoryPoint& p = trajectory.points[point];
  const int code = p.stage_code;
  const int slot = timeline_slot(prepared, code);
  if (code < 1 || code > 3 || slot < 0 || !(p.state[kStateV] >= kMinimumSpeed_ft_s) ||
      (code == 1) != (mode == HardoverMode::kFinsAndVanes)) {
    return Status::kHardoverPointInvalid;
  }
  const StageTimeline& line = prepared.timeline[slot];
  if (!(p.stage_time_s < line.duration_s - kTimeTolerance_s)) return Status::kHardoverPointInvalid;
  const StageContext context = make_stage_context(mission, prepared, line);
  const HardoverStage& stage = data.stages[code - 1];
  const Constants& constants = mission.constants;
  const double sign = static_cast<double>(static_cast<int>(direction));

  turn->stage = code;
  turn->mode = mode;
  turn->nominal_point = point;
  turn->failure_time_s = p.time_s;

  // The over-turning force and its lever (Sec. 16): stage 1 the deflection delta and the additive
  // misalignment; upper stages the misalignment (mode 1) or a control-jet force (modes 2, 3).
  const bool stage1 = code == 1;
  const bool misaligned = stage1 || mode == HardoverMode::kThrustMisalignment;
  const double alpha_t_rad = misaligned ? sign * stage.thrust_misalignment_rad : 0.0;
  const double delta_rad = stage1 ? sign * data.fin_vane_deflection_rad : 0.0;
  const double jet_force_lbf = mode == HardoverMode::kSingleJet         ? sign * stage.single_jet_force_lbf
                               : mode == HardoverMode::kPitchAndYawJets ? sign * stage.pitch_yaw_jet_force_lbf
                                                                        : 0.0;
  // g and, for the upper stages, sin gamma held at their values at the start (Sec. 16).
  const double r0_ft = p.state[kStateR];
  const double g_ft_s2 = constants.gravitational_parameter_ft3_s2 / (r0_ft * r0_ft);
  const double gamma0_rad = p.state[kStateGamma];
  const double sin_gamma0 = std::sin(gamma0_rad);

  StateVector state = p.state;  // psi, lambda, tau held: the turn is two-dimensional
  double v_ft_s = p.state[kStateV];
  double gamma_rad = gamma0_rad;
  double r_ft = r0_ft;
  double eta_rad = gamma0_rad;  // eta_0 = gamma_0
  double eta_rate_rad_s = 0.0;
  double elapsed_s = 0.0;
  double next_output_s = 0.0;
  double limit_reached_at_s = -1.0;  // when |q-bar alpha| first reached (q-bar alpha)max

  StepCommand held;
  held.mode = AttitudeMode::kHeld;
  held.theta_start_rad = p.theta_rad;
  held.theta_end_rad = p.theta_rad;
  held.chi_rad = p.chi_rad;

  for (;;) {
    const double t_s = p.time_s + elapsed_s;
    const double stage_time_s = p.stage_time_s + elapsed_s;
    state[kStateV] = v_ft_s;
    state[kStateGamma] = gamma_rad;
    state[kStateR] = r_ft;
    held.step_start_s = t_s;
    Evaluation ev;
    evaluate_flight(mission, prepared, context, held, t_s, state, 0.0, &ev);
    const double mass_slug = ev.weight_lb / constants.g0_ft_s2;
    const double alpha_rad = eta_rad - gamma_rad;
    const double thrust_lbf = ev.net_thrust_lbf;
    RigidBodyInputs body_inputs;
    body_inputs.body_stage = code;
    body_inputs.body_stage_time_s = stage_time_s;
    body_inputs.flown = context.data;
    body_inputs.flown_stage_time_s = stage_time_s;
    body_inputs.alpha_rad = alpha_rad;
    body_inputs.rate_rad_s = eta_rate_rad_s;
    body_inputs.speed_ft_s = v_ft_s;
    body_inputs.deflection_rad = delta_rad;
    body_inputs.misalignment_rad = alpha_t_rad;
    body_inputs.jet_force_lbf = jet_force_lbf;
    const RigidBodyMoment loads = rigid_body_moment(mission, data, ev, body_inputs);
    const double q_lbf_ft2 = loads.dynamic_pressure_lbf_ft2;
    const double drag_lbf = stage1 ? ev.drag_lbf : 0.0;
    const double lift_lbf = loads.lift_lbf;
    const double normal_force_lbf = loads.normal_force_lbf;
    const double moment_lbf_ft = loads.moment_lbf_ft;
    const double inertia_slug_ft2 = loads.inertia_slug_ft2;

    // The thrust along the body axis is reduced by the misalignment (HARDOVR).
    const double axial_thrust_lbf = thrust_lbf * std::cos(alpha_t_rad);
    const double sin_gamma = stage1 ? std::sin(gamma_rad) : sin_gamma0;
    const double sin_alpha = std::sin(alpha_rad), cos_alpha = std::cos(alpha_rad);
    const double v_dot =
        (axial_thrust_lbf * cos_alpha - drag_lbf - normal_force_lbf * sin_alpha) / mass_slug -
        g_ft_s2 * sin_gamma;
    const double gamma_dot =
        (axial_thrust_lbf * sin_alpha + lift_lbf + normal_force_lbf * cos_alpha) / (mass_slug * v_ft_s);
    const double r_dot = v_ft_s * sin_gamma;
    const double eta_acceleration = moment_lbf_ft / inertia_slug_ft2;
    const double qbar_alpha = q_lbf_ft2 * alpha_rad;

    // The output line at this time, then the stops.
    const bool tumbling = std::fabs(alpha_rad) >= kTumblingAlpha_rad;
    if (limit_reached_at_s < 0.0 && std::fabs(qbar_alpha) >= data.max_qbar_alpha_lbf_rad_ft2) {
      limit_reached_at_s = elapsed_s;
    }
    bool stop = true;
    // Two branches stop as tumbling on purpose (an attitude past the limit, and equations that
    // lose meaning); they are kept apart because their conditions differ in kind.
    if (stage_time_s >= line.duration_s - kTimeTolerance_s) {
      turn->stop = HardoverStop::kEndOfStage;
    } else if (elapsed_s >= kTurnLimit_s - kTimeTolerance_s) {
      turn->stop = HardoverStop::kTimeLimit;
    } else if (tumbling) {  // NOLINT(bugprone-branch-clone): the same stop as below, on purpose
      turn->stop = HardoverStop::kTumbling;
    } else if (limit_reached_at_s >= 0.0 &&
               elapsed_s >= limit_reached_at_s + kAfterQbarAlphaLimit_s - kTimeTolerance_s) {
      turn->stop = HardoverStop::kQbarAlphaLimit;
    } else if (turn->steps >= stage.max_steps_per_turn) {
      turn->stop = HardoverStop::kStepLimit;
    } else if (!std::isfinite(v_dot) || !std::isfinite(gamma_dot) || !std::isfinite(eta_acceleration) ||
               !(v_ft_s >= kMinimumSpeed_ft_s)) {
      turn->stop = HardoverStop::kTumbling;  // the equations lose meaning: the vehicle is out of control
    } else {
      stop = false;
    }
    if (stop || elapsed_s >= next_output_s - kTimeTolerance_s) {
      if (turn->sample_count < kMaxHardoverSamples) {
        HardoverSample& sample = turn->samples[turn->sample_count++];
        sample.time_s = elapsed_s;
        sample.change_in_gamma_rad = gamma_rad - gamma0_rad;
        sample.qbar_alpha_lbf_rad_ft2 = qbar_alpha;
        sample.attitude_change_rad = eta_rad - gamma0_rad;
        sample.attitude_rate_rad_s = eta_rate_rad_s;
      }
      while (next_output_s <= elapsed_s + kTimeTolerance_s) next_output_s += data.output_interval_s;
    }
    if (stop) return Status::kOk;

    // Euler step within (delta theta)max, (DT)min <= dt <= (DT)max, ending on the next output time,
    // the ten-second limit, the end of the stage and the second after the q-bar alpha limit.
    double dt_s = stage.max_step_s;
    if (std::fabs(eta_rate_rad_s) * dt_s > stage.max_attitude_step_rad) {
      dt_s = stage.max_attitude_step_rad / std::fabs(eta_rate_rad_s);
    }
    if (dt_s < stage.min_step_s) dt_s = stage.min_step_s;
    double until_s = next_output_s;
    if (kTurnLimit_s < until_s) until_s = kTurnLimit_s;
    if (line.duration_s - p.stage_time_s < until_s) until_s = line.duration_s - p.stage_time_s;
    if (limit_reached_at_s >= 0.0 && limit_reached_at_s + kAfterQbarAlphaLimit_s < until_s) {
      until_s = limit_reached_at_s + kAfterQbarAlphaLimit_s;
    }
    if (elapsed_s + dt_s > until_s) dt_s = until_s - elapsed_s;
    v_ft_s += dt_s * v_dot;
    gamma_rad += dt_s * gamma_dot;
    r_ft += dt_s * r_dot;
    eta_rad += dt_s * eta_rate_rad_s;
    eta_rate_rad_s += dt_s * eta_acceleration;
    elapsed_s += dt_s;
    ++turn->steps;
  }
}

Status compute_hardover_turns(const Mission& mission, const PreparedCase& prepared,
                              const Trajectory& trajectory, const HardoverData& data, HardoverResult* result,
                              HardoverFault* fault) {
  result->turn_count = 0;
  const Status valid = validate_hardover_data(mission, data, fault);
  if (!ok(valid)) return valid;
  for (int e = 0; e < trajectory.stage_count; ++e) {
    const StageEvent& event = trajectory.stages[e];
    if (event.code < 1 || event.code > 3) continue;
    const HardoverStage& stage = data.stages[event.code - 1];
    for (int point = event.first_point; point < event.last_point; point += stage.every_nth_step) {
      const TrajectoryPoint& p = trajectory.points[point];
      if (p.stage_code != event.code || !(p.state[kStateV] >= kMinimumSpeed_ft_s)) continue;
      const HardoverMode first =
          event.code == 1 ? HardoverMode::kFinsAndVanes : HardoverMode::kThrustMisalignment;
      const HardoverMode last =
          event.code == 1 ? HardoverMode::kFinsAndVanes : HardoverMode::kPitchAndYawJets;
      for (int m = static_cast<int>(first); m <= static_cast<int>(last); ++m) {
        if (result->turn_count >= kMaxHardoverTurns) {
          return fail(fault, Status::kTooManyHardoverTurns, 45, 0, event.code);
        }
        HardoverTurn& turn = result->turns[result->turn_count];
        const Status status =
            compute_hardover_turn(mission, prepared, trajectory, data, point, static_cast<HardoverMode>(m),
                                  HardoverDirection::kNoseUp, &turn);
        if (!ok(status)) continue;  // a point at the very end of its stage: no turn
        ++result->turn_count;
      }
    }
  }
  return Status::kOk;
}

}  // namespace tolip
