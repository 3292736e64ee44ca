// The reference mission optimized from its crude program and then linearized (Sec. 6, 10): the
// one set-up of the linearization tests (tests/core/linearization_test.cpp,
// tests/core/linearization_qalpha_test.cpp, tests/noalloc/linearization_noalloc_test.cpp).
#pragma once

#include "support/reference_mission.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip::test {

// A mission, its optimum and the optimum's linearization. Large: hold it in static storage.
struct LinearizedCase {
  Mission mission;
  OptimizerWorkspace optimized;
  OptimizerResult optimum;
  LinearizationWorkspace workspace;
  LinearizationResult result;
  Status optimizer_status = Status::kNotPrepared;
  Status status = Status::kNotPrepared;  // of the linearization
};

// Fills c->mission with the reference mission from its crude starting program (data block 40),
// lets change(Mission&) edit it, and optimizes it into c->optimized / c->optimum.
template <typename Change>
void optimize_reference(LinearizedCase* c, Change&& change) {
  build_reference_mission(ReferenceProgram::kInitialNominal, &c->mission);
  change(c->mission);
  c->optimizer_status = optimize_trajectory(c->mission, &c->optimized, &c->optimum);
}

inline void optimize_reference(LinearizedCase* c) {
  optimize_reference(c, [](Mission&) {});
}

// Linearizes c's optimum into c->workspace / c->result (when the optimization succeeded).
inline void linearize_optimum(LinearizedCase* c) {
  if (ok(c->optimizer_status)) {
    c->status = linearize_pitch_program(c->optimized, &c->workspace, &c->result);
  }
}

// The reference mission unchanged, optimized and linearized once per test binary.
inline const LinearizedCase& linearized_reference() {
  static LinearizedCase c;
  static const bool built = [] {
    optimize_reference(&c);
    linearize_optimum(&c);
    return true;
  }();
  static_cast<void>(built);
  return c;
}

}  // namespace tolip::test
