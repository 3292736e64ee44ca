// Reports of the hardover turns (tolip_ground/hardover_report.hpp).
#include "tolip_ground/hardover_report.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "case_document.hpp"
#include "listing_pager.hpp"
#include "number_format.hpp"
#include "tolip/core/constants.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;
using report_detail::json_number;

const char* mode_name(HardoverMode mode) {
  switch (mode) {
    case HardoverMode::kFinsAndVanes: return "FINS AND VANES";
    case HardoverMode::kThrustMisalignment: return "MODE 1 THRUST MISALIGNMENT";
    case HardoverMode::kSingleJet: return "MODE 2 SINGLE CONTROL JET";
    case HardoverMode::kPitchAndYawJets: return "MODE 3 PITCH AND YAW JETS";
  }
  return "";
}

const char* mode_key(HardoverMode mode) {
  switch (mode) {
    case HardoverMode::kFinsAndVanes: return "fins_and_vanes";
    case HardoverMode::kThrustMisalignment: return "thrust_misalignment";
    case HardoverMode::kSingleJet: return "single_jet";
    case HardoverMode::kPitchAndYawJets: return "pitch_and_yaw_jets";
  }
  return "";
}

const char* stop_key(HardoverStop stop) {
  switch (stop) {
    case HardoverStop::kTimeLimit: return "time_limit";
    case HardoverStop::kQbarAlphaLimit: return "qbar_alpha_limit";
    case HardoverStop::kTumbling: return "tumbling";
    case HardoverStop::kEndOfStage: return "end_of_stage";
    case HardoverStop::kStepLimit: return "step_limit";
  }
  return "";
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

bool computed(const HardoverStep& step) {
  return step.outcome == StepOutcome::kRun && ok(step.status) && step.result != nullptr;
}

std::string fault_text(const HardoverStep& step) {
  const HardoverFault& f = step.fault;
  std::string text = "data block " + std::to_string(f.data_block);
  if (f.word > 0) text += " word " + std::to_string(f.word);
  if (f.stage > 0) text += " stage " + std::to_string(f.stage);
  return text;
}

}  // namespace

std::string hardover_turn_name(const HardoverTurn& turn) {
  return "STAGE " + std::to_string(turn.stage) + " " + mode_name(turn.mode);
}

namespace report_detail {

void write_hardover_pages(Pager& pager, const HardoverStep& step) {
  if (step.outcome == StepOutcome::kNotRequested) return;
  pager.new_page("HARDOVER TURNS", false);
  if (!computed(step)) {
    pager.emit(" FAILURE-MODE HARDOVER TURNS (SEC. 16, DATA BLOCKS 44-45) NOT COMPUTED: " +
               std::string(status_name(step.status)) + ": " + status_message(step.status) +
               (step.outcome == StepOutcome::kRun ? " (" + fault_text(step) + ")" : ""));
    return;
  }
  pager.emit(" FAILURE-MODE HARDOVER TURNS (SEC. 16), NOSE-UP FAILURES FROM THE " +
             upper(step.trajectory_kind) + " TRAJECTORY");
  pager.emit("");
  const HardoverResult& r = *step.result;
  char line[160];
  for (int k = 0; k < r.turn_count; ++k) {
    const HardoverTurn& turn = r.turns[k];
    pager.reserve(4 + turn.sample_count);
    std::snprintf(line, sizeof line, " FAILURE AT %9.3f SEC   %s   STOP: %s AFTER %d STEPS",
                  turn.failure_time_s, hardover_turn_name(turn).c_str(), hardover_stop_name(turn.stop),
                  turn.steps);
    pager.emit(line);
    pager.emit("      TIME   CHG GAMMA      QBAR-A");
    pager.emit("       SEC         DEG  LB DEG/FT2");
    for (int i = 0; i < turn.sample_count; ++i) {
      const HardoverSample& s = turn.samples[i];
      std::snprintf(line, sizeof line, "%10.3f %11.5f %11.2f", s.time_s, s.change_in_gamma_rad * kRadToDeg,
                    s.qbar_alpha_lbf_rad_ft2 * kRadToDeg);
      pager.emit(line);
    }
    pager.emit("");
  }
}

}  // namespace report_detail

json hardover_json(const HardoverStep& step) {
  json h = json::object();
  h["computed"] = computed(step);
  h["status"] = status_name(step.status);
  h["status_message"] = status_message(step.status);
  h["trajectory"] = step.trajectory_kind;
  if (step.outcome == StepOutcome::kRun && !ok(step.status)) {
    h["fault"] = {
        {"data_block", step.fault.data_block}, {"word", step.fault.word}, {"stage", step.fault.stage}};
  }
  json turns = json::array();
  if (computed(step)) {
    const HardoverResult& r = *step.result;
    for (int k = 0; k < r.turn_count; ++k) {
      const HardoverTurn& turn = r.turns[k];
      json t = json::object();
      t["stage"] = turn.stage;
      t["mode"] = static_cast<int>(turn.mode);
      t["mode_name"] = mode_key(turn.mode);
      t["failure_time_s"] = json_number(turn.failure_time_s);
      t["nominal_point"] = turn.nominal_point;
      t["stop"] = stop_key(turn.stop);
      t["steps"] = turn.steps;
      t["duration_s"] = json_number(turn.last().time_s);
      t["change_in_gamma_deg"] = json_number(turn.last().change_in_gamma_rad * kRadToDeg);
      json samples = json::array();
      for (int i = 0; i < turn.sample_count; ++i) {
        const HardoverSample& s = turn.samples[i];
        samples.push_back({{"time_s", json_number(s.time_s)},
                           {"change_in_gamma_deg", json_number(s.change_in_gamma_rad * kRadToDeg)},
                           {"qbar_alpha_lbf_deg_ft2", json_number(s.qbar_alpha_lbf_rad_ft2 * kRadToDeg)},
                           {"attitude_change_deg", json_number(s.attitude_change_rad * kRadToDeg)}});
      }
      t["samples"] = std::move(samples);
      turns.push_back(std::move(t));
    }
  }
  h["turns"] = std::move(turns);
  return h;
}

void write_hardover_csv(std::ostream& out, const HardoverStep& step) {
  out << "stage,mode,failure_time_s,time_s,change_in_gamma_deg,qbar_alpha_lbf_deg_ft2,attitude_change_deg,"
         "stop\n";
  if (!computed(step)) return;
  const HardoverResult& r = *step.result;
  char line[256];
  for (int k = 0; k < r.turn_count; ++k) {
    const HardoverTurn& turn = r.turns[k];
    for (int i = 0; i < turn.sample_count; ++i) {
      const HardoverSample& s = turn.samples[i];
      std::snprintf(line, sizeof line, "%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%s\n", turn.stage,
                    static_cast<int>(turn.mode), turn.failure_time_s, s.time_s,
                    s.change_in_gamma_rad * kRadToDeg, s.qbar_alpha_lbf_rad_ft2 * kRadToDeg,
                    s.attitude_change_rad * kRadToDeg, stop_key(turn.stop));
      out << line;
    }
  }
}

void write_hardover_listing(std::ostream& out, const DeckListingOptions* listing, const HardoverStep& step) {
  report_detail::Pager pager(out, listing);
  report_detail::write_hardover_pages(pager, step);
}

json hardover_document(const DeckListingOptions& listing, const std::string& deck_path,
                       Status trajectory_status, const HardoverStep& step) {
  json document = report_detail::case_document(deck_path, listing, trajectory_status);
  document["hardover"] = hardover_json(step);
  return document;
}

}  // namespace tolip::ground
