// The fault scenarios of the HIL bench (bench.hpp, docs/hil.md "Fault scenarios").
#include <string>
#include <vector>

#include "tolip_hal_sim/bench.hpp"

namespace tolip::sim {

const std::vector<ScenarioInfo>& scenarios() {
  static const std::vector<ScenarioInfo> all = {
      {Scenario::kNominal, "nominal", "none", "flies to the final burnout near the ground prediction"},
      {Scenario::kCorruptUpload, "upload-corrupt",
       "a table image with one bit flipped is uploaded at the fault time",
       "rejected (kTableImageCrcMismatch); the table loaded at boot is flown: the run is the nominal one"},
      {Scenario::kTruncatedUpload, "upload-truncated",
       "a table image cut to 800 bytes is uploaded at the fault time",
       "rejected (kTableImageTruncated); the table loaded at boot is flown: the run is the nominal one"},
      {Scenario::kSensorDropout, "sensor-dropout",
       "the inertial platform gives no valid sample for N cycles from the fault time",
       "counted; the last attitude is propagated with its rates for 10 cycles, then the actuators are "
       "commanded neutral until samples return; the vehicle recovers and reaches the final burnout"},
      {Scenario::kStuckActuator, "actuator-stuck",
       "the stage-1 pitch fin and vane actuator freezes at its position at the fault time",
       "the autopilot cannot correct pitch for the rest of stage 1: tracking error and q-bar alpha grow; "
       "the upper stages' jets recover the attitude; the burnout misses the prediction"},
      {Scenario::kHardoverActuator, "actuator-hardover",
       "the stage-1 pitch fin and vane actuator goes to its limit (block 45 word 11) at the fault time",
       "q-bar alpha passes (q-bar alpha)max (block 45 word 2) about when the Sec. 16 hardover turn from "
       "the same time says; the statically stable vehicle trims at a large angle of attack instead of "
       "tumbling, and the burnout misses the prediction by tens of nmi and hundreds of ft/s"},
      {Scenario::kLateIgnition, "late-ignition",
       "the ignition of the late stage (default 2) comes late by the given time (default 2 s)",
       "the flight application follows the discretes: the stage's segments start at its real ignition; "
       "the coast before it is longer, the burnout state differs from the prediction by the gravity loss"},
      {Scenario::kThrustMisalignment, "thrust-misalignment",
       "pitch-plane thrust misalignment of the stage-1 motor (default 0.25 deg)",
       "the autopilot trims the misalignment moment with a standing deflection or jet duty; the "
       "vehicle reaches the final burnout with a small standing tracking error"},
      {Scenario::kLinkLoss, "link-loss",
       "every n-th sensor frame and actuator frame (default 50) from the fault time is lost",
       "detected by the sequence number and counted; a lost sensor frame is a platform dropout "
       "(propagated), a lost actuator frame holds the last good command; the flight is nominal within "
       "the noise"},
      {Scenario::kLinkCorruption, "link-corruption",
       "one byte of every n-th sensor frame and actuator frame (default 50) from the fault time is "
       "flipped",
       "detected by the CRC-32 and counted; handled as a lost frame"},
  };
  return all;
}

bool find_scenario(const std::string& name, Scenario* scenario) {
  for (const ScenarioInfo& info : scenarios()) {
    if (name == info.name) {
      *scenario = info.id;
      return true;
    }
  }
  return false;
}

const char* scenario_name(Scenario scenario) {
  for (const ScenarioInfo& info : scenarios()) {
    if (info.id == scenario) return info.name;
  }
  return "unknown";
}

}  // namespace tolip::sim
