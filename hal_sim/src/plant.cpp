// The HIL bench's plant (plant.hpp, docs/hil.md "The plant").
#include "plant.hpp"

#include <algorithm>
#include <cmath>

#include "tolip/body/body_dynamics.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/stage_codes.hpp"
#include "tolip/dynamics/vertical_flight.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/integrator/rkad.hpp"
#include "tolip/trajectory/liftoff.hpp"

namespace tolip::sim {

namespace {

constexpr double kTimeTolerance_s = 1e-9;
constexpr double kTumblingAlpha_rad = 0.5 * kPi;
constexpr double kImpactAltitude_ft = -1000.0;  // the trajectory module's impact altitude

double clamp(double v, double limit) { return std::max(-limit, std::min(limit, v)); }

}  // namespace

std::uint64_t NoiseSource::next_u64() {
  std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double NoiseSource::uniform() { return (static_cast<double>(next_u64() >> 11) + 0.5) * 0x1.0p-53; }

double NoiseSource::normal() {
  if (have_spare_) {
    have_spare_ = false;
    return spare_;
  }
  const double u1 = uniform();
  const double u2 = uniform();
  const double radius = std::sqrt(-2.0 * std::log(u1));
  spare_ = radius * std::sin(2.0 * kPi * u2);
  have_spare_ = true;
  return radius * std::cos(2.0 * kPi * u2);
}

Status Plant::init(const BenchInputs& inputs, const BenchConfig& config) {
  mission_ = inputs.mission;
  prepared_ = inputs.prepared;
  hardover_ = inputs.hardover;
  config_ = config;
  slot_count_ = prepared_->stage_count;
  double shift_s = 0.0;
  last_powered_slot_ = -1;
  for (int i = 0; i < slot_count_; ++i) {
    const StageTimeline& line = prepared_->timeline[i];
    const bool late = config.scenario == Scenario::kLateIgnition && line.code == config.late_stage;
    if (late) shift_s += config.late_ignition_s;
    Slot& slot = slots_[i];
    slot.code = line.code;
    slot.start_s = line.start_s + shift_s;
    slot.duration_s = line.duration_s;
    slot.context = make_stage_context(*mission_, *prepared_, line);
    slot.context.start_s = slot.start_s;
    if (is_powered_stage(line.code)) last_powered_slot_ = i;
    if (line.code == 3) stage3_duration_s_ = line.duration_s;
  }
  // A late ignition lengthens the coast before the stage.
  for (int i = 0; i + 1 < slot_count_; ++i) slots_[i].duration_s = slots_[i + 1].start_s - slots_[i].start_s;
  if (last_powered_slot_ < 0) return Status::kStageSequenceInvalid;  // no powered stage to fly
  final_burnout_s_ = slots_[last_powered_slot_].start_s + slots_[last_powered_slot_].duration_s;

  LiftoffResult liftoff;
  const Status lifted = closed_form_liftoff(*mission_, *prepared_, &liftoff);
  if (!ok(lifted)) return lifted;
  liftoff_s_ = mission_->launch.liftoff_duration_s;
  liftoff_state_ = liftoff.state_at_end;
  x_ = prepared_->pad_state;
  t_ = 0.0;
  slot_ = 0;
  theta_ = 0.5 * kPi;
  chi_ = 0.0;
  q_ = r_ = 0.0;
  act_pitch_ = act_yaw_ = 0.0;
  finished_ = lost_ = false;
  return Status::kOk;
}

int Plant::stage_code() const { return slots_[slot_].code; }

bool Plant::spun() const { return mission_->options.stage_is_spun(slots_[slot_].code); }

double Plant::weight_lb() const {
  const Slot& s = slots_[slot_];
  const double stage_time = t_ - s.start_s;
  const double own = s.context.thrust != nullptr ? s.context.data->consumable_weight_lb(stage_time) : 0.0;
  return s.context.weight_above_consumable_lb + own;
}

void Plant::body_stage_of(int code, double stage_time_s, int* body_stage, double* body_time_s) const {
  switch (code) {
    case 1: *body_stage = 1, *body_time_s = stage_time_s; return;
    case 6: *body_stage = 2, *body_time_s = 0.0; return;
    case 2: *body_stage = 2, *body_time_s = stage_time_s; return;
    case 7: *body_stage = 3, *body_time_s = 0.0; return;
    case 3: *body_stage = 3, *body_time_s = stage_time_s; return;
    default: *body_stage = 3, *body_time_s = stage3_duration_s_; return;  // the stack after stage 3
  }
}

void Plant::command_actuators(const hal::ActuatorCommand& command, double dt) {
  const bool fault_active = t_ + kTimeTolerance_s >= config_.fault_time_s && slots_[slot_].code == 1;
  const HardoverData& data = *hardover_;
  limited_ = false;
  if (slots_[slot_].code == 1) {
    // Fins and jet vanes: position limit (block 45 word 11), rate limit.
    const double limit = data.fin_vane_deflection_rad;
    const double step = config_.fin_rate_limit_rad_s * dt;
    auto move = [&](double position, double target) {
      const double wanted = clamp(target, limit);
      if (wanted != target) limited_ = true;
      const double change = wanted - position;
      if (std::fabs(change) > step) limited_ = true;
      return position + clamp(change, step);
    };
    act_kind_ = hal::ActuatorKind::kFinsAndVanes;
    const double pitch_target = command.kind == hal::ActuatorKind::kFinsAndVanes ? command.pitch : 0.0;
    const double yaw_target = command.kind == hal::ActuatorKind::kFinsAndVanes ? command.yaw : 0.0;
    if (config_.scenario == Scenario::kStuckActuator && fault_active) {
      // The pitch actuator stays where it is; yaw still works.
      act_yaw_ = move(act_yaw_, yaw_target);
      limited_ = true;
    } else if (config_.scenario == Scenario::kHardoverActuator && fault_active) {
      act_pitch_ = limit;
      act_yaw_ = move(act_yaw_, yaw_target);
      limited_ = true;
    } else {
      act_pitch_ = move(act_pitch_, pitch_target);
      act_yaw_ = move(act_yaw_, yaw_target);
    }
    return;
  }
  // Upper stages: control jets, a fraction of full force over the cycle.
  act_kind_ = command.kind;
  if (command.kind != hal::ActuatorKind::kControlJets || spun()) {
    act_kind_ = hal::ActuatorKind::kNone;
    act_pitch_ = act_yaw_ = 0.0;
    return;
  }
  act_pitch_ = clamp(command.pitch, 1.0);
  act_yaw_ = clamp(command.yaw, 1.0);
  limited_ = act_pitch_ != command.pitch || act_yaw_ != command.yaw;
}

Plant::Augmented Plant::derivative(const Slot& slot, double t, const Augmented& y, bool heading_hold) const {
  const StateVector x = y.head<6>();
  const double theta = y[6], theta_dot = y[7], chi = y[8], chi_dot = y[9];
  StepCommand held;
  held.mode = AttitudeMode::kHeld;
  held.theta_start_rad = held.theta_end_rad = theta;
  held.chi_rad = chi;
  held.step_start_s = t;
  held.heading_hold = heading_hold;
  Evaluation ev;
  evaluate_flight(*mission_, *prepared_, slot.context, held, t, x, 0.0, &ev);
  Augmented d = Augmented::Zero();
  d.head<6>() = ev.derivative;
  const bool is_spun = mission_->options.stage_is_spun(slot.code);
  if (is_spun) return d;  // gyroscopically stiff: the attitude does not move
  d[6] = theta_dot;
  d[8] = chi_dot;
  if (t < liftoff_s_) return d;

  const double stage_time = t - slot.start_s;
  int body_stage = 1;
  double body_time = 0.0;
  body_stage_of(slot.code, stage_time, &body_stage, &body_time);
  const Matrix3 platform_to_local = inertial_to_local(x) * prepared_->platform_to_inertial;
  const BodyAngles angles = body_angles_of_attack(theta, chi, platform_to_local);
  // Stage 1 only, as the stage-1 misalignment of the dispersions (block 49): the upper stages' jets
  // (block 45 words 12-13) are weaker than a misalignment of their motors (docs/hil.md).
  const double misalignment =
      config_.scenario == Scenario::kThrustMisalignment && slot.code == 1 ? config_.misalignment_rad : 0.0;
  const HardoverStage& jets = hardover_->stages[body_stage - 1];

  RigidBodyInputs in;
  in.body_stage = body_stage;
  in.body_stage_time_s = body_time;
  in.flown = slot.context.data;
  in.flown_stage_time_s = stage_time;
  in.speed_ft_s = x[kStateV];
  // Pitch plane.
  in.alpha_rad = angles.alpha_rad;
  in.rate_rad_s = theta_dot;
  in.deflection_rad = act_kind_ == hal::ActuatorKind::kFinsAndVanes ? act_pitch_ : 0.0;
  in.misalignment_rad = misalignment;
  in.jet_force_lbf =
      act_kind_ == hal::ActuatorKind::kControlJets ? act_pitch_ * jets.single_jet_force_lbf : 0.0;
  const RigidBodyMoment pitch = rigid_body_moment(*mission_, *hardover_, ev, in);
  // Yaw plane (axisymmetric vehicle: the same terms with beta, I_zz = I_yy).
  in.alpha_rad = angles.beta_rad;
  in.rate_rad_s = chi_dot;
  in.deflection_rad = act_kind_ == hal::ActuatorKind::kFinsAndVanes ? act_yaw_ : 0.0;
  in.misalignment_rad = 0.0;
  in.jet_force_lbf =
      act_kind_ == hal::ActuatorKind::kControlJets ? act_yaw_ * jets.single_jet_force_lbf : 0.0;
  const RigidBodyMoment yaw = rigid_body_moment(*mission_, *hardover_, ev, in);
  d[7] = pitch.moment_lbf_ft / pitch.inertia_slug_ft2;
  d[9] = yaw.moment_lbf_ft / yaw.inertia_slug_ft2;
  return d;
}

PlantTruth Plant::truth() const {
  PlantTruth out;
  const Slot& slot = slots_[slot_];
  StepCommand held;
  held.mode = AttitudeMode::kHeld;
  held.theta_start_rad = held.theta_end_rad = theta_;
  held.chi_rad = chi_;
  held.step_start_s = t_;
  held.heading_hold = t_ < mission_->launch.heading_hold_until_s;
  Evaluation ev;
  evaluate_flight(*mission_, *prepared_, slot.context, held, t_, x_, 0.0, &ev);
  if (t_ >= liftoff_s_) {
    const Matrix3 platform_to_local = inertial_to_local(x_) * prepared_->platform_to_inertial;
    const BodyAngles angles = body_angles_of_attack(theta_, chi_, platform_to_local);
    out.alpha_rad = angles.alpha_rad;
    out.beta_rad = angles.beta_rad;
  }
  out.dynamic_pressure_lbf_ft2 = ev.dynamic_pressure_lbf_ft2;
  out.altitude_ft = ev.altitude_ft;
  out.velocity_ft_s = x_[kStateV];
  return out;
}

void Plant::enter_slot(int slot) {
  slot_ = slot;
  // Spin-up at the ignition of a spun stage: the rates are taken out, the attitude stays.
  if (mission_->options.stage_is_spun(slots_[slot].code)) q_ = r_ = 0.0;
}

Status Plant::advance(double t_end) {
  while (!finished_ && !lost_ && t_ < t_end - kTimeTolerance_s) {
    // The vertical lift-off: the vehicle rises on the launcher, attitude held (closed form).
    if (t_ < liftoff_s_ - kTimeTolerance_s) {
      if (t_end < liftoff_s_ - kTimeTolerance_s) {
        t_ = t_end;
        return Status::kOk;
      }
      t_ = liftoff_s_;
      x_ = liftoff_state_;
      theta_ = 0.5 * kPi;
      chi_ = q_ = r_ = 0.0;
      continue;
    }
    const Slot& slot = slots_[slot_];
    const double slot_end = slot.start_s + slot.duration_s;
    if (t_ >= slot_end - kTimeTolerance_s) {
      if (slot_ == last_powered_slot_) {
        finished_ = true;
        break;
      }
      enter_slot(slot_ + 1);
      continue;
    }
    const double tb = std::min(t_end, slot_end);
    const double h = tb - t_;
    const bool heading_hold =
        t_ + 0.5 * mission_->constants.time_epsilon_s < mission_->launch.heading_hold_until_s;
    const bool vertical = !(mission_->launch.heading_hold_until_s > 0.0) && starts_near_vertical(x_);
    const double heading_reference = x_[kStatePsi];
    Augmented y;
    y.head<6>() = vertical ? to_vertical_coordinates(x_) : x_;
    y[6] = theta_;
    y[7] = q_;
    y[8] = chi_;
    y[9] = r_;
    const auto f = [&](double time, const Augmented& a) {
      if (!vertical) return derivative(slot, time, a, heading_hold);
      Augmented b = a;
      b.head<6>() = from_vertical_coordinates(a.head<6>(), heading_reference);
      Augmented d = derivative(slot, time, b, heading_hold);
      d.head<6>() = vertical_derivative(b.head<6>(), d.head<6>());
      return d;
    };
    const Augmented y1 = runge_kutta4_step(f, t_, y, f(t_, y), h);
    if (!y1.allFinite()) return Status::kNonFiniteState;
    x_ = vertical ? from_vertical_coordinates(y1.head<6>(), heading_reference) : StateVector(y1.head<6>());
    theta_ = y1[6];
    q_ = y1[7];
    chi_ = y1[8];
    r_ = y1[9];
    t_ = tb;
    // A stage that ends here hands over at once: the discretes of this cycle carry the new stage.
    if (t_ >= slot_end - kTimeTolerance_s) {
      if (slot_ == last_powered_slot_) {
        finished_ = true;
      } else {
        enter_slot(slot_ + 1);
      }
    }
    const PlantTruth now = truth();
    if (now.altitude_ft < kImpactAltitude_ft) {
      lost_ = true;
      return Status::kAltitudeBelowSurface;
    }
    if (now.dynamic_pressure_lbf_ft2 > 0.0 && std::hypot(now.alpha_rad, now.beta_rad) >= kTumblingAlpha_rad) {
      lost_ = true;
      return Status::kOk;
    }
  }
  if (!finished_ && t_ >= final_burnout_s_ - kTimeTolerance_s) finished_ = true;
  return Status::kOk;
}

}  // namespace tolip::sim
