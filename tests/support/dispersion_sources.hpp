// Building dispersion data by hand in tests (manual Sec. 22 data blocks 46-55): one source of a
// code appended with the stage its code names, and the nominal a dispersion run flies about.
// Shared by the core, no-heap and ground dispersion and Monte Carlo tests so that the rule "a
// code's stage comes from dispersion_code_info" is written once on the test side too.
#pragma once

#include <gtest/gtest.h>

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

}  // namespace tolip::test
