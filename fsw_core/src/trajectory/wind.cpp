// Air-relative velocity and angle of attack under a wind (manual Sec. 15).
#include "tolip/trajectory/wind.hpp"

#include <cmath>

namespace tolip {

Vector3 air_relative_velocity_local(const StateVector& state, const StateTrig& trig, double wind_speed_ft_s,
                                    double wind_azimuth_rad) {
  const double relative_azimuth = wind_azimuth_rad - state[kStatePsi];
  return air_relative_velocity_local(state, trig, wind_speed_ft_s,
                                     SineCosine{std::sin(relative_azimuth), std::cos(relative_azimuth)});
}

Vector3 air_relative_velocity_local(const StateVector& state, const StateTrig& trig, double wind_speed_ft_s,
                                    const SineCosine& relative_azimuth) {
  const double along = wind_speed_ft_s * relative_azimuth.cos;
  return Vector3(-wind_speed_ft_s * relative_azimuth.sin, state[kStateV] - along * trig.cos_gamma,
                 along * trig.sin_gamma);
}

Matrix3 local_to_air_frame(const Vector3& air_velocity_local) {
  return local_to_air_frame(air_velocity_local, air_velocity_local.norm());
}

// Eigen's normalized() is v / sqrt(v.squaredNorm()) when that is > 0, else v: v / v.norm() with
// the caller's norm, the same vector bit for bit.
Matrix3 local_to_air_frame(const Vector3& air_velocity_local, double air_speed_ft_s) {
  const Vector3 a_y =
      (air_speed_ft_s > 0.0) ? Vector3(air_velocity_local / air_speed_ft_s) : air_velocity_local;
  const Vector3 a_z = (Vector3::UnitZ() - a_y.z() * a_y).normalized();
  const Vector3 a_x = a_y.cross(a_z);
  Matrix3 m;
  m.row(0) = a_x.transpose();
  m.row(1) = a_y.transpose();
  m.row(2) = a_z.transpose();
  return m;
}

double air_angle_of_attack_rad(const Matrix3& local_to_air, const Vector3& thrust_axis_local) {
  return angle_of_attack_rad(thrust_axis_air(local_to_air, thrust_axis_local));
}

Vector3 thrust_axis_air(const Matrix3& local_to_air, const Vector3& thrust_axis_local) {
  return local_to_air * thrust_axis_local;
}

}  // namespace tolip
