// Monte Carlo samples on threads (tolip_ground/monte_carlo_run.hpp).
#include "tolip_ground/monte_carlo_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

namespace tolip::ground {

Status run_monte_carlo(const DispersionNominal& nominal, const DispersionData& data, std::uint64_t seed,
                       int count, int threads, MonteCarloSamples* out, const MonteCarloProgress& progress,
                       const MonteCarloImpactRequest& impacts) {
  out->samples.assign(static_cast<std::size_t>(std::max(count, 0)), DispersedTrajectory{});
  const bool with_impacts = impacts.data != nullptr;
  out->impact_request = impacts;
  out->nominal_impacts = MonteCarloImpacts{};
  out->impacts.assign(with_impacts ? static_cast<std::size_t>(std::max(count, 0)) : 0u, MonteCarloImpacts{});
  const int workers = std::max(1, std::min(threads, std::max(count, 1)));
  // Worker 0's workspaces are made here: the nominal's record, which every sample's dispersions are
  // taken against, comes from them. The other workers make and prepare their own on their threads
  // (about 2 ms each, most of it the workspaces' first touch), while worker 0 already flies.
  std::vector<std::unique_ptr<DispersionWorkspace>> workspaces(static_cast<std::size_t>(workers));
  std::vector<std::unique_ptr<ImpactWorkspace>> impact_workspaces(static_cast<std::size_t>(workers));
  std::vector<Status> prepared(static_cast<std::size_t>(workers), Status::kOk);
  const auto make_workspaces = [&](int worker) {
    const std::size_t w = static_cast<std::size_t>(worker);
    workspaces[w] = std::make_unique<DispersionWorkspace>();
    impact_workspaces[w] = std::make_unique<ImpactWorkspace>();
    prepared[w] = prepare_monte_carlo(nominal, data, workspaces[w].get());
    return prepared[w];
  };
  Status status = make_workspaces(0);
  if (!ok(status)) return out->status = status;
  DispersionWorkspace& first = *workspaces.front();
  out->nominal = DispersedTrajectory{};
  status = record_dispersed_trajectory(*nominal.mission, first.nominal_prepared, first.nominal, first.nominal,
                                       nullptr, &out->nominal);
  out->nominal.status = status;
  if (!ok(status)) return out->status = status;
  if (with_impacts) {
    (void)fly_monte_carlo_casings(nominal, impacts, *nominal.mission, first.nominal_prepared, first.nominal,
                                  impact_workspaces.front().get(), &out->nominal_impacts);
  }
  // Each worker takes the next sample not yet taken, so that a worker on a slower or busier core
  // flies fewer samples instead of holding up the rest (a fixed split, sample i on worker i mod K,
  // waits for the slowest core). Which worker flies a sample does not change it: its draws are
  // counter-based and its workspace's earlier samples leave nothing it reads
  // (MonteCarlo.ASampleIsTheSameWhateverItsWorkspaceFlewBeforeIt).
  std::atomic<int> next{0};
  std::atomic<int> flown{0};
  const auto work = [&](int worker) {
    const std::size_t w = static_cast<std::size_t>(worker);
    if (worker > 0 && !ok(make_workspaces(worker))) return;  // reported after the join
    DispersionWorkspace* ws = workspaces[w].get();
    for (int i = next.fetch_add(1, std::memory_order_relaxed); i < count;
         i = next.fetch_add(1, std::memory_order_relaxed)) {
      const std::size_t at = static_cast<std::size_t>(i);
      const Status sample = fly_monte_carlo_sample(nominal, data, seed, static_cast<std::uint64_t>(i),
                                                   out->nominal, ws, &out->samples[at]);
      if (with_impacts && ok(sample)) {
        (void)fly_monte_carlo_casings(nominal, impacts, ws->mission, ws->prepared, ws->dispersed,
                                      impact_workspaces[w].get(), &out->impacts[at]);
      }
      flown.fetch_add(1, std::memory_order_relaxed);
    }
  };
  std::vector<std::thread> pool;
  for (int t = progress ? 0 : 1; t < workers; ++t) pool.emplace_back(work, t);
  if (progress) {
    // Worker 0's workspaces are prepared, so it flies whatever the others do not take: the count
    // is reached even when another worker could not prepare.
    while (flown.load(std::memory_order_relaxed) < count) {
      progress(flown.load(std::memory_order_relaxed), count);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  } else {
    work(0);
  }
  for (std::thread& thread : pool) thread.join();
  // The same preparation as worker 0's cannot fail otherwise; if it did, it is said.
  for (int t = 1; t < workers; ++t) {
    if (!ok(prepared[static_cast<std::size_t>(t)]))
      return out->status = prepared[static_cast<std::size_t>(t)];
  }
  if (progress) progress(count, count);
  return out->status = Status::kOk;
}

MonteCarloStatistic statistic_of(std::vector<double> values) {
  MonteCarloStatistic s;
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
               values.end());
  s.count = static_cast<int>(values.size());
  if (values.empty()) return s;
  double sum = 0.0;
  for (double v : values) sum += v;
  s.mean = sum / s.count;
  double squares = 0.0;
  for (double v : values) squares += (v - s.mean) * (v - s.mean);
  s.standard_deviation = (s.count > 1) ? std::sqrt(squares / (s.count - 1)) : 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = [&](double fraction) {
    const int k = static_cast<int>(std::ceil(fraction * s.count)) - 1;
    return values[static_cast<std::size_t>(std::clamp(k, 0, s.count - 1))];
  };
  s.p00135 = rank(0.00135);
  s.p50 = rank(0.5);
  s.p99865 = rank(0.99865);
  return s;
}

MonteCarloStatistic monte_carlo_statistic(const MonteCarloSamples& samples, int column,
                                          StagingVariable variable) {
  std::vector<double> values;
  const int i = static_cast<int>(variable);
  for (const DispersedTrajectory& t : samples.samples) {
    if (ok(t.status)) values.push_back(t.dispersions[column][i]);
  }
  return statistic_of(std::move(values));
}

}  // namespace tolip::ground
