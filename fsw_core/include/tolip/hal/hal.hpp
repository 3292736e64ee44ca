// Hardware abstraction of the guidance computer (docs/hil.md): what the flight application touches
// each minor cycle, as plain structs of a context pointer and function pointers.
//
// Why function pointers and not virtual functions or templates: a port is bound once, at start-up,
// to a static instance (the bench's simulated hardware on the host, a driver on the target); the
// call costs one indirect branch, needs no RTTI and no vtable, keeps the flight application one
// non-template translation unit that builds identically for the host and the Cortex-M7, and lets a
// test swap one port (a failing sensor, a refusing actuator) without touching the others. Nothing
// here allocates; every port's storage belongs to its implementation.
//
// Every call returns a tolip::Status. kOk: the call did what it says. Anything else: it did not,
// and the flight application's defined reaction is given with each port (docs/hil.md, "Failed
// calls").
#pragma once

#include <cstddef>
#include <cstdint>

#include "tolip/core/status.hpp"

namespace tolip::hal {

inline constexpr double kDefaultMinorCycleHz = 50.0;

// ---- minor-cycle clock ---------------------------------------------------------------------------
// wait_next_cycle blocks until the start of the next minor cycle and gives its index, counted from
// lift-off (cycle 0 starts at lift-off; the time since lift-off is cycle x period_s). A failure
// (kHalClockOverrun: the previous cycle ran past its frame) is counted; the cycle still runs with
// the index the clock gave.
struct ClockPort {
  void* context = nullptr;
  Status (*wait_next_cycle)(void* context, std::uint32_t* cycle) = nullptr;
  double period_s = 1.0 / kDefaultMinorCycleHz;
};

// ---- inertial platform ---------------------------------------------------------------------------
// Attitude of the missile's thrust axis in the platform frame (theta, chi as the guidance table
// uses them) and the body rates about the pitch and yaw axes. A failure (kHalSensorInvalid: no
// valid sample this cycle) makes the application propagate the last good attitude with the last good
// rates; after kMaxPlatformDropoutCycles consecutive failures it commands neutral actuators.
struct PlatformSample {
  double theta_rad = 0.0;
  double chi_rad = 0.0;
  double pitch_rate_rad_s = 0.0;  // d theta / dt
  double yaw_rate_rad_s = 0.0;    // d chi / dt
};
struct InertialPlatformPort {
  void* context = nullptr;
  Status (*read)(void* context, PlatformSample* sample) = nullptr;
};

// ---- actuators -----------------------------------------------------------------------------------
// Stage 1: fins and jet vanes, a deflection in rad (limited by the application to the table's
// maximum deflection). Stages 2-3 (and continuous upper stages): the control jets, a fraction of full
// jet force in [-1, 1] (the deflection command over the table's maximum deflection; the jets are
// pulse-width modulated over the minor cycle). Spun stages and coasts with zero gains: kNone, no
// command. A failure (kHalActuatorRejected) is counted; the application repeats the command the
// next cycle.
enum class ActuatorKind : std::uint8_t { kNone = 0, kFinsAndVanes = 1, kControlJets = 2 };
struct ActuatorCommand {
  ActuatorKind kind = ActuatorKind::kNone;
  double pitch = 0.0;  // rad (fins) or fraction of full force (jets); > 0 noses up
  double yaw = 0.0;    // rad or fraction; > 0 increases chi
};
struct ActuatorPort {
  void* context = nullptr;
  Status (*command)(void* context, const ActuatorCommand& command) = nullptr;
};

// ---- non-volatile table store --------------------------------------------------------------------
// read copies the stored table image (at most `capacity` bytes) into `buffer` and gives its size.
// Called at boot and when an upload is announced, between cycles. A failure (kHalTableStoreFailed)
// leaves the active table in force; the image read is always validated by the loader, whose
// rejection also leaves the active table in force.
struct TableStorePort {
  void* context = nullptr;
  Status (*read)(void* context, std::uint8_t* buffer, std::size_t capacity, std::size_t* size) = nullptr;
};

// ---- stage discretes -----------------------------------------------------------------------------
// The sequencer's latched discretes: the stage code in force (1-5 after ignition of that stage,
// 6-10 after its burnout and separation), spin-up done (spun upper stage), and a sequence number
// that changes whenever a discrete changed. A failure (kHalDiscretesInvalid) keeps the stage in
// force; a stage code out of flight order is refused by the executor and counted.
struct StageDiscretes {
  int stage_code = 1;
  bool spun_up = false;
  std::uint32_t sequence = 0;
};
struct DiscretesPort {
  void* context = nullptr;
  Status (*read)(void* context, StageDiscretes* discretes) = nullptr;
};

// ---- telemetry -----------------------------------------------------------------------------------
// One frame per minor cycle, after the actuators were commanded. A failure (kHalTelemetryFailed)
// is counted and the frame dropped: telemetry never holds the cycle up.
struct TelemetryFrame {
  std::uint32_t cycle = 0;
  double time_s = 0.0;
  int stage_code = 1;
  int guidance_mode = 0;  // tolip::GuidanceMode
  double theta_command_rad = 0.0;
  double chi_command_rad = 0.0;
  double theta_measured_rad = 0.0;
  double chi_measured_rad = 0.0;
  double pitch_rate_rad_s = 0.0;
  double yaw_rate_rad_s = 0.0;
  double k_theta = 0.0;
  double k_q_s = 0.0;
  ActuatorKind actuator = ActuatorKind::kNone;
  double pitch_command = 0.0;
  double yaw_command = 0.0;
  bool saturated = false;
  bool platform_valid = true;
  std::uint32_t table_crc = 0;
  std::uint32_t fault_count = 0;  // all failed calls since boot
};
struct TelemetryPort {
  void* context = nullptr;
  Status (*emit)(void* context, const TelemetryFrame& frame) = nullptr;
};

// All ports of one guidance computer.
struct Ports {
  ClockPort clock;
  InertialPlatformPort platform;
  ActuatorPort actuators;
  TableStorePort table_store;
  DiscretesPort discretes;
  TelemetryPort telemetry;
};

// True when every function pointer is set and the clock period is positive and finite.
bool ports_complete(const Ports& ports);

}  // namespace tolip::hal
