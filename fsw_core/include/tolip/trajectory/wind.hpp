// Winds for the dispersed trajectories (manual Sec. 15, "Programming - SIXD - Dispersion", data
// blocks 53-54): a wind profile as a function of altitude, the air-relative velocity it gives, and
// the angle of attack against the air mass. evaluate_flight() and the dispersion module's q-bar
// alpha both use these, so the flown and the reported angle are one rule.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/state.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/math/table.hpp"

namespace tolip {

using WindTable = Table<kMaxWindTablePoints>;

// WINDVL and WINDAZ: altitude (ft above the oblate surface) -> wind speed (ft/s) and azimuth of
// the wind VELOCITY vector (rad, clockwise from north). Both tables finalized.
struct WindProfile {
  WindTable speed_ft_s;   // block 53
  WindTable azimuth_rad;  // block 54
};

// The air-mass-relative velocity in the local frame L (Sec. 15):
//   V_ix = -V_w sin(psi_w - psi), V_iy = V - V_w cos(psi_w - psi) cos gamma,
//   V_iz = V_w cos(psi_w - psi) sin gamma
// (the horizontal wind resolved on i_x, i_y, i_z and subtracted from V i_y).
Vector3 air_relative_velocity_local(const StateVector& state, const StateTrig& trig, double wind_speed_ft_s,
                                    double wind_azimuth_rad);
// The same with sin and cos of psi_w - psi given (a dispersion flight's, by the addition theorem).
Vector3 air_relative_velocity_local(const StateVector& state, const StateTrig& trig, double wind_speed_ft_s,
                                    const SineCosine& relative_azimuth);

// The air-relative frame expressed in L, as the rows of the returned matrix (L -> air frame):
// a_y along the air-relative velocity, a_z the part of i_z normal to a_y (the "up" of the
// point-mass lift), a_x = a_y x a_z. With no wind it is the identity. Precondition: a non-zero
// air-relative velocity not along i_z.
Matrix3 local_to_air_frame(const Vector3& air_velocity_local);
// The same with |air_velocity_local| (its norm(), > 0) already computed: the same matrix, bit for bit.
Matrix3 local_to_air_frame(const Vector3& air_velocity_local, double air_speed_ft_s);

// In-plane angle of attack against the air mass: the angle from a_y to the thrust axis in the
// a_y-a_z plane (angle_of_attack_rad() of the thrust axis resolved in the air frame).
double air_angle_of_attack_rad(const Matrix3& local_to_air, const Vector3& thrust_axis_local);
// The thrust axis resolved in the air frame, whose angle_of_attack_rad() that is.
Vector3 thrust_axis_air(const Matrix3& local_to_air, const Vector3& thrust_axis_local);

}  // namespace tolip
