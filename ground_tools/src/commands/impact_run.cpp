// The impact locus of a case (tolip_ground/impact_run.hpp).
#include "tolip_ground/impact_run.hpp"

#include "tolip/dispersion/dispersion.hpp"
#include "tolip_ground/deck_table.hpp"
#include "tolip_ground/dispersion_run.hpp"

namespace tolip::ground {
namespace {

std::string str(int value) { return std::to_string(value); }

// One deck table into a core body; false (with *fault) when it is longer than the core holds.
bool fill_body(const ImpactDragTable& deck, int block, int stage, const char* group, ImpactBody* body,
               ImpactMappingFault* fault) {
  *body = ImpactBody{};
  if (!deck.present) return true;  // validate_impact_data names a missing table of a flown stage
  // A non-increasing Mach is left unfinalized: validate_impact_data names it.
  if (!copy_deck_table(deck.cd_vs_mach, 1.0, "the drag table", &body->drag_coefficient, &fault->message)) {
    fault->data_block = block;
    fault->word = std::string("CD") + str(stage) + (block == 42 ? "F" : "E");
    fault->field = std::string("impact.") + group + "." + str(stage);
    return false;
  }
  body->present = true;
  body->reference_area_ft2 = deck.reference_area_ft2;
  body->casing_weight_lb = deck.casing_weight_lb;
  return true;
}

// Deck data blocks 42-43 and DA6D(17-19) into *data, unchecked but for the core's table capacity.
bool map_impact_data(const DeckExtras& extras, ImpactLocusData* data, ImpactMappingFault* fault) {
  *data = ImpactLocusData{};
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    const std::size_t k = static_cast<std::size_t>(stage - 1);
    if (!fill_body(extras.impact.failure_mode[k], 42, stage, "failure_drag", &data->failure_mode[k], fault) ||
        !fill_body(extras.impact.expended_casing[k], 43, stage, "casing_drag", &data->expended_casing[k],
                   fault)) {
      return false;
    }
    data->every_nth_point[k] = extras.body_dynamics.impact_every_nth_step[k];
  }
  return true;
}

// The core's validation fault in deck terms; `needed_by` names what needs a missing table.
void describe_fault(const Mission& mission, Status status, const ImpactFault& core,
                    const std::string& needed_by, ImpactMappingFault* fault) {
  fault->data_block = core.data_block;
  fault->word = core.field;
  const std::string stage = str(core.stage);
  if (core.data_block == 33) {
    fault->field = "body_dynamics.impact_every_nth_step[" + str(core.stage - 1) + "]";
    fault->message = "n = " + str(static_cast<int>(core.value)) + " for stage " + stage + ": expected " +
                     core.expected + " (stage " + stage + " has " +
                     str(mission.vehicle.stages[stage_index(core.stage)].integration_steps) + "; " +
                     status_name(status) + ")";
  } else {
    fault->field =
        std::string("impact.") + (core.data_block == 42 ? "failure_drag." : "casing_drag.") + stage;
    if (status == Status::kImpactDataMissing) {
      fault->message = "missing: " + needed_by + " needs the data block " + str(core.data_block) +
                       " drag table of stage " + stage;
    } else {
      fault->message = std::string(core.field) + ": expected " + core.expected + " (" + status_name(status) +
                       ": " + status_message(status) + ")";
    }
  }
}

}  // namespace

bool fill_impact_data(const Mission& mission, const DeckExtras& extras, ImpactLocusData* data,
                      ImpactMappingFault* fault) {
  if (!map_impact_data(extras, data, fault)) return false;
  ImpactFault core;
  const Status status = validate_impact_data(mission, *data, &core);
  if (ok(status)) return true;
  describe_fault(mission, status, core, "options.impact (IP(23))", fault);
  return false;
}

bool fill_casing_impact_data(const Mission& mission, const DeckExtras& extras,
                             const bool (&stages)[kImpactStages], const std::string& needed_by,
                             ImpactLocusData* data, ImpactMappingFault* fault) {
  if (!map_impact_data(extras, data, fault)) return false;
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    if (stages[stage - 1] && !mission.vehicle.stages[stage_index(stage)].in_sequence) {
      fault->data_block = 43;
      fault->word = std::string("CD") + str(stage) + "E";
      fault->field = "impact.casing_drag." + str(stage);
      fault->message = needed_by + " asks for the casing of stage " + str(stage) +
                       ", which is not in the vehicle's stage sequence";
      return false;
    }
  }
  ImpactFault core;
  const Status status = validate_casing_data(mission, *data, stages, &core);
  if (ok(status)) return true;
  describe_fault(mission, status, core, needed_by, fault);
  return false;
}

std::string impact_fault_text(const std::string& deck_path, const ImpactMappingFault& fault) {
  return deck_path + ": data block " + str(fault.data_block) + ", " + fault.word + " (" + fault.field +
         "): " + fault.message;
}

void run_impact_about(const Mission& mission, const PreparedCase& prepared, const Trajectory& trajectory,
                      const std::string& nominal_kind, std::unique_ptr<ImpactLocusData> data,
                      ImpactStep* step) {
  step->data = std::move(data);
  step->nominal_kind = nominal_kind;
  step->mission = &mission;
  if (!ok(trajectory.status)) {
    step->outcome = StepOutcome::kSkipped;
    step->status = trajectory.status;
    return;
  }
  step->outcome = StepOutcome::kRun;
  step->workspace = std::make_unique<ImpactWorkspace>();
  step->locus = std::make_unique<ImpactLocus>();
  step->status = compute_impact_locus(mission, prepared, trajectory, *step->data, step->workspace.get(),
                                      step->locus.get());
}

void run_impact_step(const Mission& mission, const OptimizationRun& run,
                     std::unique_ptr<ImpactLocusData> data, ImpactStep* step) {
  if (!mission.options.impact()) return;
  DispersionNominal nominal;
  Status why = Status::kOk;
  std::string kind;
  if (!final_dispersion_nominal(mission, run, &nominal, &kind, &why)) {
    step->data = std::move(data);
    step->outcome = StepOutcome::kSkipped;
    step->status = why;
    return;
  }
  // Flown as run_dispersions() flies its nominal: the case prepared at its own payload, the
  // per-point program, body dynamics in stage 1 when the 6D re-linearization ran, the same flight
  // numerics (dispersion_flight_inputs), so the Monte Carlo's casings start from the same points.
  step->prepared = std::make_unique<PreparedCase>();
  step->nominal = std::make_unique<Trajectory>();
  Status status = prepare_case(*nominal.mission, step->prepared.get());
  if (ok(status)) {
    status = fly_trajectory(*nominal.mission, *step->prepared, dispersion_flight_inputs(nominal),
                            step->nominal.get());
  }
  if (!ok(status)) {
    step->data = std::move(data);
    step->nominal_kind = kind;
    step->mission = nominal.mission;
    step->outcome = StepOutcome::kRun;
    step->status = status;
    return;
  }
  run_impact_about(*nominal.mission, *step->prepared, *step->nominal, kind, std::move(data), step);
}

}  // namespace tolip::ground
