// Monte Carlo dispersions, per sample (tolip/dispersion/monte_carlo.hpp).
#include "tolip/dispersion/monte_carlo.hpp"

#include <cmath>

namespace tolip {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// The code whose value and draw a code shares: the high member of a high/low pair.
int family_leader(int code) {
  const int pairs[][2] = {{1, 2},   {3, 4},   {5, 6},   {7, 8},   {9, 10},  {11, 12}, {13, 14}, {15, 16},
                          {17, 18}, {19, 20}, {21, 22}, {24, 25}, {27, 28}, {30, 31}, {34, 35}, {36, 37}};
  // cppcheck-suppress constVariable ; 'pair' is a const reference already (to an int[2] row)
  for (const auto& pair : pairs) {
    if (code == pair[1]) return pair[0];
  }
  return code;
}

bool has_code(const DispersionData& data, int code) {
  for (int k = 0; k < data.count; ++k) {
    if (data.sources[k].code == code) return true;
  }
  return false;
}

int index_of(const DispersionData& data, int code) {
  for (int k = 0; k < data.count; ++k) {
    if (data.sources[k].code == code) return k;
  }
  return -1;
}

bool in_sequence(const Mission& mission, int code) {
  const StageSequence& sequence = mission.vehicle.sequence;
  for (int k = 0; k < sequence.count; ++k) {
    if (sequence.codes[k] == code) return true;
  }
  return false;
}

bool is_table_kind(DispersionKind kind) {
  return kind == DispersionKind::kVacuumThrust || kind == DispersionKind::kPitchingMoment ||
         kind == DispersionKind::kWind;
}

// Abscissae closer than this (relative) are one point of a merged grid: the reference thrust
// tables scale time and burn time alike, so their normalized times agree to round-off.
constexpr double kMergeTolerance = 1e-12;

// Sorted union of the abscissae of up to four tables, each scaled by 1 / scale[i] (0: skipped);
// false when more than `capacity` points result.
template <int N>
struct Grid {
  double x[N] = {};
  int count = 0;
};

// A run of a table's entries [first, first + count) at abscissa x - offset: one stage's part of
// stacked stage-4/5 tables (codes 7-8 with block 55), merged as a table of its own.
template <int N>
struct TablePart {
  const Table<N>* table = nullptr;
  int first = 0;
  int count = 0;
  double offset = 0.0;
  int size() const { return count; }
  double x(int i) const { return table->x(first + i) - offset; }
};

// A, B, C, D: Table<N> or TablePart<N> (size() and x(i)).
template <int G, class A, class B, class C, class D>
bool merge_grid(const A* a, double sa, const B* b, double sb, const C* c, double sc, const D* d, double sd,
                Grid<G>* out) {
  out->count = 0;
  int ia = 0, ib = 0, ic = 0, id = 0;
  const auto next = [](auto* table, double scale, int i) {
    return (table != nullptr && i < table->size()) ? table->x(i) / scale : HUGE_VAL;
  };
  // Each table's next scaled abscissa, computed when its index moves.
  double xa = next(a, sa, ia), xb = next(b, sb, ib), xc = next(c, sc, ic), xd = next(d, sd, id);
  for (;;) {
    const double x = std::fmin(std::fmin(xa, xb), std::fmin(xc, xd));
    if (x == HUGE_VAL) return true;
    const double tolerance = kMergeTolerance * std::fmax(1.0, std::fabs(x));
    if (xa - x <= tolerance) xa = next(a, sa, ++ia);
    if (xb - x <= tolerance) xb = next(b, sb, ++ib);
    if (xc - x <= tolerance) xc = next(c, sc, ++ic);
    if (xd - x <= tolerance) xd = next(d, sd, ++id);
    if (out->count >= G) return false;
    out->x[out->count++] = x;
  }
}

// Codes 1-8: the stage's thrust and consumable-weight tables and burn time blended between the
// nominal's (c = 0) and the source's (c = 1) in normalized stage time tau = t / burn time:
// b = b_n + c (b_s - b_n), T(tau b) = T_n(tau b_n) + c (T_s(tau b_s) - T_n(tau b_n)), W alike, on
// the union of both grids (exactly the source's tables at c = 1, linear in c). The union grid and
// the four tables at its points do not depend on c: plan_thrust_blend() works them out once per
// Monte Carlo (MonteCarloPlan), apply_thrust_blend() blends them with a sample's c.
void plan_thrust_blend(const StageData& nominal, const ThrustTable& source_thrust,
                       const WeightTable& source_weight, int slot, MonteCarloThrustBlend* out) {
  const double bn = nominal.duration_s;
  const double bs = source_thrust.last_x();
  out->slot = slot;
  out->nominal_burn_s = bn;
  out->source_burn_s = bs;
  out->merged = false;
  out->count = 0;
  if (!(bn > 0.0) || !(bs > 0.0)) return;  // every c fails on the burn time first
  Grid<kMaxThrustPoints> grid;
  if (!merge_grid(&nominal.vacuum_thrust_lbf, bn, &nominal.consumable_weight_lb, bn, &source_thrust, bs,
                  &source_weight, bs, &grid)) {
    return;
  }
  int hint_tn = -1, hint_ts = -1, hint_wn = -1, hint_ws = -1;  // tau increases: hinted look-ups
  for (int i = 0; i < grid.count; ++i) {
    const double tau = grid.x[i];
    out->tau[i] = tau;
    out->nominal_thrust_lbf[i] = nominal.vacuum_thrust_lbf(tau * bn, &hint_tn);
    out->source_thrust_lbf[i] = source_thrust(tau * bs, &hint_ts);
    out->nominal_weight_lb[i] = nominal.consumable_weight_lb(tau * bn, &hint_wn);
    out->source_weight_lb[i] = source_weight(tau * bs, &hint_ws);
  }
  out->count = grid.count;
  out->merged = true;
}

Status apply_thrust_blend(const MonteCarloThrustBlend& blend, double c, StageData* out) {
  const double bn = blend.nominal_burn_s;
  const double bs = blend.source_burn_s;
  const double b = bn + c * (bs - bn);
  if (!(bn > 0.0) || !(bs > 0.0) || !(b > 0.0)) return Status::kMonteCarloBurnTimeNotPositive;
  if (!blend.merged) return Status::kTooManyTablePoints;
  out->vacuum_thrust_lbf.clear();
  out->consumable_weight_lb.clear();
  for (int i = 0; i < blend.count; ++i) {
    const double tau = blend.tau[i];
    const double tn = blend.nominal_thrust_lbf[i];
    const double ts = blend.source_thrust_lbf[i];
    const double wn = blend.nominal_weight_lb[i];
    const double ws = blend.source_weight_lb[i];
    const double thrust = tn + c * (ts - tn);
    const double weight = wn + c * (ws - wn);
    if (!(thrust >= 0.0)) return Status::kMonteCarloThrustNegative;
    if (!(weight >= 0.0)) return Status::kNegativeWeight;
    if (i > 0 && weight > out->consumable_weight_lb.y(i - 1)) return Status::kConsumableWeightIncreases;
    const double t = (tau == 1.0) ? b : tau * b;
    Status status = out->vacuum_thrust_lbf.append(t, thrust);
    if (ok(status)) status = out->consumable_weight_lb.append(t, weight);
    if (!ok(status)) return status;
  }
  Status status = out->vacuum_thrust_lbf.finalize();
  if (ok(status)) status = out->consumable_weight_lb.finalize();
  if (!ok(status)) return status;
  out->duration_s = b;
  return Status::kOk;
}

// Codes 19-20: C_M_alpha(M) = C_n(M) + c (C_s(M) - C_n(M)) on the union of the Mach grids (the
// grid and both tables at it once per Monte Carlo, as the thrust).
void plan_moment_blend(const AeroTable& nominal, const AeroTable& source, MonteCarloMomentBlend* out) {
  out->merged = false;
  out->count = 0;
  Grid<kMaxAeroTablePoints> grid;
  if (!merge_grid(&nominal, 1.0, &source, 1.0, static_cast<const AeroTable*>(nullptr), 1.0,
                  static_cast<const AeroTable*>(nullptr), 1.0, &grid)) {
    return;
  }
  for (int i = 0; i < grid.count; ++i) {
    const double mach = grid.x[i];
    out->mach[i] = mach;
    out->nominal_per_rad[i] = nominal.empty() ? 0.0 : nominal(mach);
    out->source_per_rad[i] = source(mach);
  }
  out->count = grid.count;
  out->merged = true;
}

Status apply_moment_blend(const MonteCarloMomentBlend& blend, double c, AeroTable* out) {
  if (!blend.merged) return Status::kTooManyTablePoints;
  AeroTable blended;
  for (int i = 0; i < blend.count; ++i) {
    const double n = blend.nominal_per_rad[i];
    const Status status = blended.append(blend.mach[i], n + c * (blend.source_per_rad[i] - n));
    if (!ok(status)) return status;
  }
  const Status status = blended.finalize();
  if (!ok(status)) return status;
  *out = blended;
  return Status::kOk;
}

// Codes 36-38: the sample's wind, the sum of the drawn profiles each scaled by its draw c (a
// negative c reverses the wind vector). One profile: its own tables, the speed times |c| (azimuth
// turned by pi when c < 0), exactly. Two (a high/low and the yaw profile): the vector sum at every
// altitude of the union of their grids, as speed and azimuth (unwrapped, continuous), linear
// between the points as the tables are.
struct ScaledWind {
  const WindProfile* profile = nullptr;
  double scale = 0.0;
};

// The c-independent part of two profiles' sum: the union grid and both profiles at its points.
void plan_wind_blend(const WindProfile& a, const WindProfile& b, MonteCarloWindBlend* out) {
  out->merged = false;
  out->count = 0;
  Grid<kMaxWindTablePoints> grid;
  if (!merge_grid(&a.speed_ft_s, 1.0, &a.azimuth_rad, 1.0, &b.speed_ft_s, 1.0, &b.azimuth_rad, 1.0, &grid)) {
    return;
  }
  const WindProfile* profiles[2] = {&a, &b};
  for (int i = 0; i < grid.count; ++i) {
    const double h = grid.x[i];
    out->altitude_ft[i] = h;
    for (int k = 0; k < 2; ++k) {
      const WindProfile& w = *profiles[k];
      out->speed_ft_s[k][i] = w.speed_ft_s(h);
      const double azimuth = w.azimuth_rad(h);
      out->cos_azimuth[k][i] = std::cos(azimuth);
      out->sin_azimuth[k][i] = std::sin(azimuth);
    }
  }
  out->count = grid.count;
  out->merged = true;
}

// `pair`: the plan of winds[0] and winds[1] when count is 2.
Status compose_wind(const ScaledWind* winds, int count, const MonteCarloWindBlend* pair, WindProfile* out) {
  out->speed_ft_s.clear();
  out->azimuth_rad.clear();
  if (count == 1) {
    const WindProfile& w = *winds[0].profile;
    const double c = winds[0].scale;
    for (int i = 0; i < w.speed_ft_s.size(); ++i) {
      const Status status = out->speed_ft_s.append(w.speed_ft_s.x(i), std::fabs(c) * w.speed_ft_s.y(i));
      if (!ok(status)) return status;
    }
    for (int i = 0; i < w.azimuth_rad.size(); ++i) {
      const Status status =
          out->azimuth_rad.append(w.azimuth_rad.x(i), w.azimuth_rad.y(i) + (c < 0.0 ? kPi : 0.0));
      if (!ok(status)) return status;
    }
  } else {
    if (!pair->merged) return Status::kTooManyTablePoints;
    double previous = 0.0;
    bool have_previous = false;
    for (int i = 0; i < pair->count; ++i) {
      const double h = pair->altitude_ft[i];
      double north = 0.0, east = 0.0;
      for (int k = 0; k < count; ++k) {
        const double speed = winds[k].scale * pair->speed_ft_s[k][i];
        north += speed * pair->cos_azimuth[k][i];
        east += speed * pair->sin_azimuth[k][i];
      }
      const double speed = std::hypot(north, east);
      double azimuth = (speed > 0.0) ? std::atan2(east, north) : previous;
      if (have_previous) azimuth = previous + std::remainder(azimuth - previous, 2.0 * kPi);
      previous = azimuth;
      have_previous = have_previous || speed > 0.0;
      Status status = out->speed_ft_s.append(h, speed);
      if (ok(status)) status = out->azimuth_rad.append(h, azimuth);
      if (!ok(status)) return status;
    }
  }
  Status status = out->speed_ft_s.finalize();
  if (ok(status)) status = out->azimuth_rad.finalize();
  return status;
}

}  // namespace

bool monte_carlo_draws_source(const DispersionNominal& nominal, const DispersionData& data, int k) {
  const DispersionSource& s = data.sources[k];
  DispersionCodeInfo info;
  if (!dispersion_code_info(s.code, &info)) return false;
  const int leader = family_leader(s.code);
  if (leader != s.code && has_code(data, leader)) return false;
  switch (info.kind) {
    case DispersionKind::kWeightIncrement:
    case DispersionKind::kDrag:
    case DispersionKind::kControlDeadband:
    case DispersionKind::kLaunchAzimuth:
    case DispersionKind::kLaunchAttitude: return true;
    case DispersionKind::kThrustMisalignment: return nominal.body_dynamics;
    case DispersionKind::kTipoff:
      return nominal.mission != nullptr && nominal.mission->options.stage_is_spun(s.stage);
    case DispersionKind::kVacuumThrust:
      // Stacked stage-4/5 tables (block 55) blend both stages, so stage 5 must fly too.
      return nominal.mission != nullptr && in_sequence(*nominal.mission, dispersion_source_stage(s)) &&
             (!s.stacked_stage4_5_tables || in_sequence(*nominal.mission, 5));
    case DispersionKind::kPitchingMoment: return nominal.body_dynamics;
    case DispersionKind::kWind: return true;
    default: return false;
  }
}

int monte_carlo_low_partner(const DispersionNominal& nominal, const DispersionData& data, int k) {
  if (!monte_carlo_draws_source(nominal, data, k)) return -1;
  DispersionCodeInfo info;
  if (!dispersion_code_info(data.sources[k].code, &info) || !is_table_kind(info.kind)) return -1;
  for (int j = 0; j < data.count; ++j) {
    const int code = data.sources[j].code;
    if (code != data.sources[k].code && family_leader(code) == data.sources[k].code) {
      // The low member flies its own table only where it is a table of the same stage(s): both
      // stacked (stages 4 and 5), or both of one stage.
      if (info.kind == DispersionKind::kVacuumThrust &&
          (data.sources[j].stacked_stage4_5_tables != data.sources[k].stacked_stage4_5_tables ||
           dispersion_source_stage(data.sources[j]) != dispersion_source_stage(data.sources[k]))) {
        return -1;
      }
      return j;
    }
  }
  return -1;
}

double counter_uniform(std::uint64_t seed, std::uint64_t sample, std::uint32_t stream) {
  const std::uint64_t h = splitmix64(splitmix64(splitmix64(seed) ^ sample) ^ stream);
  return (static_cast<double>(h >> 11) + 0.5) * 0x1.0p-53;  // 53 bits, never 0 or 1
}

double counter_normal(std::uint64_t seed, std::uint64_t sample, std::uint32_t stream) {
  const double u1 = counter_uniform(seed, sample, 2u * stream);
  const double u2 = counter_uniform(seed, sample, 2u * stream + 1u);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

namespace {

// The plan of `data` about the nominal (MonteCarloPlan) into ws->monte_carlo_plan, keyed by
// nothing (the caller keys it). ws->unstacked is its scratch.
void make_monte_carlo_plan(const DispersionNominal& nominal, const DispersionData& data,
                           DispersionWorkspace* ws) {
  MonteCarloPlan& plan = ws->monte_carlo_plan;
  plan.mission = nominal.mission;
  plan.program = nominal.program;
  plan.body_dynamics = nominal.body_dynamics;
  plan.data = nullptr;
  plan.thrust_count = 0;
  plan.moment_count = 0;
  plan.wind_count = 0;
  for (int k = 0; k < data.count; ++k) {
    const DispersionSource& s = data.sources[k];
    MonteCarloPlan::Source& planned = plan.sources[k];
    planned = MonteCarloPlan::Source{};
    DispersionCodeInfo info;
    planned.known = dispersion_code_info(s.code, &info);
    if (!planned.known) continue;
    planned.drawn = monte_carlo_draws_source(nominal, data, k);
    if (!planned.drawn) continue;
    planned.kind = info.kind;
    planned.yaw = info.plane == DispersionPlane::kYaw;
    planned.leader = family_leader(s.code);
    planned.stage = dispersion_source_stage(s);
    if (!is_table_kind(info.kind)) continue;
    planned.partner = monte_carlo_low_partner(nominal, data, k);
    if (info.kind == DispersionKind::kWind && plan.wind_count < 2) plan.wind_sources[plan.wind_count++] = k;
    for (int side = 0; side < (planned.partner >= 0 ? 2 : 1); ++side) {
      const DispersionSource& table = (side == 1) ? data.sources[planned.partner] : s;
      MonteCarloPlan::TableSide& t = planned.sides[side];
      if (info.kind == DispersionKind::kVacuumThrust) {
        // The stage's own tables, or stages 4 and 5 of stacked tables (page 22-30).
        t.stacked = table.stacked_stage4_5_tables;
        if (t.stacked) {
          t.status = unstack_stage4_5_tables(table, &ws->unstacked[0], &ws->unstacked[1]);
          if (!ok(t.status)) continue;
        }
        t.parts = t.stacked ? 2 : 1;
        for (int part = 0; part < t.parts; ++part) {
          t.slots[part] = stage_index(t.stacked ? 4 + part : dispersion_source_stage(table));
          if (plan.thrust_count >= kMaxMonteCarloThrustBlends) continue;  // per sample (blends[part] = -1)
          t.blends[part] = plan.thrust_count++;
          plan_thrust_blend(nominal.mission->vehicle.stages[t.slots[part]],
                            t.stacked ? ws->unstacked[part].vacuum_thrust_lbf : table.vacuum_thrust_lbf,
                            t.stacked ? ws->unstacked[part].consumable_weight_lb : table.consumable_weight_lb,
                            t.slots[part], &plan.thrust[t.blends[part]]);
        }
      } else if (info.kind == DispersionKind::kPitchingMoment) {
        t.parts = 1;
        if (plan.moment_count >= kMaxMonteCarloMomentBlends) continue;
        t.blends[0] = plan.moment_count++;
        plan_moment_blend(nominal.mission->body_dynamics.pitching_moment_per_rad,
                          table.pitching_moment_per_rad, &plan.moment[t.blends[0]]);
      }
    }
  }
  // Two wind profiles: their sum for each table either may fly.
  if (plan.wind_count == 2) {
    const int k0 = plan.wind_sources[0];
    const int k1 = plan.wind_sources[1];
    for (int s0 = 0; s0 < (plan.sources[k0].partner >= 0 ? 2 : 1); ++s0) {
      for (int s1 = 0; s1 < (plan.sources[k1].partner >= 0 ? 2 : 1); ++s1) {
        const DispersionSource& a = data.sources[s0 == 1 ? plan.sources[k0].partner : k0];
        const DispersionSource& b = data.sources[s1 == 1 ? plan.sources[k1].partner : k1];
        plan_wind_blend(a.wind, b.wind, &plan.wind[s0][s1]);
      }
    }
  }
}

// The plan of this sample: the workspace's when it was made for this nominal and data, else one
// made now for this sample alone.
const MonteCarloPlan& plan_of(const DispersionNominal& nominal, const DispersionData& data,
                              DispersionWorkspace* ws) {
  const MonteCarloPlan& plan = ws->monte_carlo_plan;
  if (plan.data == &data && plan.mission == nominal.mission && plan.program == nominal.program &&
      plan.body_dynamics == nominal.body_dynamics) {
    return plan;
  }
  make_monte_carlo_plan(nominal, data, ws);
  return plan;
}

// Part `part` of a thrust table side blended with c into the sample's mission: the plan's blend,
// or (repeated codes beyond the plan's blends) one worked out now.
Status blend_thrust_part(const DispersionNominal& nominal, const DispersionSource& table,
                         const MonteCarloPlan::TableSide& side, int part, double c, DispersionWorkspace* ws) {
  MonteCarloPlan& plan = ws->monte_carlo_plan;
  const int slot = side.slots[part];
  StageData* out = &ws->mission.vehicle.stages[slot];
  if (side.blends[part] >= 0) return apply_thrust_blend(plan.thrust[side.blends[part]], c, out);
  if (side.stacked) {
    const Status status = unstack_stage4_5_tables(table, &ws->unstacked[0], &ws->unstacked[1]);
    if (!ok(status)) return status;
  }
  plan_thrust_blend(nominal.mission->vehicle.stages[slot],
                    side.stacked ? ws->unstacked[part].vacuum_thrust_lbf : table.vacuum_thrust_lbf,
                    side.stacked ? ws->unstacked[part].consumable_weight_lb : table.consumable_weight_lb,
                    slot, &plan.thrust_scratch);
  return apply_thrust_blend(plan.thrust_scratch, c, out);
}

// The sample's mission starts as the nominal: copied whole when the workspace holds no copy of this
// nominal (DispersionWorkspace::MonteCarloEdits), else only the stage weights and the azimuth are
// reset here; the tables the last sample changed are rebuilt by this one's draws or restored by
// restore_unchanged_tables() after them.
void begin_sample_mission(const Mission& nominal, DispersionWorkspace* ws) {
  DispersionWorkspace::MonteCarloEdits& edits = ws->monte_carlo_edits;
  Mission& m = ws->mission;
  if (edits.base != &nominal) {
    m = nominal;
    edits = DispersionWorkspace::MonteCarloEdits{};
    edits.base = &nominal;
    return;
  }
  for (int k = 0; k < kMaxStages; ++k) {
    m.vehicle.stages[k].jettison_weight_lb = nominal.vehicle.stages[k].jettison_weight_lb;
  }
  m.launch.azimuth_rad = nominal.launch.azimuth_rad;
}

// The tables an earlier sample changed and this one did not draw, back to the nominal's.
void restore_unchanged_tables(const Mission& nominal, const bool* thrust_drawn, bool drag_drawn,
                              bool pitching_moment_drawn, DispersionWorkspace* ws) {
  DispersionWorkspace::MonteCarloEdits& edits = ws->monte_carlo_edits;
  Mission& m = ws->mission;
  for (int k = 0; k < kMaxStages; ++k) {
    StageData& stage = m.vehicle.stages[k];
    const StageData& from = nominal.vehicle.stages[k];
    if (edits.thrust_blended[k] && !thrust_drawn[k]) {
      stage.vacuum_thrust_lbf = from.vacuum_thrust_lbf;
      stage.consumable_weight_lb = from.consumable_weight_lb;
      stage.duration_s = from.duration_s;
      edits.thrust_blended[k] = false;
    }
    if (edits.drag_scaled && !drag_drawn) stage.drag_coefficient = from.drag_coefficient;
  }
  if (!drag_drawn) edits.drag_scaled = false;
  if (edits.pitching_moment_blended && !pitching_moment_drawn) {
    m.body_dynamics.pitching_moment_per_rad = nominal.body_dynamics.pitching_moment_per_rad;
    edits.pitching_moment_blended = false;
  }
}

}  // namespace

Status build_monte_carlo_case(const DispersionNominal& nominal, const PreparedCase& nominal_prepared,
                              const DispersionData& data, std::uint64_t seed, std::uint64_t sample,
                              DispersionWorkspace* ws) {
  const MonteCarloPlan& plan = plan_of(nominal, data, ws);
  begin_sample_mission(*nominal.mission, ws);
  DispersionWorkspace::MonteCarloEdits& edits = ws->monte_carlo_edits;
  bool thrust_drawn[kMaxStages] = {};
  bool pitching_moment_drawn = false;
  ws->perturbation = FlightPerturbation{};
  ws->program_mapped = false;
  Mission& m = ws->mission;
  FlightPerturbation& p = ws->perturbation;
  bool prepares = false;
  bool thrust_changed = false;
  double drag_fraction = 0.0;
  ScaledWind winds[2];
  int wind_sides[2] = {};
  int wind_count = 0;
  for (int k = 0; k < data.count; ++k) {
    const DispersionSource& s = data.sources[k];
    const MonteCarloPlan::Source& planned = plan.sources[k];
    if (!planned.known) return Status::kDispersionCodeInvalid;
    if (!planned.drawn) continue;
    const double z =
        counter_normal(seed, sample, static_cast<std::uint32_t>(planned.leader)) / 3.0;  // 3 sigma -> 1 sigma
    const int stage = planned.stage;
    const bool yaw = planned.yaw;
    switch (planned.kind) {
      case DispersionKind::kWeightIncrement:
        m.vehicle.stages[stage_index(stage)].jettison_weight_lb += z * s.weight_increment_lb;
        prepares = true;
        break;
      case DispersionKind::kDrag: drag_fraction += z * s.drag_variation_fraction; break;
      case DispersionKind::kThrustMisalignment:
        (yaw ? p.misalignment_yaw_rad : p.misalignment_pitch_rad) += z * s.misalignment_rad;
        p.thrust_station_ft = s.thrust_station_ft;
        break;
      case DispersionKind::kControlDeadband:
        (yaw ? p.chi_offset_rad : p.theta_offset_rad)[stage_index(stage)] += z * s.deadband_rad;
        break;
      case DispersionKind::kTipoff: {
        double* offsets = yaw ? p.chi_offset_rad : p.theta_offset_rad;
        offsets[stage_index(stage)] += z * s.tipoff_rad;
        offsets[stage_index(stage + 5)] += z * s.tipoff_rad;
        if (stage == 4 && m.options.spin_stages_4_5() == 1) {
          offsets[stage_index(5)] += z * s.tipoff_rad;
          offsets[stage_index(10)] += z * s.tipoff_rad;
        }
        break;
      }
      case DispersionKind::kLaunchAzimuth:
        m.launch.azimuth_rad += z * s.launch_change_rad;
        prepares = true;
        break;
      case DispersionKind::kLaunchAttitude:
        for (double& offset : p.theta_offset_rad) offset += z * s.launch_change_rad;
        break;
      case DispersionKind::kVacuumThrust:
      case DispersionKind::kPitchingMoment:
      case DispersionKind::kWind: {
        // A table source: the high table for a positive draw, the pair's low table (when given)
        // for a negative one, else the same table mirrored (a negative scale).
        const int partner = planned.partner;
        const bool low = partner >= 0 && z < 0.0;
        const DispersionSource& table = low ? data.sources[partner] : s;
        const double c = low ? -z : z;
        const MonteCarloPlan::TableSide& side = planned.sides[low ? 1 : 0];
        if (planned.kind == DispersionKind::kVacuumThrust) {
          // The stage's own tables, or stages 4 and 5 of stacked tables (page 22-30), each blended
          // with the same draw.
          if (!ok(side.status)) return side.status;
          for (int part = 0; part < side.parts; ++part) {
            const int slot = side.slots[part];
            edits.thrust_blended[slot] = true;  // before the blend: a failed one leaves it changed
            thrust_drawn[slot] = true;
            const Status status = blend_thrust_part(nominal, table, side, part, c, ws);
            if (!ok(status)) return status;
            if (slot == 0 && !(m.vehicle.stages[0].duration_s > m.launch.liftoff_duration_s)) {
              return Status::kLiftoffLongerThanStage1;
            }
          }
          prepares = true;
          thrust_changed = true;
        } else if (planned.kind == DispersionKind::kPitchingMoment) {
          edits.pitching_moment_blended = true;
          pitching_moment_drawn = true;
          MonteCarloPlan& mutable_plan = ws->monte_carlo_plan;
          if (side.blends[0] < 0) {
            plan_moment_blend(nominal.mission->body_dynamics.pitching_moment_per_rad,
                              table.pitching_moment_per_rad, &mutable_plan.moment_scratch);
          }
          const Status status =
              apply_moment_blend(side.blends[0] >= 0 ? plan.moment[side.blends[0]] : plan.moment_scratch, c,
                                 &m.body_dynamics.pitching_moment_per_rad);
          if (!ok(status)) return status;
        } else if (wind_count < 2) {
          wind_sides[wind_count] = low ? 1 : 0;
          winds[wind_count++] = ScaledWind{&table.wind, c};
        }
        break;
      }
      default: break;  // not drawn (monte_carlo_draws_source)
    }
  }
  if (wind_count > 0) {
    const Status status =
        compose_wind(winds, wind_count, &plan.wind[wind_sides[0]][wind_sides[1]], &ws->wind);
    if (!ok(status)) return status;
    p.wind = &ws->wind;
  }
  restore_unchanged_tables(*nominal.mission, thrust_drawn, drag_fraction != 0.0, pitching_moment_drawn, ws);
  if (drag_fraction != 0.0) {
    if (!(std::fabs(drag_fraction) < 1.0)) return Status::kDispersionDragVariationOutOfRange;
    edits.drag_scaled = true;
    for (int k = 0; k < kMaxStages; ++k) {
      // The nominal's coefficients scaled (only set_y changes these tables: the abscissae and the
      // count are the nominal's).
      AeroTable& cd = m.vehicle.stages[k].drag_coefficient;
      const AeroTable& from = nominal.mission->vehicle.stages[k].drag_coefficient;
      for (int i = 0; i < cd.size(); ++i) cd.set_y(i, from.y(i) * (1.0 + drag_fraction));
      if (!cd.empty()) {
        const Status status = cd.finalize();
        if (!ok(status)) return status;
      }
    }
  }
  if (!prepares) {
    ws->prepared = nominal_prepared;
    return Status::kOk;
  }
  const Status status = prepare_case(m, &ws->prepared);
  if (!ok(status)) return status;
  if (thrust_changed && nominal.program != nullptr) {
    // A changed burn time: the nominal program flown in stage time (as build_dispersed_case).
    if (trajectory_point_count(ws->prepared) != nominal.program->point_count) {
      return Status::kControlProgramSizeMismatch;
    }
    map_control_program(nominal_prepared, *nominal.program, ws->prepared, &ws->program);
    ws->program_mapped = true;
  } else if (thrust_changed) {
    set_program_clock_shifts(nominal_prepared, ws->prepared, &p);
  }
  return Status::kOk;
}

Status check_monte_carlo_data(const DispersionNominal& nominal, const DispersionData& data, int* fault_code) {
  *fault_code = 0;
  if (nominal.mission == nullptr) return Status::kDispersionNominalNotPrepared;
  for (int k = 0; k < data.count; ++k) {
    if (!monte_carlo_draws_source(nominal, data, k)) continue;
    const DispersionSource& s = data.sources[k];
    DispersionCodeInfo info;
    if (!dispersion_code_info(s.code, &info) || !is_table_kind(info.kind)) continue;
    const int partner = monte_carlo_low_partner(nominal, data, k);
    for (int side = 0; side < 2; ++side) {
      const DispersionSource& t = (side == 1 && partner >= 0) ? data.sources[partner] : s;
      if (side == 1 && partner < 0) break;
      *fault_code = t.code;
      if (info.kind == DispersionKind::kVacuumThrust) {
        // The table's part of each stage it replaces: the whole table, or stage 4's and stage 5's
        // entries of stacked tables (find_stacked_stage4_5_split).
        const int n_table = t.vacuum_thrust_lbf.size();
        TablePart<kMaxThrustPoints> thrust_parts[2] = {{&t.vacuum_thrust_lbf, 0, n_table, 0.0}, {}};
        int stages[2] = {dispersion_source_stage(t), 0};
        int parts = 1;
        if (t.stacked_stage4_5_tables) {
          StackedStage45Split split;
          const Status status = find_stacked_stage4_5_split(t, &split);
          if (!ok(status)) return status;
          thrust_parts[0].count = split.stage4_last + 1;
          thrust_parts[1] = {&t.vacuum_thrust_lbf, split.stage5_first, n_table - split.stage5_first,
                             split.stage5_offset_s};
          stages[0] = 4;
          stages[1] = 5;
          parts = 2;
        }
        for (int part = 0; part < parts; ++part) {
          const TablePart<kMaxThrustPoints>& thrust = thrust_parts[part];
          const TablePart<kMaxWeightPoints> weight{&t.consumable_weight_lb, thrust.first, thrust.count,
                                                   thrust.offset};
          const double burn_s = thrust.x(thrust.count - 1);
          const StageData& n = nominal.mission->vehicle.stages[stage_index(stages[part])];
          Grid<kMaxThrustPoints> grid;
          if (!merge_grid(&n.vacuum_thrust_lbf, n.duration_s, &n.consumable_weight_lb, n.duration_s, &thrust,
                          burn_s, &weight, burn_s, &grid)) {
            return Status::kTooManyTablePoints;
          }
        }
      } else if (info.kind == DispersionKind::kPitchingMoment) {
        Grid<kMaxAeroTablePoints> grid;
        if (!merge_grid(&nominal.mission->body_dynamics.pitching_moment_per_rad, 1.0,
                        &t.pitching_moment_per_rad, 1.0, static_cast<const AeroTable*>(nullptr), 1.0,
                        static_cast<const AeroTable*>(nullptr), 1.0, &grid)) {
          return Status::kTooManyTablePoints;
        }
      }
    }
  }
  // The yaw profile (38) is summed with the high or low profile (36, 37) of the same sample on the
  // union of their grids.
  const int yaw = index_of(data, 38);
  if (yaw >= 0 && monte_carlo_draws_source(nominal, data, yaw)) {
    const WindProfile& b = data.sources[yaw].wind;
    for (int code : {36, 37}) {
      const int k = index_of(data, code);
      if (k < 0) continue;
      *fault_code = code;
      const WindProfile& a = data.sources[k].wind;
      Grid<kMaxWindTablePoints> grid;
      if (!merge_grid(&a.speed_ft_s, 1.0, &a.azimuth_rad, 1.0, &b.speed_ft_s, 1.0, &b.azimuth_rad, 1.0,
                      &grid)) {
        return Status::kTooManyTablePoints;
      }
    }
  }
  *fault_code = 0;
  return Status::kOk;
}

Status prepare_monte_carlo(const DispersionNominal& nominal, DispersionWorkspace* ws) {
  if (nominal.mission == nullptr) return Status::kDispersionNominalNotPrepared;
  ws->monte_carlo_edits.base = nullptr;  // the first sample copies the nominal's mission whole
  ws->monte_carlo_plan.data = nullptr;   // no plan: each sample makes its own
  Status status = prepare_case(*nominal.mission, &ws->nominal_prepared);
  if (!ok(status)) return status;
  return fly_trajectory(*nominal.mission, ws->nominal_prepared, dispersion_flight_inputs(nominal),
                        &ws->nominal);
}

Status prepare_monte_carlo(const DispersionNominal& nominal, const DispersionData& data,
                           DispersionWorkspace* ws) {
  const Status status = prepare_monte_carlo(nominal, ws);
  if (!ok(status)) return status;
  make_monte_carlo_plan(nominal, data, ws);
  ws->monte_carlo_plan.data = &data;
  return Status::kOk;
}

Status fly_monte_carlo_sample(const DispersionNominal& nominal, const DispersionData& data,
                              std::uint64_t seed, std::uint64_t sample,
                              const DispersedTrajectory& nominal_values, DispersionWorkspace* ws,
                              DispersedTrajectory* out) {
  *out = DispersedTrajectory{};
  Status status = build_monte_carlo_case(nominal, ws->nominal_prepared, data, seed, sample, ws);
  if (ok(status)) status = fly_dispersed_case(nominal, ws, out);
  out->status = status;
  if (!ok(status)) return status;
  for (int j = 0; j < kMaxStagingPoints; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) {
      out->dispersions[j][i] = out->values[j][i] - nominal_values.values[j][i];
    }
  }
  for (int i = 0; i < kOrbitDispersionElements; ++i) {
    const double d = out->orbit[i] - nominal_values.orbit[i];
    out->orbit_dispersions[i] = (i >= 3) ? std::remainder(d, 2.0 * kPi) : d;
  }
  return Status::kOk;
}

Status fly_monte_carlo_casings(const DispersionNominal& nominal, const MonteCarloImpactRequest& request,
                               const Mission& mission, const PreparedCase& prepared, const Trajectory& flight,
                               ImpactWorkspace* workspace, MonteCarloImpacts* out) {
  out->count = 0;
  if (request.data == nullptr || nominal.mission == nullptr) {
    return out->status = Status::kDispersionNominalNotPrepared;
  }
  if (!ok(flight.status)) {
    return out->status = Status::kImpactNominalFailed;
  }
  double weight_change_lb[kImpactStages] = {};
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    const int k = stage_index(stage);
    weight_change_lb[stage - 1] =
        mission.vehicle.stages[k].jettison_weight_lb - nominal.mission->vehicle.stages[k].jettison_weight_lb;
  }
  out->status = fly_expended_casings(mission, prepared, nominal.mission->launch, flight, *request.data,
                                     request.stages, weight_change_lb, workspace, out->casings, &out->count);
  return out->status;
}

}  // namespace tolip
