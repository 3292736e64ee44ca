// The column table shared by the CSV, the JSON points and docs/cli.md.
#include <algorithm>
#include <cmath>

#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {
namespace {

double deg(double radians) { return radians * kRadToDeg; }

constexpr PointColumn kColumns[] = {
    {"time_s", "s", "TIME: time from launch, coasts included", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.time_s; }},
    {"stage", "-", "stage code (1-5 powered, 6-10 the coast after stage code-5)", ColumnKind::kInteger,
     [](const TrajectoryPoint& p) { return static_cast<double>(p.stage_code); }},
    {"stage_time_s", "s", "time from the start of the stage", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.stage_time_s; }},
    {"velocity_ft_s", "ft/s", "VEL: velocity relative to the rotating Earth", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.state[kStateV]; }},
    {"gamma_deg", "deg", "GAMMA: flight-path angle of VEL above the geocentric horizontal", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.state[kStateGamma]); }},
    {"psi_deg", "deg", "PSI: azimuth of VEL, east of north", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.state[kStatePsi]); }},
    {"altitude_ft", "ft", "ALTITUDE: height above the oblate Earth surface", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.altitude_ft; }},
    {"geocentric_latitude_deg", "deg", "GEOC LAT: geocentric latitude, north positive", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.state[kStateLambda]); }},
    {"longitude_deg", "deg", "TAU: Earth-fixed longitude (tau - omega t), east positive, in (-180, 180]",
     ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return wrap_degrees_180(deg(p.earth_longitude_rad)); }},
    {"inertial_longitude_deg", "deg",
     "inertial longitude tau (from the Greenwich meridian at lift-off), in (-180, 180]", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return wrap_degrees_180(deg(p.state[kStateTau])); }},
    {"dynamic_pressure_lbf_ft2", "lbf/ft^2", "QBAR: dynamic pressure", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.dynamic_pressure_lbf_ft2; }},
    {"net_thrust_lbf", "lbf", "THRUST: net thrust, vacuum thrust - p Ae", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.net_thrust_lbf; }},
    {"vacuum_thrust_lbf", "lbf", "vacuum thrust from the Sec. 14 modified table", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.vacuum_thrust_lbf; }},
    {"weight_lb", "lb", "WEIGHT: vehicle sea-level weight", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.weight_lb; }},
    {"geodetic_latitude_deg", "deg", "GEOD LAT: geodetic latitude", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.geodetic_latitude_rad); }},
    {"radius_ft", "ft", "RADIUS: distance from the Earth's centre", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.state[kStateR]; }},
    {"heating_rate_btu_ft2_s", "Btu/ft^2/s",
     "HEAT RATE: stagnation-point heating rate (Sec. 13; 0 without a nose radius)", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.heating_rate_btu_ft2_s; }},
    {"theta_deg", "deg", "THETA: pitch attitude from the launch geodetic horizontal (platform frame)",
     ColumnKind::kReal, [](const TrajectoryPoint& p) { return deg(p.theta_rad); }},
    {"chi_deg", "deg", "CHI: yaw attitude in the platform frame", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.chi_rad); }},
    {"inertial_velocity_ft_s", "ft/s", "VI: velocity relative to the non-rotating Earth", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.inertial.velocity_ft_s; }},
    {"inertial_gamma_deg", "deg", "GAMI: flight-path angle of VI", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.inertial.flight_path_angle_rad); }},
    {"inertial_psi_deg", "deg", "PSII: azimuth of VI, east of north", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.inertial.azimuth_rad); }},
    {"mach", "-", "MACH: VEL / local speed of sound", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.mach; }},
    {"alpha_deg", "deg", "ALPHA: in-plane angle between the thrust axis and VEL", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return deg(p.alpha_rad); }},
    {"drag_lbf", "lbf", "DRAG: aerodynamic drag", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.drag_lbf; }},
    {"lift_lbf", "lbf", "LIFT: aerodynamic lift", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.lift_lbf; }},
    {"qalpha_lbf_deg_ft2", "lbf deg/ft^2", "QALPHA: QBAR x ALPHA (alpha in degrees)", ColumnKind::kReal,
     [](const TrajectoryPoint& p) { return p.dynamic_pressure_lbf_ft2 * deg(p.alpha_rad); }},
    {"range_nmi", "n.mi.", "RANGE: great-circle arc from the launch site, 1 n.mi. = 1 minute of arc",
     ColumnKind::kReal, [](const TrajectoryPoint& p) { return p.downrange_rad * kNauticalMilesPerRadian; }},
    {"heading_hold", "0/1", "1 when dpsi/dt is held at 0 on the step starting here", ColumnKind::kFlag,
     [](const TrajectoryPoint& p) { return p.heading_hold ? 1.0 : 0.0; }},
    {"alpha_zero", "0/1", "1 when theta is set for alpha = 0 on the step starting here", ColumnKind::kFlag,
     [](const TrajectoryPoint& p) { return p.alpha_zero ? 1.0 : 0.0; }},
};

}  // namespace

std::span<const PointColumn> trajectory_point_columns() { return kColumns; }

double wrap_degrees_180(double degrees) {
  if (!std::isfinite(degrees)) return degrees;
  double wrapped = std::fmod(degrees, 360.0);  // (-360, 360)
  if (wrapped <= -180.0) wrapped += 360.0;
  if (wrapped > 180.0) wrapped -= 360.0;
  return wrapped;
}

int stored_point_count(const Trajectory& trajectory) {
  return std::clamp(trajectory.point_count, 0, kMaxTrajectoryPoints);
}

}  // namespace tolip::ground
