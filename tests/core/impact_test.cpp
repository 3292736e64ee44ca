// Nominal impact locus (manual Sec. 17, data blocks 42-43, DA6D(17-19)): the expended stage-1
// casing against an independent integration (an inertial Cartesian model with an adaptive
// Dormand-Prince 5(4) integrator at tight tolerance, the same drag table, atmosphere and oblate
// Earth); a vacuum trajectory against the closed-form Kepler ellipse intersected with a spherical
// Earth; the crossing found inside the step; the locus covering every n-th point; the named faults.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/cartesian_model.hpp"
#include "support/reference_impact.hpp"
#include "support/reference_mission.hpp"
#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/impact/impact.hpp"
#include "tolip/orbit/orbit_elements.hpp"

namespace tolip {
namespace {

constexpr double kFtPerNmi = 6076.11549;

struct Fixture {
  Mission mission;
  PreparedCase prepared;
  Trajectory nominal;
  ImpactLocusData data;
  ImpactWorkspace workspace;
  ImpactLocus locus;
};

std::unique_ptr<Fixture> make_fixture() {
  auto f = std::make_unique<Fixture>();
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &f->mission);
  EXPECT_EQ(prepare_case(f->mission, &f->prepared), Status::kOk);
  EXPECT_EQ(fly_trajectory(f->mission, f->prepared, &f->nominal), Status::kOk);
  test::build_reference_impact_data(&f->data);
  return f;
}

const ImpactCase* find_case(const ImpactLocus& locus, ImpactKind kind, int stage) {
  for (int i = 0; i < locus.count; ++i) {
    if (locus.cases[i].kind == kind && locus.cases[i].stage == stage) return &locus.cases[i];
  }
  return nullptr;
}

// Surface distance between two points given by geocentric latitude and Earth-fixed longitude, ft
// (great circle on the equatorial radius: at 0.1 nmi the figure's shape is immaterial).
double surface_distance_ft(const Constants& k, double lat1, double lon1, double lat2, double lon2) {
  return downrange_angle_rad(lat1, lon1, lat2, lon2) * k.earth_equatorial_radius_ft;
}

// ---- the independent integration ------------------------------------------------------------------

using Vector6 = Eigen::Matrix<double, 6, 1>;

// Inertial position and velocity derivative: textbook J2 gravity and drag against the velocity
// relative to the rotating atmosphere, q S C_D(M) from the same table, atmosphere and HAERO.
struct CartesianBallistic {
  const Mission& mission;
  const ImpactBody& body;
  double mass_slug;

  double altitude_ft(const Vector3& r) const {
    return oblate_altitude_ft(mission.constants, r.norm(), std::asin(r.z() / r.norm()));
  }
  Vector6 operator()(const Vector6& y) const {
    const Constants& k = mission.constants;
    const Vector3 r = y.head<3>();
    const Vector3 v = y.tail<3>();
    Vector3 a = test::j2_acceleration(k, r);
    const double h = altitude_ft(r);
    if (h <= k.haero_ft) {
      AtmosphereSample air;
      const double surface = oblate_radius_ft(k, std::asin(r.z() / r.norm()));
      if (ok(evaluate_atmosphere(mission.atmosphere, k, h, surface, &air))) {
        const Vector3 v_rel = v - Vector3(0.0, 0.0, k.earth_rotation_rate_rad_s).cross(r);
        const double speed = v_rel.norm();
        const double mach = speed / air.speed_of_sound_ft_s;
        const double drag = 0.5 * air.density_slug_ft3 * speed * speed * body.reference_area_ft2 *
                            body.drag_coefficient(mach);
        if (speed > 0.0) a -= (drag / mass_slug) * v_rel / speed;
      }
    }
    Vector6 d;
    d << v, a;
    return d;
  }
};

// One Dormand-Prince 5(4) step: the fifth-order solution and the error estimate.
template <typename F>
Vector6 dormand_prince_step(const F& f, const Vector6& y, double h, Vector6* error) {
  const Vector6 k1 = f(y);
  const Vector6 k2 = f(Vector6(y + h * (1.0 / 5.0) * k1));
  const Vector6 k3 = f(Vector6(y + h * (3.0 / 40.0 * k1 + 9.0 / 40.0 * k2)));
  const Vector6 k4 = f(Vector6(y + h * (44.0 / 45.0 * k1 - 56.0 / 15.0 * k2 + 32.0 / 9.0 * k3)));
  const Vector6 k5 = f(Vector6(
      y + h * (19372.0 / 6561.0 * k1 - 25360.0 / 2187.0 * k2 + 64448.0 / 6561.0 * k3 - 212.0 / 729.0 * k4)));
  const Vector6 k6 = f(Vector6(y + h * (9017.0 / 3168.0 * k1 - 355.0 / 33.0 * k2 + 46732.0 / 5247.0 * k3 +
                                        49.0 / 176.0 * k4 - 5103.0 / 18656.0 * k5)));
  const Vector6 y5 = y + h * (35.0 / 384.0 * k1 + 500.0 / 1113.0 * k3 + 125.0 / 192.0 * k4 -
                              2187.0 / 6784.0 * k5 + 11.0 / 84.0 * k6);
  const Vector6 k7 = f(y5);
  const Vector6 y4 = y + h * (5179.0 / 57600.0 * k1 + 7571.0 / 16695.0 * k3 + 393.0 / 640.0 * k4 -
                              92097.0 / 339200.0 * k5 + 187.0 / 2100.0 * k6 + 1.0 / 40.0 * k7);
  *error = y5 - y4;
  return y5;
}

struct IndependentImpact {
  double time_s = 0.0;  // from launch
  double geocentric_latitude_rad = 0.0;
  double longitude_rad = 0.0;  // Earth-fixed
};

// Adaptive integration (relative tolerance 1e-12 in position and velocity) to the first crossing of
// the oblate surface, found by bisection on the length of the step from the last point above it.
IndependentImpact integrate_independently(const Mission& mission, const ImpactBody& body, double weight_lb,
                                          double t0, const StateVector& x0) {
  const Constants& k = mission.constants;
  const CartesianBallistic f{mission, body, weight_lb / k.g0_ft_s2};
  const test::Cartesian c = test::to_cartesian(k, x0);
  Vector6 y;
  y << c.r, c.v;
  double t = t0;
  double h = 0.1;
  constexpr double kTolerance = 1e-12;
  for (int guard = 0; guard < 2000000; ++guard) {
    Vector6 error;
    const Vector6 trial = dormand_prince_step(f, y, h, &error);
    const double scale_r = trial.head<3>().norm();
    const double scale_v = std::fmax(trial.tail<3>().norm(), 1.0);
    const double err = std::fmax(error.head<3>().norm() / scale_r, error.tail<3>().norm() / scale_v);
    if (err > kTolerance && h > 1e-6) {
      h *= std::fmax(0.2, 0.9 * std::pow(kTolerance / err, 0.2));
      continue;
    }
    if (f.altitude_ft(trial.head<3>()) <= 0.0) {
      double lo = 0.0, hi = h;
      Vector6 hit = trial;
      for (int i = 0; i < 200 && hi - lo > 1e-10; ++i) {
        const double mid = 0.5 * (lo + hi);
        Vector6 e;
        const Vector6 m = dormand_prince_step(f, y, mid, &e);
        if (f.altitude_ft(m.head<3>()) > 0.0) {
          lo = mid;
        } else {
          hi = mid;
          hit = m;
        }
      }
      IndependentImpact out;
      out.time_s = t + hi;
      const Vector3 r = hit.head<3>();
      out.geocentric_latitude_rad = std::asin(r.z() / r.norm());
      out.longitude_rad =
          std::remainder(std::atan2(r.y(), r.x()) - k.earth_rotation_rate_rad_s * out.time_s, 2.0 * kPi);
      return out;
    }
    t += h;
    y = trial;
    h *= std::fmin(5.0, 0.9 * std::pow(kTolerance / std::fmax(err, 1e-30), 0.2));
    h = std::fmin(h, 5.0);
  }
  ADD_FAILURE() << "the independent integration did not reach the surface";
  return {};
}

TEST(Sec17Impact, ExpendedStage1CasingMatchesAnIndependentAdaptiveIntegration) {
  auto f = make_fixture();
  ASSERT_EQ(compute_impact_locus(f->mission, f->prepared, f->nominal, f->data, &f->workspace, &f->locus),
            Status::kOk);
  const ImpactCase* casing = find_case(f->locus, ImpactKind::kExpendedCasing, 1);
  ASSERT_NE(casing, nullptr);
  ASSERT_EQ(casing->status, Status::kOk);
  const TrajectoryPoint& burnout = f->nominal.points[casing->nominal_point];
  EXPECT_EQ(casing->failure_time_s, burnout.time_s);
  EXPECT_NEAR(burnout.time_s, 45.0, 1e-9);  // stage 1 burns 45 s
  const IndependentImpact truth =
      integrate_independently(f->mission, f->data.expended_casing[0],
                              f->data.expended_casing[0].casing_weight_lb, burnout.time_s, burnout.state);
  const double miss_ft =
      surface_distance_ft(f->mission.constants, casing->geocentric_latitude_rad, casing->longitude_rad,
                          truth.geocentric_latitude_rad, truth.longitude_rad);
  RecordProperty("stage1_casing_miss_ft", std::to_string(miss_ft));
  std::printf("stage-1 casing: impact %.3f s (independent %.3f s), downrange %.3f nmi, miss %.3f ft\n",
              casing->impact_time_s, truth.time_s, casing->downrange_rad * kNauticalMilesPerRadian, miss_ft);
  EXPECT_LT(miss_ft, 0.1 * kFtPerNmi);
  EXPECT_NEAR(casing->impact_time_s, truth.time_s, 0.5);
  // A tumbling casing (C_D about 9) is slowed to terminal velocity long before the ground.
  EXPECT_TRUE(casing->reached_terminal_velocity);
  EXPECT_GT(casing->impact_time_s, casing->failure_time_s + 60.0);
}

// Zero drag, zero J2, a spherical Earth (CT1(12) = 0): the flight is a Kepler ellipse in the
// inertial frame; the impact is where r = R_eq on its descending branch, at the time Kepler's
// equation gives. The closed form is for the sphere (the oblate crossing has none).
TEST(Sec17Impact, VacuumImpactMatchesTheKeplerEllipseOnASphericalEarth) {
  auto f = make_fixture();
  Mission& m = f->mission;
  m.constants.j2 = 0.0;
  m.constants.inverse_flattening = 0.0;
  ImpactBody vacuum;
  vacuum.present = true;
  ASSERT_EQ(vacuum.drag_coefficient.append(0.0, 0.0), Status::kOk);
  ASSERT_EQ(vacuum.drag_coefficient.append(10.0, 0.0), Status::kOk);
  ASSERT_EQ(vacuum.drag_coefficient.finalize(), Status::kOk);
  vacuum.reference_area_ft2 = 10.0;
  const Constants& k = m.constants;
  const double mu = k.gravitational_parameter_ft3_s2;
  const double re = k.earth_equatorial_radius_ft;

  const double t0 = 120.0;
  StateVector x0;
  x0 << 14000.0, 25.0 * kDegToRad, re + 400000.0, 100.0 * kDegToRad, 36.0 * kDegToRad, -1.2;
  ImpactFlight flight;
  ASSERT_EQ(
      fly_to_impact(m, f->prepared, vacuum, 1000.0, t0, x0, f->data.steps, &f->workspace.body_stage, &flight),
      Status::kOk);

  // The closed form.
  const test::Cartesian c = test::to_cartesian(k, x0);
  const Vector3 hv = c.r.cross(c.v);
  const Vector3 ev = c.v.cross(hv) / mu - c.r / c.r.norm();
  const double e = ev.norm();
  const double p = hv.squaredNorm() / mu;
  const double a = p / (1.0 - e * e);
  const Vector3 P = ev / e;
  const Vector3 Q = hv.normalized().cross(P);
  const double nu0 = std::atan2(c.r.dot(Q), c.r.dot(P));
  const double nu_hit = 2.0 * kPi - std::acos((p / re - 1.0) / e);  // descending branch, (pi, 2 pi)
  const auto mean_anomaly = [e](double nu) {
    const double E =
        2.0 * std::atan2(std::sqrt(1.0 - e) * std::sin(0.5 * nu), std::sqrt(1.0 + e) * std::cos(0.5 * nu));
    return E - e * std::sin(E);
  };
  double dm = mean_anomaly(nu_hit) - mean_anomaly(nu0);
  while (dm < 0.0) dm += 2.0 * kPi;
  const double t_hit = t0 + dm / std::sqrt(mu / (a * a * a));
  const Vector3 r_hit = re * (std::cos(nu_hit) * P + std::sin(nu_hit) * Q);
  const double lat_hit = std::asin(r_hit.z() / re);
  const double lon_hit =
      std::remainder(std::atan2(r_hit.y(), r_hit.x()) - k.earth_rotation_rate_rad_s * t_hit, 2.0 * kPi);

  const StateVector& x = flight.impact_state;
  const double lon =
      std::remainder(x[kStateTau] - k.earth_rotation_rate_rad_s * flight.impact_time_s, 2.0 * kPi);
  const double miss_ft = surface_distance_ft(k, x[kStateLambda], lon, lat_hit, lon_hit);
  std::printf("vacuum: impact %.4f s (Kepler %.4f s), flight %.1f s, miss %.3f ft\n", flight.impact_time_s,
              t_hit, t_hit - t0, miss_ft);
  EXPECT_GT(t_hit - t0, 300.0);  // a real arc, several regimes
  EXPECT_NEAR(flight.impact_time_s, t_hit, 0.01);
  EXPECT_LT(miss_ft, 20.0);
  EXPECT_NEAR(x[kStateR], re, 1e-3);
  EXPECT_GT(flight.regime_steps[static_cast<int>(ImpactRegime::kOutOfAtmosphere)], 0);
  EXPECT_GT(flight.regime_steps[static_cast<int>(ImpactRegime::kReentered)], 0);
}

// The crossing is found inside the step: the impact state lies on the oblate surface, and a coarse
// terminal-velocity step moves the impact time by far less than a step (stopping at the first
// point below would move it by up to one).
TEST(Sec17Impact, SurfaceCrossingIsFoundInsideTheLastStep) {
  auto f = make_fixture();
  const TrajectoryPoint& burnout = f->nominal.points[f->nominal.stages[0].last_point];
  const ImpactBody& body = f->data.expended_casing[0];
  ImpactFlight fine, coarse;
  ASSERT_EQ(fly_to_impact(f->mission, f->prepared, body, body.casing_weight_lb, burnout.time_s, burnout.state,
                          f->data.steps, &f->workspace.body_stage, &fine),
            Status::kOk);
  EXPECT_NEAR(
      oblate_altitude_ft(f->mission.constants, fine.impact_state[kStateR], fine.impact_state[kStateLambda]),
      0.0, 1e-3);
  ImpactStepSizes steps = f->data.steps;
  steps.terminal_velocity_s = 8.0;
  ASSERT_EQ(fly_to_impact(f->mission, f->prepared, body, body.casing_weight_lb, burnout.time_s, burnout.state,
                          steps, &f->workspace.body_stage, &coarse),
            Status::kOk);
  EXPECT_NEAR(coarse.impact_time_s, fine.impact_time_s, 0.05);
  EXPECT_GT(coarse.regime_steps[static_cast<int>(ImpactRegime::kTerminalVelocity)], 0);
}

// The locus: every n-th integration point of stages 1-3 (stage 1 after the lift-off), then the three
// casings; each case from its nominal point, impacting later, downrange of the launch site.
TEST(Sec17Impact, LocusCoversEveryNthPointOfStages1To3AndTheCasings) {
  auto f = make_fixture();
  f->data.every_nth_point[0] = 3;
  f->data.every_nth_point[1] = 1;
  f->data.every_nth_point[2] = 4;
  ASSERT_EQ(compute_impact_locus(f->mission, f->prepared, f->nominal, f->data, &f->workspace, &f->locus),
            Status::kOk);
  int expected[kImpactStages] = {};
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    const StageEvent& e = f->nominal.stages[2 * (stage - 1)];  // sequence 1 6 2 7 3 8 4
    ASSERT_EQ(e.code, stage);
    int first = e.first_point;
    while (f->nominal.points[first].time_s < f->mission.launch.liftoff_duration_s - 1e-6) ++first;
    expected[stage - 1] =
        (e.last_point - first + f->data.every_nth_point[stage - 1] - 1) / f->data.every_nth_point[stage - 1];
  }
  EXPECT_EQ(f->locus.count, expected[0] + expected[1] + expected[2] + 3);
  double previous_time = -1.0;
  for (int i = 0; i < f->locus.count; ++i) {
    const ImpactCase& c = f->locus.cases[i];
    EXPECT_EQ(c.status, Status::kOk) << i;
    EXPECT_EQ(c.failure_time_s, f->nominal.points[c.nominal_point].time_s);
    EXPECT_GT(c.impact_time_s, c.failure_time_s) << i;
    EXPECT_GT(c.downrange_rad, 0.0) << i;
    if (c.kind == ImpactKind::kThrustFailure) {
      EXPECT_GT(c.failure_time_s, previous_time);
      EXPECT_EQ(c.weight_lb, f->nominal.points[c.nominal_point].weight_lb);
      previous_time = c.failure_time_s;
    }
  }
  EXPECT_NEAR(f->locus.cases[0].failure_time_s, f->mission.launch.liftoff_duration_s, 1e-9);
  // A later failure falls farther downrange (stage 3's last failure beyond stage 1's first).
  EXPECT_GT(f->locus.cases[f->locus.count - 4].downrange_rad, f->locus.cases[0].downrange_rad);
  EXPECT_EQ(f->locus.cases[f->locus.count - 1].kind, ImpactKind::kExpendedCasing);
  EXPECT_EQ(f->locus.cases[f->locus.count - 1].stage, 3);
}

// The default INTPIM steps against steps ten times smaller, every case of the reference locus: the
// step sizes change no impact point by more than the 0.1 n.mi. asked of the independent check.
TEST(Sec17Impact, DefaultStepsAgreeWithStepsTenTimesSmallerOverTheWholeLocus) {
  auto f = make_fixture();
  ASSERT_EQ(compute_impact_locus(f->mission, f->prepared, f->nominal, f->data, &f->workspace, &f->locus),
            Status::kOk);
  auto fine = std::make_unique<ImpactLocus>();
  ImpactLocusData fine_data = f->data;
  ImpactStepSizes& s = fine_data.steps;
  s.in_atmosphere_s /= 10.0;
  s.out_of_atmosphere_s /= 10.0;
  s.reentered_s /= 10.0;
  s.terminal_velocity_s /= 10.0;
  s.max_drag_velocity_fraction /= 10.0;
  ASSERT_EQ(compute_impact_locus(f->mission, f->prepared, f->nominal, fine_data, &f->workspace, fine.get()),
            Status::kOk);
  ASSERT_EQ(fine->count, f->locus.count);
  double worst_ft = 0.0, worst_s = 0.0;
  int worst_case = 0;
  for (int i = 0; i < f->locus.count; ++i) {
    const ImpactCase& a = f->locus.cases[i];
    const ImpactCase& b = fine->cases[i];
    const double miss_ft = surface_distance_ft(f->mission.constants, a.geocentric_latitude_rad,
                                               a.longitude_rad, b.geocentric_latitude_rad, b.longitude_rad);
    if (miss_ft > worst_ft) worst_case = i;
    worst_ft = std::fmax(worst_ft, miss_ft);
    worst_s = std::fmax(worst_s, std::fabs(a.impact_time_s - b.impact_time_s));
  }
  std::printf(
      "default vs 10x finer steps, %d cases: worst %.2f ft (case %d, stage %d, from %.1f s), %.3f s\n",
      f->locus.count, worst_ft, worst_case, f->locus.cases[worst_case].stage,
      f->locus.cases[worst_case].failure_time_s, worst_s);
  EXPECT_LT(worst_ft, 0.1 * kFtPerNmi);  // the accuracy asked of the independent check
  EXPECT_LT(worst_s, 0.1);
}

TEST(Sec17Impact, CrossrangeIsSignedFromTheLaunchAzimuthGreatCircle) {
  const double lat0 = 37.6 * kDegToRad, lon0 = -75.5 * kDegToRad;
  // Due east from the launch point along the azimuth-90 great circle: on it; north of it: left.
  EXPECT_NEAR(launch_crossrange_angle_rad(lat0, lon0, 0.0, lat0 + 0.1, lon0), 0.0, 1e-15);
  EXPECT_LT(launch_crossrange_angle_rad(lat0, lon0, 90.0 * kDegToRad, lat0 + 0.01, lon0 + 0.02), 0.0);
  EXPECT_GT(launch_crossrange_angle_rad(lat0, lon0, 90.0 * kDegToRad, lat0 - 0.01, lon0 + 0.02), 0.0);
  // Due south of the launch point with a northward azimuth: on the great circle (behind it).
  EXPECT_NEAR(launch_crossrange_angle_rad(lat0, lon0, 0.0, lat0 - 0.2, lon0), 0.0, 1e-15);
  // 0.01 rad east on the equator with azimuth north: 0.01 rad to the right.
  EXPECT_NEAR(launch_crossrange_angle_rad(0.0, 0.0, 0.0, 0.0, 0.01), 0.01, 1e-12);
}

TEST(Sec17Impact, ValidationNamesTheDataBlockStageAndWord) {
  auto f = make_fixture();
  ImpactFault fault;
  EXPECT_EQ(validate_impact_data(f->mission, f->data, &fault), Status::kOk);

  ImpactLocusData missing = f->data;
  missing.failure_mode[1].present = false;
  EXPECT_EQ(validate_impact_data(f->mission, missing, &fault), Status::kImpactDataMissing);
  EXPECT_EQ(fault.data_block, 42);
  EXPECT_EQ(fault.stage, 2);
  EXPECT_STREQ(fault.field, "CD2F");

  ImpactLocusData past = f->data;
  past.every_nth_point[2] = f->mission.vehicle.stages[2].integration_steps + 1;
  EXPECT_EQ(validate_impact_data(f->mission, past, &fault), Status::kImpactEveryNthPointOutOfRange);
  EXPECT_EQ(fault.data_block, 33);
  EXPECT_STREQ(fault.field, "DA6D(19)");

  ImpactLocusData weightless = f->data;
  weightless.expended_casing[0].casing_weight_lb = 0.0;
  EXPECT_EQ(validate_impact_data(f->mission, weightless, &fault), Status::kImpactCasingWeightNotPositive);
  EXPECT_EQ(fault.data_block, 43);
  EXPECT_STREQ(fault.field, "casing weight");
  // The locus refuses the same data before it flies anything.
  EXPECT_EQ(compute_impact_locus(f->mission, f->prepared, f->nominal, past, &f->workspace, &f->locus),
            Status::kImpactEveryNthPointOutOfRange);
  EXPECT_EQ(f->locus.count, 0);
}

}  // namespace
}  // namespace tolip
