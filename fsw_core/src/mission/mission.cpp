// validate_mission() and vehicle_weight_lb() (mission.hpp).
//
// validate_mission() is the boundary check of a case (manual Sec. 22, data blocks 1-40): the
// ground tools call it after filling a Mission from a deck, and the core trusts a Mission that
// passed. It returns the first fault found, in data-block order, and names it in *fault with the
// manual's data block, the stage code and the Mission field (a string literal). No heap, no
// exceptions.
#include "tolip/mission/mission.hpp"

#include <cmath>

#include "tolip/mission/adjustable_parameter.hpp"
#include "tolip/mission/stage_weight.hpp"

namespace tolip {
namespace {

// Data block 5: the only order stages may be flown in.

// Tolerance on the 90-degree flight-path angle of block 21 (deck conversions round in the last bit).
constexpr double kAngleTolerance_rad = 1.0e-9;

// Angles the manual gives as angles (launch azimuth and longitude, spun-stage attitudes, the pitch
// program) lie within one turn either way; latitude within +-90 deg.
constexpr double kFullTurn_rad = 2.0 * kPi;

// Launch altitude (DA6(1)): from below the lowest land (the Dead Sea shore, about -1400 ft) to an
// air launch (tens of km).
constexpr double kLowestLaunchAltitude_ft = -1500.0;
constexpr double kHighestLaunchAltitude_ft = 100000.0;

constexpr ValueRange at_least(double low) {
  ValueRange range;
  range.has_low = true;
  range.low = low;
  return range;
}
constexpr ValueRange above(double low) {
  ValueRange range = at_least(low);
  range.low_inclusive = false;
  return range;
}
constexpr ValueRange at_most(double high) {
  ValueRange range;
  range.has_high = true;
  range.high = high;
  return range;
}
constexpr ValueRange between(double low, double high) {
  ValueRange range = at_least(low);
  range.has_high = true;
  range.high = high;
  return range;
}
constexpr ValueRange below(ValueRange range, double high) {
  range.has_high = true;
  range.high = high;
  range.high_inclusive = false;
  return range;
}
constexpr ValueRange exactly(double value) { return between(value, value); }

bool within(double value, const ValueRange& range) {
  if (range.has_low && !(range.low_inclusive ? value >= range.low : value > range.low)) return false;
  if (range.has_high && !(range.high_inclusive ? value <= range.high : value < range.high)) return false;
  return true;
}

struct Check {
  MissionFault* fault;

  // A fault without a value (a missing table, a capacity the ground tools count themselves).
  Status fail(Status status, int data_block, int stage_code, const char* field) const {
    if (fault != nullptr) {
      *fault = MissionFault{};
      fault->data_block = data_block;
      fault->stage_code = stage_code;
      fault->field = field;
    }
    return status;
  }

  // A fault with the value found (element `index` of `field`, -1 for none), the range it must lie
  // in and, when the range cannot say it, what was expected.
  Status fail(Status status, int data_block, int stage_code, const char* field, int index, double value,
              const char* unit, const ValueRange& range, const char* expected = "") const {
    const Status failed = fail(status, data_block, stage_code, field);
    if (fault != nullptr) {
      fault->index = index;
      fault->has_value = true;
      fault->value = value;
      fault->unit = unit;
      fault->range = range;
      fault->expected = expected;
    }
    return failed;
  }

  // kOk when the value lies in the range, else `status` with the value and the range.
  Status range(double value, const ValueRange& allowed, Status status, int data_block, int stage_code,
               const char* field, const char* unit, int index = -1) const {
    if (within(value, allowed)) return Status::kOk;
    return fail(status, data_block, stage_code, field, index, value, unit, allowed);
  }

  // kOk when the value is finite, else kValueNotFinite with the value.
  Status finite(double value, int data_block, int stage_code, const char* field, const char* unit,
                int index = -1) const {
    if (std::isfinite(value)) return Status::kOk;
    return fail(Status::kValueNotFinite, data_block, stage_code, field, index, value, unit, ValueRange{},
                "a finite number");
  }
};

#define TOLIP_CHECK(expression)                   \
  do {                                            \
    const Status check_status_ = expression;      \
    if (!ok(check_status_)) return check_status_; \
  } while (false)

// Every stored point finite and the abscissae strictly increasing (what finalize() checks); the
// fault names the point. `x_field` and `y_field` name the table's columns.
template <int N>
Status table_shape(const Table<N>& table, const Check& check, int data_block, int stage_code,
                   const char* x_field, const char* x_unit, const char* y_field, const char* y_unit) {
  for (int i = 0; i < table.size(); ++i) {
    TOLIP_CHECK(check.finite(table.x(i), data_block, stage_code, x_field, x_unit, i));
    TOLIP_CHECK(check.finite(table.y(i), data_block, stage_code, y_field, y_unit, i));
    if (i > 0 && !(table.x(i) > table.x(i - 1))) {
      return check.fail(Status::kTableNotMonotonic, data_block, stage_code, x_field, i, table.x(i), x_unit,
                        above(table.x(i - 1)), "strictly increasing");
    }
  }
  return Status::kOk;
}

// A table that may be empty; when it has points it must be well formed and finalized.
template <int N>
Status optional_table(const Table<N>& table, const Check& check, int data_block, int stage_code,
                      const char* x_field, const char* x_unit, const char* y_field, const char* y_unit) {
  if (table.empty()) return Status::kOk;
  TOLIP_CHECK(table_shape(table, check, data_block, stage_code, x_field, x_unit, y_field, y_unit));
  return table.finalized() ? Status::kOk
                           : check.fail(Status::kTableNotMonotonic, data_block, stage_code, x_field);
}

// Data block 8 codes: 0-14 terminal (14 = heating), X5-X9 at the end of stage X = 1-9,
// 100-102 the hyperbolic-asymptote constraints of Addendum H.
bool known_constraint_code(int code) {
  if (code >= 0 && code <= 14) return true;
  if (code >= 15 && code <= 99) {
    const int parameter = code % 10;  // 0-9
    return parameter >= 5;
  }
  return code >= 100 && code <= 102;
}

bool coast_adjustable_code(int code) { return adjusted_coast_stage_code(code) != 0; }

int position_in_sequence(const StageSequence& sequence, int code) {
  for (int k = 0; k < sequence.count; ++k) {
    if (sequence.codes[k] == code) return k;
  }
  return -1;
}

// Time from launch at which stage `code` of the sequence starts (the durations of data block 16
// of the stages before it); -1 when it is not in the sequence.
double stage_ignition_s(const Vehicle& vehicle, int code) {
  double start = 0.0;
  for (int k = 0; k < vehicle.sequence.count; ++k) {
    const int listed = vehicle.sequence.codes[k];
    if (listed == code) return start;
    if (listed >= 1 && listed <= kMaxStages) start += vehicle.stages[stage_index(listed)].duration_s;
  }
  return -1.0;
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
  auto option = [&](int n, double low, double high) {
    return check.range(ip[n], between(low, high), Status::kOptionOutOfRange, 4, 0, "ip", "", n);
  };
  // Options the manual marks "not used" must stay 0.
  const int unused[] = {4, 5, 8, 14, 16, 18, 19, 20};
  for (int n : unused) TOLIP_CHECK(option(n, 0, 0));
  const int binary[] = {2, 3, 7, 11, 12, 13, 15, 17, 21, 22, 23, 24};
  for (int n : binary) TOLIP_CHECK(option(n, 0, 1));
  TOLIP_CHECK(option(1, 0, 2));
  TOLIP_CHECK(option(6, 0, 2));
  TOLIP_CHECK(option(9, 0, 3));
  TOLIP_CHECK(option(10, 0, 2));
  // IP(6) = 1 (6D after linearization) requires IP(7) = 1.
  if (ip[6] == 1 && ip[7] != 1) {
    return check.fail(Status::kBodyDynamicsRelinearizationWithoutLinearization, 4, 0, "ip", 7, ip[7], "",
                      exactly(1), "IP(7) = 1 (linearization) with IP(6) = 1");
  }
  // The q-bar x alpha limit (an extension of the options, issue 15): 0 (none) or positive.
  TOLIP_CHECK(check.finite(options.qbar_alpha_limit_lbf_rad_ft2, 4, 0, "qbar_alpha_limit_lbf_rad_ft2",
                           "lbf rad/ft^2"));
  TOLIP_CHECK(check.range(options.qbar_alpha_limit_lbf_rad_ft2, at_least(0.0), Status::kOptionOutOfRange, 4,
                          0, "qbar_alpha_limit_lbf_rad_ft2", "lbf rad/ft^2"));
  return Status::kOk;
}

// ---- data block 5 -------------------------------------------------------------------------------
Status check_sequence(const Vehicle& vehicle, const Check& check) {
  const StageSequence& sequence = vehicle.sequence;
  if (sequence.count < 1 || sequence.count > kMaxStages) {
    return check.fail(Status::kStageSequenceInvalid, 5, 0, "sequence", -1, sequence.count, "",
                      between(1, kMaxStages),
                      "1-10 stage codes in the order 1 6 2 7 3 8 4 9 5 10, coasts optional");
  }
  for (int k = 0; k < sequence.count; ++k) {
    const int code = sequence.codes[k];
    if (!is_powered_stage(code) && !is_coast_stage(code)) {
      return check.fail(Status::kUnknownStageCode, 5, code, "sequence", k, code, "", between(1, kMaxStages),
                        "1-5 (powered stages) or 6-10 (the coasts after them)");
    }
    if (!may_follow_in_sequence(k == 0 ? 0 : sequence.codes[k - 1], code)) {
      return check.fail(
          Status::kStageSequenceInvalid, 5, code, "sequence", k, code, "", ValueRange{},
          k == 0 ? "stage 1 first"
                 : "after stage n the next powered stage n+1 or the coast n+5, after coast n+5 stage n+1 "
                   "(the order 1 6 2 7 3 8 4 9 5 10, coasts optional)");
    }
  }
  for (int code = 1; code <= kMaxStages; ++code) {
    const bool listed = position_in_sequence(sequence, code) >= 0;
    if (vehicle.stages[stage_index(code)].in_sequence != listed) {
      return check.fail(Status::kStageSequenceInvalid, 5, code, "in_sequence", -1, code, "", ValueRange{},
                        "StageData::in_sequence set exactly for the stages of the sequence");
    }
  }
  return Status::kOk;
}

// ---- data block 4 against data block 5: IP(9) ------------------------------------------------
// Sec. 22: "Set = 3 only when there are five stages. Otherwise, 1 or 2." A flown stage 4 needs the
// option (0, this project's "no stage 4", would leave it neither spun nor declared continuous).
Status check_spin_option(const Options& options, const Vehicle& vehicle, const Check& check) {
  const int spin = options.spin_stages_4_5();
  if (vehicle.stages[stage_index(4)].in_sequence && spin == 0) {
    return check.fail(Status::kSpinOptionInconsistent, 4, 4, "ip", 9, spin, "", between(1, 3),
                      "1 (stages 4 and 5 spun), 2 (stage 4 continuous, 5 spun) or 3 (both continuous) when "
                      "stage 4 is in the sequence");
  }
  if (spin == 3 && !vehicle.stages[stage_index(5)].in_sequence) {
    return check.fail(Status::kSpinOptionInconsistent, 4, 5, "ip", 9, spin, "", between(1, 2),
                      "3 only with five stages (Sec. 22); a four-stage vehicle with a continuous stage 4 "
                      "sets 2");
  }
  // IP(10), the stage-5 yaw (Sec. 22: 0 fewer than 5 stages, 1 chi5 = chi4, 2 chi5 independent),
  // admitted only where spun_stage_attitude() gives it that meaning: 1 or 2 when stage 5 is spun
  // apart from stage 4 (IP(9) = 2); 0 or 1 under IP(9) = 1, which itself sets chi5 = chi4; 0
  // otherwise (no stage 5, or a continuous stage 5 flying the pitch program).
  const int yaw = options.stage5_chi();
  const bool stage5 = vehicle.stages[stage_index(5)].in_sequence;
  if (stage5 && spin == 2 && yaw == 0) {
    return check.fail(Status::kStage5YawOptionInconsistent, 4, 5, "ip", 10, yaw, "", between(1, 2),
                      "1 (chi5 = chi4) or 2 (chi5 independent) when stage 5 is spun apart from stage 4 "
                      "(IP(9) = 2)");
  }
  if (stage5 && spin == 1 && yaw == 2) {
    return check.fail(Status::kStage5YawOptionInconsistent, 4, 5, "ip", 10, yaw, "", between(0, 1),
                      "0 or 1: IP(9) = 1 spins stage 5 on stage 4's attitudes (chi5 = chi4)");
  }
  if ((!stage5 || spin == 3) && yaw != 0) {
    return check.fail(Status::kStage5YawOptionInconsistent, 4, 5, "ip", 10, yaw, "", exactly(0),
                      stage5 ? "0 when stage 5 flies the pitch program (IP(9) = 3)"
                             : "0 with fewer than five stages (Sec. 22)");
  }
  return Status::kOk;
}

// A word of a data block with its field name and unit, for the checks that every word of a block
// is finite.
struct NamedWord {
  double value;
  const char* field;
  const char* unit;
};

// ---- data block 10 ------------------------------------------------------------------------------
Status check_constants(const Constants& c, const Check& check) {
  const NamedWord words[] = {{c.earth_rotation_rate_rad_s, "earth_rotation_rate_rad_s", "rad/s"},
                             {c.gravitational_parameter_ft3_s2, "gravitational_parameter_ft3_s2", "ft^3/s^2"},
                             {c.earth_equatorial_radius_ft, "earth_equatorial_radius_ft", "ft"},
                             {c.gas_constant_ft2_s2_R, "gas_constant_ft2_s2_R", "ft^2/(s^2 R)"},
                             {c.g0_ft_s2, "g0_ft_s2", "ft/s^2"},
                             {c.sea_level_pressure_lbf_ft2, "sea_level_pressure_lbf_ft2", "lbf/ft^2"},
                             {c.haero_ft, "haero_ft", "ft"},
                             {c.time_epsilon_s, "time_epsilon_s", "s"},
                             {c.j2, "j2", ""},
                             {c.inverse_flattening, "inverse_flattening", ""},
                             {c.ct1_13, "ct1_13", ""}};
  for (const NamedWord& word : words) TOLIP_CHECK(check.finite(word.value, 10, 0, word.field, word.unit));
  const Status bad = Status::kConstantOutOfRange;
  TOLIP_CHECK(check.range(c.gravitational_parameter_ft3_s2, above(0.0), bad, 10, 0,
                          "gravitational_parameter_ft3_s2", "ft^3/s^2"));
  TOLIP_CHECK(
      check.range(c.earth_equatorial_radius_ft, above(0.0), bad, 10, 0, "earth_equatorial_radius_ft", "ft"));
  TOLIP_CHECK(
      check.range(c.gas_constant_ft2_s2_R, above(0.0), bad, 10, 0, "gas_constant_ft2_s2_R", "ft^2/(s^2 R)"));
  TOLIP_CHECK(check.range(c.g0_ft_s2, above(0.0), bad, 10, 0, "g0_ft_s2", "ft/s^2"));
  TOLIP_CHECK(check.range(c.sea_level_pressure_lbf_ft2, at_least(0.0), bad, 10, 0,
                          "sea_level_pressure_lbf_ft2", "lbf/ft^2"));
  TOLIP_CHECK(check.range(c.haero_ft, at_least(0.0), bad, 10, 0, "haero_ft", "ft"));
  TOLIP_CHECK(check.range(c.time_epsilon_s, above(0.0), bad, 10, 0, "time_epsilon_s", "s"));
  // CT1(12) = 0 is the spherical Earth (no flattening); any other value is 1 / flattening.
  if (c.inverse_flattening != 0.0 && !within(c.inverse_flattening, above(1.0))) {
    return check.fail(bad, 10, 0, "inverse_flattening", -1, c.inverse_flattening, "", above(1.0),
                      "or 0 for a spherical Earth");
  }
  return Status::kOk;
}

// ---- data blocks 11-14 --------------------------------------------------------------------------
Status check_atmosphere(const AtmosphereTable& a, const Check& check) {
  for (int i = 0; i < kAtmosphereLayers; ++i) {
    TOLIP_CHECK(
        check.finite(a.base_geopotential_altitude_ft[i], 11, 0, "base_geopotential_altitude_ft", "ft", i));
  }
  for (int i = 0; i < kAtmosphereLayers; ++i) {
    TOLIP_CHECK(
        check.finite(a.base_molecular_temperature_R[i], 12, 0, "base_molecular_temperature_R", "R", i));
  }
  for (int i = 0; i < kAtmosphereLayers; ++i) {
    TOLIP_CHECK(check.finite(a.lapse_rate_R_per_ft[i], 13, 0, "lapse_rate_R_per_ft", "R/ft", i));
  }
  for (int i = 0; i < kAtmosphereLayers; ++i) {
    TOLIP_CHECK(check.finite(a.base_density_slug_ft3[i], 14, 0, "base_density_slug_ft3", "slug/ft^3", i));
  }
  const Status bad = Status::kAtmosphereTableInvalid;
  TOLIP_CHECK(check.range(a.base_geopotential_altitude_ft[0], exactly(0.0), bad, 11, 0,
                          "base_geopotential_altitude_ft", "ft", 0));
  for (int i = 1; i < kAtmosphereLayers; ++i) {
    TOLIP_CHECK(check.range(a.base_geopotential_altitude_ft[i], above(a.base_geopotential_altitude_ft[i - 1]),
                            bad, 11, 0, "base_geopotential_altitude_ft", "ft", i));
  }
  for (int i = 0; i < kAtmosphereLayers; ++i) {
    TOLIP_CHECK(check.range(a.base_molecular_temperature_R[i], above(0.0), bad, 12, 0,
                            "base_molecular_temperature_R", "R", i));
    TOLIP_CHECK(check.range(a.base_density_slug_ft3[i], above(0.0), bad, 14, 0, "base_density_slug_ft3",
                            "slug/ft^3", i));
  }
  return Status::kOk;
}

// ---- data blocks 16, 30, 31, 38, 39 for one stage ------------------------------------------------
Status check_stage(const StageData& stage, int code, double time_epsilon_s, const Check& check) {
  TOLIP_CHECK(check.finite(stage.duration_s, 16, code, "duration_s", "s"));
  TOLIP_CHECK(check.finite(stage.jettison_weight_lb, 39, code, "jettison_weight_lb", "lb"));
  TOLIP_CHECK(check.finite(stage.reference_area_ft2, 39, code, "reference_area_ft2", "ft^2"));
  TOLIP_CHECK(check.finite(stage.nozzle_exit_area_ft2, 39, code, "nozzle_exit_area_ft2", "ft^2"));

  // A coast of 0 s is not flown as zero steps: it is left out of the sequence (data block 5), so
  // the powered stages around it burn back to back (docs/deck-format.md).
  if (is_coast_stage(code) && stage.duration_s == 0.0) {
    return check.fail(Status::kZeroLengthCoast, 16, code, "duration_s", -1, 0.0, "s", above(0.0),
                      "> 0, or leave the coast out of the stage sequence (data block 5)");
  }
  TOLIP_CHECK(
      check.range(stage.duration_s, above(0.0), Status::kNonPositiveDuration, 16, code, "duration_s", "s"));
  TOLIP_CHECK(check.range(stage.integration_steps, at_least(1), Status::kNonPositiveStepCount, 16, code,
                          "integration_steps", ""));
  TOLIP_CHECK(check.range(stage.jettison_weight_lb, at_least(0.0), Status::kNegativeWeight, 39, code,
                          "jettison_weight_lb", "lb"));
  TOLIP_CHECK(check.range(stage.reference_area_ft2, at_least(0.0), Status::kNegativeArea, 39, code,
                          "reference_area_ft2", "ft^2"));
  TOLIP_CHECK(check.range(stage.nozzle_exit_area_ft2, at_least(0.0), Status::kNegativeArea, 39, code,
                          "nozzle_exit_area_ft2", "ft^2"));

  TOLIP_CHECK(
      optional_table(stage.drag_coefficient, check, 31, code, "drag_mach", "", "drag_coefficient", ""));
  if (!stage.drag_coefficient.empty() && !(stage.reference_area_ft2 > 0.0)) {
    return check.fail(Status::kReferenceAreaMissing, 39, code, "reference_area_ft2", -1,
                      stage.reference_area_ft2, "ft^2", above(0.0),
                      "> 0 for a stage with a drag table (data block 31)");
  }

  if (is_coast_stage(code)) {
    TOLIP_CHECK(check.range(stage.integration_steps, at_most(kMaxCoastSteps), Status::kTooManyCoastSteps, 16,
                            code, "integration_steps", ""));
    if (!stage.vacuum_thrust_lbf.empty()) {
      return check.fail(Status::kPropulsionInCoast, 30, code, "vacuum_thrust_lbf", -1,
                        stage.vacuum_thrust_lbf.size(), "points", exactly(0), "no thrust table in a coast");
    }
    TOLIP_CHECK(check.range(stage.nozzle_exit_area_ft2, exactly(0.0), Status::kPropulsionInCoast, 39, code,
                            "nozzle_exit_area_ft2", "ft^2"));
    if (!stage.consumable_weight_lb.empty()) {
      return check.fail(Status::kPropulsionInCoast, 38, code, "consumable_weight_lb", -1,
                        stage.consumable_weight_lb.size(), "points", exactly(0),
                        "no consumable weight table in a coast");
    }
    return Status::kOk;
  }

  // Powered stage: block 30 thrust and block 38 consumable weight, both finalized.
  const ThrustTable& thrust = stage.vacuum_thrust_lbf;
  const WeightTable& weight = stage.consumable_weight_lb;
  if (thrust.empty()) return check.fail(Status::kMissingThrustTable, 30, code, "vacuum_thrust_lbf");
  TOLIP_CHECK(table_shape(thrust, check, 30, code, "vacuum_thrust_time_s", "s", "vacuum_thrust_lbf", "lbf"));
  if (!thrust.finalized()) return check.fail(Status::kMissingThrustTable, 30, code, "vacuum_thrust_lbf");
  if (weight.empty()) return check.fail(Status::kMissingWeightTable, 38, code, "consumable_weight_lb");
  TOLIP_CHECK(
      table_shape(weight, check, 38, code, "consumable_weight_time_s", "s", "consumable_weight_lb", "lb"));
  if (!weight.finalized()) {
    return check.fail(Status::kMissingWeightTable, 38, code, "consumable_weight_lb");
  }
  TOLIP_CHECK(check.range(thrust.first_x(), at_least(0.0), Status::kTableTimeNegative, 30, code,
                          "vacuum_thrust_time_s", "s", 0));
  TOLIP_CHECK(check.range(weight.first_x(), at_least(0.0), Status::kTableTimeNegative, 38, code,
                          "consumable_weight_time_s", "s", 0));
  for (int i = 0; i < thrust.size(); ++i) {
    TOLIP_CHECK(check.range(thrust.y(i), at_least(0.0), Status::kNegativeThrust, 30, code,
                            "vacuum_thrust_lbf", "lbf", i));
  }
  for (int i = 0; i < weight.size(); ++i) {
    TOLIP_CHECK(check.range(weight.y(i), at_least(0.0), Status::kNegativeWeight, 38, code,
                            "consumable_weight_lb", "lb", i));
  }
  // Propellant is consumed, never made: the weight remaining never increases.
  for (int i = 1; i < weight.size(); ++i) {
    if (weight.y(i) > weight.y(i - 1)) {
      return check.fail(Status::kConsumableWeightIncreases, 38, code, "consumable_weight_lb", i, weight.y(i),
                        "lb", at_most(weight.y(i - 1)),
                        "no more than the weight remaining at the point before");
    }
  }
  if (std::fabs(thrust.last_x() - weight.last_x()) > time_epsilon_s) {
    return check.fail(Status::kThrustWeightTimesDiffer, 38, code, "consumable_weight_lb");
  }
  // Thrust needs propellant: a stage with thrust carries consumable weight, and wherever the thrust
  // table is positive before its last point some consumable weight remains.
  bool thrusts = false;
  for (int i = 0; i < thrust.size(); ++i) thrusts = thrusts || thrust.y(i) > 0.0;
  if (thrusts && !(weight.y(0) > 0.0)) {
    return check.fail(Status::kThrustWithoutPropellant, 38, code, "consumable_weight_lb", 0, weight.y(0),
                      "lb", above(0.0), "propellant for the thrust of data block 30");
  }
  for (int i = 0; i + 1 < thrust.size(); ++i) {
    if (thrust.y(i) > 0.0 && !(weight(thrust.x(i)) > 0.0)) {
      return check.fail(Status::kThrustWithoutPropellant, 30, code, "vacuum_thrust_lbf", i, thrust.y(i),
                        "lbf", exactly(0.0), "no thrust once the consumable weight of data block 38 is gone");
    }
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
    TOLIP_CHECK(check_stage(vehicle.stages[stage_index(code)], code, constants.time_epsilon_s, check));
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
  TOLIP_CHECK(optional_table(vehicle.lift_curve_slope_per_rad, check, 32, 0, "lift_mach", "",
                             "lift_curve_slope_per_rad", "per rad"));
  for (int i = 0; i < kMaxStages; ++i) {
    if (vehicle.stages[i].in_sequence && vehicle.stages[i].uses_lift_table) {
      if (vehicle.lift_curve_slope_per_rad.empty()) {
        return check.fail(Status::kTableEmpty, 32, i + 1, "lift_curve_slope_per_rad");
      }
      if (!(vehicle.stages[i].reference_area_ft2 > 0.0)) {
        return check.fail(Status::kReferenceAreaMissing, 39, i + 1, "reference_area_ft2", -1,
                          vehicle.stages[i].reference_area_ft2, "ft^2", above(0.0),
                          "> 0 for a stage using the lift table (data block 32)");
      }
    }
  }

  // The payload rides in the jettison weight of the last powered stage (Sec. 14).
  const int last_powered = last_powered_stage(sequence);
  TOLIP_CHECK(check.finite(vehicle.payload_lb, 39, last_powered, "payload_lb", "lb"));
  TOLIP_CHECK(check.range(vehicle.payload_lb, at_least(0.0), Status::kNegativeWeight, 39, last_powered,
                          "payload_lb", "lb"));
  return Status::kOk;
}

// ---- data blocks 20, 21 -------------------------------------------------------------------------
Status check_launch(const LaunchConditions& l, const Vehicle& vehicle, const Check& check) {
  TOLIP_CHECK(check.finite(l.liftoff_duration_s, 20, 0, "liftoff_duration_s", "s"));
  TOLIP_CHECK(check.finite(l.launch_space_age_date_days, 20, 0, "launch_space_age_date_days", "days"));
  TOLIP_CHECK(check.finite(l.altitude_ft, 21, 0, "altitude_ft", "ft"));
  TOLIP_CHECK(check.finite(l.longitude_rad, 21, 0, "longitude_rad", "rad"));
  TOLIP_CHECK(check.finite(l.geocentric_latitude_rad, 21, 0, "geocentric_latitude_rad", "rad"));
  TOLIP_CHECK(check.finite(l.velocity_ft_s, 21, 0, "velocity_ft_s", "ft/s"));
  TOLIP_CHECK(check.finite(l.azimuth_rad, 21, 0, "azimuth_rad", "rad"));
  TOLIP_CHECK(check.finite(l.flight_path_angle_rad, 21, 0, "flight_path_angle_rad", "rad"));
  TOLIP_CHECK(check.finite(l.heading_hold_until_s, 21, 0, "heading_hold_until_s", "s"));

  const Status bad = Status::kLaunchConditionOutOfRange;
  // The integration starts from the lift-off's end state: at V = 0 (no lift-off) the equations of
  // motion are singular, so the closed-form lift-off must last a while.
  TOLIP_CHECK(check.range(l.liftoff_duration_s, above(0.0), Status::kLiftoffNotPositive, 20, 0,
                          "liftoff_duration_s", "s"));
  const StageData& stage1 = vehicle.stages[stage_index(1)];
  TOLIP_CHECK(check.range(l.liftoff_duration_s, below(above(0.0), stage1.duration_s),
                          Status::kLiftoffLongerThanStage1, 20, 1, "liftoff_duration_s", "s"));
  TOLIP_CHECK(check.range(l.altitude_ft, between(kLowestLaunchAltitude_ft, kHighestLaunchAltitude_ft), bad,
                          21, 0, "altitude_ft", "ft"));
  TOLIP_CHECK(check.range(l.longitude_rad, between(-kFullTurn_rad, kFullTurn_rad), bad, 21, 0,
                          "longitude_rad", "rad"));
  TOLIP_CHECK(check.range(l.geocentric_latitude_rad, between(-0.5 * kPi, 0.5 * kPi), bad, 21, 0,
                          "geocentric_latitude_rad", "rad"));
  TOLIP_CHECK(check.range(l.velocity_ft_s, exactly(0.0), Status::kInitialConditionsInvalid, 21, 0,
                          "velocity_ft_s", "ft/s"));
  TOLIP_CHECK(
      check.range(l.azimuth_rad, between(-kFullTurn_rad, kFullTurn_rad), bad, 21, 0, "azimuth_rad", "rad"));
  TOLIP_CHECK(check.range(l.flight_path_angle_rad,
                          between(0.5 * kPi - kAngleTolerance_rad, 0.5 * kPi + kAngleTolerance_rad),
                          Status::kInitialConditionsInvalid, 21, 0, "flight_path_angle_rad", "rad"));
  TOLIP_CHECK(check.range(l.heading_hold_until_s, at_least(0.0), bad, 21, 0, "heading_hold_until_s", "s"));
  return Status::kOk;
}

// ---- data block 22 ------------------------------------------------------------------------------
Status check_control(const ControlConstraints& c, const Options& options, const Vehicle& vehicle,
                     double time_epsilon_s, const Check& check) {
  TOLIP_CHECK(check.finite(c.zero_alpha_start_s, 22, 0, "zero_alpha_start_s", "s"));
  TOLIP_CHECK(check.finite(c.zero_alpha_end_s, 22, 0, "zero_alpha_end_s", "s"));
  TOLIP_CHECK(check.finite(c.max_pitch_rate_rad_s, 22, 0, "max_pitch_rate_rad_s", "rad/s"));
  TOLIP_CHECK(check.finite(c.min_pitch_rate_rad_s, 22, 0, "min_pitch_rate_rad_s", "rad/s"));
  TOLIP_CHECK(check.finite(c.min_pitch_rate_change_rad_s, 22, 0, "min_pitch_rate_change_rad_s", "rad/s"));
  const Status bad = Status::kPitchRateLimitNegative;
  TOLIP_CHECK(
      check.range(c.max_pitch_rate_rad_s, at_least(0.0), bad, 22, 0, "max_pitch_rate_rad_s", "rad/s"));
  TOLIP_CHECK(
      check.range(c.min_pitch_rate_rad_s, at_least(0.0), bad, 22, 0, "min_pitch_rate_rad_s", "rad/s"));
  TOLIP_CHECK(check.range(c.min_pitch_rate_change_rad_s, at_least(0.0), bad, 22, 0,
                          "min_pitch_rate_change_rad_s", "rad/s"));
  if (options.zero_alpha_window()) {
    // IP(11): the alpha = 0 window lies inside stage 1 (times from launch).
    const double stage1_end_s = vehicle.stages[stage_index(1)].duration_s + time_epsilon_s;
    TOLIP_CHECK(check.range(c.zero_alpha_start_s, at_least(0.0), Status::kZeroAlphaWindowInvalid, 22, 0,
                            "zero_alpha_start_s", "s"));
    if (!(c.zero_alpha_end_s > c.zero_alpha_start_s) || c.zero_alpha_end_s > stage1_end_s) {
      ValueRange window = above(c.zero_alpha_start_s);
      window.has_high = true;
      window.high = stage1_end_s;
      return check.fail(Status::kZeroAlphaWindowInvalid, 22, 1, "zero_alpha_end_s", -1, c.zero_alpha_end_s,
                        "s", window, "after zero_alpha_start_s, by the end of stage 1 within CT1(10)");
    }
  }
  return Status::kOk;
}

// ---- data block 17 ------------------------------------------------------------------------------
Status check_misc(const MiscellaneousData& m, const AdjustableParameters& adjustable, const Check& check) {
  const NamedWord words[] = {{m.stage4_theta_rad, "stage4_theta_rad", "rad"},
                             {m.stage4_chi_rad, "stage4_chi_rad", "rad"},
                             {m.nose_radius_ft, "nose_radius_ft", "ft"},
                             {m.gyro_uncage_s_before_launch, "gyro_uncage_s_before_launch", "s"},
                             {m.stage5_theta_rad, "stage5_theta_rad", "rad"},
                             {m.stage5_chi_rad, "stage5_chi_rad", "rad"},
                             {m.payload_weighting_factor, "payload_weighting_factor", ""},
                             {m.coast_change_limit_s, "coast_change_limit_s", "s"},
                             {m.minimum_coast_s, "minimum_coast_s", "s"}};
  for (const NamedWord& word : words) TOLIP_CHECK(check.finite(word.value, 17, 0, word.field, word.unit));
  const Status bad = Status::kMiscellaneousDataOutOfRange;
  // The spun-stage attitudes are angles: within one turn either way.
  const int angles[] = {0, 1, 4, 5};
  for (int i : angles) {
    TOLIP_CHECK(check.range(words[i].value, between(-kFullTurn_rad, kFullTurn_rad), bad, 17, 0,
                            words[i].field, "rad"));
  }
  TOLIP_CHECK(check.range(m.nose_radius_ft, at_least(0.0), bad, 17, 0, "nose_radius_ft", "ft"));
  TOLIP_CHECK(check.range(m.gyro_uncage_s_before_launch, at_least(0.0), bad, 17, 0,
                          "gyro_uncage_s_before_launch", "s"));
  TOLIP_CHECK(
      check.range(m.payload_weighting_factor, above(0.0), bad, 17, 0, "payload_weighting_factor", ""));
  TOLIP_CHECK(check.range(m.coast_change_limit_s, at_least(0.0), bad, 17, 0, "coast_change_limit_s", "s"));
  TOLIP_CHECK(check.range(m.minimum_coast_s, at_least(0.0), bad, 17, 0, "minimum_coast_s", "s"));
  // DA2(16) "must be input if any coast is used as an adjustable parameter".
  for (int i = 0; i < adjustable.count && i < kMaxAdjustableParameters; ++i) {
    if (coast_adjustable_code(adjustable.codes[i]) && !(m.coast_change_limit_s > 0.0)) {
      return check.fail(Status::kCoastChangeLimitMissing, 17, 0, "coast_change_limit_s", -1,
                        m.coast_change_limit_s, "s", above(0.0),
                        "> 0 when a coast is an adjustable parameter (data block 6)");
    }
  }
  return Status::kOk;
}

// ---- data blocks 8, 19, 29 ----------------------------------------------------------------------
// Faults name the constraint entry (the index in IB3(2..), the payoff 0) in MissionFault::index;
// deadband faults too (DA14(j) belongs to entry j + 1).
Status check_constraints(const ConstraintList& c, const Options& options, const Vehicle& vehicle,
                         const Check& check) {
  if (c.count > kMaxConstraints) return check.fail(Status::kTooManyConstraints, 8, 0, "count");
  TOLIP_CHECK(check.range(c.count, at_least(1), Status::kNoPayoffConstraint, 8, 0, "count", ""));
  for (int i = 0; i < kMaxConstraints + 1; ++i) {
    TOLIP_CHECK(check.finite(c.desired[i], 19, 0, "desired", "", i));
  }
  for (int j = 0; j < kMaxConstraints; ++j) {
    TOLIP_CHECK(check.finite(c.deadband_optimization[j], 29, 0, "deadband_optimization", "", j + 1));
    TOLIP_CHECK(check.finite(c.deadband_linearization[j], 29, 0, "deadband_linearization", "", j + 1));
  }
  constexpr const char* kKnownCodes =
      "a known code: 0-13 (terminal; 0 payload as the payoff only), 14 (heating, last), X5-X9 (at the end of "
      "stage X "
      "of the sequence) or 100-102";
  for (int i = 0; i < c.count; ++i) {
    const int code = c.codes[i];
    const bool stage_point = code >= 15 && code <= 99;
    if (!known_constraint_code(code) || code == 14 ||
        (stage_point && position_in_sequence(vehicle.sequence, code / 10) < 0)) {
      return check.fail(Status::kUnknownConstraintCode, 8, stage_point ? code / 10 : 0, "codes", i, code, "",
                        ValueRange{}, kKnownCodes);
    }
    if (code == 0 && i != 0) {
      return check.fail(Status::kPayloadCodeNotFirst, 8, 0, "codes", i, code, "", ValueRange{},
                        "payload (code 0) only as the payoff, the first entry");
    }
    for (int j = 0; j < i; ++j) {
      if (c.codes[j] == code) {
        return check.fail(Status::kDuplicateConstraintCode, 8, 0, "codes", i, code, "", ValueRange{},
                          "each code once (it is listed twice)");
      }
    }
  }
  // The payoff first, consistent with IP(1): payload (0), velocity (1 or 5), altitude (7).
  const int payoff = c.codes[0];
  const bool payoff_ok = (options.payoff() == 0 && payoff == 0) ||
                         (options.payoff() == 1 && (payoff == 1 || payoff == 5)) ||
                         (options.payoff() == 2 && payoff == 7);
  if (!payoff_ok) {
    return check.fail(Status::kPayoffCodeMismatch, 8, 0, "codes", 0, payoff, "", ValueRange{},
                      "the payoff of IP(1): code 0 with payoff 0, 1 or 5 with payoff 1, 7 with payoff 2");
  }
  // The heating code 14 follows the counted list exactly when IP(2) = 1.
  const bool heating_listed = c.count < kMaxConstraints + 1 && c.codes[c.count] == 14;
  if (options.heating_constraint() != heating_listed) {
    return check.fail(Status::kHeatingCodeMismatch, 8, 0, "codes", c.count, c.codes[c.count], "",
                      ValueRange{},
                      "the heating code 14 after the counted constraints exactly when IP(2) = 1");
  }
  // The optimizer appends the heating constraint to the counted list when it activates (Sec. 13),
  // so with it the counted list holds at most 12.
  if (heating_listed && c.count + 1 > kMaxConstraints) {
    return check.fail(Status::kTooManyConstraints, 8, 0, "count", -1, c.count, "",
                      at_most(kMaxConstraints - 1),
                      "at most 12 counted constraints with the heating constraint (13 in all)");
  }
  // The q-bar x alpha constraint (options, issue 15) joins the list the same way: one more entry.
  if (options.qbar_alpha_constraint() && c.count + (heating_listed ? 1 : 0) + 1 > kMaxConstraints) {
    return check.fail(Status::kTooManyConstraints, 8, 0, "count", -1, c.count, "",
                      at_most(kMaxConstraints - 1 - (heating_listed ? 1 : 0)),
                      "room for the q-bar x alpha constraint (13 entries in all)");
  }
  // Every constraint after the payoff is scaled by its optimization deadband (it must be > 0);
  // linearization (IP(7)) holds each constraint it fits (all but inclination and node) to its
  // linearization deadband.
  const int deadbands = c.count - 1 + (heating_listed ? 1 : 0);
  for (int j = 0; j < deadbands; ++j) {
    TOLIP_CHECK(check.range(c.deadband_optimization[j], above(0.0), Status::kDeadbandNotPositive, 29, 0,
                            "deadband_optimization", "", j + 1));
    const int code = c.codes[j + 1];
    const bool fitted = options.linearization() && j + 1 < c.count && code != 10 && code != 12;
    TOLIP_CHECK(check.range(c.deadband_linearization[j], fitted ? above(0.0) : at_least(0.0),
                            Status::kDeadbandNotPositive, 29, 0, "deadband_linearization", "", j + 1));
  }
  return Status::kOk;
}

// ---- data blocks 6, 27 --------------------------------------------------------------------------
Status check_adjustable(const AdjustableParameters& a, const Options& options, const Vehicle& vehicle,
                        const Check& check) {
  if (a.count > kMaxAdjustableParameters) {
    return check.fail(Status::kTooManyAdjustableParameters, 6, 0, "count");
  }
  TOLIP_CHECK(check.range(a.count, at_least(0), Status::kNegativeCount, 6, 0, "count", ""));
  for (int i = 0; i < kMaxAdjustableParameters; ++i) {
    TOLIP_CHECK(check.finite(a.weights[i], 27, 0, "weights", "", i));
  }
  for (int i = 0; i < a.count; ++i) {
    const int code = a.codes[i];
    TOLIP_CHECK(
        check.range(code, between(1, 11), Status::kUnknownAdjustableParameterCode, 6, 0, "codes", "", i));
    for (int j = 0; j < i; ++j) {
      if (a.codes[j] == code) {
        return check.fail(Status::kDuplicateAdjustableParameterCode, 6, 0, "codes", i, code, "", ValueRange{},
                          "each code once (it is listed twice)");
      }
    }
    // A coast length (codes 5, 4, 3, 10, 11: coasts 6, 7, 8, 9, 10) needs that coast flown.
    const int coast = adjusted_coast_stage_code(code);
    if (coast != 0 && !vehicle.stages[stage_index(coast)].in_sequence) {
      return check.fail(Status::kAdjustableCoastNotInSequence, 6, coast, "codes", i, code, "", ValueRange{},
                        "a coast-length code only for a coast of the stage sequence (data block 5)");
    }
    // A spun attitude (codes 1, 2: stage 4; 8, 9: stage 5) needs that stage flown on its own
    // data block 17 attitudes: stage 4 spun (IP(9) = 1, which spins stage 5 on them too), stage 5
    // spun apart from it (IP(9) = 2). A continuous stage's attitude is its pitch program.
    AdjustableParameter parameter = AdjustableParameter::kStage4Theta;
    decode_adjustable_parameter(code, &parameter);
    const bool stage4_attitude =
        parameter == AdjustableParameter::kStage4Theta || parameter == AdjustableParameter::kStage4Chi;
    const bool stage5_attitude =
        parameter == AdjustableParameter::kStage5Theta || parameter == AdjustableParameter::kStage5Chi;
    if (stage4_attitude || stage5_attitude) {
      const int stage = stage4_attitude ? 4 : 5;
      // Under IP(10) = 1 the spun stage 5 yaws at chi4: DA2(10), code 9, is not flown.
      const bool own = stage4_attitude
                           ? options.stage_is_spun(4)
                           : options.stage_is_spun(5) && !options.stage_is_spun(4) &&
                                 !(parameter == AdjustableParameter::kStage5Chi && options.stage5_chi() == 1);
      if (!vehicle.stages[stage_index(stage)].in_sequence || !own) {
        return check.fail(Status::kAdjustableAttitudeNotSpun, 6, stage, "codes", i, code, "", ValueRange{},
                          stage4_attitude
                              ? "codes 1, 2 (spun stage-4 attitudes) only with stage 4 flown and "
                                "IP(9) = 1"
                              : "codes 8, 9 (spun stage-5 attitudes) only with stage 5 flown and "
                                "IP(9) = 2, code 9 with IP(10) = 2 (with IP(9) = 1 stage 5 flies stage 4's "
                                "attitudes: codes 1, 2)");
      }
    }
    TOLIP_CHECK(
        check.range(a.weights[i], above(0.0), Status::kWeightingFactorNotPositive, 27, 0, "weights", "", i));
  }
  return Status::kOk;
}

// ---- data blocks 18, 26 -------------------------------------------------------------------------
// TLIN: the segment boundaries (stage n, t seconds from its ignition; the deck's 100 n + t,
// decoded by the deck readers) in increasing order, unused entries {0, 0}. Between consecutive
// listed powered stages the coast (when the sequence has one; else the staging instant) lies within
// one segment, so segment_count = number of boundaries - 1 (manual example: 103.0, 182.6, 200.0,
// 239.2 are three segments). A fault names field "boundaries", the entry (index) and its stage; the
// value is t in s (the ground re-codes it as the deck's 100 n + t in its messages).
// (Whether t lies within the burn is the deck reader's check: an exchange-ratio run that shortens a
// burn keeps the deck's boundaries.)
bool is_unused(const SegmentBoundary& b) { return b.stage == 0 && b.time_from_ignition_s == 0.0; }

// In the deck's order of boundaries: a later stage, or a later time in the same stage (the order
// of the coded values 100 n + t).
bool listed_after(const SegmentBoundary& b, const SegmentBoundary& previous) {
  return b.stage > previous.stage ||
         (b.stage == previous.stage && b.time_from_ignition_s > previous.time_from_ignition_s);
}

Status check_linearization(const LinearizationData& l, const Options& options, const Vehicle& vehicle,
                           const Check& check) {
  if (l.segment_count > kMaxLinearSegments) {
    return check.fail(Status::kTooManyLinearSegments, 18, 0, "segment_count");
  }
  TOLIP_CHECK(check.range(l.segment_count, at_least(0), Status::kNegativeCount, 18, 0, "segment_count", ""));
  for (int i = 0; i < kMaxLinearSegments + 1; ++i) {
    TOLIP_CHECK(check.finite(l.boundaries[i].time_from_ignition_s, 18, 0, "boundaries", "s", i));
  }
  for (int i = 0; i < kMaxLinearSegments; ++i) {
    TOLIP_CHECK(check.finite(l.segment_weights[i], 26, 0, "segment_weights", "", i));
  }
  int times = 0;
  while (times < kMaxLinearSegments + 1 && !is_unused(l.boundaries[times])) ++times;
  for (int i = times; i < kMaxLinearSegments + 1; ++i) {
    const SegmentBoundary& b = l.boundaries[i];
    if (!is_unused(b)) {
      return check.fail(Status::kCodedTimeAfterUnusedEntry, 18, b.stage, "boundaries", i,
                        b.time_from_ignition_s, "s", ValueRange{}, "0 after the first unused entry");
    }
  }
  for (int i = 0; i < times; ++i) {
    const SegmentBoundary& b = l.boundaries[i];
    const int code = b.stage >= 1 && b.stage <= kMaxPoweredStages ? b.stage : 0;
    if (code == 0 || !vehicle.stages[stage_index(code)].in_sequence) {
      return check.fail(Status::kCodedTimeStageInvalid, 18, 0, "boundaries", i, b.time_from_ignition_s, "s",
                        ValueRange{}, "100 n + t with n a powered stage of the sequence");
    }
    // Segments belong to the stages that fly the pitch program (IP(9)): a spun stage holds its
    // data block 17 attitudes.
    if (!options.stage_is_steered(code)) {
      return check.fail(Status::kCodedTimeInSpunStage, 18, code, "boundaries", i, b.time_from_ignition_s, "s",
                        ValueRange{},
                        "100 n + t with n a stage that flies the pitch program (IP(9) spins this one)");
    }
    if (i == 0) continue;
    const SegmentBoundary& previous = l.boundaries[i - 1];
    if (!listed_after(b, previous)) {
      return check.fail(Status::kTableNotMonotonic, 18, code, "boundaries", i, b.time_from_ignition_s, "s",
                        ValueRange{}, "strictly increasing");
    }
    // With stage n+1 directly after stage n (no coast between them), 100 n + (its burn) and
    // 100 (n+1) + 0 are the same instant: a segment of no length.
    if (previous.stage != code &&
        !(stage_ignition_s(vehicle, code) + b.time_from_ignition_s >
          stage_ignition_s(vehicle, previous.stage) + previous.time_from_ignition_s)) {
      return check.fail(
          Status::kTableNotMonotonic, 18, code, "boundaries", i, b.time_from_ignition_s, "s", ValueRange{},
          "later in flight than the coded time before it (a stage that ignites at the burnout "
          "of the one before, with no coast between, starts at that burnout: list one of the two)");
    }
  }
  // IP(7) = 1 "requires input of times of beginning of each linear segment in Data Block 18", and
  // Sec. 22 "times ... at ignition and burnout of all non-spun powered stages": every stage that
  // flies the pitch program (stages 4 and 5 too when IP(9) steers them) has its boundaries, or
  // the linearized trajectory would fly it at the last break's value.
  if (options.linearization()) {
    TOLIP_CHECK(check.range(l.segment_count, at_least(1), Status::kLinearizationWithoutSegments, 18, 0,
                            "segment_count", ""));
    for (int code = 1; code <= kMaxPoweredStages; ++code) {
      if (!vehicle.stages[stage_index(code)].in_sequence || !options.stage_is_steered(code)) continue;
      bool listed = false;
      for (int i = 0; i < times; ++i) listed = listed || l.boundaries[i].stage == code;
      if (!listed) {
        return check.fail(
            Status::kSteeredStageWithoutSegments, 18, code, "boundaries", -1, 0.0, "s", ValueRange{},
            "coded times 100 n + t in every stage that flies the pitch program (its ignition "
            "100 n and burnout 100 n + duration), IP(9) counting stages 4 and 5 when continuous");
      }
    }
  }
  if (times != (l.segment_count > 0 ? l.segment_count + 1 : 0)) {
    return check.fail(Status::kSegmentCountMismatch, 18, 0, "segment_count", -1, l.segment_count, "",
                      exactly(times > 0 ? times - 1 : 0), "the number of coded times - 1");
  }
  for (int i = 0; i < l.segment_count; ++i) {
    TOLIP_CHECK(check.range(l.segment_weights[i], above(0.0), Status::kWeightingFactorNotPositive, 26, 0,
                            "segment_weights", "", i));
  }
  return Status::kOk;
}

// ---- data block 28 ------------------------------------------------------------------------------
Status check_convergence(const ConvergenceData& c, const Check& check) {
  TOLIP_CHECK(check.finite(c.initial_payoff_improvement, 28, 0, "initial_payoff_improvement", ""));
  TOLIP_CHECK(check.finite(c.stop_improvement, 28, 0, "stop_improvement", ""));
  const Status bad = Status::kConvergenceDataOutOfRange;
  TOLIP_CHECK(
      check.range(c.initial_payoff_improvement, at_least(0.0), bad, 28, 0, "initial_payoff_improvement", ""));
  TOLIP_CHECK(check.range(c.stop_improvement, at_least(0.0), bad, 28, 0, "stop_improvement", ""));
  TOLIP_CHECK(
      check.range(c.max_forward_trajectories, at_least(1), bad, 28, 0, "max_forward_trajectories", ""));
  TOLIP_CHECK(check.range(c.max_linearization_iterations, at_least(0), bad, 28, 0,
                          "max_linearization_iterations", ""));
  return Status::kOk;
}

// ---- data blocks 33-37 (6D) --------------------------------------------------------------------
// A table a 6D run needs: given, well formed and finalized.
template <int N>
Status required_table(const Table<N>& table, const Check& check, int data_block, int stage_code,
                      const char* x_field, const char* x_unit, const char* y_field, const char* y_unit) {
  if (table.empty()) return check.fail(Status::kBodyDynamicsDataMissing, data_block, stage_code, y_field);
  return optional_table(table, check, data_block, stage_code, x_field, x_unit, y_field, y_unit);
}

// DA6D(12-15): substep counts, so whole numbers from 1 to the capacity (one status per cause).
Status check_integration_multipliers(const BodyDynamicsBlocks& b, const Check& check) {
  for (int k = 0; k < kIntegrationMultiplierStages; ++k) {
    const double m = b.integration_frequency_multiplier[k];
    const char* field = "integration_frequency_multiplier";
    TOLIP_CHECK(check.finite(m, 33, 0, field, "", k));
    TOLIP_CHECK(check.range(m, at_least(1.0), Status::kIntegrationMultiplierBelowOne, 33, 0, field, "", k));
    TOLIP_CHECK(check.range(m, at_most(static_cast<double>(kMaxIntegrationFrequencyMultiplier)),
                            Status::kIntegrationMultiplierAboveCapacity, 33, 0, field, "", k));
    if (m != std::floor(m)) {
      return check.fail(Status::kIntegrationMultiplierNotInteger, 33, 0, field, k, m, "", ValueRange{},
                        "a whole number of substeps");
    }
  }
  return Status::kOk;
}

Status check_body_dynamics(const Mission& mission, const Check& check) {
  const BodyDynamicsBlocks& b = mission.body_dynamics;
  if (!b.present) return check.fail(Status::kBodyDynamicsDataMissing, 33, 0, "body_dynamics");
  TOLIP_CHECK(check_integration_multipliers(b, check));
  // Every word given must be finite (stages 2-3 are kept for the dispersion and hardover work).
  for (int k = 0; k < kBodyDynamicsStages; ++k) {
    TOLIP_CHECK(check.finite(b.position_gain[k], 33, 0, "position_gain", "", k));
    TOLIP_CHECK(check.finite(b.rate_gain_s[k], 33, 0, "rate_gain_s", "s", k));
    TOLIP_CHECK(check.finite(b.control_station_ft[k], 33, 0, "control_station_ft", "ft", k));
  }
  TOLIP_CHECK(
      check.finite(b.jet_vane_effectiveness_per_rad, 33, 0, "jet_vane_effectiveness_per_rad", "per rad"));
  TOLIP_CHECK(check.finite(b.moment_reference_station_ft, 33, 0, "moment_reference_station_ft", "ft"));
  TOLIP_CHECK(check.finite(b.reference_length_ft, 33, 0, "reference_length_ft", "ft"));
  TOLIP_CHECK(check.finite(b.reference_area_ft2, 33, 0, "reference_area_ft2", "ft^2"));
  TOLIP_CHECK(check.finite(b.control_surfaces_per_plane, 33, 0, "control_surfaces_per_plane", ""));
  // Stage 1 (and the coast after it) is what a 6D run flies: a positive position gain (eq. 7-6
  // divides by K_theta M_delta - M_alpha, and K_theta = 0 means no autopilot), a rate gain >= 0.
  const Status bad = Status::kBodyDynamicsValueOutOfRange;
  TOLIP_CHECK(check.range(b.position_gain[0], above(0.0), bad, 33, 1, "position_gain", "", 0));
  TOLIP_CHECK(check.range(b.rate_gain_s[0], at_least(0.0), bad, 33, 1, "rate_gain_s", "s", 0));
  TOLIP_CHECK(check.range(b.jet_vane_effectiveness_per_rad, at_least(0.0), bad, 33, 0,
                          "jet_vane_effectiveness_per_rad", "per rad"));
  TOLIP_CHECK(check.range(b.reference_length_ft, above(0.0), bad, 33, 0, "reference_length_ft", "ft"));
  TOLIP_CHECK(check.range(b.reference_area_ft2, above(0.0), bad, 33, 0, "reference_area_ft2", "ft^2"));
  TOLIP_CHECK(
      check.range(b.control_surfaces_per_plane, above(0.0), bad, 33, 0, "control_surfaces_per_plane", ""));
  TOLIP_CHECK(required_table(b.fin_normal_force_per_rad, check, 34, 0, "mach", "", "fin_normal_force_per_rad",
                             "per rad"));
  TOLIP_CHECK(required_table(b.pitching_moment_per_rad, check, 35, 0, "mach", "", "pitching_moment_per_rad",
                             "per rad"));
  TOLIP_CHECK(required_table(b.fin_pitching_moment_per_rad, check, 36, 0, "mach", "",
                             "fin_pitching_moment_per_rad", "per rad"));
  TOLIP_CHECK(required_table(b.cg_station_ft[0], check, 37, 1, "stage_time_s", "s", "cg_station_ft", "ft"));
  for (int k = 1; k < kCgTableStages; ++k) {
    TOLIP_CHECK(
        optional_table(b.cg_station_ft[k], check, 37, k + 1, "stage_time_s", "s", "cg_station_ft", "ft"));
  }
  // F_CNL = M_alpha alpha / (X_delta - X_CG) (Sec. 11): the stage-1 c.g. (piecewise linear, its
  // values held past the ends) stays within its tabulated range, so X_delta must lie outside it.
  const CgTable& cg = b.cg_station_ft[0];
  // cppcheck-suppress duplicateAssignExpression ; both extremes start at the first station
  double lowest = cg.y(0);
  double highest = cg.y(0);
  for (int i = 1; i < cg.size(); ++i) {
    lowest = cg.y(i) < lowest ? cg.y(i) : lowest;
    highest = cg.y(i) > highest ? cg.y(i) : highest;
  }
  const double station = b.control_station_ft[0];
  if (station >= lowest && station <= highest) {
    return check.fail(Status::kControlStationAtCenterOfGravity, 33, 1, "control_station_ft", 0, station, "ft",
                      ValueRange{}, "outside the stage-1 c.g. stations of data block 37");
  }
  return Status::kOk;
}

}  // namespace

Status validate_mission(const Mission& mission, MissionFault* fault) {
  const Check check{fault};
  if (fault != nullptr) *fault = MissionFault{};

  TOLIP_CHECK(check_options(mission.options, check));
  TOLIP_CHECK(check_sequence(mission.vehicle, check));
  TOLIP_CHECK(check_spin_option(mission.options, mission.vehicle, check));
  TOLIP_CHECK(check_constants(mission.constants, check));
  TOLIP_CHECK(check_atmosphere(mission.atmosphere, check));
  TOLIP_CHECK(check_vehicle(mission.vehicle, mission.constants, check));
  TOLIP_CHECK(check_launch(mission.launch, mission.vehicle, check));
  TOLIP_CHECK(check_control(mission.control, mission.options, mission.vehicle,
                            mission.constants.time_epsilon_s, check));
  TOLIP_CHECK(check_misc(mission.misc, mission.adjustable, check));
  TOLIP_CHECK(check_constraints(mission.constraints, mission.options, mission.vehicle, check));
  TOLIP_CHECK(check_adjustable(mission.adjustable, mission.options, mission.vehicle, check));
  TOLIP_CHECK(check_linearization(mission.linearization, mission.options, mission.vehicle, check));
  TOLIP_CHECK(check_convergence(mission.convergence, check));

  // Data block 40: the initial-nominal pitch program; theta is an attitude, within one turn.
  const PitchTable& pitch = mission.pitch_program_rad;
  if (pitch.empty()) return check.fail(Status::kTableEmpty, 40, 0, "pitch_program_rad");
  TOLIP_CHECK(optional_table(pitch, check, 40, 0, "pitch_program_time_s", "s", "pitch_program_rad", "rad"));
  for (int i = 0; i < pitch.size(); ++i) {
    TOLIP_CHECK(check.range(pitch.y(i), between(-kFullTurn_rad, kFullTurn_rad),
                            Status::kPitchAttitudeOutOfRange, 40, 0, "pitch_program_rad", "rad", i));
  }

  // DA6D(12-15) always (a deck without body dynamics keeps the default 1s), blocks 33-37 in full
  // when a 6D trajectory is asked for (IP(6) = 1 or 2).
  TOLIP_CHECK(check_integration_multipliers(mission.body_dynamics, check));
  if (mission.options.body_dynamics_6d() >= 1) return check_body_dynamics(mission, check);
  return Status::kOk;
}

Status validate_body_dynamics(const Mission& mission, MissionFault* fault) {
  const Check check{fault};
  if (fault != nullptr) *fault = MissionFault{};
  return check_body_dynamics(mission, check);
}

#undef TOLIP_CHECK

int integration_substeps(const BodyDynamicsBlocks& blocks, int stage_code, bool body_dynamics) {
  if (!body_dynamics) return 1;
  const int stage = is_coast_stage(stage_code) ? stage_code - 5 : stage_code;
  if (stage < 1 || stage > kIntegrationMultiplierStages) return 1;
  return static_cast<int>(blocks.integration_frequency_multiplier[stage - 1]);
}

// Consumable weight of the current powered stage (0 in a coast), plus the jettison weights of this
// and every later stage of the sequence, plus the payload while the last powered stage is current
// or later, plus the initial consumable weight (first weight-table entry) of every later powered
// stage. A code that is not in the sequence weighs 0.
double vehicle_weight_lb(const Vehicle& vehicle, int code, double stage_time_s) {
  return StageWeight(vehicle, code)(stage_time_s);
}

// The loop of additions vehicle_weight_lb() defines (0 + each stage's jettison weight, the payload at
// the last powered stage, the consumable weight of every powered stage: its own at t, the later
// ones' first entries), cut at the one term that depends on t.
StageWeight::StageWeight(const Vehicle& vehicle, int code) {
  const StageSequence& sequence = vehicle.sequence;
  const int position = position_in_sequence(sequence, code);
  if (position < 0) return;
  const int last_powered = last_powered_stage(sequence);
  const auto add = [this](double term_lb) {
    if (consumable_ == nullptr) {
      leading_lb_ += term_lb;
    } else {
      trailing_lb_[trailing_count_++] = term_lb;
    }
  };
  // A coast after the last powered stage (addendum H's "integrated coast following the final
  // stage") flies what that stage burned out with: its jettison weight and the payload booked in
  // it (Sec. 14). Nothing is staged after the last powered stage; dropping both would leave it
  // massless.
  if (is_coast_stage(code) && last_powered != 0 && position > position_in_sequence(sequence, last_powered)) {
    add(vehicle.stages[stage_index(last_powered)].jettison_weight_lb);
    add(vehicle.payload_lb);
  }
  for (int k = position; k < sequence.count; ++k) {
    const int stage_code = sequence.codes[k];
    if (stage_code < 1 || stage_code > kMaxStages) continue;
    const StageData& stage = vehicle.stages[stage_index(stage_code)];
    add(stage.jettison_weight_lb);
    if (stage_code == last_powered) add(vehicle.payload_lb);
    if (!is_powered_stage(stage_code) || stage.consumable_weight_lb.empty()) continue;
    if (k == position) {
      consumable_ = &stage.consumable_weight_lb;
    } else {
      add(stage.consumable_weight_lb.y(0));
    }
  }
}

double StageWeight::operator()(double stage_time_s) {
  if (consumable_ == nullptr) return leading_lb_;
  double weight = leading_lb_ + (*consumable_)(stage_time_s, &hint_);
  for (int i = 0; i < trailing_count_; ++i) weight += trailing_lb_[i];
  return weight;
}

}  // namespace tolip
