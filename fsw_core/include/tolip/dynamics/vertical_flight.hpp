// Near-vertical flight in regular coordinates (manual Sec. 4 equations H, G; issue 10 part 2).
//
// The heading equation H divides by cos(gamma): at the end of the closed-form lift-off gamma is
// exactly 90 deg, where the heading of a velocity with no horizontal part is undefined and dpsi/dt
// of the printed equations is ~1e12 rad/s. A fixed 1 s Runge-Kutta step through that singularity
// leaves psi meaningless (-1.7e14 deg on the reference without the hold) and the adjoint of the
// step with it, so the steering and eq. 5-34 see sensitivities that are artefacts of the
// coordinates, not of the flight. The physical motion is regular: in the velocity's up, north and
// east components (v_up, v_N, v_E) = V (sin gamma, cos gamma cos psi, cos gamma sin psi) the
// derivatives are
//   dv_up/dt = F sin gamma + V cos gamma G
//   dv_N/dt  = F cos gamma cos psi - V sin gamma cos psi G - (V cos gamma H) sin psi
//   dv_E/dt  = F cos gamma sin psi - V sin gamma sin psi G + (V cos gamma H) cos psi
// where V cos gamma H has no division left. A Runge-Kutta step that starts within
// kVerticalFlightMaxAngleFromVertical of the vertical integrates these (with r, lambda and tau
// unchanged) and converts back at its end, so the stored points and everything downstream keep the
// manual's state. docs/theory/liftoff.md.
#pragma once

#include "tolip/core/state.hpp"

namespace tolip {

// A step whose starting flight-path angle is closer than this to the vertical (85 deg) flies in the
// regular coordinates: there the heading's relaxation rate T cos(theta) / (m V cos gamma) is too
// fast for a 1 s Runge-Kutta step (RK4 is stable to about 2.8 / step).
inline constexpr double kVerticalFlightMinCosGamma = 0.087155742747658166;  // cos(85 deg)

// The regular coordinates share the state's slots: [v_up, v_N, r, v_E, lambda, tau].
inline constexpr int kVerticalUp = kStateV;
inline constexpr int kVerticalNorth = kStateGamma;
inline constexpr int kVerticalEast = kStatePsi;

bool starts_near_vertical(const StateVector& state);

StateVector to_vertical_coordinates(const StateVector& state);
// Back to [V, gamma, r, psi, lambda, tau]. `heading_rad` (the step's starting psi) is the psi to
// report where the horizontal velocity vanishes exactly (the heading is undefined there), and
// elsewhere picks psi's branch: the result is within pi of it, so psi stays continuous.
StateVector from_vertical_coordinates(const StateVector& vertical, double heading_rad);

// d(vertical coordinates)/dt from the state and its derivative dX/dt = [F, G, I, H, J, K].
StateVector vertical_derivative(const StateVector& state, const StateVector& derivative);

// d(vertical coordinates)/d(state) at `state`, and d(state)/d(vertical coordinates) there (the
// inverse; it needs a horizontal velocity, cos gamma != 0).
Eigen::Matrix<double, 6, 6> vertical_jacobian(const StateVector& state);
Eigen::Matrix<double, 6, 6> state_jacobian_from_vertical(const StateVector& state);

}  // namespace tolip
