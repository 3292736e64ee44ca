// The reference Scout mission built straight from tests/reference/scout_reference.json, without
// the deck reader, so trajectory tests do not depend on it (and can cross-check it).
#pragma once

#include "tolip/mission/mission.hpp"

namespace tolip::test {

enum class ReferenceProgram {
  kOptimum,         // oracle optimum: pitch nodes as flown, stage-4 theta, coast 8, payload
  kInitialNominal,  // the crude starting program tth_block40_initial_nominal
};

// Fills *mission (which must be default-constructed) and finalizes its tables.
void build_reference_mission(ReferenceProgram program, Mission* mission);

// The stage of stage code `code` (1-10), to edit a mission in a test.
inline StageData& stage(Mission& mission, int code) { return mission.vehicle.stages[stage_index(code)]; }

}  // namespace tolip::test
