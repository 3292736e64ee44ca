// Issue 16 (manual Sec. 7 eqs. 7-1 to 7-4, Sec. 16 moment terms): autopilot gains placed at a
// requested natural frequency and damping. Independent truth: Eigen's eigenvalues of the loop's
// state matrix, a step response integrated here (RK4) against the analytic second-order response,
// Routh-Hurwitz margins against the eigenvalues of the 3-state loop with the actuator lag.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>

#include "support/reference_mission.hpp"
#include "tolip/autopilot/autopilot_design.hpp"
#include "tolip/core/constants.hpp"

namespace tolip {
namespace {

// Models per unit inertia: a = M_alpha / I (> 0 statically unstable), b = M_delta / I, c = M_q / I.
ShortPeriodModel model(double a, double b, double c) {
  ShortPeriodModel m;
  m.pitch_inertia_slug_ft2 = 2.0e5;
  m.m_alpha_lbf_ft_per_rad = a * m.pitch_inertia_slug_ft2;
  m.m_delta_lbf_ft_per_rad = b * m.pitch_inertia_slug_ft2;
  m.m_q_aero_lbf_ft_s_per_rad = c * m.pitch_inertia_slug_ft2;
  m.a_per_s2 = a;
  m.b_per_s2 = b;
  m.c_per_s = c;
  return m;
}

AutopilotRequest request(double w, double zeta, double tau = 0.0) {
  AutopilotRequest r;
  r.natural_frequency_rad_s = w;
  r.damping_ratio = zeta;
  r.attitude_error_rad = 2.0 * kDegToRad;
  r.max_deflection_rad = 10.0 * kDegToRad;
  r.actuator_time_constant_s = tau;
  return r;
}

// The models of the test: stable, unstable (M_alpha > 0), lightly damped, jet-vane only (a = 0).
struct Case {
  double a, b, c, w, zeta;
};
constexpr Case kCases[] = {
    {-4.0, 9.0, -0.3, 3.0, 0.7}, {2.5, 6.0, -0.1, 2.5, 0.5},  {-0.5, 3.0, 0.0, 1.5, 0.9},
    {0.0, 1.2, -0.05, 1.0, 0.6}, {6.0, 12.0, -0.4, 4.0, 0.3}, {-10.0, 20.0, -1.0, 4.5, 0.8},
};

Eigen::Matrix2d closed_loop_matrix(const ShortPeriodModel& m, double k_theta, double k_q) {
  Eigen::Matrix2d A;
  A << 0.0, 1.0, -(k_theta * m.b_per_s2 - m.a_per_s2), -(k_q * m.b_per_s2 - m.c_per_s);
  return A;
}

TEST(AutopilotDesign, Issue16_ClosedLoopEigenvaluesMeetTheRequestedFrequencyAndDamping) {
  double worst = 0.0;
  for (const Case& k : kCases) {
    const ShortPeriodModel m = model(k.a, k.b, k.c);
    AutopilotDesign d;
    ASSERT_EQ(design_autopilot_gains(m, request(k.w, k.zeta), &d), Status::kOk);
    Eigen::EigenSolver<Eigen::Matrix2d> eig(closed_loop_matrix(m, d.k_theta, d.k_q_s));
    for (int i = 0; i < 2; ++i) {
      const std::complex<double> s = eig.eigenvalues()(i);
      const double wn = std::abs(s);
      const double zeta = -s.real() / wn;
      worst = std::fmax(worst, std::fabs(wn - k.w) / k.w);
      worst = std::fmax(worst, std::fabs(zeta - k.zeta) / k.zeta);
      // The design's own closed-loop roots are the eigenvalues.
      const double re = d.closed_loop.re[0], im = std::fabs(d.closed_loop.im[0]);
      EXPECT_NEAR(s.real(), re, 1e-9 * k.w);
      EXPECT_NEAR(std::fabs(s.imag()), im, 1e-9 * k.w);
    }
    // Open-loop poles: s^2 - c s - a, a positive real root when a > 0.
    if (k.a > 0.0) EXPECT_GT(std::fmax(d.open_loop.re[0], d.open_loop.re[1]), 0.0);
  }
  EXPECT_LT(worst, 1e-6);
  std::printf("closed-loop w_n and zeta from Eigen eigenvalues: worst relative error %.2e\n", worst);
}

// Step in theta_c from rest, the linear loop integrated by RK4 (dt = period / 20000), normalised by
// its final value; against the analytic second-order response and its formulas.
TEST(AutopilotDesign, Issue16_StepResponseHasTheOvershootAndSettlingTimeOfTheSecondOrderFormulas) {
  for (const Case& k : kCases) {
    const ShortPeriodModel m = model(k.a, k.b, k.c);
    AutopilotDesign d;
    ASSERT_EQ(design_autopilot_gains(m, request(k.w, k.zeta), &d), Status::kOk);
    const Eigen::Matrix2d A = closed_loop_matrix(m, d.k_theta, d.k_q_s);
    const Eigen::Vector2d B(0.0, d.k_theta * m.b_per_s2);
    const double final_value = d.k_theta * m.b_per_s2 / (d.k_theta * m.b_per_s2 - m.a_per_s2);
    const double dt = 2.0 * kPi / k.w / 20000.0;
    const double horizon = 12.0 / (k.zeta * k.w);
    Eigen::Vector2d x = Eigen::Vector2d::Zero();
    double peak = 0.0, settled_at = 0.0;
    for (double t = 0.0; t < horizon; t += dt) {
      auto f = [&](const Eigen::Vector2d& y) -> Eigen::Vector2d { return A * y + B; };
      const Eigen::Vector2d k1 = f(x), k2 = f(x + 0.5 * dt * k1), k3 = f(x + 0.5 * dt * k2),
                            k4 = f(x + dt * k3);
      x += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      const double y = x(0) / final_value;
      peak = std::fmax(peak, y);
      if (std::fabs(y - 1.0) > 0.02) settled_at = t + dt;
    }
    // Independent formulas: overshoot exp(-pi zeta / sqrt(1 - zeta^2)); settling time the last time
    // the analytic response 1 - exp(-zeta w t) sin(w_d t + phi) / sqrt(1 - zeta^2) leaves the 2 % band.
    const double z = k.zeta, w = k.w, root = std::sqrt(1.0 - z * z);
    const double overshoot = std::exp(-kPi * z / root);
    const double phi = std::acos(z);
    double analytic_settling = 0.0;
    for (double t = 0.0; t < horizon; t += dt * 0.25) {
      const double y = 1.0 - std::exp(-z * w * t) * std::sin(w * root * t + phi) / root;
      if (std::fabs(y - 1.0) > 0.02) analytic_settling = t;
    }
    EXPECT_NEAR(peak - 1.0, overshoot, 0.02 * overshoot) << "zeta " << z;
    EXPECT_NEAR(settled_at, analytic_settling, 0.02 * analytic_settling) << "zeta " << z;
    // And the envelope bound -ln(0.02 sqrt(1 - zeta^2)) / (zeta w) is never exceeded.
    EXPECT_LE(settled_at, -std::log(0.02 * root) / (z * w) * 1.0001);
  }
}

// Margins at the actuator: the closed loop with the loop gain times the upper (lower) gain margin
// has an eigenvalue on the imaginary axis (3 states with the lag: theta, q, delta); the phase
// margin rotates L(j w_c) onto -1.
TEST(AutopilotDesign, Issue16_GainAndPhaseMarginsAtTheActuatorAreWhereTheLoopGoesUnstable) {
  const double tau = 0.05;
  int finite_upper = 0;
  for (const Case& k : kCases) {
    const ShortPeriodModel m = model(k.a, k.b, k.c);
    AutopilotDesign d;
    ASSERT_EQ(design_autopilot_gains(m, request(k.w, k.zeta, tau), &d), Status::kOk);
    ASSERT_TRUE(d.margins.closed_loop_stable);
    auto max_real = [&](double gain) {
      // x = (theta, q, delta): delta-dot = (gain (-K_theta theta - K_q q) - delta) / tau.
      Eigen::Matrix3d A;
      A << 0.0, 1.0, 0.0, m.a_per_s2, m.c_per_s, m.b_per_s2, -gain * d.k_theta / tau, -gain * d.k_q_s / tau,
          -1.0 / tau;
      Eigen::EigenSolver<Eigen::Matrix3d> eig(A);
      double r = -1e300;
      for (int i = 0; i < 3; ++i) r = std::fmax(r, eig.eigenvalues()(i).real());
      return r;
    };
    EXPECT_LT(max_real(1.0), 0.0);
    if (std::isfinite(d.margins.upper_gain_margin)) {
      ++finite_upper;
      EXPECT_NEAR(max_real(d.margins.upper_gain_margin), 0.0, 1e-7 * k.w);
      EXPECT_GT(max_real(d.margins.upper_gain_margin * 1.01), 0.0);
      EXPECT_LT(max_real(d.margins.upper_gain_margin * 0.99), 0.0);
    } else {
      // Relative degree 2 with the lag: the phase never reaches -180 deg, no gain destabilizes.
      for (double gain : {10.0, 1e3, 1e5}) EXPECT_LT(max_real(gain), 0.0) << gain;
    }
    if (k.a > 0.0) {
      EXPECT_GT(d.margins.lower_gain_margin, 0.0);
      EXPECT_NEAR(max_real(d.margins.lower_gain_margin), 0.0, 1e-7 * k.w);
      EXPECT_GT(max_real(d.margins.lower_gain_margin * 0.99), 0.0);
    } else {
      EXPECT_EQ(d.margins.lower_gain_margin, 0.0);
    }
    // Phase margin: |L(j w_c)| = 1 and L(j w_c) e^{-j PM} = -1.
    ASSERT_GT(d.margins.crossover_rad_s, 0.0);
    const std::complex<double> s(0.0, d.margins.crossover_rad_s);
    const std::complex<double> L =
        m.b_per_s2 * (d.k_theta + d.k_q_s * s) / ((s * s - m.c_per_s * s - m.a_per_s2) * (tau * s + 1.0));
    EXPECT_NEAR(std::abs(L), 1.0, 1e-9);
    const std::complex<double> rotated = L * std::exp(std::complex<double>(0.0, -d.margins.phase_margin_rad));
    EXPECT_NEAR(rotated.real(), -1.0, 1e-8);
    EXPECT_NEAR(rotated.imag(), 0.0, 1e-8);
    EXPECT_GT(d.margins.phase_margin_rad, 0.0);
  }
  // A slow actuator with a rate gain small against the position gain: a finite upper margin.
  {
    const ShortPeriodModel m = model(-4.0, 9.0, -0.3);
    AutopilotDesign d;
    ASSERT_EQ(design_autopilot_gains(m, request(3.0, 0.2, 0.2), &d), Status::kOk);
    EXPECT_TRUE(std::isfinite(d.margins.upper_gain_margin));
    EXPECT_TRUE(d.margins.closed_loop_stable);
    EXPECT_NEAR(d.margins.upper_gain_margin, 8.1, 0.2);
    ++finite_upper;
  }
  EXPECT_GE(finite_upper, 1);
  // Without a lag no finite gain increase destabilizes the loop.
  AutopilotDesign d;
  ASSERT_EQ(design_autopilot_gains(model(-4.0, 9.0, -0.3), request(3.0, 0.7), &d), Status::kOk);
  EXPECT_TRUE(std::isinf(d.margins.upper_gain_margin));
}

TEST(AutopilotDesign, Issue16_BadRequestsAreRejectedByName) {
  const ShortPeriodModel m = model(2.5, 6.0, -0.1);
  AutopilotDesign d;
  d.k_theta = 123.0;
  EXPECT_EQ(design_autopilot_gains(m, request(2.5, 0.0), &d), Status::kAutopilotDampingNotPositive);
  EXPECT_EQ(design_autopilot_gains(m, request(2.5, -0.3), &d), Status::kAutopilotDampingNotPositive);
  EXPECT_EQ(design_autopilot_gains(m, request(0.0, 0.7), &d), Status::kAutopilotFrequencyNotPositive);
  EXPECT_EQ(design_autopilot_gains(m, request(2.5, 0.7, -0.1), &d), Status::kAutopilotRequestInvalid);
  // The deflection limit: K_theta e <= delta_max delivers w_n^2 <= b delta_max / e - a.
  const double w_max = max_deliverable_frequency_rad_s(m, request(1.0, 0.7));
  EXPECT_NEAR(w_max, std::sqrt(6.0 * 5.0 - 2.5), 1e-12);
  EXPECT_EQ(design_autopilot_gains(m, request(w_max * 1.001, 0.7), &d),
            Status::kAutopilotFrequencyBeyondDeflection);
  EXPECT_EQ(design_autopilot_gains(m, request(w_max * 0.999, 0.7), &d), Status::kOk);
  AutopilotDesign untouched;
  untouched.k_theta = 123.0;
  EXPECT_EQ(design_autopilot_gains(model(2.5, -1.0, 0.0), request(1.0, 0.7), &untouched),
            Status::kAutopilotModelInvalid);
  EXPECT_EQ(untouched.k_theta, 123.0);
  // A very stable vehicle asked for a frequency below its own: K_theta would be negative.
  EXPECT_EQ(design_autopilot_gains(model(-40.0, 9.0, 0.0), request(1.0, 0.7), &d),
            Status::kAutopilotGainOutOfRange);
}

// Every word of the request and of the model is checked on its own: one not finite, or out of
// its range, names the request or the model; the gain beyond the table's K_q range (100 s) too.
TEST(AutopilotDesign, Issue16_EveryRequestAndModelWordIsCheckedOnItsOwn) {
  const double nan = std::nan("");
  const ShortPeriodModel good_model = model(2.5, 6.0, -0.1);
  const AutopilotRequest good_request = request(2.5, 0.7, 0.02);
  AutopilotDesign d;
  ASSERT_EQ(design_autopilot_gains(good_model, good_request, &d), Status::kOk);
  struct RequestEdit {
    double AutopilotRequest::*word;
    double value;
    Status status;
  };
  const RequestEdit request_edits[] = {
      {&AutopilotRequest::damping_ratio, nan, Status::kAutopilotDampingNotPositive},
      {&AutopilotRequest::damping_ratio, HUGE_VAL, Status::kAutopilotDampingNotPositive},
      {&AutopilotRequest::natural_frequency_rad_s, nan, Status::kAutopilotFrequencyNotPositive},
      {&AutopilotRequest::attitude_error_rad, 0.0, Status::kAutopilotRequestInvalid},
      {&AutopilotRequest::attitude_error_rad, nan, Status::kAutopilotRequestInvalid},
      {&AutopilotRequest::max_deflection_rad, -0.1, Status::kAutopilotRequestInvalid},
      {&AutopilotRequest::actuator_time_constant_s, nan, Status::kAutopilotRequestInvalid},
      {&AutopilotRequest::actuator_time_constant_s, HUGE_VAL, Status::kAutopilotRequestInvalid},
  };
  for (const RequestEdit& e : request_edits) {
    AutopilotRequest r = good_request;
    r.*e.word = e.value;
    EXPECT_EQ(design_autopilot_gains(good_model, r, &d), e.status) << e.value;
  }
  struct ModelEdit {
    double ShortPeriodModel::*word;
    double value;
  };
  const ModelEdit model_edits[] = {
      {&ShortPeriodModel::pitch_inertia_slug_ft2, 0.0},
      {&ShortPeriodModel::pitch_inertia_slug_ft2, nan},
      {&ShortPeriodModel::m_delta_lbf_ft_per_rad, 0.0},
      {&ShortPeriodModel::a_per_s2, nan},
      {&ShortPeriodModel::a_per_s2, -HUGE_VAL},
      {&ShortPeriodModel::b_per_s2, HUGE_VAL},
      {&ShortPeriodModel::c_per_s, nan},
  };
  for (const ModelEdit& e : model_edits) {
    ShortPeriodModel m = good_model;
    m.*e.word = e.value;
    EXPECT_EQ(design_autopilot_gains(m, good_request, &d), Status::kAutopilotModelInvalid) << e.value;
  }
  // By hand, a = c = 0, b = 0.01 per s^2, w = 0.5 rad/s (and deflection to spare): K_theta = w^2 / b
  // = 25, K_q = 2 zeta w / b = 70 s at zeta = 0.7, and 150 s (beyond the table's 100 s) at zeta = 1.5.
  AutopilotRequest r = request(0.5, 0.7);
  r.max_deflection_rad = 1e3;
  ShortPeriodModel slow = model(0.0, 0.01, 0.0);
  ASSERT_EQ(design_autopilot_gains(slow, r, &d), Status::kOk);
  EXPECT_NEAR(d.k_q_s, 70.0, 1e-12);
  EXPECT_NEAR(d.k_theta, 25.0, 1e-12);
  r.damping_ratio = 1.5;
  EXPECT_EQ(design_autopilot_gains(slow, r, &d), Status::kAutopilotGainOutOfRange);
  // No deliverable frequency without an attitude error to deliver it for.
  r.attitude_error_rad = 0.0;
  EXPECT_EQ(max_deliverable_frequency_rad_s(slow, r), 0.0);
}

// The model from the reference data (blocks 33-37) at a stage-1 flight condition: M_alpha and
// M_delta are unit_moments()'s, the damping terms the Sec. 16 expressions shared with the hardover
// module, and dividing by I gives a, b, c.
TEST(AutopilotDesign, Issue16_ShortPeriodModelUsesTheBodyModuleMomentsAndDamping) {
  static Mission mission;
  if (!mission.body_dynamics.present)
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  AutopilotCondition c;
  c.moments.stage = 1;
  c.moments.cg_stage_time_s = 30.0;
  c.moments.mach = 1.5;
  c.moments.dynamic_pressure_lbf_ft2 = 1200.0;
  c.moments.vacuum_thrust_lbf = 90000.0;
  c.moments.normal_force_slope_per_rad = mission.vehicle.lift_curve_slope_per_rad(1.5);
  c.speed_ft_s = 1500.0;
  c.pitch_inertia_slug_ft2 = 3.0e5;
  c.inertia_rate_slug_ft2_s = -2000.0;
  c.mass_rate_slug_s = -12.0;
  c.thrust_station_ft = 70.0;
  c.pitch_damping_per_rad = -20.0;
  const ShortPeriodModel m = short_period_model(mission.body_dynamics, c);
  const UnitMoments u = unit_moments(mission.body_dynamics, c.moments);
  EXPECT_EQ(m.m_alpha_lbf_ft_per_rad, u.m_alpha_lbf_ft_per_rad);
  EXPECT_EQ(m.m_delta_lbf_ft_per_rad, u.m_delta_lbf_ft_per_rad);
  const BodyDynamicsBlocks& b = mission.body_dynamics;
  const double aero =
      -20.0 * b.reference_length_ft * b.reference_length_ft * 1200.0 * b.reference_area_ft2 / (2.0 * 1500.0);
  const double arm = u.cg_station_ft - 70.0;
  const double jet = -12.0 * arm * arm - 2000.0;
  EXPECT_NEAR(m.m_q_aero_lbf_ft_s_per_rad, aero, 1e-12 * std::fabs(aero));
  EXPECT_NEAR(m.m_q_jet_lbf_ft_s_per_rad, jet, 1e-12 * std::fabs(jet));
  EXPECT_NEAR(m.a_per_s2, u.m_alpha_lbf_ft_per_rad / 3.0e5, 1e-15 * std::fabs(m.a_per_s2));
  EXPECT_NEAR(m.c_per_s, (aero + jet) / 3.0e5, 1e-12 * std::fabs(m.c_per_s));
  EXPECT_LT(m.m_alpha_lbf_ft_per_rad, 0.0);  // the reference vehicle is statically stable
  EXPECT_GT(m.m_delta_lbf_ft_per_rad, 0.0);
}

}  // namespace
}  // namespace tolip
