// Inputs read but not acted on (tolip_ground/unused_inputs.hpp).
#include "tolip_ground/unused_inputs.hpp"

#include "deck_common.hpp"

namespace tolip::ground {

std::vector<InputWarning> unused_inputs(const Mission& mission, const DeckExtras& extras) {
  std::vector<InputWarning> out;
  const Options& o = mission.options;
  const auto warn = [&out](int block, const char* word, const char* field, std::string message) {
    out.push_back(InputWarning{block, word, field, std::move(message)});
  };
  // Data block 4: the 1966 dump. (IP(10) acts through spun_stage_attitude() where validate_mission()
  // admits it.)
  if (o.memory_dump()) {
    warn(4, "IP(15)", "options.memory_dump",
         "the core-memory dump of the 1966 program has no counterpart: ignored");
  }
  // Data block 9's initial and intermediate frequencies act: a deck giving one other than 1 asks
  // `optimize` for the listings of the initial nominal and of every forward run (run_listing.hpp).
  // Data block 19: DA4(1), the payoff entry's desired value, is a placeholder (Sec. 22): the payoff
  // is maximized, not driven to a value.
  if (mission.constraints.count > 0 && mission.constraints.desired[0] != 0.0) {
    deck_detail::ConstraintUnit unit{};
    const std::string key = deck_detail::constraint_unit(mission.constraints.codes[0], &unit)
                                ? std::string("constraint[0].desired_") + unit.suffix
                                : std::string("constraint[0].desired");
    warn(19, "DA4(1)", key.c_str(),
         "the payoff entry's desired value is a placeholder: the payoff is maximized, the value has no "
         "effect");
  }
  // Data block 10: CT1(6) and CT1(9) differing from the manual's nominal values. The pressure is
  // rho R T of the ARDC table (Sec. 19, blocks 11-14); angles are converted with the exact pi/180.
  if (mission.constants.sea_level_pressure_lbf_ft2 != Constants{}.sea_level_pressure_lbf_ft2) {
    warn(10, "CT1(6)", "constants.sea_level_pressure_lbf_ft2",
         "has no effect: the pressure is rho R T of the ARDC table (data blocks 11-14)");
  }
  if (extras.listing.deg_to_rad_as_printed != DeckListingOptions{}.deg_to_rad_as_printed) {
    warn(10, "CT1(9)", "constants.deg_to_rad_as_printed",
         "is printed in the input echo only: angles are converted with the exact pi/180");
  }
  // Data block 10: CT1(13) has no use in the equations this version integrates.
  if (mission.constants.ct1_13 != 1.0) {
    warn(10, "CT1(13)", "constants.ct1_13", "has no effect in this version");
  }
  // Data block 17: the spun-stage attitudes only act on a stage IP(9) spins on them (IP(9) = 1 spins
  // stage 5 on stage 4's words; 2 flies stage 4 on the pitch program; 3 both).
  const std::string ip9 = "IP(9) = " + std::to_string(o.spin_stages_4_5());
  const MiscellaneousData& misc = mission.misc;
  const bool stage4_flown = mission.vehicle.stages[stage_index(4)].in_sequence;
  const bool stage5_flown = mission.vehicle.stages[stage_index(5)].in_sequence;
  // Under IP(9) = 2, IP(10) = 1 the spun stage 5 yaws at DA2(6): that word acts, DA2(5) alone not.
  const bool chi4_flown_by_stage5 =
      stage5_flown && o.stage_is_spun(5) && !o.stage_is_spun(4) && o.stage5_chi() == 1;
  const std::string stage4_why =
      stage4_flown ? "with " + ip9 + " stage 4 flies the pitch program" : std::string("stage 4 is not flown");
  if (!(stage4_flown && o.stage_is_spun(4))) {
    if (chi4_flown_by_stage5 && misc.stage4_theta_rad != 0.0) {
      warn(17, "DA2(5)", "misc.stage4_theta_deg",
           "the spun stage-4 pitch attitude has no effect: " + stage4_why +
               " (DA2(6) acts: stage 5 yaws at it, IP(10) = 1)");
    } else if (!chi4_flown_by_stage5 && (misc.stage4_theta_rad != 0.0 || misc.stage4_chi_rad != 0.0)) {
      warn(17, "DA2(5), DA2(6)", "misc.stage4_theta_deg/stage4_chi_deg",
           "the spun stage-4 attitudes have no effect: " + stage4_why);
    }
  }
  const bool stage5_own_attitudes = stage5_flown && o.stage_is_spun(5) && !o.stage_is_spun(4);
  if (!stage5_own_attitudes && (misc.stage5_theta_rad != 0.0 || misc.stage5_chi_rad != 0.0)) {
    warn(17, "DA2(9), DA2(10)", "misc.stage5_theta_deg/stage5_chi_deg",
         "the spun stage-5 attitudes have no effect: " +
             (!stage5_flown        ? std::string("stage 5 is not flown")
              : o.stage_is_spun(5) ? "with " + ip9 + " stage 5 holds stage 4's attitudes"
                                   : "with " + ip9 + " stage 5 flies the pitch program"));
  } else if (stage5_own_attitudes && o.stage5_chi() == 1 && misc.stage5_chi_rad != 0.0) {
    warn(17, "DA2(10)", "misc.stage5_chi_deg",
         "the spun stage-5 yaw attitude has no effect: with IP(10) = 1 stage 5 yaws at chi4 (DA2(6))");
  }
  // Data block 17: the platform frame is fixed at lift-off here (the launch matrices), not at uncage.
  if (mission.misc.gyro_uncage_s_before_launch != 0.0) {
    warn(17, "DA2(8)", "misc.gyro_uncage_s_before_launch",
         "the gyro uncage time has no effect: the platform frame is aligned at lift-off in this version "
         "(uncaging DA2(8) s earlier would turn it by the Earth's rotation in that time)");
  }
  // Data block 33, DA6D(12-15): substeps of 6D forward trajectories, which only IP(6) = 2 (the
  // initial nominal) and IP(6) = 1 with the linearization (IP(7)) fly.
  const bool six_d_flown = o.body_dynamics_6d() == 2 || (o.body_dynamics_6d() == 1 && o.linearization());
  for (double multiplier : mission.body_dynamics.integration_frequency_multiplier) {
    if (multiplier != 1.0 && !six_d_flown) {
      warn(33, "DA6D(12-15)", "body_dynamics.integration_frequency_multiplier",
           "the 6D integration frequency multipliers have no effect: no 6D forward trajectory is flown "
           "(IP(6) = " +
               std::to_string(o.body_dynamics_6d()) + ", IP(7) = " + std::to_string(o.linearization()) + ")");
      break;
    }
  }
  // Data block 33 words 22-30 (autopilot design, issue 16): they act only with designed gains.
  const AutopilotDesignData& ap = extras.autopilot;
  const AutopilotDesignData ap_default;
  if (ap.designed == 0 && (ap.natural_frequency_rad_s != ap_default.natural_frequency_rad_s ||
                           ap.damping_ratio != ap_default.damping_ratio ||
                           ap.attitude_error_rad != ap_default.attitude_error_rad ||
                           ap.actuator_time_constant_s != ap_default.actuator_time_constant_s ||
                           ap.points_per_stage != ap_default.points_per_stage)) {
    warn(33, "DA6D(22-30)",
         "body_dynamics.autopilot_natural_frequency_rad_s/autopilot_damping_ratio/"
         "autopilot_attitude_error_deg/"
         "autopilot_actuator_time_constant_s/autopilot_points_per_stage",
         "the autopilot design data have no effect: body_dynamics.autopilot_designed_gains is 0, the table "
         "and the 6D runs use the constant gains DA6D(1-6)");
  }
  // Data block 37: the stage-4 c.g. history (XCG4). Stage 1's flies the body dynamics; stages 2-3's
  // the dispersions and the hardover turns, which Sec. 15 and 16 take in stages 1-3 only; stage 4 is
  // spun or flies the point-mass program, so nothing reads XCG4.
  if (!mission.body_dynamics.cg_station_ft[3].empty()) {
    warn(37, "XCG4", "body_dynamics.cg.4",
         "the stage-4 c.g. history ([body_dynamics.cg.4]) has no effect: body dynamics fly stage 1, the "
         "dispersions and hardover "
         "turns use the c.g. of stages 1-3 only");
  }
  return out;
}

void print_input_warnings(std::ostream& err, const std::string& deck_path, int case_number, int case_count,
                          const std::vector<InputWarning>& warnings) {
  for (const InputWarning& w : warnings) {
    err << "tolip: warning: " << deck_path;
    if (case_count > 1) err << ": case " << case_number;
    err << ": data block " << w.data_block << ", " << w.word << " (" << w.field << "): " << w.message << '\n';
  }
}

void print_deck_input_warnings(std::ostream& err, const std::string& deck_path, const Deck& deck) {
  const int count = static_cast<int>(deck.cases.size());
  for (const DeckCase& deck_case : deck.cases) {
    print_input_warnings(err, deck_path, deck_case.number, count,
                         unused_inputs(*deck_case.mission, deck_case.extras));
  }
}

}  // namespace tolip::ground
