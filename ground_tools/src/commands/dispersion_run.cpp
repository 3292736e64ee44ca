// The dispersion analysis of a case (tolip_ground/dispersion_run.hpp).
#include "tolip_ground/dispersion_run.hpp"

#include <cstring>
#include <sstream>

#include "tolip_ground/deck_table.hpp"

namespace tolip::ground {
namespace {

// Stacked stage 4/5 tables (block 55) restart at 0 and stay unfinalized: the core splits them.
template <int N>
bool fill_table(const DeckTable& deck, Table<N>* table, int block, int code, const std::string& field,
                DispersionMappingFault* fault) {
  if (copy_deck_table(deck, 1.0, "the table", table, &fault->message)) return true;
  fault->data_block = block;
  fault->code = code;
  fault->field = field;
  return false;
}

// Where validate_dispersion_data() found the deck's source `k` at fault with `status`: the data block
// and the deck key of what the status is about; for stacked stage 4/5 tables (codes 7-8 with block
// 55) the durations given, and for codes 7-8 whose tables hold stages 4 and 5 without block 55 the
// form they need.
void name_source_fault(const DispersionCase& source, const DispersionSource& core, std::size_t k,
                       Status status, DispersionMappingFault* fault) {
  const std::string path = "dispersion[" + std::to_string(k) + "]";
  DispersionCodeInfo info;
  const bool known = dispersion_code_info(source.code, &info);
  fault->code = source.code;
  fault->data_block = 46;
  fault->field = path;
  if (status == Status::kDispersionCodeInvalid) {
    fault->field = path + ".code";
  } else if (status == Status::kDispersionStageCodeMismatch || status == Status::kDispersionStageNotSpun) {
    fault->data_block = info.kind == DispersionKind::kTipoff ? 51 : 46;
    fault->field = path + ".stage";
  } else if (status == Status::kDispersionStageDurationsMismatch) {
    fault->data_block = 55;
    fault->field = path + ".stage_durations_s";
  } else if (status == Status::kDispersionDragVariationOutOfRange) {
    fault->data_block = 48;
    fault->field = path + ".drag_variation_fraction";
  } else if (known && info.kind == DispersionKind::kVacuumThrust) {
    const bool weight = status == Status::kNegativeWeight || status == Status::kConsumableWeightIncreases;
    fault->data_block = weight ? 38 : 30;
    fault->field = path + (weight ? ".consumable_weight" : ".thrust");
  } else if (known && info.kind == DispersionKind::kPitchingMoment) {
    fault->data_block = 35;
    fault->field = path + ".pitching_moment";
  } else if (known && info.kind == DispersionKind::kWind) {
    // The core checks both tables' presence, then both tables' order, the speed first.
    const bool speed =
        status == Status::kTableEmpty ? core.wind.speed_ft_s.empty() : !core.wind.speed_ft_s.finalized();
    fault->data_block = speed ? 53 : 54;
    fault->field = path + (fault->data_block == 53 ? ".wind_speed" : ".wind_azimuth");
  }
  fault->message = std::string(status_name(status)) + ": " + status_message(status);
  if (core.stacked_stage4_5_tables) {
    // Codes 7-8 with block 55 (find_stacked_stage4_5_split): the durations given beside the status.
    std::ostringstream given;
    given.precision(10);
    given << " (data block 55: stage 4 " << core.stage4_5_durations_s[0] << " s, stage 5 "
          << core.stage4_5_durations_s[1] << " s)";
    fault->message =
        "the stacked stage 4 and 5 tables (data blocks 30 and 38 with data block 55, manual page 22-30): " +
        fault->message + given.str();
  }
  const bool restarts_or_refills = status == Status::kConsumableWeightIncreases ||
                                   status == Status::kTableNotMonotonic ||
                                   status == Status::kDispersionThrustTableTimesInvalid;
  if (known && info.stage == 4 && info.kind == DispersionKind::kVacuumThrust && !source.has_stage_durations &&
      restarts_or_refills) {
    fault->message +=
        " (stages 4 and 5 in these tables are the manual's stacked form, page 22-30: it needs data block "
        "55, stage_durations_s)";
  }
}

}  // namespace

bool fill_dispersion_data(const std::vector<DispersionCase>& deck, DispersionData* data,
                          DispersionMappingFault* fault) {
  data->count = 0;
  if (deck.size() > static_cast<std::size_t>(kMaxDispersionSources)) {
    fault->data_block = 46;
    fault->field = "dispersion";
    fault->message =
        "at most " + std::to_string(kMaxDispersionSources) + " dispersed trajectories (codes 1-38, 40)";
    return false;
  }
  for (std::size_t k = 0; k < deck.size(); ++k) {
    const DispersionCase& d = deck[k];
    DispersionSource& s = data->sources[data->count];
    s = DispersionSource{};
    s.code = d.code;
    s.stage = d.stage;
    std::strncpy(s.title, d.title.c_str(), sizeof(s.title) - 1);
    const std::string path = "dispersion[" + std::to_string(k) + "]";
    if (!fill_table(d.vacuum_thrust_lbf, &s.vacuum_thrust_lbf, 30, d.code, path + ".thrust", fault) ||
        !fill_table(d.consumable_weight_lb, &s.consumable_weight_lb, 38, d.code, path + ".consumable_weight",
                    fault) ||
        !fill_table(d.pitching_moment_per_rad, &s.pitching_moment_per_rad, 35, d.code,
                    path + ".pitching_moment", fault) ||
        !fill_table(d.wind_speed_ft_s, &s.wind.speed_ft_s, 53, d.code, path + ".wind_speed", fault) ||
        !fill_table(d.wind_azimuth_rad, &s.wind.azimuth_rad, 54, d.code, path + ".wind_azimuth", fault)) {
      return false;
    }
    s.stacked_stage4_5_tables = d.has_stage_durations;
    s.stage4_5_durations_s[0] = d.stage4_5_durations_s[0];
    s.stage4_5_durations_s[1] = d.stage4_5_durations_s[1];
    s.weight_increment_lb = d.weight_increment_lb;
    s.drag_variation_fraction = d.drag_variation_fraction;
    s.misalignment_rad = d.misalignment_rad;
    s.thrust_station_ft = d.thrust_station_in * kFeetPerInch;
    s.deadband_rad = d.deadband_rad;
    s.tipoff_rad = d.tipoff_rad;
    s.launch_change_rad = d.launch_change_rad;
    ++data->count;
  }
  // The core's rules of the sources (a code's tables, stage and values, the codes' order) at the
  // boundary, before anything flies, named like the deck's own errors. The core checks the sources
  // in order and stops at the first at fault: checking the first k + 1 of them finds which one.
  const int filled = data->count;
  for (int k = 0; k < filled; ++k) {
    data->count = k + 1;
    int code = 0;
    const Status status = validate_dispersion_data(*data, &code);
    if (!ok(status)) {
      data->count = filled;
      const std::size_t at = static_cast<std::size_t>(k);
      name_source_fault(deck[at], data->sources[k], at, status, fault);
      return false;
    }
  }
  data->count = filled;
  return true;
}

bool final_dispersion_nominal(const Mission& mission, const OptimizationRun& run, DispersionNominal* nominal,
                              std::string* kind, Status* why) {
  const bool converged = ok(run.optimizer_status) && run.result != nullptr && run.result->converged;
  if (!converged) {
    *why = ok(run.optimizer_status) ? Status::kOptimizationNotStarted : run.optimizer_status;
    return false;
  }
  if (mission.options.linearization()) {
    // The manual's D4/TTH storage: dispersions about the linearized program (with body dynamics in
    // stage 1 when the 6D re-linearization ran).
    const LinearizationStep& lin = run.linearization;
    if (lin.outcome != StepOutcome::kRun || lin.result == nullptr || !lin.result->finished) {
      *why = (lin.outcome == StepOutcome::kRun && !ok(lin.status)) ? lin.status
                                                                   : Status::kLinearizationNotFinished;
      return false;
    }
    nominal->mission = &lin.workspace->mission;
    nominal->program = &lin.workspace->program;
    nominal->body_dynamics = lin.result->body_dynamics;
    *kind = "linearized program";
  } else {
    nominal->mission = &run.workspace->mission;
    nominal->program = &run.workspace->program;
    nominal->body_dynamics = false;
    *kind = "optimum";
  }
  return true;
}

void run_dispersion_step(const Mission& mission, const OptimizationRun& run,
                         std::unique_ptr<DispersionData> data, DispersionStep* step) {
  if (!mission.options.dispersions()) return;
  step->data = std::move(data);
  DispersionNominal nominal;
  Status why = Status::kOk;
  if (!final_dispersion_nominal(mission, run, &nominal, &step->nominal_kind, &why)) {
    step->outcome = StepOutcome::kSkipped;
    step->status = why;
    return;
  }
  step->outcome = StepOutcome::kRun;
  step->workspace = std::make_unique<DispersionWorkspace>();
  step->result = std::make_unique<DispersionResult>();
  step->status = run_dispersions(nominal, *step->data, step->workspace.get(), step->result.get());
}

}  // namespace tolip::ground
