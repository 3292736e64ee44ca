// The flight application of the guidance computer (docs/hil.md): on the hardware-abstraction ports
// of hal.hpp, each minor cycle it reads the stage discretes and the inertial platform, runs the
// guidance executor on the active table, the attitude control law (eq. 7-3) with the gains in force
// of the executor's output in pitch and yaw, commands the actuators and emits one telemetry frame.
// Uploads go through the double-buffered loader between cycles.
//
// The same source builds for the host (the HIL bench, hal_sim/) and the Cortex-M7. The object holds
// everything it uses (the table service's two buffers, the executor, the upload buffer): about
// 4.5 KiB, meant for static storage. Nothing allocates.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tolip/core/status.hpp"
#include "tolip/hal/hal.hpp"
#include "tolip/table/control_law.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"

namespace tolip::hal {

// Consecutive platform failures the application rides through by propagating the last good
// attitude with its rates; from the next one on it commands neutral actuators until a good sample
// returns (0.2 s at 50 Hz).
inline constexpr int kMaxPlatformDropoutCycles = 10;

// Failed calls and refused requests since boot, by cause.
struct FlightCounters {
  std::uint32_t cycles = 0;
  std::uint32_t clock_overruns = 0;
  std::uint32_t platform_dropouts = 0;  // cycles without a valid platform sample
  std::uint32_t neutral_cycles = 0;     // cycles commanded neutral after too long a dropout
  std::uint32_t actuator_rejections = 0;
  std::uint32_t telemetry_drops = 0;
  std::uint32_t discrete_faults = 0;       // discretes unreadable
  std::uint32_t stage_events_refused = 0;  // a stage code out of flight order
  std::uint32_t guidance_faults = 0;       // executor or control law refused (neutral command)
  std::uint32_t table_loads = 0;           // successful loads (boot included)
  std::uint32_t table_rejections = 0;      // uploads refused by the store or the loader
  std::uint32_t saturated_cycles = 0;      // pitch or yaw command at its limit
  std::uint32_t total_faults() const {
    return clock_overruns + platform_dropouts + actuator_rejections + telemetry_drops + discrete_faults +
           stage_events_refused + guidance_faults + table_rejections;
  }
};

class FlightApplication {
 public:
  explicit FlightApplication(const Ports& ports) : ports_(ports), executor_(service_) {}
  FlightApplication(const FlightApplication&) = delete;
  FlightApplication& operator=(const FlightApplication&) = delete;

  // Checks the ports and loads the table store's image (load_table). Before lift-off.
  Status boot();
  // Reads the table store and loads its image through the loader (stage, validate, commit). On any
  // failure the active table stays in force and the status names the cause. Between cycles.
  Status load_table();
  // One minor cycle (docs/hil.md, "The minor cycle"). kOk, or the first failed call's status (the
  // cycle always completes with its defined reaction).
  Status run_minor_cycle();

  const FlightCounters& counters() const { return counters_; }
  const GuidanceTableService& tables() const { return service_; }
  const GuidanceExecutor& executor() const { return executor_; }
  const TelemetryFrame& last_frame() const { return frame_; }

 private:
  Ports ports_;
  GuidanceTableService service_;
  GuidanceExecutor executor_;
  FlightCounters counters_;
  TelemetryFrame frame_;
  PlatformSample last_good_;
  bool have_good_sample_ = false;
  int dropout_run_ = 0;
  std::uint32_t last_discrete_sequence_ = 0;
  std::uint8_t upload_[kTableImageSize + 1] = {};  // one more byte: an oversized image is seen
};

}  // namespace tolip::hal
