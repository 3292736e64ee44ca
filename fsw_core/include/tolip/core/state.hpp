// The state vector of integration, X(1..6) of the manual (Sec. 4, 9).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products of fixed-size vectors

namespace tolip {

// [V, gamma, r, psi, lambda, tau]: velocity relative to the rotating Earth (ft/s), its flight-path
// angle above the geocentric horizontal (rad), geocentric radius (ft), its azimuth east of north
// (rad), geocentric latitude (rad), and the INERTIAL longitude tau (rad), measured from an inertial
// x axis through the Greenwich meridian at lift-off (Earth-fixed longitude = tau - omega t).
using StateVector = Eigen::Matrix<double, 6, 1>;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

inline constexpr int kStateV = 0;
inline constexpr int kStateGamma = 1;
inline constexpr int kStateR = 2;
inline constexpr int kStatePsi = 3;
inline constexpr int kStateLambda = 4;
inline constexpr int kStateTau = 5;

}  // namespace tolip
