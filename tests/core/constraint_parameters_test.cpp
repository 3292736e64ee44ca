// Constraint parameters of data block 8 and their adjoint initial conditions (manual Sec. 5
// "INITIAL CONDITIONS FOR INTEGRATION OF THE ADJOINT EQUATIONS", subroutine ICS, Addendum H5.5).
//
// Every analytic partial is checked against a fourth-order central difference of
// constraint_value() at several states (the oracle's circular burnout, its suborbital stage-3
// burnout, its inclined eccentric orbit, a near-circular orbit, an eastward-heading state, a
// low atmospheric state, two hyperbolic states). The printed partials are also evaluated as
// printed and compared with differences in the inertial variables, which proves each misprint
// listed in docs/theory/constraints-and-ics.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "support/reference_data.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/orbit/orbit_elements.hpp"

namespace tolip {
namespace {

constexpr double kTwoPi = 2.0 * kPi;
using Vector7 = Eigen::Matrix<double, 7, 1>;

using test::state_from_json;

StateVector oracle_state(std::size_t n) {
  return state_from_json(test::oracle_test_vectors().at("orbit_elements").at(n).at("state"));
}

// The state whose inertial velocity is (V_I, gamma_I, psi_I) at (r, lambda, tau).
StateVector state_from_inertial(const Constants& c, double r, double lat, double tau, double v_i,
                                double gamma_i, double psi_i) {
  const double up = v_i * std::sin(gamma_i);
  const double north = v_i * std::cos(gamma_i) * std::cos(psi_i);
  const double east =
      v_i * std::cos(gamma_i) * std::sin(psi_i) - c.earth_rotation_rate_rad_s * r * std::cos(lat);
  StateVector x;
  x << std::sqrt(up * up + north * north + east * east), std::atan2(up, std::hypot(north, east)), r,
      std::atan2(east, north), lat, tau;
  return x;
}

// Wallops Island launch of the reference case (reference README Sec. 3).
LaunchConditions reference_launch() {
  LaunchConditions l;
  l.launch_space_age_date_days = 2373.625;
  l.longitude_rad = -75.48 * kDegToRad;
  l.geocentric_latitude_rad = 37.653239661 * kDegToRad;
  l.altitude_ft = 10.0;
  l.azimuth_rad = 100.0 * kDegToRad;
  l.flight_path_angle_rad = 90.0 * kDegToRad;
  return l;
}

// An exponential atmosphere with its exact altitude derivative, so that the q-bar and heating
// partials can be differenced exactly (the Sec. 19 table's d()/dh is d()/dH*, see the note).
constexpr double kSeaLevelDensity = 2.3769e-3;
constexpr double kScaleHeight_ft = 23800.0;

constexpr double kTimeFromLaunch_s = 600.0;
constexpr double kMass_slug = 12.7;

// The point of a 7-vector [V, gamma, r, psi, lambda, tau, m].
ConstraintPoint make_point(const Constants& c, const Vector7& y, double heating = 1234.5) {
  ConstraintPoint p;
  p.state = y.head<6>();
  p.time_from_launch_s = kTimeFromLaunch_s;
  p.weight_lb = c.g0_ft_s2 * y(kAdjointMass);
  const double h = oblate_altitude_ft(c, y(kStateR), y(kStateLambda));
  p.density_slug_ft3 = kSeaLevelDensity * std::exp(-h / kScaleHeight_ft);
  p.ddensity_dh = -p.density_slug_ft3 / kScaleHeight_ft;
  p.total_heating_btu_ft2 = heating;
  return p;
}

Vector7 with_mass(const StateVector& x) {
  Vector7 y;
  y.head<6>() = x;
  y(kAdjointMass) = kMass_slug;
  return y;
}

struct NamedState {
  std::string name;
  StateVector x;
};

// States of the tests.
NamedState circular_burnout() { return {"oracle circular burnout", oracle_state(0)}; }
NamedState suborbital_stage3() { return {"oracle suborbital stage-3 burnout", oracle_state(1)}; }
NamedState inclined_eccentric() { return {"oracle inclined eccentric (south)", oracle_state(2)}; }
NamedState near_circular() {
  StateVector x = oracle_state(0);
  x(kStateV) *= 1.0005;
  x(kStateGamma) = 0.002;  // e ~ 2e-3
  return {"near-circular e~2e-3", x};
}
NamedState eastward() {
  StateVector x = oracle_state(2);
  x(kStatePsi) = 0.5 * kPi;  // cos psi = 0: the printed INER psi_I partials are 0/0 here
  x(kStateGamma) = 0.0;      // gamma_I = 0: the printed true-anomaly partials are 0/0 here
  return {"eastward, gamma = 0", x};
}
NamedState atmospheric() {
  const Constants c;
  StateVector x;
  x << 4500.0, 0.6, oblate_radius_ft(c, 0.66) + 90000.0, 1.75, 0.66, -1.30;
  return {"atmospheric (90 kft)", x};
}
NamedState hyperbolic_north() {
  const Constants c;
  return {"hyperbolic north", state_from_inertial(c, 2.15e7, 0.35, 0.7, 40000.0, 0.17, 1.2)};
}
NamedState hyperbolic_south() {
  const Constants c;
  return {"hyperbolic south, descending", state_from_inertial(c, 2.3e7, -0.5, 2.9, 37500.0, 0.05, 2.4)};
}

std::vector<NamedState> orbital_states() {
  return {circular_burnout(), suborbital_stage3(), inclined_eccentric(), near_circular(), eastward()};
}

bool is_angle_code(int code) { return code == 12 || code == 13 || code == 101; }

// Steps of the central differences and the "typical perturbation" that sets each component's
// absolute floor: [V ft/s, gamma rad, r ft, psi rad, lambda rad, tau rad, m slug].
const double kStep[7] = {0.1, 1e-5, 100.0, 1e-5, 1e-5, 1e-5, 1e-2};
const double kTypical[7] = {1.0, 1e-4, 100.0, 1e-4, 1e-4, 1e-4, 1.0};

// Fourth-order central difference of f along component i; angle-valued f is unwrapped.
double central_difference(const std::function<double(const Vector7&)>& f, const Vector7& y, int i,
                          double step, bool angle) {
  const double f0 = f(y);
  auto at = [&](double k) {
    Vector7 z = y;
    z(i) += k * step;
    const double d = f(z) - f0;
    return angle ? std::remainder(d, kTwoPi) : d;
  };
  return (at(-2.0) - 8.0 * at(-1.0) + 8.0 * at(1.0) - at(2.0)) / (12.0 * step);
}

struct Agreement {
  double max_rel = 0.0;  // over components well above the difference's noise
  bool ok = true;
  std::string detail;
};

// Analytic partials against differences: component i passes if
// |a - fd| <= tol |fd| + floor_i, floor_i = 1e-9 max_j |fd_j| typical_j / typical_i (a change
// below a billionth of the largest typical first-order change) + 100 eps max(|f0|, 1) / step_i
// (the round-off of the differenced values).
Agreement compare(const Eigen::VectorXd& analytic, const Eigen::VectorXd& fd, double f0, const double* steps,
                  const double* typical, double tol, double noise_factor = 1.0) {
  Agreement a;
  const auto n = fd.size();
  double largest = 0.0;
  for (Eigen::Index j = 0; j < n; ++j) largest = std::max(largest, std::fabs(fd(j)) * typical[j]);
  const double eps = std::numeric_limits<double>::epsilon();
  for (Eigen::Index i = 0; i < n; ++i) {
    const double err = std::fabs(analytic(i) - fd(i));
    const double floor =
        1e-9 * largest / typical[i] + noise_factor * 100.0 * eps * std::max(std::fabs(f0), 1.0) / steps[i];
    if (err > tol * std::fabs(fd(i)) + floor) {
      a.ok = false;
      char buf[200];
      std::snprintf(buf, sizeof buf, " [component %d: analytic %.12e, difference %.12e]", static_cast<int>(i),
                    analytic(i), fd(i));
      a.detail += buf;
    }
    if (std::fabs(fd(i)) > 1e3 * floor) a.max_rel = std::max(a.max_rel, err / std::fabs(fd(i)));
  }
  return a;
}

Agreement compare(const Vector7& analytic, const Vector7& fd, double f0, double tol) {
  return compare(Eigen::VectorXd(analytic), Eigen::VectorXd(fd), f0, kStep, kTypical, tol);
}

Vector7 differences_of_value(const Constants& c, const LaunchConditions& launch, const ConstraintCode& code,
                             const Vector7& y) {
  auto f = [&](const Vector7& z) {
    double v = 0.0;
    const Status s = constraint_value(c, launch, code, make_point(c, z), &v);
    EXPECT_EQ(s, Status::kOk) << "code " << code.code;
    return v;
  };
  Vector7 fd;
  for (int i = 0; i < 7; ++i) fd(i) = central_difference(f, y, i, kStep[i], is_angle_code(code.code));
  return fd;
}

// Checks one code at the given states; returns the worst relative error.
double expect_partials_match(int code_number, const std::vector<NamedState>& states, double tol = 1e-6) {
  const Constants c;
  const LaunchConditions launch = reference_launch();
  ConstraintCode code;
  EXPECT_EQ(decode_constraint_code(code_number, &code), Status::kOk);
  double worst = 0.0;
  for (const NamedState& s : states) {
    const Vector7 y = with_mass(s.x);
    AdjointVector analytic;
    const Status st = constraint_partials(c, launch, code, make_point(c, y), &analytic);
    EXPECT_EQ(st, Status::kOk) << "code " << code_number << " at " << s.name;
    if (st != Status::kOk) continue;
    const Vector7 fd = differences_of_value(c, launch, code, y);
    double f0 = 0.0;
    EXPECT_EQ(constraint_value(c, launch, code, make_point(c, y), &f0), Status::kOk);
    const Agreement a = compare(analytic, fd, f0, tol);
    EXPECT_TRUE(a.ok) << "code " << code_number << " at " << s.name << a.detail;
    worst = std::max(worst, a.max_rel);
  }
  std::printf(
      "[ figures  ] Sec5 ICS code %3d: analytic vs central differences, max rel err %.2e over %zu states\n",
      code_number, worst, states.size());
  return worst;
}

// ---- Decoding -----------------------------------------------------------------------------------

TEST(Sec5Ics, DecodesEveryBlock8CodeAndRejectsUnknownOnesByName) {
  for (int code = 0; code <= 14; ++code) {
    ConstraintCode d;
    ASSERT_EQ(decode_constraint_code(code, &d), Status::kOk) << code;
    EXPECT_FALSE(d.is_stage_point);
    EXPECT_EQ(d.stage_code, 0);
    EXPECT_EQ(d.quantity, code);
    EXPECT_EQ(static_cast<int>(d.kind), code);
  }
  const ConstraintQuantity stage_kinds[5] = {
      ConstraintQuantity::kAerodynamicVelocity, ConstraintQuantity::kAerodynamicFlightPathAngle,
      ConstraintQuantity::kAltitude, ConstraintQuantity::kDownrange, ConstraintQuantity::kDynamicPressure};
  for (int stage = 1; stage <= 9; ++stage) {
    for (int q = 0; q <= 9; ++q) {
      const int code = 10 * stage + q;
      ConstraintCode d;
      d.code = -77;
      const Status s = decode_constraint_code(code, &d);
      if (code <= 14) continue;  // terminal codes 10..14
      if (q >= 5) {
        ASSERT_EQ(s, Status::kOk) << code;
        EXPECT_TRUE(d.is_stage_point);
        EXPECT_EQ(d.stage_code, stage);
        EXPECT_EQ(d.quantity, q);
        EXPECT_EQ(d.kind, stage_kinds[q - 5]) << code;
      } else {
        EXPECT_EQ(s, Status::kUnknownConstraintCode) << code;
        EXPECT_EQ(d.code, -77) << "output untouched on failure";
      }
    }
  }
  ConstraintCode d;
  ASSERT_EQ(decode_constraint_code(100, &d), Status::kOk);
  EXPECT_EQ(d.kind, ConstraintQuantity::kHyperbolicExcessVelocity);
  ASSERT_EQ(decode_constraint_code(101, &d), Status::kOk);
  EXPECT_EQ(d.kind, ConstraintQuantity::kAsymptoteRightAscension);
  ASSERT_EQ(decode_constraint_code(102, &d), Status::kOk);
  EXPECT_EQ(d.kind, ConstraintQuantity::kAsymptoteDeclination);
  EXPECT_FALSE(d.is_stage_point);
  for (int bad : {-1, -15, 103, 105, 109, 110, 115, 999, 1000}) {
    EXPECT_EQ(decode_constraint_code(bad, &d), Status::kUnknownConstraintCode) << bad;
  }
  EXPECT_STREQ(status_name(Status::kUnknownConstraintCode), "kUnknownConstraintCode");
  EXPECT_EQ(decode_constraint_code(1, nullptr), Status::kOutputPointerNull);

  // A hand-made code that decode_constraint_code would not produce is rejected too.
  const Constants c;
  const LaunchConditions launch = reference_launch();
  ConstraintCode forged;
  forged.code = 9;
  forged.kind = ConstraintQuantity::kDynamicPressure;  // 9 is 2E when terminal
  const ConstraintPoint p = make_point(c, with_mass(oracle_state(0)));
  double v = 0.0;
  AdjointVector g;
  EXPECT_EQ(constraint_value(c, launch, forged, p, &v), Status::kUnknownConstraintCode);
  EXPECT_EQ(constraint_partials(c, launch, forged, p, &g), Status::kUnknownConstraintCode);
}

// ---- INER partials ------------------------------------------------------------------------------

TEST(Sec5Ics, InertialVariablePartialsMatchCentralDifferences) {
  const Constants c;
  std::vector<NamedState> states = orbital_states();
  states.push_back(atmospheric());
  states.push_back(hyperbolic_north());
  double worst = 0.0;
  for (const NamedState& s : states) {
    InertialJacobian j;
    ASSERT_EQ(inertial_variable_partials(c, s.x, &j), Status::kOk) << s.name;
    for (int row = 0; row < 3; ++row) {
      auto f = [&](const Vector7& z) {
        const InertialVelocity iv = inertial_velocity(c, z.head<6>());
        return row == 0 ? iv.velocity_ft_s : row == 1 ? iv.flight_path_angle_rad : iv.azimuth_rad;
      };
      Vector7 fd, an;
      const Vector7 y = with_mass(s.x);
      for (int i = 0; i < 7; ++i) fd(i) = central_difference(f, y, i, kStep[i], row == 2);
      an.head<6>() = j.row(row).transpose();
      an(6) = 0.0;
      const Agreement a = compare(an, fd, f(y), 1e-6);
      EXPECT_TRUE(a.ok) << "row " << row << " at " << s.name << a.detail;
      worst = std::max(worst, a.max_rel);
    }
  }
  std::printf("[ figures  ] Sec5 ICS INER partials dV_I, dgamma_I, dpsi_I: max rel err %.2e\n", worst);
}

// The printed INER partials (Sec. 5, "PARTIAL DERIVATIVES OF INERTIAL TRAJECTORY VARIABLES"),
// evaluated as printed where they are regular; all of them are right, including
// dV_I/dgamma = -(omega r cos lambda) sin gamma_I sin psi (sin gamma_I = V sin gamma / V_I).
TEST(Sec5Ics, PrintedInerPartialsAreCorrectAsPrinted) {
  const Constants c;
  const double w = c.earth_rotation_rate_rad_s;
  for (const NamedState& s : {suborbital_stage3(), inclined_eccentric(), atmospheric(), hyperbolic_north()}) {
    const StateVector& x = s.x;
    const double v = x(0), gam = x(1), r = x(2), psi = x(3), lat = x(4);
    const InertialVelocity iv = inertial_velocity(c, x);
    const double vi = iv.velocity_ft_s, gi = iv.flight_path_angle_rad, pi_ = iv.azimuth_rad;
    const double ur = w * r * std::cos(lat);  // "ur cos lambda"
    const double k = std::cos(pi_) * std::cos(pi_) / (v * std::cos(gam) * std::cos(psi));
    const double cross = (v * std::cos(gam) * std::sin(psi)) * ur + ur * ur;
    InertialJacobian printed;
    printed.setZero();
    printed(0, kStateV) = (v + ur * std::cos(gam) * std::sin(psi)) / vi;
    printed(0, kStateR) = cross / (r * vi);
    printed(0, kStateGamma) = -ur * std::sin(gi) * std::sin(psi);
    printed(0, kStatePsi) = ur * v * std::cos(gam) * std::cos(psi) / vi;
    printed(0, kStateLambda) = -std::tan(lat) * cross / vi;
    const double tg = std::tan(gi) / vi;
    printed(1, kStateV) = tg * (vi / v - printed(0, kStateV));
    printed(1, kStateR) = -tg * printed(0, kStateR);
    printed(1, kStateGamma) = v / vi * std::cos(gam) / std::cos(gi) - tg * printed(0, kStateGamma);
    printed(1, kStatePsi) = -tg * printed(0, kStatePsi);
    printed(1, kStateLambda) = -tg * printed(0, kStateLambda);
    printed(2, kStateV) = -ur / v * k;
    printed(2, kStateR) = ur / r * k;
    printed(2, kStateGamma) = ur * std::tan(gam) * k;
    printed(2, kStatePsi) = std::pow(std::cos(pi_) / std::cos(psi), 2) + std::tan(psi) * ur * k;
    printed(2, kStateLambda) = -w * r * std::sin(lat) * k;
    InertialJacobian j;
    ASSERT_EQ(inertial_variable_partials(c, x, &j), Status::kOk);
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 6; ++col) {
        EXPECT_NEAR(j(row, col), printed(row, col), 1e-10 * std::max(1.0, std::fabs(printed(row, col))))
            << s.name << " row " << row << " col " << col;
      }
    }
  }
}

// ---- Every code: analytic partials against central differences of the value -----------------

TEST(Sec5Ics, PayloadPartialIsG0PerSlugOfFinalMass) {
  const std::vector<NamedState> states = {circular_burnout(), inclined_eccentric()};
  expect_partials_match(0, states);
  const Constants c;
  ConstraintCode code;
  ASSERT_EQ(decode_constraint_code(0, &code), Status::kOk);
  AdjointVector g;
  ASSERT_EQ(constraint_partials(c, reference_launch(), code, make_point(c, with_mass(oracle_state(0))), &g),
            Status::kOk);
  EXPECT_EQ(g(kAdjointMass), 32.174);
  EXPECT_EQ(g.head<6>().norm(), 0.0);
  double w = 0.0;
  ASSERT_EQ(constraint_value(c, reference_launch(), code, make_point(c, with_mass(oracle_state(0))), &w),
            Status::kOk);
  EXPECT_DOUBLE_EQ(w, 32.174 * kMass_slug);
}

TEST(Sec5Ics, InertialVelocityPartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(hyperbolic_north());
  s.push_back(atmospheric());
  expect_partials_match(1, s);
}

TEST(Sec5Ics, InertialPathAnglePartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(hyperbolic_north());
  s.push_back(atmospheric());
  expect_partials_match(2, s);
}

TEST(Sec5Ics, VelocityOverCircularPartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(hyperbolic_north());
  expect_partials_match(3, s);
}

TEST(Sec5Ics, RadiusPartialsMatchCentralDifferences) { expect_partials_match(4, orbital_states()); }
TEST(Sec5Ics, AerodynamicVelocityPartialsMatchCentralDifferences) {
  expect_partials_match(5, orbital_states());
}
TEST(Sec5Ics, AerodynamicPathAnglePartialsMatchCentralDifferences) {
  expect_partials_match(6, orbital_states());
}

TEST(Sec5Ics, AltitudePartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(atmospheric());
  expect_partials_match(7, s);
}

TEST(Sec5Ics, DownrangePartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(atmospheric());
  s.push_back(hyperbolic_south());
  expect_partials_match(8, s);
}

TEST(Sec5Ics, TwiceEnergyPartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(hyperbolic_north());
  expect_partials_match(9, s);
}

TEST(Sec5Ics, InclinationPartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(hyperbolic_north());
  s.push_back(hyperbolic_south());
  expect_partials_match(10, s);
}

TEST(Sec5Ics, PerigeeRadiusPartialsMatchCentralDifferences) {
  // Not the circular burnout: r_p has a kink there (see SingularStatesFailWithNamedStatus).
  expect_partials_match(11, {suborbital_stage3(), inclined_eccentric(), near_circular(), eastward(),
                             hyperbolic_north(), hyperbolic_south()});
}

TEST(Sec5Ics, NodeLongitudePartialsMatchCentralDifferences) {
  std::vector<NamedState> s = orbital_states();
  s.push_back(hyperbolic_north());
  s.push_back(hyperbolic_south());
  expect_partials_match(12, s);
}

TEST(Sec5Ics, ArgumentOfPerigeePartialsMatchCentralDifferences) {
  expect_partials_match(13, {suborbital_stage3(), inclined_eccentric(), near_circular(), eastward(),
                             hyperbolic_north(), hyperbolic_south()});
}

TEST(Sec5Ics, TotalHeatingIsTheCallersIntegralWithZeroInitialAdjoint) {
  expect_partials_match(14, {circular_burnout(), atmospheric()});
  const Constants c;
  ConstraintCode code;
  ASSERT_EQ(decode_constraint_code(14, &code), Status::kOk);
  double q = 0.0;
  ASSERT_EQ(
      constraint_value(c, reference_launch(), code, make_point(c, with_mass(oracle_state(1)), 987.0), &q),
      Status::kOk);
  EXPECT_EQ(q, 987.0);
}

TEST(Sec5Ics, StagePointCodesMatchCentralDifferences) {
  const std::vector<NamedState> states = {atmospheric(), suborbital_stage3(), inclined_eccentric()};
  for (int stage : {1, 3, 6, 9}) {
    for (int q = 5; q <= 9; ++q) {
      const int code = 10 * stage + q;
      expect_partials_match(code, states);
      // The stage-point forms X5..X8 are the terminal quantities 5..8.
      if (q <= 8) {
        const Constants c;
        ConstraintCode stage_code, terminal_code;
        ASSERT_EQ(decode_constraint_code(code, &stage_code), Status::kOk);
        ASSERT_EQ(decode_constraint_code(q, &terminal_code), Status::kOk);
        const ConstraintPoint p = make_point(c, with_mass(atmospheric().x));
        double a = 0.0, b = 0.0;
        ASSERT_EQ(constraint_value(c, reference_launch(), stage_code, p, &a), Status::kOk);
        ASSERT_EQ(constraint_value(c, reference_launch(), terminal_code, p, &b), Status::kOk);
        EXPECT_EQ(a, b) << code;
      }
    }
  }
}

TEST(Sec5Ics, DynamicPressureIsHalfRhoVSquaredWithLatitudeTerm) {
  const Constants c;
  ConstraintCode code;
  ASSERT_EQ(decode_constraint_code(19, &code), Status::kOk);
  const ConstraintPoint p = make_point(c, with_mass(atmospheric().x));
  double q = 0.0;
  ASSERT_EQ(constraint_value(c, reference_launch(), code, p, &q), Status::kOk);
  EXPECT_DOUBLE_EQ(q, 0.5 * p.density_slug_ft3 * 4500.0 * 4500.0);
  AdjointVector g;
  ASSERT_EQ(constraint_partials(c, reference_launch(), code, p, &g), Status::kOk);
  // The printed dq/dV and dq/dr, and the latitude term through the oblate altitude.
  EXPECT_DOUBLE_EQ(g(kStateV), p.density_slug_ft3 * 4500.0);
  EXPECT_DOUBLE_EQ(g(kStateR), 0.5 * 4500.0 * 4500.0 * p.ddensity_dh);
  EXPECT_NE(g(kStateLambda), 0.0);
}

TEST(Sec5Ics, HyperbolicExcessVelocityPartialsMatchCentralDifferences) {
  expect_partials_match(100, {hyperbolic_north(), hyperbolic_south()});
}

TEST(Sec5Ics, AsymptoteRightAscensionPartialsMatchCentralDifferences) {
  expect_partials_match(101, {hyperbolic_north(), hyperbolic_south()});
}

TEST(Sec5Ics, AsymptoteDeclinationPartialsMatchCentralDifferences) {
  expect_partials_match(102, {hyperbolic_north(), hyperbolic_south()});
}

// ---- Values ---------------------------------------------------------------------------------------

TEST(Sec5Ics, ValuesEqualTheOrbitElementsModuleAndTheOracle) {
  const Constants c;
  const LaunchConditions launch = reference_launch();
  const auto& cases = test::oracle_test_vectors().at("orbit_elements");
  auto value = [&](int code_number, const StateVector& x) {
    ConstraintCode code;
    EXPECT_EQ(decode_constraint_code(code_number, &code), Status::kOk);
    double v = 0.0;
    EXPECT_EQ(constraint_value(c, launch, code, make_point(c, with_mass(x)), &v), Status::kOk) << code_number;
    return v;
  };
  for (std::size_t n = 0; n < cases.size(); ++n) {
    const StateVector x = state_from_json(cases[n].at("state"));
    ASSERT_EQ(cases[n].at("launch_space_age_date").get<double>(), launch.launch_space_age_date_days);
    OrbitElements e;
    ASSERT_EQ(compute_orbit_elements(c, x, launch.launch_space_age_date_days, &e), Status::kOk);
    EXPECT_EQ(value(1, x), e.inertial.velocity_ft_s);
    EXPECT_EQ(value(2, x), e.inertial.flight_path_angle_rad);
    EXPECT_EQ(value(3, x),
              e.inertial.velocity_ft_s - std::sqrt(c.gravitational_parameter_ft3_s2 / x(kStateR)));
    EXPECT_EQ(value(4, x), x(kStateR));
    EXPECT_EQ(value(5, x), x(kStateV));
    EXPECT_EQ(value(6, x), x(kStateGamma));
    EXPECT_EQ(value(7, x), oblate_altitude_ft(c, x(kStateR), x(kStateLambda)));
    EXPECT_EQ(value(8, x),
              kNauticalMilesPerRadian *
                  downrange_angle_rad(launch.geocentric_latitude_rad, launch.longitude_rad, x(kStateLambda),
                                      x(kStateTau) - c.earth_rotation_rate_rad_s * kTimeFromLaunch_s));
    EXPECT_EQ(value(9, x), e.twice_energy_ft2_s2);
    EXPECT_EQ(value(10, x), e.inclination_rad);
    EXPECT_EQ(value(11, x), e.perigee_radius_ft);
    EXPECT_EQ(value(12, x), e.node_longitude_rad);
    EXPECT_EQ(value(13, x), e.argument_of_perigee_rad);
    // And the oracle's elements.
    const auto& want = cases[n].at("elements");
    EXPECT_NEAR(value(1, x), want.at("VI_fps").get<double>(), 1e-9 * value(1, x));
    EXPECT_NEAR(value(9, x), want.at("twoE_ft2_per_s2").get<double>(), 1e-9 * std::fabs(value(9, x)));
    EXPECT_NEAR(value(10, x) * kRadToDeg, want.at("inclination_deg").get<double>(), 1e-9);
    EXPECT_NEAR(value(11, x), want.at("perigee_radius_ft").get<double>(), 1e-9 * value(11, x));
    EXPECT_NEAR(
        std::remainder(value(12, x) * kRadToDeg - want.at("longitude_of_node_deg").get<double>(), 360.0), 0.0,
        1e-9);
    if (n != 0) {
      EXPECT_NEAR(
          std::remainder(value(13, x) * kRadToDeg - want.at("argument_of_perigee_deg").get<double>(), 360.0),
          0.0, 1e-9);
    }
  }
  // Circular-orbit constraint of the reference case (code 3) is ~0 at its burnout.
  EXPECT_LT(std::fabs(value(3, oracle_state(0))), 1e-6);
  // The asymptote codes equal the module's Addendum H elements.
  const StateVector xh = hyperbolic_north().x;
  OrbitElements eh;
  ASSERT_EQ(compute_orbit_elements(c, xh, launch.launch_space_age_date_days, &eh), Status::kOk);
  ASSERT_TRUE(eh.has_asymptote);
  EXPECT_EQ(value(100, xh), eh.hyperbolic_excess_velocity_ft_s);
  EXPECT_EQ(value(101, xh), eh.asymptote_right_ascension_rad);
  EXPECT_EQ(value(102, xh), eh.asymptote_declination_rad);
}

TEST(Sec5Ics, AngleDeviationsAreWrappedAcrossZero) {
  ConstraintCode node, inclination, path_angle;
  ASSERT_EQ(decode_constraint_code(12, &node), Status::kOk);
  ASSERT_EQ(decode_constraint_code(10, &inclination), Status::kOk);
  ASSERT_EQ(decode_constraint_code(2, &path_angle), Status::kOk);
  EXPECT_NEAR(constraint_deviation(node, 359.9 * kDegToRad, 0.1 * kDegToRad), -0.2 * kDegToRad, 1e-14);
  EXPECT_NEAR(constraint_deviation(node, 0.1 * kDegToRad, 359.9 * kDegToRad), 0.2 * kDegToRad, 1e-14);
  EXPECT_NEAR(constraint_deviation(node, 3.0, 1.0), 2.0, 1e-15);
  for (int code_number : {13, 101}) {
    ConstraintCode c;
    ASSERT_EQ(decode_constraint_code(code_number, &c), Status::kOk);
    EXPECT_NEAR(constraint_deviation(c, 6.2, 0.05), 6.2 - 0.05 - kTwoPi, 1e-14) << code_number;
  }
  EXPECT_EQ(constraint_deviation(inclination, 2.0, 0.5), 1.5);
  EXPECT_EQ(constraint_deviation(path_angle, -0.1, 0.2), -0.1 - 0.2);
}

// ---- Launch time of day ---------------------------------------------------------------------------

TEST(Sec5Ics, NodeLongitudeLaunchTimePartialIsTheHergetSiderealRate) {
  const Constants c;
  LaunchConditions launch = reference_launch();
  const double rate = node_longitude_partial_wrt_launch_time_rad_per_s();
  double worst = 0.0;
  for (int code_number : {12, 101}) {
    ConstraintCode code;
    ASSERT_EQ(decode_constraint_code(code_number, &code), Status::kOk);
    EXPECT_EQ(constraint_partial_wrt_launch_time(code), rate);
    const ConstraintPoint p =
        make_point(c, with_mass(code_number == 12 ? oracle_state(2) : hyperbolic_north().x));
    const double step_s = 10.0;
    auto at = [&](double dt_s) {
      LaunchConditions l = launch;
      l.launch_space_age_date_days += dt_s / 86400.0;
      double v = 0.0;
      EXPECT_EQ(constraint_value(c, l, code, p, &v), Status::kOk);
      return v;
    };
    const double fd = std::remainder(at(step_s) - at(-step_s), kTwoPi) / (2.0 * step_s);
    worst = std::max(worst, std::fabs(fd - rate) / rate);
    EXPECT_NEAR(fd, rate, 1e-6 * rate) << code_number;
  }
  for (int code_number : {1, 2, 8, 10, 11, 13, 102}) {
    ConstraintCode code;
    ASSERT_EQ(decode_constraint_code(code_number, &code), Status::kOk);
    EXPECT_EQ(constraint_partial_wrt_launch_time(code), 0.0) << code_number;
  }
  // 360.98564743 deg/day = 4.1780746e-3 deg/s; the printed 4.1068643e-3 deg/s is 1.7% low.
  EXPECT_NEAR(rate * kRadToDeg, 4.1780746e-3, 1e-10);
  EXPECT_GT(std::fabs(rate * kRadToDeg - 4.1068643e-3) / 4.1068643e-3, 0.01);
  // Within 1e-6 of the Earth rate CT1(1) that Addendum H prints for d alpha_eH / d t_G.
  EXPECT_NEAR(rate, c.earth_rotation_rate_rad_s, 1e-6 * rate);
  std::printf(
      "[ figures  ] Sec5 ICS d Omega_e / d t_launch = %.10e rad/s (%.9e deg/s), vs launch-date difference "
      "%.2e rel\n",
      rate, rate * kRadToDeg, worst);
}

// ---- The printed orbit-element partials, differenced in the inertial variables -------------------

// Inertial variables q = [V_I, gamma_I, psi_I, r, lambda, tau] and the value of a code at q.
using Vector6 = Eigen::Matrix<double, 6, 1>;
Vector6 inertial_variables(const Constants& c, const StateVector& x) {
  const InertialVelocity iv = inertial_velocity(c, x);
  Vector6 q;
  q << iv.velocity_ft_s, iv.flight_path_angle_rad, iv.azimuth_rad, x(kStateR), x(kStateLambda), x(kStateTau);
  return q;
}

double value_at_q(const Constants& c, int code_number, const Vector6& q) {
  ConstraintCode code;
  EXPECT_EQ(decode_constraint_code(code_number, &code), Status::kOk);
  ConstraintPoint p;
  p.state = state_from_inertial(c, q(3), q(4), q(5), q(0), q(1), q(2));
  double v = 0.0;
  EXPECT_EQ(constraint_value(c, reference_launch(), code, p, &v), Status::kOk);
  return v;
}

// Steps and typical perturbations of q = [V_I, gamma_I, psi_I, r, lambda, tau].
const double kQStep[6] = {0.1, 1e-5, 1e-5, 100.0, 1e-5, 1e-5};
const double kQTypical[6] = {1.0, 1e-4, 1e-4, 100.0, 1e-4, 1e-4};

Vector6 q_differences(const Constants& c, int code_number, const Vector6& q) {
  Vector6 fd;
  for (int i = 0; i < 6; ++i) {
    auto f = [&](const Vector7& z) { return value_at_q(c, code_number, z.head<6>()); };
    Vector7 y;
    y.head<6>() = q;
    y(6) = 0.0;
    fd(i) = central_difference(f, y, i, kQStep[i], is_angle_code(code_number));
  }
  return fd;
}

// Printed partials with respect to q against q-differences of the value.
Agreement compare_in_q(const Constants& c, int code_number, const Vector6& q, const Vector6& printed,
                       Vector6* fd_out = nullptr) {
  const Vector6 fd = q_differences(c, code_number, q);
  if (fd_out != nullptr) *fd_out = fd;
  // The orbit module's r_p = H^2 / (mu + sqrt(mu^2 + 2E H^2)) loses digits as 1/e near a circle
  // (mu^2 and 2E H^2 cancel): its round-off, not the partials, sets the floor there.
  double noise_factor = 1.0;
  if (code_number == 11) {
    OrbitElements e;
    const StateVector x = state_from_inertial(c, q(3), q(4), q(5), q(0), q(1), q(2));
    EXPECT_EQ(compute_orbit_elements(c, x, reference_launch().launch_space_age_date_days, &e), Status::kOk);
    noise_factor = 1.0 / std::min(e.eccentricity, 1.0);
  }
  return compare(Eigen::VectorXd(printed), Eigen::VectorXd(fd), value_at_q(c, code_number, q), kQStep,
                 kQTypical, 1e-6, noise_factor);
}

// The printed partials of Sec. 5 and Addendum H with respect to q at a state.
struct Printed {
  Vector6 perigee_radius = Vector6::Zero();
  Vector6 inclination = Vector6::Zero();
  Vector6 node = Vector6::Zero();
  Vector6 argument_of_perigee_sec5 = Vector6::Zero();      // d/dlambda with cos lambda cos lambda
  Vector6 argument_of_perigee_addendum = Vector6::Zero();  // d/dlambda with sin lambda cos lambda
  Vector6 excess_velocity = Vector6::Zero();
  Vector6 declination = Vector6::Zero();
  Vector6 right_ascension = Vector6::Zero();  // as printed, with the extra d/dr term
  Vector6 right_ascension_without_extra = Vector6::Zero();
  double extra_dr_term = 0.0;
};

Printed printed_partials(const Constants& c, const StateVector& x) {
  const double mu = c.gravitational_parameter_ft3_s2;
  OrbitElements e;
  EXPECT_EQ(compute_orbit_elements(c, x, reference_launch().launch_space_age_date_days, &e), Status::kOk);
  const double vi = e.inertial.velocity_ft_s, gi = e.inertial.flight_path_angle_rad,
               psii = e.inertial.azimuth_rad;
  const double r = x(kStateR), lat = x(kStateLambda);
  const double h = e.angular_momentum_ft2_s, rp = e.perigee_radius_ft, two_e = e.twice_energy_ft2_s2;
  const double inc = e.inclination_rad;
  Printed p;
  // ENERGY (of E) and ANGULAR MOMENTUM.
  const double de_dvi = vi, de_dr = mu / (r * r);
  const double dh_dvi = r * std::cos(gi), dh_dr = vi * std::cos(gi), dh_dgi = -r * vi * std::sin(gi);
  // PERIGEE RADIUS.
  const double s = std::sqrt(two_e + (mu / h) * (mu / h));
  p.perigee_radius(0) = (dh_dvi - rp * rp / h * de_dvi) / s;
  p.perigee_radius(3) = (dh_dr - rp * rp / h * de_dr) / s;
  p.perigee_radius(1) = dh_dgi / s;
  // INCLINATION and NODE.
  p.inclination(4) = std::sin(lat) * std::sin(psii) / std::sin(inc);
  p.inclination(2) = -std::cos(lat) * std::cos(psii) / std::sin(inc);
  p.node(4) = -std::cos(inc) * std::cos(psii) / std::pow(std::sin(inc), 2);
  p.node(2) = -std::sin(lat) / std::pow(std::sin(inc), 2);
  p.node(5) = 1.0;
  // ARGUMENT OF PERIGEE.
  const double zeta = e.true_anomaly_rad, beta = e.in_plane_angle_from_node_rad;
  const double k = (mu / h) * (r / h);
  const double s2z = std::pow(std::sin(zeta), 2);
  Vector6 bp = Vector6::Zero();
  bp(0) = 2.0 * s2z * k / (vi * std::tan(gi));
  bp(3) = s2z * (mu / h) / (h * std::tan(gi));
  bp(1) = -s2z * ((1.0 - k) / std::pow(std::sin(gi), 2) + 2.0 * k);
  bp(2) = std::sin(beta) * std::cos(beta) * std::sin(psii) / std::cos(psii);
  p.argument_of_perigee_sec5 = bp;
  p.argument_of_perigee_sec5(4) = std::sin(beta) * std::cos(beta) / (std::cos(lat) * std::cos(lat));
  p.argument_of_perigee_addendum = bp;
  p.argument_of_perigee_addendum(4) = std::sin(beta) * std::cos(beta) / (std::sin(lat) * std::cos(lat));
  if (!e.has_asymptote) return p;
  // H5.5-2d, 2e, 3a-c.
  const double vh = e.hyperbolic_excess_velocity_ft_s;
  const double pr = h * vh / mu;
  Vector6 dzh = Vector6::Zero();
  dzh(0) = -pr * (1.0 + std::pow(vi / vh, 2)) / (vi * (1.0 + pr * pr));
  dzh(1) = pr * std::tan(gi) / (1.0 + pr * pr);
  dzh(3) = -pr * (1.0 + mu / (r * vh * vh)) / (r * (1.0 + pr * pr));
  const Vector6 dbh = p.argument_of_perigee_addendum + dzh;
  p.excess_velocity(0) = vi / vh;
  p.excess_velocity(3) = (mu / (r * r)) / vh;
  const double bh = e.argument_of_perigee_rad + kPi - std::atan(pr);
  const double sd = std::sqrt(1.0 - std::pow(std::sin(e.asymptote_declination_rad), 2));
  const double si = std::sin(inc), ci = std::cos(inc);
  p.declination(0) = si * std::cos(bh) / sd * dbh(0);
  p.declination(1) = si * std::cos(bh) / sd * dbh(1);
  p.declination(3) = si * std::cos(bh) / sd * dbh(3);
  p.declination(2) = (si * std::cos(bh) * dbh(2) + std::sin(bh) * ci * p.inclination(2)) / sd;
  p.declination(4) = (si * std::cos(bh) * dbh(4) + std::sin(bh) * ci * p.inclination(4)) / sd;
  const double nuh = std::atan2(ci * std::sin(bh), std::cos(bh));
  const double f = (ci / std::pow(std::cos(bh), 2)) / (1.0 + std::pow(std::tan(nuh), 2));
  const double g = std::tan(bh) / (1.0 + std::pow(std::tan(nuh), 2));
  InertialJacobian j;
  EXPECT_EQ(inertial_variable_partials(c, x, &j), Status::kOk);
  p.extra_dr_term = p.node(2) * j(2, kStateR);  // (d Omega_e / d psi_I)(d psi_I / d r)
  p.right_ascension_without_extra(0) = f * dbh(0);
  p.right_ascension_without_extra(3) = f * dbh(3);
  p.right_ascension_without_extra(1) = f * dbh(1);
  p.right_ascension_without_extra(4) = p.node(4) + f * dbh(4) - g * si * p.inclination(4);
  p.right_ascension_without_extra(2) = p.node(2) + f * dbh(2) - g * si * p.inclination(2);
  p.right_ascension_without_extra(5) = 1.0;
  p.right_ascension = p.right_ascension_without_extra;
  p.right_ascension(3) += p.extra_dr_term;
  return p;
}

double max_rel_err(const Vector6& a, const Vector6& b) {
  double scale = 0.0;
  for (int i = 0; i < 6; ++i) scale = std::max(scale, std::fabs(b(i)) * kQTypical[i]);
  double worst = 0.0;
  for (int i = 0; i < 6; ++i) {
    worst = std::max(worst, std::fabs(a(i) - b(i)) / std::max(std::fabs(b(i)), 1e-12 * scale / kQTypical[i]));
  }
  return worst;
}

TEST(Sec5Ics, PrintedOrbitElementPartialsAreCorrectExceptTheDocumentedMisprints) {
  const Constants c;
  double worst_correct = 0.0;
  auto check = [&](int code, const Vector6& q, const Vector6& printed, const std::string& what,
                   Vector6* fd = nullptr) {
    const Agreement a = compare_in_q(c, code, q, printed, fd);
    EXPECT_TRUE(a.ok) << "printed partials of code " << code << " at " << what << a.detail;
    worst_correct = std::max(worst_correct, a.max_rel);
  };
  for (const NamedState& s :
       {suborbital_stage3(), inclined_eccentric(), near_circular(), hyperbolic_north(), hyperbolic_south()}) {
    const Vector6 q = inertial_variables(c, s.x);
    const Printed p = printed_partials(c, s.x);
    check(11, q, p.perigee_radius, s.name);
    check(10, q, p.inclination, s.name);
    check(12, q, p.node, s.name);
    Vector6 fd_bp;
    check(13, q, p.argument_of_perigee_addendum, s.name + " (Addendum H d beta_p / d lambda)", &fd_bp);
    // Misprint: Sec. 5 prints d beta_p / d lambda = sin beta cos beta / (cos lambda cos lambda),
    // off by the factor tan lambda.
    EXPECT_GT(std::fabs(p.argument_of_perigee_sec5(4) - fd_bp(4)), 1e-3 * std::fabs(fd_bp(4))) << s.name;
    EXPECT_NEAR(p.argument_of_perigee_sec5(4) / std::tan(s.x(kStateLambda)), fd_bp(4),
                1e-6 * std::fabs(fd_bp(4)));
    if (p.excess_velocity(0) != 0.0) {
      check(100, q, p.excess_velocity, s.name);
      check(102, q, p.declination, s.name);
      Vector6 fd_a;
      check(101, q, p.right_ascension_without_extra, s.name + " (H5.5-3c without the extra d/dr term)",
            &fd_a);
      // Misprint: the printed d alpha_eH / d r adds (d Omega_e/d psi_I)(d psi_I/d r), which is
      // not a partial at fixed psi_I (the chain rule adds it again through psi_I).
      EXPECT_GT(std::fabs(p.right_ascension(3) - fd_a(3)), 1e-2 * std::fabs(fd_a(3))) << s.name;
      EXPECT_NEAR(p.right_ascension(3) - fd_a(3), p.extra_dr_term, 1e-4 * std::fabs(p.extra_dr_term));
      std::printf(
          "[ figures  ] H5.5-3c printed d alpha_eH/dr at %s: extra term %.3e rad/ft = %.1f%% of the true "
          "%.3e\n",
          s.name.c_str(), p.extra_dr_term, 100.0 * std::fabs(p.extra_dr_term / fd_a(3)), fd_a(3));
    }
  }
  std::printf(
      "[ figures  ] Sec5/H5.5 printed orbit-element partials (corrected set) vs q-differences: max rel err "
      "%.2e\n",
      worst_correct);
}

// And the chain: module partials = (printed partials wrt q, corrected) x (printed INER partials).
TEST(Sec5Ics, ModulePartialsAreThePrintedChainRule) {
  const Constants c;
  for (const NamedState& s : {inclined_eccentric(), hyperbolic_north()}) {
    const Printed p = printed_partials(c, s.x);
    InertialJacobian j;
    ASSERT_EQ(inertial_variable_partials(c, s.x, &j), Status::kOk);
    Eigen::Matrix<double, 6, 6> dq_dx = Eigen::Matrix<double, 6, 6>::Zero();
    dq_dx.topRows<3>() = j;
    dq_dx(3, kStateR) = 1.0;
    dq_dx(4, kStateLambda) = 1.0;
    dq_dx(5, kStateTau) = 1.0;
    struct Case {
      int code;
      Vector6 printed;
    };
    std::vector<Case> cases = {
        {10, p.inclination}, {11, p.perigee_radius}, {12, p.node}, {13, p.argument_of_perigee_addendum}};
    if (p.excess_velocity(0) != 0.0) {
      cases.push_back({100, p.excess_velocity});
      cases.push_back({101, p.right_ascension_without_extra});
      cases.push_back({102, p.declination});
    }
    for (const Case& k : cases) {
      ConstraintCode code;
      ASSERT_EQ(decode_constraint_code(k.code, &code), Status::kOk);
      AdjointVector g;
      ASSERT_EQ(constraint_partials(c, reference_launch(), code, make_point(c, with_mass(s.x)), &g),
                Status::kOk);
      const Vector6 chained = (k.printed.transpose() * dq_dx).transpose();
      EXPECT_LT(max_rel_err(g.head<6>(), chained), 1e-8) << "code " << k.code << " at " << s.name;
    }
  }
}

// ---- Singular states ----------------------------------------------------------------------------

TEST(Sec5Ics, SingularStatesFailWithNamedStatus) {
  const Constants c;
  const LaunchConditions launch = reference_launch();
  auto partial_status = [&](int code_number, const StateVector& x, double time_s = kTimeFromLaunch_s) {
    ConstraintCode code;
    EXPECT_EQ(decode_constraint_code(code_number, &code), Status::kOk);
    ConstraintPoint p = make_point(c, with_mass(x));
    p.time_from_launch_s = time_s;
    AdjointVector g;
    return constraint_partials(c, launch, code, p, &g);
  };
  auto value_status = [&](int code_number, const StateVector& x) {
    ConstraintCode code;
    EXPECT_EQ(decode_constraint_code(code_number, &code), Status::kOk);
    double v = 0.0;
    return constraint_value(c, launch, code, make_point(c, with_mass(x)), &v);
  };
  // The reference burnout is circular to round-off: r_p has a kink, beta_p no direction.
  const StateVector circ = oracle_state(0);
  EXPECT_EQ(partial_status(11, circ), Status::kConstraintSingular);
  EXPECT_EQ(partial_status(13, circ), Status::kConstraintSingular);
  EXPECT_EQ(value_status(13, circ), Status::kOk);  // the value exists (orbit module convention)
  for (int code : {1, 2, 3, 9, 10, 12}) EXPECT_EQ(partial_status(code, circ), Status::kOk) << code;
  // Equatorial orbit: inclination, node, argument of perigee have no derivative.
  const StateVector equatorial = state_from_inertial(c, 2.2e7, 0.0, 0.3, 26000.0, 0.05, 0.5 * kPi);
  for (int code : {10, 12, 13})
    EXPECT_EQ(partial_status(code, equatorial), Status::kConstraintSingular) << code;
  EXPECT_EQ(partial_status(11, equatorial), Status::kOk);
  // Vertical inertial velocity: gamma_I, psi_I have no derivative; V_I and 2E do.
  const StateVector vertical = state_from_inertial(c, 2.1e7, 0.2, 0.0, 5000.0, 0.5 * kPi, 0.0);
  EXPECT_EQ(partial_status(2, vertical), Status::kConstraintSingular);
  EXPECT_EQ(partial_status(10, vertical), Status::kConstraintSingular);
  EXPECT_EQ(partial_status(1, vertical), Status::kOk);
  EXPECT_EQ(partial_status(9, vertical), Status::kOk);
  // Downrange at the launch point.
  StateVector pad;
  pad << 0.0, 0.5 * kPi, oblate_radius_ft(c, launch.geocentric_latitude_rad) + 10.0, launch.azimuth_rad,
      launch.geocentric_latitude_rad, launch.longitude_rad;
  EXPECT_EQ(partial_status(8, pad, 0.0), Status::kConstraintSingular);
  // Asymptote constraints on an elliptic orbit.
  for (int code : {100, 101, 102}) {
    EXPECT_EQ(value_status(code, oracle_state(2)), Status::kConstraintNotHyperbolic) << code;
    EXPECT_EQ(partial_status(code, oracle_state(2)), Status::kConstraintNotHyperbolic) << code;
  }
  EXPECT_STREQ(status_name(Status::kConstraintSingular), "kConstraintSingular");
  EXPECT_STREQ(status_name(Status::kConstraintNotHyperbolic), "kConstraintNotHyperbolic");
  // Non-finite input.
  StateVector bad = oracle_state(1);
  bad(kStateR) = std::nan("");
  for (int code : {0, 1, 7, 13, 19}) {
    EXPECT_EQ(value_status(code, bad), Status::kNonFiniteState) << code;
    EXPECT_EQ(partial_status(code, bad), Status::kNonFiniteState) << code;
  }
  ConstraintCode code;
  ASSERT_EQ(decode_constraint_code(1, &code), Status::kOk);
  EXPECT_EQ(constraint_value(c, launch, code, make_point(c, with_mass(oracle_state(1))), nullptr),
            Status::kOutputPointerNull);
  EXPECT_EQ(constraint_partials(c, launch, code, make_point(c, with_mass(oracle_state(1))), nullptr),
            Status::kOutputPointerNull);
}

// ---- Oblate radius derivative and heating forcing ------------------------------------------------

TEST(Sec5Ics, OblateRadiusLatitudeDerivativeMatchesCentralDifferences) {
  const Constants c;
  double worst = 0.0;
  for (double lat_deg : {-80.0, -37.0, -5.0, 0.0, 12.0, 37.65, 61.0, 89.0}) {
    const double lat = lat_deg * kDegToRad;
    const double h = 1e-4;
    const double fd = (oblate_radius_ft(c, lat - 2 * h) - 8 * oblate_radius_ft(c, lat - h) +
                       8 * oblate_radius_ft(c, lat + h) - oblate_radius_ft(c, lat + 2 * h)) /
                      (12 * h);
    const double an = oblate_radius_latitude_derivative_ft_per_rad(c, lat);
    EXPECT_NEAR(an, fd, 1e-7 * std::fabs(fd) + 1e-3) << lat_deg;  // 1e-3 ft/rad: round-off of R / h
    if (std::fabs(fd) > 1.0) worst = std::max(worst, std::fabs(an - fd) / std::fabs(fd));
  }
  // ~ -R e^2 sin lambda cos lambda: -70,000 ft/rad at 45 deg.
  EXPECT_NEAR(oblate_radius_latitude_derivative_ft_per_rad(c, 0.25 * kPi), -70000.0, 1000.0);
  std::printf("[ figures  ] Sec5 ICS dR_OBL/dlambda vs differences: max rel err %.2e\n", worst);
}

TEST(Sec5Ics, HeatingRatePartialsMatchCentralDifferences) {
  const Constants c;
  const double nose_ft = 0.5;
  const Vector7 y = with_mass(atmospheric().x);
  Eigen::Matrix<double, 6, 1> an;
  ASSERT_EQ(stagnation_heating_rate_partials(c, nose_ft, kSeaLevelDensity, make_point(c, y), &an),
            Status::kOk);
  auto f = [&](const Vector7& z) {
    const ConstraintPoint p = make_point(c, z);
    return stagnation_heating_rate(nose_ft, p.density_slug_ft3, kSeaLevelDensity, z(kStateV));
  };
  Vector7 fd, an7;
  for (int i = 0; i < 7; ++i) fd(i) = central_difference(f, y, i, kStep[i], false);
  an7.head<6>() = an;
  an7(6) = 0.0;
  const Agreement a = compare(an7, fd, f(y), 1e-6);
  EXPECT_TRUE(a.ok) << a.detail;
  std::printf("[ figures  ] Sec13 heating-rate forcing partials vs differences: max rel err %.2e\n",
              a.max_rel);
  // Above the atmosphere (rho = 0) the forcing vanishes instead of dividing by zero.
  ConstraintPoint vacuum = make_point(c, y);
  vacuum.density_slug_ft3 = 0.0;
  vacuum.ddensity_dh = 0.0;
  ASSERT_EQ(stagnation_heating_rate_partials(c, nose_ft, kSeaLevelDensity, vacuum, &an), Status::kOk);
  EXPECT_EQ(an.norm(), 0.0);
  EXPECT_EQ(stagnation_heating_rate_partials(c, -1.0, kSeaLevelDensity, vacuum, &an),
            Status::kNoseRadiusNotPositive);
}

// ---- Stopping-condition correction (eqs. 5-12 .. 5-18) -------------------------------------------

// A ballistic state y = [p (3), v (3), m] with p' = v, v' = g, m' = -mdot, whose flow is known in
// closed form. Z = |p|^2 + v_1 m, stopped where S = p_3 reaches its nominal final value.
struct Ballistic {
  Vector3 g{0.3, -0.2, -9.0};
  double mdot = 0.7;
  Vector7 flow(const Vector7& y, double t) const {
    Vector7 out = y;
    out.head<3>() = y.head<3>() + y.segment<3>(3) * t + 0.5 * g * t * t;
    out.segment<3>(3) = y.segment<3>(3) + g * t;
    out(6) = y(6) - mdot * t;
    return out;
  }
  Vector7 rate(const Vector7& y) const {
    Vector7 out;
    out.head<3>() = y.segment<3>(3);
    out.segment<3>(3) = g;
    out(6) = -mdot;
    return out;
  }
  static double z(const Vector7& y) { return y.head<3>().squaredNorm() + y(3) * y(6); }
  static Vector7 dz(const Vector7& y) {
    Vector7 d = Vector7::Zero();
    d.head<3>() = 2.0 * y.head<3>();
    d(3) = y(6);
    d(6) = y(3);
    return d;
  }
  static double s(const Vector7& y) { return y(2); }
  static Vector7 ds(const Vector7&) {
    Vector7 d = Vector7::Zero();
    d(2) = 1.0;
    return d;
  }
  // Z where the trajectory through y (at t_f) reaches S = s_target: Newton on the flow time.
  double z_stopped(const Vector7& y, double s_target) const {
    double t = 0.0;
    for (int k = 0; k < 50; ++k) {
      const Vector7 yt = flow(y, t);
      const double residual = s(yt) - s_target;
      t -= residual / rate(yt)(2);
      if (std::fabs(residual) < 1e-14) break;
    }
    return z(flow(y, t));
  }
};

TEST(Sec5Ics, StoppingConditionCorrectionMatchesDifferencesOfAStoppedTrajectory) {
  const Ballistic b;
  Vector7 yf;
  yf << 3.0, -1.0, 20.0, 4.0, 2.5, -6.0, 11.0;  // S decreasing through the stop (Sdot = -6)
  const double s_target = Ballistic::s(yf);
  const AdjointVector corrected =
      apply_stopping_condition_correction(Ballistic::dz(yf), Ballistic::dz(yf).dot(b.rate(yf)),
                                          Ballistic::ds(yf), Ballistic::ds(yf).dot(b.rate(yf)));
  Vector7 fd;
  const double h = 1e-4;
  for (int i = 0; i < 7; ++i) {
    auto at = [&](double k) {
      Vector7 z = yf;
      z(i) += k * h;
      return b.z_stopped(z, s_target);
    };
    fd(i) = (at(-2) - 8 * at(-1) + 8 * at(1) - at(2)) / (12 * h);
  }
  double worst = 0.0;
  for (int i = 0; i < 7; ++i) {
    EXPECT_NEAR(corrected(i), fd(i), 1e-7 * std::max(1.0, std::fabs(fd(i)))) << i;
    worst = std::max(worst, std::fabs(corrected(i) - fd(i)) / std::max(1.0, std::fabs(fd(i))));
  }
  // The uncorrected dZ/dx is wrong in the p_3 component (the stop moves).
  EXPECT_GT(std::fabs(Ballistic::dz(yf)(2) - fd(2)), 1.0);
  // TOLIP's fixed-time stop: S = t has dS/dx = 0 and the correction is the identity.
  const AdjointVector fixed_time =
      apply_stopping_condition_correction(Ballistic::dz(yf), 3.7, AdjointVector::Zero(), 1.0);
  EXPECT_EQ(fixed_time, Ballistic::dz(yf));
  std::printf(
      "[ figures  ] Sec5 stopping-condition correction vs stopped-trajectory differences: max err %.2e\n",
      worst);
}

}  // namespace
}  // namespace tolip
