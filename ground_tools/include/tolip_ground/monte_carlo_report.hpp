// The reports of `tolip montecarlo` (docs/cli.md "tolip montecarlo"; docs/theory/dispersions.md
// "Monte Carlo"): the statistics of every Sec. 15 quantity over the samples (mean, standard
// deviation, 0.135/50/99.865 % points) beside the manual's linear RSS three-sigma of the same
// sources, the fraction of samples reaching orbit, the 99.7 % ellipse of the burnout point (and, with
// the casing impacts, of every casing's impact point); as a
// listing, one JSON document, a CSV of every sample and gnuplot figures. Everything is formed from
// the samples in sample order, so the same samples give the same bytes whoever flew them.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip/core/constants.hpp"
#include "tolip_ground/monte_carlo_run.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::ground {

// The default perigee altitude a sample must exceed to count as reaching orbit (--orbit-perigee-nmi).
inline constexpr double kDefaultOrbitPerigee_nmi = 100.0;

// What the reports are formed from (all owned by the caller).
struct MonteCarloInputs {
  std::uint64_t seed = 0;
  std::string deck_path;
  std::string nominal_kind;  // "linearized program" or "optimum"
  double orbit_perigee_nmi = kDefaultOrbitPerigee_nmi;
  const Constants* constants = nullptr;      // the nominal case's (perigee and apogee altitudes)
  DispersionNominal nominal;                 // what was sampled about
  const DispersionData* data = nullptr;      // the deck's data blocks 46-55
  const DispersionResult* linear = nullptr;  // run_dispersions of the same data (columns, RSS)
  const MonteCarloSamples* samples = nullptr;
};

// One quantity: the nominal value and the statistics of the samples' dispersions from it (units of
// the key), the Monte Carlo three-sigma (3 x the standard deviation) and the RSS three-sigma of the
// deterministic dispersions of the sources drawn (NaN when one of them did not fly).
struct QuantityStatistics {
  std::string key;    // "altitude_ft"
  std::string label;  // "ALTITUDE FT"
  double nominal = 0.0;
  MonteCarloStatistic statistic;
  double rss_three_sigma = 0.0;
};

struct StagingColumnStatistics {
  int stage_code = 0;                          // powered stage at ignition; 0: final point
  std::vector<QuantityStatistics> quantities;  // the five staging variables
};

// The 99.7 % ellipse of the burnout point (final-point downrange, crossrange dispersions, n.mi.):
// the sample covariance's axes scaled by sqrt(chi-square 2 dof at 0.997) = sqrt(-2 ln 0.003).
struct DispersionEllipse {
  double probability = 0.997;
  double center_downrange_nmi = 0.0;
  double center_crossrange_nmi = 0.0;
  double semi_major_nmi = 0.0;
  double semi_minor_nmi = 0.0;
  double major_axis_angle_deg = 0.0;  // from the downrange axis toward +crossrange, (-90, 90]
  double fraction_inside = 0.0;       // of the samples that flew
};

// The 99.7 % ellipse of the points (x[i], y[i]) (finite pairs of equal-length vectors, in sample
// order): the one computation of every Monte Carlo ellipse (the burnout point's, the casings'
// impacts'). Fewer than 3 points: the axes, angle and fraction NaN; a degenerate covariance: the
// fraction NaN.
DispersionEllipse dispersion_ellipse(const std::vector<double>& x, const std::vector<double>& y);

// One stage's expended casing over the samples (--impacts; Sec. 17 data block 43): the nominal's
// impact (fly_monte_carlo_casings about the nominal: the casing line of the impact locus about the
// same nominal), the samples whose casing reached the surface, their mean impact point and the
// 99.7 % ellipse of their downrange and crossrange (Sec. 4, from the launch site and the nominal's
// azimuth) dispersion from the nominal impact, n.mi.
struct CasingImpactStatistics {
  int stage = 0;
  double casing_weight_lb = 0.0;  // the nominal's (block 43)
  ImpactCase nominal;             // status: kImpactNominalStageIncomplete when not flown
  int impacted = 0;               // samples that flew and whose casing reached the surface
  int not_impacted = 0;           // samples that flew but whose casing did not
  double mean_impact_time_s = 0.0;
  double mean_geodetic_latitude_deg = 0.0;
  double mean_longitude_deg = 0.0;  // about the nominal's longitude, (-180, 180]
  double mean_downrange_nmi = 0.0;
  double mean_crossrange_nmi = 0.0;
  DispersionEllipse ellipse;  // of the dispersions from the nominal impact
};

struct MonteCarloSummary {
  int samples = 0;
  int flown = 0;
  int reaching_orbit = 0;
  std::vector<int> sampled_codes;                  // drawn (monte_carlo_draws_source)
  std::vector<int> not_sampled_codes;              // given but not drawn
  std::vector<StagingColumnStatistics> columns;    // the linear analysis' staging columns
  std::vector<QuantityStatistics> orbit;           // TWOE .. OMEGAE, perigee and apogee altitudes
  std::vector<QuantityStatistics> max_qbar_alpha;  // value, time
  DispersionEllipse burnout_ellipse;
  std::vector<CasingImpactStatistics> impact_ellipses;  // --impacts: the casings asked for, by stage
  // Per sample (index = sample): perigee and apogee altitude, n.mi. (NaN when not flown; apogee NaN
  // unless elliptic) and whether it reached orbit.
  std::vector<double> perigee_altitude_nmi;
  std::vector<double> apogee_altitude_nmi;
  std::vector<bool> reaches_orbit;
};

MonteCarloSummary summarize_monte_carlo(const MonteCarloInputs& inputs);

// The document of `tolip montecarlo --json` (docs/cli.md).
nlohmann::ordered_json monte_carlo_json(const MonteCarloInputs& inputs, const MonteCarloSummary& summary);

// The text listing of the statistics.
void write_monte_carlo_listing(std::ostream& out, const MonteCarloInputs& inputs,
                               const MonteCarloSummary& summary);

// One row per sample: its status, every staging point's values and dispersions, the orbit elements,
// perigee and apogee altitudes, reaches_orbit, the max q-bar alpha, and with the casing impacts
// each casing's status, impact time, latitude, longitude, downrange and crossrange.
void write_monte_carlo_csv(std::ostream& out, const MonteCarloInputs& inputs,
                           const MonteCarloSummary& summary);

// The figures of --plots DIR: histograms of burnout altitude, velocity and flight-path angle,
// perigee vs apogee, the Monte Carlo three-sigma over the RSS three-sigma at every staging point,
// and with the casing impacts each casing's impact points with their ellipse.
std::vector<Figure> monte_carlo_figures(const MonteCarloInputs& inputs, const MonteCarloSummary& summary);

}  // namespace tolip::ground
