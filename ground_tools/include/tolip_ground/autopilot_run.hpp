// Autopilot gains designed along the trajectory (issue 16, docs/theory/autopilot-design.md): the
// deck's request (data block 33 words 21-30, [body_dynamics] autopilot_*), the core's
// design_gain_schedule() along a trajectory, the hook that gives the 6D re-linearization (IP(6) = 1)
// the designed stage-1 schedule, the records of the table image (format version 3), and the reports
// (listing page, JSON member "autopilot", docs/cli.md).
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "tolip/autopilot/gain_schedule_design.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace tolip::ground {

namespace report_detail {
class Pager;
}

// The deck's request per stage 1-3, with the table image's deflection limit. False, with a message
// naming the stage and the key ("body_dynamics.autopilot_damping_ratio[1] (stage 2) ..."), when a
// value cannot be designed with: damping <= 0, frequency <= 0, attitude error <= 0, a negative
// actuator lag, points per stage outside 1-8 (the table's capacity), or no [hardover] I_yy table
// of a designed stage (data block 44). Stages 1-3 in the sequence are designed.
struct AutopilotPlan {
  AutopilotRequest requests[kGainScheduleStages];
  bool designed[kGainScheduleStages] = {false, false, false};
  int points_per_stage = 0;
  std::unique_ptr<tolip::HardoverData> hardover;  // blocks 44-45 in the core's form
};
bool plan_autopilot_design(const Mission& mission, const DeckExtras& extras, AutopilotPlan* plan,
                           std::string* message);

// The deck key of a design status for a stage (the field the status is about).
std::string autopilot_fault_key(Status status, int stage);

struct AutopilotStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;
  int fault_stage = 0;
  std::string trajectory_kind;  // "linearized program", "optimum" or "simulated"
  std::unique_ptr<GainScheduleDesign> schedule;
  // IP(6) = 1: the 6D re-linearization flew the stage-1 schedule designed along the accepted
  // point-mass linearized trajectory (SixDAutopilotGains).
  bool six_d_scheduled = false;
};

// Designs along `trajectory`.
void run_autopilot_step(const Mission& mission, const AutopilotPlan& plan, const Trajectory& trajectory,
                        const std::string& kind, AutopilotStep* step);

// "data block 33, body_dynamics.autopilot_natural_frequency_rad_s[0] (stage 1, t = 12.0 s): ..."
std::string autopilot_fault_text(const AutopilotStep& step);

// The 6D re-linearization's hook (linearization.hpp): designs along the accepted point-mass
// program's trajectory and sets the stage-1 schedule of the linearization's mission.
class SixDAutopilotGains final : public SixDGainDesign {
 public:
  SixDAutopilotGains(const AutopilotPlan& plan) : plan_(plan) {}
  Status before_body_dynamics(const Trajectory& point_mass_nominal, Mission* mission) override;
  bool called() const { return called_; }
  int fault_stage() const { return fault_stage_; }
  Status status() const { return status_; }
  // The design ran and failed: the run stops, and fault_text() names the stage and field.
  bool failed() const { return called_ && !ok(status_); }
  std::string fault_text() const;  // autopilot_fault_text of the failed design

 private:
  const AutopilotPlan& plan_;
  bool called_ = false;
  int fault_stage_ = 0;
  Status status_ = Status::kOk;
};

// The stage-1 schedule of a design in the Mission's form (BodyDynamicsBlocks::stage1_schedule_*).
void set_stage1_schedule(const GainScheduleDesign& schedule, BodyDynamicsBlocks* body);

// The design's records in the table (format version 3); the coast after a designed stage holds the
// stage's last designed gains in its constant record (its 6D steady state does the same).
void apply_gain_schedule(const GainScheduleDesign& schedule, GuidanceTable* table);

nlohmann::ordered_json autopilot_json(const AutopilotStep& step);

namespace report_detail {
void write_autopilot_pages(Pager& pager, const AutopilotStep& step);
}

}  // namespace tolip::ground
