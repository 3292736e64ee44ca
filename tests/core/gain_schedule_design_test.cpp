// Issue 16: the gain schedule of the reference vehicle along its nominal (stages 1-3), the poles
// of every point's delivered gains (through the table image) checked with Eigen, and the bad
// requests named with their stage.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

#include "support/guidance_table_fixture.hpp"
#include "support/reference_hardover.hpp"
#include "support/reference_mission.hpp"
#include "tolip/autopilot/gain_schedule_design.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

struct Flown {
  Mission mission;
  PreparedCase prepared;
  Trajectory trajectory;
  HardoverData hardover;
  GainScheduleDesign schedule;
};

AutopilotRequest request(double w, double zeta) {
  AutopilotRequest r;
  r.natural_frequency_rad_s = w;
  r.damping_ratio = zeta;
  r.attitude_error_rad = 1.0 * kDegToRad;
  r.max_deflection_rad = 10.0 * kDegToRad;
  r.actuator_time_constant_s = 0.02;
  return r;
}

Flown& flown() {
  static Flown* f = [] {
    static Flown x;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &x.mission);
    EXPECT_EQ(prepare_case(x.mission, &x.prepared), Status::kOk);
    EXPECT_EQ(fly_trajectory(x.mission, x.prepared, &x.trajectory), Status::kOk);
    x.hardover = test::reference_hardover();
    return &x;
  }();
  return *f;
}

const AutopilotRequest kRequests[kGainScheduleStages] = {request(2.0, 0.7), request(1.5, 0.7),
                                                         request(1.5, 0.7)};
const bool kAll[kGainScheduleStages] = {true, true, true};

TEST(GainScheduleDesign, Issue16_DeliveredGainsPlaceThePolesAtEveryPointOfTheReferenceNominal) {
  Flown& f = flown();
  int fault_stage = -1;
  ASSERT_EQ(design_gain_schedule(f.mission, f.trajectory, f.hardover, kRequests, kAll, 6, &f.schedule,
                                 &fault_stage),
            Status::kOk)
      << "stage " << fault_stage << " "
      << status_name(design_gain_schedule(f.mission, f.trajectory, f.hardover, kRequests, kAll, 6,
                                          &f.schedule, &fault_stage));
  ASSERT_GE(f.schedule.count, 15);
  // Deliver through the table image: the gains the flight side reads are the designed ones.
  GuidanceTable table = test::make_test_table(0);
  table.schedule_count = f.schedule.count;
  for (int i = 0; i < f.schedule.count; ++i) {
    const GainScheduleDesignPoint& p = f.schedule.points[i];
    table.schedule[i] = GainSchedulePoint{p.stage_code, p.stage_time_s, p.design.k_theta, p.design.k_q_s};
  }
  const test::Image image = test::encode(table);
  GuidanceTable delivered;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &delivered), Status::kOk);
  double worst = 0.0;
  std::printf(
      "stage  t(s)    q(psf)   M_alpha(ft-lb/rad) M_delta(ft-lb/rad)  K_theta  K_q(s)  GM+     PM(deg)\n");
  for (int i = 0; i < f.schedule.count; ++i) {
    const GainScheduleDesignPoint& p = f.schedule.points[i];
    const ShortPeriodModel& m = p.design.model;
    const StageGains g = scheduled_gains(delivered, p.stage_code, p.stage_time_s);
    Eigen::Matrix2d A;
    A << 0.0, 1.0, -(g.k_theta * m.b_per_s2 - m.a_per_s2), -(g.k_q_s * m.b_per_s2 - m.c_per_s);
    Eigen::EigenSolver<Eigen::Matrix2d> eig(A);
    const AutopilotRequest& r = kRequests[p.stage_code - 1];
    for (int k = 0; k < 2; ++k) {
      const std::complex<double> s = eig.eigenvalues()(k);
      worst =
          std::fmax(worst, std::fabs(std::abs(s) - r.natural_frequency_rad_s) / r.natural_frequency_rad_s);
      worst = std::fmax(worst, std::fabs(-s.real() / std::abs(s) - r.damping_ratio) / r.damping_ratio);
    }
    EXPECT_TRUE(p.design.margins.closed_loop_stable);
    EXPECT_LE(p.design.step_deflection_rad, r.max_deflection_rad);
    std::printf("%3d %7.1f %9.1f %16.4g %18.4g %9.4f %7.4f %7.2f %8.2f\n", p.stage_code, p.stage_time_s,
                p.condition.moments.dynamic_pressure_lbf_ft2, m.m_alpha_lbf_ft_per_rad,
                m.m_delta_lbf_ft_per_rad, p.design.k_theta, p.design.k_q_s,
                p.design.margins.upper_gain_margin, p.design.margins.phase_margin_rad * kRadToDeg);
  }
  EXPECT_LT(worst, 1e-6);
  std::printf("worst relative error of w_n, zeta over %d points: %.2e\n", f.schedule.count, worst);
}

TEST(GainScheduleDesign, Issue16_BadRequestsNameTheStage) {
  Flown& f = flown();
  static GainScheduleDesign schedule;
  int stage = 0;
  AutopilotRequest bad[kGainScheduleStages] = {kRequests[0], kRequests[1], kRequests[2]};
  bad[1].damping_ratio = 0.0;
  EXPECT_EQ(design_gain_schedule(f.mission, f.trajectory, f.hardover, bad, kAll, 6, &schedule, &stage),
            Status::kAutopilotDampingNotPositive);
  EXPECT_EQ(stage, 2);
  bad[1] = kRequests[1];
  bad[2].natural_frequency_rad_s = 1000.0;
  EXPECT_EQ(design_gain_schedule(f.mission, f.trajectory, f.hardover, bad, kAll, 6, &schedule, &stage),
            Status::kAutopilotFrequencyBeyondDeflection);
  EXPECT_EQ(stage, 3);
  EXPECT_EQ(design_gain_schedule(f.mission, f.trajectory, f.hardover, kRequests, kAll,
                                 kMaxGainSchedulePointsPerStage + 1, &schedule, &stage),
            Status::kTooManyGainSchedulePoints);
  EXPECT_EQ(design_gain_schedule(f.mission, f.trajectory, f.hardover, kRequests, kAll, 0, &schedule, nullptr),
            Status::kTooManyGainSchedulePoints)
      << "at least one point per stage";
  // A designed stage needs its pitch inertia (data block 44); without the fault record as well.
  static HardoverData no_inertia;
  no_inertia = f.hardover;
  no_inertia.stages[1].pitch_inertia_slug_ft2.clear();
  EXPECT_EQ(design_gain_schedule(f.mission, f.trajectory, no_inertia, kRequests, kAll, 6, &schedule, &stage),
            Status::kHardoverInertiaMissing);
  EXPECT_EQ(stage, 2);
  EXPECT_EQ(design_gain_schedule(f.mission, f.trajectory, no_inertia, kRequests, kAll, 6, &schedule, nullptr),
            Status::kHardoverInertiaMissing);
  // Stage 1 alone, one point: one record, at the first controllable point of stage 1 (stages not
  // asked for are not designed, so stage 2's missing inertia does not matter).
  const bool stage1_only[kGainScheduleStages] = {true, false, false};
  ASSERT_EQ(
      design_gain_schedule(f.mission, f.trajectory, no_inertia, kRequests, stage1_only, 1, &schedule, &stage),
      Status::kOk);
  ASSERT_EQ(schedule.count, 1);
  EXPECT_EQ(schedule.points[0].stage_code, 1);
  EXPECT_EQ(stage, 0);
}

}  // namespace
}  // namespace tolip
