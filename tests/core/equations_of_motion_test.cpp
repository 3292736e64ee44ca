// Sec. 4 equations of motion F..K against the oracle and against an independent inertial
// (Cartesian) model of the same forces, which is how the printed J2 sign error in F is found.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/cartesian_model.hpp"
#include "support/reference_data.hpp"
#include "tolip/dynamics/equations_of_motion.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"

namespace tolip {
namespace {

using test::Cartesian;
using test::from_cartesian;
using test::j2_acceleration;
using test::to_cartesian;

Matrix3 json_to_matrix(const nlohmann::json& j) {
  Matrix3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = j[r][c].get<double>();
  return m;
}

// dX/dt by a central difference of the Cartesian-to-state map along (v, a): exact to O(h^2).
StateVector cartesian_rates(const Constants& k, const StateVector& x, const AppliedForces& forces) {
  const Cartesian c = to_cartesian(k, x);
  const Matrix3 a = inertial_to_local(x);
  const Vector3 local_force(forces.thrust_local_lbf.x(), forces.thrust_local_lbf.y() - forces.drag_lbf,
                            forces.thrust_local_lbf.z() + forces.lift_lbf);
  const Vector3 acc = j2_acceleration(k, c.r) + a.transpose() * local_force / forces.mass_slug;
  const double h = 1e-3;
  const StateVector xp = from_cartesian(k, {c.r + h * c.v, c.v + h * acc});
  const StateVector xm = from_cartesian(k, {c.r - h * c.v, c.v - h * acc});
  StateVector d = (xp - xm) / (2.0 * h);
  d[kStateTau] = std::remainder(xp[kStateTau] - xm[kStateTau], 2.0 * kPi) / (2.0 * h);
  d[kStatePsi] = std::remainder(xp[kStatePsi] - xm[kStatePsi], 2.0 * kPi) / (2.0 * h);
  return d;
}

AppliedForces random_forces(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  AppliedForces f;
  f.mass_slug = 500.0;
  f.thrust_local_lbf = Vector3(3000.0 * u(rng), 40000.0 * (1.2 + u(rng)), 8000.0 * u(rng));
  f.drag_lbf = 2000.0 * (1.0 + u(rng));
  f.lift_lbf = 1000.0 * u(rng);
  return f;
}

TEST(Sec4EquationsOfMotion, AgreeWithIndependentCartesianModel) {
  const Constants k;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    StateVector x;
    x << 3000.0 + 20000.0 * (1.0 + u(rng)) / 2.0, 1.2 * u(rng), 2.1e7 + 1.5e6 * (1.0 + u(rng)), 3.0 * u(rng),
        1.2 * u(rng), 3.0 * u(rng);
    const AppliedForces f = random_forces(rng);
    const StateVector mine = state_derivative(k, x, f);
    const StateVector truth = cartesian_rates(k, x, f);
    for (int i = 0; i < 6; ++i) {
      const double scale = std::fabs(truth[i]) + (i == kStateR ? 1.0 : i == kStateV ? 1e-3 : 1e-9);
      EXPECT_LT(std::fabs(mine[i] - truth[i]) / scale, 1e-6) << "component " << i << " trial " << trial;
    }
  }
}

// The printed F has -J2/2 in its radial term; the Cartesian model says +J2/2. This test shows the
// independent model distinguishes the two (the difference is far above its own error).
TEST(Sec4EquationsOfMotion, PrintedJ2SignInFContradictsCartesianModel) {
  const Constants k;
  StateVector x;
  x << 8000.0, 0.6, 2.12e7, 1.8, 0.65, -1.3;
  AppliedForces f;
  f.mass_slug = 400.0;
  const StateVector mine = state_derivative(k, x, f);
  const StateVector truth = cartesian_rates(k, x, f);
  const double g = k.gravitational_parameter_ft3_s2 / (x[2] * x[2]);
  const double printed_minus_mine = g * k.j2 * std::pow(k.earth_equatorial_radius_ft / x[2], 2) *
                                    (3.0 - 9.0 * std::pow(std::sin(x[4]), 2)) * std::sin(x[1]);
  EXPECT_LT(std::fabs(mine[kStateV] - truth[kStateV]), 1e-7);
  EXPECT_GT(std::fabs(mine[kStateV] + printed_minus_mine - truth[kStateV]), 1e-3);
}

// The oracle's derivatives at 11 trajectory points, given the same thrust, weight, drag, lift and
// attitude the oracle used there.
TEST(Sec4EquationsOfMotion, MatchOracleDerivativesAlongReferenceTrajectory) {
  const auto& v = test::oracle_test_vectors();
  const auto& launch = v["launch"];
  const Constants k;
  const Matrix3 bbp = json_to_matrix(launch["BBprime"]);
  for (const auto& point : v["derivatives"]) {
    StateVector x;
    for (int i = 0; i < 6; ++i) x[i] = point["state"][i];
    const double theta = point["theta_rad"];
    const double chi = point.value("chi_rad", 0.0);
    const Vector3 axis = inertial_to_local(x) * bbp * thrust_axis_platform(theta, chi);
    AppliedForces f;
    f.mass_slug = point["weight_lb"].get<double>() / k.g0_ft_s2;
    f.thrust_local_lbf = point["net_thrust_lbf"].get<double>() * axis;
    f.drag_lbf = point["drag_lbf"];
    f.lift_lbf = point["lift_lbf"];
    f.heading_hold = point["heading_hold"];
    EXPECT_NEAR(angle_of_attack_rad(axis), point["alpha_rad"].get<double>(), 1e-12);
    const StateVector d = state_derivative(k, x, f);
    for (int i = 0; i < 6; ++i) {
      const double ref = point["derivatives_F_G_I_H_J_K"][i];
      EXPECT_NEAR(d[i], ref, 1e-11 * std::fabs(ref) + 1e-15) << "t " << point["t_s"] << " component " << i;
    }
  }
}

}  // namespace
}  // namespace tolip
