// Reports of the dispersion analysis (manual Sec. 15, Sec. 22 "Output format - Dispersion
// analysis"): the listing pages (each dispersed trajectory's staging variables and orbit elements
// with their dispersions, the summary of the individual dispersions, the three-sigma variations),
// the JSON member `dispersions` (docs/cli.md) and the CSV of `--dispersions-csv`.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "tolip_ground/dispersion_run.hpp"

namespace tolip::ground {

namespace report_detail {
class Pager;
// The dispersion pages, continuing the pager's page numbers (optimize's listing).
void write_dispersion_pages(Pager& pager, const DispersionStep& step);
}  // namespace report_detail

// The dispersion pages alone, numbered from page 1 with the case's titles (`tolip dispersions`).
void write_dispersion_listing(std::ostream& out, const DeckListingOptions* listing,
                              const DispersionStep& step);

nlohmann::ordered_json dispersion_json(const DispersionStep& step);

// One row per dispersed trajectory (nominal first) and staging point: values, dispersions, and on
// the final-point row the orbit elements, their dispersions and the max q-bar alpha.
void write_dispersion_csv(std::ostream& out, const DispersionStep& step);

// Display name of a staging column ("STAGE 2 IGNITION", "FINAL POINT") and its JSON/CSV key.
std::string staging_point_name(int stage_code);
std::string staging_point_key(int stage_code);

}  // namespace tolip::ground
