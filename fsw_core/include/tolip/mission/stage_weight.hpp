// vehicle_weight_lb() (mission.hpp) of one stage at many times.
#pragma once

#include "tolip/mission/mission.hpp"

namespace tolip {

// vehicle_weight_lb(vehicle, code, t) with the stage's place in the sequence and the last powered
// stage found once, and the stage's own consumable table looked up with a hint
// (Table::operator()(x, hint)): the same sum in the same order, so the same weight bit for bit
// (vehicle_weight_lb() is this class). For a caller that steps through the stage in time (the
// Sec. 14 ideal-velocity integrals).
class StageWeight {
 public:
  StageWeight(const Vehicle& vehicle, int code);
  double operator()(double stage_time_s);

 private:
  // The sum before the stage's own consumable weight, exactly as the loop over the sequence forms
  // it, and every term after it in order (jettison weights, the payload, later initial consumables).
  double leading_lb_ = 0.0;
  const WeightTable* consumable_ = nullptr;  // null: no term of its own
  double trailing_lb_[3 * kMaxStages] = {};
  int trailing_count_ = 0;
  int hint_ = -1;
};

}  // namespace tolip
