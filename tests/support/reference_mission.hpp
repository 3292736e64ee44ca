// The reference Scout mission built straight from tests/reference/scout_reference.json, without
// the deck reader, so trajectory tests do not depend on it (and can cross-check it).
#pragma once

#include "tolip/mission/mission.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip::test {

enum class ReferenceProgram {
  kOptimum,         // oracle optimum: pitch nodes as flown, stage-4 theta, coast 8, payload
  kInitialNominal,  // the crude starting program tth_block40_initial_nominal
};

// Fills *mission (which must be default-constructed) and finalizes its tables.
void build_reference_mission(ReferenceProgram program, Mission* mission);

// Replaces the Sec. 14 modified thrust tables of a prepared reference case by the oracle's. The
// oracle computed the ideal velocities A and B by Simpson's rule per table interval (tests/reference
// README, choice 8), the core integrates them exactly (docs/theory/thrust-modification.md), so
// their tables differ by the ratio of the two scales A / B (4e-6 to 1.3e-5 per stage); flown with
// the oracle's own tables, the core's trajectory is compared with the oracle's to round-off.
void use_oracle_thrust_tables(PreparedCase* prepared);

// The stage of stage code `code` (1-10), to edit a mission in a test.
inline StageData& stage(Mission& mission, int code) { return mission.vehicle.stages[stage_index(code)]; }

}  // namespace tolip::test
