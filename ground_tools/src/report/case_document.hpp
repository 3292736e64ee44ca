// The members a case's JSON document opens with (private to ground_tools/src/report).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "tolip/core/status.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground::report_detail {

// program, version, deck, title, case_heading, date (data blocks 1-3, trailing blanks removed),
// status and status_message, in that order: the head of `tolip simulate`, `tolip radar` and
// `tolip hardover` documents (docs/cli.md). The caller adds its own members after them.
nlohmann::ordered_json case_document(const std::string& deck_path, const DeckListingOptions& listing,
                                     Status status);

}  // namespace tolip::ground::report_detail
