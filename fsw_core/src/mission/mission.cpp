// validate_mission() and vehicle_weight_lb() (mission.hpp).
//
// validate_mission() is the boundary check of a case (manual Sec. 22, data blocks 1-40): the
// ground tools call it after filling a Mission from a deck, and the core trusts a Mission that
// passed. It returns the first fault found, in data-block order, and names it in *fault with the
// manual's data block, the stage code and the Mission field (a string literal). No heap, no
// exceptions.
#include "tolip/mission/mission.hpp"

#include <cmath>

namespace tolip {
namespace {

// Data block 5: the only order stages may be flown in.
constexpr int kCanonicalSequence[kMaxStages] = {1, 6, 2, 7, 3, 8, 4, 9, 5, 10};

// Tolerance on the 90-degree flight-path angle of block 21 (deck conversions round in the last bit).
constexpr double kAngleTolerance_rad = 1.0e-9;

struct Check {
  MissionFault* fault;

  Status fail(Status status, int data_block, int stage_code, const char* field) const {
    if (fault != nullptr) {
      fault->data_block = data_block;
      fault->stage_code = stage_code;
      fault->field = field;
    }
    return status;
  }
};

bool finite(double value) { return std::isfinite(value); }

bool all_finite(const double* values, int count) {
  for (int i = 0; i < count; ++i) {
    if (!finite(values[i])) return false;
  }
  return true;
}

// Every stored point finite and the abscissae strictly increasing (what finalize() checks).
template <int N>
Status table_shape(const Table<N>& table) {
  for (int i = 0; i < table.size(); ++i) {
    if (!finite(table.x(i)) || !finite(table.y(i))) return Status::kValueNotFinite;
    if (i > 0 && !(table.x(i) > table.x(i - 1))) return Status::kTableNotMonotonic;
  }
  return Status::kOk;
}

// A table that may be empty; when it has points it must be well formed and finalized.
template <int N>
Status optional_table(const Table<N>& table) {
  if (table.empty()) return Status::kOk;
  const Status shape = table_shape(table);
  if (!ok(shape)) return shape;
  return table.finalized() ? Status::kOk : Status::kTableNotMonotonic;
}

// Data block 8 codes: 0-14 terminal (14 = heating), X5-X9 at the end of stage X = 1-9,
// 100-102 the hyperbolic-asymptote constraints of Addendum H.
bool known_constraint_code(int code) {
  if (code >= 0 && code <= 14) return true;
  if (code >= 15 && code <= 99) {
    const int parameter = code % 10;
    return parameter >= 5 && parameter <= 9;
  }
  return code >= 100 && code <= 102;
}

bool coast_adjustable_code(int code) {
  return code == 3 || code == 4 || code == 5 || code == 10 || code == 11;
}

int position_in_sequence(const StageSequence& sequence, int code) {
  for (int k = 0; k < sequence.count; ++k) {
    if (sequence.codes[k] == code) return k;
  }
  return -1;
}

int last_powered_stage(const StageSequence& sequence) {
  int last = 0;
  for (int k = 0; k < sequence.count; ++k) {
    if (is_powered_stage(sequence.codes[k])) last = sequence.codes[k];
  }
  return last;
}

// ---- data block 4 -------------------------------------------------------------------------------
Status check_options(const Options& options, const Check& check) {
  const int* ip = options.ip;
  auto in_range = [](int value, int low, int high) { return value >= low && value <= high; };
  // Options the manual marks "not used" must stay 0.
  const int unused[] = {4, 5, 8, 14, 16, 18, 19, 20};
  for (int n : unused) {
    if (ip[n] != 0) return check.fail(Status::kValueOutOfRange, 4, 0, "ip");
  }
  const int binary[] = {2, 3, 7, 11, 12, 13, 15, 17, 21, 22, 23, 24};
  for (int n : binary) {
    if (!in_range(ip[n], 0, 1)) return check.fail(Status::kValueOutOfRange, 4, 0, "ip");
  }
  if (!in_range(ip[1], 0, 2) || !in_range(ip[6], 0, 2) || !in_range(ip[9], 0, 3) ||
      !in_range(ip[10], 0, 2)) {
    return check.fail(Status::kValueOutOfRange, 4, 0, "ip");
  }
  // IP(6) = 1 (6D after linearization) requires IP(7) = 1.
  if (ip[6] == 1 && ip[7] != 1) return check.fail(Status::kValueOutOfRange, 4, 0, "ip");
  return Status::kOk;
}

// ---- data block 5 -------------------------------------------------------------------------------
Status check_sequence(const Vehicle& vehicle, const Check& check) {
  const StageSequence& sequence = vehicle.sequence;
  if (sequence.count < 1 || sequence.count > kMaxStages) {
    return check.fail(Status::kStageSequenceInvalid, 5, 0, "sequence");
  }
  for (int k = 0; k < sequence.count; ++k) {
    const int code = sequence.codes[k];
    if (!is_powered_stage(code) && !is_coast_stage(code)) {
      return check.fail(Status::kUnknownStageCode, 5, code, "sequence");
    }
    if (code != kCanonicalSequence[k]) {
      return check.fail(Status::kStageSequenceInvalid, 5, code, "sequence");
    }
  }
  for (int code = 1; code <= kMaxStages; ++code) {
    const bool listed = position_in_sequence(sequence, code) >= 0;
    if (vehicle.stages[stage_index(code)].in_sequence != listed) {
      return check.fail(Status::kStageSequenceInvalid, 5, code, "in_sequence");
    }
  }
  return Status::kOk;
}

// ---- data block 10 ------------------------------------------------------------------------------
Status check_constants(const Constants& c, const Check& check) {
  const double values[] = {c.earth_rotation_rate_rad_s, c.gravitational_parameter_ft3_s2,
                           c.earth_equatorial_radius_ft, c.gas_constant_ft2_s2_R,
                           c.g0_ft_s2, c.sea_level_pressure_lbf_ft2, c.haero_ft,
                           c.lines_per_page, c.deg_to_rad_as_printed, c.time_epsilon_s,
                           c.j2, c.inverse_flattening, c.ct1_13};
  if (!all_finite(values, static_cast<int>(sizeof(values) / sizeof(values[0])))) {
    return check.fail(Status::kValueNotFinite, 10, 0, "constants");
  }
  if (!(c.gravitational_parameter_ft3_s2 > 0.0)) {
    return check.fail(Status::kValueOutOfRange, 10, 0, "gravitational_parameter_ft3_s2");
  }
  if (!(c.earth_equatorial_radius_ft > 0.0)) {
    return check.fail(Status::kValueOutOfRange, 10, 0, "earth_equatorial_radius_ft");
  }
  if (!(c.gas_constant_ft2_s2_R > 0.0)) {
    return check.fail(Status::kValueOutOfRange, 10, 0, "gas_constant_ft2_s2_R");
  }
  if (!(c.g0_ft_s2 > 0.0)) return check.fail(Status::kValueOutOfRange, 10, 0, "g0_ft_s2");
  if (c.sea_level_pressure_lbf_ft2 < 0.0) {
    return check.fail(Status::kValueOutOfRange, 10, 0, "sea_level_pressure_lbf_ft2");
  }
  if (c.haero_ft < 0.0) return check.fail(Status::kValueOutOfRange, 10, 0, "haero_ft");
  if (!(c.time_epsilon_s > 0.0)) return check.fail(Status::kValueOutOfRange, 10, 0, "time_epsilon_s");
  if (!(c.inverse_flattening > 1.0)) {
    return check.fail(Status::kValueOutOfRange, 10, 0, "inverse_flattening");
  }
  return Status::kOk;
}

// ---- data blocks 11-14 --------------------------------------------------------------------------
Status check_atmosphere(const AtmosphereTable& a, const Check& check) {
  if (!all_finite(a.base_geopotential_altitude_ft, kAtmosphereLayers)) {
    return check.fail(Status::kValueNotFinite, 11, 0, "base_geopotential_altitude_ft");
  }
  if (!all_finite(a.base_molecular_temperature_R, kAtmosphereLayers)) {
    return check.fail(Status::kValueNotFinite, 12, 0, "base_molecular_temperature_R");
  }
  if (!all_finite(a.lapse_rate_R_per_ft, kAtmosphereLayers)) {
    return check.fail(Status::kValueNotFinite, 13, 0, "lapse_rate_R_per_ft");
  }
  if (!all_finite(a.base_density_slug_ft3, kAtmosphereLayers)) {
    return check.fail(Status::kValueNotFinite, 14, 0, "base_density_slug_ft3");
  }
  if (a.base_geopotential_altitude_ft[0] != 0.0) {
    return check.fail(Status::kAtmosphereTableInvalid, 11, 0, "base_geopotential_altitude_ft");
  }
  for (int i = 1; i < kAtmosphereLayers; ++i) {
    if (!(a.base_geopotential_altitude_ft[i] > a.base_geopotential_altitude_ft[i - 1])) {
      return check.fail(Status::kAtmosphereTableInvalid, 11, 0, "base_geopotential_altitude_ft");
    }
  }
  for (int i = 0; i < kAtmosphereLayers; ++i) {
    if (!(a.base_molecular_temperature_R[i] > 0.0)) {
      return check.fail(Status::kAtmosphereTableInvalid, 12, 0, "base_molecular_temperature_R");
    }
    if (!(a.base_density_slug_ft3[i] > 0.0)) {
      return check.fail(Status::kAtmosphereTableInvalid, 14, 0, "base_density_slug_ft3");
    }
  }
  return Status::kOk;
}

// ---- data blocks 16, 30, 31, 38, 39 for one stage ------------------------------------------------
Status check_stage(const StageData& stage, int code, double time_epsilon_s, const Check& check) {
  const double scalars[] = {stage.duration_s, stage.jettison_weight_lb, stage.reference_area_ft2,
                            stage.nozzle_exit_area_ft2};
  if (!finite(scalars[0])) return check.fail(Status::kValueNotFinite, 16, code, "duration_s");
  if (!all_finite(scalars + 1, 3)) return check.fail(Status::kValueNotFinite, 39, code, "stage_data");

  if (!(stage.duration_s > 0.0)) return check.fail(Status::kNonPositiveDuration, 16, code, "duration_s");
  if (stage.integration_steps <= 0) {
    return check.fail(Status::kNonPositiveStepCount, 16, code, "integration_steps");
  }
  if (stage.jettison_weight_lb < 0.0) {
    return check.fail(Status::kNegativeWeight, 39, code, "jettison_weight_lb");
  }
  if (stage.reference_area_ft2 < 0.0) {
    return check.fail(Status::kValueOutOfRange, 39, code, "reference_area_ft2");
  }
  if (stage.nozzle_exit_area_ft2 < 0.0) {
    return check.fail(Status::kValueOutOfRange, 39, code, "nozzle_exit_area_ft2");
  }

  Status status = optional_table(stage.drag_coefficient);
  if (!ok(status)) return check.fail(status, 31, code, "drag_coefficient");
  if (!stage.drag_coefficient.empty() && !(stage.reference_area_ft2 > 0.0)) {
    return check.fail(Status::kValueOutOfRange, 39, code, "reference_area_ft2");
  }

  if (is_coast_stage(code)) {
    if (stage.integration_steps > kMaxCoastSteps) {
      return check.fail(Status::kTooManyCoastSteps, 16, code, "integration_steps");
    }
    if (!stage.vacuum_thrust_lbf.empty()) {
      return check.fail(Status::kValueOutOfRange, 30, code, "vacuum_thrust_lbf");
    }
    if (stage.nozzle_exit_area_ft2 != 0.0) {
      return check.fail(Status::kValueOutOfRange, 39, code, "nozzle_exit_area_ft2");
    }
    if (!stage.consumable_weight_lb.empty()) {
      return check.fail(Status::kValueOutOfRange, 38, code, "consumable_weight_lb");
    }
    return Status::kOk;
  }

  // Powered stage: block 30 thrust and block 38 consumable weight, both finalized.
  const ThrustTable& thrust = stage.vacuum_thrust_lbf;
  const WeightTable& weight = stage.consumable_weight_lb;
  if (thrust.empty()) return check.fail(Status::kMissingThrustTable, 30, code, "vacuum_thrust_lbf");
  status = table_shape(thrust);
  if (!ok(status)) return check.fail(status, 30, code, "vacuum_thrust_lbf");
  if (!thrust.finalized()) return check.fail(Status::kMissingThrustTable, 30, code, "vacuum_thrust_lbf");
  if (weight.empty()) return check.fail(Status::kMissingWeightTable, 38, code, "consumable_weight_lb");
  status = table_shape(weight);
  if (!ok(status)) return check.fail(status, 38, code, "consumable_weight_lb");
  if (!weight.finalized()) {
    return check.fail(Status::kMissingWeightTable, 38, code, "consumable_weight_lb");
  }
  if (thrust.first_x() < 0.0) return check.fail(Status::kValueOutOfRange, 30, code, "vacuum_thrust_lbf");
  if (weight.first_x() < 0.0) {
    return check.fail(Status::kValueOutOfRange, 38, code, "consumable_weight_lb");
  }
  for (int i = 0; i < thrust.size(); ++i) {
    if (thrust.y(i) < 0.0) return check.fail(Status::kValueOutOfRange, 30, code, "vacuum_thrust_lbf");
  }
  for (int i = 0; i < weight.size(); ++i) {
    if (weight.y(i) < 0.0) return check.fail(Status::kNegativeWeight, 38, code, "consumable_weight_lb");
  }
  if (std::fabs(thrust.last_x() - weight.last_x()) > time_epsilon_s) {
    return check.fail(Status::kThrustWeightTimesDiffer, 38, code, "consumable_weight_lb");
  }
  if (std::fabs(stage.duration_s - thrust.last_x()) > time_epsilon_s) {
    return check.fail(Status::kStageDurationMismatch, 16, code, "duration_s");
  }
  return Status::kOk;
}

Status check_vehicle(const Vehicle& vehicle, const Constants& constants, const Check& check) {
  const StageSequence& sequence = vehicle.sequence;
  for (int k = 0; k < sequence.count; ++k) {
    const int code = sequence.codes[k];
    const Status status = check_stage(vehicle.stages[stage_index(code)], code,
                                      constants.time_epsilon_s, check);
    if (!ok(status)) return status;
  }

  // Block 16 step counts.
  const StageData& stage1 = vehicle.stages[stage_index(1)];
  if (stage1.integration_steps < kMinStage1Steps) {
    return check.fail(Status::kTooFewStage1Steps, 16, 1, "integration_steps");
  }
  int powered_steps = 0;
  for (int code = 1; code <= kMaxPoweredStages; ++code) {
    const StageData& stage = vehicle.stages[stage_index(code)];
    if (stage.in_sequence) powered_steps += stage.integration_steps;
  }
  if (powered_steps > kMaxPoweredSteps) {
    return check.fail(Status::kTooManyPoweredSteps, 16, 0, "integration_steps");
  }
  const StageData& coast6 = vehicle.stages[stage_index(6)];
  const int with_coast6 = powered_steps + (coast6.in_sequence ? coast6.integration_steps : 0);
  if (with_coast6 > kMaxPoweredStepsWithFollowingCoast) {
    return check.fail(Status::kTooManyPoweredStepsWithFollowingCoast, 16, 6, "integration_steps");
  }

  // Blocks 30 and 38: the 1966 program pooled 120 thrust and 120 weight points over all stages.
  int thrust_points = 0;
  int weight_points = 0;
  for (int i = 0; i < kMaxStages; ++i) {
    thrust_points += vehicle.stages[i].vacuum_thrust_lbf.size();
    weight_points += vehicle.stages[i].consumable_weight_lb.size();
  }
  if (thrust_points > kMaxThrustPoints) {
    return check.fail(Status::kTooManyThrustPointsInAllStages, 30, 0, "vacuum_thrust_lbf");
  }
  if (weight_points > kMaxWeightPoints) {
    return check.fail(Status::kTooManyWeightPointsInAllStages, 38, 0, "consumable_weight_lb");
  }

  // Block 32.
  const Status lift = optional_table(vehicle.lift_curve_slope_per_rad);
  if (!ok(lift)) return check.fail(lift, 32, 0, "lift_curve_slope_per_rad");
  for (int i = 0; i < kMaxStages; ++i) {
    if (vehicle.stages[i].in_sequence && vehicle.stages[i].uses_lift_table) {
      if (vehicle.lift_curve_slope_per_rad.empty()) {
        return check.fail(Status::kTableEmpty, 32, i + 1, "lift_curve_slope_per_rad");
      }
      if (!(vehicle.stages[i].reference_area_ft2 > 0.0)) {
        return check.fail(Status::kValueOutOfRange, 39, i + 1, "reference_area_ft2");
      }
    }
  }

  // The payload rides in the jettison weight of the last powered stage (Sec. 14).
  const int last_powered = last_powered_stage(sequence);
  if (!finite(vehicle.payload_lb)) return check.fail(Status::kValueNotFinite, 39, last_powered, "payload_lb");
  if (vehicle.payload_lb < 0.0) return check.fail(Status::kNegativeWeight, 39, last_powered, "payload_lb");
  return Status::kOk;
}

// ---- data blocks 20, 21 -------------------------------------------------------------------------
Status check_launch(const LaunchConditions& l, const Vehicle& vehicle, const Check& check) {
  if (!finite(l.liftoff_duration_s)) return check.fail(Status::kValueNotFinite, 20, 0, "liftoff_duration_s");
  if (!finite(l.launch_space_age_date_days)) {
    return check.fail(Status::kValueNotFinite, 20, 0, "launch_space_age_date_days");
  }
  if (!finite(l.altitude_ft)) return check.fail(Status::kValueNotFinite, 21, 0, "altitude_ft");
  if (!finite(l.longitude_rad)) return check.fail(Status::kValueNotFinite, 21, 0, "longitude_rad");
  if (!finite(l.geocentric_latitude_rad)) {
    return check.fail(Status::kValueNotFinite, 21, 0, "geocentric_latitude_rad");
  }
  if (!finite(l.velocity_ft_s)) return check.fail(Status::kValueNotFinite, 21, 0, "velocity_ft_s");
  if (!finite(l.azimuth_rad)) return check.fail(Status::kValueNotFinite, 21, 0, "azimuth_rad");
  if (!finite(l.flight_path_angle_rad)) {
    return check.fail(Status::kValueNotFinite, 21, 0, "flight_path_angle_rad");
  }
  if (!finite(l.heading_hold_until_s)) {
    return check.fail(Status::kValueNotFinite, 21, 0, "heading_hold_until_s");
  }

  if (l.liftoff_duration_s < 0.0) return check.fail(Status::kValueOutOfRange, 20, 0, "liftoff_duration_s");
  const StageData& stage1 = vehicle.stages[stage_index(1)];
  if (!(l.liftoff_duration_s < stage1.duration_s)) {
    return check.fail(Status::kLiftoffLongerThanStage1, 20, 1, "liftoff_duration_s");
  }
  if (std::fabs(l.geocentric_latitude_rad) > 0.5 * kPi) {
    return check.fail(Status::kValueOutOfRange, 21, 0, "geocentric_latitude_rad");
  }
  if (l.velocity_ft_s != 0.0) return check.fail(Status::kInitialConditionsInvalid, 21, 0, "velocity_ft_s");
  if (std::fabs(l.flight_path_angle_rad - 0.5 * kPi) > kAngleTolerance_rad) {
    return check.fail(Status::kInitialConditionsInvalid, 21, 0, "flight_path_angle_rad");
  }
  if (l.heading_hold_until_s < 0.0) {
    return check.fail(Status::kValueOutOfRange, 21, 0, "heading_hold_until_s");
  }
  return Status::kOk;
}

// ---- data block 22 ------------------------------------------------------------------------------
Status check_control(const ControlConstraints& c, const Options& options, const Vehicle& vehicle,
                     double time_epsilon_s, const Check& check) {
  const double values[] = {c.zero_alpha_start_s, c.zero_alpha_end_s, c.max_pitch_rate_rad_s,
                           c.min_pitch_rate_rad_s, c.min_pitch_rate_change_rad_s};
  if (!all_finite(values, 5)) return check.fail(Status::kValueNotFinite, 22, 0, "control");
  if (c.max_pitch_rate_rad_s < 0.0) return check.fail(Status::kValueOutOfRange, 22, 0, "max_pitch_rate_rad_s");
  if (c.min_pitch_rate_rad_s < 0.0) return check.fail(Status::kValueOutOfRange, 22, 0, "min_pitch_rate_rad_s");
  if (c.min_pitch_rate_change_rad_s < 0.0) {
    return check.fail(Status::kValueOutOfRange, 22, 0, "min_pitch_rate_change_rad_s");
  }
  if (options.zero_alpha_window()) {
    // IP(11): the alpha = 0 window lies inside stage 1 (times from launch).
    if (c.zero_alpha_start_s < 0.0) return check.fail(Status::kValueOutOfRange, 22, 0, "zero_alpha_start_s");
    if (!(c.zero_alpha_end_s > c.zero_alpha_start_s)) {
      return check.fail(Status::kValueOutOfRange, 22, 0, "zero_alpha_end_s");
    }
    if (c.zero_alpha_end_s > vehicle.stages[stage_index(1)].duration_s + time_epsilon_s) {
      return check.fail(Status::kValueOutOfRange, 22, 1, "zero_alpha_end_s");
    }
  }
  return Status::kOk;
}

// ---- data block 17 ------------------------------------------------------------------------------
Status check_misc(const MiscellaneousData& m, const AdjustableParameters& adjustable,
                  const Check& check) {
  const double values[] = {m.stage4_theta_rad, m.stage4_chi_rad, m.nose_radius_ft,
                           m.gyro_uncage_s_before_launch, m.stage5_theta_rad, m.stage5_chi_rad,
                           m.payload_weighting_factor, m.coast_change_limit_s, m.minimum_coast_s};
  if (!all_finite(values, 9)) return check.fail(Status::kValueNotFinite, 17, 0, "misc");
  if (m.nose_radius_ft < 0.0) return check.fail(Status::kValueOutOfRange, 17, 0, "nose_radius_ft");
  if (m.gyro_uncage_s_before_launch < 0.0) {
    return check.fail(Status::kValueOutOfRange, 17, 0, "gyro_uncage_s_before_launch");
  }
  if (!(m.payload_weighting_factor > 0.0)) {
    return check.fail(Status::kValueOutOfRange, 17, 0, "payload_weighting_factor");
  }
  if (m.coast_change_limit_s < 0.0) return check.fail(Status::kValueOutOfRange, 17, 0, "coast_change_limit_s");
  if (m.minimum_coast_s < 0.0) return check.fail(Status::kValueOutOfRange, 17, 0, "minimum_coast_s");
  // DA2(16) "must be input if any coast is used as an adjustable parameter".
  for (int i = 0; i < adjustable.count && i < kMaxAdjustableParameters; ++i) {
    if (coast_adjustable_code(adjustable.codes[i]) && !(m.coast_change_limit_s > 0.0)) {
      return check.fail(Status::kValueOutOfRange, 17, 0, "coast_change_limit_s");
    }
  }
  return Status::kOk;
}

// ---- data blocks 8, 19, 29 ----------------------------------------------------------------------
Status check_constraints(const ConstraintList& c, const Options& options, const Check& check) {
  if (c.count > kMaxConstraints) return check.fail(Status::kTooManyConstraints, 8, 0, "count");
  if (c.count < 1) return check.fail(Status::kValueOutOfRange, 8, 0, "count");
  if (!all_finite(c.desired, kMaxConstraints + 1)) return check.fail(Status::kValueNotFinite, 19, 0, "desired");
  if (!all_finite(c.deadband_optimization, kMaxConstraints) ||
      !all_finite(c.deadband_linearization, kMaxConstraints)) {
    return check.fail(Status::kValueNotFinite, 29, 0, "deadband");
  }
  for (int i = 0; i < c.count; ++i) {
    const int code = c.codes[i];
    if (!known_constraint_code(code) || code == 14) return check.fail(Status::kValueOutOfRange, 8, 0, "codes");
    if (code == 0 && i != 0) return check.fail(Status::kValueOutOfRange, 8, 0, "codes");
    for (int j = 0; j < i; ++j) {
      if (c.codes[j] == code) return check.fail(Status::kValueOutOfRange, 8, 0, "codes");
    }
  }
  // The payoff first, consistent with IP(1): payload (0), velocity (1 or 5), altitude (7).
  const int payoff = c.codes[0];
  const bool payoff_ok = (options.payoff() == 0 && payoff == 0) ||
                         (options.payoff() == 1 && (payoff == 1 || payoff == 5)) ||
                         (options.payoff() == 2 && payoff == 7);
  if (!payoff_ok) return check.fail(Status::kValueOutOfRange, 8, 0, "codes");
  // The heating code 14 follows the counted list exactly when IP(2) = 1.
  const bool heating_listed = c.count < kMaxConstraints + 1 && c.codes[c.count] == 14;
  if (options.heating_constraint() != heating_listed) {
    return check.fail(Status::kValueOutOfRange, 8, 0, "codes");
  }
  const int deadbands = c.count - 1 + (heating_listed ? 1 : 0);
  for (int i = 0; i < deadbands; ++i) {
    if (c.deadband_optimization[i] < 0.0) {
      return check.fail(Status::kValueOutOfRange, 29, 0, "deadband_optimization");
    }
    if (c.deadband_linearization[i] < 0.0) {
      return check.fail(Status::kValueOutOfRange, 29, 0, "deadband_linearization");
    }
  }
  return Status::kOk;
}

// ---- data blocks 6, 27 --------------------------------------------------------------------------
Status check_adjustable(const AdjustableParameters& a, const Vehicle& vehicle, const Check& check) {
  if (a.count > kMaxAdjustableParameters) {
    return check.fail(Status::kTooManyAdjustableParameters, 6, 0, "count");
  }
  if (a.count < 0) return check.fail(Status::kValueOutOfRange, 6, 0, "count");
  if (!all_finite(a.weights, kMaxAdjustableParameters)) {
    return check.fail(Status::kValueNotFinite, 27, 0, "weights");
  }
  for (int i = 0; i < a.count; ++i) {
    const int code = a.codes[i];
    if (code < 1 || code > 11) return check.fail(Status::kValueOutOfRange, 6, 0, "codes");
    for (int j = 0; j < i; ++j) {
      if (a.codes[j] == code) return check.fail(Status::kValueOutOfRange, 6, 0, "codes");
    }
    // A coast length (codes 5, 4, 3, 10, 11: coasts 6, 7, 8, 9, 10) needs that coast flown.
    int coast = 0;
    if (code == 5) coast = 6;
    if (code == 4) coast = 7;
    if (code == 3) coast = 8;
    if (code == 10) coast = 9;
    if (code == 11) coast = 10;
    if (coast != 0 && !vehicle.stages[stage_index(coast)].in_sequence) {
      return check.fail(Status::kValueOutOfRange, 6, coast, "codes");
    }
    if (!(a.weights[i] > 0.0)) return check.fail(Status::kValueOutOfRange, 27, 0, "weights");
  }
  return Status::kOk;
}

// ---- data blocks 18, 26 -------------------------------------------------------------------------
// TLIN: the coded times 100 n + t (n a powered stage, t seconds from its ignition) in increasing
// order, unused entries 0. Between consecutive listed powered stages the coast is one implicit
// segment, so segment_count = number of times - 1 (manual example: 103.0, 182.6, 200.0, 239.2 are
// three segments).
Status check_linearization(const LinearizationData& l, const Options& options, const Check& check) {
  if (l.segment_count > kMaxLinearSegments) {
    return check.fail(Status::kTooManyLinearSegments, 18, 0, "segment_count");
  }
  if (l.segment_count < 0) return check.fail(Status::kValueOutOfRange, 18, 0, "segment_count");
  if (!all_finite(l.coded_start_times, kMaxLinearSegments + 1)) {
    return check.fail(Status::kValueNotFinite, 18, 0, "coded_start_times");
  }
  if (!all_finite(l.segment_weights, kMaxLinearSegments)) {
    return check.fail(Status::kValueNotFinite, 26, 0, "segment_weights");
  }
  int times = 0;
  while (times < kMaxLinearSegments + 1 && l.coded_start_times[times] != 0.0) ++times;
  for (int i = times; i < kMaxLinearSegments + 1; ++i) {
    if (l.coded_start_times[i] != 0.0) return check.fail(Status::kValueOutOfRange, 18, 0, "coded_start_times");
  }
  for (int i = 0; i < times; ++i) {
    const double coded = l.coded_start_times[i];
    const double stage = std::floor(coded / 100.0);
    if (stage < 1.0 || stage > static_cast<double>(kMaxPoweredStages)) {
      return check.fail(Status::kValueOutOfRange, 18, 0, "coded_start_times");
    }
    if (i > 0 && !(coded > l.coded_start_times[i - 1])) {
      return check.fail(Status::kTableNotMonotonic, 18, 0, "coded_start_times");
    }
  }
  // IP(7) = 1 "requires input of times of beginning of each linear segment in Data Block 18".
  if (options.linearization() && l.segment_count < 1) {
    return check.fail(Status::kValueOutOfRange, 18, 0, "segment_count");
  }
  if (times != (l.segment_count > 0 ? l.segment_count + 1 : 0)) {
    return check.fail(Status::kValueOutOfRange, 18, 0, "segment_count");
  }
  for (int i = 0; i < l.segment_count; ++i) {
    if (!(l.segment_weights[i] > 0.0)) return check.fail(Status::kValueOutOfRange, 26, 0, "segment_weights");
  }
  return Status::kOk;
}

// ---- data block 28 ------------------------------------------------------------------------------
Status check_convergence(const ConvergenceData& c, const Check& check) {
  if (!finite(c.initial_payoff_improvement) || !finite(c.stop_improvement)) {
    return check.fail(Status::kValueNotFinite, 28, 0, "convergence");
  }
  if (c.initial_payoff_improvement < 0.0) {
    return check.fail(Status::kValueOutOfRange, 28, 0, "initial_payoff_improvement");
  }
  if (c.stop_improvement < 0.0) return check.fail(Status::kValueOutOfRange, 28, 0, "stop_improvement");
  if (c.max_forward_trajectories < 1) {
    return check.fail(Status::kValueOutOfRange, 28, 0, "max_forward_trajectories");
  }
  if (c.max_linearization_iterations < 0) {
    return check.fail(Status::kValueOutOfRange, 28, 0, "max_linearization_iterations");
  }
  return Status::kOk;
}

// ---- data block 9 -------------------------------------------------------------------------------
Status check_output(const OutputFrequency& o, const Check& check) {
  for (int i = 0; i < kMaxStages; ++i) {
    if (o.initial[i] < 1) return check.fail(Status::kValueOutOfRange, 9, i + 1, "initial");
    if (o.intermediate[i] < 1) return check.fail(Status::kValueOutOfRange, 9, i + 1, "intermediate");
    if (o.final_trajectory[i] < 1) return check.fail(Status::kValueOutOfRange, 9, i + 1, "final_trajectory");
  }
  return Status::kOk;
}

// ---- data blocks 33-37 (6D) --------------------------------------------------------------------
// A table a 6D run needs: given, well formed and finalized.
template <int N>
Status required_table(const Table<N>& table) {
  if (table.empty()) return Status::kBodyDynamicsDataMissing;
  const Status shape = table_shape(table);
  if (!ok(shape)) return shape;
  return table.finalized() ? Status::kOk : Status::kTableNotMonotonic;
}

Status check_body_dynamics(const Mission& mission, const Check& check) {
  const BodyDynamicsBlocks& b = mission.body_dynamics;
  if (!b.present) return check.fail(Status::kBodyDynamicsDataMissing, 33, 0, "body_dynamics");
  // Every word given must be finite (stages 2-3 are kept for the dispersion and hardover work).
  if (!all_finite(b.position_gain, kBodyDynamicsStages)) return check.fail(Status::kValueNotFinite, 33, 0, "position_gain");
  if (!all_finite(b.rate_gain_s, kBodyDynamicsStages)) return check.fail(Status::kValueNotFinite, 33, 0, "rate_gain_s");
  if (!all_finite(b.control_station_ft, kBodyDynamicsStages)) {
    return check.fail(Status::kValueNotFinite, 33, 0, "control_station_ft");
  }
  const double words[] = {b.jet_vane_effectiveness_per_rad, b.moment_reference_station_ft, b.reference_length_ft,
                          b.reference_area_ft2, b.control_surfaces_per_plane};
  const char* names[] = {"jet_vane_effectiveness_per_rad", "moment_reference_station_ft", "reference_length_ft",
                         "reference_area_ft2", "control_surfaces_per_plane"};
  for (int i = 0; i < 5; ++i) {
    if (!finite(words[i])) return check.fail(Status::kValueNotFinite, 33, 0, names[i]);
  }
  // Stage 1 (and the coast after it) is what a 6D run flies: a positive position gain (eq. 7-6
  // divides by K_theta M_delta - M_alpha, and K_theta = 0 means no autopilot), a rate gain >= 0.
  if (!(b.position_gain[0] > 0.0)) return check.fail(Status::kValueOutOfRange, 33, 1, "position_gain");
  if (!(b.rate_gain_s[0] >= 0.0)) return check.fail(Status::kValueOutOfRange, 33, 1, "rate_gain_s");
  if (!(b.jet_vane_effectiveness_per_rad >= 0.0)) {
    return check.fail(Status::kValueOutOfRange, 33, 0, "jet_vane_effectiveness_per_rad");
  }
  if (!(b.reference_length_ft > 0.0)) return check.fail(Status::kValueOutOfRange, 33, 0, "reference_length_ft");
  if (!(b.reference_area_ft2 > 0.0)) return check.fail(Status::kValueOutOfRange, 33, 0, "reference_area_ft2");
  if (!(b.control_surfaces_per_plane > 0.0)) {
    return check.fail(Status::kValueOutOfRange, 33, 0, "control_surfaces_per_plane");
  }
  Status status = required_table(b.fin_normal_force_per_rad);
  if (!ok(status)) return check.fail(status, 34, 0, "fin_normal_force_per_rad");
  status = required_table(b.pitching_moment_per_rad);
  if (!ok(status)) return check.fail(status, 35, 0, "pitching_moment_per_rad");
  status = required_table(b.fin_pitching_moment_per_rad);
  if (!ok(status)) return check.fail(status, 36, 0, "fin_pitching_moment_per_rad");
  status = required_table(b.cg_station_ft[0]);
  if (!ok(status)) return check.fail(status, 37, 1, "cg_station_ft");
  for (int k = 1; k < kCgTableStages; ++k) {
    status = optional_table(b.cg_station_ft[k]);
    if (!ok(status)) return check.fail(status, 37, k + 1, "cg_station_ft");
  }
  // F_CNL = M_alpha alpha / (X_delta - X_CG) (Sec. 11): the stage-1 c.g. (piecewise linear, its
  // values held past the ends) stays within its tabulated range, so X_delta must lie outside it.
  const CgTable& cg = b.cg_station_ft[0];
  double lowest = cg.y(0);
  double highest = cg.y(0);
  for (int i = 1; i < cg.size(); ++i) {
    lowest = cg.y(i) < lowest ? cg.y(i) : lowest;
    highest = cg.y(i) > highest ? cg.y(i) : highest;
  }
  const double station = b.control_station_ft[0];
  if (station >= lowest && station <= highest) {
    return check.fail(Status::kControlStationAtCenterOfGravity, 33, 1, "control_station_ft");
  }
  return Status::kOk;
}

}  // namespace

Status validate_mission(const Mission& mission, MissionFault* fault) {
  const Check check{fault};
  if (fault != nullptr) *fault = MissionFault{};

  Status status = check_options(mission.options, check);
  if (!ok(status)) return status;
  status = check_sequence(mission.vehicle, check);
  if (!ok(status)) return status;
  status = check_constants(mission.constants, check);
  if (!ok(status)) return status;
  status = check_atmosphere(mission.atmosphere, check);
  if (!ok(status)) return status;
  status = check_vehicle(mission.vehicle, mission.constants, check);
  if (!ok(status)) return status;
  status = check_launch(mission.launch, mission.vehicle, check);
  if (!ok(status)) return status;
  status = check_control(mission.control, mission.options, mission.vehicle,
                         mission.constants.time_epsilon_s, check);
  if (!ok(status)) return status;
  status = check_misc(mission.misc, mission.adjustable, check);
  if (!ok(status)) return status;
  status = check_constraints(mission.constraints, mission.options, check);
  if (!ok(status)) return status;
  status = check_adjustable(mission.adjustable, mission.vehicle, check);
  if (!ok(status)) return status;
  status = check_linearization(mission.linearization, mission.options, check);
  if (!ok(status)) return status;
  status = check_convergence(mission.convergence, check);
  if (!ok(status)) return status;
  status = check_output(mission.output, check);
  if (!ok(status)) return status;

  // Data block 40: the initial-nominal pitch program.
  if (mission.pitch_program_rad.empty()) return check.fail(Status::kTableEmpty, 40, 0, "pitch_program_rad");
  status = optional_table(mission.pitch_program_rad);
  if (!ok(status)) return check.fail(status, 40, 0, "pitch_program_rad");

  // Data blocks 33-37 when a 6D trajectory is asked for (IP(6) = 1 or 2).
  if (mission.options.body_dynamics_6d() >= 1) return check_body_dynamics(mission, check);
  return Status::kOk;
}

Status validate_body_dynamics(const Mission& mission, MissionFault* fault) {
  const Check check{fault};
  if (fault != nullptr) *fault = MissionFault{};
  return check_body_dynamics(mission, check);
}

// Consumable weight of the current powered stage (0 in a coast), plus the jettison weights of this
// and every later stage of the sequence, plus the payload while the last powered stage is current
// or later, plus the initial consumable weight (first weight-table entry) of every later powered
// stage. A code that is not in the sequence weighs 0.
double vehicle_weight_lb(const Vehicle& vehicle, int code, double stage_time_s) {
  const StageSequence& sequence = vehicle.sequence;
  const int position = position_in_sequence(sequence, code);
  if (position < 0) return 0.0;
  const int last_powered = last_powered_stage(sequence);

  double weight = 0.0;
  for (int k = position; k < sequence.count; ++k) {
    const int stage_code = sequence.codes[k];
    if (stage_code < 1 || stage_code > kMaxStages) continue;
    const StageData& stage = vehicle.stages[stage_index(stage_code)];
    weight += stage.jettison_weight_lb;
    if (stage_code == last_powered) weight += vehicle.payload_lb;
    if (!is_powered_stage(stage_code) || stage.consumable_weight_lb.empty()) continue;
    weight += (k == position) ? stage.consumable_weight_lb(stage_time_s)
                              : stage.consumable_weight_lb.y(0);
  }
  return weight;
}

}  // namespace tolip
