// Building dispersion data by hand in tests (manual Sec. 22 data blocks 46-55): one source of a
// code appended with the stage its code names, and the nominal a dispersion run flies about.
// Shared by the core, no-heap and ground dispersion and Monte Carlo tests so that the rule "a
// code's stage comes from dispersion_code_info" is written once on the test side too.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>

#include "support/reference_mission.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/dispersion/dispersion.hpp"

namespace tolip::test {

// Appends a zeroed source of `code` to `data`, its stage the one the code names (the caller
// overrides it for the stage-4/5 codes), and returns it for the caller to fill. A code
// dispersion_code_info does not know fails the calling test.
inline DispersionSource& add_dispersion_source(DispersionData* data, int code) {
  DispersionSource& s = data->sources[data->count++];
  s = DispersionSource{};
  s.code = code;
  DispersionCodeInfo info;
  EXPECT_TRUE(dispersion_code_info(code, &info)) << "code " << code;
  s.stage = info.stage;
  return s;
}

// Appends, for each of `codes`, the scalar source of that code in the reference dispersion data at
// `scale` of its size: weights of stages 1-4 (9, 11, 13, 15), drag (17), deadbands (24, 26, 27,
// 29), the stage-4 pitch and yaw tip-off (30, 32) and the launch changes (33, 34). The tests pick
// the codes they fly; a code not in that list fails the calling test.
inline void add_reference_scalar_sources(DispersionData* data, double scale,
                                         std::initializer_list<int> codes) {
  const double deg = kPi / 180.0;
  for (int code : codes) {
    DispersionSource& s = add_dispersion_source(data, code);
    switch (code) {
      case 9: s.weight_increment_lb = 150.0 * scale; break;
      case 11: s.weight_increment_lb = 50.0 * scale; break;
      case 13: s.weight_increment_lb = 15.0 * scale; break;
      case 15: s.weight_increment_lb = 5.0 * scale; break;
      case 17: s.drag_variation_fraction = 0.1 * scale; break;
      case 24:
      case 26:
      case 27:
      case 29: s.deadband_rad = 0.5 * deg * scale; break;
      case 30:
      case 32:
        s.stage = 4;
        s.tipoff_rad = 2.0 * deg * scale;
        break;
      case 33: s.launch_change_rad = 0.5 * deg * scale; break;
      case 34: s.launch_change_rad = 0.3 * deg * scale; break;
      default: ADD_FAILURE() << "code " << code << " is not a reference scalar source";
    }
  }
}

// The reference mission (the oracle's optimum) with reference scalar sources, and the nominal a
// run flies about it: the block 40 table, point mass.
struct ReferenceDispersionCase {
  Mission mission;
  DispersionData data;
  DispersionNominal nominal;
};

// Fills `c` with the reference mission and the reference scalar sources of `codes` at `scale`.
inline void make_reference_dispersion_case(double scale, std::initializer_list<int> codes,
                                           ReferenceDispersionCase* c) {
  build_reference_mission(ReferenceProgram::kOptimum, &c->mission);
  add_reference_scalar_sources(&c->data, scale, codes);
  c->nominal.mission = &c->mission;
}

// The nominal of a dispersion run: `mission` flown with `program` (nullptr: the mission's own
// block 40 program), with body dynamics or without.
inline DispersionNominal dispersion_nominal(const Mission& mission, const ControlProgram* program,
                                            bool body_dynamics) {
  DispersionNominal n;
  n.mission = &mission;
  n.program = program;
  n.body_dynamics = body_dynamics;
  return n;
}

// The five-stage vehicle of the stacked-table tests: the reference, a coast 9 and a second spun
// kick stage 5 (stage 4's motor) after stage 4 - the sequence 4, 9, 5 of the manual's five-stage
// Scout (page 22-30).
inline void make_five_stage_vehicle(Mission* m) {
  StageData& coast = m->vehicle.stages[stage_index(9)];
  coast = StageData{};
  coast.duration_s = 6.0;
  coast.integration_steps = 3;
  StageData& s5 = m->vehicle.stages[stage_index(5)];
  s5 = m->vehicle.stages[stage_index(4)];
  s5.integration_steps = 20;
  s5.jettison_weight_lb = 60.0;
  m->vehicle.sequence.codes[m->vehicle.sequence.count++] = 9;
  m->vehicle.sequence.codes[m->vehicle.sequence.count++] = 5;
  coast.in_sequence = true;
  s5.in_sequence = true;
  MissionFault fault;
  ASSERT_EQ(validate_mission(*m, &fault), Status::kOk) << fault.field;
}

// Appends entries of one stage's tables to stacked tables, at table time offset_s + stage time.
inline void append_part(const ThrustTable& thrust, const WeightTable& weight, double offset_s,
                        DispersionSource* s) {
  for (int i = 0; i < thrust.size(); ++i) {
    ASSERT_EQ(s->vacuum_thrust_lbf.append(offset_s + thrust.x(i), thrust.y(i)), Status::kOk);
    ASSERT_EQ(s->consumable_weight_lb.append(offset_s + weight.x(i), weight.y(i)), Status::kOk);
  }
}

// Page 22-30's stacked source: stage 4's table, the coast "input arbitrarily as two seconds" (zero
// thrust; stage 4's last remaining weight), stage 5's table, and block 55 = both durations. With
// restart, stage 5 and the coast each restart at stage time 0; else the times continue
// (d4, d4 + 2, d4 + 2 + t).
inline void stack_stage4_5_tables(const StageData& stage4, const StageData& stage5, bool restart,
                                  DispersionSource* s) {
  s->vacuum_thrust_lbf.clear();
  s->consumable_weight_lb.clear();
  const double d4 = stage4.vacuum_thrust_lbf.last_x();
  append_part(stage4.vacuum_thrust_lbf, stage4.consumable_weight_lb, 0.0, s);
  if (restart) {
    for (double t : {0.0, 2.0}) {
      ASSERT_EQ(s->vacuum_thrust_lbf.append(t, 0.0), Status::kOk);
      ASSERT_EQ(s->consumable_weight_lb.append(t, stage4.consumable_weight_lb.last_y()), Status::kOk);
    }
  }
  append_part(stage5.vacuum_thrust_lbf, stage5.consumable_weight_lb, restart ? 0.0 : d4 + 2.0, s);
  (void)s->vacuum_thrust_lbf.finalize();  // the restarting layout is not one increasing table
  (void)s->consumable_weight_lb.finalize();
  s->stacked_stage4_5_tables = true;
  s->stage4_5_durations_s[0] = d4;
  s->stage4_5_durations_s[1] = stage5.vacuum_thrust_lbf.last_x();
}

}  // namespace tolip::test
