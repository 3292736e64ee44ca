// Sec. 7 and 11: body dynamics (6D) of the nominal trajectory. The steady-state attitude, the
// platform velocity angles, the force resolution and the guards, each against an independent
// construction; then the reference vehicle flown with 6D in stage 1 and coast 6.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "support/reference_mission.hpp"
#include "tolip/body/body_dynamics.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

constexpr double kDeg = kPi / 180.0;

struct Case {
  Mission mission;
  PreparedCase prepared;
};

const Case& reference_case(test::ReferenceProgram program) {
  static Case* optimum = nullptr;
  static Case* initial = nullptr;
  Case*& slot = program == test::ReferenceProgram::kOptimum ? optimum : initial;
  if (slot == nullptr) {
    slot = new Case;
    test::build_reference_mission(program, &slot->mission);
    MissionFault fault;
    EXPECT_EQ(validate_mission(slot->mission, &fault), Status::kOk) << fault.data_block << " " << fault.field;
    EXPECT_EQ(prepare_case(slot->mission, &slot->prepared), Status::kOk);
  }
  return *slot;
}

// A state in stage 1 near maximum dynamic pressure and a [C] for it.
StateVector stage1_state(const Case& c, double gamma_deg, double psi_offset_deg) {
  StateVector x = c.prepared.pad_state;
  x[kStateV] = 2000.0;
  x[kStateGamma] = gamma_deg * kDeg;
  x[kStateR] += 40000.0;
  x[kStatePsi] += psi_offset_deg * kDeg;
  return x;
}

Matrix3 platform_to_local(const Case& c, const StateVector& x) {
  return inertial_to_local(x) * c.prepared.platform_to_inertial;
}

// Conditions of the reference stage 1 at stage time t (Mach, q from a representative point).
MomentConditions conditions_at(const Case& c, double stage_time_s, double mach, double q_lbf_ft2) {
  MomentConditions m;
  m.stage = 1;
  m.cg_stage_time_s = stage_time_s;
  m.mach = mach;
  m.dynamic_pressure_lbf_ft2 = q_lbf_ft2;
  m.vacuum_thrust_lbf = c.prepared.modified_thrust_lbf[0](stage_time_s);
  m.normal_force_slope_per_rad = c.mission.vehicle.lift_curve_slope_per_rad(mach);
  return m;
}

// ---- Sec. 7: the steady-state attitude --------------------------------------------------------

// Eq. 7-4 (the printed left side theta-dot is theta-ddot, from 7-1..7-3):
// theta-ddot = K_theta M_delta (theta_c - theta) - K_q M_delta theta-dot + M_alpha theta - M_alpha gamma.
double moment_balance_residual(const AutopilotGains& g, const UnitMoments& m, double theta_c,
                               double theta_c_dot, double theta, double gamma) {
  const double theta_dot = theta_c_dot;  // steady state
  return g.position_gain * m.m_delta_lbf_ft_per_rad * (theta_c - theta) -
         g.rate_gain_s * m.m_delta_lbf_ft_per_rad * theta_dot + m.m_alpha_lbf_ft_per_rad * theta -
         m.m_alpha_lbf_ft_per_rad * gamma;
}

TEST(BodyDynamics, Sec7_SteadyStateAttitudeSatisfiesMomentBalance) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  double worst = 0.0;
  for (double t = 2.0; t <= 45.0; t += 4.3) {
    for (double q : {0.0, 150.0, 900.0, 2200.0}) {
      const UnitMoments m = unit_moments(c.mission.body_dynamics, conditions_at(c, t, 0.3 + t / 20.0, q));
      AutopilotGains g{c.mission.body_dynamics.position_gain[0], c.mission.body_dynamics.rate_gain_s[0]};
      AutopilotCommand command;
      command.theta_rad = (80.0 - t) * kDeg;
      command.theta_rate_rad_s = -0.9 * kDeg;
      command.chi_rad = 0.0;
      PlatformVelocityAngles v;
      v.gamma_w_rad = command.theta_rad - 3.0 * kDeg;
      v.azimuth_w_rad = 0.4 * kDeg;
      SteadyAttitude a;
      ASSERT_EQ(steady_state_attitude(g, m, command, v, &a), Status::kOk);
      ASSERT_FALSE(a.follows_command);
      // Residuals in angular-acceleration units: divided by the moment scale K_theta M_delta.
      const double scale = g.position_gain * m.m_delta_lbf_ft_per_rad;
      const double pitch = moment_balance_residual(g, m, command.theta_rad, command.theta_rate_rad_s,
                                                   a.theta_rad, v.gamma_w_rad) /
                           scale;
      const double yaw =
          moment_balance_residual(g, m, command.chi_rad, 0.0, a.chi_rad, v.azimuth_w_rad) / scale;
      worst = std::fmax(worst, std::fmax(std::fabs(pitch), std::fabs(yaw)));
      // Eq. 7-1 in the steady state: M_delta delta + M_alpha alpha = 0 with delta of eq. 7-3.
      const double eq71 = (m.m_delta_lbf_ft_per_rad * a.pitch_deflection_rad +
                           m.m_alpha_lbf_ft_per_rad * (a.theta_rad - v.gamma_w_rad)) /
                          scale;
      EXPECT_LT(std::fabs(eq71), 1e-12);
    }
  }
  std::printf("[ figures ] eq. 7-4 moment-balance residual (relative to K_theta M_delta): %.2e\n", worst);
  RecordProperty("moment_balance_residual", std::to_string(worst));
  EXPECT_LT(worst, 1e-12);
}

TEST(BodyDynamics, Sec11_SignsOfUnitMomentsWithReferenceTables) {
  // Reference README: with these tables M_alpha < 0 (statically stable) and M_delta > 0, over all
  // of stage 1 and its Mach range.
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  for (double t = 0.0; t <= 45.0; t += 1.5) {
    for (double mach = 0.0; mach <= 6.0; mach += 0.25) {
      const UnitMoments m = unit_moments(c.mission.body_dynamics, conditions_at(c, t, mach, 800.0));
      EXPECT_LT(m.m_alpha_lbf_ft_per_rad, 0.0) << t << " " << mach;
      EXPECT_GT(m.m_delta_lbf_ft_per_rad, 0.0) << t << " " << mach;
      EXPECT_GT(m.control_lever_ft, 0.0);  // vanes and fins aft of the c.g.
    }
  }
}

TEST(BodyDynamics, Sec11_UnitMomentsEqualTheFormulasWithStationsInFeet) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const BodyDynamicsBlocks& b = c.mission.body_dynamics;
  // Stage time 25 s: c.g. 497 in (between 502 at 20 s and 492 at 30 s); Mach 1.2 (table nodes).
  const double q = 1000.0, t = 25.0, mach = 1.2;
  const MomentConditions mc = conditions_at(c, t, mach, q);
  const UnitMoments m = unit_moments(b, mc);
  const double xcg = 497.0 / 12.0, xfs = 600.0 / 12.0, xd = 842.0 / 12.0, s = 8.7266, l = 3.33333;
  const double cn_alpha = 4.1, cm_alpha = -9.02, cn_delta = 0.35, cm_delta = -2.1175;
  const double ktv = 0.0011 / kDeg;
  EXPECT_NEAR(m.cg_station_ft, xcg, 1e-12);
  EXPECT_NEAR(m.control_lever_ft, xd - xcg, 1e-12);
  const double m_alpha = (cm_alpha * l - cn_alpha * (xfs - xcg)) * q * s;
  const double m_delta =
      2.0 * ((-cm_delta * l + cn_delta * (xfs - xcg)) * q * s + ktv * mc.vacuum_thrust_lbf * (xd - xcg));
  EXPECT_NEAR(m.m_alpha_lbf_ft_per_rad, m_alpha, 1e-9 * std::fabs(m_alpha));
  EXPECT_NEAR(m.m_delta_lbf_ft_per_rad, m_delta, 1e-9 * std::fabs(m_delta));
}

TEST(BodyDynamics, Sec7_InfiniteGainFollowsCommand) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const UnitMoments m = unit_moments(c.mission.body_dynamics, conditions_at(c, 30.0, 1.5, 1500.0));
  AutopilotCommand command;
  command.theta_rad = 40.0 * kDeg;
  command.theta_rate_rad_s = -0.8 * kDeg;
  PlatformVelocityAngles v;
  v.gamma_w_rad = 35.0 * kDeg;
  v.azimuth_w_rad = 1.0 * kDeg;
  double previous = 1.0;
  for (double gain : {1.0, 1e2, 1e4, 1e6, 1e9}) {
    AutopilotGains g{gain, 0.35};
    SteadyAttitude a;
    ASSERT_EQ(steady_state_attitude(g, m, command, v, &a), Status::kOk);
    const double error = std::fabs(a.theta_rad - command.theta_rad) + std::fabs(a.chi_rad - command.chi_rad);
    EXPECT_LT(error, previous);  // monotonic approach
    previous = error;
  }
  EXPECT_LT(previous, 1e-8);
  // The same through a whole stage-1 flight: K_theta huge -> the flown attitude is the command.
  static Case stiff;
  stiff.mission = c.mission;
  stiff.prepared = c.prepared;
  for (double& k : stiff.mission.body_dynamics.position_gain) k = 1e9;
  static Trajectory trajectory;
  FlightInputs inputs;
  inputs.body_dynamics = true;
  ASSERT_EQ(fly_trajectory(stiff.mission, stiff.prepared, inputs, &trajectory), Status::kOk);
  double worst = 0.0;
  for (int i = 0; i < trajectory.point_count; ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    if (!p.body_dynamics) continue;
    worst = std::fmax(worst, std::fabs(p.theta_rad - static_cast<double>(p.theta_command_rad)));
  }
  EXPECT_LT(worst, 1e-6);  // theta_command is stored in single precision
}

TEST(BodyDynamics, Sec7_StaticStabilityPullsAttitudeTowardVelocity) {
  // M_alpha < 0: the flown attitude lies between the command and gamma_w (weathercocking), and
  // without a rate command the flown alpha is K_theta M_delta / (K_theta M_delta - M_alpha) of the
  // commanded one.
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const UnitMoments m = unit_moments(c.mission.body_dynamics, conditions_at(c, 35.0, 2.0, 2000.0));
  AutopilotGains g{1.2, 0.35};
  AutopilotCommand command;
  command.theta_rad = 30.0 * kDeg;
  PlatformVelocityAngles v;
  v.gamma_w_rad = 25.0 * kDeg;
  SteadyAttitude a;
  ASSERT_EQ(steady_state_attitude(g, m, command, v, &a), Status::kOk);
  EXPECT_GT(a.theta_rad, v.gamma_w_rad);
  EXPECT_LT(a.theta_rad, command.theta_rad);
  const double k = g.position_gain * m.m_delta_lbf_ft_per_rad;
  EXPECT_NEAR((a.theta_rad - v.gamma_w_rad) / (command.theta_rad - v.gamma_w_rad),
              k / (k - m.m_alpha_lbf_ft_per_rad), 1e-12);
  EXPECT_GT(a.pitch_deflection_rad, 0.0);  // nose-up deflection holds the positive alpha
}

TEST(BodyDynamics, Sec7_GuardsNeverLetNaNOut) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  AutopilotCommand command;
  command.theta_rad = 0.7;
  command.theta_rate_rad_s = -0.01;
  PlatformVelocityAngles v{0.6, 0.02};
  SteadyAttitude a;
  // No moment at all (q = 0, no thrust: a coast above HAERO): the body follows the command.
  const UnitMoments none = unit_moments(c.mission.body_dynamics, MomentConditions{});
  EXPECT_EQ(none.m_alpha_lbf_ft_per_rad, 0.0);
  EXPECT_EQ(none.m_delta_lbf_ft_per_rad, 0.0);
  EXPECT_EQ(steady_state_attitude(AutopilotGains{1.2, 0.35}, none, command, v, &a), Status::kOk);
  EXPECT_TRUE(a.follows_command);
  EXPECT_EQ(a.theta_rad, command.theta_rad);
  EXPECT_EQ(a.chi_rad, command.chi_rad);
  // q = 0 with thrust (the pad): only the jet vanes act; eq. 7-6 reduces to the autopilot's ramp
  // lag theta = theta_c - (K_q / K_theta) theta_c-dot.
  MomentConditions pad;
  pad.vacuum_thrust_lbf = 100000.0;
  const UnitMoments vanes = unit_moments(c.mission.body_dynamics, pad);
  EXPECT_EQ(vanes.m_alpha_lbf_ft_per_rad, 0.0);
  EXPECT_EQ(steady_state_attitude(AutopilotGains{1.2, 0.35}, vanes, command, v, &a), Status::kOk);
  EXPECT_NEAR(a.theta_rad, command.theta_rad - 0.35 / 1.2 * command.theta_rate_rad_s, 1e-15);
  // K_theta M_delta - M_alpha = 0 (unstable vehicle, balanced control): no steady state.
  UnitMoments balanced;
  balanced.m_alpha_lbf_ft_per_rad = 5000.0;
  balanced.m_delta_lbf_ft_per_rad = 5000.0;
  balanced.control_lever_ft = 20.0;
  EXPECT_EQ(steady_state_attitude(AutopilotGains{1.0, 0.35}, balanced, command, v, &a),
            Status::kBodyDynamicsNotTrimmable);
  EXPECT_TRUE(a.follows_command);
  EXPECT_TRUE(std::isfinite(a.theta_rad) && std::isfinite(a.chi_rad) &&
              std::isfinite(a.pitch_deflection_rad));
  // Control station at the c.g.: no control force, no division by zero.
  UnitMoments at_cg = balanced;
  at_cg.control_lever_ft = 0.0;
  const BodyForces f = body_forces(at_cg, BodyAngles{0.05, 0.01}, 30000.0, 0.7, 0.0, Matrix3::Identity());
  EXPECT_EQ(f.control_x_lbf, 0.0);
  EXPECT_EQ(f.control_z_lbf, 0.0);
  EXPECT_TRUE(f.local_lbf.allFinite());
  // Non-finite moments: follows the command with a finite output, and says so by name (a NaN
  // never passes as kOk, unlike "no moment at all" above).
  UnitMoments broken;
  broken.m_alpha_lbf_ft_per_rad = std::nan("");
  broken.m_delta_lbf_ft_per_rad = 1.0;
  EXPECT_EQ(steady_state_attitude(AutopilotGains{1.0, 0.35}, broken, command, v, &a),
            Status::kBodyDynamicsNotFinite);
  EXPECT_TRUE(a.follows_command);
  EXPECT_TRUE(std::isfinite(a.theta_rad) && std::isfinite(a.chi_rad) &&
              std::isfinite(a.pitch_deflection_rad));
}

// Sec. 7: every way a non-finite number can reach eqs. 7-6 and 7-7 (a unit moment, a gain, the
// command, the velocity angles, an overflow of the quotient) is kBodyDynamicsNotFinite, from each
// branch of the guards: the trimmable one, "no moment at all" and the untrimmable one.
TEST(BodyDynamics, Sec7_NonFiniteInputsAreNamedOnEveryBranch) {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  UnitMoments trimmable;  // K_theta M_delta - M_alpha > 0: eq. 7-6 is solved
  trimmable.m_alpha_lbf_ft_per_rad = -2000.0;
  trimmable.m_delta_lbf_ft_per_rad = 5000.0;
  trimmable.control_lever_ft = 20.0;
  const AutopilotGains gains{1.2, 0.35};
  AutopilotCommand command;
  command.theta_rad = 0.7;
  const PlatformVelocityAngles v{0.6, 0.02};
  SteadyAttitude a;
  ASSERT_EQ(steady_state_attitude(gains, trimmable, command, v, &a), Status::kOk);  // the control
  EXPECT_FALSE(a.follows_command);

  UnitMoments m = trimmable;
  m.m_delta_lbf_ft_per_rad = inf;
  EXPECT_EQ(steady_state_attitude(gains, m, command, v, &a), Status::kBodyDynamicsNotFinite);
  EXPECT_EQ(steady_state_attitude(AutopilotGains{1.2, nan}, trimmable, command, v, &a),
            Status::kBodyDynamicsNotFinite);
  AutopilotCommand bad = command;
  bad.chi_rate_rad_s = nan;
  EXPECT_EQ(steady_state_attitude(gains, trimmable, bad, v, &a), Status::kBodyDynamicsNotFinite);
  EXPECT_TRUE(a.follows_command);
  EXPECT_EQ(steady_state_attitude(gains, trimmable, command, PlatformVelocityAngles{nan, 0.02}, &a),
            Status::kBodyDynamicsNotFinite);
  UnitMoments huge = trimmable;  // finite inputs whose numerator M_alpha gamma_w overflows
  huge.m_alpha_lbf_ft_per_rad = -1e300;
  EXPECT_EQ(steady_state_attitude(gains, huge, command, PlatformVelocityAngles{-1e300, 0.0}, &a),
            Status::kBodyDynamicsNotFinite);

  // No moment at all, yet the command is not finite: not kOk either.
  bad = command;
  bad.theta_rad = nan;
  EXPECT_EQ(steady_state_attitude(gains, UnitMoments{}, bad, v, &a), Status::kBodyDynamicsNotFinite);
  // Untrimmable with a NaN command: still named as not finite (the output is what is wrong).
  UnitMoments balanced = trimmable;
  balanced.m_alpha_lbf_ft_per_rad = 6000.0;
  EXPECT_EQ(steady_state_attitude(gains, balanced, command, v, &a), Status::kBodyDynamicsNotTrimmable);
  EXPECT_EQ(steady_state_attitude(gains, balanced, bad, v, &a), Status::kBodyDynamicsNotFinite);
}

// ---- Sec. 11: platform velocity angles, CONTRL, force resolution ----------------------------------

TEST(BodyDynamics, Sec11_PlatformVelocityAnglesFromInverseC) {
  // Independent construction: V in L is (0, V, 0); solve [C] v_P = v_L with a general 3x3 inverse
  // (not the transpose), and also go L -> inertial ([A]^T) -> platform (([B][B'])^-1).
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  double worst = 0.0;
  for (double gamma = 5.0; gamma < 89.0; gamma += 7.0) {
    for (double dpsi = -20.0; dpsi <= 20.0; dpsi += 10.0) {
      const StateVector x = stage1_state(c, gamma, dpsi);
      const Matrix3 cm = platform_to_local(c, x);
      const Vector3 v_local(0.0, x[kStateV], 0.0);
      const Vector3 by_inverse = cm.inverse() * v_local;
      const Vector3 by_frames =
          c.prepared.platform_to_inertial.inverse() * (inertial_to_local(x).inverse() * v_local);
      for (const Vector3& vp : {by_inverse, by_frames}) {
        const double gamma_w = std::atan(vp.z() / std::sqrt(vp.x() * vp.x() + vp.y() * vp.y()));
        const double a_zw = std::atan(vp.x() / vp.y());  // V_jy > 0 on an ascent
        const PlatformVelocityAngles mine = platform_velocity_angles(cm);
        worst = std::fmax(worst, std::fabs(mine.gamma_w_rad - gamma_w));
        worst = std::fmax(worst, std::fabs(mine.azimuth_w_rad - a_zw));
      }
    }
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(BodyDynamics, Sec11_AnglesOfAttackAgreeWithPlaneGeometry) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const StateVector x = stage1_state(c, 50.0, 3.0);
  const Matrix3 cm = platform_to_local(c, x);
  const PlatformVelocityAngles v = platform_velocity_angles(cm);
  // chi = A_zw: beta = 0 and alpha = theta - gamma_w exactly (the pitch plane holds V).
  const BodyAngles a = body_angles_of_attack(v.gamma_w_rad + 4.0 * kDeg, v.azimuth_w_rad, cm);
  EXPECT_NEAR(a.beta_rad, 0.0, 1e-14);
  EXPECT_NEAR(a.alpha_rad, 4.0 * kDeg, 1e-14);
  // Small angles: alpha ~ theta - gamma_w, beta ~ (chi - A_zw) cos(gamma_w).
  const BodyAngles b = body_angles_of_attack(v.gamma_w_rad + 1e-4, v.azimuth_w_rad + 2e-4, cm);
  EXPECT_NEAR(b.alpha_rad, 1e-4, 1e-8);
  EXPECT_NEAR(b.beta_rad, 2e-4 * std::cos(v.gamma_w_rad), 1e-8);
  // The in-plane alpha nearly agrees with the point-mass model's (thrust axis projected on the
  // i_y-i_z plane of L): the pitch plane of Sec. 7 holds V and the platform vertical j_z, the
  // point-mass one V and the local vertical i_z, which are tilted by delta-lambda (and the range
  // angle) against each other.
  const Vector3 u_local = cm * thrust_axis_platform(v.gamma_w_rad + 4.0 * kDeg, v.azimuth_w_rad);
  EXPECT_NEAR(angle_of_attack_rad(u_local), a.alpha_rad, 1e-5);
}

TEST(BodyDynamics, Sec11_ForcesResolveThroughC) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const StateVector x = stage1_state(c, 40.0, -4.0);
  const Matrix3 cm = platform_to_local(c, x);
  EXPECT_NEAR((cm * cm.transpose() - Matrix3::Identity()).norm(), 0.0, 1e-14);
  for (double theta : {10.0, 45.0, 80.0}) {
    for (double chi : {-3.0, 0.0, 2.0}) {
      const MissileAxes m = missile_axes_platform(theta * kDeg, chi * kDeg);
      // Orthonormal, right-handed, thrust along m_y.
      Matrix3 axes;
      axes.col(0) = m.x;
      axes.col(1) = m.y;
      axes.col(2) = m.z;
      EXPECT_NEAR((axes.transpose() * axes - Matrix3::Identity()).norm(), 0.0, 1e-15);
      EXPECT_NEAR(axes.determinant(), 1.0, 1e-15);
      EXPECT_NEAR((m.y - thrust_axis_platform(theta * kDeg, chi * kDeg)).norm(), 0.0, 1e-15);
      EXPECT_NEAR(m.x.z(), 0.0, 0.0);  // m_x in the j_x, j_y plane
      UnitMoments u;
      u.m_alpha_lbf_ft_per_rad = -4.0e5;
      u.control_lever_ft = 28.0;
      const BodyAngles a{0.03, -0.01};
      const BodyForces f = body_forces(u, a, 3.0e4, theta * kDeg, chi * kDeg, cm);
      // The printed component formulas of Sec. 11.
      const double s_t = std::sin(theta * kDeg), c_t = std::cos(theta * kDeg);
      const double s_c = std::sin(chi * kDeg), c_c = std::cos(chi * kDeg);
      EXPECT_NEAR(f.platform_lbf.x(), f.missile_x_lbf * c_c - f.missile_z_lbf * s_t * s_c, 1e-9);
      EXPECT_NEAR(f.platform_lbf.y(), -f.missile_x_lbf * s_c - f.missile_z_lbf * s_t * c_c, 1e-9);
      EXPECT_NEAR(f.platform_lbf.z(), f.missile_z_lbf * c_t, 1e-9);
      EXPECT_NEAR(f.control_z_lbf, -4.0e5 * 0.03 / 28.0, 1e-9);
      EXPECT_NEAR(f.control_x_lbf, -4.0e5 * -0.01 / 28.0, 1e-9);
      // Magnitudes preserved m -> P -> L, and no component along the thrust axis.
      const double magnitude = std::hypot(f.missile_x_lbf, f.missile_z_lbf);
      EXPECT_NEAR(f.platform_lbf.norm(), magnitude, 1e-9);
      EXPECT_NEAR(f.local_lbf.norm(), magnitude, 1e-9);
      EXPECT_NEAR(f.platform_lbf.dot(m.y), 0.0, 1e-9);
      EXPECT_NEAR((f.local_lbf - cm * f.platform_lbf).norm(), 0.0, 1e-12);
    }
  }
}

TEST(BodyDynamics, Sec11_ForcesEnterVdotGammadotPsidotAsPrinted) {
  // evaluate_flight adds F_iy / m to V-dot, F_iz / (m V) to gamma-dot, F_ix / (m V cos gamma) to
  // psi-dot, and drops the point-mass lift: compared with the point-mass evaluation at the flown
  // attitude with the lift removed.
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const StageContext stage = make_stage_context(c.mission, c.prepared, c.prepared.timeline[0]);
  const StateVector x = stage1_state(c, 55.0, 1.0);
  StepCommand command;
  command.mode = AttitudeMode::kLinear;
  command.theta_start_rad = 58.0 * kDeg;
  command.theta_end_rad = 57.0 * kDeg;
  command.step_start_s = 30.0;
  command.step_s = 1.0;
  command.body_dynamics = true;
  Evaluation six;
  evaluate_flight(c.mission, c.prepared, stage, command, 30.25, x, 0.0, &six);
  ASSERT_EQ(six.body_status, Status::kOk);
  EXPECT_NEAR(six.theta_command_rad, 57.75 * kDeg, 1e-15);
  EXPECT_GT(std::fabs(six.theta_rad - six.theta_command_rad), 1e-4);

  // Point-mass evaluation held at the flown attitude, without lift (a mission with no lift table).
  static Mission no_lift;
  no_lift = c.mission;
  no_lift.vehicle.lift_curve_slope_per_rad.clear();
  StepCommand held;
  held.mode = AttitudeMode::kHeld;
  held.theta_start_rad = held.theta_end_rad = six.theta_rad;
  held.chi_rad = six.chi_rad;
  Evaluation point_mass;
  evaluate_flight(no_lift, c.prepared, stage, held, 30.25, x, 0.0, &point_mass);

  // The Sec. 11 force again, from the pieces.
  const Matrix3 cm = platform_to_local(c, x);
  BodyDynamicsInputs in;
  in.conditions = conditions_at(c, 30.25 - stage.start_s, six.mach, six.dynamic_pressure_lbf_ft2);
  in.command.theta_rad = six.theta_command_rad;
  in.command.theta_rate_rad_s = -1.0 * kDeg;
  in.normal_force_lbf_per_rad = six.dynamic_pressure_lbf_ft2 *
                                c.mission.vehicle.stages[0].reference_area_ft2 *
                                c.mission.vehicle.lift_curve_slope_per_rad(six.mach);
  in.platform_to_local = cm;
  BodyDynamicsResult r;
  ASSERT_EQ(evaluate_body_dynamics(c.mission.body_dynamics, in, &r), Status::kOk);
  EXPECT_NEAR(r.attitude.theta_rad, six.theta_rad, 1e-15);
  const double m = six.weight_lb / c.mission.constants.g0_ft_s2;
  const double v = x[kStateV];
  const Vector3 fl = r.forces.local_lbf;
  EXPECT_NEAR(six.derivative[kStateV] - point_mass.derivative[kStateV], fl.y() / m, 1e-12);
  EXPECT_NEAR(six.derivative[kStateGamma] - point_mass.derivative[kStateGamma], fl.z() / (m * v), 1e-14);
  EXPECT_NEAR(six.derivative[kStatePsi] - point_mass.derivative[kStatePsi],
              fl.x() / (m * v * std::cos(x[kStateGamma])), 1e-14);
  for (int i : {kStateR, kStateLambda, kStateTau}) EXPECT_EQ(six.derivative[i], point_mass.derivative[i]);
  EXPECT_NEAR(six.lift_lbf, fl.z(), 1e-9);
}

// ---- Flying it ----------------------------------------------------------------------------------

struct Pair {
  Trajectory point_mass;
  Trajectory six_d;
};

const Pair& flown_pair(test::ReferenceProgram program) {
  static Pair* optimum = nullptr;
  static Pair* initial = nullptr;
  Pair*& slot = program == test::ReferenceProgram::kOptimum ? optimum : initial;
  if (slot == nullptr) {
    slot = new Pair;
    const Case& c = reference_case(program);
    EXPECT_EQ(fly_trajectory(c.mission, c.prepared, &slot->point_mass), Status::kOk);
    FlightInputs inputs;
    inputs.body_dynamics = true;
    EXPECT_EQ(fly_trajectory(c.mission, c.prepared, inputs, &slot->six_d), Status::kOk);
  }
  return *slot;
}

const TrajectoryPoint& end_of_stage(const Trajectory& t, int code) {
  for (int k = 0; k < t.stage_count; ++k) {
    if (t.stages[k].code == code) return t.points[t.stages[k].last_point];
  }
  return t.final_point();
}

void report_differences(const char* name, const Pair& pair) {
  for (int code : {1, 6, 4}) {
    const TrajectoryPoint& a = end_of_stage(pair.point_mass, code);
    const TrajectoryPoint& b = end_of_stage(pair.six_d, code);
    std::printf(
        "[ figures ] %s, end of stage %d: 6D - point mass: V %+.2f ft/s, altitude %+.1f ft, "
        "gamma %+.4f deg (point mass V %.2f ft/s, h %.1f ft, gamma %.4f deg)\n",
        name, code, b.state[kStateV] - a.state[kStateV], b.altitude_ft - a.altitude_ft,
        (b.state[kStateGamma] - a.state[kStateGamma]) / kDeg, a.state[kStateV], a.altitude_ft,
        a.state[kStateGamma] / kDeg);
  }
  double worst_lag = 0.0, worst_alpha_pm = 0.0, worst_alpha_6d = 0.0, worst_delta = 0.0;
  for (int i = 0; i < pair.six_d.point_count; ++i) {
    const TrajectoryPoint& p = pair.six_d.points[i];
    if (!p.body_dynamics) continue;
    worst_lag = std::fmax(worst_lag, std::fabs(p.theta_rad - static_cast<double>(p.theta_command_rad)));
    worst_alpha_6d = std::fmax(worst_alpha_6d, std::fabs(p.alpha_rad));
    worst_alpha_pm = std::fmax(worst_alpha_pm, std::fabs(pair.point_mass.points[i].alpha_rad));
    worst_delta = std::fmax(worst_delta, std::fabs(static_cast<double>(p.control_deflection_rad)));
  }
  std::printf(
      "[ figures ] %s, stage 1 + coast 6: max |theta - theta_c| %.3f deg, max |alpha| 6D %.3f deg "
      "(point mass %.3f deg), max |delta| %.3f deg\n",
      name, worst_lag / kDeg, worst_alpha_6d / kDeg, worst_alpha_pm / kDeg, worst_delta / kDeg);
}

TEST(BodyDynamics, Sec11_Reference6DTrajectoryFliesToTheEnd) {
  for (test::ReferenceProgram program :
       {test::ReferenceProgram::kInitialNominal, test::ReferenceProgram::kOptimum}) {
    const Pair& pair = flown_pair(program);
    const char* name = program == test::ReferenceProgram::kOptimum ? "reference optimum" : "block-40 program";
    ASSERT_EQ(pair.six_d.status, Status::kOk) << name;
    EXPECT_EQ(pair.six_d.point_count, pair.point_mass.point_count);
    EXPECT_EQ(pair.six_d.final_point().time_s, pair.point_mass.final_point().time_s);
    int six_d_points = 0;
    for (int i = 0; i < pair.six_d.point_count; ++i) {
      const TrajectoryPoint& p = pair.six_d.points[i];
      EXPECT_TRUE(p.state.allFinite());
      EXPECT_TRUE(std::isfinite(p.theta_rad) && std::isfinite(p.alpha_rad) && std::isfinite(p.lift_lbf));
      six_d_points += p.body_dynamics ? 1 : 0;
      EXPECT_EQ(p.body_dynamics, i > 0 && (p.stage_code == 1 || p.stage_code == 6)) << i;
    }
    EXPECT_GT(six_d_points, 40);
    OrbitElements elements;
    EXPECT_EQ(
        compute_orbit_elements(reference_case(program).mission.constants, pair.six_d.final_point().state,
                               reference_case(program).mission.launch.launch_space_age_date_days, &elements),
        Status::kOk);
    report_differences(name, pair);
    // The weathercocking reduces the flown alpha in stage 1: the 6D vehicle turns less.
    const TrajectoryPoint& a = end_of_stage(pair.point_mass, 1);
    const TrajectoryPoint& b = end_of_stage(pair.six_d, 1);
    EXPECT_GT(b.state[kStateGamma], a.state[kStateGamma]) << name;
  }
}

TEST(BodyDynamics, Sec11_OnlyStageOneAndFollowingCoast) {
  // Every other stage follows the command: after coast 6 the 6D run is the point-mass run started
  // from the 6D state. Fly the point mass from the 6D state at stage-2 ignition by injecting the
  // state difference there; every later point must agree to round-off (state + (b - a) is not
  // exactly b), and no later point is flagged 6D.
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const Pair& pair = flown_pair(test::ReferenceProgram::kOptimum);
  int first = -1;
  for (int k = 0; k < pair.six_d.stage_count; ++k) {
    if (pair.six_d.stages[k].code == 2) first = pair.six_d.stages[k].first_point;
  }
  ASSERT_GT(first, 0);
  // Stage 1 and coast 6 differ; the pitch commands are the same everywhere (block 40 table).
  EXPECT_NE(pair.six_d.points[first].state, pair.point_mass.points[first].state);
  static Trajectory replay;
  FlightInputs inputs;
  inputs.injection_point = first;
  inputs.injection = pair.six_d.points[first].state - pair.point_mass.points[first].state;
  ASSERT_EQ(fly_trajectory(c.mission, c.prepared, inputs, &replay), Status::kOk);
  double worst = 0.0;
  for (int i = first; i < replay.point_count; ++i) {
    const TrajectoryPoint& p = pair.six_d.points[i];
    const TrajectoryPoint& q = replay.points[i];
    EXPECT_FALSE(p.body_dynamics);
    EXPECT_NEAR(p.theta_rad, q.theta_rad, 1e-12) << i;
    EXPECT_EQ(p.chi_rad, q.chi_rad) << i;
    EXPECT_EQ(p.theta_rad, static_cast<double>(p.theta_command_rad) +
                               (p.theta_rad - static_cast<double>(p.theta_command_rad)));
    for (int j = 0; j < 6; ++j) {
      const double scale = std::fmax(1.0, std::fabs(p.state[j]));
      worst = std::fmax(worst, std::fabs(p.state[j] - q.state[j]) / scale);
    }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(BodyDynamics, Sec11_OffIsThePointMassRunBitForBit) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const Pair& pair = flown_pair(test::ReferenceProgram::kOptimum);
  static Trajectory off;
  FlightInputs inputs;
  inputs.body_dynamics = false;
  ASSERT_EQ(fly_trajectory(c.mission, c.prepared, inputs, &off), Status::kOk);
  ASSERT_EQ(off.point_count, pair.point_mass.point_count);
  for (int i = 0; i < off.point_count; ++i) {
    EXPECT_EQ(off.points[i].state, pair.point_mass.points[i].state);
    EXPECT_FALSE(off.points[i].body_dynamics);
    EXPECT_EQ(off.points[i].control_deflection_rad, 0.0f);
    EXPECT_EQ(static_cast<double>(off.points[i].theta_command_rad),
              static_cast<double>(static_cast<float>(off.points[i].theta_rad)));
  }
}

TEST(BodyDynamics, Sec11_ExplicitProgramIsTheCommand) {
  // With an explicit per-point program (the optimizer's control) the 6D run flies about that
  // program: at every step whose attitude the program decides, the stored command is the program's
  // value and the flown attitude is the steady state about it (different where q-bar acts).
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const Pair& pair = flown_pair(test::ReferenceProgram::kOptimum);
  static ControlProgram program;
  program.point_count = pair.point_mass.point_count;
  for (int i = 0; i < program.point_count; ++i) {
    // A program of its own: the point-mass commands, bent by a slow ripple.
    program.theta_rad[i] = pair.point_mass.points[i].theta_rad + 0.5 * kDeg * std::sin(0.1 * i);
  }
  static Trajectory six;
  FlightInputs inputs;
  inputs.program = &program;
  inputs.body_dynamics = true;
  ASSERT_EQ(fly_trajectory(c.mission, c.prepared, inputs, &six), Status::kOk);
  int checked = 0;
  double largest_lag = 0.0;
  for (int k = 0; k < six.step_count; ++k) {
    const StepRecord& step = six.steps[k];
    const TrajectoryPoint& p = six.points[step.point];
    if (step.command.mode != AttitudeMode::kLinear) continue;
    const StageTimeline& line = c.prepared.timeline[step.stage_slot];
    if (attitude_set_in_flight(c.mission, line.code, line.start_s, p.time_s)) continue;
    EXPECT_EQ(step.command.theta_start_rad, program.theta_rad[step.point]);
    EXPECT_EQ(step.command.theta_end_rad, program.theta_rad[step.point + 1]);
    EXPECT_EQ(p.theta_command_rad, static_cast<float>(program.theta_rad[step.point]));
    EXPECT_EQ(step.command.body_dynamics, line.code == 1 || line.code == 6);
    if (!p.body_dynamics) {
      EXPECT_EQ(p.theta_rad, program.theta_rad[step.point]);
    } else {
      largest_lag = std::fmax(largest_lag, std::fabs(p.theta_rad - program.theta_rad[step.point]));
    }
    ++checked;
  }
  EXPECT_GT(checked, 100);
  EXPECT_GT(largest_lag, 0.5 * kDeg);
}

TEST(BodyDynamics, Sec10_BackwardRunLinearizesTheSixDModel) {
  // Sec. 10: 6D linearization runs are "backward and forward" runs with 6D considerations. The
  // backward run re-evaluates each recorded step's command, which carries the 6D flag, and takes
  // the partials with respect to the commanded rate as well (the steady state of eq. 7-6 depends on
  // theta_c-dot), so its adjoint is the gradient of the 6D trajectory: theta windows in stage 1
  // (the kick, and across the start of the zero-alpha window) and coast 6, and a state perturbation
  // in stage 1, against central differences of 6D forward runs.
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  const Pair& pair = flown_pair(test::ReferenceProgram::kOptimum);
  static ControlProgram program;
  program.point_count = pair.point_mass.point_count;
  for (int i = 0; i < program.point_count; ++i) program.theta_rad[i] = pair.point_mass.points[i].theta_rad;
  static Trajectory nominal;
  static Trajectory perturbed;
  static BackwardRun backward;
  FlightInputs inputs;
  inputs.program = &program;
  inputs.body_dynamics = true;
  ASSERT_EQ(fly_trajectory(c.mission, c.prepared, inputs, &nominal), Status::kOk);
  // Terminal V, gamma, r at the final point.
  constexpr int kCount = 3;
  const int components[kCount] = {kStateV, kStateGamma, kStateR};
  ConstraintTerminal terminals[kCount];
  for (int j = 0; j < kCount; ++j) {
    terminals[j].point = nominal.point_count - 1;
    terminals[j].partials[components[j]] = 1.0;
  }
  ASSERT_EQ(run_backward(c.mission, c.prepared, nominal, kCount, terminals, &backward), Status::kOk);

  auto check = [&](const char* what, const double predicted[kCount], const StateVector& plus,
                   const StateVector& minus) {
    for (int j = 0; j < kCount; ++j) {
      const double fd = (plus[components[j]] - minus[components[j]]) / 2.0;
      std::printf("[ figures ] 6D adjoint %-16s X[%d]: adjoint % .6e  fd % .6e\n", what, components[j],
                  predicted[j], fd);
      EXPECT_LE(std::fabs(predicted[j] - fd), 1e-4 * std::fabs(fd) + 1e-12) << what << " " << j;
    }
  };
  static ControlProgram changed;
  const double windows[][2] = {{4.5, 7.5}, {9.5, 13.5}, {45.5, 49.0}, {7.5, 16.5}};
  const double d_theta = 1e-3;
  for (const auto& w : windows) {
    double predicted[kCount] = {};
    for (int i = 0; i < nominal.point_count; ++i) {
      const double t = nominal.points[i].time_s;
      if (t < w[0] || t > w[1]) continue;
      for (int j = 0; j < kCount; ++j) predicted[j] += backward.theta_gradient[i](j) * d_theta;
    }
    StateVector ends[2];
    for (int s = 0; s < 2; ++s) {
      changed = program;
      for (int i = 0; i < nominal.point_count; ++i) {
        const double t = nominal.points[i].time_s;
        if (t >= w[0] && t <= w[1]) changed.theta_rad[i] += (s == 0 ? 1.0 : -1.0) * d_theta;
      }
      FlightInputs moved = inputs;
      moved.program = &changed;
      ASSERT_EQ(fly_trajectory(c.mission, c.prepared, moved, &perturbed), Status::kOk);
      ends[s] = perturbed.final_point().state;
    }
    char what[32];
    std::snprintf(what, sizeof what, "theta %.0f-%.0f s", w[0], w[1]);
    check(what, predicted, ends[0], ends[1]);
  }
  // dgamma = 1e-4 rad at 30 s.
  int point = 0;
  for (int i = 1; i < nominal.point_count; ++i) {
    if (std::fabs(nominal.points[i].time_s - 30.0) < std::fabs(nominal.points[point].time_s - 30.0))
      point = i;
  }
  ASSERT_TRUE(nominal.points[point].body_dynamics);
  double predicted[kCount];
  for (int j = 0; j < kCount; ++j) predicted[j] = backward.lambda[point](kStateGamma, j) * 1e-4;
  StateVector ends[2];
  for (int s = 0; s < 2; ++s) {
    FlightInputs kicked = inputs;
    kicked.injection_point = point;
    kicked.injection[kStateGamma] = (s == 0 ? 1.0 : -1.0) * 1e-4;
    ASSERT_EQ(fly_trajectory(c.mission, c.prepared, kicked, &perturbed), Status::kOk);
    ends[s] = perturbed.final_point().state;
  }
  check("dgamma at 30 s", predicted, ends[0], ends[1]);
}

TEST(BodyDynamics, Sec11_SixDRunWithoutDataFailsBeforeFlying) {
  static Case bare;
  bare.mission = reference_case(test::ReferenceProgram::kOptimum).mission;
  bare.prepared = reference_case(test::ReferenceProgram::kOptimum).prepared;
  bare.mission.body_dynamics = BodyDynamicsBlocks{};
  static Trajectory t;
  FlightInputs inputs;
  inputs.body_dynamics = true;
  EXPECT_EQ(fly_trajectory(bare.mission, bare.prepared, inputs, &t), Status::kBodyDynamicsDataMissing);
  // validate_mission asks for blocks 33-37 when IP(6) >= 1 (the reference has IP(6) = 1).
  MissionFault fault;
  EXPECT_EQ(validate_mission(bare.mission, &fault), Status::kBodyDynamicsDataMissing);
  EXPECT_EQ(fault.data_block, 33);
  bare.mission.options.ip[6] = 0;
  EXPECT_EQ(validate_mission(bare.mission, &fault), Status::kOk);
}

TEST(BodyDynamics, Sec11_ValidationNamesTheFaultyBlock) {
  static Mission m;
  m = reference_case(test::ReferenceProgram::kOptimum).mission;
  MissionFault fault;
  ASSERT_EQ(validate_body_dynamics(m, &fault), Status::kOk);
  m.body_dynamics.control_station_ft[0] = 500.0 / 12.0;  // inside the stage-1 c.g. range 478-515 in
  EXPECT_EQ(validate_body_dynamics(m, &fault), Status::kControlStationAtCenterOfGravity);
  EXPECT_EQ(fault.data_block, 33);
  m = reference_case(test::ReferenceProgram::kOptimum).mission;
  m.body_dynamics.position_gain[0] = 0.0;
  EXPECT_EQ(validate_body_dynamics(m, &fault), Status::kBodyDynamicsValueOutOfRange);
  m = reference_case(test::ReferenceProgram::kOptimum).mission;
  m.body_dynamics.pitching_moment_per_rad.clear();
  EXPECT_EQ(validate_body_dynamics(m, &fault), Status::kBodyDynamicsDataMissing);
  EXPECT_EQ(fault.data_block, 35);
  m = reference_case(test::ReferenceProgram::kOptimum).mission;
  m.body_dynamics.cg_station_ft[0].clear();
  EXPECT_EQ(validate_body_dynamics(m, &fault), Status::kBodyDynamicsDataMissing);
  EXPECT_EQ(fault.data_block, 37);
  EXPECT_EQ(fault.stage_code, 1);
  m = reference_case(test::ReferenceProgram::kOptimum).mission;
  m.body_dynamics.reference_length_ft = std::nan("");
  EXPECT_EQ(validate_body_dynamics(m, &fault), Status::kValueNotFinite);
}

// ---- DA6D(12-15): the 6D integration frequency multipliers (Sec. 22, data block 33) ------------

// The reference optimum flown 6D with every multiplier of stages 1-4 set to m.
const Trajectory& six_d_with_substeps(int m) {
  static Trajectory* flown[9] = {};
  if (flown[m] == nullptr) {
    const Case& c = reference_case(test::ReferenceProgram::kOptimum);
    static Mission mission;
    mission = c.mission;
    for (double& multiplier : mission.body_dynamics.integration_frequency_multiplier) multiplier = m;
    EXPECT_EQ(validate_mission(mission, nullptr), Status::kOk);
    flown[m] = new Trajectory;
    FlightInputs inputs;
    inputs.body_dynamics = true;
    EXPECT_EQ(fly_trajectory(mission, c.prepared, inputs, flown[m]), Status::kOk) << m;
  }
  return *flown[m];
}

int first_point_of_stage(const Trajectory& t, int code) {
  for (int k = 0; k < t.stage_count; ++k) {
    if (t.stages[k].code == code) return t.stages[k].first_point;
  }
  return -1;
}

// Distance of two states: their inertial positions (ft, frame free) and their speeds (ft/s).
struct StateDistance {
  double position_ft;
  double speed_ft_s;
};
StateDistance distance(const StateVector& a, const StateVector& b) {
  const auto position = [](const StateVector& x) {
    const double r = x[kStateR];
    return Vector3(r * std::cos(x[kStateLambda]) * std::cos(x[kStateTau]),
                   r * std::cos(x[kStateLambda]) * std::sin(x[kStateTau]), r * std::sin(x[kStateLambda]));
  };
  return {(position(a) - position(b)).norm(), std::fabs(a[kStateV] - b[kStateV])};
}

// Richardson: halving the substep of a fourth-order method divides the error, hence the difference
// of successive halvings, by 2^4 = 16, while the integrand is smooth within a step. The tables the
// equations interpolate linearly in Mach (C_D, C_L_alpha, the moment coefficients) have knots that
// fall inside steps; their kinks cost RK4 its order, so once their error dominates a halving gains
// about 2^2 = 4. At stage-2 ignition (stage 1 and coast 6: RK4 steps for
// every m) the first halving shows the fourth order, the next one the kinks; at the final point
// m = 1 flies the coasts with Adams-Bashforth (RKAD) and the long coast before stage 4 carries the
// powered stages' velocity differences, so there every halving must only shrink the difference. The
// trajectory keeps its points: one per step, whatever m.
TEST(BodyDynamics, Sec22_IntegrationMultipliersConvergeAtFourthOrder) {
  const Trajectory& t1 = six_d_with_substeps(1);
  const Trajectory& t2 = six_d_with_substeps(2);
  const Trajectory& t4 = six_d_with_substeps(4);
  const Trajectory& t8 = six_d_with_substeps(8);
  ASSERT_EQ(t2.point_count, t1.point_count);
  ASSERT_EQ(t4.point_count, t1.point_count);
  ASSERT_EQ(t8.point_count, t1.point_count);
  const int ignition = first_point_of_stage(t1, 2);
  ASSERT_GT(ignition, 0);
  const StateDistance i12 = distance(t1.points[ignition].state, t2.points[ignition].state);
  const StateDistance i24 = distance(t2.points[ignition].state, t4.points[ignition].state);
  const StateDistance i48 = distance(t4.points[ignition].state, t8.points[ignition].state);
  const int last = t1.point_count - 1;
  const StateDistance f12 = distance(t1.points[last].state, t2.points[last].state);
  const StateDistance f24 = distance(t2.points[last].state, t4.points[last].state);
  const StateDistance f48 = distance(t4.points[last].state, t8.points[last].state);
  std::printf(
      "[ figures ] DA6D(12-15) stage-2 ignition: position 1->2 %.4g ft, 2->4 %.4g ft, 4->8 %.4g ft; "
      "speed 1->2 %.4g, 2->4 %.4g, 4->8 %.4g ft/s\n",
      i12.position_ft, i24.position_ft, i48.position_ft, i12.speed_ft_s, i24.speed_ft_s, i48.speed_ft_s);
  std::printf(
      "[ figures ] DA6D(12-15) final point: position 1->2 %.4g ft, 2->4 %.4g ft, 4->8 %.4g ft; "
      "speed 1->2 %.4g, 2->4 %.4g, 4->8 %.4g ft/s\n",
      f12.position_ft, f24.position_ft, f48.position_ft, f12.speed_ft_s, f24.speed_ft_s, f48.speed_ft_s);
  // The substeps act: m = 2 differs from m = 1.
  EXPECT_GT(i12.position_ft, 0.0);
  EXPECT_GT(f12.position_ft, 0.0);
  // Fourth order at the first halving (measured 12.1; a second-order method gives 4, a first-order
  // one 2), at least the kinks' second order at the next (measured 3.7).
  EXPECT_GT(i12.position_ft / i24.position_ft, 8.0);
  EXPECT_GT(i24.position_ft / i48.position_ft, 3.0);
  EXPECT_LT(f24.position_ft, f12.position_ft);
  EXPECT_LT(f48.position_ft, f24.position_ft);
}

// Each word acts on its own stage and the coast after it: DA6D(13) = 2 (stage 2) leaves stage 1
// and coast 6 bit for bit and changes the points after the first step of stage 2.
TEST(BodyDynamics, Sec22_IntegrationMultiplierActsOnItsOwnStage) {
  const Case& c = reference_case(test::ReferenceProgram::kOptimum);
  static Mission mission;
  mission = c.mission;
  mission.body_dynamics.integration_frequency_multiplier[1] = 2.0;
  static Trajectory stage2;
  FlightInputs inputs;
  inputs.body_dynamics = true;
  ASSERT_EQ(fly_trajectory(mission, c.prepared, inputs, &stage2), Status::kOk);
  const Trajectory& base = six_d_with_substeps(1);
  const int ignition = first_point_of_stage(base, 2);
  ASSERT_EQ(stage2.point_count, base.point_count);
  for (int i = 0; i <= ignition; ++i) EXPECT_EQ(stage2.points[i].state, base.points[i].state) << i;
  EXPECT_NE(stage2.points[ignition + 1].state, base.points[ignition + 1].state);
  // Point-mass runs ignore the words (Sec. 22: "during 6D forward trajectories").
  static Trajectory point_mass;
  ASSERT_EQ(fly_trajectory(mission, c.prepared, &point_mass), Status::kOk);
  const Pair& pair = flown_pair(test::ReferenceProgram::kOptimum);
  for (int i = 0; i < point_mass.point_count; ++i) {
    EXPECT_EQ(point_mass.points[i].state, pair.point_mass.points[i].state) << i;
  }
  // Stage k's word serves stage k and the coast after it; stage 5 has none.
  BodyDynamicsBlocks b;
  for (int k = 0; k < 4; ++k) b.integration_frequency_multiplier[k] = k + 2;
  EXPECT_EQ(integration_substeps(b, 1, true), 2);
  EXPECT_EQ(integration_substeps(b, 6, true), 2);
  EXPECT_EQ(integration_substeps(b, 4, true), 5);
  EXPECT_EQ(integration_substeps(b, 9, true), 5);
  EXPECT_EQ(integration_substeps(b, 5, true), 1);
  EXPECT_EQ(integration_substeps(b, 10, true), 1);
  EXPECT_EQ(integration_substeps(b, 1, false), 1);
}

// A whole number of substeps, at least 1, at most the capacity: one status per cause, naming the
// word (data block 33, field and element).
TEST(BodyDynamics, Sec22_IntegrationMultiplierValidationNamesEachCause) {
  static Mission m;
  const struct {
    double value;
    Status status;
  } cases[] = {
      {1.5, Status::kIntegrationMultiplierNotInteger},
      {0.0, Status::kIntegrationMultiplierBelowOne},
      {-2.0, Status::kIntegrationMultiplierBelowOne},
      {kMaxIntegrationFrequencyMultiplier + 1.0, Status::kIntegrationMultiplierAboveCapacity},
      {std::nan(""), Status::kValueNotFinite},
  };
  for (const auto& c : cases) {
    m = reference_case(test::ReferenceProgram::kOptimum).mission;
    m.body_dynamics.integration_frequency_multiplier[2] = c.value;
    MissionFault fault;
    EXPECT_EQ(validate_mission(m, &fault), c.status) << c.value;
    EXPECT_EQ(fault.data_block, 33);
    EXPECT_STREQ(fault.field, "integration_frequency_multiplier");
    EXPECT_EQ(fault.index, 2);
    EXPECT_EQ(validate_body_dynamics(m, &fault), c.status) << c.value;
    // Checked without body dynamics too: the words are data of the case.
    m.options.ip[6] = 0;
    EXPECT_EQ(validate_mission(m, &fault), c.status) << c.value;
  }
  m = reference_case(test::ReferenceProgram::kOptimum).mission;
  m.body_dynamics.integration_frequency_multiplier[3] = kMaxIntegrationFrequencyMultiplier;
  EXPECT_EQ(validate_mission(m, nullptr), Status::kOk);
}

TEST(BodyDynamics, Sec11_TrajectoryPointDidNotGrow) {
  // The commanded theta and the deflection live in padding: a point is still 240 bytes.
  EXPECT_EQ(sizeof(TrajectoryPoint), 240u);
  EXPECT_EQ(sizeof(StepCommand), 56u);
}

}  // namespace
}  // namespace tolip
