// The q-bar x alpha load limit (issue 15, a TOLIP extension; docs/theory/constraints-and-ics.md
// "The q-bar x alpha path constraint"): its excess integral and the adjoint forcing of the backward
// run against central differences of forward runs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/adjoint_check.hpp"
#include "support/reference_mission.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/qbar_alpha.hpp"

namespace tolip {
namespace {

constexpr double kLbDegPerLbRad = 180.0 / kPi;

// The backward run here is that of the excess integral alone, not of the six terminal quantities.
struct Fixture : test::AdjointCase {
  double peak_lbf_rad_ft2 = 0.0;
};

// The oracle's optimum program flown with a limit at 60 % of its own peak q-bar alpha, so that the
// excess integral is positive over a few seconds of stage 1.
Fixture& fixture() {
  static Fixture* f = [] {
    static Fixture fx;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &fx.mission);
    EXPECT_EQ(prepare_case(fx.mission, &fx.prepared), Status::kOk);
    EXPECT_EQ(fly_trajectory(fx.mission, fx.prepared, &fx.nominal), Status::kOk);
    fx.peak_lbf_rad_ft2 = peak_qbar_alpha(fx.mission, fx.nominal, true).value_lbf_rad_ft2;
    fx.mission.options.qbar_alpha_limit_lbf_rad_ft2 = 0.6 * fx.peak_lbf_rad_ft2;
    fx.program.point_count = fx.nominal.point_count;
    for (int i = 0; i < fx.nominal.point_count; ++i) fx.program.theta_rad[i] = fx.nominal.points[i].theta_rad;
    ConstraintTerminal terminal;
    terminal.point = fx.nominal.point_count - 1;
    terminal.qbar_alpha_integral = true;
    EXPECT_EQ(run_backward(fx.mission, fx.prepared, fx.nominal, 1, &terminal, &fx.backward), Status::kOk);
    return &fx;
  }();
  return *f;
}

// The excess integral written out here from the stored points (independent of the core's sum):
// trapezoids of max(0, |q alpha| / L - 1)^2 over the intervals of lift-table stages.
double excess_by_intervals(const Mission& m, const Trajectory& t) {
  const double limit = m.options.qbar_alpha_limit_lbf_rad_ft2;
  const auto g = [&](const TrajectoryPoint& p) {
    const bool lift =
        p.dynamic_pressure_lbf_ft2 > 0.0 && m.vehicle.stages[stage_index(p.stage_code)].uses_lift_table;
    const double e = std::fabs(p.dynamic_pressure_lbf_ft2 * p.alpha_rad) / limit - 1.0;
    return (lift && e > 0.0) ? e * e : 0.0;
  };
  double sum = 0.0;
  for (int k = 1; k < t.point_count; ++k)
    sum += 0.5 * (g(t.points[k - 1]) + g(t.points[k])) * (t.points[k].time_s - t.points[k - 1].time_s);
  return sum;
}

TEST(Sec5QAlpha, ExcessIntegralIsTheTrapezoidalIntegralOfTheSquaredRelativeExcess) {
  Fixture& f = fixture();
  const double j = qbar_alpha_excess_s(f.mission, f.nominal);
  std::printf("peak %.1f lb deg/ft^2, limit %.1f, excess integral %.6e s\n",
              f.peak_lbf_rad_ft2 * kLbDegPerLbRad,
              f.mission.options.qbar_alpha_limit_lbf_rad_ft2 * kLbDegPerLbRad, j);
  ASSERT_GT(j, 0.0);
  EXPECT_NEAR(j, excess_by_intervals(f.mission, f.nominal), 1e-12 * j);
  Mission off = f.mission;
  off.options.qbar_alpha_limit_lbf_rad_ft2 = 0.0;
  EXPECT_EQ(qbar_alpha_excess_s(off, f.nominal), 0.0);
}

// The adjoint of J (forced at every point through the state and the point's own pitch value)
// predicts the change of J for state changes injected at points before and inside the excess and
// for pitch changes over short windows; central differences of forward runs are the truth.
TEST(Sec5QAlpha, Sec5_QAlphaAdjointMatchesFiniteDifference) {
  Fixture& f = fixture();
  const auto point_near = [&](double t) {
    int point = 1;
    for (int i = 1; i < f.nominal.point_count; ++i) {
      if (std::fabs(f.nominal.points[i].time_s - t) < std::fabs(f.nominal.points[point].time_s - t))
        point = i;
    }
    return point;
  };
  const auto difference = [&](auto fly) {
    EXPECT_EQ(fly(+1.0), Status::kOk);
    const double plus = qbar_alpha_excess_s(f.mission, f.perturbed);
    EXPECT_EQ(fly(-1.0), Status::kOk);
    const double minus = qbar_alpha_excess_s(f.mission, f.perturbed);
    return 0.5 * (plus - minus);
  };
  double worst = 0.0;
  const double sizes[6] = {0.5, 1e-4, 20.0, 1e-4, 1e-6, 1e-6};
  for (double t : {4.0, 7.0, 10.0, 12.0}) {
    const int point = point_near(t);
    for (int i = 0; i < 6; ++i) {
      FlightInputs inputs;
      inputs.program = &f.program;
      inputs.injection_point = point;
      const double fd = difference([&](double sign) {
        inputs.injection = StateVector::Zero();
        inputs.injection[i] = sign * sizes[i];
        return fly_trajectory(f.mission, f.prepared, inputs, &f.perturbed);
      });
      const double predicted = f.backward.lambda[point](i, 0) * sizes[i];
      const double rel = std::fabs(predicted - fd) / std::fmax(std::fabs(fd), 1e-300);
      std::printf("t=%6.2f dX[%d]   adjoint % .6e  fd % .6e  rel %.1e\n", f.nominal.points[point].time_s, i,
                  predicted, fd, rel);
      if (std::fabs(fd) > 1e-9) worst = std::fmax(worst, rel);
      EXPECT_LE(std::fabs(predicted - fd), 0.01 * std::fabs(fd) + 1e-10) << "t " << t << " dX[" << i << "]";
    }
  }
  const double windows[][2] = {{4.0, 7.0}, {7.0, 10.0}, {10.0, 13.0}, {3.0, 13.0}};
  const double d_theta = 2e-4;  // rad
  static ControlProgram changed;
  for (const auto& w : windows) {
    double predicted = 0.0;
    for (int i = 0; i < f.nominal.point_count; ++i) {
      const double t = f.nominal.points[i].time_s;
      if (t >= w[0] && t <= w[1]) predicted += f.backward.theta_gradient[i](0) * d_theta;
    }
    const double fd = difference([&](double sign) {
      changed = f.program;
      for (int i = 0; i < f.nominal.point_count; ++i) {
        const double t = f.nominal.points[i].time_s;
        if (t >= w[0] && t <= w[1]) changed.theta_rad[i] += sign * d_theta;
      }
      return fly_trajectory(f.mission, f.prepared, changed, &f.perturbed);
    });
    const double rel = std::fabs(predicted - fd) / std::fmax(std::fabs(fd), 1e-300);
    std::printf("theta %4.0f-%4.0f s  adjoint % .6e  fd % .6e  rel %.1e\n", w[0], w[1], predicted, fd, rel);
    worst = std::fmax(worst, rel);
    EXPECT_GT(std::fabs(fd), 1e-8) << "the window must move the excess";
    EXPECT_LE(std::fabs(predicted - fd), 0.01 * std::fabs(fd)) << "theta " << w[0] << "-" << w[1];
  }
  std::printf("worst relative disagreement %.2e\n", worst);
}

}  // namespace
}  // namespace tolip
