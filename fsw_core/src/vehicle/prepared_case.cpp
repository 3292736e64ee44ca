// Subroutine REIN (Sec. 14) and the launch geometry (Sec. 4), done once per case.
#include "tolip/vehicle/prepared_case.hpp"

#include <cmath>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"

namespace tolip {
namespace {

// Ideal-velocity integrand g0 T / W at stage time t, with the total vehicle weight (case payload
// included), as Sec. 14 integrates "thrust/weight".
template <typename ThrustLookup>
double thrust_per_mass(const Vehicle& vehicle, int code, double g0, const ThrustLookup& thrust, double t) {
  return g0 * thrust(t) / vehicle_weight_lb(vehicle, code, t);
}

// Fourth-order Runge-Kutta quadrature of a function of t alone (Simpson's rule) over [t0, t1].
template <typename Integrand>
double simpson(const Integrand& f, double t0, double t1) {
  return (t1 - t0) / 6.0 * (f(t0) + 4.0 * f(0.5 * (t0 + t1)) + f(t1));
}

// Exact impulse of the piecewise-linear input table over [0, t1].
double input_impulse(const ThrustTable& table, double t1) {
  double impulse = 0.0;
  for (int i = 0; i + 1 < table.size() && table.x(i) < t1; ++i) {
    const double a = table.x(i);
    const double b = (table.x(i + 1) < t1) ? table.x(i + 1) : t1;
    impulse += 0.5 * (table(a) + table(b)) * (b - a);
  }
  return impulse;
}

Status build_timeline(const Mission& mission, PreparedCase* prepared) {
  const StageSequence& sequence = mission.vehicle.sequence;
  double start_s = 0.0;
  for (int k = 0; k < sequence.count; ++k) {
    const int code = sequence.codes[k];
    const StageData& stage = mission.vehicle.stages[stage_index(code)];
    StageTimeline& line = prepared->timeline[k];
    line.code = code;
    line.start_s = start_s;
    line.duration_s = stage.duration_s;
    line.steps = stage.integration_steps;
    line.first_step_stage_time_s = (code == 1) ? mission.launch.liftoff_duration_s : 0.0;
    if (line.steps <= 0) return Status::kNonPositiveStepCount;
    line.step_s = (line.duration_s - line.first_step_stage_time_s) / line.steps;
    if (!(line.step_s > 0.0)) return Status::kNonPositiveDuration;
    start_s += stage.duration_s;
  }
  prepared->stage_count = sequence.count;
  return Status::kOk;
}

// Sec. 14: re-tabulate the vacuum thrust at the integration times, remove the initial pulse by a
// replacement T(0) that keeps the impulse of the first integration interval, and scale every entry so the
// stage's ideal velocity equals that of the input table.
Status modify_thrust_table(const Mission& mission, const StageTimeline& line, ModifiedThrustTable* table,
                           ThrustModification* modification) {
  const Vehicle& vehicle = mission.vehicle;
  const StageData& stage = vehicle.stages[stage_index(line.code)];
  const ThrustTable& input = stage.vacuum_thrust_lbf;
  const double g0 = mission.constants.g0_ft_s2;
  const int code = line.code;

  // A: over the input entries.
  const auto input_integrand = [&](double t) { return thrust_per_mass(vehicle, code, g0, input, t); };
  double ideal_input = 0.0;
  for (int i = 0; i + 1 < input.size(); ++i) {
    ideal_input += simpson(input_integrand, input.x(i), input.x(i + 1));
  }

  // The grid: 0, the first step time (TL in stage 1), then every step to the end of the stage.
  table->clear();
  const double first_grid_time =
      (line.first_step_stage_time_s > 0.0) ? line.first_step_stage_time_s : line.step_s;
  const double new_initial_thrust =
      2.0 * input_impulse(input, first_grid_time) / first_grid_time - input(first_grid_time);
  Status status = table->append(0.0, new_initial_thrust);
  if (line.first_step_stage_time_s > 0.0 && ok(status)) {
    status = table->append(line.first_step_stage_time_s, input(line.first_step_stage_time_s));
  }
  for (int i = 1; i <= line.steps && ok(status); ++i) {
    const double t = (i == line.steps) ? line.duration_s : line.first_step_stage_time_s + i * line.step_s;
    status = table->append(t, input(t));
  }
  if (ok(status)) status = table->finalize();
  if (!ok(status)) return status;

  // B: over the grid table, then scale to make B = A.
  const auto grid_integrand = [&](double t) { return thrust_per_mass(vehicle, code, g0, *table, t); };
  double ideal_grid = 0.0;
  for (int i = 0; i + 1 < table->size(); ++i) {
    ideal_grid += simpson(grid_integrand, table->x(i), table->x(i + 1));
  }
  if (!(ideal_grid > 0.0) || !std::isfinite(ideal_input)) return Status::kValueOutOfRange;
  const double scale = ideal_input / ideal_grid;
  for (int i = 0; i < table->size(); ++i) table->set_y(i, table->y(i) * scale);
  status = table->finalize();
  if (!ok(status)) return status;

  modification->ideal_velocity_input_ft_s = ideal_input;
  modification->ideal_velocity_grid_ft_s = ideal_grid;
  modification->scale = scale;
  modification->new_initial_thrust_lbf = table->y(0);
  return Status::kOk;
}

}  // namespace

void prepare_launch_geometry(const Mission& mission, PreparedCase* prepared) {
  // Frozen at t = 0 (Sec. 4: "matrices B and B' are evaluated only at time = 0").
  const Constants& constants = mission.constants;
  const LaunchConditions& launch = mission.launch;
  const double latitude = launch.geocentric_latitude_rad;
  prepared->pad_radius_ft = oblate_radius_ft(constants, latitude) + launch.altitude_ft;
  prepared->delta_lambda_rad = delta_lambda_rad(constants, latitude, prepared->pad_radius_ft);
  prepared->geocentric_to_inertial =
      geocentric_to_inertial(launch.azimuth_rad, latitude, launch.longitude_rad);
  prepared->platform_to_geocentric = platform_to_geocentric(launch.azimuth_rad, prepared->delta_lambda_rad);
  prepared->platform_to_inertial = prepared->geocentric_to_inertial * prepared->platform_to_geocentric;
  prepared->pad_state << launch.velocity_ft_s, launch.flight_path_angle_rad, prepared->pad_radius_ft,
      launch.azimuth_rad, latitude, launch.longitude_rad;
}

Status rebuild_timeline(const Mission& mission, PreparedCase* prepared) {
  return build_timeline(mission, prepared);
}

Status prepare_case(const Mission& mission, PreparedCase* prepared) {
  prepared->prepared = false;
  Status status = build_timeline(mission, prepared);
  if (!ok(status)) return status;

  for (int k = 0; k < prepared->stage_count; ++k) {
    const StageTimeline& line = prepared->timeline[k];
    if (!is_powered_stage(line.code)) continue;
    status = modify_thrust_table(mission, line, &prepared->modified_thrust_lbf[stage_index(line.code)],
                                 &prepared->thrust_modification[stage_index(line.code)]);
    if (!ok(status)) return status;
  }

  prepare_launch_geometry(mission, prepared);
  prepared->prepared = true;
  return Status::kOk;
}

}  // namespace tolip
