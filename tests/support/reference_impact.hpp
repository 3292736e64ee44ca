// The reference impact data (tests/reference/scout_reference.json, "impact": data blocks 42-43,
// and DA6D(17-19)) as the core's ImpactLocusData, without the deck reader.
#pragma once

#include "tolip/impact/impact.hpp"

namespace tolip::test {

// Fills *data from the reference set: the failure-mode and casing drag tables of stages 1-3 with
// their reference areas and casing weights, and the every-n-th-point rates.
void build_reference_impact_data(ImpactLocusData* data);

}  // namespace tolip::test
