// The bundled example decks as core Missions, for core tests that must not link the deck reader:
// C++ that tolip_embed_mission generates from the deck at build time (tests/CMakeLists.txt;
// the same generator as the flight image's, whose tests prove the generated Mission equal to the
// deck's field for field).
#pragma once

#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip::flight {

// examples/scout/reference_optimum.toml
Status build_reference_optimum_deck(Mission* mission);

}  // namespace tolip::flight
