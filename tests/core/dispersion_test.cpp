// Dispersion analysis (manual Sec. 15, Sec. 22 data blocks 46-55): a zero change reproduces the
// nominal bit for bit; each family equals a forward run of the case changed by hand; the physical
// signs (thrust high, drag high, winds, azimuth); the three-sigma groups against a hand computation.
// The nominal is the reference mission (tests/reference) flown with a per-point pitch program.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "support/dispersion_sources.hpp"
#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/dispersion/dispersion.hpp"
#include "tolip/trajectory/wind.hpp"

namespace tolip {
namespace {

constexpr double kDeg = kPi / 180.0;
constexpr int kAlt = static_cast<int>(StagingVariable::kAltitude);
constexpr int kVel = static_cast<int>(StagingVariable::kVelocity);
constexpr int kCross = static_cast<int>(StagingVariable::kCrossrange);

struct Fixture {
  Mission mission;
  PreparedCase prepared;
  Trajectory table_flight;
  ControlProgram program;
  DispersionData data;
  DispersionWorkspace workspace;
  DispersionResult result;
  Trajectory hand;
  Mission hand_mission;
  PreparedCase hand_prepared;
};

// A case changed by hand flies with the analysis' own flight numerics (dispersion_flight_inputs:
// the state's sines inside a step by the addition theorem), so the code's figures must equal it
// bit for bit.
Status fly_by_hand(const Mission& mission, const PreparedCase& prepared, FlightInputs inputs,
                   Trajectory* out) {
  inputs.trig_by_series = true;
  return fly_trajectory(mission, prepared, inputs, out);
}
Status fly_by_hand(const Mission& mission, const PreparedCase& prepared, const ControlProgram& program,
                   Trajectory* out) {
  FlightInputs inputs;
  inputs.program = &program;
  return fly_by_hand(mission, prepared, inputs, out);
}
Status fly_by_hand(const Mission& mission, const PreparedCase& prepared, Trajectory* out) {
  return fly_by_hand(mission, prepared, FlightInputs{}, out);
}

// The reference mission and its block 40 program sampled at every point (as the optimizer keeps it).
std::unique_ptr<Fixture> make_fixture() {
  auto f = std::make_unique<Fixture>();
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &f->mission);
  EXPECT_EQ(prepare_case(f->mission, &f->prepared), Status::kOk);
  EXPECT_EQ(fly_trajectory(f->mission, f->prepared, &f->table_flight), Status::kOk);
  f->program.point_count = f->table_flight.point_count;
  for (int k = 0; k < f->table_flight.point_count; ++k)
    f->program.theta_rad[k] = f->table_flight.points[k].theta_rad;
  return f;
}

DispersionNominal nominal_of(const Fixture& f, bool body_dynamics = false) {
  return test::dispersion_nominal(f.mission, &f.program, body_dynamics);
}

constexpr auto add = test::add_dispersion_source;

template <int N>
void fill(Table<N>* table, const nlohmann::json& x, const nlohmann::json& y, double scale = 1.0) {
  table->clear();
  for (std::size_t i = 0; i < x.size(); ++i)
    ASSERT_EQ(table->append(x[i].get<double>(), y[i].get<double>() * scale), Status::kOk);
  ASSERT_EQ(table->finalize(), Status::kOk);
}

// Every code of the reference data (tests/reference, "dispersions": blocks 46-55), and code 40.
void reference_data(DispersionData* data) {
  const nlohmann::json& d = test::scout_reference()["dispersions"];
  data->count = 0;
  for (int code = 1; code <= 8; ++code) {
    DispersionSource& s = add(data, code);
    const std::string key = "stage_" + std::to_string(s.stage) + (code % 2 ? "_high" : "_low");
    const nlohmann::json& t = d["codes_1_8_vacuum_thrust_variation"]["tables"][key];
    fill(&s.vacuum_thrust_lbf, t["time_s"], t["vacuum_thrust_lbf"]);
    fill(&s.consumable_weight_lb, t["time_s"], t["consumable_weight_remaining_lb"]);
  }
  for (int code = 9; code <= 16; ++code) {
    DispersionSource& s = add(data, code);
    const double w =
        d["codes_9_16_block47_weight_increment_lb"]["stage_" + std::to_string(s.stage)].get<double>();
    s.weight_increment_lb = (code % 2) ? w : -w;
  }
  const double drag = d["codes_17_18_block48_drag_variation_fraction"].get<double>();
  add(data, 17).drag_variation_fraction = drag;
  add(data, 18).drag_variation_fraction = -drag;
  const nlohmann::json& mis = d["codes_21_23_block49_stage1_thrust_misalignment"];
  for (int code = 21; code <= 23; ++code) {
    DispersionSource& s = add(data, code);
    s.misalignment_rad = (code == 22 ? -1.0 : 1.0) * mis["angle_deg"].get<double>() * kDeg;
    s.thrust_station_ft = mis["thrust_application_station_in"].get<double>() / 12.0;
  }
  for (int code = 24; code <= 29; ++code) {
    DispersionSource& s = add(data, code);
    const double band =
        d["codes_24_29_block50_control_deadband_deg"]["stage_" + std::to_string(s.stage)].get<double>();
    s.deadband_rad = ((code == 25 || code == 28) ? -band : band) * kDeg;
  }
  for (int code = 30; code <= 32; ++code) {
    DispersionSource& s = add(data, code);
    s.stage = 4;
    s.tipoff_rad =
        (code == 31 ? -1.0 : 1.0) * d["codes_30_32_block51_stage4_tipoff_deg"].get<double>() * kDeg;
  }
  add(data, 33).launch_change_rad = d["code_33_block52_launch_azimuth_change_deg"].get<double>() * kDeg;
  const double attitude = d["codes_34_35_block52_launch_attitude_change_deg"].get<double>() * kDeg;
  add(data, 34).launch_change_rad = attitude;
  add(data, 35).launch_change_rad = -attitude;
  const nlohmann::json& w = d["codes_36_38_winds"];
  const char* keys[] = {"code_36_high_headwind", "code_37_low_tailwind", "code_38_yaw_crosswind"};
  for (int code = 36; code <= 38; ++code) {
    DispersionSource& s = add(data, code);
    fill(&s.wind.speed_ft_s, w["block53_altitude_ft"], w["block53_wind_speed_ft_per_s"]);
    fill(&s.wind.azimuth_rad, w["block53_altitude_ft"], w["block54_wind_vector_azimuth_deg"][keys[code - 36]],
         kDeg);
  }
  add(data, 40);
}

const DispersedTrajectory* find(const DispersionResult& r, int code) {
  for (int k = 0; k < r.count; ++k) {
    if (r.trajectories[k].code == code) return &r.trajectories[k];
  }
  return nullptr;
}

// The nominal plane equals a plain forward run of the nominal, and a zero change of every kind is
// the nominal bit for bit (the perturbation path adds nothing when there is nothing to add).
TEST(Sec15Dispersions, ZeroPerturbationOfEveryKindReproducesTheNominalBitForBit) {
  auto f = make_fixture();
  DispersionData& data = f->data;
  data.count = 0;
  DispersionSource& thrust = add(&data, 3);  // stage 2's own tables
  thrust.vacuum_thrust_lbf = f->mission.vehicle.stages[1].vacuum_thrust_lbf;
  thrust.consumable_weight_lb = f->mission.vehicle.stages[1].consumable_weight_lb;
  add(&data, 9);
  add(&data, 17);
  add(&data, 24);
  add(&data, 26);
  add(&data, 30).stage = 4;
  add(&data, 32).stage = 4;
  add(&data, 33);
  add(&data, 34);
  DispersionSource& wind = add(&data, 36);
  (void)wind.wind.speed_ft_s.append(0.0, 0.0);
  (void)wind.wind.speed_ft_s.append(1.0e5, 0.0);
  (void)wind.wind.speed_ft_s.finalize();
  (void)wind.wind.azimuth_rad.append(0.0, 1.0);
  (void)wind.wind.azimuth_rad.finalize();
  add(&data, 40);
  ASSERT_EQ(run_dispersions(nominal_of(*f), data, &f->workspace, &f->result), Status::kOk);
  const DispersionResult& r = f->result;

  // The module's nominal is the program flown by hand.
  Trajectory& by_hand = f->hand;
  ASSERT_EQ(fly_by_hand(f->mission, f->prepared, f->program, &by_hand), Status::kOk);
  ASSERT_EQ(by_hand.point_count, f->workspace.nominal.point_count);
  for (int k = 0; k < by_hand.point_count; ++k) {
    ASSERT_EQ(by_hand.points[k].state, f->workspace.nominal.points[k].state) << k;
  }
  ASSERT_EQ(r.staging_count, 4);  // stage 2, 3, 4 ignition and the final point
  ASSERT_EQ(r.count, data.count - 1);
  for (int k = 0; k < r.count; ++k) {
    const DispersedTrajectory& t = r.trajectories[k];
    ASSERT_EQ(t.status, Status::kOk) << t.code;
    for (int j = 0; j < r.staging_count; ++j) {
      for (int i = 0; i < kStagingVariables; ++i) {
        EXPECT_EQ(t.dispersions[j][i], 0.0) << "code " << t.code << " point " << j << " variable " << i;
      }
    }
    for (int i = 0; i < kOrbitDispersionElements; ++i) EXPECT_EQ(t.orbit_dispersions[i], 0.0) << t.code;
    EXPECT_EQ(t.max_qbar_alpha_lbf_rad_ft2, r.nominal.max_qbar_alpha_lbf_rad_ft2) << t.code;
  }
}

// Each family's final values equal a forward run of the case with the same change made by hand.
TEST(Sec15Dispersions, WeightDragAndAzimuthEqualTheCaseChangedByHand) {
  auto f = make_fixture();
  DispersionData& data = f->data;
  data.count = 0;
  add(&data, 11).weight_increment_lb = 50.0;
  add(&data, 17).drag_variation_fraction = 0.1;
  add(&data, 33).launch_change_rad = 0.5 * kDeg;
  ASSERT_EQ(run_dispersions(nominal_of(*f), data, &f->workspace, &f->result), Status::kOk);

  for (int which = 0; which < 3; ++which) {
    Mission& m = f->hand_mission;
    m = f->mission;
    if (which == 0) m.vehicle.stages[1].jettison_weight_lb += 50.0;
    if (which == 1) {
      for (StageData& s : m.vehicle.stages) {
        for (int i = 0; i < s.drag_coefficient.size(); ++i)
          s.drag_coefficient.set_y(i, s.drag_coefficient.y(i) * 1.1);
        if (!s.drag_coefficient.empty()) ASSERT_EQ(s.drag_coefficient.finalize(), Status::kOk);
      }
    }
    if (which == 2) m.launch.azimuth_rad += 0.5 * kDeg;
    ASSERT_EQ(prepare_case(m, &f->hand_prepared), Status::kOk);
    ASSERT_EQ(fly_by_hand(m, f->hand_prepared, f->program, &f->hand), Status::kOk);
    const DispersedTrajectory& t = f->result.trajectories[which];
    ASSERT_EQ(t.status, Status::kOk);
    const TrajectoryPoint& end = f->hand.final_point();
    EXPECT_EQ(t.values[3][kAlt], end.altitude_ft) << t.code;
    EXPECT_EQ(t.values[3][kVel], end.state[kStateV]) << t.code;
    EXPECT_NE(t.dispersions[3][kVel], 0.0) << t.code;  // the change did something
  }
}

// The signs a trajectory engineer expects, over the reference data of every code.
TEST(Sec15Dispersions, SignsOfEveryFamilyOnTheReferenceData) {
  auto f = make_fixture();
  reference_data(&f->data);
  ASSERT_EQ(run_dispersions(nominal_of(*f, true), f->data, &f->workspace, &f->result), Status::kOk);
  const DispersionResult& r = f->result;
  for (int k = 0; k < r.count; ++k)
    EXPECT_EQ(r.trajectories[k].status, Status::kOk) << r.trajectories[k].code;
  const auto twoe = [&](int code) { return find(r, code)->orbit_dispersions[0]; };
  // Thrust high (the same impulse in less time, consumed weight unchanged): less gravity loss, so a
  // higher velocity at the stage's own burnout; low: lower. (Later points need not follow: the
  // fixed coast 8 and the held stage-4 attitude meet the changed orbit elsewhere.)
  ASSERT_EQ(prepare_case(f->mission, &f->hand_prepared), Status::kOk);
  DispersionWorkspace& ws = f->workspace;
  for (int code = 1; code <= 6; ++code) {
    const DispersionSource& source = f->data.sources[code - 1];
    ASSERT_EQ(build_dispersed_case(nominal_of(*f, true), f->hand_prepared, source, &ws), Status::kOk);
    FlightInputs inputs;
    inputs.program = ws.program_mapped ? &ws.program : &f->program;
    inputs.body_dynamics = true;
    inputs.perturbation = &ws.perturbation;
    ASSERT_EQ(fly_by_hand(ws.mission, ws.prepared, inputs, &f->hand), Status::kOk);
    const int slot = 2 * (source.stage - 1);  // stages 1 6 2 7 3 8 4
    const double burnout_v = f->hand.points[f->hand.stages[slot].last_point].state[kStateV];
    const double nominal_v = ws.nominal.points[ws.nominal.stages[slot].last_point].state[kStateV];
    if (code % 2) {
      EXPECT_GT(burnout_v, nominal_v + 1.0) << code;
    } else {
      EXPECT_LT(burnout_v, nominal_v - 1.0) << code;
    }
  }
  // Heavier stages: less energy; lighter: more.
  for (int code : {9, 11, 13, 15}) {
    EXPECT_LT(twoe(code), 0.0) << code;
    EXPECT_GT(twoe(code + 1), 0.0) << code + 1;
  }
  // Drag high lowers the velocity at stage 2 ignition (the end of the drag stages 1 and 6).
  EXPECT_LT(find(r, 17)->dispersions[0][kVel], 0.0);
  EXPECT_GT(find(r, 18)->dispersions[0][kVel], 0.0);
  // A headwind (air speed higher, more drag) slows stage 1; a tailwind helps.
  EXPECT_LT(find(r, 36)->dispersions[0][kVel], 0.0);
  EXPECT_GT(find(r, 37)->dispersions[0][kVel], 0.0);
  // Yaw codes move the vehicle out of plane; a launch azimuth turned clockwise goes right.
  EXPECT_GT(find(r, 33)->dispersions[3][kCross], 0.0);
  for (int code : {23, 26, 29, 32, 38}) EXPECT_NE(find(r, code)->dispersions[3][kCross], 0.0) << code;
  // Pitch-plane codes stay nearly in the plane: their crossrange (the Sec. 4 small-angle formula on
  // the rotating Earth) is a few hundredths of the yaw codes' smallest.
  double smallest_yaw = 1e30;
  for (int code : {23, 26, 29, 33, 38})
    smallest_yaw = std::fmin(smallest_yaw, std::fabs(find(r, code)->dispersions[3][kCross]));
  EXPECT_GT(smallest_yaw, 1.0);  // n.mi.
  for (int code : {1, 9, 17, 24, 30, 34}) {
    EXPECT_LT(std::fabs(find(r, code)->dispersions[3][kCross]), 0.05 * smallest_yaw) << code;
  }
  // A positive misalignment pitches the nose up (more altitude early); the two signs oppose.
  EXPECT_LT(find(r, 21)->dispersions[0][kAlt] * find(r, 22)->dispersions[0][kAlt], 0.0);
  EXPECT_TRUE(r.three_sigma.computed);
}

constexpr auto stack = test::stack_stage4_5_tables;

TEST(Sec15Dispersions, CodesThatCannotFlyAreNamedNotSkipped) {
  auto f = make_fixture();
  DispersionData& data = f->data;
  data.count = 0;
  // Stacked stage 4/5 tables (block 55) on the four-stage reference: there is no stage 5.
  stack(f->mission.vehicle.stages[3], f->mission.vehicle.stages[3], true, &add(&data, 7));
  add(&data, 19).pitching_moment_per_rad = f->mission.body_dynamics.pitching_moment_per_rad;
  add(&data, 21).misalignment_rad = 0.25 * kDeg;
  add(&data, 31).stage = 5;  // no stage 5
  ASSERT_EQ(run_dispersions(nominal_of(*f, false), data, &f->workspace, &f->result), Status::kOk);
  ASSERT_EQ(f->result.count, 4);
  EXPECT_EQ(f->result.trajectories[0].status, Status::kDispersionStackedTablesNeedStage5);
  EXPECT_EQ(f->result.trajectories[1].status, Status::kDispersionNeedsBodyDynamics);
  EXPECT_EQ(f->result.trajectories[2].status, Status::kDispersionNeedsBodyDynamics);
  EXPECT_EQ(f->result.trajectories[3].status, Status::kDispersionStageNotInSequence);
  EXPECT_FALSE(f->result.three_sigma.computed);  // no code 40

  data.count = 0;
  add(&data, 12);
  add(&data, 11);  // out of order
  EXPECT_EQ(run_dispersions(nominal_of(*f), data, &f->workspace, &f->result), Status::kDispersionCodeInvalid);
}

// Sum and RSS of hand-made dispersions, the sign rule (velocity decides at zero altitude), yaw codes
// on their own, the high/low winds only in the "with winds" groups, failed codes left out.
TEST(Sec15ThreeSigma, GroupsBySumAndRssAsTheManualGroupsThem) {
  auto r = std::make_unique<DispersionResult>();
  r->staging_count = 2;
  struct Row {
    int code;
    double alt, vel;
    Status status;
  };
  const Row rows[] = {{1, 100.0, 5.0, Status::kOk}, {2, -40.0, 9.0, Status::kOk},
                      {9, 0.0, 3.0, Status::kOk},   {10, 0.0, -2.0, Status::kOk},
                      {23, 7.0, 1.0, Status::kOk},  {33, -3.0, 2.0, Status::kOk},
                      {36, 20.0, 1.0, Status::kOk}, {37, -10.0, 1.0, Status::kOk},
                      {38, 4.0, 0.0, Status::kOk},  {5, 999.0, 9.0, Status::kAltitudeBelowSurface}};
  for (const Row& row : rows) {
    DispersedTrajectory& t = r->trajectories[r->count++];
    t.code = row.code;
    t.status = row.status;
    t.dispersions[1][kAlt] = row.alt;
    t.dispersions[1][kVel] = row.vel;
    t.dispersions[0][kAlt] = 1.0;  // an earlier column: summed as well
  }
  compute_three_sigma(r.get());
  const ThreeSigmaSummary& s = r->three_sigma;
  ASSERT_TRUE(s.computed);
  EXPECT_EQ(s.yaw.member_count, 3);  // 23, 33, 38
  EXPECT_DOUBLE_EQ(s.yaw.sum[1][kAlt], 7.0 - 3.0 + 4.0);
  EXPECT_DOUBLE_EQ(s.yaw.rss[1][kAlt], std::sqrt(49.0 + 9.0 + 16.0));
  ASSERT_EQ(s.high.member_count, 2);  // 1 and 9 (zero altitude, positive velocity)
  EXPECT_EQ(s.high.members[0], 1);
  EXPECT_EQ(s.high.members[1], 9);
  EXPECT_DOUBLE_EQ(s.high.sum[1][kVel], 8.0);
  EXPECT_DOUBLE_EQ(s.high.rss[1][kVel], std::sqrt(25.0 + 9.0));
  EXPECT_DOUBLE_EQ(s.high.sum[0][kAlt], 2.0);
  ASSERT_EQ(s.low.member_count, 2);  // 2 and 10
  EXPECT_DOUBLE_EQ(s.low.sum[1][kAlt], -40.0);
  EXPECT_DOUBLE_EQ(s.low.rss[1][kVel], std::sqrt(81.0 + 4.0));
  ASSERT_EQ(s.high_with_winds.member_count, 3);
  EXPECT_EQ(s.high_with_winds.members[2], 36);
  EXPECT_DOUBLE_EQ(s.high_with_winds.sum[1][kAlt], 120.0);
  EXPECT_DOUBLE_EQ(s.high_with_winds.rss[1][kAlt], std::sqrt(100.0 * 100.0 + 400.0));
  ASSERT_EQ(s.low_with_winds.member_count, 3);
  EXPECT_DOUBLE_EQ(s.low_with_winds.sum[1][kAlt], -50.0);
}

// A five-stage vehicle (the reference plus a second spun kick stage after stage 4): the analysis
// gives a fifth column, stage 5 ignition, instead of the manual's squeeze of five stages into four.
TEST(Sec15Dispersions, FiveStageVehicleGetsEveryStagesIgnitionWithoutTheSqueeze) {
  auto f = make_fixture();
  Mission& m = f->mission;
  StageData& s5 = m.vehicle.stages[stage_index(5)];
  s5 = m.vehicle.stages[stage_index(4)];
  s5.integration_steps = 20;
  s5.jettison_weight_lb = 60.0;
  m.vehicle.sequence.codes[m.vehicle.sequence.count++] = 5;
  s5.in_sequence = true;
  ASSERT_EQ(m.options.spin_stages_4_5(), 1);  // stage 5 spins on stage 4's attitudes
  MissionFault fault;
  ASSERT_EQ(validate_mission(m, &fault), Status::kOk) << fault.field;
  DispersionData& data = f->data;
  data.count = 0;
  add(&data, 15).weight_increment_lb = 5.0;  // stage 4 heavier
  DispersionSource& tipoff = add(&data, 30);
  tipoff.stage = 5;
  tipoff.tipoff_rad = 2.0 * kDeg;
  add(&data, 40);
  DispersionNominal nominal;
  nominal.mission = &m;  // the block 40 table
  ASSERT_EQ(run_dispersions(nominal, data, &f->workspace, &f->result), Status::kOk);
  const DispersionResult& r = f->result;
  ASSERT_EQ(r.staging_count, 5);
  const int expected[] = {2, 3, 4, 5, 0};
  for (int j = 0; j < 5; ++j) EXPECT_EQ(r.staging_stage_code[j], expected[j]) << j;
  ASSERT_EQ(r.trajectories[0].status, Status::kOk);
  ASSERT_EQ(r.trajectories[1].status, Status::kOk);
  // Stage 4's jettison weight rides from the pad: slower at every ignition, stage 5's included.
  for (int j = 0; j < 4; ++j) EXPECT_LT(r.trajectories[0].dispersions[j][kVel], 0.0) << j;
  // Stage-5 tip-off: nothing before stage 5 ignition, a flight-path change at the end.
  EXPECT_EQ(r.trajectories[1].dispersions[3][kAlt], 0.0);
  EXPECT_GT(std::fabs(r.trajectories[1].dispersions[4][static_cast<int>(StagingVariable::kFlightPathAngle)]),
            1e-4);
}

// The final point of a dispersed trajectory equals the hand-changed forward run, bit for bit.
void expect_final_equals(const DispersedTrajectory& t, int final_column, const Trajectory& hand) {
  ASSERT_EQ(t.status, Status::kOk) << t.code;
  const TrajectoryPoint& end = hand.final_point();
  EXPECT_EQ(t.values[final_column][kAlt], end.altitude_ft) << t.code;
  EXPECT_EQ(t.values[final_column][kVel], end.state[kStateV]) << t.code;
  EXPECT_EQ(t.values[final_column][static_cast<int>(StagingVariable::kFlightPathAngle)],
            end.state[kStateGamma])
      << t.code;
  EXPECT_EQ(t.values[final_column][static_cast<int>(StagingVariable::kDownrange)],
            end.downrange_rad * kNauticalMilesPerRadian)
      << t.code;
  EXPECT_NE(t.dispersions[final_column][kVel], 0.0) << t.code;  // the change did something
}

void expect_same_values(const DispersedTrajectory& a, const DispersedTrajectory& b, int columns) {
  ASSERT_EQ(a.status, Status::kOk) << a.code;
  ASSERT_EQ(b.status, Status::kOk) << b.code;
  for (int j = 0; j < columns; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) EXPECT_EQ(a.values[j][i], b.values[j][i]) << j << " " << i;
  }
  for (int i = 0; i < kOrbitDispersionElements; ++i) EXPECT_EQ(a.orbit[i], b.orbit[i]) << i;
}

// Manual Sec. 15 / Sec. 22 page 22-30 and data block 55: codes 7-8 with stages 4 and 5 stacked in
// the stage-4 tables fly as the two stages' own replacement tables. On the five-stage vehicle,
// with the reference "stage 4 high" tables (thrust x 1.03, times / 1.03) for either stage:
//  * stacked [4 high | coast | 5 nominal] and [4 nominal | coast | 5 high] give, bit for bit, every
//    staging value and orbit element of the per-stage form (code 7 on stage 4; code 7 with stage
//    code 5);
//  * stacked [4 high | coast | 5 high] is, bit for bit, the forward run of the mission with both
//    stages' tables replaced by hand (burn times their last times, coast 9 as optimized: 6 s, not
//    the 2 s of the tables);
//  * the continuing layout (stage 5 at d4 + 2 + t) flies as the restarting one, to round-off of
//    (d4 + 2 + t) - (d4 + 2).
TEST(Sec15Dispersions, StackedStage45TablesFlyAsTheirPerStageForm) {
  auto f = make_fixture();
  Mission& m = f->mission;
  test::make_five_stage_vehicle(&m);
  const nlohmann::json& t =
      test::scout_reference()["dispersions"]["codes_1_8_vacuum_thrust_variation"]["tables"]["stage_4_high"];
  StageData high;
  fill(&high.vacuum_thrust_lbf, t["time_s"], t["vacuum_thrust_lbf"]);
  fill(&high.consumable_weight_lb, t["time_s"], t["consumable_weight_remaining_lb"]);
  const StageData& nominal4 = m.vehicle.stages[stage_index(4)];
  const StageData& nominal5 = m.vehicle.stages[stage_index(5)];
  DispersionNominal nominal;
  nominal.mission = &m;  // the block 40 table

  // The per-stage form.
  DispersionData& data = f->data;
  data.count = 0;
  DispersionSource& per4 = add(&data, 7);
  per4.vacuum_thrust_lbf = high.vacuum_thrust_lbf;
  per4.consumable_weight_lb = high.consumable_weight_lb;
  DispersionSource& per5 = add(&data, 8);
  per5.stage = 5;
  per5.vacuum_thrust_lbf = high.vacuum_thrust_lbf;
  per5.consumable_weight_lb = high.consumable_weight_lb;
  ASSERT_EQ(run_dispersions(nominal, data, &f->workspace, &f->result), Status::kOk);
  const auto per_stage = std::make_unique<DispersionResult>(f->result);
  ASSERT_EQ(per_stage->staging_count, 5);
  ASSERT_EQ(per_stage->trajectories[0].status, Status::kOk);
  ASSERT_EQ(per_stage->trajectories[1].status, Status::kOk);

  // The stacked form: one stage dispersed, the other's nominal tables stacked with it.
  data.count = 0;
  stack(high, nominal5, true, &add(&data, 7));
  stack(nominal4, high, true, &add(&data, 8));
  ASSERT_EQ(run_dispersions(nominal, data, &f->workspace, &f->result), Status::kOk);
  ASSERT_EQ(f->result.count, 2);
  for (int k = 0; k < 2; ++k) expect_same_values(f->result.trajectories[k], per_stage->trajectories[k], 5);
  // Stage 5's thrust leaves every column before its ignition as the nominal's.
  for (int j = 0; j < 4; ++j) EXPECT_EQ(f->result.trajectories[1].dispersions[j][kVel], 0.0) << j;
  EXPECT_NE(f->result.trajectories[0].dispersions[3][kVel], 0.0);  // stage 5 ignition moved

  // Both stages dispersed: the hand-made forward run.
  data.count = 0;
  stack(high, high, true, &add(&data, 7));
  stack(high, high, false, &add(&data, 8));
  ASSERT_EQ(run_dispersions(nominal, data, &f->workspace, &f->result), Status::kOk);
  Mission& hand = f->hand_mission;
  hand = m;
  for (int code : {4, 5}) {
    StageData& stage = hand.vehicle.stages[stage_index(code)];
    stage.vacuum_thrust_lbf = high.vacuum_thrust_lbf;
    stage.consumable_weight_lb = high.consumable_weight_lb;
    stage.duration_s = high.vacuum_thrust_lbf.last_x();
  }
  ASSERT_EQ(hand.vehicle.stages[stage_index(9)].duration_s, 6.0);
  ASSERT_EQ(prepare_case(hand, &f->hand_prepared), Status::kOk);
  ASSERT_EQ(fly_by_hand(hand, f->hand_prepared, &f->hand), Status::kOk);
  expect_final_equals(f->result.trajectories[0], 4, f->hand);
  // The coast between them flew its 6 s (flight order 1 6 2 7 3 8 4 9 5), stage 5 its table's time.
  const PreparedCase& flown = f->workspace.prepared;
  EXPECT_EQ(flown.timeline[7].code, 9);
  EXPECT_EQ(flown.timeline[7].duration_s, 6.0);
  EXPECT_NEAR(flown.timeline[8].duration_s, high.vacuum_thrust_lbf.last_x(), 1e-12);
  // The continuing layout: the same flight to round-off.
  const DispersedTrajectory& restarting = f->result.trajectories[0];
  const DispersedTrajectory& continuing = f->result.trajectories[1];
  ASSERT_EQ(continuing.status, Status::kOk);
  for (int j = 0; j < 5; ++j) {
    EXPECT_NEAR(continuing.values[j][kAlt], restarting.values[j][kAlt],
                1e-6 * std::fabs(restarting.values[j][kAlt]) + 1e-6)
        << j;
    EXPECT_NEAR(continuing.values[j][kVel], restarting.values[j][kVel], 1e-9 * restarting.values[j][kVel])
        << j;
  }
}

// Codes 1-8: the replacement tables of the reference data (tests/reference, stage 2 high) put into
// the Mission by hand with the burn time their last time, flown with the block 40 table (the
// program is a function of time, so no per-point mapping is involved).
TEST(Sec15Dispersions, ThrustTablesEqualTheCaseChangedByHand) {
  auto f = make_fixture();
  const nlohmann::json& t =
      test::scout_reference()["dispersions"]["codes_1_8_vacuum_thrust_variation"]["tables"];
  for (int code : {1, 4, 5, 8}) {
    DispersionData& data = f->data;
    data.count = 0;
    DispersionSource& s = add(&data, code);
    const std::string key = "stage_" + std::to_string(s.stage) + (code % 2 ? "_high" : "_low");
    fill(&s.vacuum_thrust_lbf, t[key]["time_s"], t[key]["vacuum_thrust_lbf"]);
    fill(&s.consumable_weight_lb, t[key]["time_s"], t[key]["consumable_weight_remaining_lb"]);
    DispersionNominal nominal;
    nominal.mission = &f->mission;  // the block 40 table
    ASSERT_EQ(run_dispersions(nominal, data, &f->workspace, &f->result), Status::kOk);

    Mission& m = f->hand_mission;
    m = f->mission;
    StageData& stage = m.vehicle.stages[stage_index(s.stage)];
    fill(&stage.vacuum_thrust_lbf, t[key]["time_s"], t[key]["vacuum_thrust_lbf"]);
    fill(&stage.consumable_weight_lb, t[key]["time_s"], t[key]["consumable_weight_remaining_lb"]);
    stage.duration_s = t[key]["time_s"].back().get<double>();
    ASSERT_EQ(prepare_case(m, &f->hand_prepared), Status::kOk);
    // The table read in stage time (every later stage's clock starts at the nominal's start of it:
    // shifted by the burn-time change) and, in stage 1, with its step grid.
    FlightPerturbation clock;
    for (int k = 0; k < f->hand_prepared.stage_count; ++k) {
      const StageTimeline& hand_line = f->hand_prepared.timeline[k];
      const StageTimeline& nominal_line = f->prepared.timeline[k];
      clock.program_clock_shift_s[stage_index(hand_line.code)] = hand_line.start_s - nominal_line.start_s;
      if (hand_line.code == 1) clock.stage1_program_clock_rate = nominal_line.step_s / hand_line.step_s;
    }
    FlightInputs inputs;
    inputs.perturbation = &clock;
    ASSERT_EQ(fly_by_hand(m, f->hand_prepared, inputs, &f->hand), Status::kOk);
    expect_final_equals(f->result.trajectories[0], f->result.staging_count - 1, f->hand);
  }
}

// Sec. 15 "variation in thrust, burn time, and consumed weight" of stage 1 about the reference's
// data block 40 nominal with body dynamics (IP(11) zero-alpha window and IP(12) on): thrust x c,
// every table time / c. A smooth model's burnout altitude is linear in c - 1 for small changes:
// the slopes of +d and -d agree, the central difference converges, and a change across TIMEP/2 of
// burn time (d ~ 2.2e-4: where the window end and the stage-2 ignition used to leave the table's
// nodes at 45 and 50 s) or across 0.035 s at the window start (d ~ 7.8e-4) has the same slope.
TEST(Sec15Dispersions, Stage1ThrustResponseIsLinearForSmallChanges) {
  auto f = make_fixture();
  const StageData& n = f->mission.vehicle.stages[stage_index(1)];
  const DispersionNominal nominal = test::dispersion_nominal(f->mission, nullptr, true);
  const auto final_altitude_dispersion = [&](double d) {
    DispersionData& data = f->data;
    data.count = 0;
    DispersionSource& s = add(&data, 1);
    for (int i = 0; i < n.vacuum_thrust_lbf.size(); ++i) {
      EXPECT_EQ(s.vacuum_thrust_lbf.append(n.vacuum_thrust_lbf.x(i) / (1.0 + d),
                                           n.vacuum_thrust_lbf.y(i) * (1.0 + d)),
                Status::kOk);
      EXPECT_EQ(
          s.consumable_weight_lb.append(n.consumable_weight_lb.x(i) / (1.0 + d), n.consumable_weight_lb.y(i)),
          Status::kOk);
    }
    EXPECT_EQ(s.vacuum_thrust_lbf.finalize(), Status::kOk);
    EXPECT_EQ(s.consumable_weight_lb.finalize(), Status::kOk);
    EXPECT_EQ(run_dispersions(nominal, data, &f->workspace, &f->result), Status::kOk);
    EXPECT_EQ(f->result.trajectories[0].status, Status::kOk);
    return f->result.trajectories[0].dispersions[f->result.staging_count - 1][kAlt];
  };
  const double slope_plus_4 = final_altitude_dispersion(1e-4) / 1e-4;
  const double slope_minus_4 = final_altitude_dispersion(-1e-4) / -1e-4;
  const double slope_plus_3 = final_altitude_dispersion(1e-3) / 1e-3;
  const double slope_minus_3 = final_altitude_dispersion(-1e-3) / -1e-3;
  std::printf("stage-1 thrust: slopes ft per unit c: +1e-4 %.6g, -1e-4 %.6g, +1e-3 %.6g, -1e-3 %.6g\n",
              slope_plus_4, slope_minus_4, slope_plus_3, slope_minus_3);
  EXPECT_GT(slope_plus_4, 0.0);  // the same impulse burnt sooner: less gravity loss, higher
  EXPECT_NEAR(slope_plus_4 / slope_minus_4, 1.0, 0.01);
  EXPECT_NEAR(slope_plus_3 / slope_minus_3, 1.0, 0.01);
  const double central_4 = 0.5 * (slope_plus_4 + slope_minus_4);
  const double central_3 = 0.5 * (slope_plus_3 + slope_minus_3);
  EXPECT_NEAR(central_3 / central_4, 1.0, 0.005);
  for (double d : {2.0e-4, 2.5e-4, 7.5e-4, 8.5e-4, 3e-3, -3e-3}) {
    EXPECT_NEAR(final_altitude_dispersion(d) / d / central_4, 1.0, 0.01) << d;
  }
}

// Deadband (stage 3 pitch), tip-off (stage 4 pitch and yaw) and launch attitude: the attitude
// offsets made by hand in the per-point program and the spun stage's block 17 attitudes.
TEST(Sec15Dispersions, DeadbandTipoffAndLaunchAttitudeEqualTheCaseChangedByHand) {
  auto f = make_fixture();
  // The zero-alpha window (IP(11)) fixes its own attitudes and the one at its end, and IP(12) the
  // one at stage-2 ignition: off here, in the nominal and the hand case alike, so that every
  // attitude after lift-off is the program's.
  f->mission.options.set_zero_alpha_window(false);
  f->mission.options.set_alpha_zero_at_stage2_ignition(false);
  DispersionData& data = f->data;
  data.count = 0;
  const double band = 0.5 * kDeg, tip = 2.0 * kDeg, attitude = 0.3 * kDeg;
  add(&data, 27).deadband_rad = band;
  DispersionSource& tipoff = add(&data, 30);
  tipoff.stage = 4;
  tipoff.tipoff_rad = tip;
  DispersionSource& yaw_tipoff = add(&data, 32);
  yaw_tipoff.stage = 4;
  yaw_tipoff.tipoff_rad = -tip;
  add(&data, 34).launch_change_rad = attitude;
  ASSERT_EQ(run_dispersions(nominal_of(*f), data, &f->workspace, &f->result), Status::kOk);
  const int final_column = f->result.staging_count - 1;
  ASSERT_EQ(prepare_case(f->mission, &f->prepared), Status::kOk);
  int stage3_first = -1, stage3_last = -1;
  for (int k = 0; k < f->table_flight.stage_count; ++k) {
    if (f->table_flight.stages[k].code == 3) {
      stage3_first = f->table_flight.stages[k].first_point;
      stage3_last = f->table_flight.stages[k].last_point;
    }
  }
  ASSERT_GT(stage3_first, 0);
  for (int which = 0; which < 4; ++which) {
    Mission& m = f->hand_mission;
    m = f->mission;
    auto program = std::make_unique<ControlProgram>(f->program);
    if (which == 0) {
      for (int k = stage3_first; k <= stage3_last; ++k) program->theta_rad[k] += band;
    }
    if (which == 1) m.misc.stage4_theta_rad += tip;
    if (which == 2) m.misc.stage4_chi_rad += -tip;
    if (which == 3) {
      for (int k = 0; k < program->point_count; ++k) program->theta_rad[k] += attitude;
      m.misc.stage4_theta_rad += attitude;
    }
    ASSERT_EQ(fly_by_hand(m, f->prepared, *program, &f->hand), Status::kOk);
    expect_final_equals(f->result.trajectories[which], final_column, f->hand);
  }
}

// Misalignment (stage 1, with body dynamics), winds and the yaw deadband have no deck input outside
// data blocks 46-55: the hand case is the flight inputs written here (the block 49 moment, the
// block 53-54 profile of the reference, the stage-2 chi offset), flown without the dispersion module.
TEST(Sec15Dispersions, MisalignmentWindsAndYawDeadbandEqualTheFlightChangedByHand) {
  auto f = make_fixture();
  DispersionData& data = f->data;
  data.count = 0;
  const nlohmann::json& d = test::scout_reference()["dispersions"];
  const nlohmann::json& mis = d["codes_21_23_block49_stage1_thrust_misalignment"];
  const double angle = mis["angle_deg"].get<double>() * kDeg;
  const double station = mis["thrust_application_station_in"].get<double>() / 12.0;
  DispersionSource& high = add(&data, 21);
  high.misalignment_rad = angle;
  high.thrust_station_ft = station;
  DispersionSource& yaw = add(&data, 23);
  yaw.misalignment_rad = angle;
  yaw.thrust_station_ft = station;
  add(&data, 26).deadband_rad = 0.5 * kDeg;
  const nlohmann::json& w = d["codes_36_38_winds"];
  DispersionSource& wind = add(&data, 36);
  fill(&wind.wind.speed_ft_s, w["block53_altitude_ft"], w["block53_wind_speed_ft_per_s"]);
  fill(&wind.wind.azimuth_rad, w["block53_altitude_ft"],
       w["block54_wind_vector_azimuth_deg"]["code_36_high_headwind"], kDeg);
  ASSERT_EQ(run_dispersions(nominal_of(*f, true), data, &f->workspace, &f->result), Status::kOk);
  const int final_column = f->result.staging_count - 1;
  ASSERT_EQ(prepare_case(f->mission, &f->prepared), Status::kOk);
  auto profile = std::make_unique<WindProfile>();
  fill(&profile->speed_ft_s, w["block53_altitude_ft"], w["block53_wind_speed_ft_per_s"]);
  fill(&profile->azimuth_rad, w["block53_altitude_ft"],
       w["block54_wind_vector_azimuth_deg"]["code_36_high_headwind"], kDeg);
  for (int which = 0; which < 4; ++which) {
    FlightPerturbation p;
    if (which == 0) p.misalignment_pitch_rad = angle;
    if (which == 1) p.misalignment_yaw_rad = angle;
    if (which <= 1) p.thrust_station_ft = station;
    if (which == 2) p.chi_offset_rad[stage_index(2)] = 0.5 * kDeg;
    if (which == 3) p.wind = profile.get();
    FlightInputs inputs;
    inputs.program = &f->program;
    inputs.body_dynamics = true;
    inputs.perturbation = &p;
    ASSERT_EQ(fly_by_hand(f->mission, f->prepared, inputs, &f->hand), Status::kOk);
    expect_final_equals(f->result.trajectories[which], final_column, f->hand);
  }
}

// The air-relative velocity from psi_w - psi's sine and cosine (a dispersion flight's, by addition
// from an anchor) is the angle form's bit for bit given the library's sines, and within about two
// ulps of it (relative to the air speed) given the anchor's.
TEST(Sec15Winds, AirRelativeVelocityFromGivenSinesIsTheAngleForm) {
  StateVector state;
  state << 2500.0, 0.7, 2.1e7, 1.6, 0.5, -1.3;
  const StateTrig trig(state);
  const double speed_ft_s = 120.0;
  SineCosineAnchor anchor;
  double worst = 0.0;
  for (double azimuth = -4.0; azimuth < 4.0; azimuth += 1e-3) {
    const double relative = azimuth - state[kStatePsi];
    const Vector3 angle_form = air_relative_velocity_local(state, trig, speed_ft_s, azimuth);
    const Vector3 given = air_relative_velocity_local(state, trig, speed_ft_s,
                                                      SineCosine{std::sin(relative), std::cos(relative)});
    ASSERT_EQ(given, angle_form) << azimuth;
    const Vector3 anchored = air_relative_velocity_local(state, trig, speed_ft_s, anchor.at(relative));
    worst = std::max(worst, (anchored - angle_form).norm() / angle_form.norm());
  }
  EXPECT_LT(worst, 4e-16);
  std::printf("[ figures  ] Sec15 air-relative velocity from anchored sines: worst %.2e of |V_air|\n", worst);
}

}  // namespace
}  // namespace tolip
