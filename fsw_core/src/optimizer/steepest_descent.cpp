// Steepest-descent iteration of manual Sec. 5, 9 and 22 (docs/theory/optimizer.md).
#include "tolip/optimizer/steepest_descent.hpp"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/mission/adjustable_parameter.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/constraint_set.hpp"
#include "tolip/optimizer/qbar_alpha.hpp"

namespace tolip {
namespace {

using SquareMatrix = Eigen::Matrix<double, kMaxConstraints, kMaxConstraints>;

// The control measure's typical pitch change for the first payoff-improvement estimate (eq. 5-31):
// 1 deg over the burn of the non-spun powered stages (Options::stage_is_steered).
constexpr double kTypicalPitchChangeRad = 1.0 * kDegToRad;
// Guidance steps that make the constraint errors worse are retried at half size this many times.
constexpr int kGuidanceStepHalvings = 3;
// A step whose forward run fails is retried from the same nominal at half size up to this many
// times: 1/1024 of the step is a run indistinguishable from the nominal, which flew, so a failure
// that persists that far is not the step's size.
constexpr int kCrashRecoveryHalvings = 10;

// ---- the case's constraints and adjustable parameters -----------------------------------------

// The run's constraint set (tolip/optimizer/constraint_set.hpp: entry 0 the payoff with deadband 1;
// the constraints are steered in deadbands) and what the steering adds to it.
struct Problem : ConstraintSet {
  bool payload_is_control = false;
  double payload_weight = 1.0;  // DA2(15)
  int adjustable_count = 0;
  AdjustableParameter adjustable[kMaxAdjustableParameters] = {};
  double adjustable_weight[kMaxAdjustableParameters] = {};
  bool adjustable_active[kMaxAdjustableParameters] = {};
  // The heating constraint (IP(2), Sec. 13) joins the list when the heat integral first exceeds its limit.
  bool heating_listed = false;
  bool heating_active = false;
  double heating_limit_btu_ft2 = 0.0;
  double heating_deadband_btu_ft2 = 0.0;
  // The q-bar x alpha limit (issue 15, tolip/optimizer/qbar_alpha.hpp) joins the same way.
  bool qbar_alpha_listed = false;
  bool qbar_alpha_active = false;
};

Status make_problem(const Mission& mission, Problem* problem) {
  const ConstraintList& list = mission.constraints;
  problem->count = 0;
  for (int i = 0; i < list.count; ++i) {
    ConstraintCode code;
    Status status = decode_constraint_code(list.codes[i], &code);
    if (!ok(status)) return status;
    const double deadband = (i == 0) ? 1.0 : list.deadband_optimization[i - 1];
    status = append_constraint(code, list.desired[i], deadband, mission.options, problem);
    if (!ok(status)) return status;
  }
  const int payoff = mission.options.payoff();
  const ConstraintQuantity payoff_kind = problem->codes[0].kind;
  const bool consistent = (payoff == 0 && payoff_kind == ConstraintQuantity::kPayload) ||
                          (payoff == 1 && (payoff_kind == ConstraintQuantity::kInertialVelocity ||
                                           payoff_kind == ConstraintQuantity::kAerodynamicVelocity)) ||
                          (payoff == 2 && payoff_kind == ConstraintQuantity::kAltitude);
  if (!consistent || problem->codes[0].is_stage_point) return Status::kPayoffNotSupported;
  problem->payload_is_control = payoff == 0;
  problem->payload_payoff = problem->payload_is_control;
  problem->payload_weight = mission.misc.payload_weighting_factor;
  if (mission.options.heating_constraint()) {
    if (list.codes[list.count] != 14) return Status::kUnknownConstraintCode;
    if (list.count + 1 > kMaxConstraints) return Status::kTooManyConstraints;
    problem->heating_listed = true;
    problem->heating_limit_btu_ft2 = list.desired[list.count];
    problem->heating_deadband_btu_ft2 = list.deadband_optimization[list.count - 1];
    if (!(problem->heating_deadband_btu_ft2 > 0.0)) return Status::kDeadbandNotPositive;
  }
  if (mission.options.qbar_alpha_constraint()) {
    if (list.count + (problem->heating_listed ? 1 : 0) + 1 > kMaxConstraints) {
      return Status::kTooManyConstraints;
    }
    problem->qbar_alpha_listed = true;
  }

  problem->adjustable_count = mission.adjustable.count;
  for (int p = 0; p < mission.adjustable.count; ++p) {
    AdjustableParameter parameter = AdjustableParameter::kStage4Theta;
    if (!decode_adjustable_parameter(mission.adjustable.codes[p], &parameter)) {
      return Status::kAdjustableParameterNotSupported;
    }
    // A coast left out of the sequence (powered stages back to back) has no length to adjust.
    const int coast = adjusted_coast_stage_code(parameter);
    if (coast != 0 && !mission.vehicle.stages[stage_index(coast)].in_sequence) {
      return Status::kAdjustableCoastNotInSequence;
    }
    problem->adjustable[p] = parameter;
    problem->adjustable_weight[p] = mission.adjustable.weights[p];
    problem->adjustable_active[p] = true;
  }
  return Status::kOk;
}

// Sec. 13: once the heat integral exceeds its limit the heating constraint is appended to the list
// and kept for the rest of the case. (Room and a positive deadband were checked by make_problem, so
// a failure here is a fault of the optimizer, passed on by name rather than flown past.)
Status activate_heating_if_exceeded(const Trajectory& nominal, const Options& options, Problem* problem) {
  if (!problem->heating_listed || problem->heating_active) return Status::kOk;
  if (!(nominal.heat_integral_btu_ft2 > problem->heating_limit_btu_ft2)) return Status::kOk;
  ConstraintCode heating;
  Status status = decode_constraint_code(14, &heating);
  if (ok(status)) {
    status = append_constraint(heating, problem->heating_limit_btu_ft2, problem->heating_deadband_btu_ft2,
                               options, problem);
  }
  if (!ok(status)) return status;
  problem->heating_active = true;
  return Status::kOk;
}

// The q-bar x alpha limit likewise: appended once a nominal's excess integral is positive (room
// checked by make_problem; the deadband is a positive constant).
Status activate_qbar_alpha_if_exceeded(const Mission& mission, const Trajectory& nominal, Problem* problem) {
  if (!problem->qbar_alpha_listed || problem->qbar_alpha_active) return Status::kOk;
  if (!(qbar_alpha_excess_s(mission, nominal) > 0.0)) return Status::kOk;
  ConstraintCode code;
  Status status = decode_constraint_code(kQbarAlphaConstraintCode, &code);
  if (ok(status)) status = append_constraint(code, 0.0, kQbarAlphaExcessDeadbandS, mission.options, problem);
  if (!ok(status)) return status;
  problem->qbar_alpha_active = true;
  return Status::kOk;
}

// ---- constraint values: tolip/optimizer/constraint_set.hpp -------------------------------------

// A constraint without a value on a run (an asymptote direction the Addendum H stand-in defers: NaN)
// asks for no change and adds nothing to the error norm or the corrected payoff; within_deadbands
// still counts it as not met.
double correction(const Problem& problem, int i, const double achieved[kMaxConstraints]) {
  const double c = constraint_correction(problem, i, achieved[i]);
  return std::isnan(c) ? 0.0 : c;
}

bool is_asymptote_direction(ConstraintQuantity kind) {
  return kind == ConstraintQuantity::kAsymptoteRightAscension ||
         kind == ConstraintQuantity::kAsymptoteDeclination;
}

bool within_deadbands(const Problem& problem, const double achieved[kMaxConstraints]) {
  return tolip::within_deadbands(problem, 1, achieved);
}

// Constraint errors measured in deadbands (the guidance runs' figure of merit), without the
// constraints a guidance step defers (nullptr: none).
double error_norm(const Problem& problem, const double achieved[kMaxConstraints],
                  const bool* deferred = nullptr) {
  double sum = 0.0;
  for (int i = 1; i < problem.count; ++i) {
    if (deferred != nullptr && deferred[i]) continue;
    const double e = correction(problem, i, achieved) / problem.deadband[i];
    sum += e * e;
  }
  return std::sqrt(sum);
}

// ---- the steering law --------------------------------------------------------------------------

// Sensitivities the backward run does not produce: launch azimuth (by central differences of two
// forward runs, since the azimuth turns the platform for the whole flight and the lift-off heading)
// and launch time of day (the explicit dependence of node longitude and asymptote right
// ascension on Greenwich's right ascension, Sec. 9).
struct LaunchColumns {
  ConstraintVector azimuth = ConstraintVector::Zero();      // per rad
  ConstraintVector launch_time = ConstraintVector::Zero();  // per s
};

// Sensitivity column of adjustable parameter p.
ConstraintVector parameter_column(const Problem& problem, const BackwardRun& backward,
                                  const LaunchColumns& launch, int p) {
  switch (problem.adjustable[p]) {
    case AdjustableParameter::kStage4Theta:
    case AdjustableParameter::kStage5Theta: return backward.spun_theta;
    case AdjustableParameter::kStage4Chi:
    case AdjustableParameter::kStage5Chi: return backward.spun_chi;
    case AdjustableParameter::kLaunchAzimuth: return launch.azimuth;
    case AdjustableParameter::kLaunchTime: return launch.launch_time;
    default: return backward.coast_duration[stage_index(adjusted_coast_stage_code(problem.adjustable[p]))];
  }
}

struct Steering {
  int first = 0;  // 0 on optimization runs (payoff included), 1 on guidance runs
  // Constraints left out of this steering (weak directions of the matrix, below): their rows and
  // columns are the identity, their sensitivities and requested changes are zero.
  bool held[kMaxConstraints] = {};
  // The independent steerability of each constraint: sqrt(pivot dP^2), the deadbands the typical
  // control change dP^2 moves it with the others held (0 for the payoff and inactive constraints).
  double steerability_deadbands[kMaxConstraints] = {};
  // Held because they are deferred (the argument of perigee while the shape is corrected, below):
  // the guidance runs' figure of merit leaves them out too.
  bool deferred[kMaxConstraints] = {};
  SquareMatrix matrix = SquareMatrix::Identity();  // integral of Lambda Lambda^T + S Y^-1 S^T (scaled)
  Eigen::LLT<SquareMatrix> cholesky;
};

// Component i of a constraint-space vector scaled by the deadbands and without the constraints the
// steering leaves out (the payoff on guidance runs, held constraints).
ConstraintVector scaled(const Problem& problem, const ConstraintVector& v, const Steering& steering) {
  ConstraintVector out = ConstraintVector::Zero();
  for (int i = steering.first; i < problem.count; ++i) {
    if (!steering.held[i]) out(i) = v(i) / problem.deadband[i];
  }
  return out;
}

// A requested change without the components the steering leaves out.
ConstraintVector steered_part(const Steering& steering, const ConstraintVector& dpsi) {
  ConstraintVector out = dpsi;
  for (int i = 0; i < kMaxConstraints; ++i) {
    if (i < steering.first || steering.held[i]) out(i) = 0.0;
  }
  return out;
}

// Eqs. 9-7, 9-8: I + J over the active constraints; identity outside them.
// dZ/d(payload mass, slug) = g0 dZ/d(payload weight, lb).
ConstraintVector payload_mass_column(const BackwardRun& backward, double g0) { return g0 * backward.payload; }

// Weak directions (issue 17). The matrix's pivot for constraint i given the constraints already
// taken, p_i = M_ii - M_i,T M_T,T^-1 M_T,i (its Schur complement, deadbands^2 per unit of the control
// measure rad^2 s), is what the controls can still do to constraint i alone. A constraint whose
// pivot is near zero (the inclination of a launch due east at the target inclination: no control
// changes it to first order) makes nu = M^-1 d psi huge in its direction: a tiny in-deadband error
// then asks for an enormous pitch change, and the next runs fail their deadbands or go below the
// surface. The typical control change of
// eq. 5-31, dP^2 = (1 deg)^2 x the burn time, moves constraint i by sqrt(p_i dP^2) deadbands with
// the others held. Below kMinimumSteerableDeadbands a correction of one deadband would need a
// pitch change of 1/kMinimumSteerableDeadbands deg RMS over the whole burn (50 deg): far outside
// the first-order theory the step is computed from, so the constraint is held instead: it leaves
// the steering (row and column replaced by the identity) and is judged only by its deadband.
constexpr double kMinimumSteerableDeadbands = 0.02;

// Pivoted Cholesky over the constraints (the payoff last, always kept): the strongest remaining
// pivot is taken first, so of several nearly dependent constraints the weakest is the one held.
void hold_weak_directions(const Problem& problem, double dp2, SquareMatrix* m, Steering* steering) {
  SquareMatrix schur = *m;
  bool taken[kMaxConstraints] = {};
  const int count = problem.count;
  for (int round = 1; round < count; ++round) {
    int best = -1;
    for (int i = 1; i < count; ++i) {
      if (!taken[i] && (best < 0 || schur(i, i) > schur(best, best))) best = i;
    }
    if (best < 0) break;
    const double pivot = schur(best, best);
    if (!(pivot * dp2 >= kMinimumSteerableDeadbands * kMinimumSteerableDeadbands)) break;
    taken[best] = true;
    steering->steerability_deadbands[best] = std::sqrt(pivot * dp2);
    for (int j = 0; j < count; ++j) {
      for (int k = 0; k < count; ++k) {
        if (j != best && k != best) schur(j, k) -= schur(j, best) * schur(best, k) / pivot;
      }
    }
    for (int j = 0; j < count; ++j) schur(j, best) = schur(best, j) = 0.0;
  }
  for (int i = 1; i < count; ++i) {
    if (taken[i]) continue;
    steering->held[i] = true;
    const double pivot = schur(i, i);
    steering->steerability_deadbands[i] = (pivot > 0.0) ? std::sqrt(pivot * dp2) : 0.0;
    m->row(i).setZero();
    m->col(i).setZero();
    (*m)(i, i) = 1.0;
  }
}

// Deferred argument of perigee (issue 17). The argument of perigee (13) is the orientation of the
// ellipse in its plane: where the perigee lies depends on the orbit's shape, and its sensitivity
// to the controls grows as 1 / e. From a crude start (a 0.38 eccentric, suborbital orbit whose
// perigee lies 110 deg from the target's), its linearization is meaningless: one step asking for
// the 110 deg wrecks energy and perigee radius, and no halving recovers. Guidance therefore
// steers the shape first: while any other constraint is outside its deadband, the argument of
// perigee is held (identity row and column, no requested change, judged by its deadband like a
// weak direction), then steered with the others. Only decks constraining code 13 are affected.
bool deferred_in_guidance(const Problem& problem, int i, const double achieved[kMaxConstraints]) {
  if (problem.codes[i].kind != ConstraintQuantity::kArgumentOfPerigee) return false;
  for (int j = 1; j < problem.count; ++j) {
    if (j == i || problem.codes[j].kind == ConstraintQuantity::kArgumentOfPerigee) continue;
    if (!(std::fabs(correction(problem, j, achieved)) <= problem.deadband[j])) return true;
  }
  return false;
}

Status build_steering(const Problem& problem, const BackwardRun& backward, const LaunchColumns& launch,
                      const bool* free_points, double g0_, int first, double dp2, Steering* steering,
                      const bool* deferred = nullptr) {
  steering->first = first;
  for (int i = 0; i < kMaxConstraints; ++i) {
    steering->deferred[i] = deferred != nullptr && i >= first && i < problem.count && deferred[i];
    steering->held[i] = steering->deferred[i];
    steering->steerability_deadbands[i] = 0.0;
  }
  SquareMatrix m = SquareMatrix::Zero();
  for (int k = 0; k < backward.point_count; ++k) {
    const double w = backward.quadrature_weight_s[k];
    if (!(w > 0.0) || !free_points[k]) continue;
    const ConstraintVector g = scaled(problem, backward.theta_gradient[k], *steering);
    m += g * g.transpose() / w;
  }
  for (int p = 0; p < problem.adjustable_count; ++p) {
    if (!problem.adjustable_active[p]) continue;
    const ConstraintVector s = scaled(problem, parameter_column(problem, backward, launch, p), *steering);
    m += s * s.transpose() / problem.adjustable_weight[p];
  }
  if (problem.payload_is_control) {
    // The payload enters as a mass in slug (the column of lambda_m at launch, Sec. 9).
    const ConstraintVector s = scaled(problem, payload_mass_column(backward, g0_), *steering);
    m += problem.payload_weight * s * s.transpose();
  }
  for (int i = 0; i < kMaxConstraints; ++i) {
    if (i >= first && i < problem.count) continue;
    m.row(i).setZero();
    m.col(i).setZero();
    m(i, i) = 1.0;
  }
  hold_weak_directions(problem, dp2, &m, steering);
  steering->matrix = m;
  steering->cholesky.compute(m);
  if (steering->cholesky.info() != Eigen::Success) return Status::kSteeringMatrixSingular;
  return Status::kOk;
}

// Eq. 9-22: partials of the payoff with respect to each constraint, from the optimization matrix.
void payoff_partials(const Problem& problem, const SquareMatrix& full, double out[kMaxConstraints]) {
  SquareMatrix guidance = full;
  guidance.row(0).setZero();
  guidance.col(0).setZero();
  guidance(0, 0) = 1.0;
  const Eigen::LLT<SquareMatrix> cholesky(guidance);
  ConstraintVector coupling = full.row(0).transpose();
  coupling(0) = 0.0;
  const ConstraintVector scaled_partials = cholesky.solve(coupling);
  out[0] = 0.0;
  for (int i = 1; i < problem.count; ++i) out[i] = scaled_partials(i) / problem.deadband[i];
}

// Eqs. 5-32..5-34: the payoff improvement that a control change of size dP^2 buys while removing
// the constraint errors d phi.
bool initial_payoff_improvement(const Problem& problem, const Steering& optimization,
                                const ConstraintVector& dphi, double dp2, double* improvement) {
  const SquareMatrix a = optimization.cholesky.solve(SquareMatrix::Identity());
  const double a11 = a(0, 0);
  double n_dphi = 0.0;
  double dphi_m_dphi = 0.0;
  for (int i = 1; i < problem.count; ++i) {
    n_dphi += a(i, 0) * dphi(i);
    for (int j = 1; j < problem.count; ++j) dphi_m_dphi += dphi(i) * a(i, j) * dphi(j);
  }
  const double discriminant = n_dphi * n_dphi - a11 * (dphi_m_dphi - dp2);
  if (!(a11 > 0.0) || !(discriminant > 0.0)) return false;
  *improvement = (-n_dphi + std::sqrt(discriminant)) / a11;
  return *improvement > 0.0;
}

// ---- control constraints ------------------------------------------------------------------------

// Which per-point pitch values the optimizer steers: points of the stages that fly the pitch
// program (stages 1-3, and 4 and 5 when IP(9) does not spin them: Options::stage_is_steered) whose
// value enters a kLinear step, except the end of lift-off (theta = 90 deg there) and the points
// whose attitude is set in flight (end of the zero-alpha window, stage-2 ignition under IP(12)).
// The coasts between two steered stages (6 and 7; 8 and 9 too when IP(9) steers stages 4 and 5)
// fly one linear segment each between the attitudes of the stages around them (data block 18:
// "one segment each for intermediate coast stages"), so a lift pulse in coast 6 cannot be bought
// with an attitude spike; spun stages have their own parameters.
struct PointRoles {
  bool free[kMaxTrajectoryPoints] = {};
  bool intermediate_coast[kMaxTrajectoryPoints] = {};
  int last_shaped = 0;  // last point of the last steered stage
};

// Coast n+5 lies between steered stages n and n+1 when stage n+1 is flown and steered (stage n
// then is).
bool is_intermediate_coast(const Mission& mission, int code) {
  return is_coast_stage(code) && mission.options.stage_is_steered(code - 4) &&
         mission.vehicle.stages[stage_index(code - 4)].in_sequence;
}

void classify_points(const Mission& mission, const Trajectory& t, PointRoles* roles) {
  for (int k = 0; k < t.point_count; ++k) {
    roles->free[k] = false;
    roles->intermediate_coast[k] = false;
  }
  roles->last_shaped = 0;
  for (int s = 0; s < t.step_count; ++s) {
    const StepRecord& step = t.steps[s];
    const StageEvent& stage = t.stages[step.stage_slot];
    const int code = stage.code;
    if (is_intermediate_coast(mission, code)) {
      roles->intermediate_coast[step.point] = true;
      roles->intermediate_coast[step.point + 1] = true;
      continue;
    }
    if (!mission.options.stage_is_steered(code)) continue;
    roles->last_shaped = stage.last_point;
    if (step.command.mode != AttitudeMode::kLinear) continue;
    const bool liftoff_end = code == 1 && step.point == stage.first_point;
    const double stage_start = t.points[stage.first_point].time_s - t.points[stage.first_point].stage_time_s;
    const bool set_in_flight = attitude_set_in_flight(mission, code, stage_start, step.command.step_start_s);
    if (!liftoff_end && !set_in_flight) roles->free[step.point] = true;
    if (step.point + 1 == stage.last_point) roles->free[stage.last_point] = true;
  }
}

// The launch vertical: theta is measured from the launch geodetic horizontal (90 deg at the end of
// the lift-off). A first-order step from a program that leaves the vertical asks the early points
// to pitch back past it when the constraints want a later turn (the flat crude program of
// hard_cases_test asked 95 deg at 4 s): the flight then passes over the vertical, where its heading
// is undefined, and once the heading hold of the lift-off has ended the heading equation, which
// divides by cos(gamma), makes the 1 s steps there chaotic (psi 100 -> 2356 deg in 5 s): the
// nominal and its adjoint are artefacts and no step from them flies.
constexpr double kVerticalPitchRad = 0.5 * kPi;

// Shapes a candidate program: the steered attitudes at most vertical (above), the maximum pitch
// rate of data block 22 between consecutive shaped points (projected forward from lift-off, back
// from the end of the last steered stage, and forward again; points not steered anchor the
// projection at the attitude the nominal flew there), then the
// intermediate coasts as straight lines between their neighbours. TOLIP imposed the maximum rate
// only after lift-off; docs/theory/optimizer.md explains the projection.
void shape_program(const Mission& mission, const Trajectory& nominal, const PointRoles& roles,
                   ControlProgram* program) {
  const int last = roles.last_shaped;
  for (int k = 0; k <= last; ++k) {
    if (!roles.free[k] && !roles.intermediate_coast[k]) program->theta_rad[k] = nominal.points[k].theta_rad;
  }
  // Never steered back past the launch vertical (issue 17; docs/theory/optimizer.md "Control
  // constraints"): a steered attitude is at most 90 deg, or the nominal's where the deck's program
  // already flew above it.
  for (int k = 0; k <= last; ++k) {
    if (!roles.free[k]) continue;
    program->theta_rad[k] =
        std::fmin(program->theta_rad[k], std::fmax(kVerticalPitchRad, nominal.points[k].theta_rad));
  }
  const double rate = mission.control.max_pitch_rate_rad_s;
  if (rate > 0.0) {
    for (int pass = 0; pass < 3; ++pass) {
      const bool forward = pass != 1;
      int previous = -1;
      for (int i = 1; i <= last; ++i) {
        const int k = forward ? i : last + 1 - i;
        if (roles.intermediate_coast[k]) continue;
        if (previous >= 0 && roles.free[k]) {
          const double dt = std::fabs(nominal.points[k].time_s - nominal.points[previous].time_s);
          const double neighbour = program->theta_rad[previous];
          program->theta_rad[k] =
              std::fmax(neighbour - rate * dt, std::fmin(neighbour + rate * dt, program->theta_rad[k]));
        }
        previous = k;
      }
    }
  }
  // Intermediate coasts: linear in time from the previous stage's end to the next stage's start.
  for (int s = 0; s < nominal.stage_count; ++s) {
    const StageEvent& coast = nominal.stages[s];
    if (!is_intermediate_coast(mission, coast.code) || s == 0 || s + 1 >= nominal.stage_count) continue;
    const int before = nominal.stages[s - 1].last_point;
    const int after = nominal.stages[s + 1].first_point;
    const double t0 = nominal.points[before].time_s;
    const double t1 = nominal.points[after].time_s;
    for (int k = coast.first_point; k <= coast.last_point; ++k) {
      const double fraction = (t1 > t0) ? (nominal.points[k].time_s - t0) / (t1 - t0) : 0.0;
      program->theta_rad[k] =
          program->theta_rad[before] + fraction * (program->theta_rad[after] - program->theta_rad[before]);
    }
  }
}

// ---- closed loop (eqs. 9-1, 9-2, 9-14) -----------------------------------------------------------

// At each of the first kMaxClosedLoopPoints integration points after lift-off the remaining pitch
// program is recomputed from the deviation dx of the flight from the nominal at that point:
// nu_k = M_k^-1 (d psi - lambda_k dx_k) with M_k the steering matrix over the controls still ahead,
// dtheta_j = G_j . nu_k / w_j for every later point. After the last closed-loop point the program
// stays as last computed: the open loop with K = nu at the switch (eq. 9-3). Adjustable parameters
// and the payload are decided at launch with the open-loop law.
// final and never deleted through the base (no heap in the core):
// NOLINTNEXTLINE(cppcoreguidelines-virtual-class-destructor)
class ClosedLoopSteering final : public PitchFeedback {
 public:
  ClosedLoopSteering(const Problem& problem, const BackwardRun& backward, const PointRoles& roles,
                     const Mission& mission, const Trajectory& nominal, const ControlProgram& nominal_program,
                     const Steering& steering, const ConstraintVector& dpsi, double mass_change_slug,
                     double dp2)
      : problem_(problem), backward_(backward), roles_(roles), mission_(mission), nominal_(nominal),
        nominal_program_(nominal_program), steering_(steering), dpsi_(steered_part(steering, dpsi)),
        mass_change_slug_(mass_change_slug), dp2_(dp2), remaining_(steering.matrix) {
    // The same sum over the pitch controls alone (the adjustable parameters and the payload are
    // decided at launch: in flight they move nothing), with the rows of the constraints the
    // steering leaves out kept at the identity.
    pitch_remaining_.setZero();
    for (int k = 0; k < backward.point_count; ++k) {
      const double w = backward.quadrature_weight_s[k];
      if (!(w > 0.0) || !roles.free[k]) continue;
      const ConstraintVector g = scaled(problem, backward.theta_gradient[k], steering);
      pitch_remaining_ += g * g.transpose() / w;
    }
    for (int i = 0; i < kMaxConstraints; ++i) {
      if (i >= steering.first && i < problem.count && !steering.held[i]) continue;
      pitch_remaining_.row(i).setZero();
      pitch_remaining_.col(i).setZero();
      pitch_remaining_(i, i) = 1.0;
    }
    // The closed-loop points: the first kMaxClosedLoopPoints step starts after lift-off.
    for (int s = 0, n = 0; s < nominal.step_count && n < kMaxClosedLoopPoints; ++s, ++n) {
      last_point_ = nominal.steps[s].point;
    }
  }

  void at_point(int point, const StateVector& state, ControlProgram* program) override {
    if (point > last_point_ || point < 1) return;
    // Controls already flown leave the matrix.
    for (int j = next_removed_; j < point; ++j) {
      const double w = backward_.quadrature_weight_s[j];
      if (!(w > 0.0) || !roles_.free[j]) continue;
      const ConstraintVector g = scaled(problem_, backward_.theta_gradient[j], steering_);
      remaining_ -= g * g.transpose() / w;
      pitch_remaining_ -= g * g.transpose() / w;
    }
    next_removed_ = point;
    // A path constraint whose excess lies on points already flown (the q-bar x alpha excess of
    // the first seconds) and that the pitch controls still ahead can no longer move, by the rule
    // of the launch steering (hold_weak_directions), is held from here on: only the payload,
    // decided at launch, still couples it, and through that coupling its residual would be spread
    // over the other constraints' controls of the later stages. (Terminal constraints keep the
    // manual's closed loop: docs/theory/optimizer.md.)
    SquareMatrix pitch = pitch_remaining_;
    Steering weak;
    weak.first = steering_.first;
    hold_weak_directions(problem_, dp2_, &pitch, &weak);
    for (int i = 0; i < kMaxConstraints; ++i) {
      const bool path = i < problem_.count && problem_.codes[i].kind == ConstraintQuantity::kQbarAlphaExcess;
      weak.held[i] = path && weak.held[i] && !steering_.held[i];
    }
    SquareMatrix m = remaining_;
    for (int i = steering_.first; i < problem_.count; ++i) {
      if (!weak.held[i]) continue;
      m.row(i).setZero();
      m.col(i).setZero();
      m(i, i) = 1.0;
    }
    const Eigen::LLT<SquareMatrix> cholesky(m);
    if (cholesky.info() != Eigen::Success) return;  // keep the program as planned

    AdjointVector dx;
    dx.head<6>() = state - nominal_.points[point].state;
    dx[6] = mass_change_slug_;
    ConstraintVector rhs = dpsi_;
    const AdjointMatrix& lambda = backward_.lambda[point];
    for (int i = steering_.first; i < problem_.count; ++i) {
      if (weak.held[i]) {
        rhs(i) = 0.0;
      } else if (!steering_.held[i]) {
        rhs(i) -= lambda.col(i).dot(dx) / problem_.deadband[i];
      }
    }
    const ConstraintVector nu = cholesky.solve(rhs);
    for (int j = point; j < backward_.point_count; ++j) {
      const double w = backward_.quadrature_weight_s[j];
      if (!(w > 0.0) || !roles_.free[j]) continue;
      program->theta_rad[j] = nominal_program_.theta_rad[j] +
                              scaled(problem_, backward_.theta_gradient[j], steering_).dot(nu) / w;
    }
    shape_program(mission_, nominal_, roles_, program);
  }

 private:
  const Problem& problem_;
  const BackwardRun& backward_;
  const PointRoles& roles_;
  const Mission& mission_;
  const Trajectory& nominal_;
  const ControlProgram& nominal_program_;
  const Steering& steering_;  // outlives the forward run it steers
  const ConstraintVector dpsi_;
  const double mass_change_slug_;
  const double dp2_;              // eq. 5-31's typical control measure (the weak-direction rule)
  SquareMatrix remaining_;        // M over the controls not yet flown
  SquareMatrix pitch_remaining_;  // its pitch-control part (no adjustable parameters, no payload)
  int next_removed_ = 0;
  int last_point_ = 0;
};

// ---- one forward run with the steering applied -------------------------------------------------

class Iteration {
 public:
  Iteration(const Problem& problem, OptimizerWorkspace* ws, OptimizerResult* result)
      : problem_(problem), ws_(ws), result_(result) {}

  Status run(const Mission& input);

 private:
  Status fly_nominal_from_table();
  Status backward(int first, Steering* steering);
  Status launch_sensitivities();
  Status fly_candidate(const Steering& steering, const ConstraintVector& dpsi, double step_fraction);
  Status accept_candidate();
  Status guidance_phase(int budget, Steering* steering);
  Status optimization_phase(int budget, Steering* steering);
  void record(RunKind kind, Status run_status, bool successful, double attempted);
  ConstraintVector corrections(const double achieved[kMaxConstraints]) const;
  double corrected_payoff(const double achieved[kMaxConstraints]) const;
  double burn_time_s() const;
  double typical_control_measure() const;

  Problem problem_;  // a copy: the heating constraint may join during the case
  OptimizerWorkspace* ws_;
  OptimizerResult* result_;
  double nominal_achieved_[kMaxConstraints] = {};
  double candidate_achieved_[kMaxConstraints] = {};
  double partials_[kMaxConstraints] = {};
  PointRoles roles_;
  LaunchColumns launch_columns_;
  // A path constraint (q-bar x alpha) joined the list at the last accepted nominal: an
  // optimization phase that it ends goes back to guidance (docs/theory/optimizer.md).
  bool path_constraint_joined_ = false;
  bool guidance_stuck_ = false;  // a guidance step that never flew ended guidance
  double attempt_size_ = 0.0;    // the optimization's payoff-improvement attempt
  bool first_attempt_ = true;    // the next optimization phase sizes its first attempt
};

ConstraintVector Iteration::corrections(const double achieved[kMaxConstraints]) const {
  ConstraintVector d = ConstraintVector::Zero();
  for (int i = 1; i < problem_.count; ++i) d(i) = correction(problem_, i, achieved) / problem_.deadband[i];
  return d;
}

double Iteration::corrected_payoff(const double achieved[kMaxConstraints]) const {
  double corrected = achieved[0];
  for (int i = 1; i < problem_.count; ++i) corrected += partials_[i] * correction(problem_, i, achieved);
  return corrected;
}

double Iteration::burn_time_s() const {
  double total = 0.0;
  for (int k = 0; k < ws_->prepared.stage_count; ++k) {
    const int code = ws_->prepared.timeline[k].code;
    if (ws_->mission.options.stage_is_steered(code)) total += ws_->prepared.timeline[k].duration_s;
  }
  return total;
}

// Eq. 5-31's dP^2: the typical pitch change squared times the burn of the steered stages.
double Iteration::typical_control_measure() const {
  return kTypicalPitchChangeRad * kTypicalPitchChangeRad * burn_time_s();
}

// Records the forward run just made. Beyond the history's capacity the run is still told to the
// observer and counted in iterations_dropped. A run that failed (run_status not kOk: it went below
// the surface, say) has no payoff or constraint values of its own: they are NaN, flagged by its
// status, rather than the previous run's.
void Iteration::record(RunKind kind, Status run_status, bool successful, double attempted) {
  // cppcheck-suppress unassignedVariable ; the sink of a record beyond the capacity, written through r
  IterationRecord overflow;
  const bool stored = result_->iteration_count < kMaxOptimizerIterations;
  IterationRecord& r = stored ? result_->iterations[result_->iteration_count++] : overflow;
  if (!stored) ++result_->iterations_dropped;
  r.forward_run = result_->forward_runs;
  r.kind = kind;
  r.run_status = run_status;
  r.successful = successful;
  r.attempted_payoff_improvement = attempted;
  const bool flown = ok(run_status);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.payoff = flown ? candidate_achieved_[0] : nan;
  r.corrected_payoff = flown ? corrected_payoff(candidate_achieved_) : nan;
  r.payload_lb = ws_->candidate_mission.vehicle.payload_lb;
  r.payload_increment_lb = ws_->candidate_mission.vehicle.payload_lb - ws_->mission.vehicle.payload_lb;
  for (int i = 1; i < problem_.count; ++i) {
    // NaN too for an asymptote direction the stand-in defers (it has no value on this run).
    r.constraint_corrections[i] = flown ? constraint_correction(problem_, i, candidate_achieved_[i]) : nan;
    r.payoff_partials[i] = partials_[i];
    // The initial nominal follows no backward run: nothing was steered or held.
    r.constraint_held[i] = kind != RunKind::kInitialNominal && result_->constraint_held[i];
    if (r.constraint_held[i] && result_->constraint_deferred[i]) {
      ++result_->deferred_runs[i];
    } else if (r.constraint_held[i]) {
      ++result_->held_runs[i];
    }
  }
  if (ws_->observer != nullptr) {
    ws_->observer->on_forward_run(r, *result_);
    if (kind == RunKind::kInitialNominal) {
      ws_->observer->on_forward_trajectory(r, ws_->mission, ws_->nominal, nullptr);
    } else {
      ws_->observer->on_forward_trajectory(r, ws_->candidate_mission, ws_->candidate, &ws_->nominal);
    }
  }
}

Status Iteration::fly_nominal_from_table() {
  ++result_->forward_runs;
  Status status = fly_trajectory(ws_->mission, ws_->prepared, &ws_->nominal);
  if (!ok(status)) return status;
  ws_->program.point_count = ws_->nominal.point_count;
  for (int k = 0; k < ws_->nominal.point_count; ++k) {
    ws_->program.theta_rad[k] = ws_->nominal.points[k].theta_rad;
  }
  classify_points(ws_->mission, ws_->nominal, &roles_);
  status = activate_heating_if_exceeded(ws_->nominal, ws_->mission.options, &problem_);
  if (!ok(status)) return status;
  problem_.hyperbolic_stand_in = needs_hyperbolic_stand_in(problem_, ws_->mission, ws_->nominal);
  status = evaluate_constraints(problem_, ws_->mission, ws_->nominal, nominal_achieved_);
  if (!ok(status)) return status;
  for (int i = 0; i < problem_.count; ++i) candidate_achieved_[i] = nominal_achieved_[i];
  ws_->candidate_mission = ws_->mission;
  record(RunKind::kInitialNominal, Status::kOk, within_deadbands(problem_, nominal_achieved_), 0.0);
  return Status::kOk;
}

Status Iteration::launch_sensitivities() {
  launch_columns_ = LaunchColumns();
  bool azimuth = false;
  for (int p = 0; p < problem_.adjustable_count; ++p) {
    if (problem_.adjustable[p] == AdjustableParameter::kLaunchAzimuth) {
      azimuth = problem_.adjustable_active[p];
    }
  }
  for (int i = 0; i < problem_.count; ++i) {
    launch_columns_.launch_time(i) = constraint_partial_wrt_launch_time(problem_.codes[i]);
  }
  if (!azimuth) return Status::kOk;
  // The candidate buffers are free between a backward run and the next forward run.
  constexpr double kAzimuthStepRad = 1e-5;
  double achieved[2][kMaxConstraints] = {};
  for (int side = 0; side < 2; ++side) {
    ws_->candidate_mission = ws_->mission;
    ws_->candidate_mission.launch.azimuth_rad += (side == 0 ? 1.0 : -1.0) * kAzimuthStepRad;
    ws_->candidate_prepared = ws_->prepared;
    prepare_launch_geometry(ws_->candidate_mission, &ws_->candidate_prepared);
    Status status =
        fly_trajectory(ws_->candidate_mission, ws_->candidate_prepared, ws_->program, &ws_->candidate);
    if (ok(status)) {
      status = evaluate_constraints(problem_, ws_->candidate_mission, ws_->candidate, achieved[side]);
    }
    if (!ok(status)) return status;
  }
  for (int i = 0; i < problem_.count; ++i) {
    launch_columns_.azimuth(i) =
        -constraint_deviation(problem_.codes[i], achieved[1][i], achieved[0][i]) / (2.0 * kAzimuthStepRad);
  }
  return Status::kOk;
}

Status Iteration::backward(int first, Steering* steering) {
  ConstraintTerminal terminals[kMaxConstraints];
  Status status = constraint_terminals(problem_, ws_->mission, ws_->nominal, terminals);
  if (!ok(status)) return status;
  status = run_backward(ws_->mission, ws_->prepared, ws_->nominal, problem_.count, terminals, &ws_->backward);
  if (!ok(status)) return status;
  ++result_->backward_runs;
  status = launch_sensitivities();
  if (!ok(status)) return status;
  // The payoff partials come from the optimization form of the matrix (eq. 9-22). Both forms hold
  // the same constraints: their pivots are taken before the payoff's.
  const double dp2 = typical_control_measure();
  Steering optimization;
  status = build_steering(problem_, ws_->backward, launch_columns_, roles_.free,
                          ws_->mission.constants.g0_ft_s2, 0, dp2, &optimization);
  if (ok(status)) payoff_partials(problem_, optimization.matrix, partials_);
  if (first == 0) {
    *steering = optimization;
  } else {
    bool deferred[kMaxConstraints] = {};
    for (int i = 1; i < problem_.count; ++i) {
      deferred[i] = deferred_in_guidance(problem_, i, nominal_achieved_) ||
                    (problem_.hyperbolic_stand_in && is_asymptote_direction(problem_.codes[i].kind));
    }
    const Status guidance = build_steering(problem_, ws_->backward, launch_columns_, roles_.free,
                                           ws_->mission.constants.g0_ft_s2, first, dp2, steering, deferred);
    if (ok(status)) status = guidance;
  }
  for (int i = 0; i < kMaxConstraints; ++i) {
    result_->constraint_held[i] = steering->held[i];
    result_->constraint_deferred[i] = steering->deferred[i];
    result_->steerability_deadbands[i] = steering->steerability_deadbands[i];
  }
  return status;
}

// Eqs. 9-3, 9-4 (the open-loop law, K evaluated at launch with dx = 0): the change of every control
// that yields the requested constraint changes d psi with the least control measure.
Status Iteration::fly_candidate(const Steering& steering, const ConstraintVector& dpsi,
                                double step_fraction) {
  const ConstraintVector nu = step_fraction * steering.cholesky.solve(steered_part(steering, dpsi));
  const BackwardRun& b = ws_->backward;
  ws_->candidate_program = ws_->program;
  for (int k = 0; k < b.point_count; ++k) {
    const double w = b.quadrature_weight_s[k];
    if (!(w > 0.0) || !roles_.free[k]) continue;
    ws_->candidate_program.theta_rad[k] += scaled(problem_, b.theta_gradient[k], steering).dot(nu) / w;
  }
  shape_program(ws_->mission, ws_->nominal, roles_, &ws_->candidate_program);
  ws_->candidate_mission = ws_->mission;
  Mission& m = ws_->candidate_mission;
  bool timeline_changed = false;
  bool launch_changed = false;
  for (int p = 0; p < problem_.adjustable_count; ++p) {
    if (!problem_.adjustable_active[p]) continue;
    const double change =
        scaled(problem_, parameter_column(problem_, b, launch_columns_, p), steering).dot(nu) /
        problem_.adjustable_weight[p];
    const AdjustableParameter parameter = problem_.adjustable[p];
    switch (parameter) {
      case AdjustableParameter::kStage4Theta: m.misc.stage4_theta_rad += change; break;
      case AdjustableParameter::kStage4Chi: m.misc.stage4_chi_rad += change; break;
      case AdjustableParameter::kStage5Theta: m.misc.stage5_theta_rad += change; break;
      case AdjustableParameter::kStage5Chi: m.misc.stage5_chi_rad += change; break;
      case AdjustableParameter::kLaunchAzimuth:
        m.launch.azimuth_rad += change;
        launch_changed = true;
        break;
      case AdjustableParameter::kLaunchTime: m.launch.launch_space_age_date_days += change / 86400.0; break;
      default: {
        // Coast lengths: at most DA2(16) per iteration, never below DA2(17) (Sec. 9).
        StageData& coast = m.vehicle.stages[stage_index(adjusted_coast_stage_code(parameter))];
        const double limit = m.misc.coast_change_limit_s;
        const double bounded = (limit > 0.0) ? std::fmax(-limit, std::fmin(limit, change)) : change;
        const double minimum = std::fmax(m.misc.minimum_coast_s, 1e-3 * coast.integration_steps);
        coast.duration_s = std::fmax(minimum, coast.duration_s + bounded);
        timeline_changed = true;
        break;
      }
    }
  }
  if (problem_.payload_is_control) {
    const double g0 = m.constants.g0_ft_s2;
    const double mass_change_slug =
        problem_.payload_weight * scaled(problem_, payload_mass_column(b, g0), steering).dot(nu);
    m.vehicle.payload_lb += g0 * mass_change_slug;
    if (m.vehicle.payload_lb < 0.0) m.vehicle.payload_lb = 0.0;
  }
  ws_->candidate_prepared = ws_->prepared;
  ++result_->forward_runs;  // counted before anything can fail, so a failed run has its own number
  if (timeline_changed) {
    const Status status = rebuild_timeline(m, &ws_->candidate_prepared);
    if (!ok(status)) return status;
  }
  if (launch_changed) prepare_launch_geometry(m, &ws_->candidate_prepared);
  const double mass_change_slug =
      (m.vehicle.payload_lb - ws_->mission.vehicle.payload_lb) / m.constants.g0_ft_s2;
  ClosedLoopSteering closed_loop(problem_, b, roles_, ws_->mission, ws_->nominal, ws_->program, steering,
                                 step_fraction * dpsi, mass_change_slug, typical_control_measure());
  FlightInputs inputs;
  inputs.feedback = &closed_loop;
  inputs.live_program = &ws_->candidate_program;
  Status status = fly_trajectory(m, ws_->candidate_prepared, inputs, &ws_->candidate);
  if (!ok(status)) return status;
  return evaluate_constraints(problem_, m, ws_->candidate, candidate_achieved_);
}

Status Iteration::accept_candidate() {
  ws_->mission = ws_->candidate_mission;
  ws_->prepared = ws_->candidate_prepared;
  ws_->program = ws_->candidate_program;
  ws_->nominal = ws_->candidate;
  for (int i = 0; i < problem_.count; ++i) nominal_achieved_[i] = candidate_achieved_[i];
  classify_points(ws_->mission, ws_->nominal, &roles_);
  // Addendum H: a nominal that has left the stand-in's range is valued by the true asymptote from
  // here on (one way: a later nominal never returns to the stand-in).
  if (problem_.hyperbolic_stand_in && !needs_hyperbolic_stand_in(problem_, ws_->mission, ws_->nominal)) {
    problem_.hyperbolic_stand_in = false;
    double values[kMaxConstraints] = {};
    if (ok(evaluate_constraints(problem_, ws_->mission, ws_->nominal, values))) {
      for (int i = 0; i < problem_.count; ++i) nominal_achieved_[i] = values[i];
    } else {
      problem_.hyperbolic_stand_in = true;
    }
  }
  if (!problem_.heating_active) {
    const Status status = activate_heating_if_exceeded(ws_->nominal, ws_->mission.options, &problem_);
    if (!ok(status)) return status;
    if (problem_.heating_active) {
      const int i = problem_.count - 1;
      nominal_achieved_[i] = ws_->nominal.heat_integral_btu_ft2;
    }
  }
  // The q-bar x alpha limit joins at the first nominal that meets every other deadband and exceeds
  // it: the crude programs guidance starts from have loads that mean nothing (the reference deck's
  // initial program flies 10,100 lb deg/ft^2 at the end of coast 6), and asking guidance to remove
  // an excess of thousands of deadbands at once sends the step below the surface.
  if (!problem_.qbar_alpha_active && within_deadbands(problem_, nominal_achieved_)) {
    const Status status = activate_qbar_alpha_if_exceeded(ws_->mission, ws_->nominal, &problem_);
    if (!ok(status)) return status;
    if (problem_.qbar_alpha_active) {
      const int i = problem_.count - 1;
      nominal_achieved_[i] = qbar_alpha_excess_s(ws_->mission, ws_->nominal);
      path_constraint_joined_ = true;
    }
  }
  return Status::kOk;
}

// Guidance, as run() describes it. A failed backward run is returned; a step that never flew ends
// guidance with guidance_stuck_ set.
Status Iteration::guidance_phase(int budget, Steering* steering_out) {
  Steering& steering = *steering_out;
  while (!guidance_stuck_ && !within_deadbands(problem_, nominal_achieved_) &&
         result_->forward_runs < budget - 1) {
    Status status = backward(1, &steering);
    if (!ok(status)) return status;
    const double before = error_norm(problem_, nominal_achieved_, steering.deferred);
    double fraction = 1.0;
    // The loop counts attempts (an int); the halved fraction rides along. NOLINTNEXTLINE(cert-flp30-c)
    for (int attempt = 0;; ++attempt, fraction *= 0.5) {
      ++result_->guidance_runs;
      status = fly_candidate(steering, corrections(nominal_achieved_), fraction);
      const bool flown = ok(status);
      if (!flown) ++result_->crashed_runs;
      const bool better = flown && error_norm(problem_, candidate_achieved_, steering.deferred) < before;
      record(RunKind::kGuidance, status, better && within_deadbands(problem_, candidate_achieved_), 0.0);
      if (better || result_->forward_runs >= budget - 1) break;
      if (flown ? attempt >= kGuidanceStepHalvings : attempt >= kCrashRecoveryHalvings) break;
    }
    if (ok(status)) {
      status = accept_candidate();
      if (!ok(status)) return status;
    } else {
      guidance_stuck_ = true;
    }
  }
  return Status::kOk;
}

// Optimization: ask for payoff improvement, judged by the corrected payoff; halve on failure. The
// first attempt (again after a path constraint joined) is sized by the DA13 rules.
Status Iteration::optimization_phase(int budget, Steering* steering_out) {
  Steering& steering = *steering_out;
  while (within_deadbands(problem_, nominal_achieved_) && result_->forward_runs < budget - 1) {
    Status status = backward(0, &steering);
    if (!ok(status)) return status;
    const double best_corrected = corrected_payoff(nominal_achieved_);
    const ConstraintVector dphi = corrections(nominal_achieved_);
    if (first_attempt_) {
      if (!initial_payoff_improvement(problem_, steering, steered_part(steering, dphi),
                                      typical_control_measure(), &attempt_size_)) {
        attempt_size_ = ws_->mission.convergence.initial_payoff_improvement;
        result_->initial_improvement_from_da13_1 = true;
      }
      result_->initial_payoff_improvement = attempt_size_;
      first_attempt_ = false;
    }
    bool improved = false;
    while (attempt_size_ >= ws_->mission.convergence.stop_improvement && result_->forward_runs < budget - 1) {
      ConstraintVector dpsi = dphi;
      dpsi(0) = attempt_size_;
      status = fly_candidate(steering, dpsi, 1.0);
      ++result_->optimization_runs;
      if (!ok(status)) ++result_->crashed_runs;  // recovered like any failure: half the attempt
      improved = ok(status) && within_deadbands(problem_, candidate_achieved_) &&
                 corrected_payoff(candidate_achieved_) > best_corrected;
      record(RunKind::kOptimization, status, improved, attempt_size_);
      if (improved) break;
      attempt_size_ *= 0.5;
    }
    if (!improved) break;
    ++result_->successful_optimization_runs;
    const bool joined_before = path_constraint_joined_;
    status = accept_candidate();
    if (!ok(status)) return status;
    // A path constraint that joined at this nominal ends the phase: the next sizes its first attempt
    // anew (a join earlier, in guidance, leaves the halved attempt as it is).
    if (path_constraint_joined_ && !joined_before) first_attempt_ = true;
  }
  return Status::kOk;
}

Status Iteration::run(const Mission& input) {
  ws_->mission = input;
  Status status = prepare_case(ws_->mission, &ws_->prepared);
  if (!ok(status)) return status;
  status = fly_nominal_from_table();
  if (!ok(status)) return status;
  const int budget = ws_->mission.convergence.max_forward_trajectories;

  // Guidance: every forward guidance run becomes the nominal (Sec. 22); a step that makes the
  // errors worse is retried at half size first, and a step whose run failed (below the surface, a
  // non-finite state) is retried from the same nominal at half size until it flies or
  // kCrashRecoveryHalvings are spent (our safeguards, docs/theory/optimizer.md "Failed runs"). A
  // failed run never becomes the nominal; if no step flies, guidance ends there and the case
  // reports kGuidanceDidNotConverge with the last good nominal.
  Steering steering;
  // Guidance then optimization; once more from guidance when the q-bar x alpha constraint joined
  // during the optimization and the nominal is outside its deadband (never on decks without it).
  bool guidance_converged = false;
  for (;;) {
    path_constraint_joined_ = false;
    status = guidance_phase(budget, &steering);
    if (!ok(status)) return status;
    guidance_converged = within_deadbands(problem_, nominal_achieved_);
    status = optimization_phase(budget, &steering);
    if (!ok(status)) return status;
    if (!(path_constraint_joined_ && guidance_converged && !guidance_stuck_ &&
          !within_deadbands(problem_, nominal_achieved_) && result_->forward_runs < budget - 1)) {
      break;
    }
  }
  // Once guidance has succeeded every nominal is feasible, so the phase ends by one of Sec. 22's
  // two rules; which one is told by the budget.
  if (result_->optimization_runs > 0) {
    result_->optimization_stop = result_->forward_runs >= budget - 1
                                     ? OptimizationStop::kForwardRunBudget
                                     : OptimizationStop::kImprovementBelowMinimum;
  }

  // Final backward and forward guidance run. A feasible nominal is replaced only by a feasible
  // final run (it is the reported optimum); an infeasible one by any run that reduces the errors.
  status = backward(1, &steering);
  if (!ok(status)) return status;
  status = fly_candidate(steering, corrections(nominal_achieved_), 1.0);
  if (!ok(status)) ++result_->crashed_runs;  // the feasible nominal stays the reported trajectory
  result_->final_guidance_met = ok(status) && within_deadbands(problem_, candidate_achieved_);
  const bool nominal_feasible = within_deadbands(problem_, nominal_achieved_);
  const bool final_accepted = nominal_feasible ? result_->final_guidance_met
                                               : ok(status) && error_norm(problem_, candidate_achieved_) <=
                                                                   error_norm(problem_, nominal_achieved_);
  record(RunKind::kFinalGuidance, status, result_->final_guidance_met, 0.0);
  if (final_accepted) {
    status = accept_candidate();
    if (!ok(status)) return status;
  }

  result_->converged = guidance_converged && result_->optimization_runs > 0 &&
                       result_->optimization_stop == OptimizationStop::kImprovementBelowMinimum &&
                       result_->final_guidance_met;
  result_->constraint_count = problem_.count;
  for (int i = 0; i < problem_.count; ++i) {
    result_->codes[i] = problem_.codes[i].code;
    result_->desired[i] = problem_.desired[i];
    result_->achieved[i] = nominal_achieved_[i];
    result_->tolerance[i] = (i == 0) ? 0.0 : problem_.deadband[i];
    result_->inequality[i] = problem_.inequality[i];
    result_->payoff_partials[i] = partials_[i];
  }
  result_->payoff = nominal_achieved_[0];
  result_->corrected_payoff = corrected_payoff(nominal_achieved_);
  result_->payload_lb = ws_->mission.vehicle.payload_lb;
  result_->adjustable_count = problem_.adjustable_count;
  for (int p = 0; p < problem_.adjustable_count; ++p) {
    const AdjustableParameter parameter = problem_.adjustable[p];
    result_->adjustable_codes[p] = adjustable_parameter_code(parameter);
    const MiscellaneousData& misc = ws_->mission.misc;
    const LaunchConditions& launch = ws_->mission.launch;
    double value = 0.0;
    switch (parameter) {
      case AdjustableParameter::kStage4Theta: value = misc.stage4_theta_rad; break;
      case AdjustableParameter::kStage4Chi: value = misc.stage4_chi_rad; break;
      case AdjustableParameter::kStage5Theta: value = misc.stage5_theta_rad; break;
      case AdjustableParameter::kStage5Chi: value = misc.stage5_chi_rad; break;
      case AdjustableParameter::kLaunchAzimuth: value = launch.azimuth_rad; break;
      case AdjustableParameter::kLaunchTime: value = launch.launch_space_age_date_days; break;
      default:
        value = ws_->mission.vehicle.stages[stage_index(adjusted_coast_stage_code(parameter))].duration_s;
        break;
    }
    result_->adjustable_values[p] = value;
  }
  if (!guidance_converged) return Status::kGuidanceDidNotConverge;
  if (result_->optimization_runs == 0) return Status::kOptimizationNotStarted;
  if (result_->optimization_stop == OptimizationStop::kForwardRunBudget) {
    return Status::kOptimizationBudgetExhausted;
  }
  if (!result_->final_guidance_met) return Status::kFinalGuidanceFailed;
  return Status::kOk;
}

}  // namespace

Status optimize_trajectory(const Mission& mission, OptimizerWorkspace* workspace, OptimizerResult* result) {
  result->forward_runs = 0;
  result->backward_runs = 0;
  result->iteration_count = 0;
  result->iterations_dropped = 0;
  result->converged = false;
  result->optimization_stop = OptimizationStop::kNotReached;
  result->guidance_runs = 0;
  result->optimization_runs = 0;
  result->successful_optimization_runs = 0;
  result->final_guidance_met = false;
  result->initial_payoff_improvement = 0.0;
  result->initial_improvement_from_da13_1 = false;
  result->crashed_runs = 0;
  for (int i = 0; i < kMaxConstraints; ++i) {
    result->constraint_held[i] = false;
    result->steerability_deadbands[i] = 0.0;
    result->held_runs[i] = 0;
    result->constraint_deferred[i] = false;
    result->deferred_runs[i] = 0;
  }
  Problem problem;
  Status status = make_problem(mission, &problem);
  if (ok(status)) {
    Iteration iteration(problem, workspace, result);
    status = iteration.run(mission);
  }
  result->status = status;
  return status;
}

}  // namespace tolip
