// Monte Carlo dispersions, the core's per-sample part (issue 11 "Beyond the manual", in part;
// docs/theory/dispersions.md "Monte Carlo"). Every sampled source of data blocks 46-55 is drawn at
// once per sample from a counter-based generator keyed by (seed, sample index, source), so sample
// i is the same whatever the number of threads or ranks and the order they run in. The dispersed
// case is flown like the deterministic codes (dispersion.hpp). No heap.
#pragma once

#include <cstdint>

#include "tolip/dispersion/dispersion.hpp"
#include "tolip/impact/impact.hpp"

namespace tolip {

// A uniform draw in (0, 1) from the counter (seed, sample, stream): the SplitMix64 finalizer of the
// three words combined (no state, so any draw can be made in any order).
double counter_uniform(std::uint64_t seed, std::uint64_t sample, std::uint32_t stream);

// A standard normal draw: Box-Muller on the uniforms of streams 2 stream and 2 stream + 1.
double counter_normal(std::uint64_t seed, std::uint64_t sample, std::uint32_t stream);

// Whether source k of `data` gets a draw of its own in build_monte_carlo_case (the one rule of what
// is sampled): a scalar source of a sampled kind, the misalignment only about a body-dynamics
// nominal, the tip-off only of a spun stage, and the low code of a pair only when its high code is
// absent (otherwise the pair's high code speaks for both).
bool monte_carlo_draws_source(const DispersionNominal& nominal, const DispersionData& data, int k);

// For a drawn table source k (thrust 1-8, C_M_alpha 19-20, winds 36-37) whose pair's low code is
// given too (the same stage for thrust): the index of that low code, whose table a negative draw
// flies; -1 otherwise (a negative draw then mirrors the drawn table about the nominal).
int monte_carlo_low_partner(const DispersionNominal& nominal, const DispersionData& data, int k);

// Checks, before any sample flies, that every drawn table source fits the core's tables once
// merged with what it is blended or summed with (kTooManyTablePoints, *fault_code the code).
Status check_monte_carlo_data(const DispersionNominal& nominal, const DispersionData& data, int* fault_code);

// Builds sample `sample` about the nominal into *workspace: every scalar source of `data` at once,
// normal with 1 sigma = the deck's (three-sigma) value / 3, one draw per high/low pair (keyed by its
// high code) and one per yaw code: weight increments (9-16), drag (17-18), misalignment (21-23,
// with body dynamics), deadbands (24-29), tip-off (30-32, spun stages), launch azimuth (33) and
// attitude (34-35); and the table sources with c = the draw (z / 3): thrust 1-8 (thrust, consumed
// weight and burn time blended between the nominal's and the code's tables, c = 1 the code's;
// stacked stage-4/5 tables of codes 7-8 with block 55 unstacked and both stages blended) and
// C_M_alpha 19-20 (with body dynamics) alike, winds 36-38 (the profile scaled by c; the high/low and
// the yaw profile of a sample summed as vectors). A negative draw of a pair flies its low table
// (monte_carlo_low_partner) or the mirror. `nominal_prepared` is the nominal's prepare_case().
// The workspace keeps its copy of the nominal's mission from one sample to the next and resets only
// what a sample changes (DispersionWorkspace::MonteCarloEdits): a nominal mission changed in place
// needs prepare_monte_carlo() again before its samples. What the case takes from `data` but not from
// the draws comes from workspace->monte_carlo_plan when prepare_monte_carlo() made it for this
// nominal and this `data` object, else it is worked out for this call (the same case, bit for bit).
Status build_monte_carlo_case(const DispersionNominal& nominal, const PreparedCase& nominal_prepared,
                              const DispersionData& data, std::uint64_t seed, std::uint64_t sample,
                              DispersionWorkspace* workspace);

// Prepares and flies the nominal into workspace->nominal_prepared / ->nominal (once per workspace).
// Without the data, every sample works out the half of its case its draws do not change itself.
Status prepare_monte_carlo(const DispersionNominal& nominal, DispersionWorkspace* workspace);

// The same, and that half of `data`'s samples once, for all of them (workspace->monte_carlo_plan,
// MonteCarloPlan): build_monte_carlo_case() uses it for this nominal and this `data` object, bit for
// bit the case it would build without it. Data changed in place needs prepare_monte_carlo() again
// before its samples, as a changed nominal does.
Status prepare_monte_carlo(const DispersionNominal& nominal, const DispersionData& data,
                           DispersionWorkspace* workspace);

// Builds and flies sample `sample`, recording it into *out (values and dispersions about
// workspace->nominal, which prepare_monte_carlo() flew; `nominal_values` its record).
Status fly_monte_carlo_sample(const DispersionNominal& nominal, const DispersionData& data,
                              std::uint64_t seed, std::uint64_t sample,
                              const DispersedTrajectory& nominal_values, DispersionWorkspace* workspace,
                              DispersedTrajectory* out);

// The casing impacts of the Monte Carlo (issue 11: "dispersion ellipses ... of stage impact
// points"; docs/theory/dispersions.md "Monte Carlo"): which expended casings (stage k when
// stages[k - 1]) a sample flies to impact, with the data blocks 43 tables and INTPIM steps of `data`
// (validate_casing_data() checked). Null data: no impacts.
struct MonteCarloImpactRequest {
  const ImpactLocusData* data = nullptr;
  bool stages[kImpactStages] = {};
};

// One sample's (or the nominal's) casings, in stage order: at most kImpactStages, no heap.
struct MonteCarloImpacts {
  Status status = Status::kNotPrepared;  // kOk: every casing asked for reached the surface
  int count = 0;
  ImpactCase casings[kImpactStages];
};

// The casings of `request` flown from the burnouts of `flight` (a completed flight of `mission` /
// `prepared`: a sample's ws->mission, ws->prepared, ws->dispersed, or the nominal's) exactly as the
// impact locus flies the nominal's (fly_expended_casings(): the same record, the same Sec. 4
// ranges), with the ranges from the nominal's launch site and azimuth (a sample's azimuth
// dispersion, code 33, moves its impact off the nominal's ground track instead of turning the
// track with it) and the casing weight changed by the sample's jettison weight increment of the
// stage (codes 9-14: mission's jettison weight minus the nominal mission's). The casing falls in
// still air with its block 43 drag: a sample's wind and drag draws (36-38, 17-18) disperse the
// ascent only. Returns out->status.
Status fly_monte_carlo_casings(const DispersionNominal& nominal, const MonteCarloImpactRequest& request,
                               const Mission& mission, const PreparedCase& prepared, const Trajectory& flight,
                               ImpactWorkspace* workspace, MonteCarloImpacts* out);

}  // namespace tolip
