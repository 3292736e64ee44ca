#include "support/reference_mission.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "support/reference_data.hpp"
#include "tolip/core/constants.hpp"

namespace tolip::test {
namespace {

// The reference deck's TLIN word 100 n + t (manual Sec. 22, data block 18) as the core's boundary:
// n = floor(TLIN / 100), t = TLIN - 100 n.
SegmentBoundary boundary_of(double coded) {
  const double stage = std::floor(coded / 100.0);
  return SegmentBoundary{static_cast<int>(stage), coded - 100.0 * stage};
}

template <typename TableT>
void fill(TableT* table, const nlohmann::json& xs, const nlohmann::json& ys, double y_scale = 1.0) {
  table->clear();
  for (size_t i = 0; i < xs.size(); ++i) {
    if (!ok(table->append(xs[i].get<double>(), ys[i].get<double>() * y_scale))) {
      throw std::runtime_error("reference table does not fit");
    }
  }
  if (!ok(table->finalize())) throw std::runtime_error("reference table not monotonic");
}

}  // namespace

void use_oracle_thrust_tables(PreparedCase* prepared) {
  const nlohmann::json& tables = scout_reference()["oracle_solution"]["modified_thrust_tables_section14"];
  for (const auto& [key, t] : tables.items()) {
    fill(&prepared->modified_thrust_lbf[stage_index(std::stoi(key))], t["time_s"], t["vacuum_thrust_lbf"]);
  }
}

void build_reference_mission(ReferenceProgram program, Mission* m) {
  const nlohmann::json& ref = scout_reference();
  const nlohmann::json& ct = ref["constants_block10_CT1"];
  m->constants.earth_rotation_rate_rad_s = ct["earth_rotation_rate_rad_per_s"];
  m->constants.gravitational_parameter_ft3_s2 = ct["gravitational_parameter_ft3_per_s2"];
  m->constants.earth_equatorial_radius_ft = ct["earth_equatorial_radius_ft"];
  m->constants.gas_constant_ft2_s2_R = ct["gas_constant_ft2_per_s2_R"];
  m->constants.g0_ft_s2 = ct["g0_weight_to_mass_ft_per_s2"];
  m->constants.sea_level_pressure_lbf_ft2 = ct["sea_level_pressure_lbf_per_ft2"];
  m->constants.haero_ft = ct["haero_aero_bypass_altitude_ft"];
  m->constants.time_epsilon_s = ct["time_epsilon_s"];
  m->constants.j2 = ct["j2"];
  m->constants.inverse_flattening = ct["inverse_flattening"];

  const nlohmann::json& atm = ref["atmosphere_blocks11_14_ARDC"];
  for (int i = 0; i < kAtmosphereLayers; ++i) {
    m->atmosphere.base_geopotential_altitude_ft[i] = atm["base_geopotential_altitude_ft"][i];
    m->atmosphere.base_molecular_temperature_R[i] = atm["base_molecular_temperature_R"][i];
    m->atmosphere.lapse_rate_R_per_ft[i] = atm["lapse_rate_R_per_geopotential_ft"][i];
    m->atmosphere.base_density_slug_ft3[i] = atm["base_density_slug_per_ft3"][i];
  }

  const nlohmann::json& veh = ref["vehicle"];
  const nlohmann::json& oracle = ref["oracle_solution"];
  const bool optimum = program == ReferenceProgram::kOptimum;
  const nlohmann::json& initial = oracle["tth_block40_initial_nominal"];
  m->vehicle.sequence.count = 0;
  for (const auto& code : veh["stage_sequence_block5"]) {
    if (code.get<int>() == 0) break;
    m->vehicle.sequence.codes[m->vehicle.sequence.count++] = code.get<int>();
  }
  for (const auto& [key, s] : veh["stages"].items()) {
    const int code = std::stoi(key);
    StageData& stage = m->vehicle.stages[stage_index(code)];
    stage.in_sequence = true;
    stage.duration_s = s["duration_s"];
    stage.integration_steps = s["integration_steps"];
    stage.jettison_weight_lb = s["jettison_weight_lb"];
    stage.reference_area_ft2 = s.value("reference_area_ft2", 0.0);
    stage.nozzle_exit_area_ft2 = s.value("nozzle_exit_area_ft2", 0.0);
    if (s["kind"] == "powered") {
      fill(&stage.vacuum_thrust_lbf, s["thrust_table"]["time_s"], s["thrust_table"]["vacuum_thrust_lbf"]);
      fill(&stage.consumable_weight_lb, s["consumable_weight_table"]["time_s"],
           s["consumable_weight_table"]["consumable_weight_remaining_lb"]);
    }
    if (code == 8) {
      stage.duration_s =
          optimum ? oracle["coast8_duration_s"].get<double>() : initial["coast8_s"].get<double>();
    }
  }
  const nlohmann::json& aero = veh["aerodynamics"];
  for (const auto& [key, t] : aero["drag_coefficient_tables"].items()) {
    const int code = std::stoi(key.substr(key.find('_') + 1));
    fill(&m->vehicle.stages[stage_index(code)].drag_coefficient, t["mach"], t["cd"]);
  }
  fill(&m->vehicle.lift_curve_slope_per_rad, aero["lift_curve_slope_table"]["mach"],
       aero["lift_curve_slope_table"]["cl_alpha_per_rad"]);
  for (const auto& code : aero["lift_curve_slope_table"]["used_in_stages"]) {
    m->vehicle.stages[stage_index(code.get<int>())].uses_lift_table = true;
  }
  m->vehicle.payload_lb = optimum ? oracle["payload_lb"].get<double>() : initial["payload_lb"].get<double>();

  const nlohmann::json& mis = ref["mission"];
  const nlohmann::json& ic = mis["initial_conditions_block21"];
  m->launch.liftoff_duration_s = mis["liftoff_duration_s_block20_word1"];
  m->launch.launch_space_age_date_days = mis["launch_date_space_age_days_block20_word2"];
  m->launch.altitude_ft = ic["altitude_ft"];
  m->launch.longitude_rad = ic["longitude_deg"].get<double>() * kDegToRad;
  m->launch.geocentric_latitude_rad = ic["geocentric_latitude_deg"].get<double>() * kDegToRad;
  m->launch.velocity_ft_s = ic["velocity_ft_per_s"];
  m->launch.azimuth_rad = ic["azimuth_deg"].get<double>() * kDegToRad;
  m->launch.flight_path_angle_rad = ic["flight_path_angle_deg"].get<double>() * kDegToRad;
  m->launch.heading_hold_until_s = mis["heading_hold_until_s"];

  const nlohmann::json& b22 = mis["block22_control_constraints"];
  m->control.zero_alpha_start_s = b22["alpha_zero_start_s"];
  m->control.zero_alpha_end_s = b22["alpha_zero_end_s"];
  m->control.max_pitch_rate_rad_s = b22["max_pitch_rate_deg_per_s"].get<double>() * kDegToRad;
  m->control.min_pitch_rate_rad_s = b22["min_pitch_rate_deg_per_s"].get<double>() * kDegToRad;
  m->control.min_pitch_rate_change_rad_s =
      b22["min_change_in_pitch_rate_deg_per_s"].get<double>() * kDegToRad;

  const nlohmann::json& b17 = mis["block17"];
  m->misc.stage4_theta_rad =
      (optimum ? oracle["stage4_theta_deg"].get<double>() : initial["theta4_deg"].get<double>()) * kDegToRad;
  m->misc.stage4_chi_rad = b17["stage4_chi_deg"].get<double>() * kDegToRad;
  m->misc.nose_radius_ft = b17["nose_radius_ft"];
  m->misc.gyro_uncage_s_before_launch = b17["gyro_uncage_s_before_launch"];
  m->misc.payload_weighting_factor = b17["payload_weighting_factor"];
  m->misc.coast_change_limit_s = b17["coast_change_limit_per_iteration_s"];
  m->misc.minimum_coast_s = b17["minimum_coast_duration_s"];
  const nlohmann::json& tlin = mis["pitch_program_definition"]["tlin_block18"];
  m->linearization.segment_count = tlin[0];
  for (size_t i = 1; i < tlin.size(); ++i)
    m->linearization.boundaries[i - 1] = boundary_of(tlin[i].get<double>());
  for (int i = 0; i < m->linearization.segment_count; ++i) m->linearization.segment_weights[i] = 1.0;
  const nlohmann::json& b28 = mis["block28_convergence"];
  m->convergence.initial_payoff_improvement = b28["initial_payoff_improvement_lb"];
  m->convergence.stop_improvement = b28["stop_when_attempt_below_lb"];
  m->convergence.max_forward_trajectories = b28["max_forward_trajectories"];
  m->convergence.max_linearization_iterations = b28["max_linearization_iterations"];

  const nlohmann::json& tc = mis["terminal_constraints"];
  m->constraints.count = tc["block8_codes"][0];
  for (int i = 0; i < m->constraints.count; ++i) {
    m->constraints.codes[i] = tc["block8_codes"][i + 1];
    m->constraints.desired[i] = tc["block19_desired_values"][i];
  }
  for (int i = 0; i + 1 < m->constraints.count; ++i) {
    m->constraints.deadband_optimization[i] = tc["block29_allowed_deviations_optimization"][i];
    m->constraints.deadband_linearization[i] = tc["block29_allowed_deviations_linearization"][i];
  }
  const nlohmann::json& adjustable = mis["adjustable_parameters_block6"]["codes"];
  m->adjustable.count = adjustable[0];
  m->adjustable.codes[0] = adjustable[1];
  m->adjustable.codes[1] = adjustable[2];
  m->adjustable.weights[0] = mis["weighting_block27"]["stage4_theta"];
  m->adjustable.weights[1] = mis["weighting_block27"]["coast_after_stage3"];

  for (const auto& [key, value] : mis["block4_options_IP"].items()) {
    m->options.ip[std::stoi(key.substr(0, key.find('_')))] = value.get<int>();
  }

  // Data blocks 33-37 (body dynamics): stations inches -> ft, K_TV per degree -> per radian, S the
  // block 34 reference area (the deck mapping takes stage 1's block 39 area, the same 8.7266 ft^2).
  const nlohmann::json& bd = ref["body_dynamics_6D"];
  const nlohmann::json& da6d = bd["block33_DA6D"];
  BodyDynamicsBlocks& body = m->body_dynamics;
  body.present = true;
  for (int k = 0; k < kBodyDynamicsStages; ++k) {
    const std::string stage = "stage_" + std::to_string(k + 1);
    body.position_gain[k] = da6d["position_gain_K_theta_deg_per_deg"][stage];
    body.rate_gain_s[k] = da6d["rate_gain_K_q_s"][stage];
    body.control_station_ft[k] = da6d["jet_vane_and_fin_station_in"][stage].get<double>() / 12.0;
  }
  body.jet_vane_effectiveness_per_rad =
      da6d["jet_vane_effectiveness_lb_per_lb_vacuum_thrust_per_deg_per_vane"].get<double>() / kDegToRad;
  body.moment_reference_station_ft = da6d["moment_reference_station_X_FS_in"].get<double>() / 12.0;
  body.reference_length_ft = da6d["reference_length_ft"];
  body.reference_area_ft2 = bd["block34_fin_normal_force_per_delta"]["reference_area_ft2"];
  fill(&body.fin_normal_force_per_rad, bd["block34_fin_normal_force_per_delta"]["mach"],
       bd["block34_fin_normal_force_per_delta"]["cn_delta_per_rad_per_fin"]);
  fill(&body.pitching_moment_per_rad, bd["block35_pitching_moment_per_alpha_about_X_FS"]["mach"],
       bd["block35_pitching_moment_per_alpha_about_X_FS"]["cm_alpha_per_rad"]);
  fill(&body.fin_pitching_moment_per_rad, bd["block36_fin_pitching_moment_per_delta_about_X_FS"]["mach"],
       bd["block36_fin_pitching_moment_per_delta_about_X_FS"]["cm_delta_per_rad_per_fin"]);
  for (int k = 0; k < kCgTableStages; ++k) {
    const nlohmann::json& cg = bd["block37_center_of_gravity_station_in"]["stage_" + std::to_string(k + 1)];
    fill(&body.cg_station_ft[k], cg["stage_time_s"], cg["cg_station_in"], 1.0 / 12.0);
  }

  m->pitch_program_rad.clear();
  if (optimum) {
    const nlohmann::json& pp = oracle["pitch_program"];
    nlohmann::json times = nlohmann::json::array({0.0});
    nlohmann::json thetas = nlohmann::json::array({0.5 * kPi});
    for (size_t i = 0; i < pp["node_times_s"].size(); ++i) {
      times.push_back(pp["node_times_s"][i].get<double>());
      thetas.push_back(pp["theta_deg_as_flown"][i].get<double>() * kDegToRad);
    }
    fill(&m->pitch_program_rad, times, thetas);
  } else {
    fill(&m->pitch_program_rad, initial["time_s"], initial["theta_deg"], kDegToRad);
  }
}

}  // namespace tolip::test
