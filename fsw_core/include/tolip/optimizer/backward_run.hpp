// Backward runs (manual Sec. 5, 9): the adjoint variables of every constraint along a stored
// nominal trajectory, and from them the sensitivities the steepest-descent law needs.
//
// The adjoint equations are those of the integrator actually flown (the discrete adjoint of RK4
// and of the RK4-started Adams-Bashforth coasts), not a separate integration of the continuous
// adjoint ODE: lambda is then the exact gradient of the computed trajectory, and an adjoint
// prediction agrees with a finite difference of forward runs to the difference's own truncation.
// The partial derivatives of F, G, H, I, J, K with respect to the state, the mass and the
// attitude are taken by central differences of the same model evaluation the forward run used
// (evaluate_flight), so the zero-alpha window's dependence of theta on the state, tables, the
// atmosphere and J2 are all linearized consistently (docs/theory/optimizer.md).
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

// Adjoint variables of one constraint: [lambda_V, lambda_gamma, lambda_r, lambda_psi, lambda_lambda,
// lambda_tau, lambda_m] (mass in slug).
inline constexpr int kAdjointSize = 7;
using AdjointVector = Eigen::Matrix<double, kAdjointSize, 1>;
using AdjointMatrix = Eigen::Matrix<double, kAdjointSize, kMaxConstraints>;  // one column per constraint
using ConstraintVector = Eigen::Matrix<double, kMaxConstraints, 1>;

// Where a constraint applies and its partial derivatives there (the ICS initial conditions).
struct ConstraintTerminal {
  int point = 0;  // trajectory point index
  AdjointVector partials = AdjointVector::Zero();
  // The total-heating constraint (code 14, Sec. 13) is the integral of the stagnation heating rate
  // over the stored points (trapezoidal): its adjoint is driven at every point by the heating
  // rate's partials instead of starting from `partials`.
  bool heat_integral = false;
  // The q-bar x alpha excess (code 200, tolip/optimizer/qbar_alpha.hpp), also an integral over the
  // stored points: driven at every point by qbar_alpha_excess_gradient (state and pitch value).
  bool qbar_alpha_integral = false;
};

struct BackwardRun {
  int constraint_count = 0;
  int point_count = 0;
  // dZ_j / dX at every point (column j = constraint j).
  AdjointMatrix lambda[kMaxTrajectoryPoints];
  // dZ_j / d theta_k: the effect of the per-point pitch-program value theta_k (rad) on constraint j.
  // Zero at points whose attitude is not a control (lift-off, zero-alpha window, alpha = 0 at stage-2
  // ignition, spun stages).
  ConstraintVector theta_gradient[kMaxTrajectoryPoints];
  // Weight of point k in the control measure: the integral of dtheta^2 dt is sum w_k dtheta_k^2.
  double quadrature_weight_s[kMaxTrajectoryPoints] = {};
  // dZ_j / d(spun stage-4 theta) and chi (rad), over stages 4 (and 5 when spun together).
  ConstraintVector spun_theta = ConstraintVector::Zero();
  ConstraintVector spun_chi = ConstraintVector::Zero();
  // dZ_j / d(duration of the coast with code 6..10) (s), index stage_index(code).
  ConstraintVector coast_duration[kMaxStages];
  // dZ_j / d(payload) (lb): through every stage's mass and through the lift-off.
  ConstraintVector payload = ConstraintVector::Zero();
};

// Integrates the adjoint of `trajectory` (flown with `program`, or with the block 40 table when
// program is null) backward from its last point. Constraint j's adjoint variables are zero after
// its point and set to its partials there. Fails with a named status on inconsistent input.
Status run_backward(const Mission& mission, const PreparedCase& prepared, const Trajectory& trajectory,
                    int constraint_count, const ConstraintTerminal* terminals, BackwardRun* out);

}  // namespace tolip
