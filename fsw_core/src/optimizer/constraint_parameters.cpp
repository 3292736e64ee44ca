// Constraint parameters of data block 8 and their adjoint initial conditions (subroutine ICS,
// manual Sec. 5 and Addendum H5.5); see docs/theory/constraints-and-ics.md.
//
// The partials follow the manual's chain rule: each orbit constraint is first differentiated
// with respect to the inertial variables q = [V_I, gamma_I, psi_I, r, lambda, tau], then
// multiplied by dq/dx. The printed formulas are used where they are regular; where a printed form
// is 0/0 at an ordinary state (cos psi = 0 in the psi_I partials, gamma_I = 0 in the true-anomaly
// partials, lambda = 0 in d beta / d lambda) the algebraically equal regular form is used, and
// the printed misprints are corrected (each one is listed in the theory note and checked by
// tests/core/constraint_parameters_test.cpp against central differences).
#include "tolip/optimizer/constraint_parameters.hpp"

#include "tolip/atmosphere/atmosphere.hpp"

#include <cmath>

#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/qbar_alpha.hpp"
#include "tolip/orbit/orbit_elements.hpp"

namespace tolip {

namespace {

// Row vector of partials with respect to the inertial variables q.
using InertialRow = Eigen::Matrix<double, 1, 6>;
constexpr int kQVelocity = 0;
constexpr int kQGamma = 1;
constexpr int kQPsi = 2;
constexpr int kQRadius = 3;
constexpr int kQLatitude = 4;
constexpr int kQTau = 5;

// Thresholds below which a derivative does not exist (the quantity has a kink or its angle is
// undefined there); documented in the header.
constexpr double kMinSinInclination = 1e-12;
constexpr double kMinEccentricity = 1e-10;
constexpr double kMinSinDownrange = 1e-12;
constexpr double kMinHorizontalFraction = 1e-12;  // horizontal inertial speed / V_I
constexpr double kMinCosDeclination = 1e-12;
constexpr double kMinInertialSpeed_ft_s = 1e-6;  // as compute_orbit_elements

constexpr double kSecondsPerDay = 86400.0;
// Herget: right ascension of Greenwich = 99.659967 + 0.98564743 tG + 360 frac(tG) deg.
constexpr double kGreenwichRateDegPerDay = 360.0 + 0.98564743;

static_assert(static_cast<int>(ConstraintQuantity::kTotalHeating) == 14 &&
                  static_cast<int>(ConstraintQuantity::kTwiceEnergy) == 9,
              "terminal codes 0..14 are the enumerators' values");

bool point_finite(const ConstraintPoint& point) {
  return point.state.allFinite() && std::isfinite(point.time_from_launch_s) &&
         std::isfinite(point.weight_lb) && std::isfinite(point.density_slug_ft3) &&
         std::isfinite(point.ddensity_dh) && std::isfinite(point.total_heating_btu_ft2) &&
         std::isfinite(point.qbar_alpha_excess_s);
}

// The code must be one decode_constraint_code() produces.
bool code_consistent(const ConstraintCode& code) {
  ConstraintCode decoded;
  if (decode_constraint_code(code.code, &decoded) != Status::kOk) return false;
  return decoded.kind == code.kind && decoded.is_stage_point == code.is_stage_point &&
         decoded.stage_code == code.stage_code && decoded.quantity == code.quantity;
}

bool needs_orbit(ConstraintQuantity kind) {
  switch (kind) {
    case ConstraintQuantity::kInertialVelocity:
    case ConstraintQuantity::kInertialFlightPathAngle:
    case ConstraintQuantity::kVelocityOverCircular:
    case ConstraintQuantity::kTwiceEnergy:
    case ConstraintQuantity::kInclination:
    case ConstraintQuantity::kPerigeeRadius:
    case ConstraintQuantity::kNodeLongitude:
    case ConstraintQuantity::kArgumentOfPerigee:
    case ConstraintQuantity::kHyperbolicExcessVelocity:
    case ConstraintQuantity::kAsymptoteRightAscension:
    case ConstraintQuantity::kAsymptoteDeclination: return true;
    default: return false;
  }
}

bool is_hyperbolic_kind(ConstraintQuantity kind) {
  return kind == ConstraintQuantity::kHyperbolicExcessVelocity ||
         kind == ConstraintQuantity::kAsymptoteRightAscension ||
         kind == ConstraintQuantity::kAsymptoteDeclination;
}

double earth_fixed_longitude_rad(const Constants& constants, const ConstraintPoint& point) {
  return point.state(kStateTau) - constants.earth_rotation_rate_rad_s * point.time_from_launch_s;
}

// Inertial velocity components up / north / east (Sec. 4 INER) and their state partials.
struct InertialComponents {
  double up_ft_s = 0.0;
  double north_ft_s = 0.0;
  double east_ft_s = 0.0;
  Eigen::Matrix<double, 1, 6> d_up = Eigen::Matrix<double, 1, 6>::Zero();
  Eigen::Matrix<double, 1, 6> d_north = Eigen::Matrix<double, 1, 6>::Zero();
  Eigen::Matrix<double, 1, 6> d_east = Eigen::Matrix<double, 1, 6>::Zero();
};

InertialComponents inertial_components(const Constants& constants, const StateVector& x) {
  const double v = x(kStateV);
  const double r = x(kStateR);
  const double omega = constants.earth_rotation_rate_rad_s;
  const double sg = std::sin(x(kStateGamma));
  const double cg = std::cos(x(kStateGamma));
  const double sp = std::sin(x(kStatePsi));
  const double cp = std::cos(x(kStatePsi));
  const double sl = std::sin(x(kStateLambda));
  const double cl = std::cos(x(kStateLambda));
  InertialComponents c;
  c.up_ft_s = v * sg;
  c.north_ft_s = v * cg * cp;
  c.east_ft_s = v * cg * sp + omega * r * cl;
  c.d_up(kStateV) = sg;
  c.d_up(kStateGamma) = v * cg;
  c.d_north(kStateV) = cg * cp;
  c.d_north(kStateGamma) = -v * sg * cp;
  c.d_north(kStatePsi) = -v * cg * sp;
  c.d_east(kStateV) = cg * sp;
  c.d_east(kStateGamma) = -v * sg * sp;
  c.d_east(kStateR) = omega * cl;
  c.d_east(kStatePsi) = v * cg * cp;
  c.d_east(kStateLambda) = -omega * r * sl;
  return c;
}

// The orbit at the point with the derivative building blocks of the orbit constraints, each a
// row of partials with respect to q = [V_I, gamma_I, psi_I, r, lambda, tau].
struct OrbitPartials {
  OrbitElements elements;
  double sin_i = 0.0;
  double cos_i = 0.0;
  double eccentricity = 0.0;  // sqrt(X^2 + Y^2), X = e cos zeta, Y = e sin zeta
  InertialRow d_twice_energy = InertialRow::Zero();
  InertialRow d_angular_momentum = InertialRow::Zero();
  InertialRow d_inclination = InertialRow::Zero();
  InertialRow d_node = InertialRow::Zero();
  InertialRow d_argument_of_perigee = InertialRow::Zero();
};

// Fills the partials that need no division by a vanishing quantity unconditionally; those that
// do are left zero and the caller checks sin_i / eccentricity before using them.
void orbit_partials(const Constants& constants, const StateVector& x, const OrbitElements& e,
                    OrbitPartials* out) {
  const double mu = constants.gravitational_parameter_ft3_s2;
  const double r = x(kStateR);
  const double lambda = x(kStateLambda);
  const double sl = std::sin(lambda);
  const double cl = std::cos(lambda);
  const double v_i = e.inertial.velocity_ft_s;
  const double sgi = std::sin(e.inertial.flight_path_angle_rad);
  const double cgi = std::cos(e.inertial.flight_path_angle_rad);
  const double spi = std::sin(e.inertial.azimuth_rad);
  const double cpi = std::cos(e.inertial.azimuth_rad);
  const double h = e.angular_momentum_ft2_s;

  OrbitPartials& p = *out;
  p.elements = e;
  // 2E = V_I^2 - 2 mu / r. The manual prints the partials of E (dE/dV_I = V_I, dE/dr = mu/r^2).
  p.d_twice_energy(kQVelocity) = 2.0 * v_i;
  p.d_twice_energy(kQRadius) = 2.0 * mu / (r * r);
  // H = r V_I cos gamma_I (printed partials, Sec. 5).
  p.d_angular_momentum(kQVelocity) = r * cgi;
  p.d_angular_momentum(kQGamma) = -r * v_i * sgi;
  p.d_angular_momentum(kQRadius) = v_i * cgi;

  p.cos_i = cl * spi;
  p.sin_i = std::hypot(sl, cl * cpi);
  if (p.sin_i >= kMinSinInclination) {
    const double sin2_i = p.sin_i * p.sin_i;
    // cos i = cos lambda sin psi_I (printed).
    p.d_inclination(kQLatitude) = sl * spi / p.sin_i;
    p.d_inclination(kQPsi) = -cl * cpi / p.sin_i;
    // Omega_e = alpha_G + tau - nu, tan nu = sin lambda sin psi_I / cos psi_I (printed).
    p.d_node(kQLatitude) = -p.cos_i * cpi / sin2_i;
    p.d_node(kQPsi) = -sl / sin2_i;
    p.d_node(kQTau) = 1.0;
  }

  // True anomaly from X = e cos zeta = H^2/(mu r) - 1 and Y = e sin zeta = H V_I sin gamma_I / mu
  // (tan zeta = tan gamma_I / (1 - (mu/H)(r/H)) is Y / X). d zeta = (X dY - Y dX) / e^2 equals
  // the printed sin^2 zeta forms but stays regular at gamma_I = 0.
  const double x_ecc = h * h / (mu * r) - 1.0;
  const double y_ecc = h * v_i * sgi / mu;
  p.eccentricity = std::hypot(x_ecc, y_ecc);
  if (p.eccentricity >= kMinEccentricity && p.sin_i >= kMinSinInclination) {
    const InertialRow& dh = p.d_angular_momentum;
    InertialRow dx = (2.0 * h / (mu * r)) * dh;
    dx(kQRadius) -= h * h / (mu * r * r);
    InertialRow dy = (v_i * sgi / mu) * dh;
    dy(kQVelocity) += h * sgi / mu;
    dy(kQGamma) += h * v_i * cgi / mu;
    const InertialRow d_zeta = (x_ecc * dy - y_ecc * dx) / (p.eccentricity * p.eccentricity);
    // beta: tan beta = sin lambda / (cos lambda cos psi_I). Addendum H prints
    // d beta/d lambda = sin beta cos beta / (sin lambda cos lambda) = cos psi_I / sin^2 i (Sec. 5
    // misprints the denominator as cos lambda cos lambda); the right-hand form is used, regular
    // at the equator. d beta / d psi_I = sin beta cos beta tan psi_I = sin lambda cos lambda
    // sin psi_I / sin^2 i, regular at psi_I = 90 deg.
    const double sin2_i = p.sin_i * p.sin_i;
    InertialRow d_beta = InertialRow::Zero();
    d_beta(kQLatitude) = cpi / sin2_i;
    d_beta(kQPsi) = sl * cl * spi / sin2_i;
    p.d_argument_of_perigee = d_beta - d_zeta;
  }
}

// d(state quantity)/d(state) of the inertial variables as the 6 x 6 chain matrix dq/dx.
Eigen::Matrix<double, 6, 6> chain_matrix(const InertialJacobian& jacobian) {
  Eigen::Matrix<double, 6, 6> dq_dx = Eigen::Matrix<double, 6, 6>::Zero();
  dq_dx.row(kQVelocity) = jacobian.row(0);
  dq_dx.row(kQGamma) = jacobian.row(1);
  dq_dx.row(kQPsi) = jacobian.row(2);
  dq_dx(kQRadius, kStateR) = 1.0;
  dq_dx(kQLatitude, kStateLambda) = 1.0;
  dq_dx(kQTau, kStateTau) = 1.0;
  return dq_dx;
}

// Partials of an orbit constraint with respect to q; Status for singular cases.
Status orbit_constraint_row(const Constants& constants, const StateVector& x, ConstraintQuantity kind,
                            const OrbitPartials& p, InertialRow* row) {
  const double mu = constants.gravitational_parameter_ft3_s2;
  const double r = x(kStateR);
  const OrbitElements& e = p.elements;
  const double v_i = e.inertial.velocity_ft_s;
  InertialRow g = InertialRow::Zero();
  const bool equatorial = p.sin_i < kMinSinInclination;
  const bool circular = p.eccentricity < kMinEccentricity;
  switch (kind) {
    case ConstraintQuantity::kInertialVelocity: g(kQVelocity) = 1.0; break;
    case ConstraintQuantity::kInertialFlightPathAngle: g(kQGamma) = 1.0; break;
    case ConstraintQuantity::kVelocityOverCircular:
      // V_ORB = V_I - sqrt(mu/r): d/dr = (1/(2r)) sqrt(mu/r) beyond dV_I/dr (printed).
      g(kQVelocity) = 1.0;
      g(kQRadius) = 0.5 * std::sqrt(mu / r) / r;
      break;
    case ConstraintQuantity::kTwiceEnergy: g = p.d_twice_energy; break;
    case ConstraintQuantity::kInclination:
      if (equatorial) return Status::kConstraintSingular;
      g = p.d_inclination;
      break;
    case ConstraintQuantity::kNodeLongitude:
      if (equatorial) return Status::kConstraintSingular;
      g = p.d_node;
      break;
    case ConstraintQuantity::kPerigeeRadius: {
      // r_p solves 2E r_p^2 + 2 mu r_p - H^2 = 0, so d r_p = (2 H dH - r_p^2 d(2E)) / (2 mu e)
      // with mu e = 2E r_p + mu = H sqrt(2E + (mu/H)^2): the printed
      // (dH - (r_p^2/H) dE) / sqrt(2E + (mu/H)^2), regular at H = 0.
      if (circular) return Status::kConstraintSingular;
      const double mu_e = mu * p.eccentricity;
      const double h = e.angular_momentum_ft2_s;
      const double rp = e.perigee_radius_ft;
      g = (2.0 * h * p.d_angular_momentum - rp * rp * p.d_twice_energy) / (2.0 * mu_e);
      break;
    }
    case ConstraintQuantity::kArgumentOfPerigee:
      if (equatorial || circular) return Status::kConstraintSingular;
      g = p.d_argument_of_perigee;
      break;
    case ConstraintQuantity::kHyperbolicExcessVelocity:
    case ConstraintQuantity::kAsymptoteRightAscension:
    case ConstraintQuantity::kAsymptoteDeclination: {
      if (!e.has_asymptote) return Status::kConstraintNotHyperbolic;
      const double v_h = e.hyperbolic_excess_velocity_ft_s;
      // H5.5-3a: d v_H / d V_I = V_I / v_H, d v_H / d r = (mu / r^2) / v_H.
      InertialRow d_vh = InertialRow::Zero();
      d_vh(kQVelocity) = v_i / v_h;
      d_vh(kQRadius) = mu / (r * r) / v_h;
      if (kind == ConstraintQuantity::kHyperbolicExcessVelocity) {
        g = d_vh;
        break;
      }
      if (equatorial) return Status::kConstraintSingular;
      // H5.5-2d: zeta_H = pi - atan(P), P = H v_H / mu; d zeta_H = -dP / (1 + P^2).
      const double h = e.angular_momentum_ft2_s;
      const double p_ratio = h * v_h / mu;
      const InertialRow d_p = (v_h * p.d_angular_momentum + h * d_vh) / mu;
      const InertialRow d_zeta_h = -d_p / (1.0 + p_ratio * p_ratio);
      // H5.5-2e: beta_H = beta_p + zeta_H.
      const double zeta_h = kPi - std::atan(p_ratio);
      const double beta_h = e.argument_of_perigee_rad + zeta_h;
      const InertialRow d_beta_h = p.d_argument_of_perigee + d_zeta_h;
      const double sbh = std::sin(beta_h);
      const double cbh = std::cos(beta_h);
      if (kind == ConstraintQuantity::kAsymptoteDeclination) {
        // H5.5-3b: sin delta = sin i sin beta_H.
        const double cos_delta = std::cos(e.asymptote_declination_rad);
        if (cos_delta < kMinCosDeclination) return Status::kConstraintSingular;
        g = (p.sin_i * cbh * d_beta_h + sbh * p.cos_i * p.d_inclination) / cos_delta;
      } else {
        // H5.5-3c: alpha_H = Omega_e + nu_H, tan nu_H = cos i sin beta_H / cos beta_H;
        // (cos i / cos^2 beta_H) / (1 + tan^2 nu_H) = cos i / D, D = cos^2 i sin^2 beta_H +
        // cos^2 beta_H, written with D so that beta_H = 90 deg is regular. The printed d/dr
        // adds (d Omega_e / d psi_I)(d psi_I / d r), which the chain rule through psi_I already
        // counts; it is omitted here (misprint, see the theory note).
        const double d = p.cos_i * p.cos_i * sbh * sbh + cbh * cbh;
        g = p.d_node + (p.cos_i * d_beta_h - p.sin_i * sbh * cbh * p.d_inclination) / d;
      }
      break;
    }
    default: return Status::kUnknownConstraintCode;
  }
  *row = g;
  return Status::kOk;
}

}  // namespace

Status decode_constraint_code(int code, ConstraintCode* out) {
  if (out == nullptr) return Status::kOutputPointerNull;
  ConstraintCode c;
  c.code = code;
  if (code >= 0 && code <= 14) {
    c.quantity = code;
    c.kind = static_cast<ConstraintQuantity>(code);  // enumerators 0..14 follow the codes
  } else if (code >= 15 && code <= 99 && code % 10 >= 5) {
    c.is_stage_point = true;
    c.stage_code = code / 10;
    c.quantity = code % 10;
    switch (c.quantity) {
      case 5: c.kind = ConstraintQuantity::kAerodynamicVelocity; break;
      case 6: c.kind = ConstraintQuantity::kAerodynamicFlightPathAngle; break;
      case 7: c.kind = ConstraintQuantity::kAltitude; break;
      case 8: c.kind = ConstraintQuantity::kDownrange; break;
      default: c.kind = ConstraintQuantity::kDynamicPressure; break;  // 9
    }
  } else if (code == 100) {
    c.quantity = code;
    c.kind = ConstraintQuantity::kHyperbolicExcessVelocity;
  } else if (code == 101) {
    c.quantity = code;
    c.kind = ConstraintQuantity::kAsymptoteRightAscension;
  } else if (code == 102) {
    c.quantity = code;
    c.kind = ConstraintQuantity::kAsymptoteDeclination;
  } else if (code == kQbarAlphaConstraintCode) {
    c.quantity = code;
    c.kind = ConstraintQuantity::kQbarAlphaExcess;
  } else {
    return Status::kUnknownConstraintCode;
  }
  *out = c;
  return Status::kOk;
}

double oblate_radius_latitude_derivative_ft_per_rad(const Constants& constants,
                                                    double geocentric_latitude_rad) {
  // R = a b / sqrt(b^2 cos^2 + a^2 sin^2), b = a (f - 1)/f (equal to the manual's eta form), so
  // dR/dlambda = -R^3 (a^2 - b^2) sin lambda cos lambda / (a^2 b^2); 0 on the sphere (b = a).
  const double a = constants.earth_equatorial_radius_ft;
  const double b = polar_radius_ft(constants);
  const double radius = oblate_radius_ft(constants, geocentric_latitude_rad);
  return -radius * radius * radius * (a * a - b * b) * std::sin(geocentric_latitude_rad) *
         std::cos(geocentric_latitude_rad) / (a * a * b * b);
}

double constraint_deviation(const ConstraintCode& code, double value, double desired) {
  const double difference = value - desired;
  if (code.kind == ConstraintQuantity::kNodeLongitude ||
      code.kind == ConstraintQuantity::kArgumentOfPerigee ||
      code.kind == ConstraintQuantity::kAsymptoteRightAscension) {
    const double two_pi = 2.0 * kPi;
    double wrapped = std::fmod(difference + kPi, two_pi);
    if (wrapped < 0.0) wrapped += two_pi;
    return wrapped - kPi;
  }
  return difference;
}

double node_longitude_partial_wrt_launch_time_rad_per_s() {
  return kGreenwichRateDegPerDay * kDegToRad / kSecondsPerDay;
}

double constraint_partial_wrt_launch_time(const ConstraintCode& code) {
  if (code.kind == ConstraintQuantity::kNodeLongitude ||
      code.kind == ConstraintQuantity::kAsymptoteRightAscension) {
    return node_longitude_partial_wrt_launch_time_rad_per_s();
  }
  return 0.0;
}

Status inertial_variable_partials(const Constants& constants, const StateVector& state,
                                  InertialJacobian* jacobian) {
  if (jacobian == nullptr) return Status::kOutputPointerNull;
  if (!state.allFinite()) return Status::kNonFiniteState;
  const InertialComponents c = inertial_components(constants, state);
  const double horizontal = std::hypot(c.north_ft_s, c.east_ft_s);
  const double v_i = std::hypot(horizontal, c.up_ft_s);
  if (!(v_i > kMinInertialSpeed_ft_s)) return Status::kZeroVelocity;
  if (horizontal < kMinHorizontalFraction * v_i) return Status::kConstraintSingular;
  // V_I = |(u, n, e)|; gamma_I = atan2(u, hz); psi_I = atan2(e, n), hz = |(n, e)|. Equal to the
  // printed INER partials (Sec. 5), which divide by cos psi and are 0/0 for an eastward velocity.
  const Eigen::Matrix<double, 1, 6> d_horizontal =
      (c.north_ft_s * c.d_north + c.east_ft_s * c.d_east) / horizontal;
  InertialJacobian j;
  j.row(0) = (c.up_ft_s * c.d_up + c.north_ft_s * c.d_north + c.east_ft_s * c.d_east) / v_i;
  j.row(1) = (horizontal * c.d_up - c.up_ft_s * d_horizontal) / (v_i * v_i);
  j.row(2) = (c.north_ft_s * c.d_east - c.east_ft_s * c.d_north) / (horizontal * horizontal);
  if (!j.allFinite()) return Status::kNonFiniteState;
  *jacobian = j;
  return Status::kOk;
}

Status constraint_value(const Constants& constants, const LaunchConditions& launch,
                        const ConstraintCode& code, const ConstraintPoint& point, double* value) {
  if (value == nullptr) return Status::kOutputPointerNull;
  if (!code_consistent(code)) return Status::kUnknownConstraintCode;
  if (!point_finite(point)) return Status::kNonFiniteState;
  const StateVector& x = point.state;
  double result = 0.0;
  if (needs_orbit(code.kind)) {
    OrbitElements e;
    const Status s = compute_orbit_elements(constants, x, launch.launch_space_age_date_days, &e);
    if (s != Status::kOk) return s;
    switch (code.kind) {
      case ConstraintQuantity::kInertialVelocity: result = e.inertial.velocity_ft_s; break;
      case ConstraintQuantity::kInertialFlightPathAngle: result = e.inertial.flight_path_angle_rad; break;
      case ConstraintQuantity::kVelocityOverCircular:
        result = e.inertial.velocity_ft_s - std::sqrt(constants.gravitational_parameter_ft3_s2 / x(kStateR));
        break;
      case ConstraintQuantity::kTwiceEnergy: result = e.twice_energy_ft2_s2; break;
      case ConstraintQuantity::kInclination: result = e.inclination_rad; break;
      case ConstraintQuantity::kPerigeeRadius: result = e.perigee_radius_ft; break;
      case ConstraintQuantity::kNodeLongitude: result = e.node_longitude_rad; break;
      case ConstraintQuantity::kArgumentOfPerigee: result = e.argument_of_perigee_rad; break;
      default:  // the asymptote
        if (!e.has_asymptote) return Status::kConstraintNotHyperbolic;
        if (code.kind == ConstraintQuantity::kHyperbolicExcessVelocity) {
          result = e.hyperbolic_excess_velocity_ft_s;
        } else if (code.kind == ConstraintQuantity::kAsymptoteRightAscension) {
          result = e.asymptote_right_ascension_rad;
        } else {
          result = e.asymptote_declination_rad;
        }
        break;
    }
  } else {
    switch (code.kind) {
      case ConstraintQuantity::kPayload: result = point.weight_lb; break;
      case ConstraintQuantity::kRadius: result = x(kStateR); break;
      case ConstraintQuantity::kAerodynamicVelocity: result = x(kStateV); break;
      case ConstraintQuantity::kAerodynamicFlightPathAngle: result = x(kStateGamma); break;
      case ConstraintQuantity::kAltitude:
        result = oblate_altitude_ft(constants, x(kStateR), x(kStateLambda));
        break;
      case ConstraintQuantity::kDownrange:
        result = kNauticalMilesPerRadian * downrange_angle_rad(launch.geocentric_latitude_rad,
                                                               launch.longitude_rad, x(kStateLambda),
                                                               earth_fixed_longitude_rad(constants, point));
        break;
      case ConstraintQuantity::kTotalHeating: result = point.total_heating_btu_ft2; break;
      case ConstraintQuantity::kQbarAlphaExcess: result = point.qbar_alpha_excess_s; break;
      case ConstraintQuantity::kDynamicPressure:
        result = 0.5 * point.density_slug_ft3 * x(kStateV) * x(kStateV);
        break;
      default: return Status::kUnknownConstraintCode;
    }
  }
  if (!std::isfinite(result)) return Status::kNonFiniteState;
  *value = result;
  return Status::kOk;
}

Status constraint_partials(const Constants& constants, const LaunchConditions& launch,
                           const ConstraintCode& code, const ConstraintPoint& point,
                           AdjointVector* partials) {
  if (partials == nullptr) return Status::kOutputPointerNull;
  if (!code_consistent(code)) return Status::kUnknownConstraintCode;
  if (!point_finite(point)) return Status::kNonFiniteState;
  const StateVector& x = point.state;
  AdjointVector out = AdjointVector::Zero();

  if (needs_orbit(code.kind)) {
    OrbitElements e;
    const Status s = compute_orbit_elements(constants, x, launch.launch_space_age_date_days, &e);
    if (s != Status::kOk) return s;
    if (is_hyperbolic_kind(code.kind) && !e.has_asymptote) return Status::kConstraintNotHyperbolic;
    InertialJacobian jacobian;
    const Status sj = inertial_variable_partials(constants, x, &jacobian);
    // V_I, 2E and V_I - sqrt(mu/r) need only the V_I row, which exists at vertical velocity.
    const bool speed_only = code.kind == ConstraintQuantity::kInertialVelocity ||
                            code.kind == ConstraintQuantity::kTwiceEnergy ||
                            code.kind == ConstraintQuantity::kVelocityOverCircular ||
                            code.kind == ConstraintQuantity::kHyperbolicExcessVelocity;
    if (sj == Status::kConstraintSingular && speed_only) {
      const InertialComponents c = inertial_components(constants, x);
      jacobian.setZero();
      jacobian.row(0) =
          (c.up_ft_s * c.d_up + c.north_ft_s * c.d_north + c.east_ft_s * c.d_east) / e.inertial.velocity_ft_s;
    } else if (sj != Status::kOk) {
      return sj;
    }
    OrbitPartials orbit;
    orbit_partials(constants, x, e, &orbit);
    InertialRow g;
    const Status sg = orbit_constraint_row(constants, x, code.kind, orbit, &g);
    if (sg != Status::kOk) return sg;
    out.head<6>() = (g * chain_matrix(jacobian)).transpose();
  } else {
    switch (code.kind) {
      case ConstraintQuantity::kPayload:
        // The payoff weight W = g0 m at the final point: d W / d m = g0 (lb per slug).
        out(kAdjointMass) = constants.g0_ft_s2;
        break;
      case ConstraintQuantity::kRadius: out(kStateR) = 1.0; break;
      case ConstraintQuantity::kAerodynamicVelocity: out(kStateV) = 1.0; break;
      case ConstraintQuantity::kAerodynamicFlightPathAngle: out(kStateGamma) = 1.0; break;
      case ConstraintQuantity::kAltitude:
        out(kStateR) = 1.0;
        out(kStateLambda) = -oblate_radius_latitude_derivative_ft_per_rad(constants, x(kStateLambda));
        break;
      case ConstraintQuantity::kDownrange: {
        // Sec. 5 (printed, correct): d DR / d lambda = [cos l0 sin l cos(dtau) - sin l0 cos l] /
        // sin DR, d DR / d tau = cos l0 cos l sin(dtau) / sin DR; tau enters only through the
        // Earth-fixed longitude tau - omega t.
        const double lat0 = launch.geocentric_latitude_rad;
        const double lat = x(kStateLambda);
        const double d_lon = earth_fixed_longitude_rad(constants, point) - launch.longitude_rad;
        const double dr =
            downrange_angle_rad(lat0, launch.longitude_rad, lat, earth_fixed_longitude_rad(constants, point));
        const double sin_dr = std::sin(dr);
        if (sin_dr < kMinSinDownrange) return Status::kConstraintSingular;
        out(kStateLambda) =
            kNauticalMilesPerRadian *
            (std::cos(lat0) * std::sin(lat) * std::cos(d_lon) - std::sin(lat0) * std::cos(lat)) / sin_dr;
        out(kStateTau) = kNauticalMilesPerRadian * std::cos(lat0) * std::cos(lat) * std::sin(d_lon) / sin_dr;
        break;
      }
      case ConstraintQuantity::kTotalHeating:
      case ConstraintQuantity::kQbarAlphaExcess:
        // Integral constraints: their adjoints start at zero; the integrands enter the adjoint
        // equations (Sec. 13, stagnation_heating_rate_partials; qbar_alpha_excess_gradient).
        break;
      case ConstraintQuantity::kDynamicPressure: {
        // q = rho V^2 / 2 with rho(h), h = r - R_OBL(lambda): dq/dV = rho V, dq/dr = V^2/2 drho/dh
        // (printed), dq/dlambda = -V^2/2 drho/dh dR_OBL/dlambda (the manual neglects it).
        const double v = x(kStateV);
        const double dq_dh = 0.5 * v * v * point.ddensity_dh;
        out(kStateV) = point.density_slug_ft3 * v;
        out(kStateR) = dq_dh;
        out(kStateLambda) = -dq_dh * oblate_radius_latitude_derivative_ft_per_rad(constants, x(kStateLambda));
        break;
      }
      default: return Status::kUnknownConstraintCode;
    }
  }
  if (!out.allFinite()) return Status::kNonFiniteState;
  *partials = out;
  return Status::kOk;
}

Status stagnation_heating_rate_partials(const Constants& constants, double nose_radius_ft,
                                        double sea_level_density_slug_ft3, const ConstraintPoint& point,
                                        Eigen::Matrix<double, 6, 1>* partials) {
  if (partials == nullptr) return Status::kOutputPointerNull;
  const StateVector& x = point.state;
  if (!x.allFinite() || !std::isfinite(point.ddensity_dh)) return Status::kValueNotFinite;
  double q_dot = 0.0;
  const Status s = stagnation_heating_rate_checked(nose_radius_ft, point.density_slug_ft3,
                                                   sea_level_density_slug_ft3, x(kStateV), &q_dot);
  if (s != Status::kOk) return s;
  Eigen::Matrix<double, 6, 1> out = Eigen::Matrix<double, 6, 1>::Zero();
  if (q_dot > 0.0) {
    // Sec. 13: dQ/dV = 3.25 Q / V; dQ/dr = Q / (2 rho) drho/dh (the printed forms, divided by Q).
    out(kStateV) = 3.25 * q_dot / x(kStateV);
    const double dq_dh = 0.5 * q_dot / point.density_slug_ft3 * point.ddensity_dh;
    out(kStateR) = dq_dh;
    out(kStateLambda) = -dq_dh * oblate_radius_latitude_derivative_ft_per_rad(constants, x(kStateLambda));
  }
  if (!out.allFinite()) return Status::kValueNotFinite;
  *partials = out;
  return Status::kOk;
}

AdjointVector apply_stopping_condition_correction(const AdjointVector& dz_dx, double z_dot,
                                                  const AdjointVector& ds_dx, double s_dot) {
  // Eq. 5-18: lambda(t_f) = dZ/dx - (Zdot / Sdot) dS/dx.
  return dz_dx - (z_dot / s_dot) * ds_dx;
}

ConstraintPoint constraint_point_at(const Mission& mission, const Trajectory& trajectory, int index) {
  const TrajectoryPoint& p = trajectory.points[index];
  ConstraintPoint c;
  c.state = p.state;
  c.time_from_launch_s = p.time_s;
  c.weight_lb = p.weight_lb;
  c.total_heating_btu_ft2 = trajectory.heat_integral_btu_ft2;
  if (mission.options.qbar_alpha_constraint()) {
    c.qbar_alpha_excess_s = qbar_alpha_excess_s(mission, trajectory);
  }
  if (p.altitude_ft <= mission.constants.haero_ft) {
    AtmosphereSample air;
    const double radius = oblate_radius_ft(mission.constants, p.state[kStateLambda]);
    if (ok(evaluate_atmosphere(mission.atmosphere, mission.constants, p.altitude_ft, radius, &air))) {
      c.density_slug_ft3 = air.density_slug_ft3;
      const double ratio = radius / (radius + p.altitude_ft);
      c.ddensity_dh = air.ddensity_dh * ratio * ratio;
    }
  }
  return c;
}

int constraint_point_index(const ConstraintCode& code, const Trajectory& trajectory) {
  if (!code.is_stage_point) return trajectory.point_count - 1;
  for (int k = 0; k < trajectory.stage_count; ++k) {
    if (trajectory.stages[k].code == code.stage_code) return trajectory.stages[k].last_point;
  }
  return -1;
}

}  // namespace tolip
