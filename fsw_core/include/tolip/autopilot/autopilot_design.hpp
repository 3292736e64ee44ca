// Autopilot gains designed along the trajectory (issue 16; manual Sec. 7 eqs. 7-1 to 7-4 with the
// rigid-body moment terms of Sec. 16). docs/theory/autopilot-design.md derives every formula.
//
// The short-period attitude model at one flight condition, per unit pitch inertia I_yy:
//
//   theta-ddot = a (theta - gamma) + b delta + c theta-dot,   a = M_alpha / I, b = M_delta / I,
//   c = M_q / I (aerodynamic pitch damping plus jet damping, negative when it damps)
//   delta      = K_theta (theta_c - theta) - K_q theta-dot            (eq. 7-3)
//
// gives the closed loop s^2 + (K_q b - c) s + (K_theta b - a) = K_theta b theta_c - a gamma, so the
// requested natural frequency w_n and damping ratio zeta are placed exactly by
//
//   K_theta = (w_n^2 + a) / b,   K_q = (2 zeta w_n + c) / b.
//
// The deflection limit is respected for a design attitude error e: K_theta e <= delta_max (the
// deflection right after an attitude step e, before any rate builds up). Margins are those of the
// loop broken at the actuator, L(s) = b (K_theta + K_q s) / ((s^2 - c s - a)(tau s + 1)), tau the
// first-order actuator lag (0: none): the gain margins are exact (Routh-Hurwitz of the closed loop
// with the loop gain scaled by k, the stable interval of k), the phase margin
// PM = 180 deg + arg L(j w) (in (-180, 180] deg) is taken at every gain crossover |L(j w)| = 1 and
// the one of smallest magnitude (the crossing nearest to -1) is reported.
//
// No heap, no exceptions; every failure is a Status. Units: ft, s, lbf, slug, rad.
#pragma once

#include "tolip/body/body_dynamics.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip {

// What the deck asks of one stage's autopilot.
struct AutopilotRequest {
  double natural_frequency_rad_s = 0.0;   // w_n of the closed-loop attitude poles
  double damping_ratio = 0.0;             // zeta, > 0
  double attitude_error_rad = 0.0;        // e: the attitude error for which delta must stay in limit
  double max_deflection_rad = 0.0;        // delta_max (the table image's limit)
  double actuator_time_constant_s = 0.0;  // tau of a first-order actuator lag, 0: none (margins only)
};

// The flight condition at one schedule point.
struct AutopilotCondition {
  MomentConditions moments;              // stage, c.g. time, Mach, q-bar, T_V, C_N_alpha (unit_moments)
  double speed_ft_s = 0.0;               // |V| (aerodynamic damping; 0: no aerodynamic damping)
  double pitch_inertia_slug_ft2 = 0.0;   // I_yy about the c.g. (block 44), > 0
  double inertia_rate_slug_ft2_s = 0.0;  // dI_yy/dt (block 44 slope)
  double mass_rate_slug_s = 0.0;         // dm/dt (< 0 while burning; 0 in a coast)
  double thrust_station_ft = 0.0;        // X_TA, the nozzle station of the jet damping (block 45)
  double pitch_damping_per_rad = 0.0;    // C_M_q at this Mach (block 44 CMQ), 0 when not given
};

// The rigid-body short-period model (moments, lbf ft per rad, and per rad/s for M_q).
struct ShortPeriodModel {
  double m_alpha_lbf_ft_per_rad = 0.0;
  double m_delta_lbf_ft_per_rad = 0.0;
  double m_q_aero_lbf_ft_s_per_rad = 0.0;  // aerodynamic pitch damping (Sec. 16 term 4)
  double m_q_jet_lbf_ft_s_per_rad = 0.0;   // jet damping (Sec. 16 term 5)
  double pitch_inertia_slug_ft2 = 0.0;
  // Per unit inertia: a = M_alpha / I, b = M_delta / I, c = (M_q aero + M_q jet) / I.
  double a_per_s2 = 0.0;
  double b_per_s2 = 0.0;
  double c_per_s = 0.0;
};

// M_alpha and M_delta from unit_moments() (blocks 33-37), the damping terms from the Sec. 16
// expressions of the body module (aerodynamic_pitch_damping_moment, jet_damping_moment).
ShortPeriodModel short_period_model(const BodyDynamicsBlocks& data, const AutopilotCondition& condition);

// A pair of roots of a real quadratic s^2 + p1 s + p0 (complex conjugates, or two real ones).
struct RootPair {
  double re[2] = {0.0, 0.0};
  double im[2] = {0.0, 0.0};
};
RootPair quadratic_roots(double p1, double p0);

struct LoopMargins {
  // Stable interval (k_min, k_max) of a factor k on the loop gain: gain margins as factors (dB in
  // listings). k_max is +infinity when no finite increase destabilizes (no actuator lag); k_min is 0
  // when the open loop is stable, else the gain reduction at which it goes unstable (M_alpha > 0).
  double upper_gain_margin = 0.0;
  double lower_gain_margin = 0.0;
  double phase_margin_rad = 0.0;    // of the crossover nearest to -1 (smallest |PM|); +infinity when none
  double crossover_rad_s = 0.0;     // where it is taken (0 when none)
  bool closed_loop_stable = false;  // k = 1 inside the stable interval
};

struct AutopilotDesign {
  ShortPeriodModel model;
  RootPair open_loop;    // s^2 - c s - a (a real pole > 0 when the vehicle is statically unstable)
  double k_theta = 0.0;  // rad/rad
  double k_q_s = 0.0;    // s
  RootPair closed_loop;  // s^2 + (K_q b - c) s + (K_theta b - a), from the gains
  LoopMargins margins;
  double step_deflection_rad = 0.0;  // K_theta e
};

// Margins of L(s) = b (k_theta + k_q s) / ((s^2 - c s - a)(tau s + 1)).
LoopMargins loop_margins(const ShortPeriodModel& model, double k_theta, double k_q_s,
                         double actuator_time_constant_s);

// Places the poles (above). Failures, *design untouched:
//   kAutopilotDampingNotPositive          zeta <= 0 (or not finite)
//   kAutopilotFrequencyNotPositive        w_n <= 0 (or not finite)
//   kAutopilotRequestInvalid              e <= 0, delta_max <= 0 or tau < 0 (or not finite)
//   kAutopilotModelInvalid                I <= 0, M_delta <= 0 (no control power), or not finite
//   kAutopilotFrequencyBeyondDeflection   K_theta e > delta_max: the limit cannot deliver w_n
//   kAutopilotGainOutOfRange              K_theta or K_q outside the table's [0, 100]
Status design_autopilot_gains(const ShortPeriodModel& model, const AutopilotRequest& request,
                              AutopilotDesign* design);

// The highest natural frequency the deflection limit delivers for attitude error e:
// w_n^2 = b delta_max / e - a (0 when none).
double max_deliverable_frequency_rad_s(const ShortPeriodModel& model, const AutopilotRequest& request);

}  // namespace tolip
