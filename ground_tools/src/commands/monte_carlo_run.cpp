// Monte Carlo samples on threads (tolip_ground/monte_carlo_run.hpp).
#include "tolip_ground/monte_carlo_run.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>

#include "tolip/core/constants.hpp"

namespace tolip::ground {

Status run_monte_carlo(const DispersionNominal& nominal, const DispersionData& data, std::uint64_t seed,
                       int count, int threads, MonteCarloSamples* out) {
  out->samples.assign(static_cast<std::size_t>(std::max(count, 0)), DispersedTrajectory{});
  const int workers = std::max(1, std::min(threads, std::max(count, 1)));
  std::vector<std::unique_ptr<DispersionWorkspace>> workspaces;
  for (int t = 0; t < workers; ++t) {
    workspaces.push_back(std::make_unique<DispersionWorkspace>());
    const Status status = prepare_monte_carlo(nominal, workspaces.back().get());
    if (!ok(status)) return out->status = status;
  }
  DispersionWorkspace& first = *workspaces.front();
  out->nominal = DispersedTrajectory{};
  Status status = record_dispersed_trajectory(*nominal.mission, first.nominal_prepared, first.nominal,
                                              first.nominal, nullptr, &out->nominal);
  out->nominal.status = status;
  if (!ok(status)) return out->status = status;
  // Sample i on worker i mod K: which worker flies a sample does not change it (counter draws).
  const auto work = [&](int worker) {
    for (int i = worker; i < count; i += workers) {
      (void)fly_monte_carlo_sample(nominal, data, seed, static_cast<std::uint64_t>(i), out->nominal,
                                   workspaces[static_cast<std::size_t>(worker)].get(),
                                   &out->samples[static_cast<std::size_t>(i)]);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& thread : pool) thread.join();
  return out->status = Status::kOk;
}

MonteCarloStatistic monte_carlo_statistic(const MonteCarloSamples& samples, int column,
                                          StagingVariable variable) {
  MonteCarloStatistic s;
  std::vector<double> values;
  const int i = static_cast<int>(variable);
  for (const DispersedTrajectory& t : samples.samples) {
    if (ok(t.status)) values.push_back(t.dispersions[column][i]);
  }
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

nlohmann::ordered_json monte_carlo_json(const MonteCarloSamples& samples, std::uint64_t seed,
                                        const std::string& kind) {
  struct Variable {
    StagingVariable variable;
    const char* key;
    double scale;
  };
  const Variable variables[] = {{StagingVariable::kAltitude, "altitude_ft", 1.0},
                                {StagingVariable::kVelocity, "velocity_ft_s", 1.0},
                                {StagingVariable::kFlightPathAngle, "flight_path_angle_deg", 180.0 / kPi},
                                {StagingVariable::kDownrange, "downrange_nmi", 1.0},
                                {StagingVariable::kCrossrange, "crossrange_nmi", 1.0}};
  int final_column = 0;
  for (int j = 0; j < kMaxStagingPoints; ++j) {
    if (samples.nominal.values[j][0] != 0.0) final_column = j;  // the last column flown
  }
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  out["seed"] = seed;
  out["samples"] = samples.samples.size();
  nlohmann::ordered_json final_point = nlohmann::ordered_json::object();
  int flown = 0;
  for (const Variable& v : variables) {
    const MonteCarloStatistic s = monte_carlo_statistic(samples, final_column, v.variable);
    flown = s.count;
    final_point[v.key] = {{"mean", s.mean * v.scale},
                          {"standard_deviation", s.standard_deviation * v.scale},
                          {"p00135", s.p00135 * v.scale},
                          {"p50", s.p50 * v.scale},
                          {"p99865", s.p99865 * v.scale}};
  }
  out["flown"] = flown;
  out["nominal_kind"] = kind;
  out["final_point"] = std::move(final_point);
  return out;
}

}  // namespace tolip::ground
