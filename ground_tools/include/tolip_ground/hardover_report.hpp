// Reports of the hardover turns (manual Sec. 16, Sec. 22 "Output format - Hardover turns"): the
// listing page (per turn the failure time and the stage and mode, then TIME, CHG GAMMA, QBAR-A at
// the output interval and the stop reason), the JSON member `hardover` (docs/cli.md) and the CSV of
// `tolip hardover --csv`.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "tolip_ground/hardover_run.hpp"

namespace tolip::ground {

namespace report_detail {
class Pager;
// The hardover pages, continuing the pager's page numbers.
void write_hardover_pages(Pager& pager, const HardoverStep& step);
}  // namespace report_detail

// "STAGE 1 FINS AND VANES", "STAGE 2 MODE 1 THRUST MISALIGNMENT", ...
std::string hardover_turn_name(const HardoverTurn& turn);

nlohmann::ordered_json hardover_json(const HardoverStep& step);

// One row per turn and output line: stage, mode, failure time, time, change in gamma, q-bar alpha,
// attitude change, stop reason (on every row of the turn).
void write_hardover_csv(std::ostream& out, const HardoverStep& step);

// `tolip hardover`: the pages alone, and the JSON document of a case (as radar_document).
void write_hardover_listing(std::ostream& out, const DeckListingOptions* listing, const HardoverStep& step);
nlohmann::ordered_json hardover_document(const DeckListingOptions& listing, const std::string& deck_path,
                                         Status trajectory_status, const HardoverStep& step);

}  // namespace tolip::ground
