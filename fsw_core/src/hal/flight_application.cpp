// The flight application's minor cycle (docs/hil.md).
#include "tolip/hal/flight_application.hpp"

#include <cmath>

#include "tolip/core/stage_codes.hpp"

namespace tolip::hal {

bool ports_complete(const Ports& p) {
  return p.clock.wait_next_cycle != nullptr && p.platform.read != nullptr && p.actuators.command != nullptr &&
         p.table_store.read != nullptr && p.discretes.read != nullptr && p.telemetry.emit != nullptr &&
         std::isfinite(p.clock.period_s) && p.clock.period_s > 0.0;
}

namespace {

// The powered stage that follows a coast in the flight order (coast 6 -> 2, ..., 9 -> 5); 0 otherwise.
int stage_after_coast(int code) { return code >= 6 && code <= 9 ? code - 4 : 0; }

}  // namespace

Status FlightApplication::boot() {
  if (!ports_complete(ports_)) return Status::kHalPortMissing;
  executor_.reset();
  return load_table();
}

Status FlightApplication::load_table() {
  std::size_t size = 0;
  const Status read = ports_.table_store.read(ports_.table_store.context, upload_, sizeof upload_, &size);
  if (!ok(read)) {
    ++counters_.table_rejections;
    return read;
  }
  if (size > sizeof upload_) size = sizeof upload_;
  const Status loaded = service_.load(upload_, size);
  if (!ok(loaded)) {
    ++counters_.table_rejections;
    return loaded;
  }
  ++counters_.table_loads;
  return Status::kOk;
}

Status FlightApplication::run_minor_cycle() {
  Status first = Status::kOk;
  auto note = [&first](Status s) {
    if (ok(first) && !ok(s)) first = s;
  };

  // 1. Clock: the cycle index since lift-off.
  std::uint32_t cycle = counters_.cycles;
  const Status clock = ports_.clock.wait_next_cycle(ports_.clock.context, &cycle);
  if (!ok(clock)) {
    ++counters_.clock_overruns;
    note(clock);
  }
  const double dt = ports_.clock.period_s;
  const double t = static_cast<double>(cycle) * dt;
  ++counters_.cycles;

  // 2. Stage discretes: a new stage code is a stage event at this cycle's time.
  StageDiscretes discretes;
  const Status read_discretes = ports_.discretes.read(ports_.discretes.context, &discretes);
  if (!ok(read_discretes)) {
    ++counters_.discrete_faults;
    note(read_discretes);
  } else if (discretes.sequence != last_discrete_sequence_ ||
             discretes.stage_code != executor_.stage_in_force()) {
    last_discrete_sequence_ = discretes.sequence;
    if (discretes.stage_code != executor_.stage_in_force()) {
      const Status event = executor_.stage_event(discretes.stage_code, t);
      if (!ok(event)) {
        ++counters_.stage_events_refused;
        note(event);
      }
    }
  }

  // 3. Inertial platform; a dropout propagates the last good sample with its rates.
  PlatformSample sample;
  const Status platform = ports_.platform.read(ports_.platform.context, &sample);
  const bool platform_valid = ok(platform) && std::isfinite(sample.theta_rad) &&
                              std::isfinite(sample.chi_rad) && std::isfinite(sample.pitch_rate_rad_s) &&
                              std::isfinite(sample.yaw_rate_rad_s);
  if (platform_valid) {
    last_good_ = sample;
    have_good_sample_ = true;
    dropout_run_ = 0;
  } else {
    ++counters_.platform_dropouts;
    note(ok(platform) ? Status::kHalSensorInvalid : platform);
    ++dropout_run_;
    last_good_.theta_rad += last_good_.pitch_rate_rad_s * dt;
    last_good_.chi_rad += last_good_.yaw_rate_rad_s * dt;
    sample = last_good_;
  }
  const bool neutral = !have_good_sample_ || dropout_run_ > kMaxPlatformDropoutCycles;

  // 4. Guidance: the executor's command and the gains in force.
  GuidanceCommand command;
  const Status guidance = executor_.step(t, &command);
  ActuatorCommand actuators;
  bool saturated = false;
  double theta_c = command.theta_rad;
  double chi_c = command.chi_rad;
  if (!ok(guidance)) {
    ++counters_.guidance_faults;
    note(guidance);
  } else {
    // Before a spun stage, the coast aligns the stack to the attitude the spun stage flies (the
    // spin-up attitude): the coast's own attitude moves no mass point (no thrust), the spun stage
    // cannot turn after spin-up (docs/hil.md, "Spun stages").
    const GuidanceTable* table = service_.active();
    const int next = stage_after_coast(command.stage_code);
    if (table != nullptr && next != 0 && stage_is_spun(table->spin_option, next)) {
      theta_c = next == 4 ? table->stage4_theta_rad : table->stage5_theta_rad;
      chi_c = next == 4 ? table->stage4_chi_rad : table->stage5_chi_rad;
    }
    const bool autopilot = command.k_theta != 0.0 || command.k_q_s != 0.0;
    if (autopilot && !neutral) {
      GuidanceCommand pitch = command;
      pitch.theta_rad = theta_c;
      GuidanceCommand yaw = command;
      yaw.theta_rad = chi_c;
      ControlDeflection dp;
      ControlDeflection dy;
      const Status sp = attitude_control_deflection(pitch, sample.theta_rad, sample.pitch_rate_rad_s, &dp);
      const Status sy = attitude_control_deflection(yaw, sample.chi_rad, sample.yaw_rate_rad_s, &dy);
      if (!ok(sp) || !ok(sy)) {
        ++counters_.guidance_faults;
        note(ok(sp) ? sy : sp);
      }
      saturated = dp.saturated || dy.saturated;
      if (command.stage_code == 1) {
        actuators.kind = ActuatorKind::kFinsAndVanes;
        actuators.pitch = dp.deflection_rad;
        actuators.yaw = dy.deflection_rad;
      } else {
        const double limit = std::fabs(command.max_deflection_rad);
        actuators.kind = ActuatorKind::kControlJets;
        actuators.pitch = limit > 0.0 ? dp.deflection_rad / limit : 0.0;
        actuators.yaw = limit > 0.0 ? dy.deflection_rad / limit : 0.0;
      }
    } else if (autopilot) {
      actuators.kind = command.stage_code == 1 ? ActuatorKind::kFinsAndVanes : ActuatorKind::kControlJets;
      ++counters_.neutral_cycles;
    }
  }
  if (saturated) ++counters_.saturated_cycles;

  // 5. Actuators.
  const Status actuated = ports_.actuators.command(ports_.actuators.context, actuators);
  if (!ok(actuated)) {
    ++counters_.actuator_rejections;
    note(actuated);
  }

  // 6. Telemetry.
  frame_.cycle = cycle;
  frame_.time_s = t;
  frame_.stage_code = executor_.stage_in_force();
  frame_.guidance_mode = static_cast<int>(command.mode);
  frame_.theta_command_rad = theta_c;
  frame_.chi_command_rad = chi_c;
  frame_.theta_measured_rad = sample.theta_rad;
  frame_.chi_measured_rad = sample.chi_rad;
  frame_.pitch_rate_rad_s = sample.pitch_rate_rad_s;
  frame_.yaw_rate_rad_s = sample.yaw_rate_rad_s;
  frame_.k_theta = command.k_theta;
  frame_.k_q_s = command.k_q_s;
  frame_.actuator = actuators.kind;
  frame_.pitch_command = actuators.pitch;
  frame_.yaw_command = actuators.yaw;
  frame_.saturated = saturated;
  frame_.platform_valid = platform_valid;
  frame_.table_crc = service_.active_crc();
  frame_.fault_count = counters_.total_faults();
  const Status sent = ports_.telemetry.emit(ports_.telemetry.context, frame_);
  if (!ok(sent)) {
    ++counters_.telemetry_drops;
    note(sent);
  }
  return first;
}

}  // namespace tolip::hal
