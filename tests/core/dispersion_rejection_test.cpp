// Dispersion data (manual Sec. 15, Sec. 22 data blocks 46-55) and the Monte Carlo draws of them
// (issue 11, dispersion/monte_carlo.hpp), without flying: every rejection of
// validate_dispersion_data names its Status and code; build_dispersed_case refuses what cannot fly;
// the Monte Carlo rules of which source is drawn, which low table pairs with which high one, and
// the scalar sources moved by their own draw (z = counter_normal(seed, sample, leader) / 3, the
// deck's change being three sigma) against a hand computation of the changed case. One flight:
// the max |q-bar alpha| recomputed from the wind equals the one from the flight's own air alpha.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

#include "support/dispersion_sources.hpp"
#include "support/reference_mission.hpp"
#include "tolip/dispersion/dispersion.hpp"
#include "tolip/dispersion/monte_carlo.hpp"

namespace tolip {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Fixture {
  Mission mission;
  PreparedCase prepared;
  DispersionData data;
  DispersionWorkspace workspace;
};

std::unique_ptr<Fixture> make_fixture() {
  auto f = std::make_unique<Fixture>();
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &f->mission);
  EXPECT_EQ(prepare_case(f->mission, &f->prepared), Status::kOk);
  return f;
}

DispersionNominal nominal_of(const Fixture& f, bool body_dynamics) {
  return test::dispersion_nominal(f.mission, nullptr, body_dynamics);
}

constexpr auto add = test::add_dispersion_source;

template <int N>
void table(Table<N>* t, std::initializer_list<double> x, std::initializer_list<double> y,
           bool finalize = true) {
  t->clear();
  auto yi = y.begin();
  for (double xi : x) ASSERT_EQ(t->append(xi, *yi++), Status::kOk);
  if (finalize) {
    ASSERT_EQ(t->finalize(), Status::kOk);
  }
}

// A valid code-3 source (stage 2 thrust and weight, 0-40 s).
void thrust_source(DispersionSource* s) {
  table(&s->vacuum_thrust_lbf, {0.0, 20.0, 40.0}, {50000.0, 45000.0, 0.0});
  table(&s->consumable_weight_lb, {0.0, 20.0, 40.0}, {6000.0, 3000.0, 0.0});
}

struct DataRejection {
  const char* what;
  int code;
  void (*edit)(DispersionSource&);
  Status status;
};

TEST(Sec22DispersionBlocks, EveryRejectionNamesItsStatusAndCode) {
  static const DataRejection rows[] = {
      {"thrust code of another stage", 3, [](DispersionSource& s) { s.stage = 3; },
       Status::kDispersionStageCodeMismatch},
      {"thrust table given", 3, [](DispersionSource& s) { s.vacuum_thrust_lbf.clear(); },
       Status::kTableEmpty},
      {"weight table given", 3, [](DispersionSource& s) { s.consumable_weight_lb.clear(); },
       Status::kTableEmpty},
      {"thrust table finalized", 3, [](DispersionSource& s) { s.vacuum_thrust_lbf.set_y(1, 1.0); },
       Status::kTableNotMonotonic},
      {"weight table finalized", 3, [](DispersionSource& s) { s.consumable_weight_lb.set_y(1, 1.0); },
       Status::kTableNotMonotonic},
      {"as many weight as thrust points", 3,
       [](DispersionSource& s) {
         table(&s.consumable_weight_lb, {0.0, 40.0}, {6000.0, 0.0});
       },
       Status::kThrustWeightTimesDiffer},
      {"tables from stage time 0", 3,
       [](DispersionSource& s) {
         table(&s.vacuum_thrust_lbf, {1.0, 20.0, 40.0}, {1.0, 1.0, 0.0});
         table(&s.consumable_weight_lb, {1.0, 20.0, 40.0}, {2.0, 1.0, 0.0});
       },
       Status::kDispersionThrustTableTimesInvalid},
      {"a burn longer than 0 s", 3,
       [](DispersionSource& s) {
         table(&s.vacuum_thrust_lbf, {0.0}, {1.0});
         table(&s.consumable_weight_lb, {0.0}, {1.0});
       },
       Status::kDispersionThrustTableTimesInvalid},
      {"the same times", 3,
       [](DispersionSource& s) {
         table(&s.consumable_weight_lb, {0.0, 21.0, 40.0}, {6000.0, 3000.0, 0.0});
       },
       Status::kThrustWeightTimesDiffer},
      {"thrust >= 0", 3,
       [](DispersionSource& s) {
         table(&s.vacuum_thrust_lbf, {0.0, 20.0, 40.0}, {1.0, -1.0, 0.0});
       },
       Status::kDispersionThrustNegative},
      {"weight >= 0", 3,
       [](DispersionSource& s) {
         table(&s.consumable_weight_lb, {0.0, 20.0, 40.0}, {6000.0, -1.0, -2.0});
       },
       Status::kNegativeWeight},
      {"weight not increasing", 3,
       [](DispersionSource& s) {
         table(&s.consumable_weight_lb, {0.0, 20.0, 40.0}, {6000.0, 6001.0, 0.0});
       },
       Status::kConsumableWeightIncreases},
      {"C_M_alpha table given", 19, [](DispersionSource&) {}, Status::kTableEmpty},
      {"C_M_alpha table finalized", 19,
       [](DispersionSource& s) {
         table(&s.pitching_moment_per_rad, {0.0, 2.0}, {-1.0, -2.0}, false);
       },
       Status::kTableNotMonotonic},
      {"wind speed given", 36,
       [](DispersionSource& s) {
         table(&s.wind.azimuth_rad, {0.0, 1e4}, {0.0, 0.0});
       },
       Status::kTableEmpty},
      {"wind azimuth given", 36,
       [](DispersionSource& s) {
         table(&s.wind.speed_ft_s, {0.0, 1e4}, {0.0, 50.0});
       },
       Status::kTableEmpty},
      {"wind tables finalized", 37,
       [](DispersionSource& s) {
         table(&s.wind.speed_ft_s, {0.0, 1e4}, {0.0, 50.0});
         table(&s.wind.azimuth_rad, {0.0, 1e4}, {0.0, 0.0}, false);
       },
       Status::kTableNotMonotonic},
      {"drag change below 100 %", 17, [](DispersionSource& s) { s.drag_variation_fraction = -1.0; },
       Status::kDispersionDragVariationOutOfRange},
      {"tip-off of stage 4 or 5", 31, [](DispersionSource& s) { s.stage = 3; },
       Status::kDispersionStageNotSpun},
      {"weight code of its own stage", 11, [](DispersionSource& s) { s.stage = 3; },
       Status::kDispersionStageCodeMismatch},
      {"deadband finite", 24, [](DispersionSource& s) { s.deadband_rad = kNaN; }, Status::kValueNotFinite},
      {"launch change finite", 33, [](DispersionSource& s) { s.launch_change_rad = HUGE_VAL; },
       Status::kValueNotFinite},
      {"misalignment station finite", 21, [](DispersionSource& s) { s.thrust_station_ft = -HUGE_VAL; },
       Status::kValueNotFinite},
  };
  for (const DataRejection& row : rows) {
    SCOPED_TRACE(row.what);
    auto data = std::make_unique<DispersionData>();
    DispersionSource& s = add(data.get(), row.code);
    if (row.code == 3) thrust_source(&s);
    int fault_code = -1;
    if (row.code != 19 && row.code < 36) {
      ASSERT_EQ(validate_dispersion_data(*data, &fault_code), Status::kOk)
          << "the row's source before its edit";
      EXPECT_EQ(fault_code, 0);
    }
    row.edit(s);
    EXPECT_EQ(validate_dispersion_data(*data, &fault_code), row.status);
    EXPECT_EQ(fault_code, row.code);
  }
  // The code list itself: a count beyond the capacity, an unknown code (39), a code out of order.
  auto data = std::make_unique<DispersionData>();
  int fault_code = -1;
  data->count = kMaxDispersionSources + 1;
  EXPECT_EQ(validate_dispersion_data(*data, &fault_code), Status::kDispersionCodeInvalid);
  data->count = -1;
  EXPECT_EQ(validate_dispersion_data(*data, &fault_code), Status::kDispersionCodeInvalid);
  data->count = 0;
  add(data.get(), 24);
  data->sources[0].code = 39;
  EXPECT_EQ(validate_dispersion_data(*data, &fault_code), Status::kDispersionCodeInvalid);
  EXPECT_EQ(fault_code, 39);
  // Stage 5 through the stage-4 codes (five stages without the squeeze) is accepted.
  data->count = 0;
  add(data.get(), 15).stage = 5;
  add(data.get(), 32).stage = 5;
  EXPECT_EQ(validate_dispersion_data(*data, &fault_code), Status::kOk);
  EXPECT_EQ(fault_code, 0);
  EXPECT_EQ(dispersion_source_stage(data->sources[0]), 5);
  EXPECT_EQ(dispersion_source_stage(data->sources[1]), 5);
  DispersionSource unknown;
  unknown.code = 39;
  EXPECT_EQ(dispersion_source_stage(unknown), 0);
}

// Sec. 15: what build_dispersed_case refuses before it flies (and the nominal's plane 40).
TEST(Sec15Dispersions, CasesThatCannotBeBuiltAreNamed) {
  auto f = make_fixture();
  DispersionData& data = f->data;
  add(&data, 40);
  EXPECT_EQ(build_dispersed_case(nominal_of(*f, false), f->prepared, data.sources[0], &f->workspace),
            Status::kDispersionCodeInvalid)
      << "plane 40 is the nominal, not a dispersed case";
  // A stage-1 burn no longer than the lift-off.
  DispersionSource& short_burn = add(&data, 1);
  const double liftoff_s = f->mission.launch.liftoff_duration_s;
  table(&short_burn.vacuum_thrust_lbf, {0.0, liftoff_s}, {1000.0, 0.0});
  table(&short_burn.consumable_weight_lb, {0.0, liftoff_s}, {100.0, 0.0});
  EXPECT_EQ(build_dispersed_case(nominal_of(*f, false), f->prepared, short_burn, &f->workspace),
            Status::kLiftoffLongerThanStage1);
  // Tip-off of a stage that is not spun: with IP(9) = 2 stage 4 is continuous.
  DispersionSource& tipoff = add(&data, 30);
  tipoff.stage = 4;
  tipoff.tipoff_rad = 0.01;
  f->mission.options.ip[9] = 2;
  EXPECT_EQ(build_dispersed_case(nominal_of(*f, false), f->prepared, tipoff, &f->workspace),
            Status::kDispersionStageNotSpun);
  // IP(9) = 1: stage 4's tip-off moves stage 4, its coast 9, and stage 5 and coast 10 with it.
  f->mission.options.ip[9] = 1;
  ASSERT_EQ(build_dispersed_case(nominal_of(*f, false), f->prepared, tipoff, &f->workspace), Status::kOk);
  for (int code : {4, 5, 9, 10})
    EXPECT_EQ(f->workspace.perturbation.theta_offset_rad[stage_index(code)], 0.01);
  EXPECT_EQ(f->workspace.perturbation.theta_offset_rad[stage_index(3)], 0.0);

  // run_dispersions without a nominal.
  auto result = std::make_unique<DispersionResult>();
  EXPECT_EQ(run_dispersions(DispersionNominal{}, data, &f->workspace, result.get()),
            Status::kDispersionNominalNotPrepared);
  EXPECT_EQ(result->status, Status::kDispersionNominalNotPrepared);
  // A flight that failed, or never flew, records nothing.
  auto flown = std::make_unique<Trajectory>();
  auto record = std::make_unique<DispersedTrajectory>();
  flown->status = Status::kNonFiniteState;
  EXPECT_EQ(record_dispersed_trajectory(f->mission, f->prepared, *flown, *flown, nullptr, record.get()),
            Status::kNonFiniteState);
  flown->status = Status::kOk;
  flown->point_count = 0;
  EXPECT_EQ(record_dispersed_trajectory(f->mission, f->prepared, *flown, *flown, nullptr, record.get()),
            Status::kTrajectoryEmpty);
}

// Page 22-30 stacked tables (codes 7-8 with block 55): stage 4 (0-10 s), a 2 s coast of zero
// thrust, stage 5 (0-5 s), restarting at 0 or continuing, with block 55 = (10, 5).
void stacked_source(DispersionSource* s, bool restart) {
  const double o = restart ? 0.0 : 12.0;  // stage 5 ignition in table time
  if (restart) {
    table(&s->vacuum_thrust_lbf, {0.0, 5.0, 10.0, 0.0, 2.0, 0.0, 5.0},
          {900.0, 800.0, 0.0, 0.0, 0.0, 300.0, 0.0}, false);
    table(&s->consumable_weight_lb, {0.0, 5.0, 10.0, 0.0, 2.0, 0.0, 5.0},
          {100.0, 50.0, 0.0, 0.0, 0.0, 40.0, 0.0}, false);
  } else {
    table(&s->vacuum_thrust_lbf, {0.0, 5.0, 10.0, o, o + 5.0}, {900.0, 800.0, 0.0, 300.0, 0.0});
    table(&s->consumable_weight_lb, {0.0, 5.0, 10.0, o, o + 5.0}, {100.0, 50.0, 0.0, 40.0, 0.0});
  }
  s->stacked_stage4_5_tables = true;
  s->stage4_5_durations_s[0] = 10.0;
  s->stage4_5_durations_s[1] = 5.0;
}

// Sec. 22 data block 55 and page 22-30: both unambiguous layouts of the stacked tables split at
// block 55's durations into stage 4's and stage 5's own tables (stage time from 0, burn time the
// last time), and every table that does not split is refused by name, with its code, before
// anything flies.
TEST(Sec22DispersionBlocks, StackedStage45TablesSplitInEitherLayoutOrAreRefusedByName) {
  for (bool restart : {true, false}) {
    SCOPED_TRACE(restart ? "restarting" : "continuing");
    DispersionSource s;
    s.code = 7;
    s.stage = 4;
    stacked_source(&s, restart);
    StackedStage45Split split;
    ASSERT_EQ(find_stacked_stage4_5_split(s, &split), Status::kOk);
    EXPECT_EQ(split.stage4_last, 2);
    EXPECT_EQ(split.stage5_first, restart ? 5 : 3);
    EXPECT_EQ(split.stage5_offset_s, restart ? 0.0 : 12.0);
    StageData stage4, stage5;
    ASSERT_EQ(unstack_stage4_5_tables(s, &stage4, &stage5), Status::kOk);
    ASSERT_EQ(stage4.vacuum_thrust_lbf.size(), 3);
    ASSERT_EQ(stage5.vacuum_thrust_lbf.size(), 2);
    EXPECT_EQ(stage4.duration_s, 10.0);
    EXPECT_EQ(stage5.duration_s, 5.0);
    EXPECT_EQ(stage5.vacuum_thrust_lbf.x(0), 0.0);
    EXPECT_EQ(stage5.vacuum_thrust_lbf.y(0), 300.0);
    EXPECT_EQ(stage5.consumable_weight_lb.y(0), 40.0);   // stage 5's own remaining weight
    EXPECT_EQ(stage4.consumable_weight_lb.y(0), 100.0);  // stage 4's own, nothing added
    EXPECT_TRUE(stage4.vacuum_thrust_lbf.finalized() && stage5.consumable_weight_lb.finalized());
    DispersionData data;
    data.count = 1;
    data.sources[0] = s;
    int fault_code = -1;
    EXPECT_EQ(validate_dispersion_data(data, &fault_code), Status::kOk);

    struct Row {
      const char* what;
      void (*edit)(DispersionSource&);
      Status status;
    };
    const Row rows[] = {
        {"stage 4 duration not a table time", [](DispersionSource& d) { d.stage4_5_durations_s[0] = 9.0; },
         Status::kDispersionStageDurationsMismatch},
        {"stage 5 duration not its part's final time",
         [](DispersionSource& d) { d.stage4_5_durations_s[1] = 4.0; },
         Status::kDispersionStageDurationsMismatch},
        {"block 55 missing (zero durations)",
         [](DispersionSource& d) { d.stage4_5_durations_s[0] = d.stage4_5_durations_s[1] = 0.0; },
         Status::kDispersionStageDurationsMismatch},
        {"stage 5 duration not finite", [](DispersionSource& d) { d.stage4_5_durations_s[1] = kNaN; },
         Status::kDispersionStageDurationsMismatch},
        {"stage code 5 on the stage-4 area", [](DispersionSource& d) { d.stage = 5; },
         Status::kDispersionStageCodeMismatch},
        {"weight table given", [](DispersionSource& d) { d.consumable_weight_lb.clear(); },
         Status::kTableEmpty},
    };
    for (const Row& row : rows) {
      SCOPED_TRACE(row.what);
      data.sources[0] = s;
      row.edit(data.sources[0]);
      EXPECT_EQ(validate_dispersion_data(data, &fault_code), row.status);
      EXPECT_EQ(fault_code, 7);
    }
  }
  // Not splittable: thrust in the coast; a restart not at stage time 0; no coast between the stages.
  DispersionSource s;
  s.code = 8;
  s.stage = 4;
  stacked_source(&s, true);
  s.vacuum_thrust_lbf.set_y(4, 10.0);  // the coast's 2 s entry
  StackedStage45Split split;
  EXPECT_EQ(find_stacked_stage4_5_split(s, &split), Status::kDispersionStackedTablesNotSplittable);
  table(&s.vacuum_thrust_lbf, {0.0, 5.0, 10.0, 1.0, 6.0}, {900.0, 800.0, 0.0, 300.0, 0.0}, false);
  table(&s.consumable_weight_lb, {0.0, 5.0, 10.0, 1.0, 6.0}, {100.0, 50.0, 0.0, 40.0, 0.0}, false);
  EXPECT_EQ(find_stacked_stage4_5_split(s, &split), Status::kDispersionStackedTablesNotSplittable);
  table(&s.vacuum_thrust_lbf, {0.0, 5.0, 10.0, 15.0}, {900.0, 800.0, 300.0, 0.0});
  table(&s.consumable_weight_lb, {0.0, 5.0, 10.0, 15.0}, {100.0, 50.0, 40.0, 0.0});
  EXPECT_EQ(find_stacked_stage4_5_split(s, &split), Status::kDispersionStackedTablesNotSplittable);
  // A part that breaks a per-stage rule: stage 5's weight rising.
  stacked_source(&s, false);
  s.consumable_weight_lb.set_y(4, 41.0);
  EXPECT_EQ(find_stacked_stage4_5_split(s, &split), Status::kConsumableWeightIncreases);

  // A vehicle without stage 5 (the four-stage reference): named when the code is built, not flown.
  auto f = make_fixture();
  stacked_source(&s, true);
  EXPECT_EQ(build_dispersed_case(nominal_of(*f, false), f->prepared, s, &f->workspace),
            Status::kDispersionStackedTablesNeedStage5);
}

// Which sources a Monte Carlo sample draws: a low code whose high code is listed shares the high
// code's draw (it is not drawn on its own); misalignment and C_M_alpha only in a 6D case; tip-off
// only for a spun stage; thrust only for a flown stage and not from stacked stage-4/5 tables.
TEST(MonteCarlo, SourcesDrawnFollowTheirFamilyAndTheCase) {
  auto f = make_fixture();
  DispersionData& d = f->data;
  add(&d, 1);
  add(&d, 2);
  add(&d, 7).stacked_stage4_5_tables = true;
  add(&d, 10);  // low without its high (9): drawn on its own
  add(&d, 19);
  add(&d, 20);
  add(&d, 21);
  add(&d, 30).stage = 4;
  add(&d, 36);
  add(&d, 37);
  add(&d, 38);
  add(&d, 40);
  const DispersionNominal plain = nominal_of(*f, false);
  const DispersionNominal six_d = nominal_of(*f, true);
  const bool drawn_3d[] = {true, false, false, true, false, false, false, true, true, false, true, false};
  const bool drawn_6d[] = {true, false, false, true, true, false, true, true, true, false, true, false};
  for (int k = 0; k < d.count; ++k) {
    SCOPED_TRACE(d.sources[k].code);
    EXPECT_EQ(monte_carlo_draws_source(plain, d, k), drawn_3d[k]);
    EXPECT_EQ(monte_carlo_draws_source(six_d, d, k), drawn_6d[k]);
  }
  // Tip-off of a stage that is not spun (IP(9) = 2: stage 4 continuous) is not drawn.
  f->mission.options.ip[9] = 2;
  EXPECT_FALSE(monte_carlo_draws_source(plain, d, 7));
  f->mission.options.ip[9] = 1;
  // The low tables a negative draw flies: 2 for 1, 20 for 19 (6D), 37 for 36; none for the yaw
  // wind 38, a scalar source, or a source not drawn.
  EXPECT_EQ(monte_carlo_low_partner(plain, d, 0), 1);
  EXPECT_EQ(monte_carlo_low_partner(six_d, d, 4), 5);
  EXPECT_EQ(monte_carlo_low_partner(plain, d, 4), -1);
  EXPECT_EQ(monte_carlo_low_partner(plain, d, 8), 9);
  EXPECT_EQ(monte_carlo_low_partner(plain, d, 10), -1);
  EXPECT_EQ(monte_carlo_low_partner(plain, d, 3), -1);
  EXPECT_EQ(monte_carlo_low_partner(plain, d, 1), -1);
  // A stacked low table is not the partner of a plain high one.
  d.sources[1].stacked_stage4_5_tables = true;
  EXPECT_EQ(monte_carlo_low_partner(plain, d, 0), -1);
}

// Monte Carlo: one sample of the scalar sources equals the case changed by hand with the sample's
// draws z_c = counter_normal(seed, sample, leader(c)) / 3 (a low code shares its high code's draw).
TEST(MonteCarlo, ScalarSourcesMoveTheCaseByTheirOwnDrawOverThree) {
  auto f = make_fixture();
  DispersionData& d = f->data;
  add(&d, 11).weight_increment_lb = 30.0;
  add(&d, 17).drag_variation_fraction = 0.1;
  add(&d, 24).deadband_rad = 0.004;
  add(&d, 26).deadband_rad = 0.002;
  add(&d, 30).tipoff_rad = 0.02;
  add(&d, 33).launch_change_rad = 0.003;
  add(&d, 35).launch_change_rad = -0.001;  // low code of 34 (not listed): drawn on its own, with 34's draw
  const std::uint64_t seed = 1966, sample = 7;
  const auto z = [&](int leader) {
    return counter_normal(seed, sample, static_cast<std::uint32_t>(leader)) / 3.0;
  };
  const DispersionNominal nominal = nominal_of(*f, false);
  int fault_code = -1;
  ASSERT_EQ(check_monte_carlo_data(nominal, d, &fault_code), Status::kOk);
  ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, d, seed, sample, &f->workspace), Status::kOk);
  const DispersionWorkspace& ws = f->workspace;
  EXPECT_DOUBLE_EQ(ws.mission.vehicle.stages[stage_index(2)].jettison_weight_lb,
                   f->mission.vehicle.stages[stage_index(2)].jettison_weight_lb + z(11) * 30.0);
  const AeroTable& cd = f->mission.vehicle.stages[stage_index(1)].drag_coefficient;
  EXPECT_DOUBLE_EQ(ws.mission.vehicle.stages[stage_index(1)].drag_coefficient.y(4),
                   cd.y(4) * (1.0 + z(17) * 0.1));
  EXPECT_DOUBLE_EQ(ws.perturbation.theta_offset_rad[stage_index(2)], z(24) * 0.004 + z(34) * -0.001);
  EXPECT_DOUBLE_EQ(ws.perturbation.chi_offset_rad[stage_index(2)], z(26) * 0.002);
  // Tip-off (IP(9) = 1): stage 4, its coast 9, stage 5 and coast 10, each with the launch attitude.
  for (int code : {4, 5, 9, 10})
    EXPECT_DOUBLE_EQ(ws.perturbation.theta_offset_rad[stage_index(code)], z(30) * 0.02 + z(34) * -0.001);
  EXPECT_DOUBLE_EQ(ws.mission.launch.azimuth_rad, f->mission.launch.azimuth_rad + z(33) * 0.003);
  EXPECT_FALSE(ws.program_mapped);
  EXPECT_EQ(ws.perturbation.wind, nullptr);
  // Another sample draws otherwise.
  ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, d, seed, sample + 1, &f->workspace), Status::kOk);
  EXPECT_NE(ws.mission.launch.azimuth_rad, f->mission.launch.azimuth_rad + z(33) * 0.003);

  // A drag change the draw takes to -100 % or beyond is refused, not flown.
  d.sources[1].drag_variation_fraction = 1e6;
  EXPECT_EQ(build_monte_carlo_case(nominal, f->prepared, d, seed, sample, &f->workspace),
            Status::kDispersionDragVariationOutOfRange);
  // An unknown code, and no nominal.
  d.sources[1].code = 39;
  EXPECT_EQ(build_monte_carlo_case(nominal, f->prepared, d, seed, sample, &f->workspace),
            Status::kDispersionCodeInvalid);
  EXPECT_EQ(check_monte_carlo_data(DispersionNominal{}, d, &fault_code),
            Status::kDispersionNominalNotPrepared);
  EXPECT_EQ(prepare_monte_carlo(DispersionNominal{}, &f->workspace), Status::kDispersionNominalNotPrepared);
}

// The workspace keeps its copy of the nominal's mission between samples (MonteCarloEdits): a
// sample built after others is the one built in a fresh workspace, and a sample that no longer
// draws a table flies the nominal's table again.
TEST(MonteCarlo, SampleBuiltAfterOtherSamplesEqualsTheSampleBuiltAfresh) {
  auto f = make_fixture();
  DispersionData& d = f->data;
  thrust_source(&add(&d, 3));
  add(&d, 11).weight_increment_lb = 30.0;
  add(&d, 17).drag_variation_fraction = 0.1;
  add(&d, 33).launch_change_rad = 0.003;
  const DispersionNominal nominal = nominal_of(*f, false);
  auto fresh = std::make_unique<DispersionWorkspace>();
  ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, d, 5, 7, fresh.get()), Status::kOk);
  ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, d, 5, 8, &f->workspace), Status::kOk);
  ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, d, 5, 7, &f->workspace), Status::kOk);
  const DispersionWorkspace& ws = f->workspace;
  const int s2 = stage_index(2);
  ASSERT_EQ(ws.prepared.modified_thrust_lbf[s2].size(), fresh->prepared.modified_thrust_lbf[s2].size());
  for (int i = 0; i < ws.prepared.modified_thrust_lbf[s2].size(); ++i) {
    EXPECT_EQ(ws.prepared.modified_thrust_lbf[s2].y(i), fresh->prepared.modified_thrust_lbf[s2].y(i)) << i;
  }
  EXPECT_EQ(ws.mission.vehicle.stages[s2].jettison_weight_lb,
            fresh->mission.vehicle.stages[s2].jettison_weight_lb);
  EXPECT_EQ(ws.mission.launch.azimuth_rad, fresh->mission.launch.azimuth_rad);
  const AeroTable& cd = ws.mission.vehicle.stages[stage_index(1)].drag_coefficient;
  for (int i = 0; i < cd.size(); ++i) {
    EXPECT_EQ(cd.y(i), fresh->mission.vehicle.stages[stage_index(1)].drag_coefficient.y(i)) << i;
  }

  // Without the thrust and drag sources the nominal's tables and weights are flown again.
  DispersionData deadband_only;
  add(&deadband_only, 24).deadband_rad = 0.004;
  ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, deadband_only, 5, 7, &f->workspace), Status::kOk);
  const StageData& flown = ws.mission.vehicle.stages[s2];
  const StageData& given = f->mission.vehicle.stages[s2];
  EXPECT_EQ(flown.duration_s, given.duration_s);
  ASSERT_EQ(flown.vacuum_thrust_lbf.size(), given.vacuum_thrust_lbf.size());
  for (int i = 0; i < given.vacuum_thrust_lbf.size(); ++i) {
    EXPECT_EQ(flown.vacuum_thrust_lbf.y(i), given.vacuum_thrust_lbf.y(i)) << i;
  }
  EXPECT_EQ(flown.jettison_weight_lb, given.jettison_weight_lb);
  EXPECT_EQ(ws.mission.launch.azimuth_rad, f->mission.launch.azimuth_rad);
  const AeroTable& nominal_cd = f->mission.vehicle.stages[stage_index(1)].drag_coefficient;
  for (int i = 0; i < nominal_cd.size(); ++i) EXPECT_EQ(cd.y(i), nominal_cd.y(i)) << i;
}

// Page 22-30 in the Monte Carlo: stacked stage-4/5 tables (codes 7-8 with block 55) are drawn on a
// five-stage vehicle, unstacked and blended stage by stage with the one draw of code 7: with one
// stage dispersed (the stage's own tables, thrust x 1.03, times / 1.03) and the other's nominal
// tables stacked with it, the dispersed stage of a sample is, bit for bit, that of the per-stage
// form (code 7 on stage 4, or with stage code 5) of the same seed and sample; the other keeps its
// nominal burn time. A sample flies; the grids are checked for both stages before it.
TEST(MonteCarlo, StackedStage45TablesBlendEachStageAsTheirPerStageForm) {
  auto f = make_fixture();
  DispersionData& d = f->data;
  d.count = 0;
  test::stack_stage4_5_tables(f->mission.vehicle.stages[stage_index(4)],
                              f->mission.vehicle.stages[stage_index(4)], true, &add(&d, 7));
  EXPECT_FALSE(monte_carlo_draws_source(nominal_of(*f, false), d, 0));  // no stage 5
  test::make_five_stage_vehicle(&f->mission);
  ASSERT_EQ(prepare_case(f->mission, &f->prepared), Status::kOk);
  const DispersionNominal nominal = nominal_of(*f, false);
  const StageData n4 = f->mission.vehicle.stages[stage_index(4)];
  const StageData n5 = f->mission.vehicle.stages[stage_index(5)];
  StageData high;
  for (int i = 0; i < n4.vacuum_thrust_lbf.size(); ++i) {
    const double t = n4.vacuum_thrust_lbf.x(i) / 1.03;
    ASSERT_EQ(high.vacuum_thrust_lbf.append(t, 1.03 * n4.vacuum_thrust_lbf.y(i)), Status::kOk);
    ASSERT_EQ(high.consumable_weight_lb.append(t, n4.consumable_weight_lb.y(i)), Status::kOk);
  }
  ASSERT_EQ(high.vacuum_thrust_lbf.finalize(), Status::kOk);
  ASSERT_EQ(high.consumable_weight_lb.finalize(), Status::kOk);
  auto per_stage = std::make_unique<DispersionWorkspace>();
  for (int dispersed : {4, 5}) {
    SCOPED_TRACE(dispersed);
    DispersionData per;
    DispersionSource& p = add(&per, 7);
    p.stage = dispersed;
    p.vacuum_thrust_lbf = high.vacuum_thrust_lbf;
    p.consumable_weight_lb = high.consumable_weight_lb;
    d.count = 0;
    test::stack_stage4_5_tables(dispersed == 4 ? high : n4, dispersed == 5 ? high : n5, true, &add(&d, 7));
    ASSERT_TRUE(monte_carlo_draws_source(nominal, d, 0));
    int fault_code = -1;
    ASSERT_EQ(check_monte_carlo_data(nominal, d, &fault_code), Status::kOk);
    for (std::uint64_t sample : {3u, 4u}) {
      ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, per, 1966, sample, per_stage.get()),
                Status::kOk);
      ASSERT_EQ(build_monte_carlo_case(nominal, f->prepared, d, 1966, sample, &f->workspace), Status::kOk);
      const StageData& a = f->workspace.mission.vehicle.stages[stage_index(dispersed)];
      const StageData& b = per_stage->mission.vehicle.stages[stage_index(dispersed)];
      EXPECT_EQ(a.duration_s, b.duration_s);
      EXPECT_NE(a.duration_s, (dispersed == 4 ? n4 : n5).duration_s);
      ASSERT_EQ(a.vacuum_thrust_lbf.size(), b.vacuum_thrust_lbf.size());
      for (int i = 0; i < a.vacuum_thrust_lbf.size(); ++i) {
        EXPECT_EQ(a.vacuum_thrust_lbf.x(i), b.vacuum_thrust_lbf.x(i)) << i;
        EXPECT_EQ(a.vacuum_thrust_lbf.y(i), b.vacuum_thrust_lbf.y(i)) << i;
        EXPECT_EQ(a.consumable_weight_lb.y(i), b.consumable_weight_lb.y(i)) << i;
      }
      const int other = dispersed == 4 ? 5 : 4;
      EXPECT_EQ(f->workspace.mission.vehicle.stages[stage_index(other)].duration_s,
                f->mission.vehicle.stages[stage_index(other)].duration_s);
    }
  }
  // A sample of the stacked source flies.
  ASSERT_EQ(prepare_monte_carlo(nominal, &f->workspace), Status::kOk);
  auto nominal_values = std::make_unique<DispersedTrajectory>();
  ASSERT_EQ(record_dispersed_trajectory(f->mission, f->workspace.nominal_prepared, f->workspace.nominal,
                                        f->workspace.nominal, nullptr, nominal_values.get()),
            Status::kOk);
  auto out = std::make_unique<DispersedTrajectory>();
  EXPECT_EQ(fly_monte_carlo_sample(nominal, d, 1966, 3, *nominal_values, &f->workspace, out.get()),
            Status::kOk);
  EXPECT_NE(out->dispersions[4][static_cast<int>(StagingVariable::kVelocity)], 0.0);
}

// Table sources are blended on the union of their grids: more points than the tables hold is
// named by the code whose table overflows, before anything flies.
TEST(MonteCarlo, UnionGridsBeyondTheTableCapacityAreNamedByCode) {
  auto f = make_fixture();
  DispersionData& d = f->data;
  // Stage 2 thrust: the nominal's 22 points plus 110 at other normalized times.
  DispersionSource& thrust = add(&d, 3);
  for (int i = 0; i < 110; ++i) {
    const double t = 0.37 * i + 0.011;
    ASSERT_EQ(thrust.vacuum_thrust_lbf.append(i == 0 ? 0.0 : t, 10000.0), Status::kOk);
    ASSERT_EQ(thrust.consumable_weight_lb.append(i == 0 ? 0.0 : t, 5000.0 - 40.0 * i), Status::kOk);
  }
  ASSERT_EQ(thrust.vacuum_thrust_lbf.finalize(), Status::kOk);
  ASSERT_EQ(thrust.consumable_weight_lb.finalize(), Status::kOk);
  int fault_code = 0;
  EXPECT_EQ(check_monte_carlo_data(nominal_of(*f, false), d, &fault_code), Status::kTooManyTablePoints);
  EXPECT_EQ(fault_code, 3);
  EXPECT_EQ(build_monte_carlo_case(nominal_of(*f, false), f->prepared, d, 1, 1, &f->workspace),
            Status::kTooManyTablePoints);

  // Winds: the yaw profile (38) on the union of its grid and the high profile's (36).
  d.count = 0;
  DispersionSource& high = add(&d, 36);
  DispersionSource& yaw = add(&d, 38);
  for (int i = 0; i < kMaxWindTablePoints; ++i) {
    ASSERT_EQ(high.wind.speed_ft_s.append(100.0 * i, 10.0), Status::kOk);
    ASSERT_EQ(high.wind.azimuth_rad.append(100.0 * i, 0.0), Status::kOk);
    ASSERT_EQ(yaw.wind.speed_ft_s.append(100.0 * i + 50.0, 10.0), Status::kOk);
    ASSERT_EQ(yaw.wind.azimuth_rad.append(100.0 * i + 50.0, 1.0), Status::kOk);
  }
  for (DispersionSource* s : {&high, &yaw}) {
    ASSERT_EQ(s->wind.speed_ft_s.finalize(), Status::kOk);
    ASSERT_EQ(s->wind.azimuth_rad.finalize(), Status::kOk);
  }
  EXPECT_EQ(check_monte_carlo_data(nominal_of(*f, false), d, &fault_code), Status::kTooManyTablePoints);
  EXPECT_EQ(fault_code, 36);
  EXPECT_EQ(build_monte_carlo_case(nominal_of(*f, false), f->prepared, d, 1, 1, &f->workspace),
            Status::kTooManyTablePoints);

  // C_M_alpha (6D): the nominal's Mach grid and another, disjoint, beyond the capacity.
  d.count = 0;
  DispersionSource& moment = add(&d, 19);
  for (int i = 0; i < kMaxAeroTablePoints; ++i)
    ASSERT_EQ(moment.pitching_moment_per_rad.append(0.013 + 0.1 * i, -1.0), Status::kOk);
  ASSERT_EQ(moment.pitching_moment_per_rad.finalize(), Status::kOk);
  EXPECT_EQ(check_monte_carlo_data(nominal_of(*f, true), d, &fault_code), Status::kTooManyTablePoints);
  EXPECT_EQ(fault_code, 19);
  EXPECT_EQ(check_monte_carlo_data(nominal_of(*f, false), d, &fault_code), Status::kOk) << "not drawn in 3D";
}

// A thrust source's draw c blends b = b_n + c (b_s - b_n) and T = T_n + c (T_s - T_n) (a negative c
// mirrors the table about the nominal): a draw that takes the burn time to zero or below, a thrust
// below zero, or stage 1's burn time inside the lift-off interval, is that sample's named failure
// (kMonteCarloBurnTimeNotPositive, kMonteCarloThrustNegative, kLiftoffLongerThanStage1), not a
// flight; the same source's other draws build, in the workspace the failure left. The sources are
// deliberately far from the nominal (ten times its thrust, twenty times its burn time) so that a
// small draw already crosses; the samples are found from counter_normal itself.
TEST(MonteCarlo, DrawsThatTakeABlendedBurnTimeOrThrustBelowZeroAreTheSamplesNamedFailure) {
  auto f = make_fixture();
  const std::uint64_t seed = 11;
  const DispersionNominal nominal = nominal_of(*f, false);
  int fault_code = -1;
  struct Case {
    const char* what;
    int code;  // 1: stage 1's tables, 3: stage 2's
    double time_scale;
    double thrust_scale;
    double failing_draws_from, failing_draws_to;  // the draws c in [from, to) fail
    Status status;
  };
  // Burn time: b = b_n (1 + 19 c) <= 0 for c <= -1/19 = -0.0526. Thrust: T = T_n (1 + 9 c) < 0 for
  // c < -1/9 wherever T_n > 0 (the burn time stays b_n). Stage 1: 0 < 45 s (1 + 19 c) <= 3 s (the
  // lift-off) for -0.0526 < c <= -0.0491.
  const double liftoff_s = f->mission.launch.liftoff_duration_s;
  const double stage1_s = f->mission.vehicle.stages[stage_index(1)].duration_s;
  const Case cases[] = {{"burn time x 20", 3, 20.0, 1.0, -1e9, -0.06, Status::kMonteCarloBurnTimeNotPositive},
                        {"thrust x 10", 3, 1.0, 10.0, -1e9, -0.12, Status::kMonteCarloThrustNegative},
                        {"stage 1 burn time x 20", 1, 20.0, 1.0, -1.0 / 19.0 + 1e-4,
                         (liftoff_s / stage1_s - 1.0) / 19.0 - 1e-4, Status::kLiftoffLongerThanStage1}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const StageData& stage = f->mission.vehicle.stages[stage_index(c.code == 1 ? 1 : 2)];
    const auto draw = [&](std::uint64_t sample) {
      return counter_normal(seed, sample, static_cast<std::uint32_t>(c.code)) / 3.0;
    };
    // The first sample whose draw the predicate accepts, among the first million (the narrowest
    // window, stage 1's, holds about one draw in 230).
    constexpr std::uint64_t kSearched = 1000000;
    const auto first_sample = [&](auto predicate) {
      std::uint64_t sample = 0;
      while (sample < kSearched && !predicate(draw(sample))) ++sample;
      return sample;
    };
    f->data.count = 0;
    DispersionSource& source = add(&f->data, c.code);
    const ThrustTable& nominal_thrust = stage.vacuum_thrust_lbf;
    for (int i = 0; i < nominal_thrust.size(); ++i) {
      const double t = nominal_thrust.x(i);
      ASSERT_EQ(source.vacuum_thrust_lbf.append(c.time_scale * t, c.thrust_scale * nominal_thrust.y(i)),
                Status::kOk);
      ASSERT_EQ(source.consumable_weight_lb.append(c.time_scale * t, stage.consumable_weight_lb(t)),
                Status::kOk);
    }
    ASSERT_EQ(source.vacuum_thrust_lbf.finalize(), Status::kOk);
    ASSERT_EQ(source.consumable_weight_lb.finalize(), Status::kOk);
    ASSERT_EQ(check_monte_carlo_data(nominal, f->data, &fault_code), Status::kOk);

    const std::uint64_t failing =
        first_sample([&](double z) { return z >= c.failing_draws_from && z < c.failing_draws_to; });
    const std::uint64_t building = first_sample([](double z) { return z > 0.05; });
    ASSERT_LT(failing, kSearched);
    ASSERT_LT(building, kSearched);
    EXPECT_EQ(build_monte_carlo_case(nominal, f->prepared, f->data, seed, failing, &f->workspace), c.status)
        << "sample " << failing << ", c = " << draw(failing);
    EXPECT_EQ(build_monte_carlo_case(nominal, f->prepared, f->data, seed, building, &f->workspace),
              Status::kOk)
        << "sample " << building << ", c = " << draw(building);
  }
}

// FlightInputs::air_alpha_rad is "what record_dispersed_trajectory() would recompute from the
// point": recorded from the wind alone, the max |q-bar alpha| of a windy flight is the one recorded
// from the flight's own air-relative alpha; without the wind it is the inertial alpha's, another.
TEST(Sec15Dispersions, MaxQbarAlphaRecomputedFromTheWindIsTheFlightsOwn) {
  auto f = make_fixture();
  WindProfile wind;
  table(&wind.speed_ft_s, {0.0, 2.0e4, 6.0e4, 2.0e5}, {20.0, 120.0, 150.0, 0.0});
  table(&wind.azimuth_rad, {0.0, 2.0e5}, {0.3, 0.8});
  FlightPerturbation perturbation;
  perturbation.wind = &wind;
  FlightInputs inputs;
  inputs.perturbation = &perturbation;
  inputs.air_alpha_rad = f->workspace.air_alpha_rad;
  auto flown = std::make_unique<Trajectory>();
  ASSERT_EQ(fly_trajectory(f->mission, f->prepared, inputs, flown.get()), Status::kOk);
  auto from_alpha = std::make_unique<DispersedTrajectory>();
  auto from_wind = std::make_unique<DispersedTrajectory>();
  auto inertial = std::make_unique<DispersedTrajectory>();
  ASSERT_EQ(record_dispersed_trajectory(f->mission, f->prepared, *flown, *flown, &wind,
                                        f->workspace.air_alpha_rad, from_alpha.get()),
            Status::kOk);
  ASSERT_EQ(record_dispersed_trajectory(f->mission, f->prepared, *flown, *flown, &wind, from_wind.get()),
            Status::kOk);
  ASSERT_EQ(record_dispersed_trajectory(f->mission, f->prepared, *flown, *flown, nullptr, inertial.get()),
            Status::kOk);
  ASSERT_GT(from_alpha->max_qbar_alpha_lbf_rad_ft2, 0.0);
  EXPECT_NEAR(from_wind->max_qbar_alpha_lbf_rad_ft2, from_alpha->max_qbar_alpha_lbf_rad_ft2,
              1e-9 * from_alpha->max_qbar_alpha_lbf_rad_ft2);
  EXPECT_EQ(from_wind->max_qbar_alpha_time_s, from_alpha->max_qbar_alpha_time_s);
  EXPECT_GT(std::fabs(inertial->max_qbar_alpha_lbf_rad_ft2 - from_alpha->max_qbar_alpha_lbf_rad_ft2),
            1e-3 * from_alpha->max_qbar_alpha_lbf_rad_ft2)
      << "a 100 ft/s wind moves the angle of attack";
}

}  // namespace
}  // namespace tolip
