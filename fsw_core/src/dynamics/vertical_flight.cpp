// Near-vertical flight in regular coordinates (tolip/dynamics/vertical_flight.hpp).
#include "tolip/dynamics/vertical_flight.hpp"

#include <cmath>

#include "tolip/core/constants.hpp"

namespace tolip {

bool starts_near_vertical(const StateVector& state) {
  return std::fabs(std::cos(state[kStateGamma])) < kVerticalFlightMinCosGamma;
}

StateVector to_vertical_coordinates(const StateVector& x) {
  const double v = x[kStateV];
  const double sg = std::sin(x[kStateGamma]), cg = std::cos(x[kStateGamma]);
  const double sp = std::sin(x[kStatePsi]), cp = std::cos(x[kStatePsi]);
  StateVector y = x;
  y[kVerticalUp] = v * sg;
  y[kVerticalNorth] = v * cg * cp;
  y[kVerticalEast] = v * cg * sp;
  return y;
}

StateVector from_vertical_coordinates(const StateVector& y, double heading_rad) {
  const double up = y[kVerticalUp], north = y[kVerticalNorth], east = y[kVerticalEast];
  const double horizontal = std::hypot(north, east);
  StateVector x = y;
  x[kStateV] = std::hypot(up, horizontal);
  x[kStateGamma] = std::atan2(up, horizontal);
  x[kStatePsi] = (horizontal > 0.0)
                     ? heading_rad + std::remainder(std::atan2(east, north) - heading_rad, 2.0 * kPi)
                     : heading_rad;
  return x;
}

StateVector vertical_derivative(const StateVector& x, const StateVector& f) {
  const double v = x[kStateV];
  const double sg = std::sin(x[kStateGamma]), cg = std::cos(x[kStateGamma]);
  const double sp = std::sin(x[kStatePsi]), cp = std::cos(x[kStatePsi]);
  const double dv = f[kStateV];
  const double v_dgamma = v * f[kStateGamma];
  // The horizontal turn rate times the horizontal speed: H's 1/cos(gamma) cancels here.
  const double v_cg_dpsi = v * cg * f[kStatePsi];
  StateVector d = f;
  d[kVerticalUp] = dv * sg + v_dgamma * cg;
  d[kVerticalNorth] = dv * cg * cp - v_dgamma * sg * cp - v_cg_dpsi * sp;
  d[kVerticalEast] = dv * cg * sp - v_dgamma * sg * sp + v_cg_dpsi * cp;
  return d;
}

Eigen::Matrix<double, 6, 6> vertical_jacobian(const StateVector& x) {
  const double v = x[kStateV];
  const double sg = std::sin(x[kStateGamma]), cg = std::cos(x[kStateGamma]);
  const double sp = std::sin(x[kStatePsi]), cp = std::cos(x[kStatePsi]);
  Eigen::Matrix<double, 6, 6> j = Eigen::Matrix<double, 6, 6>::Identity();
  j(kVerticalUp, kStateV) = sg;
  j(kVerticalUp, kStateGamma) = v * cg;
  j(kVerticalUp, kStatePsi) = 0.0;
  j(kVerticalNorth, kStateV) = cg * cp;
  j(kVerticalNorth, kStateGamma) = -v * sg * cp;
  j(kVerticalNorth, kStatePsi) = -v * cg * sp;
  j(kVerticalEast, kStateV) = cg * sp;
  j(kVerticalEast, kStateGamma) = -v * sg * sp;
  j(kVerticalEast, kStatePsi) = v * cg * cp;
  return j;
}

Eigen::Matrix<double, 6, 6> state_jacobian_from_vertical(const StateVector& x) {
  const double v = x[kStateV];
  const double sg = std::sin(x[kStateGamma]), cg = std::cos(x[kStateGamma]);
  const double sp = std::sin(x[kStatePsi]), cp = std::cos(x[kStatePsi]);
  Eigen::Matrix<double, 6, 6> j = Eigen::Matrix<double, 6, 6>::Identity();
  // V = |v|; gamma = atan2(v_up, v_h); psi = atan2(v_E, v_N).
  j(kStateV, kVerticalUp) = sg;
  j(kStateV, kVerticalNorth) = cg * cp;
  j(kStateV, kVerticalEast) = cg * sp;
  j(kStateGamma, kVerticalUp) = cg / v;
  j(kStateGamma, kVerticalNorth) = -sg * cp / v;
  j(kStateGamma, kVerticalEast) = -sg * sp / v;
  j(kStatePsi, kVerticalUp) = 0.0;
  j(kStatePsi, kVerticalNorth) = -sp / (v * cg);
  j(kStatePsi, kVerticalEast) = cp / (v * cg);
  return j;
}

}  // namespace tolip
