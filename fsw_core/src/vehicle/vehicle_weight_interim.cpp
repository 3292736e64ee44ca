// INTERIM (weak) definition until mission.cpp lands; removed then.
#include "tolip/mission/mission.hpp"

namespace tolip {

__attribute__((weak)) double vehicle_weight_lb(const Vehicle& vehicle, int code, double stage_time_s) {
  const StageSequence& sequence = vehicle.sequence;
  int position = 0;
  while (position < sequence.count && sequence.codes[position] != code) ++position;
  int last_powered = 0;
  for (int k = 0; k < sequence.count; ++k) {
    if (is_powered_stage(sequence.codes[k])) last_powered = sequence.codes[k];
  }
  double weight = 0.0;
  for (int k = position; k < sequence.count; ++k) {
    const int c = sequence.codes[k];
    const StageData& stage = vehicle.stages[stage_index(c)];
    weight += stage.jettison_weight_lb;
    if (c == last_powered) weight += vehicle.payload_lb;
    if (!is_powered_stage(c)) continue;
    weight += (k == position) ? stage.consumable_weight_lb(stage_time_s) : stage.consumable_weight_lb.y(0);
  }
  return weight;
}

}  // namespace tolip
