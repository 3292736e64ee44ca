// Sec. 4 frames: [A] from the rotation sequence (the printed [A] is garbled), [B], [B'], [C].
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

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

}  // namespace
}  // namespace tolip
