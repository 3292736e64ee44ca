// Stage codes (manual KK2) and the spin rule of IP(9): the vocabulary every module shares,
// from the optimizer to the flight-side table executor. It lives in core, not in mission, because
// the flight side (module table) may depend on core only (fsw_core/module_graph.txt).
#pragma once

namespace tolip {

// Stage codes (manual KK2): 1-5 powered, 6-10 the coasts after stages 1-5.
inline constexpr bool is_powered_stage(int code) { return code >= 1 && code <= 5; }
inline constexpr bool is_coast_stage(int code) { return code >= 6 && code <= 10; }
inline constexpr int stage_index(int code) { return code - 1; }

// IP(9), the one rule of which stages are spun (Sec. 22: 1 stages 4 and 5 spun, theta_5 = theta_4;
// 2 stage 4 continuous and stage 5 spun; 3 stages 4 and 5 continuous; 0, this project's "no stage
// 4", spins nothing). A spun stage, and the coast after it (9, 10), holds the data block 17
// attitudes; every other stage flies the pitch program. The trajectory, the backward run, the
// optimizer, the linearization, the table builder and the flight-side executor all ask this.
inline constexpr bool stage_is_spun(int spin_option, int stage_code) {
  if (stage_code == 4 || stage_code == 9) return spin_option == 1;
  if (stage_code == 5 || stage_code == 10) return spin_option == 1 || spin_option == 2;
  return false;
}

// A powered stage whose pitch program is a control (Sec. 5: the steepest-descent perturbations,
// Sec. 6: data block 18 segments): stages 1-3 always, 4 and 5 when IP(9) does not spin them.
inline constexpr bool stage_is_steered(int spin_option, int stage_code) {
  return is_powered_stage(stage_code) && !stage_is_spun(spin_option, stage_code);
}

}  // namespace tolip
