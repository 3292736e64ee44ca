// Monte Carlo dispersions on threads (issue 11 "Beyond the manual", in part): the core flies each
// sample (tolip/dispersion/monte_carlo.hpp); here the samples are spread over threads, each with
// its own workspace and taking the next sample not yet flown, and the statistics are formed in
// sample order, so the result is bit for bit the same for any thread count. The command and its reports:
// monte_carlo_command.hpp, monte_carlo_report.hpp.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "tolip/dispersion/monte_carlo.hpp"

namespace tolip::ground {

struct MonteCarloSamples {
  Status status = Status::kNotPrepared;  // the nominal's
  DispersedTrajectory nominal;
  std::vector<DispersedTrajectory> samples;  // index = sample number; each with its own status
  // With a MonteCarloImpactRequest (its data not null): the request, the nominal's casings and every
  // sample's (index = sample number; count 0 for a sample that did not fly). Otherwise no request
  // data and `impacts` empty.
  MonteCarloImpactRequest impact_request;
  MonteCarloImpacts nominal_impacts;
  std::vector<MonteCarloImpacts> impacts;
};

// Told, on the calling thread, how many samples have been flown so far (of `count`); for a
// progress display. Never called when empty.
using MonteCarloProgress = std::function<void(int flown, int count)>;

// Flies samples 0..count-1 of (seed) on `threads` threads (>= 1). With `progress`, the calling
// thread only waits and reports (every 50 ms and at the end) while `threads` workers fly. With
// impacts.data, each sample that flew then flies its casings (fly_monte_carlo_casings), and the
// nominal its own.
Status run_monte_carlo(const DispersionNominal& nominal, const DispersionData& data, std::uint64_t seed,
                       int count, int threads, MonteCarloSamples* out,
                       const MonteCarloProgress& progress = MonteCarloProgress(),
                       const MonteCarloImpactRequest& impacts = MonteCarloImpactRequest());

struct MonteCarloStatistic {
  int count = 0;  // samples that flew
  double mean = 0.0;
  double standard_deviation = 0.0;  // sample (n - 1)
  double p00135 = 0.0;              // 0.135 % (-3 sigma of a normal), nearest rank
  double p50 = 0.0;
  double p99865 = 0.0;
};

// The statistics of `values` (in sample order; the non-finite ones left out): the sums run in that
// order and the percentiles are nearest-rank on the sorted values, so the result depends on the
// samples only, never on who flew them.
MonteCarloStatistic statistic_of(std::vector<double> values);

// Statistics of one staging variable's dispersion at one column, over the samples that flew.
MonteCarloStatistic monte_carlo_statistic(const MonteCarloSamples& samples, int column,
                                          StagingVariable variable);

}  // namespace tolip::ground
