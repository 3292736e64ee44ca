// Hardover turns of a case (tolip_ground/hardover_run.hpp).
#include "tolip_ground/hardover_run.hpp"

#include <ostream>

#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/deck_table.hpp"
#include "tolip_ground/radar_run.hpp"

namespace tolip::ground {
namespace {

bool fill_table(const DeckTable& deck, HardoverTable* table, const std::string& field,
                HardoverMappingFault* fault) {
  if (copy_deck_table(deck, 1.0, "the table", table, &fault->message)) return true;
  fault->message += " (the 22E12.8 card)";
  fault->data_block = 44;
  fault->field = field;
  return false;
}

}  // namespace

bool fill_hardover_data(const HardoverData& deck, tolip::HardoverData* data, HardoverMappingFault* fault) {
  *data = tolip::HardoverData{};
  for (int k = 0; k < 3; ++k) {
    const std::size_t at = static_cast<std::size_t>(k);
    if (!fill_table(deck.pitch_inertia_slug_ft2[at], &data->stages[k].pitch_inertia_slug_ft2,
                    "hardover.pitch_inertia." + std::to_string(k + 1), fault)) {
      return false;
    }
  }
  if (!fill_table(deck.stage1_pitch_damping_per_rad, &data->pitch_damping_per_rad, "hardover.pitch_damping",
                  fault)) {
    return false;
  }
  data->max_qbar_alpha_lbf_rad_ft2 = deck.max_qbar_alpha_lb_rad_ft2;
  data->fin_vane_deflection_rad = deck.stage1_fin_vane_deflection_rad;
  data->output_interval_s = deck.output_interval_s;
  tolip::HardoverStage& s1 = data->stages[0];
  s1.every_nth_step = deck.stage1_every_nth_step;
  s1.max_attitude_step_rad = deck.stage1_max_attitude_step_rad;
  s1.max_step_s = deck.stage1_max_step_s;
  s1.min_step_s = deck.stage1_min_step_s;
  s1.max_steps_per_turn = deck.stage1_max_steps_per_turn;
  s1.thrust_misalignment_rad = deck.thrust_misalignment_rad[0];
  s1.thrust_station_ft = deck.stage1_thrust_station_in * kFeetPerInch;
  for (int k = 1; k < 3; ++k) {
    const std::size_t upper = static_cast<std::size_t>(k - 1);
    tolip::HardoverStage& s = data->stages[k];
    s.every_nth_step = k == 1 ? deck.stage2_every_nth_step : deck.stage3_every_nth_step;
    s.max_attitude_step_rad = deck.upper_max_attitude_step_rad;
    s.max_step_s = deck.upper_max_step_s;
    s.min_step_s = deck.upper_min_step_s;
    s.max_steps_per_turn = deck.upper_max_steps_per_turn;
    s.thrust_misalignment_rad = deck.thrust_misalignment_rad[static_cast<std::size_t>(k)];
    s.thrust_station_ft = deck.thrust_station_in[upper] * kFeetPerInch;
    s.single_jet_force_lbf = deck.mode_b_jet_force_lb[upper];
    s.pitch_yaw_jet_force_lbf = deck.mode_c_jet_force_lb[upper];
    s.control_jet_station_ft = deck.control_jet_station_in[upper] * kFeetPerInch;
  }
  return true;
}

void run_hardover_step(const Mission& mission, const PreparedCase& prepared, const Trajectory& trajectory,
                       const std::string& kind, std::unique_ptr<tolip::HardoverData> data,
                       HardoverStep* step) {
  step->outcome = StepOutcome::kRun;
  step->trajectory_kind = kind;
  step->data = std::move(data);
  step->result = std::make_unique<HardoverResult>();
  step->status =
      compute_hardover_turns(mission, prepared, trajectory, *step->data, step->result.get(), &step->fault);
}

bool final_nominal_flight(const Mission& mission, const OptimizationRun& run, FinalNominal* nominal,
                          std::string* kind, Status* why) {
  nominal->trajectory = final_nominal_trajectory(mission, run, kind, why);
  if (nominal->trajectory == nullptr) return false;
  const bool linearized = mission.options.linearization();
  nominal->mission = linearized ? &run.linearization.workspace->mission : &run.workspace->mission;
  nominal->prepared = linearized ? &run.linearization.workspace->prepared : &run.workspace->prepared;
  return true;
}

void skip_hardover_step(Status why, HardoverStep* step) {
  step->outcome = StepOutcome::kSkipped;
  step->status = why;
}

bool prepare_hardover_data(const std::string& deck_path, const std::string& prefix, const DeckCase& deck_case,
                           std::unique_ptr<tolip::HardoverData>* data, std::ostream& err) {
  if (!deck_case.extras.hardover.present) {
    err << "tolip: " << prefix << deck_path
        << ": data block 44, hardover: the case has no hardover data; [hardover] (data blocks 44-45) is "
           "required\n";
    return false;
  }
  *data = std::make_unique<tolip::HardoverData>();
  HardoverMappingFault mapping;
  if (!fill_hardover_data(deck_case.extras.hardover, data->get(), &mapping)) {
    err << "tolip: " << prefix << deck_path << ": data block " << mapping.data_block << ", " << mapping.field
        << ": " << mapping.message << '\n';
    return false;
  }
  HardoverFault fault;
  const Status status = validate_hardover_data(*deck_case.mission, **data, &fault);
  if (!ok(status)) {
    err << "tolip: " << prefix << deck_path << ": data block " << fault.data_block;
    if (fault.word > 0) err << ", word " << fault.word;
    if (fault.stage > 0) err << ", stage " << fault.stage;
    err << ": " << status_name(status) << ": " << status_message(status) << '\n';
    return false;
  }
  return true;
}

}  // namespace tolip::ground
