// Point-mass equations of motion F, G, H, I, J, K of manual Sec. 4.
//
// Written from the local-frame acceleration and the force components the manual derives, with one
// correction: the J2 term of F (dV/dt) has +J2/2, not the printed minus. The printed sign
// contradicts the i_z component of the same gravity vector and the geopotential; an independent
// inertial (Cartesian) integration of the same forces agrees with + (tests/core/
// equations_of_motion_test.cpp, docs/theory/equations-of-motion.md).
#pragma once

#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/frames/frames.hpp"

namespace tolip {

// Forces other than gravity and the Earth-rotation terms, already resolved in the local frame.
struct AppliedForces {
  double mass_slug = 0.0;
  Vector3 thrust_local_lbf = Vector3::Zero();  // T [C] u_P: (T_Lx, T_Ly, T_Lz)
  double drag_lbf = 0.0;                       // along -i_y
  double lift_lbf = 0.0;                       // along +i_z
  bool heading_hold = false;                   // dpsi/dt forced to 0 (near-vertical flight)
};

// dX/dt = [F, G, I, H, J, K] in state order [V, gamma, r, psi, lambda, tau].
StateVector state_derivative(const Constants& constants, const StateVector& state,
                             const AppliedForces& forces);
// The same with the state's sines and cosines already computed.
StateVector state_derivative(const Constants& constants, const StateVector& state, const StateTrig& trig,
                             const AppliedForces& forces);

}  // namespace tolip
