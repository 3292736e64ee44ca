// tolip_montecarlo_mpi DECK SAMPLES SEED: the Monte Carlo dispersions of the deck's case (issue 11
// "Scale-out", in part; docs/theory/dispersions.md) split across the ranks of `mpirun -np K`: every
// rank optimizes the case (deterministic: the same nominal everywhere), flies samples i = rank,
// rank + K, ... (counter-based draws: sample i is the same on any rank), and rank 0 gathers the
// records in sample order and prints the statistics of the final-point dispersions as JSON, so
// the output is the same bytes for any K. Built only when CMake finds MPI.
#include <mpi.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/dispersion_run.hpp"
#include "tolip_ground/monte_carlo_run.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace {

using namespace tolip;
using namespace tolip::ground;

// One sample as doubles: status, values, dispersions (all columns), orbit elements and dispersions.
constexpr int kRecord = 1 + 2 * kMaxStagingPoints * kStagingVariables + 2 * kOrbitDispersionElements;

void pack(const DispersedTrajectory& t, double* out) {
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
}

void unpack(const double* in, DispersedTrajectory* t) {
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
}

int fail(const std::string& message) {
  std::cerr << "tolip_montecarlo_mpi: " << message << '\n';
  MPI_Abort(MPI_COMM_WORLD, 2);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (argc != 4) return fail("usage: tolip_montecarlo_mpi DECK SAMPLES SEED");
  const int count = std::atoi(argv[2]);
  const std::uint64_t seed = std::strtoull(argv[3], nullptr, 10);
  if (count <= 0 || count > 1000000) return fail("SAMPLES must be 1-1000000");

  Deck deck;
  DeckError error;
  if (!load_deck(argv[1], &deck, &error) || deck.cases.size() != 1) {
    return fail(deck.cases.size() > 1 ? "the deck must hold one case" : error.to_string());
  }
  const DeckCase& c = deck.cases.front();
  auto data = std::make_unique<DispersionData>();
  DispersionMappingFault fault;
  if (!fill_dispersion_data(c.extras.dispersions, data.get(), &fault)) return fail(fault.message);
  OptimizationRun run;
  run_optimization(*c.mission, nullptr, &run);
  DispersionNominal nominal;
  std::string kind;
  Status why = Status::kOk;
  if (!final_dispersion_nominal(*c.mission, run, &nominal, &kind, &why)) return fail(status_name(why));

  auto ws = std::make_unique<DispersionWorkspace>();
  DispersedTrajectory nominal_values;
  Status status = prepare_monte_carlo(nominal, ws.get());
  if (ok(status)) {
    status = record_dispersed_trajectory(*nominal.mission, ws->nominal_prepared, ws->nominal, ws->nominal,
                                         nullptr, &nominal_values);
  }
  if (!ok(status)) return fail(status_name(status));

  // This rank's samples, packed in its order; rank 0 puts them back in sample order.
  std::vector<double> mine;
  for (int i = rank; i < count; i += ranks) {
    DispersedTrajectory t;
    (void)fly_monte_carlo_sample(nominal, *data, seed, static_cast<std::uint64_t>(i), nominal_values,
                                 ws.get(), &t);
    mine.resize(mine.size() + kRecord);
    pack(t, mine.data() + mine.size() - kRecord);
  }
  std::vector<int> counts(static_cast<std::size_t>(ranks));
  std::vector<int> offsets(static_cast<std::size_t>(ranks));
  for (int r = 0, at = 0; r < ranks; ++r) {
    const int samples = (count - r + ranks - 1) / ranks;
    counts[static_cast<std::size_t>(r)] = samples * kRecord;
    offsets[static_cast<std::size_t>(r)] = at;
    at += samples * kRecord;
  }
  std::vector<double> all(rank == 0 ? static_cast<std::size_t>(count) * kRecord : 0);
  MPI_Gatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(), counts.data(),
              offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (rank == 0) {
    MonteCarloSamples samples;
    samples.status = Status::kOk;
    samples.nominal = nominal_values;
    samples.samples.assign(static_cast<std::size_t>(count), DispersedTrajectory{});
    for (int r = 0; r < ranks; ++r) {
      const double* block = all.data() + offsets[static_cast<std::size_t>(r)];
      for (int i = r, n = 0; i < count; i += ranks, ++n) {
        unpack(block + static_cast<std::ptrdiff_t>(n) * kRecord,
               &samples.samples[static_cast<std::size_t>(i)]);
      }
    }
    std::cout << monte_carlo_json(samples, seed, kind).dump(1) << '\n';
  }
  MPI_Finalize();
  return 0;
}
