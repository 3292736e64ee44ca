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
    default: return false;  // thrust tables, C_M_alpha tables, winds: not sampled (monte_carlo.hpp)
  }
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

Status build_monte_carlo_case(const DispersionNominal& nominal, const PreparedCase& nominal_prepared,
                              const DispersionData& data, std::uint64_t seed, std::uint64_t sample,
                              DispersionWorkspace* ws) {
  ws->mission = *nominal.mission;
  ws->perturbation = FlightPerturbation{};
  ws->program_mapped = false;
  Mission& m = ws->mission;
  FlightPerturbation& p = ws->perturbation;
  bool prepares = false;
  double drag_fraction = 0.0;
  for (int k = 0; k < data.count; ++k) {
    const DispersionSource& s = data.sources[k];
    DispersionCodeInfo info;
    if (!dispersion_code_info(s.code, &info)) return Status::kDispersionCodeInvalid;
    if (!monte_carlo_draws_source(nominal, data, k)) continue;
    const int leader = family_leader(s.code);
    const double z =
        counter_normal(seed, sample, static_cast<std::uint32_t>(leader)) / 3.0;  // 3 sigma -> 1 sigma
    const int stage = (info.kind == DispersionKind::kTipoff) ? s.stage : info.stage;
    const bool yaw = info.plane == DispersionPlane::kYaw;
    switch (info.kind) {
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
      default: break;  // not drawn (monte_carlo_draws_source)
    }
  }
  if (drag_fraction != 0.0) {
    if (!(std::fabs(drag_fraction) < 1.0)) return Status::kValueOutOfRange;
    for (StageData& stage_data : m.vehicle.stages) {
      AeroTable& cd = stage_data.drag_coefficient;
      for (int i = 0; i < cd.size(); ++i) cd.set_y(i, cd.y(i) * (1.0 + drag_fraction));
      if (!cd.empty()) {
        const Status status = cd.finalize();
        if (!ok(status)) return status;
      }
    }
  }
  if (prepares) return prepare_case(m, &ws->prepared);
  ws->prepared = nominal_prepared;
  return Status::kOk;
}

Status prepare_monte_carlo(const DispersionNominal& nominal, DispersionWorkspace* ws) {
  if (nominal.mission == nullptr) return Status::kNotPrepared;
  Status status = prepare_case(*nominal.mission, &ws->nominal_prepared);
  if (!ok(status)) return status;
  FlightInputs inputs;
  inputs.program = nominal.program;
  inputs.body_dynamics = nominal.body_dynamics;
  return fly_trajectory(*nominal.mission, ws->nominal_prepared, inputs, &ws->nominal);
}

Status fly_monte_carlo_sample(const DispersionNominal& nominal, const DispersionData& data,
                              std::uint64_t seed, std::uint64_t sample,
                              const DispersedTrajectory& nominal_values, DispersionWorkspace* ws,
                              DispersedTrajectory* out) {
  *out = DispersedTrajectory{};
  Status status = build_monte_carlo_case(nominal, ws->nominal_prepared, data, seed, sample, ws);
  if (ok(status)) {
    FlightInputs inputs;
    inputs.program = nominal.program;
    inputs.body_dynamics = nominal.body_dynamics;
    inputs.perturbation = &ws->perturbation;
    status = fly_trajectory(ws->mission, ws->prepared, inputs, &ws->dispersed);
  }
  if (ok(status))
    status = record_dispersed_trajectory(ws->mission, ws->prepared, ws->nominal, ws->dispersed, nullptr, out);
  out->status = status;
  if (!ok(status)) return status;
  for (int j = 0; j < kMaxStagingPoints; ++j) {
    for (int i = 0; i < kStagingVariables; ++i)
      out->dispersions[j][i] = out->values[j][i] - nominal_values.values[j][i];
  }
  for (int i = 0; i < kOrbitDispersionElements; ++i) {
    const double d = out->orbit[i] - nominal_values.orbit[i];
    out->orbit_dispersions[i] = (i >= 3) ? std::remainder(d, 2.0 * kPi) : d;
  }
  return Status::kOk;
}

}  // namespace tolip
