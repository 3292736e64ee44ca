// Monte Carlo dispersions on threads (issue 11 "Beyond the manual", in part): the core flies each
// sample (tolip/dispersion/monte_carlo.hpp); here the samples are spread over threads, each with
// its own workspace, and the statistics are formed in sample order, so the result is bit for bit
// the same for any thread count. (The MPI driver and the `tolip montecarlo` command are not built.)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip/dispersion/monte_carlo.hpp"

namespace tolip::ground {

struct MonteCarloSamples {
  Status status = Status::kNotPrepared;  // the nominal's
  DispersedTrajectory nominal;
  std::vector<DispersedTrajectory> samples;  // index = sample number; each with its own status
};

// Flies samples 0..count-1 of (seed) on `threads` threads (>= 1).
Status run_monte_carlo(const DispersionNominal& nominal, const DispersionData& data, std::uint64_t seed,
                       int count, int threads, MonteCarloSamples* out);

struct MonteCarloStatistic {
  int count = 0;  // samples that flew
  double mean = 0.0;
  double standard_deviation = 0.0;  // sample (n - 1)
  double p00135 = 0.0;              // 0.135 % (-3 sigma of a normal), nearest rank
  double p50 = 0.0;
  double p99865 = 0.0;
};

// Statistics of one staging variable's dispersion at one column, over the samples that flew, summed
// in sample order.
MonteCarloStatistic monte_carlo_statistic(const MonteCarloSamples& samples, int column,
                                          StagingVariable variable);

// {"seed", "samples", "flown", "nominal_kind", "final_point": {variable: {mean, standard_deviation,
// p00135, p50, p99865}}}: the final-point dispersions (ft, ft/s, deg, n.mi.), for any driver.
nlohmann::ordered_json monte_carlo_json(const MonteCarloSamples& samples, std::uint64_t seed,
                                        const std::string& kind);

}  // namespace tolip::ground
