// Pitch-program linearization (manual Sec. 6, 10; docs/theory/linearization.md).
#include "tolip/optimizer/linearization.hpp"

#include <cmath>
#include <utility>

#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/constraint_set.hpp"
#include "tolip/optimizer/qbar_alpha.hpp"

namespace tolip {
namespace {

constexpr int kMaxProgramsPerBackwardRun = 5;  // Sec. 10
constexpr double kRepairEta = 0.01;            // eta next to a fixed break (Sec. 10)
// A rate counts as positive above this (rad/s): a level segment is not a second positive rate.
constexpr double kPositiveRateRadS = 1e-7;
// Adjacent rates closer than this (rad/s) are one merged segment: the break is not a rate change.
constexpr double kMergedRateRadS = 1e-9;
// Relative slack of a rate against its limit when deciding to repair it, and when accepting a
// program. The repair is the stricter of the two on purpose: a repair sets a rate to its limit
// exactly, and the solved program then realizes it only to the round-off of the fit's solve;
// accepting 1e-6 absorbs that, while repairing above 1e-9 leaves nothing the acceptance
// would reject. With one value for both a repaired rate could fail acceptance on round-off alone.
constexpr double kRepairRateSlack = 1e-9;
constexpr double kAcceptedRateSlack = 1e-6;
// Two times (s) closer than this are the same instant: the trajectory's points at a break, a
// staging or the end of lift-off are copies of the same double, so any small value works; 1 us is
// far below the integration step (0.1 s at the least) and far above the round-off of a time sum.
constexpr double kSameInstantS = 1e-6;
// A time this close (s) outside the program's first or last break still samples the program: the
// break times are sums of durations and can differ from the point times by round-off.
constexpr double kBreakTimeRoundOffS = 1e-9;
using KktMatrix = Eigen::Matrix<double, kLinearizationKktSize, kLinearizationKktSize>;
using KktVector = Eigen::Matrix<double, kLinearizationKktSize, 1>;
constexpr int kKktSize = kLinearizationKktSize;

// ---- the constraints imposed during linearization --------------------------------------------

// The constraint set of tolip/optimizer/constraint_set.hpp without the payoff, the inclination and
// the node (docs/theory/linearization.md), with the linearization deadbands (DA14(14..25)).
struct LinearConstraints : ConstraintSet {
  // Payload payoff: the payload is the payoff, which linearization does not impose, so it is free
  // to absorb what the straight segments lose (docs/theory/linearization.md).
  bool payload_free = false;
  // The entry of the q-bar x alpha excess (code 200) when the mission has a limit, else -1: the
  // linearization keeps the limit the optimizer kept (docs/theory/linearization.md).
  int qbar_alpha = -1;
};

Status select_constraints(const Mission& mission, LinearConstraints* out) {
  const ConstraintList& list = mission.constraints;
  out->count = 0;
  ConstraintCode payoff;
  const Status payoff_status = decode_constraint_code(list.codes[0], &payoff);
  if (!ok(payoff_status)) return payoff_status;
  out->payload_free = payoff.kind == ConstraintQuantity::kPayload;
  for (int i = 1; i < list.count; ++i) {
    ConstraintCode code;
    Status status = decode_constraint_code(list.codes[i], &code);
    if (!ok(status)) return status;
    if (code.kind == ConstraintQuantity::kInclination || code.kind == ConstraintQuantity::kNodeLongitude) {
      continue;
    }
    status =
        append_constraint(code, list.desired[i], list.deadband_linearization[i - 1], mission.options, out);
    if (!ok(status)) return status;
  }
  out->qbar_alpha = -1;
  if (mission.options.qbar_alpha_constraint()) {
    // Listed from the start (not when first exceeded, as in the optimizer): the linearization
    // starts from an optimum that already rides the limit, and its segments move the load.
    ConstraintCode code;
    Status status = decode_constraint_code(kQbarAlphaConstraintCode, &code);
    if (!ok(status)) return status;
    out->qbar_alpha = out->count;
    status = append_constraint(code, 0.0, kQbarAlphaExcessDeadbandS, mission.options, out);
    if (!ok(status)) return status;
  }
  return Status::kOk;
}

// ---- break times and the program at the points -------------------------------------------------

double stage_start_s(const PreparedCase& prepared, int code) {
  for (int k = 0; k < prepared.stage_count; ++k) {
    if (prepared.timeline[k].code == code) return prepared.timeline[k].start_s;
  }
  return -1.0;
}

// Data block 18's boundaries (stage n, t from its ignition) moved to the nearest integration point
// of stage n.
Status break_times(const Mission& mission, const PreparedCase& prepared, const Trajectory& t,
                   LinearProgram* p) {
  const LinearizationData& data = mission.linearization;
  if (data.segment_count < 1 || data.segment_count > kMaxLinearSegments) {
    return Status::kTooManyLinearSegments;
  }
  p->segment_count = data.segment_count;
  for (int b = 0; b <= data.segment_count; ++b) {
    const int code = data.boundaries[b].stage;
    const double start = stage_start_s(prepared, code);
    if (start < 0.0) return Status::kCodedTimeStageInvalid;  // stage n is not in the timeline
    const double wanted = start + data.boundaries[b].time_from_ignition_s;
    double best = wanted;
    double best_error = 1e300;
    for (int k = 1; k < t.point_count; ++k) {
      if (t.points[k].stage_code != code) continue;
      const double error = std::fabs(t.points[k].time_s - wanted);
      if (error < best_error) {
        best_error = error;
        best = t.points[k].time_s;
      }
    }
    p->break_time_s[b] = best;
    if (b > 0 && !(p->break_time_s[b] > p->break_time_s[b - 1])) return Status::kTableNotMonotonic;
  }
  for (int s = 0; s < p->segment_count; ++s) {
    p->eta[s] = data.segment_weights[s] > 0.0 ? data.segment_weights[s] : 1.0;
  }
  return Status::kOk;
}

// Segment holding time t and the weight of its end break (hat functions); -1 outside the program.
int segment_of(const LinearProgram& p, double t, double* fraction) {
  if (t < p.break_time_s[0] - kBreakTimeRoundOffS ||
      t > p.break_time_s[p.segment_count] + kBreakTimeRoundOffS) {
    return -1;
  }
  int s = 0;
  while (s + 1 < p.segment_count && t >= p.break_time_s[s + 1]) ++s;
  *fraction = (t - p.break_time_s[s]) / (p.break_time_s[s + 1] - p.break_time_s[s]);
  return s;
}

// Samples the linear program at every point (before the first break the lift-off's 90 deg, after
// the last break the last value, which only coasts without aerodynamics and spun stages see).
void sample(const LinearProgram& p, const Trajectory& t, const ControlProgram& optimum, ControlProgram* out) {
  out->point_count = t.point_count;
  for (int k = 0; k < t.point_count; ++k) {
    double f = 0.0;
    const int s = segment_of(p, t.points[k].time_s, &f);
    if (s >= 0) {
      out->theta_rad[k] = p.theta_rad[s] + f * (p.theta_rad[s + 1] - p.theta_rad[s]);
    } else {
      out->theta_rad[k] =
          (t.points[k].time_s < p.break_time_s[0]) ? optimum.theta_rad[k] : p.theta_rad[p.segment_count];
    }
  }
}

void update_rates_and_stages(const Trajectory& t, LinearProgram* p) {
  for (int s = 0; s < p->segment_count; ++s) {
    p->rate_rad_s[s] =
        (p->theta_rad[s + 1] - p->theta_rad[s]) / (p->break_time_s[s + 1] - p->break_time_s[s]);
    // The stage flown at the segment's start (at a staging instant, the stage that starts).
    for (int k = t.point_count - 1; k >= 0; --k) {
      if (t.points[k].time_s <= p->break_time_s[s] + kBreakTimeRoundOffS) {
        p->stage_code[s] = t.points[k].stage_code;
        p->start_stage_time_s[s] = t.points[k].stage_time_s + (p->break_time_s[s] - t.points[k].time_s);
        break;
      }
    }
  }
}

// Gaussian elimination with partial pivoting on the fixed-size KKT system. (Eigen's LU solvers
// reach dynamic-size triangular blocks, which reference the heap; this loop does not.)
bool solve_in_place(KktMatrix* a, KktVector* b, KktVector* x) {
  KktMatrix& m = *a;
  // cppcheck-suppress constVariable ; written below through Eigen's operator() (r(row) -= ...)
  KktVector& r = *b;
  for (int col = 0; col < kKktSize; ++col) {
    int pivot = col;
    for (int row = col + 1; row < kKktSize; ++row) {
      if (std::fabs(m(row, col)) > std::fabs(m(pivot, col))) pivot = row;
    }
    if (!(std::fabs(m(pivot, col)) > 1e-300)) return false;
    if (pivot != col) {
      m.row(pivot).swap(m.row(col));
      std::swap(r(pivot), r(col));
    }
    for (int row = col + 1; row < kKktSize; ++row) {
      const double factor = m(row, col) / m(col, col);
      if (factor == 0.0) continue;
      for (int c = col; c < kKktSize; ++c) m(row, c) -= factor * m(col, c);
      r(row) -= factor * r(col);
    }
  }
  for (int row = kKktSize - 1; row >= 0; --row) {
    double sum = r(row);
    for (int c = row + 1; c < kKktSize; ++c) sum -= m(row, c) * (*x)(c);
    (*x)(row) = sum / m(row, row);
  }
  return true;
}

// ---- eq. 6-22: the constrained least-squares fit ------------------------------------------------

// Relative residual an equality row of the solved system (a fixed break value, a rate repair, a
// linearized constraint) may keep: 1e-8 of (1 + |right-hand side|) lies well above the round-off
// of the double-precision elimination and well below a repair or constraint that was not met, so
// it tells a nearly singular system (more equalities than the program can meet) from a solved one.
constexpr double kEqualityResidualTolerance = 1e-8;

// The least-squares rows of the fit (eqs. 6-6..6-10, hat functions over the segments) and the
// linearized constraint rows' sums over the points (eq. 6-2).
void assemble_fit(const LinearConstraints& c, const BackwardRun& backward, const Trajectory& nominal,
                  const ControlProgram& nominal_program, const ControlProgram& optimum,
                  const LinearProgram& p, int n, KktMatrix* kkt, KktVector* rhs) {
  for (int k = 0; k < nominal.point_count; ++k) {
    double f = 0.0;
    const int s = segment_of(p, nominal.points[k].time_s, &f);
    const double w = backward.quadrature_weight_s[k];
    if (s < 0 || !(w > 0.0)) continue;
    // Hat-function row: theta_k = (1 - f) theta_s + f theta_(s+1).
    const double h0 = 1.0 - f;
    const double h1 = f;
    const double weight = w * p.eta[s];
    (*kkt)(s, s) += weight * h0 * h0;
    (*kkt)(s, s + 1) += weight * h0 * h1;
    (*kkt)(s + 1, s) += weight * h0 * h1;
    (*kkt)(s + 1, s + 1) += weight * h1 * h1;
    (*rhs)(s) += weight * h0 * optimum.theta_rad[k];
    (*rhs)(s + 1) += weight * h1 * optimum.theta_rad[k];
    for (int j = 0; j < c.count; ++j) {
      const double g = backward.theta_gradient[k](j) / c.deadband[j];
      (*kkt)(n + j, s) += g * h0;
      (*kkt)(n + j, s + 1) += g * h1;
      (*rhs)(n + j) += g * nominal_program.theta_rad[k];
    }
  }
}

// The constraint rows' corrections and payload column, mirrored into the multiplier columns.
//
// The q-bar x alpha excess J (code 200) is listed to be evaluated and reported, not fitted: its
// row is held out of the fit (multiplier zero) and the peak rows below keep the limit instead
// (docs/theory/linearization.md: J vanishes like the square of the excess, so a linear step on it
// is poor, and it has no gradient at all once the program is under the limit).
void add_constraint_rows(const LinearConstraints& c, const BackwardRun& backward, const double achieved[],
                         int breaks, int n, KktMatrix* kkt, KktVector* rhs) {
  for (int j = 0; j < c.count; ++j) {
    if (j == c.qbar_alpha) {
      for (int col = 0; col < kKktSize; ++col) (*kkt)(n + j, col) = 0.0;
      (*kkt)(n + j, n + j) = 1.0;
      (*rhs)(n + j) = 0.0;
      for (int b = 0; b < n; ++b) (*kkt)(b, n + j) = 0.0;
      continue;
    }
    (*rhs)(n + j) += constraint_correction(c, j, achieved[j]) / c.deadband[j];
    if (c.payload_free) (*kkt)(n + j, breaks) = backward.payload(j) / c.deadband[j];
    for (int b = 0; b < n; ++b) (*kkt)(b, n + j) = (*kkt)(n + j, b);
  }
}

// Rate repairs: one more multiplier row each (a merge of two segments, or a segment at its rate).
void add_rate_repair_rows(const LinearProgram& p, int n, int first_row, KktMatrix* kkt, KktVector* rhs) {
  for (int r = 0; r < p.rate_repair_count; ++r) {
    const int row = first_row + r;
    const int seg = p.rate_segment[r];
    if (p.rate_merge[r]) {
      const double d0 = p.break_time_s[seg + 1] - p.break_time_s[seg];
      const double d1 = p.break_time_s[seg + 2] - p.break_time_s[seg + 1];
      const double f = d0 / (d0 + d1);
      (*kkt)(row, seg) = -(1.0 - f);
      (*kkt)(row, seg + 1) = 1.0;
      (*kkt)(row, seg + 2) = -f;
      (*rhs)(row) = 0.0;
    } else {
      (*kkt)(row, seg) = -1.0;
      (*kkt)(row, seg + 1) = 1.0;
      (*rhs)(row) = p.rate_value_rad_s[r] * (p.break_time_s[seg + 1] - p.break_time_s[seg]);
    }
    for (int b = 0; b < n; ++b) (*kkt)(b, row) = (*kkt)(row, b);
  }
}

// Whether the solution meets every equality row (fixed values, rate repairs, constraints): a nearly
// singular system returns garbage rather than failing.
bool equalities_met(const KktMatrix& kkt, const KktVector& rhs, const KktVector& x, const LinearProgram& p,
                    int breaks, int n, int rows) {
  for (int i = 0; i < rows; ++i) {
    const bool equality = i >= n || (i < breaks && p.fixed[i]);
    if (!equality) continue;
    double residual = rhs(i);
    for (int col = 0; col < rows; ++col) residual -= kkt(i, col) * x(col);
    if (std::fabs(residual) > kEqualityResidualTolerance * (1.0 + std::fabs(rhs(i)))) return false;
  }
  return true;
}

// ---- the q-bar x alpha limit in the fit: peak rows (docs/theory/linearization.md) -------------

// A local peak of |q-bar alpha| on the nominal above this fraction of the limit gets a row; the row
// asks for the peak at kPeakTargetFraction of the limit (the half per cent absorbs the linearization
// error of the next run, inside the optimizer's criterion J <= 1e-4 s). The rows are scaled by 1 %
// of the limit, the order of the terminal rows scaled by their deadbands.
constexpr double kPeakJoinFraction = 0.95;
constexpr double kPeakTargetFraction = 0.995;
constexpr double kPeakRowScaleFraction = 0.01;

struct PeakRows {
  int count = 0;
  int point[kMaxQbarAlphaPeakRows] = {};
  double value[kMaxQbarAlphaPeakRows] = {};   // signed q-bar alpha on the nominal, lbf rad/ft^2
  double direct[kMaxQbarAlphaPeakRows] = {};  // d(q-bar alpha)/d(theta at the point itself)
};

// |q-bar alpha| at point k where the limit covers it and alpha is a control there, else -1.
double limited_magnitude(const Mission& mission, const Trajectory& t, int k) {
  if (k < 0 || k >= t.point_count) return -1.0;
  const TrajectoryPoint& p = t.points[k];
  if (!qbar_alpha_limited(mission, p) || p.alpha_zero || !(trapezoidal_weight_s(t, k) > 0.0)) return -1.0;
  return std::fabs(qbar_alpha_lbf_rad_ft2(p));
}

// The local peaks of |q-bar alpha| over the limited points of the nominal above kPeakJoinFraction
// of the limit, the largest first, at most `room`.
void select_peaks(const Mission& mission, const Trajectory& t, int room, PeakRows* rows) {
  rows->count = 0;
  const double limit = mission.options.qbar_alpha_limit_lbf_rad_ft2;
  if (!(limit > 0.0)) return;
  if (room > kMaxQbarAlphaPeakRows) room = kMaxQbarAlphaPeakRows;
  for (int k = 0; k < t.point_count; ++k) {
    const double v = limited_magnitude(mission, t, k);
    if (v < kPeakJoinFraction * limit) continue;
    // A plateau counts once: strictly above the point before, not below the point after.
    if (!(v > limited_magnitude(mission, t, k - 1)) || v < limited_magnitude(mission, t, k + 1)) continue;
    int at = rows->count;
    while (at > 0 && std::fabs(rows->value[at - 1]) < v) --at;
    if (at >= room) continue;
    const int last = rows->count < room ? rows->count : room - 1;
    for (int i = last; i > at; --i) {
      rows->point[i] = rows->point[i - 1];
      rows->value[i] = rows->value[i - 1];
    }
    rows->point[at] = k;
    rows->value[at] = qbar_alpha_lbf_rad_ft2(t.points[k]);
    if (rows->count < room) ++rows->count;
  }
}

// The peak rows of eq. 6-22, after the rate repairs: the linearized change of q-bar alpha at each
// peak (its adjoint, column first_column + i of the backward run, plus the point's own attitude)
// brings it to the target.
void add_peak_rows(const PeakRows& q, int used, double limit, const BackwardRun& backward,
                   const Trajectory& nominal, const ControlProgram& nominal_program, const LinearProgram& p,
                   bool payload_free, int breaks, int n, int first_row, int first_column, KktMatrix* kkt,
                   KktVector* rhs) {
  const double scale = kPeakRowScaleFraction * limit;
  for (int i = 0; i < used; ++i) {
    const int row = first_row + i;
    const int col = first_column + i;
    double gradient[kMaxBreakPoints] = {};
    qbar_alpha_peak_gradients(backward, nominal, p, col, q.point[i], q.direct[i], gradient);
    for (int b = 0; b < breaks; ++b) (*kkt)(row, b) = gradient[b] / scale;
    // The same linearized change about the nominal's own program (at the first run the optimum,
    // which is no combination of the hat functions).
    for (int k = 0; k < nominal.point_count; ++k) {
      double f = 0.0;
      if (segment_of(p, nominal.points[k].time_s, &f) < 0 || !(backward.quadrature_weight_s[k] > 0.0)) {
        continue;
      }
      const double g = backward.theta_gradient[k](col) + (k == q.point[i] ? q.direct[i] : 0.0);
      (*rhs)(row) += g / scale * nominal_program.theta_rad[k];
    }
    const double target = (q.value[i] < 0.0 ? -1.0 : 1.0) * kPeakTargetFraction * limit;
    (*rhs)(row) += (target - q.value[i]) / scale;
    if (payload_free) (*kkt)(row, breaks) = backward.payload(col) / scale;
    for (int b = 0; b < n; ++b) (*kkt)(b, row) = (*kkt)(row, b);
  }
}

Status solve_program(const LinearConstraints& c, const BackwardRun& backward, const Trajectory& nominal,
                     const ControlProgram& nominal_program, const ControlProgram& optimum,
                     const double achieved[], const PeakRows& peaks, int peaks_used, double limit,
                     LinearizationSystem* system, LinearProgram* p, double* payload_change_lb) {
  // Unknowns: the break values, then the payload change when it is free.
  const int breaks = p->segment_count + 1;
  const int n = breaks + (c.payload_free ? 1 : 0);
  KktMatrix& kkt = system->assembled;
  KktVector& rhs = system->rhs;
  kkt.setZero();
  rhs.setZero();
  assemble_fit(c, backward, nominal, nominal_program, optimum, *p, n, &kkt, &rhs);
  add_constraint_rows(c, backward, achieved, breaks, n, &kkt, &rhs);
  add_rate_repair_rows(*p, n, n + c.count, &kkt, &rhs);
  add_peak_rows(peaks, peaks_used, limit, backward, nominal, nominal_program, *p, c.payload_free, breaks, n,
                n + c.count + p->rate_repair_count, c.count, &kkt, &rhs);
  // Fixed break values (eq. 6-16): their rows become theta_b = value.
  for (int b = 0; b < breaks; ++b) {
    if (!p->fixed[b]) continue;
    kkt.row(b).setZero();
    kkt(b, b) = 1.0;
    rhs(b) = p->theta_rad[b];
  }
  const int rows = n + c.count + p->rate_repair_count + peaks_used;
  for (int i = rows; i < kKktSize; ++i) kkt(i, i) = 1.0;
  system->eliminated = kkt;
  KktVector eliminated_rhs = rhs;
  KktVector x = KktVector::Zero();
  if (!solve_in_place(&system->eliminated, &eliminated_rhs, &x)) return Status::kSteeringMatrixSingular;
  if (!x.allFinite()) return Status::kNonFiniteState;
  if (!equalities_met(kkt, rhs, x, *p, breaks, n, rows)) return Status::kSteeringMatrixSingular;
  for (int b = 0; b < breaks; ++b) p->theta_rad[b] = x(b);
  *payload_change_lb = c.payload_free ? x(breaks) : 0.0;
  return Status::kOk;
}

// ---- rate limits and their repair (Sec. 10) ---------------------------------------------------

// Segments [first, last] joined to segment s by merges, and whether one of them has its rate fixed
// (then the whole group flies that rate).
struct MergeGroup {
  int first = 0;
  int last = 0;
  bool rate_fixed = false;
};

bool merged_right(const LinearProgram& p, int s) {
  for (int r = 0; r < p.rate_repair_count; ++r) {
    if (p.rate_merge[r] && p.rate_segment[r] == s) return true;
  }
  return false;
}

MergeGroup merge_group(const LinearProgram& p, int s) {
  MergeGroup g;
  g.first = s;
  g.last = s;
  while (g.first > 0 && merged_right(p, g.first - 1)) --g.first;
  while (g.last + 1 < p.segment_count && merged_right(p, g.last)) ++g.last;
  for (int r = 0; r < p.rate_repair_count; ++r) {
    if (!p.rate_merge[r] && p.rate_segment[r] >= g.first && p.rate_segment[r] <= g.last) g.rate_fixed = true;
  }
  return g;
}

double segment_rate(const LinearProgram& p, int s) {
  return (p.theta_rad[s + 1] - p.theta_rad[s]) / (p.break_time_s[s + 1] - p.break_time_s[s]);
}

// Adds the first repair the program needs, in the order of Sec. 10 (maximum rate, a single positive
// rate, minimum rate, minimum change of rate); returns false when it meets every limit or no repair
// is possible. A repair fixes the rate of a segment's merge group, or merges two adjacent segments
// (eliminating a break, as Sec. 10 does), and sets eta next to it to 0.01. A group whose rate is
// already fixed is not repaired again; merging into such a group makes the other side fly its rate.
// The long coast before a continuous stage 4 or 5 (coasts 8 and 9 as segments, IP(9) = 2, 3) is
// exempt from the minimum rate and the minimum change of rate: Sec. 10 tests a coast's rate against
// those two limits only after the repairs, for a message ("the coast stage 7 pitch rate is tested
// ... A message is printed"), and a coast of hundreds of seconds merged into the fixed rate of
// the stage before it would start the next stage degrees away from its optimum attitude (observed:
// 10 deg and 6.5 % of payload on the Scout with IP(9) = 2). Coasts 6 and 7 keep this project's
// repairs (docs/theory/linearization.md). Needs the segments' stage codes (update_rates_and_stages).
bool exempt_from_minimum_rates(const LinearProgram& p, int s) {
  return s >= 0 && s < p.segment_count && (p.stage_code[s] == 8 || p.stage_code[s] == 9);
}

bool repair_rate_limits(const Mission& mission, const LinearConstraints& c,
                        double coast_rate_rad_s_after_last, LinearProgram* p) {
  if (p->rate_repair_count >= kMaxRateRepairs) return false;
  // Every repair takes one degree of freedom of the fit; the constraints need one each. A repair
  // that would leave fewer than that makes the system singular: the violation stays instead, and
  // the next backward run starts from a different trajectory.
  int free = p->segment_count + 1 + (c.payload_free ? 1 : 0) - p->rate_repair_count;
  for (int b = 0; b <= p->segment_count; ++b) free -= p->fixed[b] ? 1 : 0;
  if (free - 1 < c.count) return false;
  const ControlConstraints& limits = mission.control;
  const int k = p->segment_count;
  const auto rate = [&](int s) { return segment_rate(*p, s); };
  // A segment between two fixed break values has no rate to repair.
  const auto determined = [&](int s) { return p->fixed[s] && p->fixed[s + 1]; };
  const auto impose = [&](int s, bool merge, double value) {
    const int r = p->rate_repair_count++;
    p->rate_segment[r] = s;
    p->rate_merge[r] = merge;
    p->rate_value_rad_s[r] = value;
    const MergeGroup g = merge_group(*p, s);
    if (g.first > 0) p->eta[g.first - 1] = kRepairEta;
    if (g.last + 1 < k) p->eta[g.last + 1] = kRepairEta;
    return true;
  };
  for (int s = 0; s < k; ++s) {
    if (limits.max_pitch_rate_rad_s > 0.0 &&
        std::fabs(rate(s)) > limits.max_pitch_rate_rad_s * (1.0 + kRepairRateSlack) &&
        !merge_group(*p, s).rate_fixed && !determined(s)) {
      return impose(s, false, (rate(s) < 0.0 ? -1.0 : 1.0) * limits.max_pitch_rate_rad_s);
    }
  }
  int positives = coast_rate_rad_s_after_last > kPositiveRateRadS ? 1 : 0;
  for (int s = 0; s < k; ++s) {
    if (!(rate(s) > kPositiveRateRadS) || rate_continues_previous(*p, s)) continue;
    ++positives;
    if (positives > 1 && !merge_group(*p, s).rate_fixed && !determined(s)) {
      return impose(s, false, -limits.min_pitch_rate_rad_s);
    }
  }
  for (int s = 0; s < k; ++s) {
    if (limits.min_pitch_rate_rad_s > 0.0 &&
        std::fabs(rate(s)) < limits.min_pitch_rate_rad_s * (1.0 - kRepairRateSlack) &&
        !merge_group(*p, s).rate_fixed && !determined(s) && !exempt_from_minimum_rates(*p, s)) {
      return impose(s, false, (rate(s) > 0.0 ? 1.0 : -1.0) * limits.min_pitch_rate_rad_s);
    }
  }
  for (int s = 0; s + 1 < k; ++s) {
    if (!(limits.min_pitch_rate_change_rad_s > 0.0) || rate_continues_previous(*p, s + 1) ||
        exempt_from_minimum_rates(*p, s) || exempt_from_minimum_rates(*p, s + 1) ||
        std::fabs(rate(s + 1) - rate(s)) >= limits.min_pitch_rate_change_rad_s * (1.0 - kRepairRateSlack)) {
      continue;
    }
    if (merge_group(*p, s).rate_fixed && merge_group(*p, s + 1).rate_fixed) continue;
    return impose(s, true, 0.0);
  }
  return false;
}

bool meets_rate_limits(const Mission& mission, double coast_rate_after_last, const LinearProgram& p) {
  const ControlConstraints& limits = mission.control;
  int positives = coast_rate_after_last > kPositiveRateRadS ? 1 : 0;
  for (int s = 0; s < p.segment_count; ++s) {
    const double r = segment_rate(p, s);
    if (limits.max_pitch_rate_rad_s > 0.0 &&
        std::fabs(r) > limits.max_pitch_rate_rad_s * (1.0 + kAcceptedRateSlack)) {
      return false;
    }
    if (limits.min_pitch_rate_rad_s > 0.0 &&
        std::fabs(r) < limits.min_pitch_rate_rad_s * (1.0 - kAcceptedRateSlack) &&
        !exempt_from_minimum_rates(p, s)) {
      return false;
    }
    if (r > kPositiveRateRadS && !rate_continues_previous(p, s)) ++positives;
    if (s + 1 < p.segment_count && limits.min_pitch_rate_change_rad_s > 0.0 &&
        !rate_continues_previous(p, s + 1) && !exempt_from_minimum_rates(p, s) &&
        !exempt_from_minimum_rates(p, s + 1) &&
        std::fabs(segment_rate(p, s + 1) - r) <
            limits.min_pitch_rate_change_rad_s * (1.0 - kAcceptedRateSlack)) {
      return false;
    }
  }
  return positives <= 1;
}

// Rate over the coast from the last stage that flies the pitch program into the first spun one
// (coast 8 before a spun stage 4 under IP(9) = 1, coast 9 before a spun stage 5 under IP(9) = 2):
// from the program's last value to the spun attitude. -1 (no positive rate) without such a coast.
double coast_rate_after_program(const Mission& mission, const PreparedCase& prepared,
                                const LinearProgram& p) {
  const Options& options = mission.options;
  for (int k = 0; k + 1 < prepared.stage_count; ++k) {
    const StageTimeline& line = prepared.timeline[k];
    if (!is_coast_stage(line.code) || !(line.duration_s > 0.0)) continue;
    const int next = line.code - 4;  // the powered stage after coast n + 5
    if (!options.stage_is_steered(next - 1) || !options.stage_is_spun(next)) continue;
    const double spun_theta_rad = spun_stage_attitude(options, mission.misc, next).theta_rad;
    return (spun_theta_rad - p.theta_rad[p.segment_count]) / line.duration_s;
  }
  return -1.0;
}

// The payoff of a linearized trajectory: the payload itself for the payload payoff (free during
// linearization), else the payoff quantity at its point.
Status linearized_payoff(const Mission& mission, const Trajectory& trajectory, double* payoff) {
  ConstraintCode code;
  Status status = decode_constraint_code(mission.constraints.codes[0], &code);
  if (!ok(status)) return status;
  if (code.kind == ConstraintQuantity::kPayload) {
    *payoff = mission.vehicle.payload_lb;
    return Status::kOk;
  }
  const int index = constraint_point_index(code, trajectory);
  if (index < 0) return Status::kConstraintPointNotInTrajectory;
  return constraint_value(mission.constants, mission.launch, code,
                          constraint_point_at(mission, trajectory, index), payoff);
}

// A forward linearization run: the sampled program, with body dynamics in stage 1 and the coast
// after it on 6D runs (Sec. 10, 11).
Status fly_linearized(const LinearizationWorkspace& ws, bool body_dynamics, Trajectory* out) {
  FlightInputs inputs;
  inputs.program = &ws.program;
  inputs.body_dynamics = body_dynamics;
  return fly_trajectory(ws.mission, ws.prepared, inputs, out);
}

}  // namespace

void break_value_gradients(const BackwardRun& backward, const Trajectory& nominal, const LinearProgram& p,
                           int j, double out[kMaxBreakPoints]) {
  for (int b = 0; b < kMaxBreakPoints; ++b) out[b] = 0.0;
  for (int k = 0; k < nominal.point_count; ++k) {
    double f = 0.0;
    const int s = segment_of(p, nominal.points[k].time_s, &f);
    // The points assemble_fit weighs (the same rule: inside the program, positive weight).
    if (s < 0 || !(backward.quadrature_weight_s[k] > 0.0)) continue;
    out[s] += backward.theta_gradient[k](j) * (1.0 - f);
    out[s + 1] += backward.theta_gradient[k](j) * f;
  }
}

void qbar_alpha_peak_gradients(const BackwardRun& backward, const Trajectory& nominal, const LinearProgram& p,
                               int column, int point, double direct, double out[kMaxBreakPoints]) {
  break_value_gradients(backward, nominal, p, column, out);
  double f = 0.0;
  const int s =
      (point >= 0 && point < nominal.point_count) ? segment_of(p, nominal.points[point].time_s, &f) : -1;
  if (s < 0 || !(backward.quadrature_weight_s[point] > 0.0)) return;
  out[s] += direct * (1.0 - f);
  out[s + 1] += direct * f;
}

// A break where the rate does not change joins two segments into one: it is neither a change of
// rate nor a second positive rate.
bool rate_continues_previous(const LinearProgram& p, int s) {
  return s > 0 && std::fabs(segment_rate(p, s) - segment_rate(p, s - 1)) < kMergedRateRadS;
}

// Sec. 10: "Before leaving the LINEAR routine, the coast stage 7 pitch rate is tested for minimum
// rate violation and minimum change in rate violation."
void check_coast7_rates(const Mission& mission, const LinearProgram& p, LinearizationResult* out) {
  const ControlConstraints& limits = mission.control;
  out->coast7_below_min_rate = false;
  out->coast7_below_min_rate_change = false;
  for (int s = 0; s < p.segment_count; ++s) {
    if (p.stage_code[s] != 7) continue;
    const double rate = segment_rate(p, s);
    if (limits.min_pitch_rate_rad_s > 0.0 &&
        std::fabs(rate) < limits.min_pitch_rate_rad_s * (1.0 - kAcceptedRateSlack)) {
      out->coast7_below_min_rate = true;
    }
    // The breaks at its start (with segment s - 1) and at its end (with s + 1); a merged one is
    // no change of rate.
    for (int later = s; later <= s + 1; ++later) {
      if (later < 1 || later >= p.segment_count || !(limits.min_pitch_rate_change_rad_s > 0.0)) continue;
      if (rate_continues_previous(p, later)) continue;
      const double change = std::fabs(segment_rate(p, later) - segment_rate(p, later - 1));
      if (change < limits.min_pitch_rate_change_rad_s * (1.0 - kAcceptedRateSlack)) {
        out->coast7_below_min_rate_change = true;
      }
    }
  }
}

namespace {

// The optimized case, flown without the zero-alpha window and without the in-flight alpha = 0
// attitude at stage-2 ignition: both become fixed values of the linear program.
void start_from_optimum(const OptimizerWorkspace& optimized, LinearizationWorkspace* ws) {
  ws->mission = optimized.mission;
  ws->mission.options.set_zero_alpha_window(false);
  ws->mission.options.set_alpha_zero_at_stage2_ignition(false);
  ws->prepared = optimized.prepared;
  const Trajectory& optimum_trajectory = optimized.nominal;
  ws->optimum.point_count = optimum_trajectory.point_count;
  for (int k = 0; k < optimum_trajectory.point_count; ++k) {
    ws->optimum.theta_rad[k] = optimum_trajectory.points[k].theta_rad;
  }
}

// Fixed break values: 90 deg at the end of lift-off; the end of a maximum-rate period after it
// (the optimum's attitude there); alpha = 0 at stage-2 ignition (the optimum's attitude there).
// Every other break starts at the optimum's attitude.
void fix_break_values(const OptimizerWorkspace& optimized, const LinearizationWorkspace& ws,
                      LinearProgram* base) {
  const Trajectory& optimum_trajectory = optimized.nominal;
  const auto optimum_theta_at = [&](double t) {
    for (int k = 1; k < optimum_trajectory.point_count; ++k) {
      if (std::fabs(optimum_trajectory.points[k].time_s - t) < kSameInstantS) {
        return optimum_trajectory.points[k].theta_rad;
      }
    }
    return optimum_trajectory.points[1].theta_rad;
  };
  for (int b = 0; b <= base->segment_count; ++b) base->theta_rad[b] = optimum_theta_at(base->break_time_s[b]);
  if (std::fabs(base->break_time_s[0] - ws.mission.launch.liftoff_duration_s) < kSameInstantS) {
    base->theta_rad[0] = 0.5 * kPi;
    base->fixed[0] = true;
  }
  if (optimized.mission.options.alpha_zero_at_stage2_ignition()) {
    const double ignition = stage_start_s(ws.prepared, 2);
    for (int b = 0; b <= base->segment_count; ++b) {
      if (std::fabs(base->break_time_s[b] - ignition) < kSameInstantS) {
        base->fixed[b] = true;
        for (int k = 0; k < optimum_trajectory.point_count; ++k) {
          if (optimum_trajectory.points[k].stage_code == 2 &&
              std::fabs(optimum_trajectory.points[k].time_s - ignition) < kSameInstantS) {
            base->theta_rad[b] = optimum_trajectory.points[k].theta_rad;
          }
        }
      }
    }
  }
  // The maximum-rate period after lift-off: if the optimum pitches at the limit from lift-off, the
  // second break moves to where that period ends and keeps the optimum's attitude there (Sec. 10).
  const double max_rate = ws.mission.control.max_pitch_rate_rad_s;
  if (max_rate > 0.0 && base->segment_count > 1) {
    double end_of_max_rate = -1.0;
    for (int k = 2;
         k < optimum_trajectory.point_count && optimum_trajectory.points[k].time_s < base->break_time_s[2];
         ++k) {
      const TrajectoryPoint& a = optimum_trajectory.points[k - 1];
      const TrajectoryPoint& b = optimum_trajectory.points[k];
      const double dt = b.time_s - a.time_s;
      if (!(dt > 0.0) || std::fabs(b.theta_rad - a.theta_rad) < max_rate * dt * 0.99) break;
      end_of_max_rate = b.time_s;
    }
    if (end_of_max_rate > base->break_time_s[0]) {
      base->break_time_s[1] = end_of_max_rate;
      base->theta_rad[1] = optimum_theta_at(end_of_max_rate);
      base->fixed[1] = true;
    }
  }
}

// One backward run about the nominal and the programs computed from it: up to five, each
// repairing one rate violation. The repairs and their eta of earlier backward runs are kept
// (docs/theory/linearization.md): restarting from none lets the program's structure flip between
// runs, and with it the trajectory.
Status next_program(const LinearConstraints& c, const LinearProgram& base, const double* achieved,
                    LinearizationWorkspace* ws, LinearProgram* program, double* payload_change_lb,
                    LinearizationResult* out) {
  ConstraintTerminal terminals[kMaxConstraints];
  Status status = constraint_terminals(c, ws->mission, ws->nominal, terminals);
  if (!ok(status)) return status;
  // The q-bar x alpha peaks get adjoint columns after the constraints': each starts at its point
  // from the partials of q-bar alpha there.
  PeakRows peaks;
  select_peaks(ws->mission, ws->nominal, kMaxConstraints - c.count, &peaks);
  for (int i = 0; i < peaks.count; ++i) {
    ConstraintTerminal& t = terminals[c.count + i];
    t = ConstraintTerminal();
    t.point = peaks.point[i];
    StateVector ds_dx;
    status =
        qbar_alpha_point_partials(ws->mission, ws->prepared, ws->nominal, t.point, &ds_dx, &peaks.direct[i]);
    if (!ok(status)) return status;
    t.partials.head<6>() = ds_dx;
  }
  status =
      run_backward(ws->mission, ws->prepared, ws->nominal, c.count + peaks.count, terminals, &ws->backward);
  if (!ok(status)) return status;
  ++out->backward_runs;
  const double limit = ws->mission.options.qbar_alpha_limit_lbf_rad_ft2;

  const LinearProgram previous = *program;
  *payload_change_lb = 0.0;
  *program = base;
  program->rate_repair_count = previous.rate_repair_count;
  for (int r = 0; r < previous.rate_repair_count; ++r) {
    program->rate_segment[r] = previous.rate_segment[r];
    program->rate_merge[r] = previous.rate_merge[r];
    program->rate_value_rad_s[r] = previous.rate_value_rad_s[r];
  }
  for (int sg = 0; sg < program->segment_count; ++sg) program->eta[sg] = previous.eta[sg];
  for (int attempt = 0; attempt < kMaxProgramsPerBackwardRun; ++attempt) {
    // With more peaks than the segments can hold, the smallest ones are left to the next run.
    int peaks_used = peaks.count;
    const LinearProgram unsolved = *program;
    status = solve_program(c, ws->backward, ws->nominal, ws->program, ws->optimum, achieved, peaks,
                           peaks_used, limit, &ws->system, program, payload_change_lb);
    while (status == Status::kSteeringMatrixSingular && peaks_used > 0) {
      --peaks_used;
      *program = unsolved;
      status = solve_program(c, ws->backward, ws->nominal, ws->program, ws->optimum, achieved, peaks,
                             peaks_used, limit, &ws->system, program, payload_change_lb);
    }
    if (!ok(status)) return status;
    ++out->programs_computed;
    if (!repair_rate_limits(ws->mission, c, coast_rate_after_program(ws->mission, ws->prepared, *program),
                            program)) {
      break;
    }
  }
  update_rates_and_stages(ws->nominal, program);
  return Status::kOk;
}

// IP(6) = 1 (Sec. 10): after a successful point-mass linearization, the program becomes the
// command of 6D runs; the linearization goes on with them, within the same DA13(4) budget, until
// the constraints and the rate limits are met again. The first 6D flight, of the accepted program
// itself, is the trajectory the next backward run linearizes about: the counterpart of the
// manual's backward run, which integrates the 6D trajectory itself, and not a linearization
// attempt (docs/theory/linearization.md). Records the point-mass result first. With designed
// autopilot gains (`gains`, issue 16) the schedule is designed along the accepted point-mass
// trajectory before the first 6D flight.
Status switch_to_body_dynamics(const LinearConstraints& c, const LinearProgram& program,
                               SixDGainDesign* gains, LinearizationWorkspace* ws, double* achieved,
                               LinearizationResult* out) {
  out->point_mass_met = true;
  out->point_mass_program = program;
  Status status = linearized_payoff(ws->mission, ws->nominal, &out->point_mass_payoff);
  if (!ok(status)) return status;
  for (int j = 0; j < c.count; ++j) out->point_mass_achieved[j] = achieved[j];
  out->body_dynamics = true;
  if (gains != nullptr) {
    status = gains->before_body_dynamics(ws->nominal, &ws->mission);
    if (!ok(status)) return status;
  }
  status = fly_linearized(*ws, true, &ws->candidate);
  ++out->reference_flights;
  if (!ok(status)) return status;
  status = evaluate_constraints(c, ws->mission, ws->candidate, achieved);
  if (!ok(status)) return status;
  for (int j = 0; j < c.count; ++j) out->point_mass_program_6d_achieved[j] = achieved[j];
  ws->nominal = ws->candidate;
  return Status::kOk;
}

// The last program, its constraints against their linearization deadbands, and its payoff.
Status record_result(const LinearConstraints& c, const LinearProgram& program, const double* achieved,
                     const LinearizationWorkspace& ws, LinearizationResult* out) {
  out->program = program;
  check_coast7_rates(ws.mission, program, out);
  out->constraint_count = c.count;
  for (int j = 0; j < c.count; ++j) {
    out->codes[j] = c.codes[j].code;
    out->desired[j] = c.desired[j];
    out->achieved[j] = achieved[j];
    out->tolerance[j] = c.deadband[j];
    out->met[j] = std::fabs(constraint_correction(c, j, achieved[j])) <= c.deadband[j];
  }
  return linearized_payoff(ws.mission, ws.nominal, &out->payoff);
}

}  // namespace

Status linearize_pitch_program(const OptimizerWorkspace& optimized, LinearizationWorkspace* ws,
                               LinearizationResult* out, SixDGainDesign* gains,
                               LinearizationObserver* observer) {
  out->forward_runs = 0;
  out->backward_runs = 0;
  out->programs_computed = 0;
  out->finished = false;
  out->constraints_met = false;
  out->rate_limits_met = false;
  out->body_dynamics = false;
  out->point_mass_met = false;
  out->reference_flights = 0;
  start_from_optimum(optimized, ws);

  LinearConstraints c;
  Status status = select_constraints(ws->mission, &c);
  if (!ok(status)) return out->status = status;
  LinearProgram base;
  status = break_times(ws->mission, ws->prepared, optimized.nominal, &base);
  if (!ok(status)) return out->status = status;
  update_rates_and_stages(optimized.nominal, &base);  // the stage codes the rate repairs read
  fix_break_values(optimized, *ws, &base);

  // The first nominal: the optimum program flown under the linearization rules.
  const int budget = ws->mission.convergence.max_linearization_iterations;
  ws->program = ws->optimum;
  status = fly_trajectory(ws->mission, ws->prepared, ws->program, &ws->nominal);
  if (!ok(status)) return out->status = status;
  double achieved[kMaxConstraints] = {};
  status = evaluate_constraints(c, ws->mission, ws->nominal, achieved);
  if (!ok(status)) return out->status = status;

  LinearProgram program = base;
  bool success = false;
  const bool six_d_after_success = optimized.mission.options.body_dynamics_6d() == 1;
  while (out->forward_runs < budget && !success) {
    double payload_change_lb = 0.0;
    status = next_program(c, base, achieved, ws, &program, &payload_change_lb, out);
    if (!ok(status)) return out->status = status;

    // Forward linearization run.
    sample(program, ws->nominal, ws->optimum, &ws->program);
    ws->mission.vehicle.payload_lb += payload_change_lb;
    if (!(ws->mission.vehicle.payload_lb >= 0.0)) return out->status = Status::kLinearizedPayloadNegative;
    if (observer != nullptr) {
      observer->on_linearization_run(out->forward_runs + 1, program, out->body_dynamics);
    }
    status = fly_linearized(*ws, out->body_dynamics, &ws->candidate);
    ++out->forward_runs;
    if (!ok(status)) return out->status = status;
    status = evaluate_constraints(c, ws->mission, ws->candidate, achieved);
    if (!ok(status)) return out->status = status;
    ws->nominal = ws->candidate;
    out->rate_limits_met =
        meets_rate_limits(ws->mission, coast_rate_after_program(ws->mission, ws->prepared, program), program);
    out->constraints_met = within_deadbands(c, 0, achieved);
    success = out->rate_limits_met && out->constraints_met;

    if (success && six_d_after_success && !out->body_dynamics) {
      status = switch_to_body_dynamics(c, program, gains, ws, achieved, out);
      if (!ok(status)) return out->status = status;
      out->constraints_met = within_deadbands(c, 0, achieved);
      success = out->rate_limits_met && out->constraints_met;
    }
  }

  status = record_result(c, program, achieved, *ws, out);
  if (!ok(status)) return out->status = status;
  out->finished = true;
  out->status = success ? Status::kOk : Status::kLinearizationDidNotConverge;
  return out->status;
}

}  // namespace tolip
