// Subroutine REIN (Sec. 14) and the launch geometry (Sec. 4), done once per case.
#include "tolip/vehicle/prepared_case.hpp"

#include <cmath>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/mission/stage_weight.hpp"

namespace tolip {
namespace {

// Below this |r| = |k h / W0| (relative weight change over one merged interval) the two ratio
// functions of exact_interval_integral() are summed as their Taylor series: the closed forms lose
// about 2 eps / |r| to cancellation in r - log1p(r) (4e-14 at the threshold) and divide 0 by 0 at
// k = 0 (a coast-like piece of constant weight, or a weight table held past its end). The series
// truncated after r^8 errs by |r|^9 / 11 < 1e-19 there.
constexpr double kSeriesRelativeWeightChange = 1e-2;

// Exact integral over [0, h] of (T0 + m s) / (W0 + k s), with T1 = T0 + m h and W1 = W0 + k h.
// The manual's closed form (m / k) h + (T0 - m W0 / k) ln(W1 / W0) / k, regrouped with
// r = k h / W0 as (T0 f1(r) + m h f2(r)) h / W0, f1 = log1p(r) / r and f2 = (r - log1p(r)) / r^2,
// so it stays accurate as k -> 0 (f1 -> 1, f2 -> 1/2: the plain integral of T / W0).
double exact_interval_integral(double t0_lbf, double t1_lbf, double w0_lb, double w1_lb, double h_s) {
  const double r = (w1_lb - w0_lb) / w0_lb;
  const double m = (t1_lbf - t0_lbf) / h_s;
  double f1 = 0.0;
  double f2 = 0.0;
  if (std::fabs(r) < kSeriesRelativeWeightChange) {
    // f1 = sum (-r)^n / (n + 1), f2 = sum (-r)^n / (n + 2), n = 0..8, by Horner.
    for (int n = 8; n >= 0; --n) {
      f1 = 1.0 / (n + 1) - r * f1;
      f2 = 1.0 / (n + 2) - r * f2;
    }
  } else {
    const double log_ratio = std::log1p(r);
    f1 = log_ratio / r;
    f2 = (r - log_ratio) / (r * r);
  }
  return (t0_lbf * f1 + m * h_s * f2) * h_s / w0_lb;
}

// The ideal velocity integral g0 T / W dt over [t_begin, t_end] of a piecewise-linear thrust table
// with the total vehicle weight (case payload included), as Sec. 14 integrates "thrust/weight".
// W is the stage's piecewise-linear consumable table plus constants, so on each interval of the
// merged thrust and weight breakpoints both are linear and the integral is exact. The look-ups
// step forward in time, so they keep hints (the same values as plain look-ups, bit for bit).
template <typename PiecewiseLinearThrust>
double ideal_velocity_ft_s(const Vehicle& vehicle, int code, double g0, const PiecewiseLinearThrust& thrust,
                           double t_begin, double t_end) {
  const auto& weight = vehicle.stages[stage_index(code)].consumable_weight_lb;
  StageWeight vehicle_weight(vehicle, code);
  int thrust_hint = -1;
  int i_thrust = 0;
  int i_weight = 0;
  double a = t_begin;
  double thrust_a = thrust(a, &thrust_hint);
  double weight_a = vehicle_weight(a);
  double ideal = 0.0;
  while (a < t_end) {
    while (i_thrust < thrust.size() && !(thrust.x(i_thrust) > a)) ++i_thrust;
    while (i_weight < weight.size() && !(weight.x(i_weight) > a)) ++i_weight;
    double b = t_end;
    if (i_thrust < thrust.size() && thrust.x(i_thrust) < b) b = thrust.x(i_thrust);
    if (i_weight < weight.size() && weight.x(i_weight) < b) b = weight.x(i_weight);
    const double thrust_b = thrust(b, &thrust_hint);
    const double weight_b = vehicle_weight(b);
    ideal += exact_interval_integral(thrust_a, thrust_b, weight_a, weight_b, b - a);
    a = b;
    thrust_a = thrust_b;
    weight_a = weight_b;
  }
  return g0 * ideal;
}

// Exact impulse of the piecewise-linear input table over [0, t1].
double input_impulse(const ThrustTable& table, double t1) {
  double impulse = 0.0;
  int hint = -1;
  for (int i = 0; i + 1 < table.size() && table.x(i) < t1; ++i) {
    const double a = table.x(i);
    const double b = (table.x(i + 1) < t1) ? table.x(i + 1) : t1;
    impulse += 0.5 * (table(a, &hint) + table(b, &hint)) * (b - a);
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

  // A: over the input table's span.
  const double ideal_input = ideal_velocity_ft_s(vehicle, code, g0, input, input.first_x(), input.last_x());

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
  int hint = -1;  // the grid times increase: a hinted look-up, the same value
  for (int i = 1; i <= line.steps && ok(status); ++i) {
    const double t = (i == line.steps) ? line.duration_s : line.first_step_stage_time_s + i * line.step_s;
    status = table->append(t, input(t, &hint));
  }
  if (ok(status)) status = table->finalize();
  if (!ok(status)) return status;

  // B: over the grid table, then scale to make B = A.
  const double ideal_grid = ideal_velocity_ft_s(vehicle, code, g0, *table, table->first_x(), table->last_x());
  if (!(ideal_grid > 0.0) || !std::isfinite(ideal_input)) return Status::kModifiedThrustIdealVelocityInvalid;
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
  prepared->oblate_figure = oblate_figure(constants);
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
