// Linearization of the optimum pitch program (manual Sec. 6 and 10).
//
// The optimum theta history is replaced by at most 15 straight segments between the break times of
// data block 18 (segment boundaries, moved to integration times), minimizing the eta-weighted integral
// of (theta_linear - theta_optimum)^2 (eqs. 6-6..6-10) subject to the linearized constraint changes
// (eq. 6-2) with some break values fixed (eqs. 6-16..6-22): theta = 90 deg at the end of lift-off,
// the end of a maximum-pitch-rate period, and alpha = 0 at stage-2 ignition under IP(12). Payoff,
// inclination and node constraints are not imposed; adjustable parameters and payload are held.
// The rate limits of data block 22 are repaired by fixing break values (Sec. 10), at most five
// programs per backward run, and forward linearization runs (at most DA13(4)) fly the segments
// until the constraints are within the linearization deadbands (data block 29 words 14-25) with
// no rate violation. The zero-alpha window (IP(11)) applies only during optimization.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/status.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip {

inline constexpr int kMaxBreakPoints = kMaxLinearSegments + 1;
// Rate repairs a program can carry: at most one per segment.
inline constexpr int kMaxRateRepairs = kMaxLinearSegments;
// Peaks of q-bar x alpha a fit can hold to the limit (docs/theory/linearization.md): one row each.
inline constexpr int kMaxQbarAlphaPeakRows = 4;
// Unknowns of the eq. 6-22 system: break values, the payload (payload payoff), constraint
// multipliers, rate-repair multipliers, q-bar x alpha peak multipliers.
inline constexpr int kLinearizationKktSize =
    kMaxBreakPoints + 1 + kMaxConstraints + kMaxRateRepairs + kMaxQbarAlphaPeakRows;

struct LinearProgram {
  int segment_count = 0;
  double break_time_s[kMaxBreakPoints] = {};  // from launch
  double theta_rad[kMaxBreakPoints] = {};
  bool fixed[kMaxBreakPoints] = {};
  double eta[kMaxLinearSegments] = {};  // segment weights (data block 26)
  // Rate repairs of Sec. 10, imposed in the fit as linear equalities that keep the segment's level
  // free: segment `rate_segment[r]` flies `rate_value_rad_s[r]`, or, for a merge, the break between
  // it and the next segment lies on the straight line through their outer breaks.
  int rate_repair_count = 0;
  int rate_segment[kMaxRateRepairs] = {};
  bool rate_merge[kMaxRateRepairs] = {};
  double rate_value_rad_s[kMaxRateRepairs] = {};
  // Per segment, for the guidance table: the stage flown at its start, the start in stage time,
  // and the pitch rate.
  int stage_code[kMaxLinearSegments] = {};
  double start_stage_time_s[kMaxLinearSegments] = {};
  double rate_rad_s[kMaxLinearSegments] = {};
};

struct LinearizationResult {
  Status status = Status::kNotPrepared;
  bool constraints_met = false;
  bool rate_limits_met = false;
  int forward_runs = 0;
  int backward_runs = 0;
  int programs_computed = 0;
  LinearProgram program;
  int constraint_count = 0;
  int codes[kMaxConstraints] = {};
  double desired[kMaxConstraints] = {};
  double achieved[kMaxConstraints] = {};
  double tolerance[kMaxConstraints] = {};  // linearization deadbands
  bool met[kMaxConstraints] = {};          // within its deadband (an inequality: not above it)
  double payoff = 0.0;                     // achieved by the linearized trajectory
  // The runs ended as Sec. 10 ends them (everything met, or DA13(4) runs made): the program, the
  // achieved values and the payoff above describe the last run. False when a failure (a singular
  // fit, a failed run) stopped them first: only the status and the counts are then meaningful.
  bool finished = false;
  // Sec. 10's closing checks of the coast between stages 2 and 3 (coast 7), which the manual reports
  // by message: its rate below the minimum rate, its rate within the minimum change of a neighbour's
  // (a merged break does not count). False when the program has no coast-7 segment.
  bool coast7_below_min_rate = false;
  bool coast7_below_min_rate_change = false;
  // IP(6) = 1, the 6D re-linearization (Sec. 10, 11): `body_dynamics` is true once the point-mass
  // program met everything and the runs went on with body dynamics; `program`, `achieved` and
  // `payoff` above then describe the 6D result. The point-mass result is kept here, with the
  // constraint values of the point-mass program flown with body dynamics before any correction
  // (the effect of the body dynamics alone).
  bool body_dynamics = false;
  bool point_mass_met = false;
  int reference_flights = 0;  // 6D flights of the accepted point-mass program (not in forward_runs)
  LinearProgram point_mass_program;
  double point_mass_payoff = 0.0;
  double point_mass_achieved[kMaxConstraints] = {};
  double point_mass_program_6d_achieved[kMaxConstraints] = {};
};

// The eq. 6-22 system (about 33 kB: kept off the stack): as assembled, and a copy eliminated in
// place; the assembled one checks the solution's equality rows.
struct LinearizationSystem {
  Eigen::Matrix<double, kLinearizationKktSize, kLinearizationKktSize> assembled;
  Eigen::Matrix<double, kLinearizationKktSize, kLinearizationKktSize> eliminated;
  Eigen::Matrix<double, kLinearizationKktSize, 1> rhs;
};

struct LinearizationWorkspace {
  Mission mission;  // the optimized case, flown without the zero-alpha window
  PreparedCase prepared;
  ControlProgram optimum;  // theta_OPT at every point
  ControlProgram program;  // the current linear program sampled at every point
  Trajectory nominal;
  Trajectory candidate;
  BackwardRun backward;
  LinearizationSystem system;
};

// True when segment `segment` flies the rate of the one before it (a merge, or a rate fixed equal
// to its neighbour's): the break between them is no change of rate (Sec. 10: a merge "in effect,
// eliminates a segment").
bool rate_continues_previous(const LinearProgram& program, int segment);

// dZ_j / d theta_b, b = 0..segment_count: the change of constraint j per unit change of break
// value b of `program`, linearized about `nominal` by its backward run (the per-point pitch
// gradients summed with the fit's hat functions over the points the fit weighs: the constraint
// rows of eq. 6-22 before their deadband scaling). For the q-bar x alpha excess (code 200) this is
// its sensitivity to the segments (docs/theory/linearization.md).
void break_value_gradients(const BackwardRun& backward, const Trajectory& nominal,
                           const LinearProgram& program, int constraint, double out[kMaxBreakPoints]);

// d s_k / d theta_b for q-bar alpha s_k at `point`: break_value_gradients of the backward run's
// column `column` (started at the point from qbar_alpha_point_partials) plus the point's own
// attitude term `direct` (d s_k / d theta_k) on its hat weights: the peak row of eq. 6-22.
void qbar_alpha_peak_gradients(const BackwardRun& backward, const Trajectory& nominal,
                               const LinearProgram& program, int column, int point, double direct,
                               double out[kMaxBreakPoints]);

// Sec. 10's closing checks of coast 7 on `program` (its stage_code per segment filled) with the
// mission's data block 22 limits; sets result->coast7_below_min_rate(_change).
void check_coast7_rates(const Mission& mission, const LinearProgram& program, LinearizationResult* result);

// Linearizes the optimum in `optimized` (the workspace optimize_trajectory left). The final
// linearized trajectory is workspace->nominal. Returns kOk when every constraint is within its
// linearization deadband and every rate limit is met; otherwise a named status with the best
// program found.
// IP(6) = 1 with designed autopilot gains (issue 16): called once, when the point-mass program
// met everything and before the first 6D flight, with the accepted point-mass trajectory; it may
// set the stage-1 gain schedule of `mission` (BodyDynamicsBlocks::stage1_schedule_*), which every
// 6D run then flies. A status other than kOk ends the linearization with it.
class SixDGainDesign {
 public:
  virtual Status before_body_dynamics(const Trajectory& point_mass_nominal, Mission* mission) = 0;

 protected:
  ~SixDGainDesign() = default;
};

// Told of the program each forward linearization run is about to fly (Sec. 22's program printout
// at the start of each linearization run): the run's number from 1, the program, and whether the
// run flies body dynamics. Between runs, on the linearization's thread.
class LinearizationObserver {
 public:
  virtual void on_linearization_run(int run, const LinearProgram& program, bool body_dynamics) = 0;

 protected:
  ~LinearizationObserver() = default;
};

Status linearize_pitch_program(const OptimizerWorkspace& optimized, LinearizationWorkspace* workspace,
                               LinearizationResult* result, SixDGainDesign* gains = nullptr,
                               LinearizationObserver* observer = nullptr);

}  // namespace tolip
