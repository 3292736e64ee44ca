// tolip_montecarlo_mpi DECK --samples N --seed S [options of `tolip montecarlo`]: the Monte Carlo
// dispersions of `tolip montecarlo` (issue 11 "Scale-out"; docs/cli.md, docs/theory/dispersions.md)
// split across the ranks of `mpirun -np K`. Every rank reads the deck and optimizes the case
// (deterministic: the same nominal everywhere), flies samples i = rank, rank + K, ... (counter-based
// draws: sample i is the same on any rank), and rank 0 gathers the records, puts them back in sample
// order and reports exactly as `tolip montecarlo` does (the same command code, with this flier), so
// the output is the same bytes as the single-process run for any K. Built only when CMake finds MPI.
#include <mpi.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <iostream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "tolip_ground/commands.hpp"
#include "tolip_ground/monte_carlo_command.hpp"

namespace {

using namespace tolip;
using namespace tolip::ground;

int g_rank = 0;
int g_ranks = 1;

// One sample as doubles: status, values, dispersions (all columns), orbit elements and dispersions,
// max q-bar alpha and its time; then its casing impacts (--impacts): their status and count, and of
// every casing each member of ImpactCase, only when the casings are flown (a record without them is
// kTrajectoryWords long).
constexpr int kCaseWords = 16;
constexpr int kImpactWords = 2 + kImpactStages * kCaseWords;
constexpr int kTrajectoryWords =
    1 + 2 * kMaxStagingPoints * kStagingVariables + 2 * kOrbitDispersionElements + 2;

int record_words(bool with_impacts) { return kTrajectoryWords + (with_impacts ? kImpactWords : 0); }

void pack_impacts(const MonteCarloImpacts& m, double* out) {
  int k = 0;
  out[k++] = static_cast<double>(static_cast<int>(m.status));
  out[k++] = m.count;
  for (const ImpactCase& c : m.casings) {
    const double words[kCaseWords] = {
        static_cast<double>(static_cast<int>(c.kind)),
        static_cast<double>(c.stage),
        static_cast<double>(c.nominal_point),
        c.failure_time_s,
        c.weight_lb,
        static_cast<double>(static_cast<int>(c.status)),
        c.impact_time_s,
        c.geodetic_latitude_rad,
        c.geocentric_latitude_rad,
        c.longitude_rad,
        c.downrange_rad,
        c.crossrange_rad,
        c.impact_velocity_ft_s,
        c.impact_flight_path_angle_rad,
        c.max_altitude_ft,
        static_cast<double>(c.steps) + (c.reached_terminal_velocity ? 0.5 : 0.0)};
    for (double w : words) out[k++] = w;
  }
}

void unpack_impacts(const double* in, MonteCarloImpacts* m) {
  int k = 0;
  m->status = static_cast<Status>(static_cast<int>(in[k++]));
  m->count = static_cast<int>(in[k++]);
  for (ImpactCase& c : m->casings) {
    c.kind = static_cast<ImpactKind>(static_cast<int>(in[k++]));
    c.stage = static_cast<int>(in[k++]);
    c.nominal_point = static_cast<int>(in[k++]);
    c.failure_time_s = in[k++];
    c.weight_lb = in[k++];
    c.status = static_cast<Status>(static_cast<int>(in[k++]));
    c.impact_time_s = in[k++];
    c.geodetic_latitude_rad = in[k++];
    c.geocentric_latitude_rad = in[k++];
    c.longitude_rad = in[k++];
    c.downrange_rad = in[k++];
    c.crossrange_rad = in[k++];
    c.impact_velocity_ft_s = in[k++];
    c.impact_flight_path_angle_rad = in[k++];
    c.max_altitude_ft = in[k++];
    const double steps = in[k++];
    c.steps = static_cast<int>(steps);
    c.reached_terminal_velocity = steps != static_cast<double>(c.steps);
  }
}

void pack(const DispersedTrajectory& t, const MonteCarloImpacts* m, double* out) {
  int k = 0;
  out[k++] = static_cast<double>(static_cast<int>(t.status));
  for (int j = 0; j < kMaxStagingPoints; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) out[k++] = t.values[j][i];
  }
  for (int j = 0; j < kMaxStagingPoints; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) out[k++] = t.dispersions[j][i];
  }
  for (int i = 0; i < kOrbitDispersionElements; ++i) out[k++] = t.orbit[i];
  for (int i = 0; i < kOrbitDispersionElements; ++i) out[k++] = t.orbit_dispersions[i];
  out[k++] = t.max_qbar_alpha_lbf_rad_ft2;
  out[k++] = t.max_qbar_alpha_time_s;
  if (m != nullptr) pack_impacts(*m, out + k);
}

void unpack(const double* in, DispersedTrajectory* t, MonteCarloImpacts* m) {
  int k = 0;
  t->status = static_cast<Status>(static_cast<int>(in[k++]));
  for (int j = 0; j < kMaxStagingPoints; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) t->values[j][i] = in[k++];
  }
  for (int j = 0; j < kMaxStagingPoints; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) t->dispersions[j][i] = in[k++];
  }
  for (int i = 0; i < kOrbitDispersionElements; ++i) t->orbit[i] = in[k++];
  for (int i = 0; i < kOrbitDispersionElements; ++i) t->orbit_dispersions[i] = in[k++];
  t->max_qbar_alpha_lbf_rad_ft2 = in[k++];
  t->max_qbar_alpha_time_s = in[k++];
  if (m != nullptr) unpack_impacts(in + k, m);
}

// The flier: this rank's share of the samples, gathered on rank 0 in sample order.
bool fly_on_ranks(const MonteCarloJob& job, MonteCarloSamples* samples) {
  const int rank = g_rank;
  const int ranks = g_ranks;
  const int count = job.count;
  auto ws = std::make_unique<DispersionWorkspace>();
  DispersedTrajectory nominal_values;
  Status status = prepare_monte_carlo(*job.nominal, *job.data, ws.get());
  if (ok(status)) {
    status = record_dispersed_trajectory(*job.nominal->mission, ws->nominal_prepared, ws->nominal,
                                         ws->nominal, nullptr, &nominal_values);
  }
  nominal_values.status = status;
  // Every rank flies the same nominal, so all fail here together or none does.
  if (!ok(status)) {
    samples->status = status;
    return rank == 0;
  }
  const bool with_impacts = job.impacts.data != nullptr;
  const int record = record_words(with_impacts);
  auto impact_ws = std::make_unique<ImpactWorkspace>();
  std::vector<double> mine;
  for (int i = rank; i < count; i += ranks) {
    DispersedTrajectory t;
    MonteCarloImpacts impacts;
    const Status sample = fly_monte_carlo_sample(*job.nominal, *job.data, job.seed,
                                                 static_cast<std::uint64_t>(i), nominal_values, ws.get(), &t);
    if (with_impacts && ok(sample)) {
      (void)fly_monte_carlo_casings(*job.nominal, job.impacts, ws->mission, ws->prepared, ws->dispersed,
                                    impact_ws.get(), &impacts);
    }
    mine.resize(mine.size() + static_cast<std::size_t>(record));
    pack(t, with_impacts ? &impacts : nullptr, mine.data() + mine.size() - record);
    if (rank == 0 && job.progress != nullptr && job.progress->enabled()) {
      job.progress->update("sample", static_cast<long>(i + 1), count, "(rank 0's share)");
    }
  }
  std::vector<int> counts(static_cast<std::size_t>(ranks));
  std::vector<int> offsets(static_cast<std::size_t>(ranks));
  for (int r = 0, at = 0; r < ranks; ++r) {
    const int share = (count - r + ranks - 1) / ranks;
    counts[static_cast<std::size_t>(r)] = share * record;
    offsets[static_cast<std::size_t>(r)] = at;
    at += share * record;
  }
  std::vector<double> all(rank == 0 ? static_cast<std::size_t>(count) * static_cast<std::size_t>(record) : 0);
  MPI_Gatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(), counts.data(),
              offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (rank != 0) return false;
  samples->status = Status::kOk;
  samples->nominal = nominal_values;
  samples->samples.assign(static_cast<std::size_t>(count), DispersedTrajectory{});
  samples->impact_request = job.impacts;
  samples->nominal_impacts = MonteCarloImpacts{};
  if (with_impacts) {
    (void)fly_monte_carlo_casings(*job.nominal, job.impacts, *job.nominal->mission, ws->nominal_prepared,
                                  ws->nominal, impact_ws.get(), &samples->nominal_impacts);
  }
  std::vector<MonteCarloImpacts> impacts(static_cast<std::size_t>(count));
  for (int r = 0; r < ranks; ++r) {
    const double* block = all.data() + offsets[static_cast<std::size_t>(r)];
    for (int i = r, n = 0; i < count; i += ranks, ++n) {
      unpack(block + static_cast<std::ptrdiff_t>(n) * record, &samples->samples[static_cast<std::size_t>(i)],
             with_impacts ? &impacts[static_cast<std::size_t>(i)] : nullptr);
    }
  }
  if (with_impacts) {
    samples->impacts = std::move(impacts);
  } else {
    samples->impacts.clear();
  }
  return true;
}

// Discards everything (the helper ranks' streams).
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
};

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_ranks);
  NullBuffer null_buffer;
  std::ostream null_stream(&null_buffer);
  std::ostream& out = (g_rank == 0) ? std::cout : null_stream;
  std::ostream& err = (g_rank == 0) ? std::cerr : null_stream;

  CLI::App app{
      "The Monte Carlo dispersions of 'tolip montecarlo' over the ranks of an MPI job\n"
      "(mpirun -np K): the same options, the same output bytes (docs/cli.md).",
      "tolip_montecarlo_mpi"};
  MonteCarloCommandOptions options;
  add_monte_carlo_options(app, &options);
  int exit_code = kExitOk;
  bool parsed = false;
  try {
    app.parse(argc, argv);
    parsed = true;
  } catch (const CLI::CallForHelp& e) {
    exit_code = app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    err << "tolip: " << e.what() << "\nRun 'tolip_montecarlo_mpi --help' for more information.\n";
    exit_code = kExitBadInput;
  }
  // One thread per rank (fly_on_ranks): the ranks are the parallelism; --threads is only checked.
  if (parsed) {
    if (options.threads == -1) options.threads = 1;
    if (g_rank != 0) options.progress = ProgressMode::kOff;
    exit_code = run_monte_carlo_command(options, fly_on_ranks, out, err);
  }
  out.flush();
  MPI_Finalize();
  return exit_code;
}
