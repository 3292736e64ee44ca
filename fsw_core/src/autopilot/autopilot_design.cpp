// Autopilot gain design at one flight condition (autopilot_design.hpp,
// docs/theory/autopilot-design.md).
#include "tolip/autopilot/autopilot_design.hpp"

#include <cmath>
#include <complex>
#include <limits>

#include "tolip/core/constants.hpp"
#include "tolip/table/table_image.hpp"

namespace tolip {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Gain crossovers |L(j w)| = 1 are searched for w^2 in [1e-8, 1e8] (rad/s)^2, a log grid of this
// many cells, each sign change refined by bisection to round-off.
constexpr int kCrossoverGridCells = 400;
constexpr double kCrossoverLowU = 1e-8;
constexpr double kCrossoverHighU = 1e8;
constexpr int kBisectionSteps = 200;

bool finite_positive(double x) { return std::isfinite(x) && x > 0.0; }

// |b (K_theta + j K_q w)|^2 - |(j w)^2 - c j w - a|^2 |1 + j tau w|^2 with u = w^2.
double crossover_function(const ShortPeriodModel& m, double k_theta, double k_q, double tau, double u) {
  const double b2 = m.b_per_s2 * m.b_per_s2;
  const double num = b2 * (k_q * k_q * u + k_theta * k_theta);
  const double re = -u - m.a_per_s2;
  const double den = (re * re + m.c_per_s * m.c_per_s * u) * (1.0 + tau * tau * u);
  return num - den;
}

std::complex<double> loop_response(const ShortPeriodModel& m, double k_theta, double k_q, double tau,
                                   double w) {
  const std::complex<double> s(0.0, w);
  const std::complex<double> num = m.b_per_s2 * (k_theta + k_q * s);
  const std::complex<double> den = (s * s - m.c_per_s * s - m.a_per_s2) * (tau * s + 1.0);
  return num / den;
}

}  // namespace

ShortPeriodModel short_period_model(const BodyDynamicsBlocks& data, const AutopilotCondition& c) {
  ShortPeriodModel m;
  const UnitMoments moments = unit_moments(data, c.moments);
  m.m_alpha_lbf_ft_per_rad = moments.m_alpha_lbf_ft_per_rad;
  m.m_delta_lbf_ft_per_rad = moments.m_delta_lbf_ft_per_rad;
  const double q = c.moments.dynamic_pressure_lbf_ft2;
  m.m_q_aero_lbf_ft_s_per_rad =
      (q > 0.0 && c.speed_ft_s > 0.0)
          ? aerodynamic_pitch_damping_moment(c.pitch_damping_per_rad, 1.0, data.reference_length_ft, q,
                                             data.reference_area_ft2, c.speed_ft_s)
          : 0.0;
  m.m_q_jet_lbf_ft_s_per_rad = jet_damping_moment(
      1.0, c.mass_rate_slug_s, moments.cg_station_ft - c.thrust_station_ft, c.inertia_rate_slug_ft2_s);
  m.pitch_inertia_slug_ft2 = c.pitch_inertia_slug_ft2;
  if (c.pitch_inertia_slug_ft2 > 0.0) {
    m.a_per_s2 = m.m_alpha_lbf_ft_per_rad / c.pitch_inertia_slug_ft2;
    m.b_per_s2 = m.m_delta_lbf_ft_per_rad / c.pitch_inertia_slug_ft2;
    m.c_per_s = (m.m_q_aero_lbf_ft_s_per_rad + m.m_q_jet_lbf_ft_s_per_rad) / c.pitch_inertia_slug_ft2;
  }
  return m;
}

RootPair quadratic_roots(double p1, double p0) {
  RootPair r;
  const double disc = p1 * p1 - 4.0 * p0;
  if (disc < 0.0) {
    r.re[0] = r.re[1] = -0.5 * p1;
    r.im[0] = 0.5 * std::sqrt(-disc);
    r.im[1] = -r.im[0];
    return r;
  }
  // The cancellation-free pair: q = -(p1 + sign(p1) sqrt(disc)) / 2, roots q and p0 / q.
  const double root = std::sqrt(disc);
  const double q = -0.5 * (p1 + (p1 >= 0.0 ? root : -root));
  if (q == 0.0) return r;  // p1 = p0 = 0: a double root at 0
  r.re[0] = q;
  r.re[1] = p0 / q;
  return r;
}

LoopMargins loop_margins(const ShortPeriodModel& m, double k_theta, double k_q, double tau) {
  LoopMargins out;
  // Closed loop with the loop gain scaled by k:
  //   tau s^3 + (1 - tau c) s^2 + (k b K_q - c - tau a) s + (k b K_theta - a) = 0.
  // Every Routh-Hurwitz condition is linear in k: each one a bound on the stable interval.
  const double a = m.a_per_s2, b = m.b_per_s2, c = m.c_per_s;
  double k_low = 0.0;
  double k_high = kInfinity;
  bool empty = false;
  // Condition "alpha0 + k beta > 0".
  auto bound = [&](double alpha0, double beta) {
    if (beta > 0.0) {
      const double k = -alpha0 / beta;
      if (k > k_low) k_low = k;
    } else if (beta < 0.0) {
      const double k = -alpha0 / beta;
      if (k < k_high) k_high = k;
    } else if (!(alpha0 > 0.0)) {
      empty = true;
    }
  };
  const double a2 = 1.0 - tau * c;
  if (!(a2 > 0.0)) empty = true;
  bound(-c - tau * a, b * k_q);                                                           // s^1 coefficient
  bound(-a, b * k_theta);                                                                 // s^0 coefficient
  if (tau > 0.0) bound(a2 * (-c - tau * a) + tau * a, a2 * b * k_q - tau * b * k_theta);  // a2 a1 > a3 a0
  if (empty || !(k_high > k_low)) {
    out.upper_gain_margin = 0.0;
    out.lower_gain_margin = 0.0;
    out.closed_loop_stable = false;
  } else {
    out.upper_gain_margin = k_high;
    out.lower_gain_margin = k_low;
    out.closed_loop_stable = k_low < 1.0 && 1.0 < k_high;
  }

  // Phase margin at every gain crossover.
  out.phase_margin_rad = kInfinity;
  out.crossover_rad_s = 0.0;
  const double log_low = std::log(kCrossoverLowU);
  const double step = (std::log(kCrossoverHighU) - log_low) / kCrossoverGridCells;
  double u0 = kCrossoverLowU;
  double f0 = crossover_function(m, k_theta, k_q, tau, u0);
  for (int i = 1; i <= kCrossoverGridCells; ++i) {
    const double u1 = std::exp(log_low + step * i);
    const double f1 = crossover_function(m, k_theta, k_q, tau, u1);
    if ((f0 > 0.0) != (f1 > 0.0)) {
      double lo = u0, hi = u1, flo = f0;
      for (int k = 0; k < kBisectionSteps; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        const double fm = crossover_function(m, k_theta, k_q, tau, mid);
        if ((fm > 0.0) == (flo > 0.0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      const double w = std::sqrt(0.5 * (lo + hi));
      double pm = kPi + std::arg(loop_response(m, k_theta, k_q, tau, w));
      if (pm > kPi) pm -= 2.0 * kPi;
      // The crossover nearest to -1 decides (the smallest |PM|): a crossing far from -1 (the
      // upward crossing below the resonance of a stable airframe, phase near 0) is not critical.
      if (std::fabs(pm) < std::fabs(out.phase_margin_rad)) {
        out.phase_margin_rad = pm;
        out.crossover_rad_s = w;
      }
    }
    u0 = u1;
    f0 = f1;
  }
  return out;
}

double max_deliverable_frequency_rad_s(const ShortPeriodModel& m, const AutopilotRequest& r) {
  if (!(r.attitude_error_rad > 0.0)) return 0.0;
  const double w2 = m.b_per_s2 * r.max_deflection_rad / r.attitude_error_rad - m.a_per_s2;
  return w2 > 0.0 ? std::sqrt(w2) : 0.0;
}

Status design_autopilot_gains(const ShortPeriodModel& m, const AutopilotRequest& r, AutopilotDesign* design) {
  if (!finite_positive(r.damping_ratio)) return Status::kAutopilotDampingNotPositive;
  if (!finite_positive(r.natural_frequency_rad_s)) return Status::kAutopilotFrequencyNotPositive;
  if (!finite_positive(r.attitude_error_rad) || !finite_positive(r.max_deflection_rad) ||
      !std::isfinite(r.actuator_time_constant_s) || r.actuator_time_constant_s < 0.0) {
    return Status::kAutopilotRequestInvalid;
  }
  if (!finite_positive(m.pitch_inertia_slug_ft2) || !finite_positive(m.m_delta_lbf_ft_per_rad) ||
      !std::isfinite(m.a_per_s2) || !finite_positive(m.b_per_s2) || !std::isfinite(m.c_per_s)) {
    return Status::kAutopilotModelInvalid;
  }
  const double w = r.natural_frequency_rad_s;
  const double k_theta = (w * w + m.a_per_s2) / m.b_per_s2;
  const double k_q = (2.0 * r.damping_ratio * w + m.c_per_s) / m.b_per_s2;
  if (k_theta * r.attitude_error_rad > r.max_deflection_rad) {
    return Status::kAutopilotFrequencyBeyondDeflection;
  }
  if (!(k_theta >= 0.0 && k_theta <= kTableMaxGain) || !(k_q >= 0.0 && k_q <= kTableMaxGain)) {
    return Status::kAutopilotGainOutOfRange;
  }
  AutopilotDesign d;
  d.model = m;
  d.open_loop = quadratic_roots(-m.c_per_s, -m.a_per_s2);
  d.k_theta = k_theta;
  d.k_q_s = k_q;
  d.closed_loop = quadratic_roots(k_q * m.b_per_s2 - m.c_per_s, k_theta * m.b_per_s2 - m.a_per_s2);
  d.margins = loop_margins(m, k_theta, k_q, r.actuator_time_constant_s);
  d.step_deflection_rad = k_theta * r.attitude_error_rad;
  *design = d;
  return Status::kOk;
}

}  // namespace tolip
