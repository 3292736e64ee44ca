// The hardware-in-the-loop bench (docs/hil.md): the simulated hardware behind the ports of
// tolip/hal/hal.hpp and the loop that flies the flight application (tolip::hal::FlightApplication)
// against it, minor cycle by minor cycle, from lift-off to the final burnout.
//
// The plant is the core's point-mass trajectory (evaluate_flight: the same Earth, atmosphere,
// thrust, weight and Sec. 14 tables; RK4 of the core's integrator) with the flown attitude a state
// of its own: rigid-body pitch and yaw rotation driven by the Sec. 16 / eq. 7-1 moment terms of the
// hardover module (rigid_body_moment: M_delta, M_alpha, pitch and jet damping, misalignment, control
// jets; data blocks 33-37 and 44-45), actuators with position and rate limits, spun upper stages.
// Sensors add seeded noise and bias. Sensor and actuator data cross a CRC-protected frame link
// (link.hpp), in process here, a serial port in the processor-in-the-loop form.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/hal/flight_application.hpp"
#include "tolip/hal/link.hpp"
#include "tolip/hardover/hardover.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip::sim {

enum class Scenario : int {
  kNominal,
  kCorruptUpload,
  kTruncatedUpload,
  kSensorDropout,
  kStuckActuator,
  kHardoverActuator,
  kLateIgnition,
  kThrustMisalignment,
  kLinkLoss,
  kLinkCorruption,
};

struct ScenarioInfo {
  Scenario id;
  const char* name;      // the --scenario word
  const char* fault;     // what is injected
  const char* expected;  // the defined outcome (docs/hil.md)
};
// Every scenario, in the order above.
const std::vector<ScenarioInfo>& scenarios();
// False when `name` is no scenario.
bool find_scenario(const std::string& name, Scenario* scenario);
const char* scenario_name(Scenario scenario);

struct BenchConfig {
  double cycle_hz = hal::kDefaultMinorCycleHz;
  std::uint64_t seed = 1;
  Scenario scenario = Scenario::kNominal;
  // Sensors (one sigma of the white noise; the biases are drawn once per run, uniform within
  // +/- the value).
  double attitude_noise_rad = 0.002 * 0.017453292519943295;  // 0.002 deg
  double rate_noise_rad_s = 0.005 * 0.017453292519943295;    // 0.005 deg/s
  double attitude_bias_rad = 0.005 * 0.017453292519943295;   // 0.005 deg
  double rate_bias_rad_s = 0.001 * 0.017453292519943295;     // 0.001 deg/s
  // Stage-1 fin and jet-vane actuators: the position limit is data block 45 word 11; the rate limit
  // is our choice (no deck datum).
  double fin_rate_limit_rad_s = 40.0 * 0.017453292519943295;
  // Faults (docs/hil.md, "Fault scenarios").
  double fault_time_s = 20.0;                             // when the fault starts
  int dropout_cycles = 25;                                // sensor dropout length
  int late_stage = 2;                                     // late ignition: this stage
  double late_ignition_s = 2.0;                           //   by this much
  double misalignment_rad = 0.25 * 0.017453292519943295;  // pitch-plane thrust misalignment, stage 1
  int link_fault_period = 50;                             // every n-th sensor and actuator frame
  // Fly only the first duration_s seconds from lift-off (0: to the final burnout).
  double duration_s = 0.0;
};

// One telemetry record: the flight application's frame and the plant's truth at that cycle.
struct TelemetryRecord {
  hal::TelemetryFrame frame;
  double theta_true_rad = 0.0;
  double chi_true_rad = 0.0;
  double alpha_rad = 0.0;
  double beta_rad = 0.0;
  double dynamic_pressure_lbf_ft2 = 0.0;
  double altitude_ft = 0.0;
  double velocity_ft_s = 0.0;
  double fin_pitch_rad = 0.0;  // actuator positions (stage 1); jet fractions upper stages
  double fin_yaw_rad = 0.0;
  bool actuator_limited = false;  // at its position or rate limit this cycle
};

struct LinkCounters {
  std::uint32_t frames_sent = 0;
  std::uint32_t frames_lost = 0;     // injected losses (detected by the sequence number)
  std::uint32_t frames_corrupt = 0;  // failed their CRC
};

struct BenchResult {
  Status status = Status::kOk;  // kOk: flew to the final burnout; else why the run stopped
  bool completed = false;
  bool truncated = false;     // stopped at BenchConfig::duration_s
  bool vehicle_lost = false;  // |alpha| reached 90 deg or the vehicle hit the ground
  Status boot_status = Status::kOk;
  Status upload_status = Status::kOk;  // the mid-flight upload (upload scenarios), else kOk
  double end_time_s = 0.0;
  int final_stage = 0;
  StateVector burnout_state = StateVector::Zero();
  double burnout_weight_lb = 0.0;
  double burnout_altitude_ft = 0.0;
  Status orbit_status = Status::kOk;
  OrbitElements orbit;
  // Attitude tracking (commanded minus true attitude) over the cycles the autopilot flies after
  // the lift-off.
  int tracked_cycles = 0;
  double pitch_error_rms_rad = 0.0;
  double pitch_error_max_rad = 0.0;
  double yaw_error_rms_rad = 0.0;
  double yaw_error_max_rad = 0.0;
  double peak_qbar_alpha_lbf_rad_ft2 = 0.0;  // q-bar times the total angle of attack
  double peak_qbar_alpha_time_s = 0.0;
  double actuator_saturation_s = 0.0;  // time an actuator sat at its position or rate limit
  std::uint32_t table_crc = 0;         // of the table flown at the end
  hal::FlightCounters flight;
  LinkCounters sensor_link;
  LinkCounters actuator_link;
  std::vector<TelemetryRecord> telemetry;  // one per cycle (reserved before the run)
};

// The flight side of the bench, behind the frame link (docs/hil.md): the guidance computer in
// process (hal::LinkedFlightComputer called directly, the default) or the Cortex-M7 image under
// QEMU in lock-step over its serial port (qemu_target.hpp). Every call carries frames as bytes.
class FlightLink {
 public:
  virtual ~FlightLink() = default;
  // Uploads a table image (the boot upload first); the flight side's loader status.
  virtual Status upload(const std::uint8_t* image, std::size_t size) = 0;
  // One minor cycle: the cycle's sensor frame (size 0: lost in the link); the flight side's actuator
  // frame (kActuatorFrameSize bytes) and telemetry. Not kOk: the link itself failed (the run stops).
  virtual Status cycle(const std::uint8_t* sensor, std::size_t size, std::uint8_t* actuator,
                       hal::TelemetryFrame* telemetry) = 0;
  // End of the flight: the flight side's counters and table in force.
  virtual Status finish(hal::LinkReport* report) = 0;
};

struct BenchInputs {
  const Mission* mission = nullptr;
  const PreparedCase* prepared = nullptr;
  const HardoverData* hardover = nullptr;  // data blocks 44-45 (inertia, damping, jets, stations)
  const std::uint8_t* table = nullptr;     // the table image uploaded at boot
  std::size_t table_size = 0;
  FlightLink* flight = nullptr;  // nullptr: the guidance computer in process
};

// Number of minor cycles from lift-off to the final burnout of the case (with the scenario's late
// ignition), plus one: the telemetry capacity run_bench reserves.
std::size_t bench_cycle_capacity(const BenchInputs& inputs, const BenchConfig& config);

// The run in two parts: prepare() allocates what the run needs (the telemetry storage, the plant,
// the flight application); fly() boots the flight application and flies, allocating nothing.
class BenchSession {
 public:
  BenchSession();
  ~BenchSession();
  BenchSession(const BenchSession&) = delete;
  BenchSession& operator=(const BenchSession&) = delete;
  Status prepare(const BenchInputs& inputs, const BenchConfig& config, BenchResult* result);
  Status fly();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Flies the scenario (prepare, then fly). kOk with result->completed when the run reached the final burnout;
// any other status names why it stopped (kHalPortMissing for incomplete inputs). During the run nothing
// allocates (the telemetry storage is reserved first).
Status run_bench(const BenchInputs& inputs, const BenchConfig& config, BenchResult* result);

// The telemetry as CSV, one row per cycle (docs/hil.md, "Telemetry"); every number printed
// with 17 significant digits, so equal runs give equal bytes.
std::string telemetry_csv(const BenchResult& result);

}  // namespace tolip::sim
