// Body dynamics (manual Sec. 7, 11): body_dynamics.hpp, docs/theory/body-dynamics.md.
#include "tolip/body/body_dynamics.hpp"

#include <cmath>

#include "tolip/frames/frames.hpp"

namespace tolip {
namespace {

// Below this relative size K_theta M_delta - M_alpha has no stable steady state (eq. 7-6).
constexpr double kTrimTolerance = 1.0e-9;
// Below this lever (ft) the control force of Sec. 11 is not defined; validate_body_dynamics keeps
// the stage-1 control station outside the c.g. range, so only hand-made data reach it.
constexpr double kMinimumLeverFt = 1.0e-6;

int clamp_stage(int stage) {
  if (stage < 1) return 1;
  if (stage > kBodyDynamicsStages) return kBodyDynamicsStages;
  return stage;
}

}  // namespace

AutopilotGains scheduled_stage1_gains(const BodyDynamicsBlocks& data, double stage_time_s) {
  AutopilotGains g;
  g.position_gain = data.position_gain[0];
  g.rate_gain_s = data.rate_gain_s[0];
  const int n = data.stage1_schedule_count;
  if (n <= 0 || n > kMaxGainSchedulePointsPerStage) return g;
  const double* t = data.stage1_schedule_time_s;
  if (!(stage_time_s > t[0])) {
    g.position_gain = data.stage1_schedule_k_theta[0];
    g.rate_gain_s = data.stage1_schedule_k_q_s[0];
    return g;
  }
  if (!(stage_time_s < t[n - 1])) {
    g.position_gain = data.stage1_schedule_k_theta[n - 1];
    g.rate_gain_s = data.stage1_schedule_k_q_s[n - 1];
    return g;
  }
  int j = 0;
  while (j + 2 < n && !(stage_time_s < t[j + 1])) ++j;
  const double f = (stage_time_s - t[j]) / (t[j + 1] - t[j]);
  g.position_gain = data.stage1_schedule_k_theta[j] +
                    f * (data.stage1_schedule_k_theta[j + 1] - data.stage1_schedule_k_theta[j]);
  g.rate_gain_s =
      data.stage1_schedule_k_q_s[j] + f * (data.stage1_schedule_k_q_s[j + 1] - data.stage1_schedule_k_q_s[j]);
  return g;
}

UnitMoments unit_moments(const BodyDynamicsBlocks& data, const MomentConditions& c) {
  return unit_moments(data, c, nullptr);
}

UnitMoments unit_moments(const BodyDynamicsBlocks& data, const MomentConditions& c,
                         BodyDynamicsHints* hints) {
  // A hinted look-up finds the interval the plain one does: the same value either way.
  const auto look_up = [](const auto& table, double x, int* hint) {
    return (hint != nullptr) ? table(x, hint) : table(x);
  };
  const int k = clamp_stage(c.stage) - 1;
  UnitMoments m;
  const CgTable& cg = data.cg_station_ft[k];
  m.cg_station_ft = look_up(cg.empty() ? data.cg_station_ft[0] : cg, c.cg_stage_time_s,
                            (hints != nullptr) ? &hints->cg_hint : nullptr);
  m.control_lever_ft = data.control_station_ft[k] - m.cg_station_ft;
  const double reference_arm_ft = data.moment_reference_station_ft - m.cg_station_ft;  // X_FS - X_CG
  const double q_s = c.dynamic_pressure_lbf_ft2 * data.reference_area_ft2;
  const double l_ref = data.reference_length_ft;

  double aero_alpha = 0.0;
  double aero_delta = 0.0;
  if (q_s > 0.0) {
    const double c_m_alpha = look_up(data.pitching_moment_per_rad, c.mach,
                                     (hints != nullptr) ? &hints->pitching_moment_hint : nullptr);
    const double c_m_delta = look_up(data.fin_pitching_moment_per_rad, c.mach,
                                     (hints != nullptr) ? &hints->fin_pitching_moment_hint : nullptr);
    const double c_n_delta = look_up(data.fin_normal_force_per_rad, c.mach,
                                     (hints != nullptr) ? &hints->fin_normal_force_hint : nullptr);
    aero_alpha = (c_m_alpha * l_ref - c.normal_force_slope_per_rad * reference_arm_ft) * q_s;
    aero_delta = (-c_m_delta * l_ref + c_n_delta * reference_arm_ft) * q_s;
  }
  const double jet_vanes = data.jet_vane_effectiveness_per_rad * c.vacuum_thrust_lbf * m.control_lever_ft;
  m.m_alpha_lbf_ft_per_rad = aero_alpha;
  m.m_delta_lbf_ft_per_rad = data.control_surfaces_per_plane * (aero_delta + jet_vanes);
  return m;
}

namespace {

// `gamma_w_anchor`: null but in a dispersion flight with hints (by_series).
PlatformVelocityAngles velocity_angles(const Matrix3& platform_to_local, bool by_series,
                                       Atan2Anchor* gamma_w_anchor) {
  // Row 2 of [C] is the second column of C^-1 = C^T: the unit velocity in P.
  const double vx = platform_to_local(1, 0);
  const double vy = platform_to_local(1, 1);
  const double vz = platform_to_local(1, 2);
  const double horizontal = std::sqrt(vx * vx + vy * vy);
  PlatformVelocityAngles out;
  out.gamma_w_rad =
      (gamma_w_anchor != nullptr) ? gamma_w_anchor->at(vz, horizontal) : std::atan2(vz, horizontal);
  out.azimuth_w_rad = small_angle_atan2(vx, vy, by_series);
  return out;
}

BodyAngles angles_of_attack(const MissileAxes& axes, const Matrix3& platform_to_local, bool by_series) {
  const Vector3 v = platform_to_local.row(1).transpose();  // unit V in P (C^T i_y)
  const double v_mx = axes.x.dot(v);
  const double v_my = axes.y.dot(v);
  const double v_mz = axes.z.dot(v);
  BodyAngles angles;
  angles.alpha_rad = small_angle_atan2(-v_mz, v_my, by_series);
  angles.beta_rad = small_angle_atan2(-v_mx, v_my, by_series);
  return angles;
}

}  // namespace

PlatformVelocityAngles platform_velocity_angles(const Matrix3& platform_to_local) {
  return velocity_angles(platform_to_local, false, nullptr);
}

Status steady_state_attitude(const AutopilotGains& gains, const UnitMoments& moments,
                             const AutopilotCommand& command, const PlatformVelocityAngles& velocity,
                             SteadyAttitude* out) {
  const double k_m_delta = gains.position_gain * moments.m_delta_lbf_ft_per_rad;  // K_theta M_delta
  const double q_m_delta = gains.rate_gain_s * moments.m_delta_lbf_ft_per_rad;    // K_q M_delta
  const double m_alpha = moments.m_alpha_lbf_ft_per_rad;
  const double denominator = k_m_delta - m_alpha;
  const double scale = std::fabs(k_m_delta) + std::fabs(m_alpha);

  // Each guard leaves the body on its command with a finite deflection; only "no moment at all" is
  // normal flight, the others are named.
  Status status = Status::kOk;
  bool follow = true;
  if (!std::isfinite(k_m_delta) || !std::isfinite(q_m_delta) || !std::isfinite(m_alpha)) {
    status = Status::kBodyDynamicsNotFinite;
  } else if (!(scale > 0.0)) {
    // No moment at all: q = 0 and no thrust (kOk).
  } else if (!(denominator > kTrimTolerance * scale)) {
    status = Status::kBodyDynamicsNotTrimmable;
  } else {
    double pitch_numerator =
        k_m_delta * command.theta_rad - q_m_delta * command.theta_rate_rad_s - m_alpha * velocity.gamma_w_rad;
    double yaw_numerator =
        k_m_delta * command.chi_rad - q_m_delta * command.chi_rate_rad_s - m_alpha * velocity.azimuth_w_rad;
    // Sec. 15's misalignment term; added only when present so a nominal run is bit for bit unchanged.
    if (command.pitch_disturbance_lbf_ft != 0.0) pitch_numerator += command.pitch_disturbance_lbf_ft;
    if (command.yaw_disturbance_lbf_ft != 0.0) yaw_numerator += command.yaw_disturbance_lbf_ft;
    out->theta_rad = pitch_numerator / denominator;
    out->chi_rad = yaw_numerator / denominator;
    follow = !std::isfinite(out->theta_rad) || !std::isfinite(out->chi_rad);
    if (follow) status = Status::kBodyDynamicsNotFinite;  // the command or the velocity angles
  }
  out->follows_command = follow;
  if (follow) {
    out->theta_rad = command.theta_rad;
    out->chi_rad = command.chi_rad;
  }
  // Eq. 7-3 in the steady state (theta-dot = theta_c-dot).
  out->pitch_deflection_rad = gains.position_gain * (command.theta_rad - out->theta_rad) -
                              gains.rate_gain_s * command.theta_rate_rad_s;
  out->yaw_deflection_rad =
      gains.position_gain * (command.chi_rad - out->chi_rad) - gains.rate_gain_s * command.chi_rate_rad_s;
  // A command or gain that is not finite reaches the outputs on every path: named, never kOk.
  if (!std::isfinite(out->theta_rad) || !std::isfinite(out->chi_rad) ||
      !std::isfinite(out->pitch_deflection_rad) || !std::isfinite(out->yaw_deflection_rad)) {
    status = Status::kBodyDynamicsNotFinite;
  }
  return status;
}

MissileAxes missile_axes_platform(double theta_rad, double chi_rad) {
  const double st = std::sin(theta_rad), ct = std::cos(theta_rad);
  const double sc = std::sin(chi_rad), cc = std::cos(chi_rad);
  MissileAxes axes;
  axes.x = Vector3(cc, -sc, 0.0);
  axes.y = Vector3(ct * sc, ct * cc, st);
  axes.z = Vector3(-st * sc, -st * cc, ct);
  return axes;
}

BodyAngles body_angles_of_attack(double theta_rad, double chi_rad, const Matrix3& platform_to_local) {
  return body_angles_of_attack(missile_axes_platform(theta_rad, chi_rad), platform_to_local);
}

BodyAngles body_angles_of_attack(const MissileAxes& axes, const Matrix3& platform_to_local) {
  return angles_of_attack(axes, platform_to_local, false);
}

BodyForces body_forces(const UnitMoments& moments, const BodyAngles& angles, double normal_force_lbf_per_rad,
                       double theta_rad, double chi_rad, const Matrix3& platform_to_local) {
  return body_forces(moments, angles, normal_force_lbf_per_rad, missile_axes_platform(theta_rad, chi_rad),
                     platform_to_local);
}

BodyForces body_forces(const UnitMoments& moments, const BodyAngles& angles, double normal_force_lbf_per_rad,
                       const MissileAxes& axes, const Matrix3& platform_to_local) {
  BodyForces f;
  if (std::fabs(moments.control_lever_ft) >= kMinimumLeverFt) {
    f.control_x_lbf = moments.m_alpha_lbf_ft_per_rad * angles.beta_rad / moments.control_lever_ft;
    f.control_z_lbf = moments.m_alpha_lbf_ft_per_rad * angles.alpha_rad / moments.control_lever_ft;
  }
  f.missile_x_lbf = f.control_x_lbf + normal_force_lbf_per_rad * angles.beta_rad;
  f.missile_z_lbf = f.control_z_lbf + normal_force_lbf_per_rad * angles.alpha_rad;
  // Sec. 11: F_jx = F_mx cos chi - F_mz sin theta sin chi, F_jy = -F_mx sin chi - F_mz sin theta cos chi,
  // F_jz = F_mz cos theta, i.e. F_mx m_x + F_mz m_z.
  f.platform_lbf = f.missile_x_lbf * axes.x + f.missile_z_lbf * axes.z;
  f.local_lbf = platform_to_local * f.platform_lbf;
  return f;
}

Status evaluate_body_dynamics(const BodyDynamicsBlocks& data, const BodyDynamicsInputs& in,
                              BodyDynamicsResult* out) {
  const int k = clamp_stage(in.conditions.stage) - 1;
  out->moments = unit_moments(data, in.conditions, in.hints);
  Atan2Anchor* gamma_w_anchor =
      (in.small_angles_by_series && in.hints != nullptr) ? &in.hints->gamma_w_anchor : nullptr;
  out->velocity = velocity_angles(in.platform_to_local, in.small_angles_by_series, gamma_w_anchor);
  AutopilotGains gains;
  gains.position_gain = data.position_gain[k];
  gains.rate_gain_s = data.rate_gain_s[k];
  if (k == 0 && data.stage1_schedule_count > 0) {
    gains = scheduled_stage1_gains(data, in.conditions.cg_stage_time_s);
  }
  const bool misaligned = in.misalignment_pitch_rad != 0.0 || in.misalignment_yaw_rad != 0.0;
  AutopilotCommand command = in.command;
  const double thrust_lever_ft = in.thrust_station_ft - out->moments.cg_station_ft;  // X_T - XCGL
  if (misaligned) {
    const double unit_moment = in.net_thrust_lbf * thrust_lever_ft;  // M_alpha_T
    command.pitch_disturbance_lbf_ft += unit_moment * in.misalignment_pitch_rad;
    command.yaw_disturbance_lbf_ft += unit_moment * in.misalignment_yaw_rad;
  }
  const Status status = steady_state_attitude(gains, out->moments, command, out->velocity, &out->attitude);
  const Matrix3& angle_frame =
      (in.air_platform_to_local != nullptr) ? *in.air_platform_to_local : in.platform_to_local;
  // The attitude's sines and cosines once, for the angles, the forces and the caller's thrust axis.
  out->axes = missile_axes_platform(out->attitude.theta_rad, out->attitude.chi_rad);
  out->angles = angles_of_attack(out->axes, angle_frame, in.small_angles_by_series);
  out->forces =
      body_forces(out->moments, out->angles, in.normal_force_lbf_per_rad, out->axes, in.platform_to_local);
  if (misaligned && std::fabs(out->moments.control_lever_ft) >= kMinimumLeverFt) {
    // The misalignment force and the control force that trims its moment (Sec. 15).
    const double factor = 1.0 - thrust_lever_ft / out->moments.control_lever_ft;
    out->forces.missile_z_lbf += -in.net_thrust_lbf * in.misalignment_pitch_rad * factor;
    out->forces.missile_x_lbf += -in.net_thrust_lbf * in.misalignment_yaw_rad * factor;
    const MissileAxes& axes = out->axes;
    out->forces.platform_lbf = out->forces.missile_x_lbf * axes.x + out->forces.missile_z_lbf * axes.z;
    out->forces.local_lbf = in.platform_to_local * out->forces.platform_lbf;
  }
  return status;
}

}  // namespace tolip
