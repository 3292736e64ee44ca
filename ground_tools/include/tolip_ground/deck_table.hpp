// A table the deck gave, into the core's fixed-capacity form: one rule for the analyses' tables the
// ground tools hand to the core (data blocks 33-37, 42-45 and 46-55). The mission's own tables
// (blocks 30-32, 38, 40) are read entry by entry, each entry's fault named, in mission_sections.cpp.
#pragma once

#include <string>

#include "tolip/math/table.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/units.hpp"

namespace tolip::ground {

// Copies `deck` into `table` with y times `y_scale` and finalizes it. A table whose x does not
// increase (the stacked stage-4/5 tables of block 55 restart at 0; a deck reader that leaves the
// check to the core) stays unfinalized, for the core to split or its validation to name. An empty
// deck table gives an empty table. More points than the core holds: false, `table` left empty, and
// *message says "<what> has K points; the core holds at most N" for the caller to put beside the
// data block and field.
template <int N>
bool copy_deck_table(const DeckTable& deck, double y_scale, const std::string& what, Table<N>* table,
                     std::string* message) {
  table->clear();
  if (deck.size() > N) {
    *message =
        what + " has " + std::to_string(deck.size()) + " points; the core holds at most " + std::to_string(N);
    return false;
  }
  for (int i = 0; i < deck.size(); ++i) {
    const std::size_t at = static_cast<std::size_t>(i);
    (void)table->append(deck.x[at], deck.y[at] * y_scale);  // fits: checked above
  }
  if (!deck.empty()) (void)table->finalize();
  return true;
}

}  // namespace tolip::ground
