// Rules of the core: the dispersion analysis (manual Sec. 15) - preparing and flying the nominal and
// every dispersed case, recording, the three-sigma groups - allocates nothing. The data are built
// (with heap, JSON) before the counting window.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>

#include "support/allocation_counter.hpp"
#include "support/dispersion_sources.hpp"
#include "support/reference_impact.hpp"
#include "support/reference_mission.hpp"
#include "tolip/dispersion/dispersion.hpp"
#include "tolip/dispersion/monte_carlo.hpp"

namespace tolip {
namespace {

// Appends a source of each code with every scalar field set (each code reads the one its kind
// names), stage 4 for the tip-off code 30, and `weight_lb` as the weight increment.
void add_scalar_sources(std::initializer_list<int> codes, double weight_lb, DispersionData* data) {
  for (int code : codes) {
    DispersionSource& s = test::add_dispersion_source(data, code);
    if (code == 30) s.stage = 4;  // tipoff of stage 4
    s.weight_increment_lb = weight_lb;
    s.drag_variation_fraction = 0.1;
    s.deadband_rad = 0.01;
    s.tipoff_rad = 0.03;
    s.launch_change_rad = 0.005;
  }
}

// The core's Monte Carlo path for one sample, as a run flies it: the nominal prepared and
// recorded, then sample `sample_index` of seed 1 flown. Allocates nothing itself: the tests call
// it inside their counting window.
struct SampleStatuses {
  Status nominal;
  Status sample;
};
SampleStatuses fly_nominal_and_sample(const DispersionNominal& nominal, const DispersionData& data,
                                      std::uint64_t sample_index, DispersionWorkspace* workspace,
                                      DispersedTrajectory* nominal_values, DispersedTrajectory* sample) {
  Status status = prepare_monte_carlo(nominal, data, workspace);
  if (ok(status)) {
    status = record_dispersed_trajectory(*nominal.mission, workspace->nominal_prepared, workspace->nominal,
                                         workspace->nominal, nullptr, nominal_values);
  }
  const Status flown =
      fly_monte_carlo_sample(nominal, data, 1, sample_index, *nominal_values, workspace, sample);
  return {status, flown};
}

TEST(CoreNoHeap, DispersionAnalysisAllocatesNothing) {
  static Mission mission;
  static DispersionData data;
  static DispersionWorkspace workspace;
  static DispersionResult result;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  add_scalar_sources({3, 11, 17, 26, 30, 33, 34, 36, 40}, 50.0, &data);
  data.sources[0].vacuum_thrust_lbf = mission.vehicle.stages[1].vacuum_thrust_lbf;
  data.sources[0].consumable_weight_lb = mission.vehicle.stages[1].consumable_weight_lb;
  WindProfile& wind = data.sources[7].wind;
  ASSERT_EQ(wind.speed_ft_s.append(0.0, 50.0), Status::kOk);
  ASSERT_EQ(wind.speed_ft_s.append(60000.0, 200.0), Status::kOk);
  ASSERT_EQ(wind.speed_ft_s.finalize(), Status::kOk);
  ASSERT_EQ(wind.azimuth_rad.append(0.0, 4.9), Status::kOk);
  ASSERT_EQ(wind.azimuth_rad.finalize(), Status::kOk);
  DispersionNominal nominal;
  nominal.mission = &mission;
  nominal.body_dynamics = true;  // the block 40 table, stage 1 with body dynamics

  test::AllocationScope scope;
  const Status status = run_dispersions(nominal, data, &workspace, &result);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  ASSERT_EQ(result.count, 8);
  for (int k = 0; k < result.count; ++k)
    EXPECT_EQ(result.trajectories[k].status, Status::kOk) << result.trajectories[k].code;
  EXPECT_TRUE(result.three_sigma.computed);  // the work really happened
  EXPECT_EQ(allocations, 0u);
}

// A Monte Carlo sample (every scalar source drawn at once) on the core path: no heap either.
TEST(CoreNoHeap, MonteCarloSampleAllocatesNothing) {
  static Mission mission;
  static DispersionData data;
  static DispersionWorkspace workspace;
  static DispersedTrajectory nominal_values;
  static DispersedTrajectory sample;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  add_scalar_sources({9, 17, 24, 26, 30, 33, 34}, 150.0, &data);
  DispersionNominal nominal;
  nominal.mission = &mission;

  test::AllocationScope scope;
  const auto [status, flown] = fly_nominal_and_sample(nominal, data, 5, &workspace, &nominal_values, &sample);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_EQ(flown, Status::kOk);
  EXPECT_NE(sample.dispersions[3][0], 0.0);  // the work really happened
  EXPECT_EQ(allocations, 0u);
}

// A sample's expended casings of stages 1-3 flown to impact (Sec. 17, data block 43; the Monte
// Carlo's casing impacts, at most kImpactStages in fixed storage) after the sample: no heap.
TEST(CoreNoHeap, MonteCarloCasingImpactsAllocateNothing) {
  static Mission mission;
  static DispersionData data;
  static DispersionWorkspace workspace;
  static DispersedTrajectory nominal_values;
  static DispersedTrajectory sample;
  static ImpactLocusData impact;
  static ImpactWorkspace impact_workspace;
  static MonteCarloImpacts impacts;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  test::build_reference_impact_data(&impact);
  for (int code : {9, 11, 13, 33}) {
    DispersionSource& s = test::add_dispersion_source(&data, code);
    s.weight_increment_lb = 50.0;
    s.launch_change_rad = 0.005;
  }
  DispersionNominal nominal;
  nominal.mission = &mission;
  MonteCarloImpactRequest request;
  request.data = &impact;
  for (bool& stage : request.stages) stage = true;

  test::AllocationScope scope;
  const auto [status, flown] = fly_nominal_and_sample(nominal, data, 3, &workspace, &nominal_values, &sample);
  const Status casings = fly_monte_carlo_casings(nominal, request, workspace.mission, workspace.prepared,
                                                 workspace.dispersed, &impact_workspace, &impacts);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_EQ(flown, Status::kOk);
  EXPECT_EQ(casings, Status::kOk);
  EXPECT_EQ(impacts.count, 3);  // the work really happened
  EXPECT_GT(impacts.casings[2].steps, 10);
  EXPECT_EQ(allocations, 0u);
}

// The table sources of a sample (thrust of stage 2 blended, program mapped onto the changed burn
// time, C_M_alpha with body dynamics, two wind profiles summed) allocate nothing either.
TEST(CoreNoHeap, MonteCarloTableSampleAllocatesNothing) {
  static Mission mission;
  static DispersionData data;
  static DispersionWorkspace workspace;
  static DispersedTrajectory nominal_values;
  static DispersedTrajectory sample;
  static ControlProgram program;
  static Trajectory flight;
  static PreparedCase prepared;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(mission, prepared, &flight), Status::kOk);
  program.point_count = flight.point_count;
  for (int k = 0; k < flight.point_count; ++k) program.theta_rad[k] = flight.points[k].theta_rad;
  const StageData& stage2 = mission.vehicle.stages[1];
  DispersionSource& thrust = data.sources[data.count++];
  thrust.code = 3;
  thrust.stage = 2;
  for (int i = 0; i < stage2.vacuum_thrust_lbf.size(); ++i) {
    ASSERT_EQ(thrust.vacuum_thrust_lbf.append(stage2.vacuum_thrust_lbf.x(i) / 1.03,
                                              stage2.vacuum_thrust_lbf.y(i) * 1.03),
              Status::kOk);
    ASSERT_EQ(thrust.consumable_weight_lb.append(stage2.consumable_weight_lb.x(i) / 1.03,
                                                 stage2.consumable_weight_lb.y(i)),
              Status::kOk);
  }
  ASSERT_EQ(thrust.vacuum_thrust_lbf.finalize(), Status::kOk);
  ASSERT_EQ(thrust.consumable_weight_lb.finalize(), Status::kOk);
  DispersionSource& cm = data.sources[data.count++];
  cm.code = 19;
  cm.stage = 1;
  cm.pitching_moment_per_rad = mission.body_dynamics.pitching_moment_per_rad;
  for (int i = 0; i < cm.pitching_moment_per_rad.size(); ++i)
    cm.pitching_moment_per_rad.set_y(i, 1.1 * cm.pitching_moment_per_rad.y(i));
  ASSERT_EQ(cm.pitching_moment_per_rad.finalize(), Status::kOk);
  for (int code : {36, 38}) {
    DispersionSource& w = data.sources[data.count++];
    w.code = code;
    ASSERT_EQ(w.wind.speed_ft_s.append(0.0, 30.0), Status::kOk);
    ASSERT_EQ(w.wind.speed_ft_s.append(50000.0, 200.0), Status::kOk);
    ASSERT_EQ(w.wind.speed_ft_s.append(150000.0, 0.0), Status::kOk);
    ASSERT_EQ(w.wind.azimuth_rad.append(0.0, code == 36 ? 1.0 : 2.5), Status::kOk);
    ASSERT_EQ(w.wind.speed_ft_s.finalize(), Status::kOk);
    ASSERT_EQ(w.wind.azimuth_rad.finalize(), Status::kOk);
  }
  DispersionNominal nominal;
  nominal.mission = &mission;
  nominal.program = &program;
  nominal.body_dynamics = true;

  test::AllocationScope scope;
  const auto [status, flown] = fly_nominal_and_sample(nominal, data, 5, &workspace, &nominal_values, &sample);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_EQ(flown, Status::kOk);
  EXPECT_TRUE(workspace.program_mapped);
  EXPECT_NE(workspace.perturbation.wind, nullptr);
  EXPECT_NE(sample.dispersions[3][0], 0.0);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
