// `tolip montecarlo DECK --samples N --seed S [--threads K] [--json] [--csv FILE] [--plots DIR]
// [--orbit-perigee-nmi H] [--impacts | --no-impacts] [--impact-stages LIST]`: Monte Carlo dispersions of a
// deck's case (issue 11; docs/cli.md "tolip montecarlo", docs/theory/dispersions.md "Monte Carlo"). The
// deck's case is optimized, the final nominal chosen as the dispersion analysis chooses it, and N samples
// drawn from data blocks 46-55 are flown; the reports (monte_carlo_report.hpp) are formed from the samples in
// sample order.
//
// Who flies the samples is a parameter (MonteCarloFlier): the threads of this process for `tolip`,
// the ranks of an MPI job for `tolip_montecarlo_mpi` (ground_tools/mpi/), which takes the same
// options and prints the same bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "tolip_ground/monte_carlo_report.hpp"
#include "tolip_ground/progress.hpp"

namespace CLI {
class App;
}

namespace tolip::ground {

// The most samples a run takes: the samples are kept in memory (about 0.6 kB each, 1 kB with the
// casing impacts) until the statistics are formed, so 100,000 is about 60 (100) MB per process.
inline constexpr long long kMaxMonteCarloSamples = 100000;
inline constexpr int kMaxMonteCarloThreads = 256;

// Whether the samples' casings are flown to impact (--impacts / --no-impacts; docs/cli.md): by
// default when the deck asks for the impact analysis (IP(23) = 1).
enum class ImpactMode { kAuto, kOn, kOff };

struct MonteCarloCommandOptions {
  std::string deck_path;
  long long samples = 0;  // 1..kMaxMonteCarloSamples
  std::uint64_t seed = 0;
  int threads = -1;  // -1 (not given): one per hardware thread
  bool json = false;
  std::string csv_path;   // empty: no CSV
  std::string plots_dir;  // empty: no plots
  std::string gnuplot;    // the gnuplot program; empty: $TOLIP_GNUPLOT, else gnuplot on PATH
  double orbit_perigee_nmi = kDefaultOrbitPerigee_nmi;
  ProgressMode progress = ProgressMode::kAuto;
  ImpactMode impacts = ImpactMode::kAuto;
  std::vector<int> impact_stages;  // --impact-stages: empty, every stage 1-3 in the sequence
};

// Adds the command's arguments and options to `command` (the `montecarlo` subcommand, or the MPI
// driver's own application).
void add_monte_carlo_options(CLI::App& command, MonteCarloCommandOptions* options);

// Adds the `montecarlo` subcommand with its help.
CLI::App* add_monte_carlo_command(CLI::App& app, MonteCarloCommandOptions* options);

// What a flier gets: the nominal, the data, the counter key and the sample count; the threads and
// the progress line (disabled when not shown) of the command line.
struct MonteCarloJob {
  const DispersionNominal* nominal = nullptr;
  const DispersionData* data = nullptr;
  std::uint64_t seed = 0;
  int count = 0;
  int threads = 1;
  ProgressLine* progress = nullptr;
  MonteCarloImpactRequest impacts;  // data null: no casing impacts
};

// Flies the job's samples into *samples (index = sample number) on the process that reports and
// returns true there; returns false on a process that only helped (an MPI rank other than 0), which
// then prints and writes nothing. samples->status: the nominal's.
using MonteCarloFlier = std::function<bool(const MonteCarloJob& job, MonteCarloSamples* samples)>;

// The flier of `tolip montecarlo`: run_monte_carlo on job.threads threads.
bool fly_on_threads(const MonteCarloJob& job, MonteCarloSamples* samples);

int run_monte_carlo_command(const MonteCarloCommandOptions& options, const MonteCarloFlier& flier,
                            std::ostream& out, std::ostream& err);
int run_monte_carlo_command(const MonteCarloCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tolip::ground
