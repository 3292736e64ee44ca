// Sec. 4 frames: [A] from the rotation sequence (the printed [A] is garbled), [B], [B'], [C].
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include <Eigen/LU>

#include "support/reference_data.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/frames/frames.hpp"

namespace tolip {
namespace {

Matrix3 json_matrix(const nlohmann::json& j) {
  Matrix3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = j[r][c].get<double>();
  return m;
}

StateVector random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  StateVector x;
  x << 5000.0, 1.2 * u(rng), 2.1e7, 3.0 * u(rng), 1.3 * u(rng), 3.0 * u(rng);
  return x;
}

TEST(Sec4Frames, MatricesAreOrthonormalRotations) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const StateVector x = random_state(rng);
    const Matrix3 a = inertial_to_local(x);
    const Matrix3 b = geocentric_to_inertial(x[3], x[4], x[5]);
    const Matrix3 bp = platform_to_geocentric(x[3], 0.003);
    for (const Matrix3& m : {a, b, bp, Matrix3(a * b * bp)}) {
      EXPECT_LT((m * m.transpose() - Matrix3::Identity()).cwiseAbs().maxCoeff(), 1e-14);
      EXPECT_NEAR(m.determinant(), 1.0, 1e-14);
    }
  }
}

TEST(Sec4Frames, MultipliedOutAEqualsTheRotationProduct) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 50; ++trial) {
    const StateVector x = random_state(rng);
    EXPECT_LT((inertial_to_local(StateTrig(x)) - inertial_to_local(x)).cwiseAbs().maxCoeff(), 1e-15);
  }
}

TEST(Sec4Frames, MatchOracleAtLaunchAndStage2Ignition) {
  const auto& v = test::oracle_test_vectors();
  const auto& launch = v["launch"];
  const Matrix3 b = geocentric_to_inertial(launch["psi0_rad"], launch["lat_gc_rad"], launch["lon_rad"]);
  const Matrix3 bp = platform_to_geocentric(launch["psi0_rad"], launch["delta_lambda_rad"]);
  EXPECT_LT((b - json_matrix(launch["B"])).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((bp - json_matrix(launch["Bprime"])).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((b * bp - json_matrix(launch["BBprime"])).cwiseAbs().maxCoeff(), 1e-14);

  const auto& ex = v["A_matrix_example"];
  StateVector x;
  for (int i = 0; i < 6; ++i) x[i] = ex["state"][i];
  const Matrix3 a = inertial_to_local(x);
  EXPECT_LT((a - json_matrix(ex["A"])).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((a * b * bp - json_matrix(ex["C"])).cwiseAbs().maxCoeff(), 1e-14);
}

// The local frame built from its definitions: i_y along V, i_x to the right of the plane of
// motion, i_z = i_x cross i_y (generally up), all in the inertial frame.
TEST(Sec4Frames, RowsOfAAreTheLocalAxesByDefinition) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const StateVector x = random_state(rng);
    const double g = x[1], p = x[3], l = x[4], t = x[5];
    const Vector3 up(std::cos(l) * std::cos(t), std::cos(l) * std::sin(t), std::sin(l));
    const Vector3 east(-std::sin(t), std::cos(t), 0.0);
    const Vector3 north = up.cross(east);
    const Vector3 horizontal = std::cos(p) * north + std::sin(p) * east;
    const Vector3 iy = std::cos(g) * horizontal + std::sin(g) * up;
    const Vector3 ix = horizontal.cross(up).normalized() * 1.0;  // right of the direction of motion
    const Vector3 iz = ix.cross(iy);
    const Matrix3 a = inertial_to_local(x);
    EXPECT_LT((a.row(0).transpose() - ix).norm(), 1e-14);
    EXPECT_LT((a.row(1).transpose() - iy).norm(), 1e-14);
    EXPECT_LT((a.row(2).transpose() - iz).norm(), 1e-14);
    EXPECT_GT(iz.dot(up), -1e-15);  // "generally up"
  }
}

// All 36 partial derivatives of [A] printed in Sec. 5 against central differences of [A].
TEST(Sec5Frames, PrintedPartialsOfAMatchCentralDifferences) {
  using Partial = std::function<double(double g, double p, double l, double t)>;
  const auto S = [](double a) { return std::sin(a); };
  const auto C = [](double a) { return std::cos(a); };
  // partial[row][col][variable] with variables gamma, psi, lambda, tau.
  Partial partial[3][3][4] = {
      {{[](double, double, double, double) { return 0.0; },
        [&](double, double p, double l, double t) { return S(t) * S(p) + C(t) * S(l) * C(p); },
        [&](double, double p, double l, double t) { return C(t) * C(l) * S(p); },
        [&](double, double p, double l, double t) { return -C(t) * C(p) - S(t) * S(l) * S(p); }},
       {[](double, double, double, double) { return 0.0; },
        [&](double, double p, double l, double t) { return -C(t) * S(p) + S(t) * S(l) * C(p); },
        [&](double, double p, double l, double t) { return S(t) * C(l) * S(p); },
        [&](double, double p, double l, double t) { return -S(t) * C(p) + C(t) * S(l) * S(p); }},
       {[](double, double, double, double) { return 0.0; },
        [&](double, double p, double l, double) { return -C(l) * C(p); },
        [&](double, double p, double l, double) { return S(l) * S(p); },
        [](double, double, double, double) { return 0.0; }}},
      {{[&](double g, double p, double l, double t) {
          return C(t) * S(l) * C(p) * S(g) + S(t) * S(p) * S(g) + C(t) * C(l) * C(g);
        },
        [&](double g, double p, double l, double t) {
          return C(t) * S(l) * S(p) * C(g) - S(t) * C(p) * C(g);
        },
        [&](double g, double p, double l, double t) {
          return -C(t) * C(l) * C(p) * C(g) - C(t) * S(l) * S(g);
        },
        [&](double g, double p, double l, double t) {
          return S(t) * S(l) * C(p) * C(g) - C(t) * S(p) * C(g) - S(t) * C(l) * S(g);
        }},
       {[&](double g, double p, double l, double t) {
          return S(t) * S(l) * C(p) * S(g) - C(t) * S(p) * S(g) + S(t) * C(l) * C(g);
        },
        [&](double g, double p, double l, double t) {
          return S(t) * S(l) * S(p) * C(g) + C(t) * C(p) * C(g);
        },
        [&](double g, double p, double l, double t) {
          return -S(t) * C(l) * C(p) * C(g) - S(t) * S(l) * S(g);
        },
        [&](double g, double p, double l, double t) {
          return -C(t) * S(l) * C(p) * C(g) - S(t) * S(p) * C(g) + C(t) * C(l) * S(g);
        }},
       {[&](double g, double p, double l, double) { return -C(l) * C(p) * S(g) + S(l) * C(g); },
        [&](double g, double p, double l, double) { return -C(l) * S(p) * C(g); },
        [&](double g, double p, double l, double) { return -S(l) * C(p) * C(g) + C(l) * S(g); },
        [](double, double, double, double) { return 0.0; }}},
      {{[&](double g, double p, double l, double t) {
          return -C(t) * C(l) * S(g) + C(t) * S(l) * C(p) * C(g) + S(t) * S(p) * C(g);
        },
        [&](double g, double p, double l, double t) {
          return -C(t) * S(l) * S(p) * S(g) + S(t) * C(p) * S(g);
        },
        [&](double g, double p, double l, double t) {
          return -C(t) * S(l) * C(g) + C(t) * C(l) * C(p) * S(g);
        },
        [&](double g, double p, double l, double t) {
          return -S(t) * C(l) * C(g) - S(t) * S(l) * C(p) * S(g) + C(t) * S(p) * S(g);
        }},
       {[&](double g, double p, double l, double t) {
          return -S(t) * C(l) * S(g) + S(t) * S(l) * C(p) * C(g) - C(t) * S(p) * C(g);
        },
        [&](double g, double p, double l, double t) {
          return -S(t) * S(l) * S(p) * S(g) - C(t) * C(p) * S(g);
        },
        [&](double g, double p, double l, double t) {
          return -S(t) * S(l) * C(g) + S(t) * C(l) * C(p) * S(g);
        },
        [&](double g, double p, double l, double t) {
          return C(t) * C(l) * C(g) + C(t) * S(l) * C(p) * S(g) + S(t) * S(p) * S(g);
        }},
       {[&](double g, double p, double l, double) { return -S(l) * S(g) - C(l) * C(p) * C(g); },
        [&](double g, double p, double l, double) { return C(l) * S(p) * S(g); },
        [&](double g, double p, double l, double) { return C(l) * C(g) + S(l) * C(p) * S(g); },
        [](double, double, double, double) { return 0.0; }}}};
  const int state_index[4] = {kStateGamma, kStatePsi, kStateLambda, kStateTau};
  std::mt19937 rng(3);
  const double h = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const StateVector x = random_state(rng);
    for (int v = 0; v < 4; ++v) {
      StateVector xp = x, xm = x;
      xp[state_index[v]] += h;
      xm[state_index[v]] -= h;
      const Matrix3 fd = (inertial_to_local(xp) - inertial_to_local(xm)) / (2.0 * h);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(partial[r][c][v](x[1], x[3], x[4], x[5]), fd(r, c), 1e-8)
              << "dA" << r + 1 << c + 1 << "/d"
              << "gplt"[v];
    }
  }
}

TEST(Sec4ThrustResolution, ZeroAlphaAttitudeAlignsThrustWithVelocity) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 50; ++trial) {
    const StateVector x = random_state(rng);
    const Matrix3 c =
        inertial_to_local(x) * geocentric_to_inertial(0.3, 0.6, -1.2) * platform_to_geocentric(0.3, 0.003);
    const double theta = theta_for_zero_alpha_rad(c, 0.0);
    const Vector3 axis = c * thrust_axis_platform(theta, 0.0);
    EXPECT_NEAR(axis.norm(), 1.0, 1e-15);
    EXPECT_NEAR(angle_of_attack_rad(axis), 0.0, 1e-12);
    EXPECT_GT(axis.y(), 0.0);
  }
}

// A small error for the test's record (std::to_string prints 0.000000).
std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// Error of `value` in units in the last place of the double nearest `reference`.
double ulps_from(long double reference, double value) {
  const double nearest = std::fabs(static_cast<double>(reference));
  const double ulp = std::nextafter(nearest, INFINITY) - nearest;
  return static_cast<double>(std::fabs(static_cast<long double>(value) - reference)) / ulp;
}

// The addition-theorem StateTrig that the dispersion flights use (StateTrigAnchor, anchored at
// `base`; docs/theory/trajectory.md), against sinl/cosl in long double (an independent reference),
// over random states and angle steps up to the limit: within 2 ulps (the rounded sine and cosine of
// the anchor carry into the sum; the library itself is within 0.52 ulp at the same points).
TEST(Sec19Integration, StateTrigByAdditionAgreesWithLongDoubleWithinTwoUlps) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int angles[4] = {kStateGamma, kStatePsi, kStateLambda, kStateTau};
  double worst_added_ulps = 0.0, worst_library_ulps = 0.0, worst_added_abs = 0.0;
  for (int trial = 0; trial < 100000; ++trial) {
    const StateVector base = random_state(rng);
    StateVector x = base;
    // Steps of every size up to the limit, most of them as small as an RK4 stage's.
    const double scale = kStateTrigAdditionLimitRad * std::pow(10.0, -5.0 * std::fabs(unit(rng)));
    for (int i : angles) x[i] += scale * unit(rng);
    StateTrigAnchor anchor;
    anchor.at(base);
    const StateTrig added = anchor.at(x);
    const StateTrig library(x);
    const double values[8] = {added.sin_gamma,  added.cos_gamma,  added.sin_psi, added.cos_psi,
                              added.sin_lambda, added.cos_lambda, added.sin_tau, added.cos_tau};
    const double library_values[8] = {library.sin_gamma, library.cos_gamma,  library.sin_psi,
                                      library.cos_psi,   library.sin_lambda, library.cos_lambda,
                                      library.sin_tau,   library.cos_tau};
    for (int k = 0; k < 8; ++k) {
      const long double a = static_cast<long double>(x[angles[k / 2]]);
      const long double reference = (k % 2 == 0) ? sinl(a) : cosl(a);
      worst_added_abs = std::max(
          worst_added_abs, static_cast<double>(std::fabs(static_cast<long double>(values[k]) - reference)));
      if (std::fabs(reference) < 1.0L / 16.0L) continue;  // near a zero: judged by the absolute error
      worst_added_ulps = std::max(worst_added_ulps, ulps_from(reference, values[k]));
      worst_library_ulps = std::max(worst_library_ulps, ulps_from(reference, library_values[k]));
    }
  }
  EXPECT_LT(worst_added_ulps, 2.0) << "library: " << worst_library_ulps;  // measured 1.80 (library 0.51)
  EXPECT_LT(worst_added_abs, 1.2e-16);                                    // about half an ulp of 1
  EXPECT_LT(worst_library_ulps, 1.0);
  RecordProperty("worst_added_ulps", std::to_string(worst_added_ulps));
  RecordProperty("worst_library_ulps", std::to_string(worst_library_ulps));
}

// Along a flight the anchor's values never drift: 20,000 small steps move every angle by several
// radians (re-anchoring many times), and each value stays within 2 ulps of sinl/cosl, because each
// is one addition from a library value, not a chain of them.
TEST(Sec19Integration, StateTrigAnchorDoesNotAccumulateErrorAlongAFlight) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const int angles[4] = {kStateGamma, kStatePsi, kStateLambda, kStateTau};
  StateTrigAnchor anchor;
  StateVector x = random_state(rng);
  const double rates[4] = {3e-3, -2e-3, 1e-3, 4e-3};  // rad per step (tau: 80 rad in all), jittered
  double worst_ulps = 0.0, worst_abs = 0.0;
  for (int step = 0; step < 20000; ++step) {
    for (int k = 0; k < 4; ++k) x[angles[k]] += rates[k] * (1.0 + 0.5 * unit(rng));
    const StateTrig t = anchor.at(x);
    const double values[8] = {t.sin_gamma,  t.cos_gamma,  t.sin_psi, t.cos_psi,
                              t.sin_lambda, t.cos_lambda, t.sin_tau, t.cos_tau};
    for (int k = 0; k < 8; ++k) {
      const long double a = static_cast<long double>(x[angles[k / 2]]);
      const long double reference = (k % 2 == 0) ? sinl(a) : cosl(a);
      worst_abs = std::max(worst_abs,
                           static_cast<double>(std::fabs(static_cast<long double>(values[k]) - reference)));
      if (std::fabs(reference) >= 1.0L / 16.0L)
        worst_ulps = std::max(worst_ulps, ulps_from(reference, values[k]));
    }
  }
  EXPECT_LT(worst_ulps, 2.0);
  EXPECT_LT(worst_abs, 1.2e-16);
  RecordProperty("worst_ulps", std::to_string(worst_ulps));
}

// atan2_by_series (a dispersion flight's small angles of attack) against atan2l in long double over
// random small angles of every size up to the limit: within 1.5 ulps (the quotient's rounding and
// the sum's); beyond the limit, for x <= 0 and for NaN it is the library's atan2 exactly.
TEST(Sec19Integration, Atan2BySeriesAgreesWithLongDoubleForSmallAnglesAndFallsBack) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  double worst_ulps = 0.0, worst_library_ulps = 0.0;
  for (int trial = 0; trial < 100000; ++trial) {
    const double x = 1e-3 + 1e3 * std::fabs(unit(rng));
    const double y = x / 16.0 * unit(rng) * std::pow(10.0, -6.0 * std::fabs(unit(rng)));
    const long double reference = atan2l(static_cast<long double>(y), static_cast<long double>(x));
    worst_ulps = std::max(worst_ulps, ulps_from(reference, atan2_by_series(y, x)));
    worst_library_ulps = std::max(worst_library_ulps, ulps_from(reference, std::atan2(y, x)));
  }
  EXPECT_LT(worst_ulps, 1.5) << "library: " << worst_library_ulps;
  RecordProperty("worst_ulps", std::to_string(worst_ulps));
  for (const double y : {1.0 / 16.0, -0.5, 3.0}) EXPECT_EQ(atan2_by_series(y, 1.0), std::atan2(y, 1.0));
  EXPECT_EQ(atan2_by_series(0.01, -1.0), std::atan2(0.01, -1.0));
  EXPECT_EQ(atan2_by_series(0.0, 0.0), std::atan2(0.0, 0.0));
  EXPECT_TRUE(std::isnan(atan2_by_series(std::nan(""), 1.0)));
  EXPECT_TRUE(std::isnan(atan2_by_series(0.01, std::nan(""))));
  EXPECT_EQ(atan2_by_series(0.0, 2.0), 0.0);
  EXPECT_TRUE(std::signbit(atan2_by_series(-0.0, 2.0)));
}

// Atan2Anchor (a dispersion flight's gamma_w in the body dynamics) along a direction that turns by
// small steps from -1.4 rad to about +1.6 rad (10,000 steps, the anchor moving many times), against
// atan2l in long double: within 2.5 ulps of the angle where it is not near 0 (the anchor's rounded
// angle, sine and cosine carry into the sum) and 3e-16 rad everywhere (measured 1.85 ulps,
// 2.1e-16 rad). A direction far from the anchor moves the anchor: the library's value exactly; NaN
// stays NaN.
TEST(Sec19Integration, Atan2AnchorAgreesWithLongDoubleAlongATurningDirection) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Atan2Anchor anchor;
  double angle = -1.4;
  double worst_ulps = 0.0, worst_abs = 0.0;
  int library_values = 0;
  for (int step = 0; step < 10000; ++step) {
    angle += 3e-4 * (1.0 + unit(rng));                 // about 3 rad in all, 0 to 6e-4 rad a step
    const double length = 0.5 + std::fabs(unit(rng));  // not a unit vector: the ratio matters
    const double x = length * std::cos(angle), y = length * std::sin(angle);
    const double value = anchor.at(y, x);
    if (value == std::atan2(y, x)) ++library_values;
    const long double reference = atan2l(static_cast<long double>(y), static_cast<long double>(x));
    worst_abs =
        std::max(worst_abs, static_cast<double>(std::fabs(static_cast<long double>(value) - reference)));
    if (std::fabs(reference) >= 0.25L) worst_ulps = std::max(worst_ulps, ulps_from(reference, value));
  }
  EXPECT_LT(worst_ulps, 2.5);
  EXPECT_LT(worst_abs, 3e-16);
  EXPECT_LT(library_values, 9000);  // the series path is taken (most values differ in the last bit)
  RecordProperty("worst_ulps", std::to_string(worst_ulps));
  RecordProperty("worst_abs_rad", scientific(worst_abs));
  // A jump beyond atan2_by_series' domain re-anchors on the library's value.
  EXPECT_EQ(anchor.at(-2.0, 0.3), std::atan2(-2.0, 0.3));
  EXPECT_EQ(anchor.at(0.5, -1.0), std::atan2(0.5, -1.0));
  EXPECT_TRUE(std::isnan(anchor.at(std::nan(""), 1.0)));
  EXPECT_EQ(anchor.at(0.1, 1.0), std::atan2(0.1, 1.0));  // and recovers from the NaN
}

// inertial_to_local_times, the four frame rotations applied in turn (a dispersion flight's thrust
// axis), over random states and vectors, against the same rotations in long double with sinl and
// cosl (an independent reference): within 5e-16 of |v|, as close as [A] times v is (measured 4.0e-16
// against 3.9e-16: both are round-off, neither is bit for bit the other).
TEST(Sec4Frames, RotationByRotationProductAgreesWithLongDouble) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  using L = long double;
  // Frame rotation of (a, b) by angle q: (c a + s b, -s a + c b).
  const auto turn = [](L q, L* a, L* b) {
    const L c = cosl(q), s = sinl(q), a0 = *a;
    *a = c * a0 + s * *b;
    *b = -s * a0 + c * *b;
  };
  double worst = 0.0, worst_matrix = 0.0;
  for (int trial = 0; trial < 10000; ++trial) {
    const StateVector x = random_state(rng);
    const Vector3 v(unit(rng), unit(rng), unit(rng));
    L rx = v.x(), ry = v.y(), rz = v.z();
    const L half_pi = 1.5707963267948966192313216916397514L;
    turn(static_cast<L>(x[kStateTau]), &rx, &ry);               // Rz(tau)
    turn(half_pi - static_cast<L>(x[kStateLambda]), &rz, &rx);  // Ry(90 - lambda): (z, x)
    turn(half_pi - static_cast<L>(x[kStatePsi]), &rx, &ry);     // Rz(90 - psi)
    turn(static_cast<L>(x[kStateGamma]), &ry, &rz);             // Rx(gamma)
    const auto error = [&](const Vector3& w) {
      const L dx = w.x() - rx, dy = w.y() - ry, dz = w.z() - rz;
      return static_cast<double>(sqrtl(dx * dx + dy * dy + dz * dz)) / v.norm();
    };
    worst = std::max(worst, error(inertial_to_local_times(StateTrig(x), v)));
    worst_matrix = std::max(worst_matrix, error(inertial_to_local(StateTrig(x)) * v));
  }
  EXPECT_LT(worst, 5e-16) << "[A] times v: " << worst_matrix;
  RecordProperty("worst_relative", scientific(worst));
  RecordProperty("worst_relative_matrix", scientific(worst_matrix));
}

// The four angles taken at once (two at a time, StateTrigAnchor's array form) are bit for bit the
// one-angle form, sine_cosine_by_addition, of each.
TEST(Sec19Integration, StateTrigByAdditionOfFourAnglesAtOnceEqualsEachAngleAlone) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 10000; ++trial) {
    const StateVector base = random_state(rng);
    StateVector x = base;
    for (int i : {kStateGamma, kStatePsi, kStateLambda, kStateTau})
      x[i] += kStateTrigAdditionLimitRad * unit(rng);
    const StateTrig b(base);
    StateTrigAnchor anchor;
    anchor.at(base);
    const StateTrig four = anchor.at(x);
    const SineCosine g = sine_cosine_by_addition(b.sin_gamma, b.cos_gamma, base[kStateGamma], x[kStateGamma]);
    const SineCosine p = sine_cosine_by_addition(b.sin_psi, b.cos_psi, base[kStatePsi], x[kStatePsi]);
    const SineCosine l =
        sine_cosine_by_addition(b.sin_lambda, b.cos_lambda, base[kStateLambda], x[kStateLambda]);
    const SineCosine t = sine_cosine_by_addition(b.sin_tau, b.cos_tau, base[kStateTau], x[kStateTau]);
    ASSERT_EQ(four.sin_gamma, g.sin);
    ASSERT_EQ(four.cos_gamma, g.cos);
    ASSERT_EQ(four.sin_psi, p.sin);
    ASSERT_EQ(four.cos_psi, p.cos);
    ASSERT_EQ(four.sin_lambda, l.sin);
    ASSERT_EQ(four.cos_lambda, l.cos);
    ASSERT_EQ(four.sin_tau, t.sin);
    ASSERT_EQ(four.cos_tau, t.cos);
  }
}

// A step at or beyond the limit, and an angle that is not finite, re-anchor: the library's values
// exactly. No step: the anchor's values exactly.
TEST(Sec19Integration, StateTrigByAdditionFallsBackToTheLibraryForLargeStepsAndNaN) {
  std::mt19937 rng(12);
  const StateVector base = random_state(rng);
  StateVector x = base;
  x[kStateGamma] += kStateTrigAdditionLimitRad;
  x[kStatePsi] -= 0.5;
  x[kStateLambda] = std::nan("");
  x[kStateTau] = INFINITY;
  StateTrigAnchor anchor;
  anchor.at(base);
  const StateTrig added = anchor.at(x);  // re-anchored: the library's at x
  const StateTrig library(x);
  EXPECT_EQ(added.sin_gamma, library.sin_gamma);
  EXPECT_EQ(added.cos_gamma, library.cos_gamma);
  EXPECT_EQ(added.sin_psi, library.sin_psi);
  EXPECT_EQ(added.cos_psi, library.cos_psi);
  EXPECT_TRUE(std::isnan(added.sin_lambda) && std::isnan(added.cos_lambda));
  EXPECT_TRUE(std::isnan(added.sin_tau) && std::isnan(added.cos_tau));
  // No step: the base's values exactly.
  StateTrigAnchor still;
  still.at(base);
  const StateTrig same = still.at(base);
  const StateTrig base_trig(base);
  EXPECT_EQ(same.sin_tau, base_trig.sin_tau);
  EXPECT_EQ(same.cos_gamma, base_trig.cos_gamma);
}

// wrap_angle_rad skips the library only where std::remainder(angle, 2 pi) is the angle itself:
// bit for bit the library's everywhere, at +-pi, beyond it, for -0 and for NaN.
TEST(Sec4Frames, WrapAngleIsTheLibraryRemainderBitForBit) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto same = [](double angle) {
    const double wrapped = wrap_angle_rad(angle);
    const double library = std::remainder(angle, 2.0 * kPi);
    return (std::isnan(wrapped) && std::isnan(library)) ||
           (wrapped == library && std::signbit(wrapped) == std::signbit(library));
  };
  for (int trial = 0; trial < 100000; ++trial) {
    const double angle = 20.0 * unit(rng);
    ASSERT_TRUE(same(angle)) << angle;
  }
  for (const double angle :
       {kPi, -kPi, std::nextafter(kPi, 4.0), std::nextafter(-kPi, -4.0), 2.0 * kPi, 3.0 * kPi, -0.0, 0.0,
        1e300, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_TRUE(same(angle)) << angle;
  }
}

// The angle of attack by series is atan2_by_series of the same components (the library's atan2
// where the angle is not small); without it, the library's.
TEST(Sec19Integration, AngleOfAttackBySeriesIsTheSeriesAtan2OfTheAxis) {
  const Vector3 small(0.2, 0.99, 0.03);
  EXPECT_EQ(angle_of_attack_rad(small, true), atan2_by_series(small.z(), small.y()));
  EXPECT_NEAR(angle_of_attack_rad(small, true), angle_of_attack_rad(small), 1e-16);
  EXPECT_EQ(angle_of_attack_rad(small, false), angle_of_attack_rad(small));
  const Vector3 large(0.0, 0.5, 0.8);
  EXPECT_EQ(angle_of_attack_rad(large, true), angle_of_attack_rad(large));
}

}  // namespace
}  // namespace tolip
