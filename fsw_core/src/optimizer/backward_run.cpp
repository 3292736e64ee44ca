// Discrete adjoint of the forward run (manual Sec. 5 adjoint equations, Sec. 9 backward runs).
#include "tolip/optimizer/backward_run.hpp"

#include <cmath>
#include <limits>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/dynamics/vertical_flight.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/qbar_alpha.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"
#include "tolip/trajectory/liftoff.hpp"

namespace tolip {
namespace {

using StateJacobian = Eigen::Matrix<double, 6, 6>;
using StateRows = Eigen::Matrix<double, 6, kMaxConstraints>;  // adjoint of the 6 states, per constraint
using MassRow = Eigen::Matrix<double, 1, kMaxConstraints>;

// One-sided difference steps: about 1e-8 of each variable's scale, where the truncation error of
// the model's smooth terms and the round-off of the differences are both near 1e-8 relative. (The
// backward run is the optimizer's main cost; one-sided differences halve it, and the adjoint
// predictions still agree with central differences of forward runs to 3e-4, see the tests.)
constexpr double kStateStep[6] = {1e-4, 1e-8, 0.1, 1e-8, 1e-8, 1e-8};
// The same in the regular coordinates of a near-vertical step [v_up, v_N, r, v_E, lambda, tau]
// (tolip/dynamics/vertical_flight.hpp).
constexpr double kVerticalStep[6] = {1e-4, 1e-4, 0.1, 1e-4, 1e-8, 1e-8};
constexpr double kWeightStepLb = 1e-4;
constexpr double kAngleStepRad = 1e-8;

// The model linearized about one evaluation: f and its partials with respect to the state, the
// mass (per slug), and the attitude angles (per rad).
struct Linearization {
  StateVector f = StateVector::Zero();
  StateJacobian df_dx = StateJacobian::Zero();
  StateVector df_dm = StateVector::Zero();
  StateVector df_dtheta = StateVector::Zero();
  StateVector df_dchi = StateVector::Zero();
  // Body dynamics (6D, Sec. 7): the flown attitude also depends on the commanded rate theta_c-dot
  // = (theta_end - theta_start) / step_s (per rad/s, at a fixed commanded theta). Zero otherwise.
  StateVector df_drate = StateVector::Zero();
};

class Linearizer {
 public:
  Linearizer(const Mission& mission, const PreparedCase& prepared) : mission_(mission), prepared_(prepared) {}

  // The psi of a vertical-flight step's first point (tolip/dynamics/vertical_flight.hpp).
  void set_heading_reference(double heading_rad) { heading_reference_rad_ = heading_rad; }

  // `x` is the state, or for a vertical-flight step its regular coordinates (and f, df_dx and the
  // other partials are then those of their derivative).
  void linearize(const StageContext& stage, const StepCommand& command, double t, const StateVector& x,
                 Linearization* out) const {
    out->f = f(stage, command, t, x, 0.0);
    const double* steps = command.vertical_flight ? kVerticalStep : kStateStep;
    for (int i = 0; i < 6; ++i) {
      StateVector xp = x;
      xp[i] += steps[i];
      out->df_dx.col(i) = (f(stage, command, t, xp, 0.0) - out->f) / steps[i];
    }
    // Without thrust and aerodynamics the mass and the attitude act on nothing.
    const bool forces_depend_on_attitude = stage.thrust != nullptr || stage.data->uses_lift_table;
    const bool forces_depend_on_mass =
        stage.thrust != nullptr || !stage.data->drag_coefficient.empty() || stage.data->uses_lift_table;
    // d/dm = g0 d/dW: the mass enters as weight / g0.
    out->df_dm.setZero();
    if (forces_depend_on_mass) {
      out->df_dm =
          (f(stage, command, t, x, kWeightStepLb) - out->f) / kWeightStepLb * mission_.constants.g0_ft_s2;
    }
    out->df_dtheta.setZero();
    out->df_dchi.setZero();
    if (command.mode == AttitudeMode::kZeroAlpha || !forces_depend_on_attitude) return;
    StepCommand plus = command;
    plus.theta_start_rad += kAngleStepRad;
    plus.theta_end_rad += kAngleStepRad;
    out->df_dtheta = (f(stage, plus, t, x, 0.0) - out->f) / kAngleStepRad;
    out->df_drate.setZero();
    if (command.body_dynamics && command.mode == AttitudeMode::kLinear) {
      // Turn the step's line about its value at t: theta_c(t) stays, the rate grows by
      // kAngleStepRad / step_s.
      const double fraction = (t - command.step_start_s) / command.step_s;
      StepCommand turned = command;
      turned.theta_start_rad -= fraction * kAngleStepRad;
      turned.theta_end_rad += (1.0 - fraction) * kAngleStepRad;
      out->df_drate = (f(stage, turned, t, x, 0.0) - out->f) / (kAngleStepRad / command.step_s);
    }
    if (command.mode == AttitudeMode::kHeld) {
      plus = command;
      plus.chi_rad += kAngleStepRad;
      out->df_dchi = (f(stage, plus, t, x, 0.0) - out->f) / kAngleStepRad;
    }
  }

  // d theta / dX of the alpha = 0 attitude (stage-2 ignition under IP(12)).
  StateVector zero_alpha_gradient(const StateVector& x) const {
    StateVector g;
    const double base = zero_alpha_theta_rad(prepared_, x);
    for (int i = 0; i < 6; ++i) {
      StateVector xp = x;
      xp[i] += kStateStep[i];
      g[i] = (zero_alpha_theta_rad(prepared_, xp) - base) / kStateStep[i];
    }
    return g;
  }

 private:
  StateVector f(const StageContext& stage, const StepCommand& command, double t, const StateVector& x,
                double weight_offset_lb) const {
    Evaluation e;
    if (command.vertical_flight) {
      const StateVector state = from_vertical_coordinates(x, heading_reference_rad_);
      evaluate_flight(mission_, prepared_, stage, command, t, state, weight_offset_lb, &e);
      return vertical_derivative(state, e.derivative);
    }
    evaluate_flight(mission_, prepared_, stage, command, t, x, weight_offset_lb, &e);
    return e.derivative;
  }

  const Mission& mission_;
  const PreparedCase& prepared_;
  double heading_reference_rad_ = 0.0;
};

// Adjoint-weighted contributions of one derivative evaluation: the "a" vectors of the reverse RK4
// sweep (or the accumulated Adams coefficients) times the partials.
struct Contribution {
  StateRows state = StateRows::Zero();
  MassRow mass = MassRow::Zero();
  ConstraintVector theta = ConstraintVector::Zero();
  ConstraintVector chi = ConstraintVector::Zero();
  ConstraintVector rate = ConstraintVector::Zero();  // body dynamics: per rad/s of theta_c-dot
};

void accumulate(const Linearization& lin, const StateRows& a, int count, Contribution* c) {
  c->state.leftCols(count) += lin.df_dx.transpose() * a.leftCols(count);
  c->mass.leftCols(count) += lin.df_dm.transpose() * a.leftCols(count);
  c->theta.head(count) += (lin.df_dtheta.transpose() * a.leftCols(count)).transpose();
  c->chi.head(count) += (lin.df_dchi.transpose() * a.leftCols(count)).transpose();
  c->rate.head(count) += (lin.df_drate.transpose() * a.leftCols(count)).transpose();
}

class BackwardSweep {
 public:
  BackwardSweep(const Mission& mission, const PreparedCase& prepared, const Trajectory& trajectory, int count,
                const ConstraintTerminal* terminals, BackwardRun* out)
      : mission_(mission), prepared_(prepared), trajectory_(trajectory), count_(count), terminals_(terminals),
        out_(out), linearizer_(mission, prepared) {}

  Status run();

 private:
  void inject(int point);
  StateVector heat_integral_gradient(int point) const;
  void store(int point);
  void rk4_step(const StepRecord& step);
  void adams_step(const StepRecord& step);
  void coast_sensitivity(int slot, const StepCommand& last_command);
  void attribute_theta(const StepRecord& step, const ConstraintVector& start, const ConstraintVector& end);

  const Mission& mission_;
  const PreparedCase& prepared_;
  const Trajectory& trajectory_;
  const int count_;
  const ConstraintTerminal* terminals_;
  BackwardRun* out_;
  Linearizer linearizer_;
  StateRows state_ = StateRows::Zero();  // current adjoint of the state
  MassRow mass_ = MassRow::Zero();       // current adjoint of the mass
  StateRows pending_[4];                 // Adams coefficients waiting for their point (index mod 4)
};

void BackwardSweep::inject(int point) {
  bool heating_gradient_known = false;
  StateVector heating_gradient = StateVector::Zero();
  bool qbar_alpha_known = false;
  StateVector qbar_alpha_state = StateVector::Zero();
  double qbar_alpha_theta = 0.0;
  for (int j = 0; j < count_; ++j) {
    if (terminals_[j].qbar_alpha_integral) {
      // The q-bar x alpha excess (tolip/optimizer/qbar_alpha.hpp): forced through the state and
      // through the point's own pitch value. A gradient that failed is the run's failure (the
      // sweep's finiteness check stops it).
      if (!qbar_alpha_known) {
        if (!ok(qbar_alpha_excess_gradient(mission_, prepared_, trajectory_, point, &qbar_alpha_state,
                                           &qbar_alpha_theta))) {
          qbar_alpha_state.setConstant(std::numeric_limits<double>::quiet_NaN());
        }
        qbar_alpha_known = true;
      }
      state_.col(j) += qbar_alpha_state;
      out_->theta_gradient[point](j) += qbar_alpha_theta;
      continue;
    }
    if (terminals_[j].heat_integral) {
      if (!heating_gradient_known) {
        heating_gradient = heat_integral_gradient(point);
        heating_gradient_known = true;
      }
      state_.col(j) += heating_gradient;
      continue;
    }
    if (terminals_[j].point != point) continue;
    state_.col(j) += terminals_[j].partials.head<6>();
    mass_(j) += terminals_[j].partials[6];
  }
}

// d/dX_k of the trapezoidal heat integral: the point's trapezoidal weight times dQdot/dX there.
StateVector BackwardSweep::heat_integral_gradient(int k) const {
  const TrajectoryPoint& p = trajectory_.points[k];
  const double before = (k > 0) ? trajectory_.points[k - 1].time_s : p.time_s;
  const double after = (k + 1 < trajectory_.point_count) ? trajectory_.points[k + 1].time_s : p.time_s;
  const double weight = 0.5 * (after - before);
  if (!(weight > 0.0) || !(mission_.misc.nose_radius_ft > 0.0) ||
      p.altitude_ft > mission_.constants.haero_ft) {
    return StateVector::Zero();
  }
  const ConstraintPoint point = constraint_point_at(mission_, trajectory_, k);
  Eigen::Matrix<double, 6, 1> partials;
  if (!ok(stagnation_heating_rate_partials(mission_.constants, mission_.misc.nose_radius_ft,
                                           mission_.atmosphere.base_density_slug_ft3[0], point, &partials))) {
    return StateVector::Zero();
  }
  return weight * partials;
}

void BackwardSweep::store(int point) {
  out_->lambda[point].setZero();
  out_->lambda[point].topRows<6>() = state_;
  out_->lambda[point].row(6) = mass_;
}

// Attitude sensitivities of a step, given the sums over its evaluations of (df/dtheta)^T a weighted
// by how much of theta_start and theta_end each evaluation saw.
void BackwardSweep::attribute_theta(const StepRecord& step, const ConstraintVector& start,
                                    const ConstraintVector& end) {
  const StepCommand& c = step.command;
  if (c.mode == AttitudeMode::kHeld) {
    const int code = prepared_.timeline[step.stage_slot].code;
    if (mission_.options.stage_is_spun(code)) {
      out_->spun_theta.head(count_) += start.head(count_) + end.head(count_);
    }
    return;
  }
  if (c.mode != AttitudeMode::kLinear) return;
  const StageTimeline& line = prepared_.timeline[step.stage_slot];
  if (attitude_set_in_flight(mission_, line.code, line.start_s, c.step_start_s)) {
    // theta_start is the alpha = 0 attitude of the state at this point: it acts through the state.
    const StateVector g = linearizer_.zero_alpha_gradient(trajectory_.points[step.point].state);
    state_.leftCols(count_) += g * start.head(count_).transpose();
  } else {
    out_->theta_gradient[step.point].head(count_) += start.head(count_);
  }
  out_->theta_gradient[step.point + 1].head(count_) += end.head(count_);
}

void BackwardSweep::rk4_step(const StepRecord& step) {
  const StageContext stage = make_stage_context(mission_, prepared_, prepared_.timeline[step.stage_slot]);
  const StepCommand& command = step.command;
  const double t = command.step_start_s;
  const double h = command.step_s;
  const int n = count_;
  // A vertical-flight step is swept in its regular coordinates: the adjoint of the end state
  // becomes theirs on the way in and the start state's on the way out (chain rule through the
  // conversions; tolip/dynamics/vertical_flight.hpp).
  const StateVector& x0 = trajectory_.points[step.point].state;
  const StateVector y0 = command.vertical_flight ? to_vertical_coordinates(x0) : x0;
  if (command.vertical_flight) {
    linearizer_.set_heading_reference(x0[kStatePsi]);
    const StateVector& x1 = trajectory_.points[step.point + 1].state;
    state_.leftCols(n) = state_jacobian_from_vertical(x1).transpose() * state_.leftCols(n);
  }

  Linearization l1, l2, l3, l4;
  linearizer_.linearize(stage, command, t, y0, &l1);
  linearizer_.linearize(stage, command, t + 0.5 * h, StateVector(y0 + 0.5 * h * l1.f), &l2);
  linearizer_.linearize(stage, command, t + 0.5 * h, StateVector(y0 + 0.5 * h * l2.f), &l3);
  linearizer_.linearize(stage, command, t + h, StateVector(y0 + h * l3.f), &l4);

  // Reverse sweep of y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4).
  StateRows a4 = StateRows::Zero(), a3 = StateRows::Zero(), a2 = StateRows::Zero(), a1 = StateRows::Zero();
  a4.leftCols(n) = (h / 6.0) * state_.leftCols(n);
  a3.leftCols(n) = (h / 3.0) * state_.leftCols(n) + h * l4.df_dx.transpose() * a4.leftCols(n);
  a2.leftCols(n) = (h / 3.0) * state_.leftCols(n) + 0.5 * h * l3.df_dx.transpose() * a3.leftCols(n);
  a1.leftCols(n) = (h / 6.0) * state_.leftCols(n) + 0.5 * h * l2.df_dx.transpose() * a2.leftCols(n);
  // k1 is also the derivative later Adams steps of the same coast used.
  StateRows& pending = pending_[step.point % 4];
  a1.leftCols(n) += pending.leftCols(n);
  pending.setZero();

  Contribution c1, c2, c3, c4;
  accumulate(l1, a1, n, &c1);
  accumulate(l2, a2, n, &c2);
  accumulate(l3, a3, n, &c3);
  accumulate(l4, a4, n, &c4);
  state_.leftCols(n) +=
      c1.state.leftCols(n) + c2.state.leftCols(n) + c3.state.leftCols(n) + c4.state.leftCols(n);
  if (command.vertical_flight) state_.leftCols(n) = vertical_jacobian(x0).transpose() * state_.leftCols(n);
  mass_.leftCols(n) += c1.mass.leftCols(n) + c2.mass.leftCols(n) + c3.mass.leftCols(n) + c4.mass.leftCols(n);
  if (command.mode == AttitudeMode::kHeld) {
    out_->spun_chi.head(n) += c1.chi.head(n) + c2.chi.head(n) + c3.chi.head(n) + c4.chi.head(n);
  }
  // theta(t) = theta_start + fraction (theta_end - theta_start), fraction 0, 1/2, 1/2, 1.
  ConstraintVector start = c1.theta + 0.5 * (c2.theta + c3.theta);
  ConstraintVector end = c4.theta + 0.5 * (c2.theta + c3.theta);
  if (command.body_dynamics) {
    // theta_c-dot = (theta_end - theta_start) / h in every evaluation of the step (Sec. 7).
    const ConstraintVector rate = (c1.rate + c2.rate + c3.rate + c4.rate) / h;
    start -= rate;
    end += rate;
  }
  attribute_theta(step, start, end);
}

void BackwardSweep::adams_step(const StepRecord& step) {
  const int n = count_;
  const double h = step.command.step_s;
  const int k = step.point;
  // y_{k+1} = y_k + h/24 (55 f_k - 59 f_{k-1} + 37 f_{k-2} - 9 f_{k-3})
  pending_[k % 4].leftCols(n) += (55.0 * h / 24.0) * state_.leftCols(n);
  pending_[(k + 3) % 4].leftCols(n) += (-59.0 * h / 24.0) * state_.leftCols(n);
  pending_[(k + 2) % 4].leftCols(n) += (37.0 * h / 24.0) * state_.leftCols(n);
  pending_[(k + 1) % 4].leftCols(n) += (-9.0 * h / 24.0) * state_.leftCols(n);

  // f_k is complete: every later step that used it has been swept.
  const StageContext stage = make_stage_context(mission_, prepared_, prepared_.timeline[step.stage_slot]);
  Linearization lk;
  linearizer_.linearize(stage, step.command, step.command.step_start_s, trajectory_.points[k].state, &lk);
  StateRows& a = pending_[k % 4];
  Contribution c;
  accumulate(lk, a, n, &c);
  a.setZero();
  state_.leftCols(n) += c.state.leftCols(n);
  mass_.leftCols(n) += c.mass.leftCols(n);
  if (step.command.mode == AttitudeMode::kHeld) out_->spun_chi.head(n) += c.chi.head(n);
  if (step.command.body_dynamics) {
    const ConstraintVector rate = c.rate / h;
    attribute_theta(step, c.theta - rate, rate);
  } else {
    attribute_theta(step, c.theta, ConstraintVector::Zero());
  }
}

// Extending a coast by dT adds its derivative at the end: S = lambda . P (Sec. 9), evaluated
// with the adjoint at the coast's end point.
void BackwardSweep::coast_sensitivity(int slot, const StepCommand& last_command) {
  const StageTimeline& line = prepared_.timeline[slot];
  if (!is_coast_stage(line.code)) return;
  const StageContext stage = make_stage_context(mission_, prepared_, line);
  const TrajectoryPoint& p = trajectory_.points[trajectory_.stages[slot].last_point];
  Evaluation e;
  evaluate_flight(mission_, prepared_, stage, last_command, p.time_s, p.state, 0.0, &e);
  out_->coast_duration[stage_index(line.code)].head(count_) =
      (e.derivative.transpose() * state_.leftCols(count_)).transpose();
}

Status BackwardSweep::run() {
  const int last = trajectory_.point_count - 1;
  out_->constraint_count = count_;
  out_->point_count = trajectory_.point_count;
  out_->spun_theta.setZero();
  out_->spun_chi.setZero();
  out_->payload.setZero();
  for (int p = 0; p < trajectory_.point_count; ++p) {
    out_->theta_gradient[p].setZero();
    out_->quadrature_weight_s[p] = 0.0;
  }
  for (ConstraintVector& c : out_->coast_duration) c.setZero();
  for (StateRows& p : pending_) p.setZero();

  int current = last;
  inject(current);
  store(current);
  if (trajectory_.step_count > 0) {
    const StepRecord& final_step = trajectory_.steps[trajectory_.step_count - 1];
    coast_sensitivity(final_step.stage_slot, final_step.command);
  }
  for (int s = trajectory_.step_count - 1; s >= 0; --s) {
    const StepRecord& step = trajectory_.steps[s];
    const int end = step.point + 1;
    if (end < current) {
      // Across a stage boundary: the next stage's first point and this stage's end point share
      // the state (jettison changes only the weight, which no constraint sees through the state).
      current = end;
      inject(current);
      store(current);
      coast_sensitivity(step.stage_slot, step.command);
      for (StateRows& p : pending_) p.setZero();
    }
    if (step.adams) {
      adams_step(step);
    } else {
      rk4_step(step);
    }
    // Trapezoidal weights of the control measure.
    out_->quadrature_weight_s[step.point] += 0.5 * step.command.step_s;
    out_->quadrature_weight_s[step.point + 1] += 0.5 * step.command.step_s;
    current = step.point;
    inject(current);
    store(current);
    if (!state_.allFinite() || !mass_.allFinite()) return Status::kNonFiniteState;
  }

  // The lift-off: the state at its end depends on the payload through V_L and h_L.
  LiftoffResult liftoff;
  const Status status = closed_form_liftoff(mission_, prepared_, &liftoff);
  if (!ok(status)) return status;
  const double g0 = mission_.constants.g0_ft_s2;
  for (int j = 0; j < count_; ++j) {
    out_->payload(j) = mass_(j) / g0 + state_(kStateV, j) * liftoff.dvelocity_dweight_ft_s_per_lb +
                       state_(kStateR, j) * liftoff.dheight_dweight_ft_per_lb;
  }
  if (current > 0) store(0);  // the pad point: its state is fixed; keep the lift-off end's adjoint
  return Status::kOk;
}

}  // namespace

Status run_backward(const Mission& mission, const PreparedCase& prepared, const Trajectory& trajectory,
                    int constraint_count, const ConstraintTerminal* terminals, BackwardRun* out) {
  if (constraint_count < 1 || constraint_count > kMaxConstraints) return Status::kTooManyConstraints;
  if (trajectory.status != Status::kOk || trajectory.point_count < 2) {
    return Status::kBackwardRunWithoutTrajectory;
  }
  for (int j = 0; j < constraint_count; ++j) {
    if (terminals[j].point < 0 || terminals[j].point >= trajectory.point_count) {
      return Status::kConstraintPointNotInTrajectory;
    }
    if (!terminals[j].partials.allFinite()) return Status::kValueNotFinite;
  }
  BackwardSweep sweep(mission, prepared, trajectory, constraint_count, terminals, out);
  return sweep.run();
}

}  // namespace tolip
