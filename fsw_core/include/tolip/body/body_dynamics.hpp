// Body dynamics for the nominal trajectory (manual Sec. 7 and 11, subroutines SIXD and CONTRL).
//
// The autopilot's steady-state thrust attitude (eqs. 7-6, 7-7) replaces the commanded attitude,
// and the resulting steady-state aerodynamic and control normal forces act on the point mass. The
// pieces are exposed one by one so each can be tested against the manual:
//   unit_moments()             M_alpha, M_delta of Sec. 11 (Mach, c.g. station, vacuum thrust)
//   platform_velocity_angles() gamma_w, A_zw of V resolved in the platform frame through C^-1
//   steady_state_attitude()    theta, chi of eqs. 7-6, 7-7 (with the guards listed there)
//   body_angles_of_attack()    alpha, beta of the flown attitude (CONTRL)
//   body_forces()              F_CNLX, F_CNLZ, F_alpha and the forces resolved m -> P -> L
//   evaluate_body_dynamics()   all of it for one derivative evaluation
// docs/theory/body-dynamics.md derives every formula and records the choices. Units: ft, s, lbf,
// rad; moments in lbf ft per rad. No heap, no exceptions; nothing here returns a NaN for finite
// inputs.
#pragma once

#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip {

// Where the unit moments are evaluated.
struct MomentConditions {
  int stage = 1;                 // 1-3: the DA6D word set and block 37 table used
  double cg_stage_time_s = 0.0;  // stage time at which the c.g. history is read
  double mach = 0.0;
  double dynamic_pressure_lbf_ft2 = 0.0;    // 0 on the pad or above HAERO
  double vacuum_thrust_lbf = 0.0;           // T_V (modified Sec. 14 table); 0 in a coast
  double normal_force_slope_per_rad = 0.0;  // C_N_alpha at this Mach (block 32 table, referred to S)
};

// The unit moments about the c.g. of Sec. 11 (positive nose up), and the stations they used.
struct UnitMoments {
  double m_alpha_lbf_ft_per_rad = 0.0;  // M_alpha
  double m_delta_lbf_ft_per_rad = 0.0;  // M_delta, all fins and vanes of one plane
  double cg_station_ft = 0.0;           // X_CG
  double control_lever_ft = 0.0;        // X_delta - X_CG
};

// M_alpha = [C_M_alpha l_ref - C_N_alpha (X_FS - X_CG)] q S
// M_delta = n [(-C_M_delta l_ref + C_N_delta (X_FS - X_CG)) q S + K_TV T_V (X_delta - X_CG)]
// with n = control_surfaces_per_plane. Stage 1's tables (blocks 34-36) serve every stage.
UnitMoments unit_moments(const BodyDynamicsBlocks& data, const MomentConditions& conditions);

// The intervals the unit moments' table look-ups found last (Table's hinted look-up: the same
// values, bit for bit; a flight keeps one set per stage, the look-ups' stage time and Mach moving
// little from one evaluation to the next). -1: not yet looked up.
struct BodyDynamicsHints {
  int cg_hint = -1;
  int pitching_moment_hint = -1;
  int fin_pitching_moment_hint = -1;
  int fin_normal_force_hint = -1;
  // A dispersion flight's gamma_w (BodyDynamicsInputs::small_angles_by_series).
  Atan2Anchor gamma_w_anchor;
};
// The same with hints (null: every look-up searched).
UnitMoments unit_moments(const BodyDynamicsBlocks& data, const MomentConditions& conditions,
                         BodyDynamicsHints* hints);

// The rigid-body damping moments of Sec. 16 (lbf ft), shared by the hardover turns and the
// autopilot design: term 4, aerodynamic pitch damping C_M_q eta-dot l_ref q S l_ref / (2 V), and
// term 5, jet damping eta-dot (m-dot (X_CG - X_TA)^2 + I-dot).
inline double aerodynamic_pitch_damping_moment(double cmq_per_rad, double rate_rad_s, double l_ref_ft,
                                               double q_lbf_ft2, double area_ft2, double speed_ft_s) {
  return cmq_per_rad * rate_rad_s * l_ref_ft * q_lbf_ft2 * area_ft2 * l_ref_ft / (2.0 * speed_ft_s);
}
inline double jet_damping_moment(double rate_rad_s, double mass_rate_slug_s, double jet_arm_ft,
                                 double inertia_rate_slug_ft2_s) {
  return rate_rad_s * (mass_rate_slug_s * jet_arm_ft * jet_arm_ft + inertia_rate_slug_ft2_s);
}

// gamma_w and A_zw (Sec. 7): V_P = C^-1 (0, |V|, 0) = |V| (C21, C22, C23) ([C] is orthonormal, so
// C^-1 = C^T), gamma_w = atan(V_jz / sqrt(V_jx^2 + V_jy^2)), A_zw = atan2(V_jx, V_jy).
struct PlatformVelocityAngles {
  double gamma_w_rad = 0.0;
  double azimuth_w_rad = 0.0;  // A_zw
};
PlatformVelocityAngles platform_velocity_angles(const Matrix3& platform_to_local);

struct AutopilotGains {
  double position_gain = 0.0;  // K_theta, rad/rad
  double rate_gain_s = 0.0;    // K_q (K_theta-dot), s
};

// The stage-1 gains in force at stage-1 time `stage_time_s`: DA6D(1), DA6D(4) when the mission has
// no designed schedule (stage1_schedule_count = 0); else the schedule, linear in time between its
// points and held at its ends (the coast after stage 1 reads it at stage 1's duration: the last
// point's gains). The same rule as the table image's executor (table/table_image.hpp).
AutopilotGains scheduled_stage1_gains(const BodyDynamicsBlocks& data, double stage_time_s);

// The commanded attitude and its rates (theta_c-dot is the pitch program's rate; chi_c and
// chi_c-dot are 0 in stages 1-3, Sec. 7).
struct AutopilotCommand {
  double theta_rad = 0.0;
  double theta_rate_rad_s = 0.0;
  double chi_rad = 0.0;
  double chi_rate_rad_s = 0.0;
  // Sec. 15 thrust misalignment: M_alpha_T alpha_T added to the numerator of eq. 7-6 (pitch) or
  // 7-7 (yaw), lbf ft; 0 on every nominal run.
  double pitch_disturbance_lbf_ft = 0.0;
  double yaw_disturbance_lbf_ft = 0.0;
};

struct SteadyAttitude {
  double theta_rad = 0.0;
  double chi_rad = 0.0;
  double pitch_deflection_rad = 0.0;  // delta of eq. 7-3 with theta-dot = theta_c-dot
  double yaw_deflection_rad = 0.0;
  bool follows_command = false;  // the guard applied: theta = theta_c, chi = chi_c
};

// Eqs. 7-6 and 7-7:
//   theta = (K_theta M_delta theta_c - K_q M_delta theta_c-dot - M_alpha gamma_w) / (K_theta M_delta -
//   M_alpha) chi   = (K_theta M_delta chi_c   - K_q M_delta chi_c-dot   - M_alpha A_zw)    / (K_theta M_delta
//   - M_alpha)
// Guards, each of which leaves the body on its command: with no moment at all (q = 0 and no thrust)
// it returns kOk; when K_theta M_delta - M_alpha is not positive against |K_theta M_delta| +
// |M_alpha| (no stable steady state), kBodyDynamicsNotTrimmable; when a unit moment, a gain, the
// command or the solved attitude is not finite, kBodyDynamicsNotFinite (a NaN never passes as kOk).
Status steady_state_attitude(const AutopilotGains& gains, const UnitMoments& moments,
                             const AutopilotCommand& command, const PlatformVelocityAngles& velocity,
                             SteadyAttitude* out);

// Missile axes in the platform frame (Sec. 7 figure, Sec. 11 resolution): m_y the thrust axis
// (cos theta sin chi, cos theta cos chi, sin theta), m_x = (cos chi, -sin chi, 0) in the j_x-j_y
// plane, m_z = m_x x m_y = (-sin theta sin chi, -sin theta cos chi, cos theta).
struct MissileAxes {
  Vector3 x = Vector3::UnitX();
  Vector3 y = Vector3::UnitY();
  Vector3 z = Vector3::UnitZ();
};
MissileAxes missile_axes_platform(double theta_rad, double chi_rad);

// CONTRL: in-plane alpha and out-of-plane beta of the attitude, from the direction of V in missile
// axes: alpha = atan2(-v_mz, v_my) (alpha > 0: aerodynamic force along +m_z), beta =
// atan2(-v_mx, v_my) (beta > 0: force along +m_x). For chi = A_zw = 0, alpha = theta - gamma_w.
struct BodyAngles {
  double alpha_rad = 0.0;
  double beta_rad = 0.0;
};
BodyAngles body_angles_of_attack(double theta_rad, double chi_rad, const Matrix3& platform_to_local);
// The same with the attitude's missile axes already computed (missile_axes_platform(theta, chi)).
BodyAngles body_angles_of_attack(const MissileAxes& axes, const Matrix3& platform_to_local);

// Sec. 11 forces: F_CNLX = M_alpha beta / (X_delta - X_CG), F_CNLZ = M_alpha alpha / (X_delta - X_CG),
// F_mx = F_CNLX + F_alpha beta, F_mz = F_CNLZ + F_alpha alpha, resolved to P along m_x, m_z and to L
// through [C]. The control forces are 0 when |X_delta - X_CG| is below 1e-6 ft.
struct BodyForces {
  double control_x_lbf = 0.0;              // F_CNLX
  double control_z_lbf = 0.0;              // F_CNLZ
  double missile_x_lbf = 0.0;              // F_mx
  double missile_z_lbf = 0.0;              // F_mz
  Vector3 platform_lbf = Vector3::Zero();  // (F_jx, F_jy, F_jz)
  Vector3 local_lbf = Vector3::Zero();     // (F_ix, F_iy, F_iz) = [C] F_j
};
BodyForces body_forces(const UnitMoments& moments, const BodyAngles& angles, double normal_force_lbf_per_rad,
                       double theta_rad, double chi_rad, const Matrix3& platform_to_local);
// The same with the attitude's missile axes already computed.
BodyForces body_forces(const UnitMoments& moments, const BodyAngles& angles, double normal_force_lbf_per_rad,
                       const MissileAxes& axes, const Matrix3& platform_to_local);

// One SIXD evaluation.
struct BodyDynamicsInputs {
  MomentConditions conditions;
  AutopilotCommand command;
  double normal_force_lbf_per_rad = 0.0;            // F_alpha = q S C_N_alpha
  Matrix3 platform_to_local = Matrix3::Identity();  // [C]
  // Dispersed trajectories only (Sec. 15, SIXD-D). Winds: alpha and beta come from the air-relative
  // velocity, whose direction is the i_y row of this matrix (null: from V, the nominal).
  const Matrix3* air_platform_to_local = nullptr;
  // Stage-1 thrust misalignment alpha_T (pitch plane for high/low codes, yaw for the yaw code),
  // applied at body station `thrust_station_ft` with the net thrust T: M_alpha_T = T (X_T - X_CG)
  // in eq. 7-6/7-7 and the force -T alpha_T {1 - (X_T - X_CG) / (X_delta - X_CG)} on F_mz (F_mx).
  double misalignment_pitch_rad = 0.0;
  double misalignment_yaw_rad = 0.0;
  double thrust_station_ft = 0.0;
  double net_thrust_lbf = 0.0;
  BodyDynamicsHints* hints = nullptr;  // the unit moments' look-up hints (null: none)
  // A dispersion flight's (FlightInputs::trig_by_series): the small angles (alpha, beta and the
  // velocity azimuth psi_w) by atan2_by_series (frames.hpp), the library's where they are not small,
  // and with hints the velocity's elevation gamma_w from their Atan2Anchor.
  bool small_angles_by_series = false;
};

struct BodyDynamicsResult {
  UnitMoments moments;
  PlatformVelocityAngles velocity;
  SteadyAttitude attitude;
  // missile_axes_platform(attitude.theta_rad, attitude.chi_rad): computed once per evaluation and
  // shared by the angles, the forces and the caller (the thrust axis is axes.y).
  MissileAxes axes;
  BodyAngles angles;
  BodyForces forces;
};

// Everything above in order; the status is steady_state_attitude()'s (the result is complete and
// finite either way).
Status evaluate_body_dynamics(const BodyDynamicsBlocks& data, const BodyDynamicsInputs& inputs,
                              BodyDynamicsResult* out);

}  // namespace tolip
