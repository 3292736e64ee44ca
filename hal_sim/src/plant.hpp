// The vehicle plant of the HIL bench (bench.hpp, docs/hil.md): the core's point-mass trajectory
// with the attitude as a rigid-body state, actuators and sensors.
#pragma once

#include <cstdint>

#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/hal/hal.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"
#include "tolip_hal_sim/bench.hpp"

namespace tolip::sim {

// Seeded normal deviates (splitmix64 and the Box-Muller transform): the same seed, the same
// sequence, on every host.
class NoiseSource {
 public:
  explicit NoiseSource(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next_u64();
  double uniform();  // (0, 1)
  double normal();   // mean 0, sigma 1

 private:
  std::uint64_t state_;
  bool have_spare_ = false;
  double spare_ = 0.0;
};

struct PlantTruth {
  double alpha_rad = 0.0;
  double beta_rad = 0.0;
  double dynamic_pressure_lbf_ft2 = 0.0;
  double altitude_ft = 0.0;
  double velocity_ft_s = 0.0;
};

class Plant {
 public:
  using Augmented = Eigen::Matrix<double, 10, 1>;  // X (6), theta, theta-dot, chi, chi-dot

  Status init(const BenchInputs& inputs, const BenchConfig& config);

  double time_s() const { return t_; }
  double final_burnout_s() const { return final_burnout_s_; }
  bool finished() const { return finished_; }
  bool lost() const { return lost_; }
  int stage_code() const;
  bool spun() const;
  const StateVector& state() const { return x_; }
  double theta_rad() const { return theta_; }
  double chi_rad() const { return chi_; }
  double pitch_rate_rad_s() const { return q_; }
  double yaw_rate_rad_s() const { return r_; }
  double weight_lb() const;
  double fin_pitch() const { return act_pitch_; }
  double fin_yaw() const { return act_yaw_; }
  bool actuator_limited() const { return limited_; }

  // The actuator command for the next minor cycle (position and rate limits, faults applied).
  void command_actuators(const hal::ActuatorCommand& command, double dt);
  // Integrates to t_end (stops early at the final burnout or when the vehicle is lost).
  Status advance(double t_end);
  PlantTruth truth() const;

 private:
  struct Slot {
    int code = 0;
    double start_s = 0.0;
    double duration_s = 0.0;
    StageContext context;
  };
  Augmented derivative(const Slot& slot, double t, const Augmented& y, bool heading_hold) const;
  void body_stage_of(int code, double stage_time_s, int* body_stage, double* body_time_s) const;
  void enter_slot(int slot);

  const Mission* mission_ = nullptr;
  const PreparedCase* prepared_ = nullptr;
  const HardoverData* hardover_ = nullptr;
  BenchConfig config_;
  Slot slots_[kMaxStages];
  int slot_count_ = 0;
  int slot_ = 0;
  int last_powered_slot_ = 0;
  double final_burnout_s_ = 0.0;
  double liftoff_s_ = 0.0;
  StateVector liftoff_state_ = StateVector::Zero();
  double stage3_duration_s_ = 0.0;

  double t_ = 0.0;
  bool finished_ = false;
  bool lost_ = false;
  StateVector x_ = StateVector::Zero();
  double theta_ = 0.0, q_ = 0.0, chi_ = 0.0, r_ = 0.0;
  double act_pitch_ = 0.0, act_yaw_ = 0.0;  // fins rad, jets fraction
  hal::ActuatorKind act_kind_ = hal::ActuatorKind::kNone;
  bool limited_ = false;
};

}  // namespace tolip::sim
