// Listing levels and the forward runs kept for them (tolip_ground/run_listing.hpp).
#include "tolip_ground/run_listing.hpp"

namespace tolip::ground {

const char* listing_level_name(ListingLevel level) {
  switch (level) {
    case ListingLevel::kFinal: return "final";
    case ListingLevel::kFull: return "full";
    case ListingLevel::kRuns: return "runs";
  }
  return "final";
}

bool parse_listing_level(const std::string& text, ListingLevel* level) {
  for (ListingLevel candidate : {ListingLevel::kFinal, ListingLevel::kFull, ListingLevel::kRuns}) {
    if (text == listing_level_name(candidate)) {
      *level = candidate;
      return true;
    }
  }
  return false;
}

ListingLevel deck_listing_level(const OutputFrequency& output) {
  for (std::size_t k = 0; k < output.initial.size(); ++k) {
    if (output.initial[k] != 1 || output.intermediate[k] != 1) return ListingLevel::kRuns;
  }
  return ListingLevel::kFinal;
}

void RunCapture::on_forward_run(const IterationRecord& record, const OptimizerResult& result) {
  if (inner_ != nullptr) inner_->on_forward_run(record, result);
}

void RunCapture::on_forward_trajectory(const IterationRecord& record, const Mission& flown_mission,
                                       const Trajectory& flown, const Trajectory* nominal) {
  if (inner_ != nullptr) inner_->on_forward_trajectory(record, flown_mission, flown, nominal);
  if (level_ == ListingLevel::kFinal) return;
  if (record.kind == RunKind::kFinalGuidance && nominal != nullptr) {
    final_nominal_ = std::make_unique<Trajectory>(*nominal);
    final_run_ = std::make_unique<Trajectory>(flown);
  }
  if (level_ != ListingLevel::kRuns) return;
  ListedRun run;
  run.record = record;
  run.mission = std::make_unique<Mission>(flown_mission);
  run.flown = std::make_unique<Trajectory>(flown);
  if (nominal != nullptr) run.nominal = std::make_unique<Trajectory>(*nominal);
  runs_.push_back(std::move(run));
}

}  // namespace tolip::ground
