// The optional analyses' data and the small tables they lean on (issue 14 structural coverage):
// every rejection of validate_hardover_data (Sec. 16, data blocks 44-45), validate_impact_data
// (Sec. 17, blocks 42-43 and DA6D(17-19)) and validate_atmosphere_table (Sec. 19, blocks 11-14)
// names its Status and word; so does every change perturb_stage_parameter (Sec. 8) cannot make; the stage-1
// gain schedule of body dynamics (Sec. 7) interpolates linearly between its points and holds its end values,
// against a hand computation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "support/reference_hardover.hpp"
#include "support/reference_impact.hpp"
#include "support/reference_mission.hpp"
#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/body/body_dynamics.hpp"
#include "tolip/hardover/hardover.hpp"
#include "tolip/impact/impact.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"

namespace tolip {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::unique_ptr<Mission> reference() {
  auto mission = std::make_unique<Mission>();
  test::build_reference_mission(test::ReferenceProgram::kOptimum, mission.get());
  return mission;
}

struct HardoverRejection {
  const char* what;
  void (*edit)(Mission&, HardoverData&);
  Status status;
  int data_block;
  int word;
  int stage;
};

TEST(Sec16Hardover, EveryDataRejectionIsNamedByBlockWordAndStage) {
  static const HardoverRejection rows[] = {
      {"(q-bar alpha)max finite", [](Mission&, HardoverData& d) { d.max_qbar_alpha_lbf_rad_ft2 = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 0},
      {"fin deflection finite", [](Mission&, HardoverData& d) { d.fin_vane_deflection_rad = HUGE_VAL; },
       Status::kHardoverValueNotFinite, 45, 0, 0},
      {"output interval finite", [](Mission&, HardoverData& d) { d.output_interval_s = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 0},
      {"(q-bar alpha)max > 0", [](Mission&, HardoverData& d) { d.max_qbar_alpha_lbf_rad_ft2 = 0.0; },
       Status::kHardoverQbarAlphaLimitInvalid, 45, 2, 1},
      {"attitude step finite", [](Mission&, HardoverData& d) { d.stages[0].max_attitude_step_rad = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 1},
      {"max step finite", [](Mission&, HardoverData& d) { d.stages[1].max_step_s = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 2},
      {"min step finite", [](Mission&, HardoverData& d) { d.stages[2].min_step_s = HUGE_VAL; },
       Status::kHardoverValueNotFinite, 45, 0, 3},
      {"misalignment finite", [](Mission&, HardoverData& d) { d.stages[0].thrust_misalignment_rad = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 1},
      {"thrust station finite", [](Mission&, HardoverData& d) { d.stages[1].thrust_station_ft = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 2},
      {"single jet finite", [](Mission&, HardoverData& d) { d.stages[1].single_jet_force_lbf = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 2},
      {"pitch-yaw jets finite", [](Mission&, HardoverData& d) { d.stages[2].pitch_yaw_jet_force_lbf = kNaN; },
       Status::kHardoverValueNotFinite, 45, 0, 3},
      {"jet station finite",
       [](Mission&, HardoverData& d) { d.stages[2].control_jet_station_ft = -HUGE_VAL; },
       Status::kHardoverValueNotFinite, 45, 0, 3},
      {"stage 1 every n-th step >= 1", [](Mission&, HardoverData& d) { d.stages[0].every_nth_step = 0; },
       Status::kHardoverEveryNthStepInvalid, 45, 1, 1},
      {"stage 3 every n-th step >= 1", [](Mission&, HardoverData& d) { d.stages[2].every_nth_step = -1; },
       Status::kHardoverEveryNthStepInvalid, 45, 22, 3},
      {"stage 2 (DT)min > 0", [](Mission&, HardoverData& d) { d.stages[1].min_step_s = 0.0; },
       Status::kHardoverStepLimitsInvalid, 45, 25, 2},
      {"(DT)max >= (DT)min",
       [](Mission&, HardoverData& d) { d.stages[1].max_step_s = 0.5 * d.stages[1].min_step_s; },
       Status::kHardoverStepLimitsInvalid, 45, 25, 2},
      {"stage 1 attitude step > 0",
       [](Mission&, HardoverData& d) { d.stages[0].max_attitude_step_rad = 0.0; },
       Status::kHardoverAttitudeStepInvalid, 45, 3, 1},
      {"stage 2 attitude step > 0",
       [](Mission&, HardoverData& d) { d.stages[1].max_attitude_step_rad = -1.0; },
       Status::kHardoverAttitudeStepInvalid, 45, 23, 2},
      {"stage 1 steps per turn >= 1", [](Mission&, HardoverData& d) { d.stages[0].max_steps_per_turn = 0; },
       Status::kHardoverMaxStepsInvalid, 45, 6, 1},
      {"stage 3 steps per turn >= 1", [](Mission&, HardoverData& d) { d.stages[2].max_steps_per_turn = 0; },
       Status::kHardoverMaxStepsInvalid, 45, 26, 3},
      {"inertia table finalized",
       [](Mission&, HardoverData& d) {
         HardoverTable& t = d.stages[1].pitch_inertia_slug_ft2;
         t.set_y(0, t.y(0));
       },
       Status::kHardoverInertiaMissing, 44, 0, 2},
      {"inertia > 0",
       [](Mission&, HardoverData& d) {
         HardoverTable& t = d.stages[1].pitch_inertia_slug_ft2;
         t.set_y(t.size() - 1, 0.0);
         ASSERT_EQ(t.finalize(), Status::kOk);
       },
       Status::kHardoverInertiaNotPositive, 44, 0, 2},
      {"stage 3 c.g. table", [](Mission& m, HardoverData&) { m.body_dynamics.cg_station_ft[2].clear(); },
       Status::kHardoverBodyDataMissing, 37, 0, 3},
      {"damping table finalized",
       [](Mission&, HardoverData& d) { d.pitch_damping_per_rad.set_y(0, d.pitch_damping_per_rad.y(0)); },
       Status::kHardoverDampingTableMissing, 44, 0, 4},
      {"body data given", [](Mission& m, HardoverData&) { m.body_dynamics.present = false; },
       Status::kHardoverBodyDataMissing, 33, 16, 1},
      {"reference length > 0", [](Mission& m, HardoverData&) { m.body_dynamics.reference_length_ft = 0.0; },
       Status::kHardoverBodyDataMissing, 33, 16, 1},
      {"reference area > 0", [](Mission& m, HardoverData&) { m.body_dynamics.reference_area_ft2 = 0.0; },
       Status::kHardoverBodyDataMissing, 33, 16, 1},
  };
  const HardoverData good = test::reference_hardover();
  for (const HardoverRejection& row : rows) {
    SCOPED_TRACE(row.what);
    auto mission = reference();
    HardoverData data = good;
    ASSERT_EQ(validate_hardover_data(*mission, data, nullptr), Status::kOk);
    row.edit(*mission, data);
    HardoverFault fault{-1, -1, -1};
    EXPECT_EQ(validate_hardover_data(*mission, data, &fault), row.status);
    EXPECT_EQ(fault.data_block, row.data_block);
    EXPECT_EQ(fault.word, row.word);
    EXPECT_EQ(fault.stage, row.stage);
    EXPECT_EQ(validate_hardover_data(*mission, data, nullptr), row.status) << "no fault record asked for";
  }
  // A stage that is not flown is not checked.
  auto mission = reference();
  HardoverData data = good;
  data.stages[2].every_nth_step = 0;
  test::stage(*mission, 3).in_sequence = false;
  EXPECT_EQ(validate_hardover_data(*mission, data, nullptr), Status::kOk);
}

TEST(Sec16Hardover, StopReasonsPrintAsTheManualNamesThem) {
  EXPECT_STREQ(hardover_stop_name(HardoverStop::kTimeLimit), "TIME LIMIT");
  EXPECT_STREQ(hardover_stop_name(HardoverStop::kQbarAlphaLimit), "QBAR-ALPHA MAX");
  EXPECT_STREQ(hardover_stop_name(HardoverStop::kTumbling), "TUMBLING");
  EXPECT_STREQ(hardover_stop_name(HardoverStop::kEndOfStage), "END OF STAGE");
  EXPECT_STREQ(hardover_stop_name(HardoverStop::kStepLimit), "STEP LIMIT");
  EXPECT_STREQ(hardover_stop_name(static_cast<HardoverStop>(99)), "UNKNOWN");
}

struct ImpactRejection {
  const char* what;
  void (*edit)(ImpactLocusData&);
  Status status;
  int data_block;
  int stage;
  const char* field;
};

TEST(Sec17Impact, EveryDataRejectionNamesTheBlockStageAndWord) {
  static const ImpactRejection rows[] = {
      {"failure-mode drag table given",
       [](ImpactLocusData& d) { d.failure_mode[0].drag_coefficient.clear(); }, Status::kImpactDataMissing, 42,
       1, "CD1F"},
      {"drag table finalized",
       [](ImpactLocusData& d) {
         AeroTable& t = d.expended_casing[1].drag_coefficient;
         t.set_y(0, t.y(0));
       },
       Status::kTableNotMonotonic, 43, 2, "CD2E"},
      {"drag table from Mach 0",
       [](ImpactLocusData& d) {
         AeroTable& t = d.failure_mode[2].drag_coefficient;
         t.clear();
         ASSERT_EQ(t.append(0.5, 0.3), Status::kOk);
         ASSERT_EQ(t.append(2.0, 0.4), Status::kOk);
         ASSERT_EQ(t.finalize(), Status::kOk);
       },
       Status::kImpactDragTableNotFromMach0, 42, 3, "CD3F"},
      {"C_D >= 0",
       [](ImpactLocusData& d) {
         AeroTable& t = d.failure_mode[1].drag_coefficient;
         t.set_y(1, -0.1);
         ASSERT_EQ(t.finalize(), Status::kOk);
       },
       Status::kImpactDragCoefficientInvalid, 42, 2, "CD2F"},
      {"reference area > 0", [](ImpactLocusData& d) { d.failure_mode[0].reference_area_ft2 = 0.0; },
       Status::kImpactReferenceAreaNotPositive, 42, 1, "reference area"},
      {"reference area finite", [](ImpactLocusData& d) { d.expended_casing[2].reference_area_ft2 = kNaN; },
       Status::kImpactReferenceAreaNotPositive, 43, 3, "reference area"},
      {"casing weight finite", [](ImpactLocusData& d) { d.expended_casing[1].casing_weight_lb = kNaN; },
       Status::kImpactCasingWeightNotPositive, 43, 2, "casing weight"},
      {"every n-th point >= 1", [](ImpactLocusData& d) { d.every_nth_point[0] = 0; },
       Status::kImpactEveryNthPointOutOfRange, 33, 1, "DA6D(17)"},
      {"step in the atmosphere > 0", [](ImpactLocusData& d) { d.steps.in_atmosphere_s = 0.0; },
       Status::kImpactStepSizeNotPositive, 0, 0, "in_atmosphere_s"},
      {"minimum step finite", [](ImpactLocusData& d) { d.steps.min_step_s = kNaN; },
       Status::kImpactStepSizeNotPositive, 0, 0, "min_step_s"},
      {"flight limit > 0", [](ImpactLocusData& d) { d.steps.max_flight_s = -1.0; },
       Status::kImpactStepSizeNotPositive, 0, 0, "max_flight_s"},
  };
  auto mission = reference();
  auto good = std::make_unique<ImpactLocusData>();
  test::build_reference_impact_data(good.get());
  ASSERT_EQ(validate_impact_data(*mission, *good, nullptr), Status::kOk);
  for (const ImpactRejection& row : rows) {
    SCOPED_TRACE(row.what);
    auto data = std::make_unique<ImpactLocusData>(*good);
    row.edit(*data);
    ImpactFault fault;
    EXPECT_EQ(validate_impact_data(*mission, *data, &fault), row.status);
    EXPECT_EQ(fault.data_block, row.data_block);
    EXPECT_EQ(fault.stage, row.stage);
    EXPECT_STREQ(fault.field, row.field);
    EXPECT_EQ(validate_impact_data(*mission, *data, nullptr), row.status);
  }
  // A stage that is not flown needs no impact data.
  auto data = std::make_unique<ImpactLocusData>(*good);
  data->failure_mode[2].present = false;
  test::stage(*mission, 3).in_sequence = false;
  EXPECT_EQ(validate_impact_data(*mission, *data, nullptr), Status::kOk);
}

TEST(Sec19Atmosphere, TableValidationRejectsWhatHasNoAtmosphere) {
  const AtmosphereTable good{};
  ASSERT_EQ(validate_atmosphere_table(good), Status::kOk);
  AtmosphereTable t = good;
  t.base_geopotential_altitude_ft[0] = kNaN;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kValueNotFinite);
  t = good;
  // A later base that is not a number is a value that is not finite, though the layer below it
  // reads it for its thickness (before, it was named as that layer having no thickness).
  t.base_geopotential_altitude_ft[3] = kNaN;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kValueNotFinite);
  t = good;
  t.base_molecular_temperature_R[2] = HUGE_VAL;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kValueNotFinite);
  t = good;
  t.lapse_rate_R_per_ft[1] = kNaN;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kValueNotFinite);
  t = good;
  t.base_density_slug_ft3[kAtmosphereLayers - 1] = -HUGE_VAL;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kValueNotFinite);
  t = good;
  t.base_density_slug_ft3[4] = 0.0;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kAtmosphereTableInvalid);
  t = good;
  t.base_molecular_temperature_R[4] = -1.0;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kAtmosphereTableInvalid);
  t = good;
  t.base_geopotential_altitude_ft[2] = t.base_geopotential_altitude_ft[1];
  EXPECT_EQ(validate_atmosphere_table(t), Status::kAtmosphereTableInvalid) << "a layer of no thickness";
  t = good;
  // A lapse rate that takes T_M through zero before the next base.
  const double thickness_ft = t.base_geopotential_altitude_ft[1] - t.base_geopotential_altitude_ft[0];
  t.lapse_rate_R_per_ft[0] = -2.0 * t.base_molecular_temperature_R[0] / thickness_ft;
  EXPECT_EQ(validate_atmosphere_table(t), Status::kAtmosphereTableInvalid);

  // evaluate_atmosphere: a radius that puts the point at or below the Earth's centre, none at all.
  const Constants constants{};
  AtmosphereSample s;
  EXPECT_EQ(evaluate_atmosphere(good, constants, -3.0e7, 2.09e7, &s), Status::kAtmosphereRadiusNotPositive);
  EXPECT_EQ(evaluate_atmosphere(good, constants, 1000.0, -1.0, &s), Status::kAtmosphereRadiusNotPositive);
  EXPECT_EQ(evaluate_atmosphere(good, constants, 1000.0, 2.09e7, nullptr), Status::kOutputPointerNull);
  // Density beyond the double range (a user table's base density near DBL_MAX, far below its base):
  // refused as not finite rather than returned.
  t = good;
  t.base_density_slug_ft3[0] = 1e308;
  EXPECT_EQ(evaluate_atmosphere(t, constants, -2.0e4, 1e30, &s), Status::kValueNotFinite);
}

// Sec. 7 with a designed stage-1 schedule (BodyDynamicsBlocks::stage1_schedule_*): K_theta and K_q
// linear in stage time between the points, held at the end values outside them.
TEST(BodyDynamics, Sec7_StageOneGainScheduleIsLinearBetweenItsPointsAndHeldBeyond) {
  BodyDynamicsBlocks data;
  data.position_gain[0] = 9.0;
  data.rate_gain_s[0] = 0.9;
  AutopilotGains g = scheduled_stage1_gains(data, 5.0);
  EXPECT_EQ(g.position_gain, 9.0) << "no schedule: the block 33 gains";
  EXPECT_EQ(g.rate_gain_s, 0.9);
  data.stage1_schedule_count = 3;
  const double t[] = {0.0, 10.0, 30.0}, k[] = {1.0, 2.0, 4.0}, q[] = {0.1, 0.2, 0.6};
  for (int i = 0; i < 3; ++i) {
    data.stage1_schedule_time_s[i] = t[i];
    data.stage1_schedule_k_theta[i] = k[i];
    data.stage1_schedule_k_q_s[i] = q[i];
  }
  struct Expected {
    double time_s, k_theta, k_q_s;
  };
  // Hand values: (5 s) 1 + 0.5 (2 - 1), 0.1 + 0.5 (0.2 - 0.1); (20 s) 2 + 0.5 (4 - 2), 0.2 + 0.5 (0.6 - 0.2).
  const Expected expected[] = {{-1.0, 1.0, 0.1}, {0.0, 1.0, 0.1},  {5.0, 1.5, 0.15}, {10.0, 2.0, 0.2},
                               {20.0, 3.0, 0.4}, {30.0, 4.0, 0.6}, {45.0, 4.0, 0.6}};
  for (const Expected& e : expected) {
    SCOPED_TRACE(e.time_s);
    g = scheduled_stage1_gains(data, e.time_s);
    EXPECT_NEAR(g.position_gain, e.k_theta, 1e-15);
    EXPECT_NEAR(g.rate_gain_s, e.k_q_s, 1e-15);
  }
  data.stage1_schedule_count = kMaxGainSchedulePointsPerStage + 1;
  g = scheduled_stage1_gains(data, 5.0);
  EXPECT_EQ(g.position_gain, 9.0) << "a count beyond the capacity is no schedule";

  // Stage codes outside 1..kBodyDynamicsStages are clamped; a stage without its own c.g. table
  // uses stage 1's.
  auto mission = reference();
  BodyDynamicsBlocks& b = mission->body_dynamics;
  MomentConditions c;
  c.stage = 0;
  c.cg_stage_time_s = 3.0;
  c.mach = 0.8;
  c.dynamic_pressure_lbf_ft2 = 500.0;
  const UnitMoments below = unit_moments(b, c);
  c.stage = 1;
  const UnitMoments one = unit_moments(b, c);
  EXPECT_EQ(below.cg_station_ft, one.cg_station_ft);
  EXPECT_EQ(below.m_alpha_lbf_ft_per_rad, one.m_alpha_lbf_ft_per_rad);
  b.cg_station_ft[2].clear();
  c.stage = 3;
  EXPECT_EQ(unit_moments(b, c).cg_station_ft, b.cg_station_ft[0](3.0));
}

// Sec. 8: a parameter change that has no meaning is refused, not made; one that needs no change
// (drag of a stage without a drag table) changes nothing; the burn-rate change carries the stage-1
// zero-alpha window (data block 22) with the stage's time, t / f by hand.
TEST(Sec8ExchangeRatios, ParameterChangesThatCannotBeMadeAreRefused) {
  auto base = reference();
  auto out = std::make_unique<Mission>();
  EXPECT_EQ(perturb_stage_parameter(*base, 2, ExchangeParameter::kJettisonWeight, 1.0, base.get()),
            Status::kOutputAliasesInput)
      << "the output may not be the input";
  EXPECT_EQ(perturb_stage_parameter(*base, 6, ExchangeParameter::kJettisonWeight, 1.0, out.get()),
            Status::kUnknownStageCode)
      << "a coast";
  EXPECT_EQ(perturb_stage_parameter(*base, 5, ExchangeParameter::kJettisonWeight, 1.0, out.get()),
            Status::kUnknownStageCode)
      << "a stage not flown";
  EXPECT_EQ(perturb_stage_parameter(*base, 2, ExchangeParameter::kBurnRate, -100.0, out.get()),
            Status::kExchangePercentChangeTooNegative);
  EXPECT_EQ(perturb_stage_parameter(*base, 2, ExchangeParameter::kSpecificImpulse, -150.0, out.get()),
            Status::kExchangePercentChangeTooNegative);
  const double w0 = test::stage(*base, 3).consumable_weight_lb.y(0);
  EXPECT_EQ(perturb_stage_parameter(*base, 3, ExchangeParameter::kPropellantWeight, -w0, out.get()),
            Status::kExchangePropellantChangeTooNegative);
  ASSERT_EQ(perturb_stage_parameter(*base, 3, ExchangeParameter::kDrag, 2.0, out.get()), Status::kOk);
  EXPECT_TRUE(test::stage(*out, 3).drag_coefficient.empty()) << "stage 3 has no drag table";
  test::stage(*base, 2).reference_area_ft2 = 0.0;
  EXPECT_EQ(perturb_stage_parameter(*base, 2, ExchangeParameter::kDrag, 2.0, out.get()),
            Status::kReferenceAreaMissing);
  EXPECT_EQ(perturb_stage_parameter(*base, 2, static_cast<ExchangeParameter>(9), 2.0, out.get()),
            Status::kUnknownExchangeParameter);
  base = reference();
  ASSERT_TRUE(base->options.zero_alpha_window());
  ASSERT_EQ(perturb_stage_parameter(*base, 1, ExchangeParameter::kBurnRate, 25.0, out.get()), Status::kOk);
  EXPECT_DOUBLE_EQ(out->control.zero_alpha_start_s, base->control.zero_alpha_start_s / 1.25);
  EXPECT_DOUBLE_EQ(out->control.zero_alpha_end_s, base->control.zero_alpha_end_s / 1.25);
  EXPECT_DOUBLE_EQ(test::stage(*out, 1).duration_s, test::stage(*base, 1).duration_s / 1.25);
}

// Sec. 5 partials: no output, a state that is not finite, and no inertial velocity are refused.
TEST(Sec5ConstraintPartials, GuardsRefuseWhatHasNoPartials) {
  const Constants constants{};
  StateVector x = StateVector::Zero();
  x[kStateR] = constants.earth_equatorial_radius_ft;
  InertialJacobian j;
  EXPECT_EQ(inertial_variable_partials(constants, x, nullptr), Status::kOutputPointerNull);
  StateVector bad = x;
  bad[kStateV] = kNaN;
  EXPECT_EQ(inertial_variable_partials(constants, bad, &j), Status::kNonFiniteState);
  // At rest (V = 0 relative to the Earth) at the pole, where the Earth's rotation adds no speed:
  // no inertial velocity, so no flight-path angle or heading to differentiate.
  x[kStateLambda] = 0.5 * kPi;
  EXPECT_EQ(inertial_variable_partials(constants, x, &j), Status::kZeroVelocity);
  ConstraintPoint point;
  point.state = x;
  Eigen::Matrix<double, 6, 1> partials;
  EXPECT_EQ(stagnation_heating_rate_partials(constants, 0.5, 0.0023769, point, nullptr),
            Status::kOutputPointerNull);
  point.ddensity_dh = kNaN;
  EXPECT_EQ(stagnation_heating_rate_partials(constants, 0.5, 0.0023769, point, &partials),
            Status::kValueNotFinite);
  point.ddensity_dh = 0.0;
  point.state[kStateGamma] = HUGE_VAL;
  EXPECT_EQ(stagnation_heating_rate_partials(constants, 0.5, 0.0023769, point, &partials),
            Status::kValueNotFinite);
}

}  // namespace
}  // namespace tolip
