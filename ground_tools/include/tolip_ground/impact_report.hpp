// Reports of the nominal impact locus (manual Sec. 17, Sec. 22 "Output format - IMPACT"): the
// listing page (per case the failure time, the impact time, geodetic latitude, longitude,
// downrange, crossrange, geocentric latitude), the JSON member `impact` (docs/cli.md) and the CSV.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

#include "tolip_ground/impact_run.hpp"

namespace tolip::ground {

namespace report_detail {
class Pager;
// The impact pages, continuing the pager's page numbers.
void write_impact_pages(Pager& pager, const ImpactStep& step);
}  // namespace report_detail

// The impact pages on their own (`tolip impact`), with the page titles of the case.
void write_impact_listing(std::ostream& out, const DeckListingOptions* listing, const ImpactStep& step);

nlohmann::ordered_json impact_json(const ImpactStep& step);
// Puts impact_json(step) into a simulate/optimize document as member "impact", before the (long)
// point array "trajectory" (at the end when there is none).
void add_impact_member(nlohmann::ordered_json* document, const ImpactStep& step);

// One row per case, the header row first (docs/cli.md "tolip impact").
void write_impact_csv(std::ostream& out, const ImpactStep& step);

// "thrust_failure" / "expended_casing".
const char* impact_kind_key(ImpactKind kind);

}  // namespace tolip::ground
