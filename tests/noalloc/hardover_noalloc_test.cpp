// Rules of the core: every hardover turn of Sec. 16 allocates nothing. The mission is built and
// flown (with heap, JSON) before the counting window.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/hardover/hardover.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

void constant_table(double value, HardoverTable* table) {
  table->clear();
  ASSERT_EQ(table->append(0.0, value), Status::kOk);
  ASSERT_EQ(table->append(100.0, value), Status::kOk);
  ASSERT_EQ(table->finalize(), Status::kOk);
}

TEST(CoreNoHeap, HardoverTurnsAllocateNothing) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  static HardoverData data;
  static HardoverResult result;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(mission, prepared, &trajectory), Status::kOk);
  // Round data of the reference's kind (the tables' values do not matter for the heap).
  constant_table(-400.0, &data.pitch_damping_per_rad);
  data.max_qbar_alpha_lbf_rad_ft2 = 6000.0 * kDegToRad;
  data.fin_vane_deflection_rad = 10.0 * kDegToRad;
  data.output_interval_s = 0.5;
  for (int k = 0; k < 3; ++k) {
    HardoverStage& s = data.stages[k];
    constant_table(k == 0 ? 350000.0 : (k == 1 ? 45000.0 : 2700.0), &s.pitch_inertia_slug_ft2);
    s.every_nth_step = 5;
    s.max_attitude_step_rad = 0.5 * kDegToRad;
    s.max_step_s = 0.05;
    s.min_step_s = 0.002;
    s.max_steps_per_turn = 2000;
    s.thrust_misalignment_rad = 0.25 * kDegToRad;
    s.thrust_station_ft = k == 0 ? 72.0 : (k == 1 ? 46.7 : 25.0);
    s.single_jet_force_lbf = 475.0;
    s.pitch_yaw_jet_force_lbf = 672.0;
    s.control_jet_station_ft = k == 1 ? 45.7 : 24.7;
  }
  HardoverFault fault;

  test::AllocationScope scope;
  const Status status = compute_hardover_turns(mission, prepared, trajectory, data, &result, &fault);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(result.turn_count, 10);  // the work really happened
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
