// C++ source that rebuilds a Mission without files: for flight images that must embed their case
// (the bare-metal Cortex-M7 demo, flight_image/). The generated function assigns every field of
// the Mission that the deck reader fills, writing each double as a hexadecimal floating literal
// so the target gets exactly the host's bits, appends and finalizes every non-empty table.
//
// Keep this in step with tolip/mission/mission.hpp: a field added there must be added here
// (flight_image's EmbeddedMission tests fly both missions and compare every point).
#pragma once

#include <string>

#include "tolip/mission/mission.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground {

// Source defining `tolip::Status <function_name>(tolip::Mission* mission)` in namespace
// tolip::flight; the function fills a default-constructed Mission and returns
// validate_mission()'s status. Beside it, the listing's texts of data blocks 1-3, which the Mission
// does not hold: `const char <function_name>_title[]`, `..._case_heading[]` and `..._date[]`.
// `origin` names the deck in a comment.
std::string mission_cpp_source(const Mission& mission, const DeckListingOptions& listing,
                               const std::string& function_name, const std::string& origin);

}  // namespace tolip::ground
