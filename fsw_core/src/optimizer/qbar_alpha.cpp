// The q-bar x alpha load limit (tolip/optimizer/qbar_alpha.hpp; docs/theory/constraints-and-ics.md).
#include "tolip/optimizer/qbar_alpha.hpp"

#include <cmath>

#include "tolip/frames/frames.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"

namespace tolip {
namespace {

// Central-difference steps of q-bar alpha's partials: [V, gamma, r, psi, lambda, tau] and theta.
constexpr double kStateStep[6] = {1e-3, 1e-7, 0.5, 1e-7, 1e-8, 1e-8};
constexpr double kThetaStepRad = 1e-7;

// The relative excess e = |s| / L - 1 (negative under the limit).
double relative_excess(double s, double limit) { return std::fabs(s) / limit - 1.0; }

// Timeline slot of the stage a point belongs to (-1: the pad point, which no stage integrates).
int stage_slot_of(const Trajectory& trajectory, int point) {
  for (int s = 0; s < trajectory.stage_count; ++s) {
    if (point >= trajectory.stages[s].first_point && point <= trajectory.stages[s].last_point) return s;
  }
  return -1;
}

// q-bar alpha of the model at (x, theta) with the point's stage, time and yaw: the evaluation the
// forward run made there, with the attitude held (alpha as the trajectory defines it: the in-plane
// angle of the thrust axis, angle_of_attack_rad).
double model_qbar_alpha(const Mission& mission, const PreparedCase& prepared, const StageContext& stage,
                        const TrajectoryPoint& p, const StateVector& x, double theta_rad) {
  StepCommand command;
  command.mode = AttitudeMode::kHeld;
  command.theta_start_rad = command.theta_end_rad = theta_rad;
  command.chi_rad = p.chi_rad;
  command.step_start_s = p.time_s;
  Evaluation e;
  evaluate_flight(mission, prepared, stage, command, p.time_s, x, 0.0, &e);
  return e.dynamic_pressure_lbf_ft2 * angle_of_attack_rad(e.thrust_axis_local);
}

}  // namespace

double qbar_alpha_lbf_rad_ft2(const TrajectoryPoint& point) {
  return point.dynamic_pressure_lbf_ft2 * point.alpha_rad;
}

bool qbar_alpha_limited(const Mission& mission, const TrajectoryPoint& point) {
  if (!(point.dynamic_pressure_lbf_ft2 > 0.0) || mission.vehicle.lift_curve_slope_per_rad.empty()) {
    return false;
  }
  if (point.stage_code < 1 || point.stage_code > kMaxStages) return false;
  return mission.vehicle.stages[stage_index(point.stage_code)].uses_lift_table;
}

double trapezoidal_weight_s(const Trajectory& trajectory, int k) {
  const TrajectoryPoint& p = trajectory.points[k];
  const double before = (k > 0) ? trajectory.points[k - 1].time_s : p.time_s;
  const double after = (k + 1 < trajectory.point_count) ? trajectory.points[k + 1].time_s : p.time_s;
  return 0.5 * (after - before);
}

double qbar_alpha_excess_s(const Mission& mission, const Trajectory& trajectory) {
  const double limit = mission.options.qbar_alpha_limit_lbf_rad_ft2;
  if (!(limit > 0.0)) return 0.0;
  double sum = 0.0;
  for (int k = 0; k < trajectory.point_count; ++k) {
    const TrajectoryPoint& p = trajectory.points[k];
    if (!qbar_alpha_limited(mission, p)) continue;
    const double e = relative_excess(qbar_alpha_lbf_rad_ft2(p), limit);
    if (e > 0.0) sum += trapezoidal_weight_s(trajectory, k) * e * e;
  }
  return sum;
}

QbarAlphaPeak peak_qbar_alpha(const Mission& mission, const Trajectory& trajectory, bool limited_only) {
  QbarAlphaPeak peak;
  for (int k = 0; k < trajectory.point_count; ++k) {
    const TrajectoryPoint& p = trajectory.points[k];
    if (limited_only && !qbar_alpha_limited(mission, p)) continue;
    const double value = std::fabs(qbar_alpha_lbf_rad_ft2(p));
    if (value > peak.value_lbf_rad_ft2) {
      peak.value_lbf_rad_ft2 = value;
      peak.time_s = p.time_s;
      peak.point = k;
    }
  }
  return peak;
}

Status qbar_alpha_point_partials(const Mission& mission, const PreparedCase& prepared,
                                 const Trajectory& trajectory, int k, StateVector* ds_dx, double* ds_dtheta) {
  ds_dx->setZero();
  *ds_dtheta = 0.0;
  if (k < 0 || k >= trajectory.point_count) return Status::kOk;
  const TrajectoryPoint& p = trajectory.points[k];
  const int slot = stage_slot_of(trajectory, k);
  if (!qbar_alpha_limited(mission, p) || p.alpha_zero || slot < 0) return Status::kOk;
  const StageContext stage = make_stage_context(mission, prepared, prepared.timeline[slot]);
  for (int i = 0; i < 6; ++i) {
    StateVector plus = p.state;
    StateVector minus = p.state;
    plus[i] += kStateStep[i];
    minus[i] -= kStateStep[i];
    (*ds_dx)[i] = (model_qbar_alpha(mission, prepared, stage, p, plus, p.theta_rad) -
                   model_qbar_alpha(mission, prepared, stage, p, minus, p.theta_rad)) /
                  (2.0 * kStateStep[i]);
  }
  *ds_dtheta = (model_qbar_alpha(mission, prepared, stage, p, p.state, p.theta_rad + kThetaStepRad) -
                model_qbar_alpha(mission, prepared, stage, p, p.state, p.theta_rad - kThetaStepRad)) /
               (2.0 * kThetaStepRad);
  if (!ds_dx->allFinite() || !std::isfinite(*ds_dtheta)) return Status::kNonFiniteState;
  return Status::kOk;
}

Status qbar_alpha_excess_gradient(const Mission& mission, const PreparedCase& prepared,
                                  const Trajectory& trajectory, int k, StateVector* d_state,
                                  double* d_theta) {
  d_state->setZero();
  *d_theta = 0.0;
  const double limit = mission.options.qbar_alpha_limit_lbf_rad_ft2;
  if (!(limit > 0.0) || k < 0 || k >= trajectory.point_count) return Status::kOk;
  const TrajectoryPoint& p = trajectory.points[k];
  if (!qbar_alpha_limited(mission, p) || p.alpha_zero) return Status::kOk;  // alpha = 0 at alpha-zero points
  const double s = qbar_alpha_lbf_rad_ft2(p);
  const double e = relative_excess(s, limit);
  const double w = trapezoidal_weight_s(trajectory, k);
  const int slot = stage_slot_of(trajectory, k);
  if (!(e > 0.0) || !(w > 0.0) || slot < 0) return Status::kOk;
  // dJ/ds = w 2 e sign(s) / L, times ds/dx and ds/dtheta.
  const double dj_ds = w * 2.0 * e * ((s < 0.0) ? -1.0 : 1.0) / limit;
  StateVector ds_dx;
  double ds_dtheta = 0.0;
  const Status status = qbar_alpha_point_partials(mission, prepared, trajectory, k, &ds_dx, &ds_dtheta);
  if (!ok(status)) return status;
  *d_state = dj_ds * ds_dx;
  *d_theta = dj_ds * ds_dtheta;
  return Status::kOk;
}

}  // namespace tolip
