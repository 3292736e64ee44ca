// Deck data of the optional computations that have no home in the core's Mission yet.
//
// The manual's data blocks 33-37 (6D body dynamics), 41 (radar), 42-43 (impact), 44-45 (hardover
// turns) and 46-55 (dispersions) are read from the TOML deck (docs/deck-format.md), checked for
// shape (finite numbers, strictly increasing table abscissae, counts, option requirements) and
// kept here, ground side, until the modules that use them land in the core. Units are the core's:
// angles in rad (the deck gives degrees); body stations of blocks 44-55 stay in inches as in the
// manual (the field names say so). Blocks 33-37 fill the core's Mission::body_dynamics (stations
// in ft); only the block 33 words the core does not hold are kept here.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "tolip_ground/deck.hpp"

namespace tolip::ground {

// A piecewise-linear table as read from the deck: x strictly increasing, x.size() == y.size().
// Empty when the deck does not give it.
struct DeckTable {
  std::vector<double> x;
  std::vector<double> y;
  bool empty() const { return x.empty(); }
  int size() const { return static_cast<int>(x.size()); }
};

// Data block 33's words the core's Mission does not hold. Everything else of blocks 33-37 (gains,
// stations, DA6D(12-15), the moment data and the c.g. histories) lives once, in core units, in
// Mission::body_dynamics; the deck reader converts the deck's inches and per-degree values there.
struct BodyDynamicsData {
  bool present = false;                                  // [body_dynamics] given
  std::array<int, 3> impact_every_nth_step = {1, 1, 1};  // DA6D(17-19), stages 1-3
};

// Autopilot gain design (issue 16, docs/theory/autopilot-design.md): data block 33 words 21-30, a
// TOLIP extension of DA6D (not manual words), in [body_dynamics]. Defaults: constants (0).
struct AutopilotDesignData {
  int designed = 0;                                                    // 21: 1 designed gains, 0 DA6D(1-6)
  std::array<double, 3> natural_frequency_rad_s = {2.75, 2.75, 2.75};  // 22-24, stages 1-3
  std::array<double, 3> damping_ratio = {0.7, 0.7, 0.7};               // 25-27, stages 1-3
  double attitude_error_rad = 0.017453292519943295;                    // 28 (deck: deg), 1 deg
  double actuator_time_constant_s = 0.0;                               // 29, 0: no actuator lag
  int points_per_stage = 6;                                            // 30, 1-8
};

// Data block 41: one card per station.
struct RadarStation {
  std::string id;    // 2A6, at most 12 characters
  std::string name;  // description (not a manual word)
  double geodetic_latitude_rad = 0.0;
  double longitude_rad = 0.0;  // east positive
  double altitude_ft = 0.0;
};

// One drag table of data block 42 (failure mode) or 43 (expended casing); Mach starts at 0.
struct ImpactDragTable {
  bool present = false;
  DeckTable cd_vs_mach;
  double reference_area_ft2 = 0.0;  // deck extension; defaults to the stage's block 39 area
  double casing_weight_lb = 0.0;    // block 43 only, deck extension; defaults to the jettison weight
};

// Data blocks 42-43 (CD1F-CD3F, CD1E-CD3E), stages 1-3.
struct ImpactData {
  bool present = false;
  std::array<ImpactDragTable, 3> failure_mode;
  std::array<ImpactDragTable, 3> expended_casing;
};

// Data blocks 44-45.
struct HardoverData {
  bool present = false;
  std::array<DeckTable, 3> pitch_inertia_slug_ft2;  // block 44 IYY1-IYY3: stage time s -> I_yy
  DeckTable stage1_pitch_damping_per_rad;           // block 44 (stage code 4): Mach -> CMQ
  // Block 45, words 1-26.
  int stage1_every_nth_step = 0;                       // 1
  double max_qbar_alpha_lb_rad_ft2 = 0.0;              // 2 (deck: lb deg/ft^2)
  double stage1_max_attitude_step_rad = 0.0;           // 3
  double stage1_max_step_s = 0.0;                      // 4
  double stage1_min_step_s = 0.0;                      // 5
  int stage1_max_steps_per_turn = 0;                   // 6
  std::array<double, 3> thrust_misalignment_rad = {};  // 7-9, stages 1-3
  double stage1_thrust_station_in = 0.0;               // 10
  double stage1_fin_vane_deflection_rad = 0.0;         // 11
  std::array<double, 2> mode_b_jet_force_lb = {};      // 12-13, stages 2-3
  std::array<double, 2> mode_c_jet_force_lb = {};      // 14-15, stages 2-3
  std::array<double, 2> thrust_station_in = {};        // 16-17, stages 2-3
  std::array<double, 2> control_jet_station_in = {};   // 18-19, stages 2-3
  double output_interval_s = 0.0;                      // 20
  int stage2_every_nth_step = 0;                       // 21
  int stage3_every_nth_step = 0;                       // 22
  double upper_max_attitude_step_rad = 0.0;            // 23
  double upper_max_step_s = 0.0;                       // 24
  double upper_min_step_s = 0.0;                       // 25
  int upper_max_steps_per_turn = 0;                    // 26
};

// One dispersed trajectory: a block 46 card (code, title) and the data its code needs.
struct DispersionCase {
  int code = 0;       // 1-38, or 40 (three-sigma summary)
  int stage = 0;      // stage the code applies to (0 when none)
  std::string title;  // block 46 title (at most 12 characters)
  // Codes 1-8: replacement tables (blocks 30 and 38) and, five-stage only, block 55.
  DeckTable vacuum_thrust_lbf;
  DeckTable consumable_weight_lb;
  bool has_stage_durations = false;
  std::array<double, 2> stage4_5_durations_s = {};
  double weight_increment_lb = 0.0;      // codes 9-16, block 47 (signed)
  double drag_variation_fraction = 0.0;  // codes 17-18, block 48 (signed, 0.xxxx)
  DeckTable pitching_moment_per_rad;     // codes 19-20, block 35 (complete table)
  double misalignment_rad = 0.0;         // codes 21-23, block 49 word 1 (signed)
  double thrust_station_in = 0.0;        // codes 21-23, block 49 word 2
  double deadband_rad = 0.0;             // codes 24-29, block 50 (signed)
  double tipoff_rad = 0.0;               // codes 30-32, block 51 (signed)
  double launch_change_rad = 0.0;        // codes 33-35, block 52: azimuth (33) or attitude (34-35)
  DeckTable wind_speed_ft_s;             // codes 36-38, block 53: altitude ft -> speed
  DeckTable wind_azimuth_rad;            // codes 36-38, block 54: altitude ft -> azimuth of the wind vector
};

// Data block 9: list every n-th computed point, per stage (index stage_index(code)), for the
// three kinds of trajectory.
struct OutputFrequency {
  std::array<int, kMaxStages> initial = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  std::array<int, kMaxStages> intermediate = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  std::array<int, kMaxStages> final_trajectory = {1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
};

// What the printed listing shows and how it is laid out (data blocks 1-3, 9 and data block 10
// words 8 and 9): listing concerns, kept beside the core's Mission and never in it.
struct DeckListingOptions {
  std::string title;                           // block 1 main heading (12A6, at most 72 characters)
  std::string case_heading;                    // block 2 (12A6)
  std::string date;                            // block 3 (2A6, at most 12 characters)
  OutputFrequency output;                      // block 9
  double lines_per_page = 54.0;                // CT1(8); the pager accepts 20-1000 (else 54)
  double deg_to_rad_as_printed = 0.017453292;  // CT1(9), echoed only: the core uses the exact pi/180
  // [stage.N] name (TOML only, not a manual word): printed under the listing's stage events.
  std::array<std::string, kMaxStages> stage_names;
};

struct DeckExtras {
  DeckListingOptions listing;
  BodyDynamicsData body_dynamics;
  AutopilotDesignData autopilot;
  std::vector<RadarStation> radar_stations;
  ImpactData impact;
  HardoverData hardover;
  std::vector<DispersionCase> dispersions;  // in increasing code order
};

// load_toml_deck()/parse_toml_deck() that also return the optional-computation data. On failure
// neither *mission nor *extras is changed.
bool load_toml_deck(const std::string& path, Mission* mission, DeckExtras* extras, DeckError* error);
bool parse_toml_deck(const std::string& text, const std::string& path, Mission* mission, DeckExtras* extras,
                     DeckError* error);

}  // namespace tolip::ground
