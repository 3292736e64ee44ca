// validate_mission() and validate_body_dynamics() (manual Sec. 22, the data blocks; issue 14
// structural coverage): every rejection the deck readers normally catch first is made here on the
// reference mission by one edit, and must name its Status, data block, stage, field and index. One
// row per check: a check that stopped rejecting, or rejected under another name, fails its row.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "support/reference_mission.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip {
namespace {

using test::stage;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kAnyIndex = -99;

struct Rejection {
  const char* what;
  void (*edit)(Mission&);
  Status status;
  int data_block;
  int stage_code;
  const char* field;
  int index;  // kAnyIndex: not checked
};

std::unique_ptr<Mission> reference() {
  auto mission = std::make_unique<Mission>();
  test::build_reference_mission(test::ReferenceProgram::kOptimum, mission.get());
  return mission;
}

void expect_rejections(const Rejection* rows, int count, Status (*validate)(const Mission&, MissionFault*)) {
  for (int r = 0; r < count; ++r) {
    const Rejection& row = rows[r];
    SCOPED_TRACE(row.what);
    auto mission = reference();
    ASSERT_EQ(validate(*mission, nullptr), Status::kOk);
    row.edit(*mission);
    MissionFault fault;
    const Status status = validate(*mission, &fault);
    EXPECT_EQ(status, row.status) << status_name(status) << " at block " << fault.data_block << " field "
                                  << fault.field;
    EXPECT_EQ(fault.data_block, row.data_block);
    EXPECT_EQ(fault.stage_code, row.stage_code);
    EXPECT_STREQ(fault.field, row.field);
    if (row.index != kAnyIndex) {
      EXPECT_EQ(fault.index, row.index);
    }
    // A value fault carries the rejected value (NaN compares unequal to itself).
    if (fault.has_value && row.status == Status::kValueNotFinite) {
      EXPECT_FALSE(std::isfinite(fault.value));
    }
  }
}

// Replaces a table by (x0, y0), (x1, y1), finalized.
template <int N>
void two_points(Table<N>* table, double x0, double y0, double x1, double y1) {
  table->clear();
  ASSERT_EQ(table->append(x0, y0), Status::kOk);
  ASSERT_EQ(table->append(x1, y1), Status::kOk);
  ASSERT_EQ(table->finalize(), Status::kOk);
}

// The reference list (payoff 0, then 7, 2, 3) made 13 entries long with known terminal codes.
void fill_constraint_list(ConstraintList* c) {
  const int more[] = {1, 4, 5, 6, 8, 9, 10, 11, 12};
  c->count = kMaxConstraints;
  for (int i = 0; i < 9; ++i) c->codes[4 + i] = more[i];
}

// Data blocks 4 (options), 5 with 4 (IP(9)), 10 (constants), 11-14 (atmosphere).
TEST(Sec22DataBlocks, OptionConstantAndAtmosphereRejectionsNameTheirWord) {
  static const Rejection rows[] = {
      {"IP(4) not used", [](Mission& m) { m.options.ip[4] = 1; }, Status::kOptionOutOfRange, 4, 0, "ip", 4},
      {"IP(13) 0 or 1", [](Mission& m) { m.options.ip[13] = 2; }, Status::kOptionOutOfRange, 4, 0, "ip", 13},
      {"IP(1) 0-2", [](Mission& m) { m.options.ip[1] = 3; }, Status::kOptionOutOfRange, 4, 0, "ip", 1},
      {"IP(6) 0-2", [](Mission& m) { m.options.ip[6] = 3; }, Status::kOptionOutOfRange, 4, 0, "ip", 6},
      {"IP(9) 0-3", [](Mission& m) { m.options.ip[9] = 4; }, Status::kOptionOutOfRange, 4, 0, "ip", 9},
      {"IP(10) 0-2", [](Mission& m) { m.options.ip[10] = 3; }, Status::kOptionOutOfRange, 4, 0, "ip", 10},
      {"IP(6) = 1 needs IP(7) = 1", [](Mission& m) { m.options.ip[7] = 0; },
       Status::kBodyDynamicsRelinearizationWithoutLinearization, 4, 0, "ip", 7},
      {"q-bar alpha limit finite", [](Mission& m) { m.options.qbar_alpha_limit_lbf_rad_ft2 = kNaN; },
       Status::kValueNotFinite, 4, 0, "qbar_alpha_limit_lbf_rad_ft2", -1},
      {"q-bar alpha limit >= 0", [](Mission& m) { m.options.qbar_alpha_limit_lbf_rad_ft2 = -1.0; },
       Status::kOptionOutOfRange, 4, 0, "qbar_alpha_limit_lbf_rad_ft2", -1},
      {"stage 4 flown needs IP(9)", [](Mission& m) { m.options.ip[9] = 0; }, Status::kSpinOptionInconsistent,
       4, 4, "ip", 9},
      {"IP(9) = 3 only with five stages", [](Mission& m) { m.options.ip[9] = 3; },
       Status::kSpinOptionInconsistent, 4, 5, "ip", 9},
      // Sec. 22 IP(10): "0 fewer than 5 stages, 1 chi5 = chi4, 2 chi5 independent of chi4".
      {"IP(10) 0 with fewer than five stages", [](Mission& m) { m.options.ip[10] = 1; },
       Status::kStage5YawOptionInconsistent, 4, 5, "ip", 10},
      {"earth rotation finite", [](Mission& m) { m.constants.earth_rotation_rate_rad_s = kNaN; },
       Status::kValueNotFinite, 10, 0, "earth_rotation_rate_rad_s", -1},
      {"ct1_13 finite", [](Mission& m) { m.constants.ct1_13 = HUGE_VAL; }, Status::kValueNotFinite, 10, 0,
       "ct1_13", -1},
      {"mu > 0", [](Mission& m) { m.constants.gravitational_parameter_ft3_s2 = 0.0; },
       Status::kConstantOutOfRange, 10, 0, "gravitational_parameter_ft3_s2", -1},
      {"equatorial radius > 0", [](Mission& m) { m.constants.earth_equatorial_radius_ft = -1.0; },
       Status::kConstantOutOfRange, 10, 0, "earth_equatorial_radius_ft", -1},
      {"gas constant > 0", [](Mission& m) { m.constants.gas_constant_ft2_s2_R = 0.0; },
       Status::kConstantOutOfRange, 10, 0, "gas_constant_ft2_s2_R", -1},
      {"sea-level pressure >= 0", [](Mission& m) { m.constants.sea_level_pressure_lbf_ft2 = -1.0; },
       Status::kConstantOutOfRange, 10, 0, "sea_level_pressure_lbf_ft2", -1},
      {"haero >= 0", [](Mission& m) { m.constants.haero_ft = -1.0; }, Status::kConstantOutOfRange, 10, 0,
       "haero_ft", -1},
      {"time epsilon > 0", [](Mission& m) { m.constants.time_epsilon_s = 0.0; }, Status::kConstantOutOfRange,
       10, 0, "time_epsilon_s", -1},
      {"block 11 finite", [](Mission& m) { m.atmosphere.base_geopotential_altitude_ft[2] = kNaN; },
       Status::kValueNotFinite, 11, 0, "base_geopotential_altitude_ft", 2},
      {"block 12 finite", [](Mission& m) { m.atmosphere.base_molecular_temperature_R[3] = kNaN; },
       Status::kValueNotFinite, 12, 0, "base_molecular_temperature_R", 3},
      {"block 13 finite", [](Mission& m) { m.atmosphere.lapse_rate_R_per_ft[1] = kNaN; },
       Status::kValueNotFinite, 13, 0, "lapse_rate_R_per_ft", 1},
      {"block 14 finite", [](Mission& m) { m.atmosphere.base_density_slug_ft3[4] = kNaN; },
       Status::kValueNotFinite, 14, 0, "base_density_slug_ft3", 4},
      {"first base at 0 ft", [](Mission& m) { m.atmosphere.base_geopotential_altitude_ft[0] = 10.0; },
       Status::kAtmosphereTableInvalid, 11, 0, "base_geopotential_altitude_ft", 0},
      {"base temperature > 0", [](Mission& m) { m.atmosphere.base_molecular_temperature_R[2] = 0.0; },
       Status::kAtmosphereTableInvalid, 12, 0, "base_molecular_temperature_R", 2},
      {"base density > 0", [](Mission& m) { m.atmosphere.base_density_slug_ft3[2] = 0.0; },
       Status::kAtmosphereTableInvalid, 14, 0, "base_density_slug_ft3", 2},
  };
  expect_rejections(rows, static_cast<int>(std::size(rows)), validate_mission);
}

// Data blocks 16, 30, 31, 32, 38, 39: the stages and the vehicle.
TEST(Sec22DataBlocks, StageAndVehicleRejectionsNameTheStageAndTable) {
  static const Rejection rows[] = {
      {"duration finite", [](Mission& m) { stage(m, 2).duration_s = kNaN; }, Status::kValueNotFinite, 16, 2,
       "duration_s", -1},
      {"jettison weight finite", [](Mission& m) { stage(m, 3).jettison_weight_lb = kNaN; },
       Status::kValueNotFinite, 39, 3, "jettison_weight_lb", -1},
      {"reference area finite", [](Mission& m) { stage(m, 3).reference_area_ft2 = kNaN; },
       Status::kValueNotFinite, 39, 3, "reference_area_ft2", -1},
      {"nozzle exit area finite", [](Mission& m) { stage(m, 3).nozzle_exit_area_ft2 = kNaN; },
       Status::kValueNotFinite, 39, 3, "nozzle_exit_area_ft2", -1},
      {"reference area >= 0", [](Mission& m) { stage(m, 3).reference_area_ft2 = -1.0; },
       Status::kNegativeArea, 39, 3, "reference_area_ft2", -1},
      {"nozzle exit area >= 0", [](Mission& m) { stage(m, 3).nozzle_exit_area_ft2 = -1.0; },
       Status::kNegativeArea, 39, 3, "nozzle_exit_area_ft2", -1},
      {"drag coefficient finite", [](Mission& m) { stage(m, 2).drag_coefficient.set_y(3, kNaN); },
       Status::kValueNotFinite, 31, 2, "drag_coefficient", 3},
      {"drag table finalized", [](Mission& m) { stage(m, 2).drag_coefficient.set_y(3, 0.5); },
       Status::kTableNotMonotonic, 31, 2, "drag_mach", -1},
      {"drag table needs an area", [](Mission& m) { stage(m, 2).reference_area_ft2 = 0.0; },
       Status::kReferenceAreaMissing, 39, 2, "reference_area_ft2", -1},
      {"coast steps at most 100", [](Mission& m) { stage(m, 7).integration_steps = kMaxCoastSteps + 1; },
       Status::kTooManyCoastSteps, 16, 7, "integration_steps", -1},
      {"no thrust table in a coast",
       [](Mission& m) { two_points(&stage(m, 7).vacuum_thrust_lbf, 0.0, 0.0, 6.0, 0.0); },
       Status::kPropulsionInCoast, 30, 7, "vacuum_thrust_lbf", -1},
      {"no nozzle in a coast", [](Mission& m) { stage(m, 7).nozzle_exit_area_ft2 = 1.0; },
       Status::kPropulsionInCoast, 39, 7, "nozzle_exit_area_ft2", -1},
      {"no weight table in a coast",
       [](Mission& m) { two_points(&stage(m, 7).consumable_weight_lb, 0.0, 0.0, 6.0, 0.0); },
       Status::kPropulsionInCoast, 38, 7, "consumable_weight_lb", -1},
      {"thrust finite", [](Mission& m) { stage(m, 3).vacuum_thrust_lbf.set_y(2, kNaN); },
       Status::kValueNotFinite, 30, 3, "vacuum_thrust_lbf", 2},
      {"consumable weight finite", [](Mission& m) { stage(m, 3).consumable_weight_lb.set_y(2, kNaN); },
       Status::kValueNotFinite, 38, 3, "consumable_weight_lb", 2},
      {"weight table finalized",
       [](Mission& m) { stage(m, 3).consumable_weight_lb.set_y(2, stage(m, 3).consumable_weight_lb.y(2)); },
       Status::kMissingWeightTable, 38, 3, "consumable_weight_lb", -1},
      {"thrust from t >= 0",
       [](Mission& m) { two_points(&stage(m, 4).vacuum_thrust_lbf, -1.0, 100.0, 28.0, 0.0); },
       Status::kTableTimeNegative, 30, 4, "vacuum_thrust_time_s", 0},
      {"weight from t >= 0",
       [](Mission& m) { two_points(&stage(m, 4).consumable_weight_lb, -1.0, 100.0, 28.0, 0.0); },
       Status::kTableTimeNegative, 38, 4, "consumable_weight_time_s", 0},
      {"weight >= 0",
       [](Mission& m) { two_points(&stage(m, 4).consumable_weight_lb, 0.0, 100.0, 28.0, -1.0); },
       Status::kNegativeWeight, 38, 4, "consumable_weight_lb", 1},
      {"lift table finite", [](Mission& m) { m.vehicle.lift_curve_slope_per_rad.set_y(1, kNaN); },
       Status::kValueNotFinite, 32, 0, "lift_curve_slope_per_rad", 1},
      {"lift table given when used", [](Mission& m) { m.vehicle.lift_curve_slope_per_rad.clear(); },
       Status::kTableEmpty, 32, 1, "lift_curve_slope_per_rad", -1},
      {"lift needs an area",
       [](Mission& m) {
         stage(m, 3).uses_lift_table = true;
         stage(m, 3).reference_area_ft2 = 0.0;
       },
       Status::kReferenceAreaMissing, 39, 3, "reference_area_ft2", -1},
      {"payload finite", [](Mission& m) { m.vehicle.payload_lb = kNaN; }, Status::kValueNotFinite, 39, 4,
       "payload_lb", -1},
      {"payload >= 0", [](Mission& m) { m.vehicle.payload_lb = -1.0; }, Status::kNegativeWeight, 39, 4,
       "payload_lb", -1},
  };
  expect_rejections(rows, static_cast<int>(std::size(rows)), validate_mission);
}

// Data blocks 17, 20, 21, 22, 28, 9, 40.
TEST(Sec22DataBlocks, LaunchControlMiscConvergenceAndOutputRejectionsNameTheirWord) {
  static const Rejection rows[] = {
      {"lift-off duration finite", [](Mission& m) { m.launch.liftoff_duration_s = kNaN; },
       Status::kValueNotFinite, 20, 0, "liftoff_duration_s", -1},
      {"launch date finite", [](Mission& m) { m.launch.launch_space_age_date_days = kNaN; },
       Status::kValueNotFinite, 20, 0, "launch_space_age_date_days", -1},
      {"launch altitude finite", [](Mission& m) { m.launch.altitude_ft = kNaN; }, Status::kValueNotFinite, 21,
       0, "altitude_ft", -1},
      {"longitude finite", [](Mission& m) { m.launch.longitude_rad = kNaN; }, Status::kValueNotFinite, 21, 0,
       "longitude_rad", -1},
      {"latitude finite", [](Mission& m) { m.launch.geocentric_latitude_rad = kNaN; },
       Status::kValueNotFinite, 21, 0, "geocentric_latitude_rad", -1},
      {"velocity finite", [](Mission& m) { m.launch.velocity_ft_s = kNaN; }, Status::kValueNotFinite, 21, 0,
       "velocity_ft_s", -1},
      {"azimuth finite", [](Mission& m) { m.launch.azimuth_rad = kNaN; }, Status::kValueNotFinite, 21, 0,
       "azimuth_rad", -1},
      {"flight-path angle finite", [](Mission& m) { m.launch.flight_path_angle_rad = kNaN; },
       Status::kValueNotFinite, 21, 0, "flight_path_angle_rad", -1},
      {"heading hold finite", [](Mission& m) { m.launch.heading_hold_until_s = kNaN; },
       Status::kValueNotFinite, 21, 0, "heading_hold_until_s", -1},
      {"longitude within a turn", [](Mission& m) { m.launch.longitude_rad = 7.0; },
       Status::kLaunchConditionOutOfRange, 21, 0, "longitude_rad", -1},
      {"zero-alpha start finite", [](Mission& m) { m.control.zero_alpha_start_s = kNaN; },
       Status::kValueNotFinite, 22, 0, "zero_alpha_start_s", -1},
      {"zero-alpha end finite", [](Mission& m) { m.control.zero_alpha_end_s = kNaN; },
       Status::kValueNotFinite, 22, 0, "zero_alpha_end_s", -1},
      {"max pitch rate finite", [](Mission& m) { m.control.max_pitch_rate_rad_s = kNaN; },
       Status::kValueNotFinite, 22, 0, "max_pitch_rate_rad_s", -1},
      {"min pitch rate finite", [](Mission& m) { m.control.min_pitch_rate_rad_s = kNaN; },
       Status::kValueNotFinite, 22, 0, "min_pitch_rate_rad_s", -1},
      {"min pitch-rate change finite", [](Mission& m) { m.control.min_pitch_rate_change_rad_s = kNaN; },
       Status::kValueNotFinite, 22, 0, "min_pitch_rate_change_rad_s", -1},
      {"max pitch rate >= 0", [](Mission& m) { m.control.max_pitch_rate_rad_s = -0.1; },
       Status::kPitchRateLimitNegative, 22, 0, "max_pitch_rate_rad_s", -1},
      {"min pitch rate >= 0", [](Mission& m) { m.control.min_pitch_rate_rad_s = -0.1; },
       Status::kPitchRateLimitNegative, 22, 0, "min_pitch_rate_rad_s", -1},
      {"min pitch-rate change >= 0", [](Mission& m) { m.control.min_pitch_rate_change_rad_s = -0.1; },
       Status::kPitchRateLimitNegative, 22, 0, "min_pitch_rate_change_rad_s", -1},
      {"zero-alpha window from t >= 0", [](Mission& m) { m.control.zero_alpha_start_s = -1.0; },
       Status::kZeroAlphaWindowInvalid, 22, 0, "zero_alpha_start_s", -1},
      {"zero-alpha window ends after it starts",
       [](Mission& m) { m.control.zero_alpha_end_s = m.control.zero_alpha_start_s; },
       Status::kZeroAlphaWindowInvalid, 22, 1, "zero_alpha_end_s", -1},
      {"nose radius >= 0", [](Mission& m) { m.misc.nose_radius_ft = -1.0; },
       Status::kMiscellaneousDataOutOfRange, 17, 0, "nose_radius_ft", -1},
      {"gyro uncage >= 0", [](Mission& m) { m.misc.gyro_uncage_s_before_launch = -1.0; },
       Status::kMiscellaneousDataOutOfRange, 17, 0, "gyro_uncage_s_before_launch", -1},
      {"payload weighting > 0", [](Mission& m) { m.misc.payload_weighting_factor = 0.0; },
       Status::kMiscellaneousDataOutOfRange, 17, 0, "payload_weighting_factor", -1},
      {"coast change limit >= 0", [](Mission& m) { m.misc.coast_change_limit_s = -1.0; },
       Status::kMiscellaneousDataOutOfRange, 17, 0, "coast_change_limit_s", -1},
      {"minimum coast >= 0", [](Mission& m) { m.misc.minimum_coast_s = -1.0; },
       Status::kMiscellaneousDataOutOfRange, 17, 0, "minimum_coast_s", -1},
      {"stage-4 theta within a turn", [](Mission& m) { m.misc.stage4_theta_rad = 7.0; },
       Status::kMiscellaneousDataOutOfRange, 17, 0, "stage4_theta_rad", -1},
      {"initial improvement finite", [](Mission& m) { m.convergence.initial_payoff_improvement = kNaN; },
       Status::kValueNotFinite, 28, 0, "initial_payoff_improvement", -1},
      {"stop improvement finite", [](Mission& m) { m.convergence.stop_improvement = kNaN; },
       Status::kValueNotFinite, 28, 0, "stop_improvement", -1},
      {"initial improvement >= 0", [](Mission& m) { m.convergence.initial_payoff_improvement = -1.0; },
       Status::kConvergenceDataOutOfRange, 28, 0, "initial_payoff_improvement", -1},
      {"stop improvement >= 0", [](Mission& m) { m.convergence.stop_improvement = -1.0; },
       Status::kConvergenceDataOutOfRange, 28, 0, "stop_improvement", -1},
      {"pitch program given", [](Mission& m) { m.pitch_program_rad.clear(); }, Status::kTableEmpty, 40, 0,
       "pitch_program_rad", -1},
      {"pitch program finite", [](Mission& m) { m.pitch_program_rad.set_y(1, kNaN); },
       Status::kValueNotFinite, 40, 0, "pitch_program_rad", 1},
  };
  expect_rejections(rows, static_cast<int>(std::size(rows)), validate_mission);
}

// Data blocks 8, 19, 29 (constraints), 6, 27 (adjustable parameters), 18, 26 (linearization).
TEST(Sec22DataBlocks, ConstraintAdjustableAndSegmentRejectionsNameTheEntry) {
  static const Rejection rows[] = {
      {"a payoff at least", [](Mission& m) { m.constraints.count = 0; }, Status::kNoPayoffConstraint, 8, 0,
       "count", -1},
      {"desired values finite", [](Mission& m) { m.constraints.desired[2] = kNaN; }, Status::kValueNotFinite,
       19, 0, "desired", 2},
      {"optimization deadband finite", [](Mission& m) { m.constraints.deadband_optimization[5] = kNaN; },
       Status::kValueNotFinite, 29, 0, "deadband_optimization", 6},
      {"linearization deadband finite", [](Mission& m) { m.constraints.deadband_linearization[5] = kNaN; },
       Status::kValueNotFinite, 29, 0, "deadband_linearization", 6},
      {"heating code 14 only after the list", [](Mission& m) { m.constraints.codes[2] = 14; },
       Status::kUnknownConstraintCode, 8, 0, "codes", 2},
      {"code 103 unknown", [](Mission& m) { m.constraints.codes[2] = 103; }, Status::kUnknownConstraintCode,
       8, 0, "codes", 2},
      {"payload only as the payoff", [](Mission& m) { m.constraints.codes[3] = 0; },
       Status::kPayloadCodeNotFirst, 8, 0, "codes", 3},
      {"each code once", [](Mission& m) { m.constraints.codes[3] = 2; }, Status::kDuplicateConstraintCode, 8,
       0, "codes", 3},
      {"payoff 0 is code 0", [](Mission& m) { m.constraints.codes[0] = 1; }, Status::kPayoffCodeMismatch, 8,
       0, "codes", 0},
      {"payoff 1 is code 1 or 5", [](Mission& m) { m.options.ip[1] = 1; }, Status::kPayoffCodeMismatch, 8, 0,
       "codes", 0},
      {"payoff 2 is code 7",
       [](Mission& m) {
         m.options.ip[1] = 2;
         m.constraints.codes[0] = 5;
       },
       Status::kPayoffCodeMismatch, 8, 0, "codes", 0},
      {"IP(2) = 1 lists code 14", [](Mission& m) { m.options.ip[2] = 1; }, Status::kHeatingCodeMismatch, 8, 0,
       "codes", 4},
      {"code 14 listed only with IP(2) = 1", [](Mission& m) { m.constraints.codes[4] = 14; },
       Status::kHeatingCodeMismatch, 8, 0, "codes", 4},
      {"heating leaves room: 12 counted at most",
       [](Mission& m) {
         m.options.ip[2] = 1;
         m.constraints.count = kMaxConstraints;
         fill_constraint_list(&m.constraints);
         m.constraints.codes[kMaxConstraints] = 14;
       },
       Status::kTooManyConstraints, 8, 0, "count", -1},
      {"q-bar alpha leaves room",
       [](Mission& m) {
         m.options.qbar_alpha_limit_lbf_rad_ft2 = 1000.0;
         m.constraints.count = kMaxConstraints;
         fill_constraint_list(&m.constraints);
       },
       Status::kTooManyConstraints, 8, 0, "count", -1},
      {"fitted linearization deadband > 0", [](Mission& m) { m.constraints.deadband_linearization[0] = 0.0; },
       Status::kDeadbandNotPositive, 29, 0, "deadband_linearization", 1},
      {"adjustable count >= 0", [](Mission& m) { m.adjustable.count = -1; }, Status::kNegativeCount, 6, 0,
       "count", -1},
      {"adjustable weights finite", [](Mission& m) { m.adjustable.weights[7] = kNaN; },
       Status::kValueNotFinite, 27, 0, "weights", 7},
      {"adjustable codes 1-11", [](Mission& m) { m.adjustable.codes[1] = 12; },
       Status::kUnknownAdjustableParameterCode, 6, 0, "codes", 1},
      {"adjustable codes once", [](Mission& m) { m.adjustable.codes[1] = 1; },
       Status::kDuplicateAdjustableParameterCode, 6, 0, "codes", 1},
      {"stage-4 attitude needs IP(9) = 1", [](Mission& m) { m.options.ip[9] = 2; },
       Status::kAdjustableAttitudeNotSpun, 6, 4, "codes", 0},
      {"stage-5 attitude needs stage 5", [](Mission& m) { m.adjustable.codes[0] = 8; },
       Status::kAdjustableAttitudeNotSpun, 6, 5, "codes", 0},
      {"segment count >= 0", [](Mission& m) { m.linearization.segment_count = -1; }, Status::kNegativeCount,
       18, 0, "segment_count", -1},
      {"coded times finite", [](Mission& m) { m.linearization.boundaries[12].time_from_ignition_s = kNaN; },
       Status::kValueNotFinite, 18, 0, "boundaries", 12},
      {"segment weights finite", [](Mission& m) { m.linearization.segment_weights[12] = kNaN; },
       Status::kValueNotFinite, 26, 0, "segment_weights", 12},
      {"no coded time after an unused entry",
       [](Mission& m) {
         m.linearization.boundaries[11] = {4, 0.0};
       },
       Status::kCodedTimeAfterUnusedEntry, 18, 4, "boundaries", 11},
      {"coded time of stage 6 is no stage",
       [](Mission& m) {
         m.linearization.boundaries[10] = {6, 50.0};
       },
       Status::kCodedTimeStageInvalid, 18, 0, "boundaries", 10},
      {"coded time of a stage not flown",
       [](Mission& m) {
         m.linearization.boundaries[10] = {5, 10.0};
       },
       Status::kCodedTimeStageInvalid, 18, 0, "boundaries", 10},
      {"coded times increasing",
       [](Mission& m) {
         m.linearization.boundaries[2] = {1, 3.0};
       },
       Status::kTableNotMonotonic, 18, 1, "boundaries", 2},
      {"linearization needs segments",
       [](Mission& m) {
         m.linearization.segment_count = 0;
         for (SegmentBoundary& b : m.linearization.boundaries) b = SegmentBoundary{};
       },
       Status::kLinearizationWithoutSegments, 18, 0, "segment_count", -1},
      {"segment count = coded times - 1", [](Mission& m) { m.linearization.segment_count = 8; },
       Status::kSegmentCountMismatch, 18, 0, "segment_count", -1},
      {"segment weights > 0", [](Mission& m) { m.linearization.segment_weights[3] = 0.0; },
       Status::kWeightingFactorNotPositive, 26, 0, "segment_weights", 3},
  };
  expect_rejections(rows, static_cast<int>(std::size(rows)), validate_mission);
}

// Data blocks 33-37 (6D), through validate_body_dynamics.
TEST(Sec22DataBlocks, BodyDynamicsRejectionsNameTheirWordAndTable) {
  static const Rejection rows[] = {
      {"stage-2 position gain finite", [](Mission& m) { m.body_dynamics.position_gain[1] = kNaN; },
       Status::kValueNotFinite, 33, 0, "position_gain", 1},
      {"stage-2 rate gain finite", [](Mission& m) { m.body_dynamics.rate_gain_s[1] = kNaN; },
       Status::kValueNotFinite, 33, 0, "rate_gain_s", 1},
      {"stage-2 control station finite", [](Mission& m) { m.body_dynamics.control_station_ft[1] = kNaN; },
       Status::kValueNotFinite, 33, 0, "control_station_ft", 1},
      {"jet vanes finite", [](Mission& m) { m.body_dynamics.jet_vane_effectiveness_per_rad = kNaN; },
       Status::kValueNotFinite, 33, 0, "jet_vane_effectiveness_per_rad", -1},
      {"moment reference finite", [](Mission& m) { m.body_dynamics.moment_reference_station_ft = kNaN; },
       Status::kValueNotFinite, 33, 0, "moment_reference_station_ft", -1},
      {"reference length finite", [](Mission& m) { m.body_dynamics.reference_length_ft = kNaN; },
       Status::kValueNotFinite, 33, 0, "reference_length_ft", -1},
      {"reference area finite", [](Mission& m) { m.body_dynamics.reference_area_ft2 = kNaN; },
       Status::kValueNotFinite, 33, 0, "reference_area_ft2", -1},
      {"surfaces per plane finite", [](Mission& m) { m.body_dynamics.control_surfaces_per_plane = kNaN; },
       Status::kValueNotFinite, 33, 0, "control_surfaces_per_plane", -1},
      {"rate gain >= 0", [](Mission& m) { m.body_dynamics.rate_gain_s[0] = -0.1; },
       Status::kBodyDynamicsValueOutOfRange, 33, 1, "rate_gain_s", 0},
      {"jet vanes >= 0", [](Mission& m) { m.body_dynamics.jet_vane_effectiveness_per_rad = -0.1; },
       Status::kBodyDynamicsValueOutOfRange, 33, 0, "jet_vane_effectiveness_per_rad", -1},
      {"reference length > 0", [](Mission& m) { m.body_dynamics.reference_length_ft = 0.0; },
       Status::kBodyDynamicsValueOutOfRange, 33, 0, "reference_length_ft", -1},
      {"reference area > 0", [](Mission& m) { m.body_dynamics.reference_area_ft2 = 0.0; },
       Status::kBodyDynamicsValueOutOfRange, 33, 0, "reference_area_ft2", -1},
      {"surfaces per plane > 0", [](Mission& m) { m.body_dynamics.control_surfaces_per_plane = 0.0; },
       Status::kBodyDynamicsValueOutOfRange, 33, 0, "control_surfaces_per_plane", -1},
      {"block 34 given", [](Mission& m) { m.body_dynamics.fin_normal_force_per_rad.clear(); },
       Status::kBodyDynamicsDataMissing, 34, 0, "fin_normal_force_per_rad", -1},
      {"block 36 given", [](Mission& m) { m.body_dynamics.fin_pitching_moment_per_rad.clear(); },
       Status::kBodyDynamicsDataMissing, 36, 0, "fin_pitching_moment_per_rad", -1},
      {"block 37 stage 1 given", [](Mission& m) { m.body_dynamics.cg_station_ft[0].clear(); },
       Status::kBodyDynamicsDataMissing, 37, 1, "cg_station_ft", -1},
      {"block 37 stage 2 finite", [](Mission& m) { m.body_dynamics.cg_station_ft[1].set_y(1, kNaN); },
       Status::kValueNotFinite, 37, 2, "cg_station_ft", 1},
  };
  expect_rejections(rows, static_cast<int>(std::size(rows)), validate_body_dynamics);
}

}  // namespace
}  // namespace tolip
