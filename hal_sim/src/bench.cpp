// The HIL bench loop (bench.hpp, docs/hil.md).
#include "tolip_hal_sim/bench.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "plant.hpp"
#include "tolip/hal/linked_flight_computer.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip_hal_sim/link.hpp"

namespace tolip::sim {

namespace {

// The plant side of the link for one run: the frames it sends and receives, the fault injection.
struct Hardware {
  Plant* plant = nullptr;
  const BenchConfig* config = nullptr;
  BenchResult* result = nullptr;
  double dt = 0.02;
  std::uint32_t cycle = 0;
  // Sensor link: the plant side writes the cycle's frame (size 0: lost).
  std::uint8_t sensor_bytes[kSensorFrameSize] = {};
  std::size_t sensor_size = kSensorFrameSize;
  bool platform_dropout = false;
  std::uint32_t discrete_sequence = 0;
  int last_stage_code = 1;
  // Actuator link: the flight side writes the frame, the plant side decodes it.
  std::uint8_t actuator_bytes[kActuatorFrameSize] = {};
  std::uint32_t actuator_sequence = 0;
  hal::ActuatorCommand last_good_command;
  // Truth at the cycle start, for the telemetry record.
  PlantTruth truth;
};

bool link_fault(const Hardware& hw, std::uint32_t sequence) {
  const BenchConfig& c = *hw.config;
  if (c.scenario != Scenario::kLinkLoss && c.scenario != Scenario::kLinkCorruption) return false;
  if (static_cast<double>(hw.cycle) * hw.dt + 1e-9 < c.fault_time_s) return false;
  return c.link_fault_period > 0 && sequence % static_cast<std::uint32_t>(c.link_fault_period) == 0;
}

// The guidance computer in process: the link's flight end called directly with the frames' bytes.
class InProcessFlight final : public FlightLink {
 public:
  explicit InProcessFlight(double period_s) : computer_(period_s) {}
  Status upload(const std::uint8_t* image, std::size_t size) override {
    return computer_.upload(image, size);
  }
  Status cycle(const std::uint8_t* sensor, std::size_t size, std::uint8_t* actuator,
               hal::TelemetryFrame* telemetry) override {
    (void)computer_.run_cycle(sensor, size, actuator, telemetry);  // its faults are in its counters
    return Status::kOk;
  }
  Status finish(hal::LinkReport* report) override {
    *report = computer_.report(0, Status::kOk);
    return Status::kOk;
  }

 private:
  hal::LinkedFlightComputer computer_;
};

// The telemetry record of the cycle: the flight side's frame and the plant's truth.
void record_telemetry(const Hardware& hw, const hal::TelemetryFrame& frame) {
  BenchResult& r = *hw.result;
  if (r.telemetry.size() >= r.telemetry.capacity()) return;  // never grows
  TelemetryRecord record;
  record.frame = frame;
  record.theta_true_rad = hw.plant->theta_rad();
  record.chi_true_rad = hw.plant->chi_rad();
  record.alpha_rad = hw.truth.alpha_rad;
  record.beta_rad = hw.truth.beta_rad;
  record.dynamic_pressure_lbf_ft2 = hw.truth.dynamic_pressure_lbf_ft2;
  record.altitude_ft = hw.truth.altitude_ft;
  record.velocity_ft_s = hw.truth.velocity_ft_s;
  record.fin_pitch_rad = hw.plant->fin_pitch();
  record.fin_yaw_rad = hw.plant->fin_yaw();
  r.telemetry.push_back(record);
}

// The plant side of the cycle's sensor frame: truth plus bias and noise, then the link.
void send_sensor_frame(Hardware& hw, NoiseSource& noise, const double bias[4]) {
  const Plant& p = *hw.plant;
  const BenchConfig& c = *hw.config;
  SensorFrame frame;
  frame.sequence = hw.cycle;
  frame.sample.theta_rad = p.theta_rad() + bias[0] + c.attitude_noise_rad * noise.normal();
  frame.sample.chi_rad = p.chi_rad() + bias[1] + c.attitude_noise_rad * noise.normal();
  frame.sample.pitch_rate_rad_s = p.pitch_rate_rad_s() + bias[2] + c.rate_noise_rad_s * noise.normal();
  frame.sample.yaw_rate_rad_s = p.yaw_rate_rad_s() + bias[3] + c.rate_noise_rad_s * noise.normal();
  const int code = p.stage_code();
  if (code != hw.last_stage_code) {
    hw.last_stage_code = code;
    ++hw.discrete_sequence;
  }
  frame.discretes.stage_code = code;
  frame.discretes.spun_up = p.spun();
  frame.discretes.sequence = hw.discrete_sequence;
  frame.platform_invalid = hw.platform_dropout;
  encode_sensor_frame(frame, hw.sensor_bytes);
  hw.sensor_size = kSensorFrameSize;
  ++hw.result->sensor_link.frames_sent;
  if (link_fault(hw, frame.sequence)) {
    if (c.scenario == Scenario::kLinkLoss) {
      hw.sensor_size = 0;
    } else {
      hw.sensor_bytes[10] ^= 0x10;
    }
  }
}

// The plant side of the actuator frame: a frame that fails holds the last good command.
hal::ActuatorCommand receive_actuator_frame(Hardware& hw) {
  BenchResult& r = *hw.result;
  ++r.actuator_link.frames_sent;
  const std::uint32_t sequence = hw.actuator_sequence++;
  if (link_fault(hw, sequence + 7)) {  // offset: not the same cycles as the sensor faults
    if (hw.config->scenario == Scenario::kLinkLoss) {
      ++r.actuator_link.frames_lost;
      return hw.last_good_command;
    }
    hw.actuator_bytes[12] ^= 0x01;
  }
  ActuatorFrame frame;
  if (!ok(decode_actuator_frame(hw.actuator_bytes, kActuatorFrameSize, &frame)) ||
      frame.sequence != sequence) {
    ++r.actuator_link.frames_corrupt;
    return hw.last_good_command;
  }
  hw.last_good_command = frame.command;
  return frame.command;
}

double uniform_bias(NoiseSource& noise, double limit) { return limit * (2.0 * noise.uniform() - 1.0); }

}  // namespace

std::size_t bench_cycle_capacity(const BenchInputs& inputs, const BenchConfig& config) {
  double end_s = 0.0;
  double shift_s = 0.0;
  const PreparedCase& p = *inputs.prepared;
  for (int i = 0; i < p.stage_count; ++i) {
    const StageTimeline& line = p.timeline[i];
    if (config.scenario == Scenario::kLateIgnition && line.code == config.late_stage)
      shift_s += config.late_ignition_s;
    if (line.code >= 1 && line.code <= 5) end_s = line.start_s + line.duration_s + shift_s;
  }
  return static_cast<std::size_t>(std::ceil(end_s * config.cycle_hz)) + 2;
}

struct BenchSession::Impl {
  BenchInputs inputs;
  BenchConfig config;
  BenchResult* result = nullptr;
  Plant plant;
  Hardware hw;
  std::unique_ptr<InProcessFlight> in_process;
  FlightLink* flight = nullptr;
  std::uint8_t bad_upload[kTableImageSize] = {};
  std::size_t bad_size = 0;
  bool upload_fault = false;
  NoiseSource noise{1};
  double bias[4] = {};
};

BenchSession::BenchSession() : impl_(std::make_unique<Impl>()) {}
BenchSession::~BenchSession() = default;

Status BenchSession::prepare(const BenchInputs& inputs, const BenchConfig& config, BenchResult* result) {
  Impl& s = *impl_;
  BenchResult& r = *result;
  r = BenchResult();
  s.result = result;
  s.inputs = inputs;
  s.config = config;
  if (inputs.mission == nullptr || inputs.prepared == nullptr || inputs.hardover == nullptr ||
      inputs.table == nullptr || !(config.cycle_hz > 0.0) || !std::isfinite(config.cycle_hz)) {
    r.status = Status::kHalPortMissing;
    return r.status;
  }
  r.telemetry.reserve(bench_cycle_capacity(inputs, config));
  const Status status = s.plant.init(inputs, s.config);
  if (!ok(status)) {
    r.status = status;
    return status;
  }
  Hardware& hw = s.hw;
  hw = Hardware();
  hw.plant = &s.plant;
  hw.config = &s.config;
  hw.result = &r;
  hw.dt = 1.0 / config.cycle_hz;
  s.in_process.reset();
  if (inputs.flight != nullptr) {
    s.flight = inputs.flight;
  } else {
    s.in_process = std::make_unique<InProcessFlight>(hw.dt);
    s.flight = s.in_process.get();
  }

  // The corrupted or truncated upload of the upload scenarios, prepared before the run.
  s.bad_size = 0;
  if (inputs.table_size == kTableImageSize) {
    std::memcpy(s.bad_upload, inputs.table, kTableImageSize);
    if (config.scenario == Scenario::kCorruptUpload) {
      s.bad_upload[kOffsetSegments + 17] ^= 0x04;  // one bit of a segment's theta
      s.bad_size = kTableImageSize;
    } else if (config.scenario == Scenario::kTruncatedUpload) {
      s.bad_size = 800;
    }
  }
  s.upload_fault =
      config.scenario == Scenario::kCorruptUpload || config.scenario == Scenario::kTruncatedUpload;
  s.noise = NoiseSource(config.seed);
  s.bias[0] = uniform_bias(s.noise, config.attitude_bias_rad);
  s.bias[1] = uniform_bias(s.noise, config.attitude_bias_rad);
  s.bias[2] = uniform_bias(s.noise, config.rate_bias_rad_s);
  s.bias[3] = uniform_bias(s.noise, config.rate_bias_rad_s);
  return Status::kOk;
}

Status BenchSession::fly() {
  Impl& s = *impl_;
  BenchResult& r = *s.result;
  if (s.flight == nullptr) return r.status;
  const BenchConfig& config = s.config;
  Plant* plant = &s.plant;
  Hardware* hw = &s.hw;
  FlightLink* flight = s.flight;
  bool uploaded = false;
  Status status = Status::kOk;

  r.boot_status = flight->upload(s.inputs.table, s.inputs.table_size);
  if (!ok(r.boot_status)) {
    r.status = r.boot_status;
    return r.status;
  }

  const double dt = hw->dt;
  const std::uint32_t dropout_start =
      static_cast<std::uint32_t>(std::llround(config.fault_time_s * config.cycle_hz));
  double pitch_sq = 0.0, yaw_sq = 0.0;
  std::uint32_t limited_cycles = 0;
  const double liftoff_s = s.inputs.mission->launch.liftoff_duration_s;
  hal::TelemetryFrame f;
  for (std::uint32_t k = 0;; ++k) {
    if (plant->finished() || plant->lost()) break;
    if (config.duration_s > 0.0 && static_cast<double>(k) * dt >= config.duration_s - 1e-9) {
      r.truncated = true;
      break;
    }
    hw->cycle = k;
    hw->truth = plant->truth();
    hw->platform_dropout = config.scenario == Scenario::kSensorDropout && k >= dropout_start &&
                           k < dropout_start + static_cast<std::uint32_t>(config.dropout_cycles);
    send_sensor_frame(*hw, s.noise, s.bias);
    status = flight->cycle(hw->sensor_bytes, hw->sensor_size, hw->actuator_bytes, &f);
    if (!ok(status)) break;
    record_telemetry(*hw, f);
    const hal::ActuatorCommand command = receive_actuator_frame(*hw);
    plant->command_actuators(command, dt);
    if (!r.telemetry.empty()) {
      TelemetryRecord& rec = r.telemetry.back();
      rec.fin_pitch_rad = plant->fin_pitch();
      rec.fin_yaw_rad = plant->fin_yaw();
      rec.actuator_limited = plant->actuator_limited();
    }

    // Statistics of the cycle.
    const double t = static_cast<double>(k) * dt;
    const int code = plant->stage_code();
    if (t >= liftoff_s && code >= 1 && code <= 3 && (f.k_theta != 0.0 || f.k_q_s != 0.0)) {
      const double ep = f.theta_command_rad - plant->theta_rad();
      const double ey = f.chi_command_rad - plant->chi_rad();
      pitch_sq += ep * ep;
      yaw_sq += ey * ey;
      if (std::fabs(ep) > r.pitch_error_max_rad) r.pitch_error_max_rad = std::fabs(ep);
      if (std::fabs(ey) > r.yaw_error_max_rad) r.yaw_error_max_rad = std::fabs(ey);
      ++r.tracked_cycles;
    }
    const double qbar_alpha =
        hw->truth.dynamic_pressure_lbf_ft2 * std::hypot(hw->truth.alpha_rad, hw->truth.beta_rad);
    if (qbar_alpha > r.peak_qbar_alpha_lbf_rad_ft2) {
      r.peak_qbar_alpha_lbf_rad_ft2 = qbar_alpha;
      r.peak_qbar_alpha_time_s = t;
    }
    if (plant->actuator_limited()) ++limited_cycles;

    // Uploads run between cycles.
    if (s.upload_fault && !uploaded && t + 1e-9 >= config.fault_time_s) {
      uploaded = true;
      r.upload_status = flight->upload(s.bad_upload, s.bad_size);
    }

    status = plant->advance(static_cast<double>(k + 1) * dt);
    if (!ok(status)) break;
  }
  hal::LinkReport report;
  const Status finished = flight->finish(&report);
  if (ok(status)) status = finished;
  r.status = status;
  r.vehicle_lost = plant->lost();
  r.completed = plant->finished() && ok(status);
  r.end_time_s = plant->time_s();
  r.final_stage = plant->stage_code();
  r.burnout_state = plant->state();
  r.burnout_weight_lb = plant->weight_lb();
  r.burnout_altitude_ft = plant->truth().altitude_ft;
  r.orbit_status = compute_orbit_elements(s.inputs.mission->constants, r.burnout_state,
                                          s.inputs.mission->launch.launch_space_age_date_days, &r.orbit);
  if (r.tracked_cycles > 0) {
    r.pitch_error_rms_rad = std::sqrt(pitch_sq / r.tracked_cycles);
    r.yaw_error_rms_rad = std::sqrt(yaw_sq / r.tracked_cycles);
  }
  r.actuator_saturation_s = limited_cycles * dt;
  r.table_crc = report.table_crc;
  r.flight = report.counters;
  r.sensor_link.frames_lost = report.sensor_frames_missing;
  r.sensor_link.frames_corrupt = report.sensor_frames_rejected;
  return r.status;
}

Status run_bench(const BenchInputs& inputs, const BenchConfig& config, BenchResult* result) {
  BenchSession session;
  const Status prepared = session.prepare(inputs, config, result);
  if (!ok(prepared)) return prepared;
  return session.fly();
}

std::string telemetry_csv(const BenchResult& result) {
  std::string out =
      "cycle,time_s,stage,mode,theta_cmd_deg,theta_meas_deg,theta_true_deg,chi_cmd_deg,chi_meas_deg,chi_true_"
      "deg,"
      "pitch_rate_deg_s,yaw_rate_deg_s,k_theta,k_q_s,actuator,pitch_cmd,yaw_cmd,pitch_pos,yaw_pos,saturated,"
      "limited,platform_valid,alpha_deg,beta_deg,qbar_lbf_ft2,altitude_ft,velocity_ft_s,table_crc,faults\n";
  constexpr double d = 57.295779513082320876798;
  char line[1024];
  for (const TelemetryRecord& rec : result.telemetry) {
    const hal::TelemetryFrame& f = rec.frame;
    std::snprintf(
        line, sizeof line,
        "%u,%.17g,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%.17g,%.17g,"
        "%.17g,%d,%d,%d,%.17g,%.17g,%.17g,%.17g,%.17g,0x%08X,%u\n",
        static_cast<unsigned>(f.cycle), f.time_s, f.stage_code, f.guidance_mode, f.theta_command_rad * d,
        f.theta_measured_rad * d, rec.theta_true_rad * d, f.chi_command_rad * d, f.chi_measured_rad * d,
        rec.chi_true_rad * d, f.pitch_rate_rad_s * d, f.yaw_rate_rad_s * d, f.k_theta, f.k_q_s,
        static_cast<int>(f.actuator), f.pitch_command, f.yaw_command, rec.fin_pitch_rad, rec.fin_yaw_rad,
        f.saturated ? 1 : 0, rec.actuator_limited ? 1 : 0, f.platform_valid ? 1 : 0, rec.alpha_rad * d,
        rec.beta_rad * d, rec.dynamic_pressure_lbf_ft2, rec.altitude_ft, rec.velocity_ft_s,
        static_cast<unsigned>(f.table_crc), static_cast<unsigned>(f.fault_count));
    out += line;
  }
  return out;
}

}  // namespace tolip::sim
