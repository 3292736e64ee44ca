// The reports of `tolip montecarlo` (tolip_ground/monte_carlo_report.hpp).
#include "tolip_ground/monte_carlo_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "dispersion_quantities.hpp"
#include "number_format.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip_ground/dispersion_report.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;
using report_detail::fixed_cell;
using report_detail::json_number;
using report_detail::kOrbitQuantities;
using report_detail::kStagingQuantities;
using report_detail::round_trip;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The Monte Carlo's own quantities, beside the Sec. 15 ones of dispersion_quantities.hpp.
using Quantity = report_detail::DispersionQuantity;
constexpr Quantity kPerigee = {"PERIGEE ALT NMI", "perigee_altitude_nmi", 1.0, 3};
constexpr Quantity kApogee = {"APOGEE ALT NMI", "apogee_altitude_nmi", 1.0, 3};
constexpr Quantity kQbarAlpha = {"MAX QBAR*ALPHA LB DEG/FT2", "max_qbar_alpha_lb_deg_ft2", kRadToDeg, 1};
// The CSV columns of one casing (--impacts), after "casingK_".
constexpr const char* kCasingColumns[] = {"status",        "impact_time_s", "geodetic_latitude_deg",
                                          "longitude_deg", "downrange_nmi", "crossrange_nmi"};
constexpr Quantity kQbarAlphaTime = {"TIME OF MAX QBAR*ALPHA S", "max_qbar_alpha_time_s", 1.0, 2};

// Perigee and apogee altitudes (n.mi.) from the recorded TWOE, RP, EYE, BETAP (summarize_orbit: the
// oblate surface under perigee and apogee); NaN for a record that did not fly, apogee NaN unless
// the orbit is elliptic.
void orbit_altitudes(const Constants& constants, const DispersedTrajectory& t, double* perigee_nmi,
                     double* apogee_nmi) {
  *perigee_nmi = *apogee_nmi = kNaN;
  if (!ok(t.status)) return;
  OrbitElements e;
  e.twice_energy_ft2_s2 = t.orbit[0];
  e.perigee_radius_ft = t.orbit[2];
  e.inclination_rad = t.orbit[3];
  e.argument_of_perigee_rad = t.orbit[4];
  e.has_semi_major_axis = t.orbit[0] < 0.0;
  if (e.has_semi_major_axis) {
    e.semi_major_axis_ft = -constants.gravitational_parameter_ft3_s2 / t.orbit[0];
    e.apogee_radius_ft = 2.0 * e.semi_major_axis_ft - e.perigee_radius_ft;
  }
  const OrbitSummary s = summarize_orbit(constants, e);
  *perigee_nmi = s.perigee_altitude_ft / kFeetPerNauticalMile;
  *apogee_nmi = s.apogee_altitude_ft / kFeetPerNauticalMile;
}

// Whether `code` is the low code of a table pair whose high code is drawn: its table flies the
// pair's negative draws (monte_carlo_low_partner), so it is sampled without a draw of its own.
bool flies_low_table(const MonteCarloInputs& in, int code) {
  for (int k = 0; k < in.data->count; ++k) {
    const int partner = monte_carlo_low_partner(in.nominal, *in.data, k);
    if (partner >= 0 && in.data->sources[partner].code == code) return true;
  }
  return false;
}

// A quantity of a record, in report units; `Get` picks it.
template <typename Get>
QuantityStatistics quantity(const Quantity& q, const MonteCarloInputs& in, const MonteCarloSummary& summary,
                            const Get& get) {
  QuantityStatistics out;
  out.key = q.key;
  out.label = q.label;
  const DispersedTrajectory& nominal = in.samples->nominal;
  out.nominal = get(nominal, -1, false) * q.scale;
  std::vector<double> values;
  values.reserve(in.samples->samples.size());
  for (std::size_t i = 0; i < in.samples->samples.size(); ++i) {
    const DispersedTrajectory& t = in.samples->samples[i];
    if (ok(t.status)) values.push_back(get(t, static_cast<int>(i), true) * q.scale);
  }
  out.statistic = statistic_of(std::move(values));
  // The linear three-sigma: the RSS of the deterministic dispersions of the sources drawn (each the
  // source's three-sigma value; one per high/low pair, the code the pair's draw is keyed on). A table
  // pair whose negative draws fly the low table (monte_carlo_low_partner) contributes the mean of
  // its two squares: half the draws go each way.
  const auto linear_of = [&in](int code) -> const DispersedTrajectory* {
    for (int k = 0; k < in.linear->count; ++k) {
      if (in.linear->trajectories[k].code == code) return &in.linear->trajectories[k];
    }
    return nullptr;
  };
  double squares = 0.0;
  for (int code : summary.sampled_codes) {
    if (flies_low_table(in, code)) continue;  // counted with its high code
    const DispersedTrajectory* found = linear_of(code);
    if (found == nullptr || !ok(found->status)) {
      squares = kNaN;
      break;
    }
    const double d = get(*found, -1, true) * q.scale;
    int partner = -1;
    for (int k = 0; k < in.data->count; ++k) {
      if (in.data->sources[k].code == code) partner = monte_carlo_low_partner(in.nominal, *in.data, k);
    }
    if (partner < 0) {
      squares += d * d;
      continue;
    }
    const DispersedTrajectory* low = linear_of(in.data->sources[partner].code);
    if (low == nullptr || !ok(low->status)) {
      squares = kNaN;
      break;
    }
    const double l = get(*low, -1, true) * q.scale;
    squares += 0.5 * (d * d + l * l);
  }
  out.rss_three_sigma = std::sqrt(squares);
  return out;
}

// The downrange and crossrange dispersions (n.mi.) at `final_column` of every flown sample with
// both finite, in sample order: the burnout ellipse's points and its figure's.
void burnout_dispersions(const MonteCarloSamples& samples, int final_column, std::vector<double>* x,
                         std::vector<double>* y) {
  const int down = static_cast<int>(StagingVariable::kDownrange);
  const int cross = static_cast<int>(StagingVariable::kCrossrange);
  for (const DispersedTrajectory& t : samples.samples) {
    if (!ok(t.status)) continue;
    const double dx = t.dispersions[final_column][down];
    const double dy = t.dispersions[final_column][cross];
    if (std::isfinite(dx) && std::isfinite(dy)) {
      x->push_back(dx);
      y->push_back(dy);
    }
  }
}

DispersionEllipse burnout_ellipse(const MonteCarloSamples& samples, int final_column) {
  std::vector<double> x;
  std::vector<double> y;
  burnout_dispersions(samples, final_column, &x, &y);
  return dispersion_ellipse(x, y);
}

// The casing of `stage` among a record's, or null.
const ImpactCase* casing_of(const MonteCarloImpacts& impacts, int stage) {
  for (int k = 0; k < impacts.count; ++k) {
    if (impacts.casings[k].stage == stage) return &impacts.casings[k];
  }
  return nullptr;
}

CasingImpactStatistics casing_statistics(const MonteCarloSamples& samples, int stage) {
  CasingImpactStatistics c;
  c.stage = stage;
  c.casing_weight_lb = samples.impact_request.data->expended_casing[stage - 1].casing_weight_lb;
  const ImpactCase* nominal = casing_of(samples.nominal_impacts, stage);
  if (nominal != nullptr) {
    c.nominal = *nominal;
  } else {
    c.nominal.stage = stage;
    c.nominal.status = Status::kImpactNominalStageIncomplete;
  }
  const bool nominal_ok = ok(c.nominal.status);
  std::vector<double> x;
  std::vector<double> y;
  double time = 0.0, latitude = 0.0, longitude = 0.0, down = 0.0, cross = 0.0;
  for (std::size_t i = 0; i < samples.samples.size(); ++i) {
    if (!ok(samples.samples[i].status)) continue;
    const ImpactCase* casing = casing_of(samples.impacts[i], stage);
    if (casing == nullptr || !ok(casing->status)) {
      ++c.not_impacted;
      continue;
    }
    ++c.impacted;
    time += casing->impact_time_s;
    latitude += casing->geodetic_latitude_rad;
    longitude += std::remainder(casing->longitude_rad - c.nominal.longitude_rad, 2.0 * kPi);
    down += casing->downrange_rad;
    cross += casing->crossrange_rad;
    x.push_back((casing->downrange_rad - c.nominal.downrange_rad) * kNauticalMilesPerRadian);
    y.push_back((casing->crossrange_rad - c.nominal.crossrange_rad) * kNauticalMilesPerRadian);
  }
  if (c.impacted == 0 || !nominal_ok) {
    c.mean_impact_time_s = c.mean_geodetic_latitude_deg = c.mean_longitude_deg = kNaN;
    c.mean_downrange_nmi = c.mean_crossrange_nmi = kNaN;
    c.ellipse = dispersion_ellipse({}, {});
    c.ellipse.center_downrange_nmi = c.ellipse.center_crossrange_nmi = kNaN;
    return c;
  }
  const double n = static_cast<double>(c.impacted);
  c.mean_impact_time_s = time / n;
  c.mean_geodetic_latitude_deg = latitude / n * kRadToDeg;
  c.mean_longitude_deg = std::remainder(c.nominal.longitude_rad + longitude / n, 2.0 * kPi) * kRadToDeg;
  c.mean_downrange_nmi = down / n * kNauticalMilesPerRadian;
  c.mean_crossrange_nmi = cross / n * kNauticalMilesPerRadian;
  c.ellipse = dispersion_ellipse(x, y);
  return c;
}

json statistic_json(const QuantityStatistics& q) {
  const MonteCarloStatistic& s = q.statistic;
  const bool any = s.count > 0;
  const double mc3 = 3.0 * s.standard_deviation;
  return json{{"nominal", json_number(q.nominal)},
              {"count", s.count},
              {"mean", any ? json_number(s.mean) : json(nullptr)},
              {"standard_deviation", any ? json_number(s.standard_deviation) : json(nullptr)},
              {"p00135", any ? json_number(s.p00135) : json(nullptr)},
              {"p50", any ? json_number(s.p50) : json(nullptr)},
              {"p99865", any ? json_number(s.p99865) : json(nullptr)},
              {"monte_carlo_3sigma", any ? json_number(mc3) : json(nullptr)},
              {"rss_3sigma", json_number(q.rss_three_sigma)},
              {"monte_carlo_over_rss",
               (any && q.rss_three_sigma > 0.0) ? json_number(mc3 / q.rss_three_sigma) : json(nullptr)}};
}

json codes_json(const std::vector<int>& codes) {
  json out = json::array();
  for (int code : codes) out.push_back(code);
  return out;
}

int final_column(const MonteCarloInputs& in) { return in.linear->staging_count - 1; }

json ellipse_json(const DispersionEllipse& e) {
  return json{{"probability", e.probability},
              {"center_downrange_nmi", json_number(e.center_downrange_nmi)},
              {"center_crossrange_nmi", json_number(e.center_crossrange_nmi)},
              {"semi_major_nmi", json_number(e.semi_major_nmi)},
              {"semi_minor_nmi", json_number(e.semi_minor_nmi)},
              {"major_axis_angle_deg", json_number(e.major_axis_angle_deg)},
              {"fraction_inside", json_number(e.fraction_inside)}};
}

json casing_json(const CasingImpactStatistics& c) {
  const ImpactCase& n = c.nominal;
  const bool flown = ok(n.status);
  json nominal = json{
      {"status", status_name(n.status)},
      {"separation_time_s", flown ? json_number(n.failure_time_s) : json(nullptr)},
      {"impact_time_s", flown ? json_number(n.impact_time_s) : json(nullptr)},
      {"geodetic_latitude_deg", flown ? json_number(n.geodetic_latitude_rad * kRadToDeg) : json(nullptr)},
      {"longitude_deg", flown ? json_number(n.longitude_rad * kRadToDeg) : json(nullptr)},
      {"downrange_nmi", flown ? json_number(n.downrange_rad * kNauticalMilesPerRadian) : json(nullptr)},
      {"crossrange_nmi", flown ? json_number(n.crossrange_rad * kNauticalMilesPerRadian) : json(nullptr)}};
  json mean = json{{"impact_time_s", json_number(c.mean_impact_time_s)},
                   {"geodetic_latitude_deg", json_number(c.mean_geodetic_latitude_deg)},
                   {"longitude_deg", json_number(c.mean_longitude_deg)},
                   {"downrange_nmi", json_number(c.mean_downrange_nmi)},
                   {"crossrange_nmi", json_number(c.mean_crossrange_nmi)}};
  return json{{"stage", c.stage},
              {"casing_weight_lb", json_number(c.casing_weight_lb)},
              {"nominal", std::move(nominal)},
              {"impacted", c.impacted},
              {"not_impacted", c.not_impacted},
              {"mean", std::move(mean)},
              {"ellipse", ellipse_json(c.ellipse)}};
}

}  // namespace

DispersionEllipse dispersion_ellipse(const std::vector<double>& x, const std::vector<double>& y) {
  DispersionEllipse e;
  const std::size_t n = std::min(x.size(), y.size());
  if (n < 3) {
    e.semi_major_nmi = e.semi_minor_nmi = e.major_axis_angle_deg = e.fraction_inside = kNaN;
    return e;
  }
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(n);
  my /= static_cast<double>(n);
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  sxx /= static_cast<double>(n - 1);
  syy /= static_cast<double>(n - 1);
  sxy /= static_cast<double>(n - 1);
  // Axes of the covariance; a two-dimensional normal lies inside k sigma-ellipses with probability
  // 1 - exp(-k^2 / 2), so the 99.7 % ellipse has k^2 = -2 ln(0.003).
  const double k2 = -2.0 * std::log(1.0 - e.probability);
  const double half_sum = 0.5 * (sxx + syy);
  const double root = std::hypot(0.5 * (sxx - syy), sxy);
  const double major = half_sum + root;
  const double minor = std::max(half_sum - root, 0.0);
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  e.center_downrange_nmi = mx;
  e.center_crossrange_nmi = my;
  e.semi_major_nmi = std::sqrt(k2 * major);
  e.semi_minor_nmi = std::sqrt(k2 * minor);
  e.major_axis_angle_deg = angle * kRadToDeg;
  // Inside: Mahalanobis distance^2 <= k^2 (the inverse covariance; none for a degenerate one).
  const double det = sxx * syy - sxy * sxy;
  if (!(det > 0.0)) {
    e.fraction_inside = kNaN;
    return e;
  }
  std::size_t inside = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u = x[i] - mx;
    const double v = y[i] - my;
    if ((syy * u * u - 2.0 * sxy * u * v + sxx * v * v) / det <= k2) ++inside;
  }
  e.fraction_inside = static_cast<double>(inside) / static_cast<double>(n);
  return e;
}

MonteCarloSummary summarize_monte_carlo(const MonteCarloInputs& in) {
  MonteCarloSummary s;
  const MonteCarloSamples& samples = *in.samples;
  s.samples = static_cast<int>(samples.samples.size());
  for (int k = 0; k < in.data->count; ++k) {
    const int code = in.data->sources[k].code;
    if (code == kNominalDispersionCode) continue;
    const bool sampled = monte_carlo_draws_source(in.nominal, *in.data, k) || flies_low_table(in, code);
    (sampled ? s.sampled_codes : s.not_sampled_codes).push_back(code);
  }
  const double threshold_nmi = in.orbit_perigee_nmi;
  s.perigee_altitude_nmi.assign(samples.samples.size(), kNaN);
  s.apogee_altitude_nmi.assign(samples.samples.size(), kNaN);
  s.reaches_orbit.assign(samples.samples.size(), false);
  for (std::size_t i = 0; i < samples.samples.size(); ++i) {
    const DispersedTrajectory& t = samples.samples[i];
    if (!ok(t.status)) continue;
    ++s.flown;
    orbit_altitudes(*in.constants, t, &s.perigee_altitude_nmi[i], &s.apogee_altitude_nmi[i]);
    s.reaches_orbit[i] = s.perigee_altitude_nmi[i] > threshold_nmi;
    if (s.reaches_orbit[i]) ++s.reaching_orbit;
  }

  for (int j = 0; j < in.linear->staging_count; ++j) {
    StagingColumnStatistics column;
    column.stage_code = in.linear->staging_stage_code[j];
    for (int v = 0; v < kStagingVariables; ++v) {
      column.quantities.push_back(
          quantity(kStagingQuantities[v], in, s, [j, v](const DispersedTrajectory& t, int, bool dispersion) {
            return dispersion ? t.dispersions[j][v] : t.values[j][v];
          }));
    }
    s.columns.push_back(std::move(column));
  }
  for (int e = 0; e < kOrbitDispersionElements; ++e) {
    s.orbit.push_back(
        quantity(kOrbitQuantities[e], in, s, [e](const DispersedTrajectory& t, int, bool dispersion) {
          return dispersion ? t.orbit_dispersions[e] : t.orbit[e];
        }));
  }
  double nominal_perigee = kNaN, nominal_apogee = kNaN;
  orbit_altitudes(*in.constants, samples.nominal, &nominal_perigee, &nominal_apogee);
  const Constants& constants = *in.constants;
  const auto altitudes = [&constants](const DispersedTrajectory& t, double* p, double* a) {
    orbit_altitudes(constants, t, p, a);
  };
  s.orbit.push_back(quantity(kPerigee, in, s, [&](const DispersedTrajectory& t, int, bool dispersion) {
    double p = kNaN, a = kNaN;
    altitudes(t, &p, &a);
    return dispersion ? p - nominal_perigee : p;
  }));
  s.orbit.push_back(quantity(kApogee, in, s, [&](const DispersedTrajectory& t, int, bool dispersion) {
    double p = kNaN, a = kNaN;
    altitudes(t, &p, &a);
    return dispersion ? a - nominal_apogee : a;
  }));
  const DispersedTrajectory& nominal = samples.nominal;
  s.max_qbar_alpha.push_back(quantity(kQbarAlpha, in, s, [&](const DispersedTrajectory& t, int, bool d) {
    return d ? t.max_qbar_alpha_lbf_rad_ft2 - nominal.max_qbar_alpha_lbf_rad_ft2
             : t.max_qbar_alpha_lbf_rad_ft2;
  }));
  s.max_qbar_alpha.push_back(quantity(kQbarAlphaTime, in, s, [&](const DispersedTrajectory& t, int, bool d) {
    return d ? t.max_qbar_alpha_time_s - nominal.max_qbar_alpha_time_s : t.max_qbar_alpha_time_s;
  }));
  s.burnout_ellipse = burnout_ellipse(samples, final_column(in));
  if (samples.impact_request.data != nullptr) {
    for (int stage = 1; stage <= kImpactStages; ++stage) {
      if (samples.impact_request.stages[stage - 1])
        s.impact_ellipses.push_back(casing_statistics(samples, stage));
    }
  }
  return s;
}

json monte_carlo_json(const MonteCarloInputs& in, const MonteCarloSummary& s) {
  json out = json::object();
  out["seed"] = in.seed;
  out["samples"] = s.samples;
  out["flown"] = s.flown;
  out["failed"] = s.samples - s.flown;
  out["nominal_kind"] = in.nominal_kind;
  out["distribution"] = "normal, 1 sigma = the deck's three-sigma value / 3";
  out["sampled_codes"] = codes_json(s.sampled_codes);
  out["not_sampled_codes"] = codes_json(s.not_sampled_codes);
  out["orbit_perigee_altitude_nmi"] = in.orbit_perigee_nmi;
  out["reaching_orbit"] = s.reaching_orbit;
  out["fraction_reaching_orbit"] =
      s.samples > 0 ? json_number(static_cast<double>(s.reaching_orbit) / s.samples) : json(nullptr);
  json points = json::array();
  for (const StagingColumnStatistics& column : s.columns) {
    json point = json::object();
    point["point"] = staging_point_key(column.stage_code);
    point["stage_code"] = column.stage_code;
    for (const QuantityStatistics& q : column.quantities) point[q.key] = statistic_json(q);
    points.push_back(std::move(point));
  }
  out["staging_points"] = std::move(points);
  json orbit = json::object();
  for (const QuantityStatistics& q : s.orbit) orbit[q.key] = statistic_json(q);
  out["orbit_elements"] = std::move(orbit);
  for (const QuantityStatistics& q : s.max_qbar_alpha) out[q.key] = statistic_json(q);
  out["burnout_ellipse"] = ellipse_json(s.burnout_ellipse);
  if (in.samples->impact_request.data != nullptr) {
    json casings = json::array();
    for (const CasingImpactStatistics& c : s.impact_ellipses) casings.push_back(casing_json(c));
    out["impact_ellipses"] = std::move(casings);
  }
  return out;
}

void write_monte_carlo_listing(std::ostream& out, const MonteCarloInputs& in, const MonteCarloSummary& s) {
  char line[512];
  out << " MONTE CARLO DISPERSIONS  (beyond the manual; docs/theory/dispersions.md)\n";
  out << " DECK " << in.deck_path << "\n";
  std::snprintf(line, sizeof line, " SEED %llu   SAMPLES %d   FLOWN %d   FAILED %d   NOMINAL: %s\n",
                static_cast<unsigned long long>(in.seed), s.samples, s.flown, s.samples - s.flown,
                in.nominal_kind.c_str());
  out << line;
  out << " SAMPLED CODES:";
  for (int code : s.sampled_codes) out << ' ' << code;
  out << "\n NOT SAMPLED:  ";
  for (int code : s.not_sampled_codes) out << ' ' << code;
  if (s.not_sampled_codes.empty()) out << " (none)";
  std::snprintf(line, sizeof line, "\n REACHING ORBIT (PERIGEE ABOVE %.3f NMI): %d OF %d (%.2f %%)\n\n",
                in.orbit_perigee_nmi, s.reaching_orbit, s.samples,
                s.samples > 0 ? 100.0 * s.reaching_orbit / s.samples : 0.0);
  out << line;
  const auto header = [&out](const std::string& title) {
    out << ' ' << title << "   (statistics of the dispersion from the nominal)\n";
    std::string text(29, ' ');
    for (const char* name :
         {"NOMINAL", "MEAN", "SIGMA", "P0.135", "P50", "P99.865", "MC 3-SIGMA", "RSS 3-SIGMA"}) {
      const std::string cell(name);
      const std::size_t width = (text.size() == 29) ? 16 : 14;
      text += std::string(width - cell.size(), ' ') + cell;
    }
    out << text << '\n';
  };
  const auto row = [&out](const QuantityStatistics& q, int decimals) {
    const MonteCarloStatistic& st = q.statistic;
    std::string text = "   " + q.label;
    text.resize(29, ' ');
    text += fixed_cell(q.nominal, decimals, 16);
    for (double v :
         {st.mean, st.standard_deviation, st.p00135, st.p50, st.p99865, 3.0 * st.standard_deviation})
      text += fixed_cell(st.count > 0 ? v : kNaN, decimals, 14);
    text += fixed_cell(q.rss_three_sigma, decimals, 14);
    out << text << '\n';
  };
  for (const StagingColumnStatistics& column : s.columns) {
    header(staging_point_name(column.stage_code));
    for (int v = 0; v < kStagingVariables; ++v)
      row(column.quantities[static_cast<std::size_t>(v)], kStagingQuantities[v].decimals);
    out << '\n';
  }
  header("ORBIT ELEMENTS AT THE FINAL POINT");
  for (std::size_t e = 0; e < s.orbit.size(); ++e) {
    row(s.orbit[e], e < kOrbitDispersionElements ? kOrbitQuantities[e].decimals : 3);
  }
  row(s.max_qbar_alpha[0], kQbarAlpha.decimals);
  row(s.max_qbar_alpha[1], kQbarAlphaTime.decimals);
  const DispersionEllipse& e = s.burnout_ellipse;
  std::snprintf(line, sizeof line,
                "\n BURNOUT POINT 99.7 %% ELLIPSE (DOWNRANGE/CROSSRANGE DISPERSION): CENTER %.4f, %.4f NMI;"
                " SEMI-AXES %.4f, %.4f NMI; MAJOR AXIS %.3f DEG FROM DOWNRANGE; %.2f %% OF SAMPLES INSIDE\n",
                e.center_downrange_nmi, e.center_crossrange_nmi, e.semi_major_nmi, e.semi_minor_nmi,
                e.major_axis_angle_deg, 100.0 * e.fraction_inside);
  out << line;
  if (!s.impact_ellipses.empty()) {
    out << "\n EXPENDED CASING IMPACTS (SEC. 17, DATA BLOCK 43; RANGES FROM THE LAUNCH SITE AND THE NOMINAL"
           " AZIMUTH)\n";
  }
  for (const CasingImpactStatistics& c : s.impact_ellipses) {
    const ImpactCase& n = c.nominal;
    if (!ok(n.status)) {
      std::snprintf(line, sizeof line, " STAGE %d CASING: NOMINAL NOT FLOWN TO IMPACT: %s\n", c.stage,
                    status_name(n.status));
      out << line;
      continue;
    }
    std::snprintf(line, sizeof line,
                  " STAGE %d CASING %.1f LB  NOMINAL IMPACT: T %.2f S, GEODETIC LAT %.4f DEG, LON %.4f DEG,"
                  " DOWNRANGE %.3f NMI, CROSSRANGE %.3f NMI\n",
                  c.stage, c.casing_weight_lb, n.impact_time_s, n.geodetic_latitude_rad * kRadToDeg,
                  n.longitude_rad * kRadToDeg, n.downrange_rad * kNauticalMilesPerRadian,
                  n.crossrange_rad * kNauticalMilesPerRadian);
    out << line;
    std::snprintf(line, sizeof line,
                  "   %d SAMPLES IMPACTED (%d NOT); MEAN: LAT %.4f DEG, LON %.4f DEG, DOWNRANGE %.3f NMI,"
                  " CROSSRANGE %.3f NMI\n",
                  c.impacted, c.not_impacted, c.mean_geodetic_latitude_deg, c.mean_longitude_deg,
                  c.mean_downrange_nmi, c.mean_crossrange_nmi);
    out << line;
    const DispersionEllipse& ce = c.ellipse;
    std::snprintf(line, sizeof line,
                  "   99.7 %% ELLIPSE (DISPERSION FROM THE NOMINAL IMPACT): CENTER %.4f, %.4f NMI;"
                  " SEMI-AXES %.4f, %.4f NMI; MAJOR AXIS %.3f DEG FROM DOWNRANGE; %.2f %% INSIDE\n",
                  ce.center_downrange_nmi, ce.center_crossrange_nmi, ce.semi_major_nmi, ce.semi_minor_nmi,
                  ce.major_axis_angle_deg, 100.0 * ce.fraction_inside);
    out << line;
  }
}

void write_monte_carlo_csv(std::ostream& out, const MonteCarloInputs& in, const MonteCarloSummary& s) {
  const DispersionResult& r = *in.linear;
  out << "sample,status";
  for (int j = 0; j < r.staging_count; ++j) {
    const std::string point = staging_point_key(r.staging_stage_code[j]);
    for (const Quantity& v : kStagingQuantities) out << ',' << point << '_' << v.key;
    for (const Quantity& v : kStagingQuantities) out << ",d_" << point << '_' << v.key;
  }
  for (const Quantity& o : kOrbitQuantities) out << ',' << o.key;
  for (const Quantity& o : kOrbitQuantities) out << ",d_" << o.key;
  out << ",perigee_altitude_nmi,apogee_altitude_nmi,reaches_orbit,max_qbar_alpha_lb_deg_ft2,"
         "max_qbar_alpha_time_s";
  for (const CasingImpactStatistics& c : s.impact_ellipses) {
    const std::string stem = ",casing" + std::to_string(c.stage) + "_";
    for (const char* column : kCasingColumns) out << stem << column;
  }
  out << '\n';
  for (std::size_t i = 0; i < in.samples->samples.size(); ++i) {
    const DispersedTrajectory& t = in.samples->samples[i];
    out << i << ',' << status_name(t.status);
    if (ok(t.status)) {
      for (int j = 0; j < r.staging_count; ++j) {
        for (int v = 0; v < kStagingVariables; ++v)
          out << ',' << round_trip(t.values[j][v] * kStagingQuantities[v].scale);
        for (int v = 0; v < kStagingVariables; ++v)
          out << ',' << round_trip(t.dispersions[j][v] * kStagingQuantities[v].scale);
      }
      for (int e = 0; e < kOrbitDispersionElements; ++e)
        out << ',' << round_trip(t.orbit[e] * kOrbitQuantities[e].scale);
      for (int e = 0; e < kOrbitDispersionElements; ++e)
        out << ',' << round_trip(t.orbit_dispersions[e] * kOrbitQuantities[e].scale);
      out << ',' << round_trip(s.perigee_altitude_nmi[i]) << ',' << round_trip(s.apogee_altitude_nmi[i])
          << ',' << (s.reaches_orbit[i] ? 1 : 0) << ','
          << round_trip(t.max_qbar_alpha_lbf_rad_ft2 * kRadToDeg) << ','
          << round_trip(t.max_qbar_alpha_time_s);
    } else {
      const int empty = r.staging_count * 2 * kStagingVariables + 2 * kOrbitDispersionElements + 2;
      for (int k = 0; k < empty; ++k) out << ',';
      out << ",0,,";
    }
    for (const CasingImpactStatistics& c : s.impact_ellipses) {
      const ImpactCase* casing = ok(t.status) ? casing_of(in.samples->impacts[i], c.stage) : nullptr;
      if (casing == nullptr) {
        out << ",,,,,,";
        continue;
      }
      out << ',' << status_name(casing->status);
      if (!ok(casing->status)) {
        out << ",,,,,";
        continue;
      }
      out << ',' << round_trip(casing->impact_time_s) << ','
          << round_trip(casing->geodetic_latitude_rad * kRadToDeg) << ','
          << round_trip(casing->longitude_rad * kRadToDeg) << ','
          << round_trip(casing->downrange_rad * kNauticalMilesPerRadian) << ','
          << round_trip(casing->crossrange_rad * kNauticalMilesPerRadian);
    }
    out << '\n';
  }
}

namespace {

// A histogram as a step outline, the normal of the same mean and sigma over it, and markers at the
// nominal and the 0.135 / 99.865 % points.
Figure histogram(const std::string& name, const std::string& title, const std::string& x_label,
                 const std::vector<double>& raw, double nominal, const std::vector<std::string>& subtitle) {
  Figure f;
  f.name = name;
  f.title = title;
  f.x_label = x_label;
  f.y_label = "samples per bin";
  f.subtitle = subtitle;
  std::vector<double> values;
  for (double v : raw) {
    if (std::isfinite(v)) values.push_back(v);
  }
  if (values.empty()) return f;
  const MonteCarloStatistic st = statistic_of(values);
  const auto [lo_it, hi_it] = std::minmax_element(values.begin(), values.end());
  double lo = *lo_it, hi = *hi_it;
  if (!(hi > lo)) {
    lo -= 0.5;
    hi += 0.5;
  }
  const int bins = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(values.size()))), 5, 60);
  const double width = (hi - lo) / bins;
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  for (double v : values) {
    const int b = std::clamp(static_cast<int>((v - lo) / width), 0, bins - 1);
    ++counts[static_cast<std::size_t>(b)];
  }
  PlotSeries bars;
  bars.title = "Monte Carlo samples (" + std::to_string(values.size()) + ")";
  bars.x.push_back(lo);
  bars.y.push_back(0.0);
  for (int b = 0; b < bins; ++b) {
    const double left = lo + b * width;
    bars.x.insert(bars.x.end(), {left, left + width});
    bars.y.insert(bars.y.end(),
                  {double(counts[static_cast<std::size_t>(b)]), double(counts[static_cast<std::size_t>(b)])});
  }
  bars.x.push_back(hi);
  bars.y.push_back(0.0);
  f.series.push_back(std::move(bars));
  if (st.standard_deviation > 0.0) {
    PlotSeries normal;
    normal.title = "normal of the sample mean and sigma";
    normal.dashed = true;
    for (int k = 0; k <= 200; ++k) {
      const double x = lo + (hi - lo) * k / 200.0;
      const double z = (x - st.mean) / st.standard_deviation;
      normal.x.push_back(x);
      normal.y.push_back(values.size() * width * std::exp(-0.5 * z * z) /
                         (st.standard_deviation * std::sqrt(2.0 * kPi)));
    }
    f.series.push_back(std::move(normal));
  }
  f.x_markers.push_back({nominal, "nominal", 0});
  f.x_markers.push_back({st.p00135, "0.135 %", 0});
  f.x_markers.push_back({st.p99865, "99.865 %", 0});
  return f;
}

// Points in a downrange-crossrange plane (n.mi.), the nominal point (x0, y0) and the 99.7 %
// ellipse about the mean (its centre given relative to the nominal): the one drawing of every
// Monte Carlo ellipse. Both axes are n.mi.: at equal scale the ellipse shows its true shape.
Figure ellipse_scatter(const std::string& name, const std::string& title, const std::string& y_label,
                       PlotSeries points, double x0, double y0, const DispersionEllipse& e,
                       const std::vector<std::string>& subtitle) {
  Figure f;
  f.name = name;
  f.title = title;
  f.x_label = "downrange (n.mi.)";
  f.y_label = y_label;
  f.subtitle = subtitle;
  f.equal_axis_scale = true;
  points.style = SeriesStyle::kPoints;
  f.series.push_back(std::move(points));
  if (std::isfinite(e.semi_major_nmi) && std::isfinite(e.semi_minor_nmi)) {
    PlotSeries outline;
    outline.title = "99.7 % ellipse";
    const double a = e.major_axis_angle_deg / kRadToDeg;
    for (int k = 0; k <= 180; ++k) {
      const double t = 2.0 * kPi * k / 180.0;
      const double u = e.semi_major_nmi * std::cos(t);
      const double v = e.semi_minor_nmi * std::sin(t);
      outline.x.push_back(x0 + e.center_downrange_nmi + u * std::cos(a) - v * std::sin(a));
      outline.y.push_back(y0 + e.center_crossrange_nmi + u * std::sin(a) + v * std::cos(a));
    }
    f.series.push_back(std::move(outline));
  }
  f.points.push_back({x0, y0, "nominal", 0});
  return f;
}

// The impact points of one stage's casing (downrange, crossrange from the launch site, n.mi.), the
// nominal impact and the 99.7 % ellipse about the mean.
Figure casing_figure(const MonteCarloInputs& in, const CasingImpactStatistics& c,
                     const std::vector<std::string>& subtitle) {
  PlotSeries points;
  points.title = "samples (" + std::to_string(c.impacted) + " impacted)";
  for (std::size_t i = 0; i < in.samples->samples.size(); ++i) {
    if (!ok(in.samples->samples[i].status)) continue;
    const ImpactCase* casing = casing_of(in.samples->impacts[i], c.stage);
    if (casing == nullptr || !ok(casing->status)) continue;
    points.x.push_back(casing->downrange_rad * kNauticalMilesPerRadian);
    points.y.push_back(casing->crossrange_rad * kNauticalMilesPerRadian);
  }
  return ellipse_scatter(
      "montecarlo_stage" + std::to_string(c.stage) + "_casing_impacts",
      "Stage " + std::to_string(c.stage) + " expended casing impact points (Sec. 17, data block 43)",
      "crossrange (n.mi., right of the nominal azimuth)", std::move(points),
      c.nominal.downrange_rad * kNauticalMilesPerRadian, c.nominal.crossrange_rad * kNauticalMilesPerRadian,
      c.ellipse, subtitle);
}

// The final point of every flown sample (downrange and crossrange, Sec. 4's range equations, n.mi.),
// the nominal's and the burnout ellipse of the JSON and the listing.
Figure burnout_point_figure(const MonteCarloInputs& in, const MonteCarloSummary& s, int final,
                            const std::vector<std::string>& subtitle) {
  const int down = static_cast<int>(StagingVariable::kDownrange);
  const int cross = static_cast<int>(StagingVariable::kCrossrange);
  const DispersedTrajectory& nominal = in.samples->nominal;
  PlotSeries points;
  points.title = "samples (" + std::to_string(s.flown) + " flown)";
  burnout_dispersions(*in.samples, final, &points.x, &points.y);
  for (double& x : points.x) x += nominal.values[final][down];
  for (double& y : points.y) y += nominal.values[final][cross];
  return ellipse_scatter("montecarlo_burnout_point", "Final burnout point (Sec. 4 downrange and crossrange)",
                         "crossrange (n.mi.)", std::move(points), nominal.values[final][down],
                         nominal.values[final][cross], s.burnout_ellipse, subtitle);
}

}  // namespace

std::vector<Figure> monte_carlo_figures(const MonteCarloInputs& in, const MonteCarloSummary& s) {
  const std::vector<std::string> subtitle = {
      in.deck_path + ": " + std::to_string(s.samples) + " samples, seed " + std::to_string(in.seed) + ", " +
      std::to_string(s.flown) + " flown; about the " + in.nominal_kind};
  const int final = final_column(in);
  std::vector<Figure> figures;
  struct Histogram {
    const char* name;
    const char* title;
    const char* x_label;
    int variable;
  };
  const Histogram histograms[] = {
      {"montecarlo_burnout_altitude", "Burnout altitude", "altitude (ft)", 0},
      {"montecarlo_burnout_velocity", "Burnout velocity (Earth-relative)", "velocity (ft/s)", 1},
      {"montecarlo_burnout_flight_path_angle", "Burnout flight-path angle", "flight-path angle (deg)", 2},
  };
  for (const Histogram& h : histograms) {
    std::vector<double> values;
    for (const DispersedTrajectory& t : in.samples->samples) {
      if (ok(t.status)) values.push_back(t.values[final][h.variable] * kStagingQuantities[h.variable].scale);
    }
    figures.push_back(histogram(
        h.name, h.title, h.x_label, values,
        in.samples->nominal.values[final][h.variable] * kStagingQuantities[h.variable].scale, subtitle));
  }

  Figure scatter;
  scatter.name = "montecarlo_perigee_apogee";
  scatter.title = "Perigee vs apogee altitude";
  scatter.x_label = "perigee altitude (n.mi.)";
  scatter.y_label = "apogee altitude (n.mi.)";
  scatter.subtitle = subtitle;
  PlotSeries points;
  points.title = "samples (elliptic orbits)";
  points.style = SeriesStyle::kPoints;
  for (std::size_t i = 0; i < s.perigee_altitude_nmi.size(); ++i) {
    if (std::isfinite(s.perigee_altitude_nmi[i]) && std::isfinite(s.apogee_altitude_nmi[i])) {
      points.x.push_back(s.perigee_altitude_nmi[i]);
      points.y.push_back(s.apogee_altitude_nmi[i]);
    }
  }
  // The threshold inside the range drawn, however far the samples lie from it.
  if (!points.x.empty()) {
    const auto [lo, hi] = std::minmax_element(points.x.begin(), points.x.end());
    const double from = std::min(*lo, in.orbit_perigee_nmi);
    const double to = std::max(*hi, in.orbit_perigee_nmi);
    const double margin = 0.05 * std::max(to - from, 1.0);
    scatter.x_min = from - margin;
    scatter.x_max = to + margin;
  }
  scatter.series.push_back(std::move(points));
  scatter.x_markers.push_back({in.orbit_perigee_nmi, "orbit threshold", 0});
  const QuantityStatistics& perigee = s.orbit[kOrbitDispersionElements];
  const QuantityStatistics& apogee = s.orbit[kOrbitDispersionElements + 1];
  if (std::isfinite(perigee.nominal) && std::isfinite(apogee.nominal))
    scatter.points.push_back({perigee.nominal, apogee.nominal, "nominal", 0});
  figures.push_back(std::move(scatter));

  Figure ratio;
  ratio.name = "montecarlo_rss_comparison";
  ratio.title = "Monte Carlo 3-sigma / linear RSS 3-sigma (Sec. 15) at every staging point";
  std::string columns;
  for (std::size_t j = 0; j < s.columns.size(); ++j) {
    columns += (j ? ", " : "") + std::to_string(j + 1) + " = " + staging_point_key(s.columns[j].stage_code);
  }
  ratio.x_label = "staging point (" + columns + ")";
  ratio.y_label = "Monte Carlo 3-sigma / RSS 3-sigma";
  ratio.subtitle = subtitle;
  for (int v = 0; v < kStagingVariables; ++v) {
    PlotSeries series;
    series.title = kStagingQuantities[v].key;
    series.style = SeriesStyle::kLinesPoints;
    for (std::size_t j = 0; j < s.columns.size(); ++j) {
      const QuantityStatistics& q = s.columns[j].quantities[static_cast<std::size_t>(v)];
      series.x.push_back(static_cast<double>(j + 1));
      series.y.push_back(q.rss_three_sigma > 0.0 ? 3.0 * q.statistic.standard_deviation / q.rss_three_sigma
                                                 : kNaN);
    }
    ratio.series.push_back(std::move(series));
  }
  ratio.y_lines.push_back({1.0, false, "equal"});
  ratio.x_min = 0.5;
  ratio.x_max = static_cast<double>(s.columns.size()) + 0.5;
  figures.push_back(std::move(ratio));
  figures.push_back(burnout_point_figure(in, s, final, subtitle));
  for (const CasingImpactStatistics& c : s.impact_ellipses) {
    if (!ok(c.nominal.status)) continue;
    figures.push_back(casing_figure(in, c, subtitle));
  }
  return figures;
}

}  // namespace tolip::ground
