// The one description of the deck's word-per-value fields and of the dispersion codes
// (field_description.hpp).
#include "field_description.hpp"

#include <cstring>
#include <string>

#include "tolip/core/constants.hpp"
#include "tolip_ground/units.hpp"

namespace tolip::ground::deck_detail {
namespace {

FieldSlot slot_of(double* value) { return FieldSlot{value, nullptr}; }
FieldSlot slot_of(int* value) { return FieldSlot{nullptr, value}; }

// Slots: a member of a part of the Mission, an element of an array member, a member of a stage,
// an IP word, and members of the ground-side extras.
template <auto Part, auto Member>
FieldSlot in_mission(const FieldTarget& target, int, int) {
  return slot_of(&((target.mission->*Part).*Member));
}
template <auto Part, auto Member>
FieldSlot in_mission_array(const FieldTarget& target, int, int index) {
  return slot_of(&((target.mission->*Part).*Member)[index]);
}
template <auto Member>
FieldSlot in_stage(const FieldTarget& target, int stage, int) {
  return slot_of(&(target.mission->vehicle.stages[stage_index(stage)].*Member));
}
template <int N>
FieldSlot option(const FieldTarget& target, int, int) {
  return slot_of(&target.mission->options.ip[N]);
}
template <auto Part, auto Member>
FieldSlot in_extras(const FieldTarget& target, int, int) {
  return slot_of(&((target.extras->*Part).*Member));
}
template <auto Part, auto Member>
FieldSlot in_extras_array(const FieldTarget& target, int, int index) {
  return slot_of(&((target.extras->*Part).*Member)[static_cast<std::size_t>(index)]);
}

// When the TOML reader demands a field (the options that use it).
bool zero_alpha_window(const Mission& m) { return m.options.zero_alpha_window(); }
// Blocks 33-37 in full: the 6D trajectory (IP(6)) and the dispersions (IP(21)) fly the body dynamics.
bool six_d(const Mission& m) { return m.options.body_dynamics_6d() >= 1 || m.options.dispersions(); }
// The hardover turns (IP(22)) use block 33 words 7-11 and 16 as well.
bool six_d_or_hardover(const Mission& m) { return six_d(m) || m.options.hardover(); }
bool impact(const Mission& m) { return m.options.impact(); }

using C = Conversion;
using P = Presence;
using R = Range;
using SC = StageCoding;
using SS = StageSet;

FieldDescription option_flag(int ip, const char* key, const char* card_text, const char* what,
                             FieldSlot (*slot)(const FieldTarget&, int, int)) {
  FieldDescription f;
  f.block = 4;
  f.word = ip;
  f.section = "options";
  f.key = key;
  f.card_text = card_text;
  f.what = what;
  f.integer = true;
  f.range = R::kFlag;
  f.slot = slot;
  return f;
}
FieldDescription option_choice(int ip, const char* key, const char* card_text, const char* what, int low,
                               int high, FieldSlot (*slot)(const FieldTarget&, int, int)) {
  FieldDescription f = option_flag(ip, key, card_text, what, slot);
  f.range = R::kChoice;
  f.low = low;
  f.high = high;
  return f;
}

// A real word with a TOML key of its own.
FieldDescription real(int block, int word, const char* section, const char* key, const char* card_text,
                      const char* what, const char* core_name,
                      FieldSlot (*slot)(const FieldTarget&, int, int)) {
  FieldDescription f;
  f.block = block;
  f.word = word;
  f.section = section;
  f.key = key;
  f.card_text = card_text;
  f.what = what;
  f.core_name = core_name;
  f.slot = slot;
  return f;
}
FieldDescription with_default(FieldDescription f, double value) {
  f.has_default = true;
  f.default_value = value;
  return f;
}
FieldDescription required(FieldDescription f) {
  f.presence = P::kRequired;
  return f;
}
FieldDescription required_when(FieldDescription f, bool (*when)(const Mission&)) {
  f.presence = P::kRequiredWhen;
  f.required_when = when;
  return f;
}
FieldDescription degrees(FieldDescription f) {
  f.conversion = C::kDegToRad;
  return f;
}
FieldDescription integer(FieldDescription f) {
  f.integer = true;
  return f;
}
FieldDescription ranged(FieldDescription f, Range range) {
  f.range = range;
  return f;
}
FieldDescription array(FieldDescription f, int count) {
  f.count = count;
  return f;
}

std::vector<FieldDescription> make_fields() {
  std::vector<FieldDescription> f;
  // ---- data block 4: IP(n) --------------------------------------------------------------------
  f.push_back(option_choice(1, "payoff", "PAYOFF: 0 PAYLOAD, 1 VELOCITY, 2 ALT.",
                            "IP(1) payoff: 0 payload, 1 velocity, 2 altitude", 0, 2, &option<1>));
  f.push_back(option_flag(2, "heating_constraint", "HEATING CONSTRAINT",
                          "IP(2) heating inequality constraint", &option<2>));
  f.push_back(
      option_flag(3, "exchange_ratios", "EXCHANGE RATIOS", "IP(3) performance exchange ratios", &option<3>));
  f.push_back(option_choice(6, "body_dynamics_6d", "6D: 1 AFTER LINEARIZATION, 2 NOMINAL",
                            "IP(6) 6D: 0 none, 1 after successful linearization, 2 on the initial nominal", 0,
                            2, &option<6>));
  f.push_back(option_flag(7, "linearization", "PITCH PROGRAM LINEARIZATION",
                          "IP(7) pitch-program linearization after optimization", &option<7>));
  f.push_back(
      option_choice(9, "spin_stages_4_5", "STAGES 4-5: 1 SPUN, 2 4 CONT., 3 CONT.",
                    "IP(9) stages 4 and 5: 1 both spun, 2 stage 4 continuous and 5 spun, 3 both continuous "
                    "(0: no stage 4)",
                    0, 3, &option<9>));
  f.push_back(option_choice(10, "stage5_chi", "STAGE 5 CHI: 1 = CHI 4, 2 INDEPENDENT",
                            "IP(10) stage 5 chi: 0 fewer than 5 stages, 1 chi5 = chi4, 2 independent", 0, 2,
                            &option<10>));
  f.push_back(option_flag(11, "zero_alpha_window", "ZERO ALPHA IN STAGE 1 (BLOCK 22 TIMES)",
                          "IP(11) zero-alpha constraint in stage 1 (block 22 times)", &option<11>));
  f.push_back(option_flag(12, "alpha_zero_at_stage2_ignition", "ALPHA = 0 AT STAGE 2 IGNITION",
                          "IP(12) alpha = 0 at stage 2 ignition", &option<12>));
  f.push_back(option_choice(13, "qbar_constraint_type", "QBAR CONSTRAINT: 1 INEQUALITY",
                            "IP(13) q-bar constraint at stage 2 ignition: 0 none or equality, 1 inequality",
                            0, 1, &option<13>));
  f.push_back(option_flag(15, "memory_dump", "MEMORY DUMP", "IP(15) memory dump", &option<15>));
  f.push_back(
      option_flag(17, "print_input", "OUTPUT OF INPUT DATA", "IP(17) output of the input data", &option<17>));
  f.push_back(
      option_flag(21, "dispersions", "DISPERSED TRAJECTORIES", "IP(21) dispersed trajectories", &option<21>));
  f.push_back(
      option_flag(22, "hardover", "HARDOVER TURNS", "IP(22) failure-mode hardover turns", &option<22>));
  f.push_back(option_flag(23, "impact", "IMPACT LOCUS", "IP(23) nominal impact locus", &option<23>));
  f.push_back(option_flag(24, "radar", "RADAR TRACKING", "IP(24) radar tracking coordinates", &option<24>));
  for (FieldDescription& option_field : f) option_field.core_name = "options.ip[{w}]";
  {
    // Not in the manual (issue 15): the q-bar x alpha load limit, lb deg/ft^2 in the deck, lbf
    // rad/ft^2 in the core; 0 (or absent): no limit. On the cards the extension block 15 word 4.
    FieldDescription q = with_default(
        degrees(real(15, 4, "options", "qbar_alpha_limit_lb_deg_ft2", "QBAR*ALPHA LIMIT, LB DEG/FT2 (EXT.)",
                     "q-bar x alpha limit (extension), lb deg/ft^2 (0: none)",
                     "options.qbar_alpha_limit_lbf_rad_ft2",
                     &in_mission<&Mission::options, &Options::qbar_alpha_limit_lbf_rad_ft2>)),
        0.0);
    q.message_block = 4;  // an option in the TOML deck; on the cards the extension block 15
    f.push_back(q);
  }

  // ---- data block 10: CT1 (the core keeps its value when a key is absent) ----------------------
  using K = Constants;
  constexpr auto kC = &Mission::constants;
  f.push_back(real(10, 1, "constants", "earth_rotation_rate_rad_s", "OMEGA, EARTH RATE, RAD/S",
                   "CT1(1) Earth rotation rate, rad/s", "constants.earth_rotation_rate_rad_s",
                   &in_mission<kC, &K::earth_rotation_rate_rad_s>));
  f.push_back(real(10, 2, "constants", "gravitational_parameter_ft3_s2", "MU, FT3/S2", "CT1(2) mu, ft^3/s^2",
                   "constants.gravitational_parameter_ft3_s2",
                   &in_mission<kC, &K::gravitational_parameter_ft3_s2>));
  f.push_back(real(10, 3, "constants", "earth_equatorial_radius_ft", "EQUATORIAL RADIUS, FT",
                   "CT1(3) equatorial radius, ft", "constants.earth_equatorial_radius_ft",
                   &in_mission<kC, &K::earth_equatorial_radius_ft>));
  f.push_back(real(10, 4, "constants", "gas_constant_ft2_s2_R", "GAS CONSTANT, FT2/S2/DEG R",
                   "CT1(4) gas constant, ft^2/(s^2 R)", "constants.gas_constant_ft2_s2_R",
                   &in_mission<kC, &K::gas_constant_ft2_s2_R>));
  f.push_back(real(10, 5, "constants", "g0_ft_s2", "G0, WEIGHT TO MASS, FT/S2",
                   "CT1(5) weight-to-mass factor g0, ft/s^2", "constants.g0_ft_s2",
                   &in_mission<kC, &K::g0_ft_s2>));
  f.push_back(real(10, 6, "constants", "sea_level_pressure_lbf_ft2", "SEA LEVEL PRESSURE, LB/FT2",
                   "CT1(6) sea-level pressure, lbf/ft^2", "constants.sea_level_pressure_lbf_ft2",
                   &in_mission<kC, &K::sea_level_pressure_lbf_ft2>));
  f.push_back(real(10, 7, "constants", "haero_ft", "HAERO, AERO BYPASS ALT., FT", "CT1(7) HAERO, ft",
                   "constants.haero_ft", &in_mission<kC, &K::haero_ft>));
  // Words 8 and 9 lay out the printed listing: ground-side data (DeckListingOptions), not the core's.
  f.push_back(real(10, 8, "constants", "lines_per_page", "LINES PER PAGE", "CT1(8) lines per page", "",
                   &in_extras<&DeckExtras::listing, &DeckListingOptions::lines_per_page>));
  f.push_back(real(10, 9, "constants", "deg_to_rad_as_printed", "DEG TO RAD (ECHO ONLY)",
                   "CT1(9) degrees to radians (echo only)", "",
                   &in_extras<&DeckExtras::listing, &DeckListingOptions::deg_to_rad_as_printed>));
  f.push_back(real(10, 10, "constants", "time_epsilon_s", "TIMEP, TIME EPSILON, S", "CT1(10) TIMEP, s",
                   "constants.time_epsilon_s", &in_mission<kC, &K::time_epsilon_s>));
  f.push_back(real(10, 11, "constants", "j2", "J2", "CT1(11) J2", "constants.j2", &in_mission<kC, &K::j2>));
  f.push_back(real(10, 12, "constants", "inverse_flattening", "INVERSE FLATTENING",
                   "CT1(12) inverse flattening", "constants.inverse_flattening",
                   &in_mission<kC, &K::inverse_flattening>));
  f.push_back(real(10, 13, "constants", "ct1_13", "CT1(13)", "CT1(13)", "constants.ct1_13",
                   &in_mission<kC, &K::ct1_13>));

  // ---- data blocks 11-14: the atmosphere, 8 layers each ------------------------------------------
  using A = AtmosphereTable;
  constexpr auto kA = &Mission::atmosphere;
  f.push_back(array(
      real(11, 1, "atmosphere", "base_geopotential_altitude_ft", "BASE GEOPOTENTIAL ALT., FT, LAYER {i}",
           "CT2, base geopotential altitude of the 8 layers, ft'",
           "atmosphere.base_geopotential_altitude_ft[{x}]",
           &in_mission_array<kA, &A::base_geopotential_altitude_ft>),
      kAtmosphereLayers));
  f.push_back(array(
      real(12, 1, "atmosphere", "base_molecular_temperature_R", "BASE MOLECULAR TEMP., DEG R, LAYER {i}",
           "CT3, base molecular-scale temperature of the 8 layers, deg R",
           "atmosphere.base_molecular_temperature_R[{x}]",
           &in_mission_array<kA, &A::base_molecular_temperature_R>),
      kAtmosphereLayers));
  f.push_back(
      array(real(13, 1, "atmosphere", "lapse_rate_R_per_ft", "LAPSE RATE, DEG R/FT, LAYER {i}",
                 "CT4, lapse rate of the 8 layers, deg R per geopotential ft",
                 "atmosphere.lapse_rate_R_per_ft[{x}]", &in_mission_array<kA, &A::lapse_rate_R_per_ft>),
            kAtmosphereLayers));
  f.push_back(
      array(real(14, 1, "atmosphere", "base_density_slug_ft3", "BASE DENSITY, SLUG/FT3, LAYER {i}",
                 "CT5, base density of the 8 layers, slug/ft^3", "atmosphere.base_density_slug_ft3[{x}]",
                 &in_mission_array<kA, &A::base_density_slug_ft3>),
            kAtmosphereLayers));

  // ---- data blocks 16 and 39: per stage ([stage.N]); the stage reader applies the powered/coast
  // rules (a coast has no nozzle; a powered stage's duration defaults to its thrust table) --------
  {
    FieldDescription d = real(16, 1, "stage.{n}", "duration_s", "DURATION, S, STAGE {n}",
                              "data block 16 DA1({w}): duration of {kind} in s",
                              "vehicle.stages[{s}].duration_s", &in_stage<&StageData::duration_s>);
    d.stage_coding = SC::kWordPerStage;
    f.push_back(d);
    FieldDescription n =
        integer(real(16, 2, "stage.{n}", "integration_steps", "INTEGRATION STEPS, STAGE {n}",
                     "data block 16 DA1({w}): integration steps of {kind}",
                     "vehicle.stages[{s}].integration_steps", &in_stage<&StageData::integration_steps>));
    n.stage_coding = SC::kWordPerStage;
    n.presence = P::kRequired;
    f.push_back(n);
    FieldDescription j = with_default(
        real(39, 1, "stage.{n}", "jettison_weight_lb", "JETTISON WEIGHT, LB",
             "data block 39 SG{n}(1) jettison weight, lb", "vehicle.stages[{s}].jettison_weight_lb",
             &in_stage<&StageData::jettison_weight_lb>),
        0.0);
    j.stage_coding = SC::kStageCode;
    j.presence = P::kRequiredForPowered;
    f.push_back(j);
    FieldDescription a = with_default(
        real(39, 2, "stage.{n}", "reference_area_ft2", "REFERENCE AREA, FT2",
             "data block 39 SG{n}(2) aerodynamic reference area, ft^2",
             "vehicle.stages[{s}].reference_area_ft2", &in_stage<&StageData::reference_area_ft2>),
        0.0);
    a.stage_coding = SC::kStageCode;
    f.push_back(a);
    FieldDescription e = with_default(
        real(39, 3, "stage.{n}", "nozzle_exit_area_ft2", "NOZZLE EXIT AREA, FT2",
             "data block 39 SG{n}(3) nozzle exit area, ft^2", "vehicle.stages[{s}].nozzle_exit_area_ft2",
             &in_stage<&StageData::nozzle_exit_area_ft2>),
        0.0);
    e.stage_coding = SC::kStageCode;
    e.stages = SS::kPowered;
    f.push_back(e);
  }

  // ---- data blocks 20, 21 and the heading hold (extension block 15 word 2) ----------------------
  using L = LaunchConditions;
  constexpr auto kL = &Mission::launch;
  f.push_back(required(real(20, 1, "launch", "liftoff_duration_s", "VERTICAL LIFT-OFF DURATION, S",
                            "DA5(1) vertical lift-off duration, s", "launch.liftoff_duration_s",
                            &in_mission<kL, &L::liftoff_duration_s>)));
  f.push_back(
      with_default(real(20, 2, "launch", "space_age_date_days", "LAUNCH DATE, SPACE AGE DAYS",
                        "DA5(2) launch time, days from 0 h 1 January 1960 (Julian date - 2436934.5)",
                        "launch.launch_space_age_date_days", &in_mission<kL, &L::launch_space_age_date_days>),
                   0.0));
  f.push_back(required(real(21, 1, "launch", "altitude_ft", "ALTITUDE, FT", "DA6(1) launch altitude, ft",
                            "launch.altitude_ft", &in_mission<kL, &L::altitude_ft>)));
  f.push_back(required(degrees(real(21, 2, "launch", "longitude_deg", "LONGITUDE, DEG EAST",
                                    "DA6(2) longitude, deg east of Greenwich", "launch.longitude_rad",
                                    &in_mission<kL, &L::longitude_rad>))));
  f.push_back(required(degrees(real(21, 3, "launch", "geocentric_latitude_deg", "GEOCENTRIC LATITUDE, DEG",
                                    "DA6(3) geocentric latitude, deg", "launch.geocentric_latitude_rad",
                                    &in_mission<kL, &L::geocentric_latitude_rad>))));
  f.push_back(with_default(real(21, 4, "launch", "velocity_ft_s", "VELOCITY, FT/S (0)",
                                "DA6(4) initial velocity, ft/s (must be 0)", "launch.velocity_ft_s",
                                &in_mission<kL, &L::velocity_ft_s>),
                           0.0));
  f.push_back(required(degrees(real(21, 5, "launch", "azimuth_deg", "AZIMUTH, DEG EAST OF NORTH",
                                    "DA6(5) launch azimuth, deg east of north", "launch.azimuth_rad",
                                    &in_mission<kL, &L::azimuth_rad>))));
  f.push_back(
      with_default(degrees(real(21, 6, "launch", "flight_path_angle_deg", "FLIGHT PATH ANGLE, DEG (90)",
                                "DA6(6) flight-path angle, deg (must be 90)", "launch.flight_path_angle_rad",
                                &in_mission<kL, &L::flight_path_angle_rad>)),
                   90.0));
  {
    FieldDescription h =
        with_default(real(15, 2, "launch", "heading_hold_until_s", "HEADING HOLD UNTIL, S (EXTENSION)",
                          "heading hold (extension): dpsi/dt = 0 on steps starting before this time, s",
                          "launch.heading_hold_until_s", &in_mission<kL, &L::heading_hold_until_s>),
                     0.0);
    h.message_block = 21;  // a launch condition in the TOML deck; on the cards the extension block 15
    f.push_back(h);
  }

  // ---- data block 22 ------------------------------------------------------------------------------
  using CC = ControlConstraints;
  constexpr auto kCC = &Mission::control;
  f.push_back(with_default(
      required_when(real(22, 1, "control_constraints", "zero_alpha_start_s", "START OF ALPHA = 0, S",
                         "DA7(1) start of alpha = 0, s from launch", "control.zero_alpha_start_s",
                         &in_mission<kCC, &CC::zero_alpha_start_s>),
                    &zero_alpha_window),
      0.0));
  f.push_back(
      with_default(required_when(real(22, 2, "control_constraints", "zero_alpha_end_s", "END OF ALPHA = 0, S",
                                      "DA7(2) end of alpha = 0, s from launch", "control.zero_alpha_end_s",
                                      &in_mission<kCC, &CC::zero_alpha_end_s>),
                                 &zero_alpha_window),
                   0.0));
  f.push_back(
      with_default(degrees(real(22, 3, "control_constraints", "max_pitch_rate_deg_s", "MAX PITCH RATE, DEG/S",
                                "DA7(3) maximum pitch rate, deg/s", "control.max_pitch_rate_rad_s",
                                &in_mission<kCC, &CC::max_pitch_rate_rad_s>)),
                   0.0));
  f.push_back(
      with_default(degrees(real(22, 4, "control_constraints", "min_pitch_rate_deg_s", "MIN PITCH RATE, DEG/S",
                                "DA7(4) minimum pitch rate, deg/s", "control.min_pitch_rate_rad_s",
                                &in_mission<kCC, &CC::min_pitch_rate_rad_s>)),
                   0.0));
  f.push_back(with_default(
      degrees(real(22, 5, "control_constraints", "min_pitch_rate_change_deg_s",
                   "MIN CHANGE IN PITCH RATE, DEG/S", "DA7(5) minimum change in pitch rate, deg/s",
                   "control.min_pitch_rate_change_rad_s",
                   &in_mission<kCC, &CC::min_pitch_rate_change_rad_s>)),
      0.0));

  // ---- data block 17: DA2 -------------------------------------------------------------------------
  using M = MiscellaneousData;
  constexpr auto kM = &Mission::misc;
  f.push_back(with_default(
      degrees(real(17, 5, "misc", "stage4_theta_deg", "STAGE 4 THETA, DEG", "DA2(5) stage 4 theta, deg",
                   "misc.stage4_theta_rad", &in_mission<kM, &M::stage4_theta_rad>)),
      0.0));
  f.push_back(with_default(
      degrees(real(17, 6, "misc", "stage4_chi_deg", "STAGE 4 CHI, DEG", "DA2(6) stage 4 chi, deg",
                   "misc.stage4_chi_rad", &in_mission<kM, &M::stage4_chi_rad>)),
      0.0));
  f.push_back(with_default(real(17, 7, "misc", "nose_radius_ft", "NOSE RADIUS, FT", "DA2(7) nose radius, ft",
                                "misc.nose_radius_ft", &in_mission<kM, &M::nose_radius_ft>),
                           0.0));
  f.push_back(
      with_default(real(17, 8, "misc", "gyro_uncage_s_before_launch", "GYRO UNCAGE BEFORE LAUNCH, S",
                        "DA2(8) gyro uncage time before launch, s", "misc.gyro_uncage_s_before_launch",
                        &in_mission<kM, &M::gyro_uncage_s_before_launch>),
                   0.0));
  f.push_back(with_default(
      degrees(real(17, 9, "misc", "stage5_theta_deg", "STAGE 5 THETA, DEG", "DA2(9) stage 5 theta, deg",
                   "misc.stage5_theta_rad", &in_mission<kM, &M::stage5_theta_rad>)),
      0.0));
  f.push_back(with_default(
      degrees(real(17, 10, "misc", "stage5_chi_deg", "STAGE 5 CHI, DEG", "DA2(10) stage 5 chi, deg",
                   "misc.stage5_chi_rad", &in_mission<kM, &M::stage5_chi_rad>)),
      0.0));
  f.push_back(with_default(real(17, 15, "misc", "payload_weighting_factor", "PAYLOAD WEIGHTING FACTOR",
                                "DA2(15) payload weighting factor", "misc.payload_weighting_factor",
                                &in_mission<kM, &M::payload_weighting_factor>),
                           1.0));
  f.push_back(with_default(real(17, 16, "misc", "coast_change_limit_s", "COAST CHANGE LIMIT, S",
                                "DA2(16) limit on coast change per iteration, s", "misc.coast_change_limit_s",
                                &in_mission<kM, &M::coast_change_limit_s>),
                           0.0));
  f.push_back(with_default(
      real(17, 17, "misc", "minimum_coast_s", "MINIMUM COAST DURATION, S",
           "DA2(17) minimum coast duration, s", "misc.minimum_coast_s", &in_mission<kM, &M::minimum_coast_s>),
      0.0));

  // ---- data block 28: DA13 (the core keeps its value when a key is absent) ---------------------
  using V = ConvergenceData;
  constexpr auto kV = &Mission::convergence;
  f.push_back(real(28, 1, "convergence", "initial_payoff_improvement", "INITIAL PAYOFF IMPROVEMENT",
                   "DA13(1) initial payoff improvement, payoff units",
                   "convergence.initial_payoff_improvement",
                   &in_mission<kV, &V::initial_payoff_improvement>));
  f.push_back(real(28, 2, "convergence", "stop_improvement", "STOP IMPROVEMENT",
                   "DA13(2) attempted improvement below which optimization stops, payoff units",
                   "convergence.stop_improvement", &in_mission<kV, &V::stop_improvement>));
  f.push_back(integer(real(28, 3, "convergence", "max_forward_trajectories", "MAX FORWARD TRAJECTORIES",
                           "DA13(3) maximum forward trajectories", "convergence.max_forward_trajectories",
                           &in_mission<kV, &V::max_forward_trajectories>)));
  f.push_back(
      integer(real(28, 4, "convergence", "max_linearization_iterations", "MAX LINEARIZATION ITERATIONS",
                   "DA13(4) maximum linearization iterations", "convergence.max_linearization_iterations",
                   &in_mission<kV, &V::max_linearization_iterations>)));

  // ---- data block 33: DA6D (the core's Mission::body_dynamics, stations in ft; DA6D(12-15) and
  // (17-19), which the core does not hold, ground side in DeckExtras::body_dynamics) ----------------
  using B = BodyDynamicsBlocks;
  constexpr auto kB = &Mission::body_dynamics;
  using BX = BodyDynamicsData;
  constexpr auto kBX = &DeckExtras::body_dynamics;
  f.push_back(array(with_default(required_when(real(33, 1, "body_dynamics", "position_gain_deg_per_deg",
                                                    "K THETA POSITION GAIN, STAGE {i}",
                                                    "DA6D(1-3) K_theta position gain of stages 1-3, deg/deg",
                                                    "body_dynamics.position_gain[{x}]",
                                                    &in_mission_array<kB, &B::position_gain>),
                                               &six_d),
                                 0.0),
                    3));
  f.push_back(array(
      with_default(
          required_when(real(33, 4, "body_dynamics", "rate_gain_s", "K THETA-DOT RATE GAIN, S, STAGE {i}",
                             "DA6D(4-6) K_theta-dot rate gain of stages 1-3, s",
                             "body_dynamics.rate_gain_s[{x}]", &in_mission_array<kB, &B::rate_gain_s>),
                        &six_d),
          0.0),
      3));
  {
    FieldDescription x = array(
        with_default(
            required_when(
                real(33, 7, "body_dynamics", "control_station_in", "CONTROL STATION, IN, STAGE {i}",
                     "DA6D(7-9) body station of the stage-1 jet vanes and "
                     "fins and of the stage 2-3 control jets, in",
                     "body_dynamics.control_station_ft[{x}]", &in_mission_array<kB, &B::control_station_ft>),
                &six_d_or_hardover),
            0.0),
        3);
    x.conversion = C::kInchToFt;
    f.push_back(x);
  }
  {
    FieldDescription k = with_default(
        required_when(real(33, 10, "body_dynamics", "jet_vane_effectiveness_per_deg_per_vane",
                           "JET VANE EFFECT., /DEG/VANE",
                           "DA6D(10) jet vane effectiveness, lb per lb vacuum thrust per deg per vane",
                           "body_dynamics.jet_vane_effectiveness_per_rad",
                           &in_mission<kB, &B::jet_vane_effectiveness_per_rad>),
                      &six_d_or_hardover),
        0.0);
    k.conversion = C::kPerDegToPerRad;
    f.push_back(k);
  }
  {
    FieldDescription x =
        with_default(required_when(real(33, 11, "body_dynamics", "moment_reference_station_in",
                                        "X FS MOMENT REF. STATION, IN",
                                        "DA6D(11) X_FS, body station reference of the moment "
                                        "coefficients, in",
                                        "body_dynamics.moment_reference_station_ft",
                                        &in_mission<kB, &B::moment_reference_station_ft>),
                                   &six_d_or_hardover),
                     0.0);
    x.conversion = C::kInchToFt;
    f.push_back(x);
  }
  f.push_back(ranged(array(with_default(real(33, 12, "body_dynamics", "integration_frequency_multiplier",
                                             "6D INTEGRATION MULTIPLIER, STAGE {i}",
                                             "DA6D(12-15) 6D integration frequency multipliers of stages 1-4",
                                             "body_dynamics.integration_frequency_multiplier[{x}]",
                                             &in_mission_array<kB, &B::integration_frequency_multiplier>),
                                        1.0),
                           4),
                     R::kAtLeastOne));
  f.push_back(with_default(
      required_when(real(33, 16, "body_dynamics", "reference_length_ft", "REFERENCE LENGTH, FT",
                         "DA6D(16) reference length of the aerodynamic moment data, ft",
                         "body_dynamics.reference_length_ft", &in_mission<kB, &B::reference_length_ft>),
                    &six_d_or_hardover),
      0.0));
  f.push_back(ranged(
      integer(array(with_default(required_when(real(33, 17, "body_dynamics", "impact_every_nth_step",
                                                    "IMPACT EVERY N-TH STEP, STAGE {i}",
                                                    "DA6D(17-19) impact computed from every n-th step "
                                                    "of stages 1-3",
                                                    "", &in_extras_array<kBX, &BX::impact_every_nth_step>),
                                               &impact),
                                 1.0),
                    3)),
      R::kAtLeastOne));

  // ---- data block 33 words 21-30: autopilot gain design (issue 16; a TOLIP extension of DA6D, not
  // manual words; docs/theory/autopilot-design.md). Optional, with the defaults of
  // AutopilotDesignData; the design checks the values (exit 2 naming stage and key).
  using AP = AutopilotDesignData;
  constexpr auto kAP = &DeckExtras::autopilot;
  f.push_back(with_default(
      ranged(integer(real(33, 21, "body_dynamics", "autopilot_designed_gains", "AUTOPILOT GAINS: 1 DESIGNED",
                          "DA6D(21) autopilot gains: 1 designed along the trajectory, 0 DA6D(1-6) constants",
                          "", &in_extras<kAP, &AP::designed>)),
             R::kFlag),
      0.0));
  f.push_back(
      array(with_default(real(33, 22, "body_dynamics", "autopilot_natural_frequency_rad_s",
                              "AUTOPILOT FREQUENCY, RAD/S, STAGE {i}",
                              "DA6D(22-24) closed-loop attitude natural frequency of stages 1-3, rad/s", "",
                              &in_extras_array<kAP, &AP::natural_frequency_rad_s>),
                         2.75),
            3));
  f.push_back(array(with_default(real(33, 25, "body_dynamics", "autopilot_damping_ratio",
                                      "AUTOPILOT DAMPING RATIO, STAGE {i}",
                                      "DA6D(25-27) closed-loop attitude damping ratio of stages 1-3", "",
                                      &in_extras_array<kAP, &AP::damping_ratio>),
                                 0.7),
                    3));
  f.push_back(degrees(with_default(
      real(33, 28, "body_dynamics", "autopilot_attitude_error_deg", "AUTOPILOT DESIGN ATTITUDE ERROR, DEG",
           "DA6D(28) attitude error the deflection limit must cover, deg", "",
           &in_extras<kAP, &AP::attitude_error_rad>),
      1.0)));
  f.push_back(with_default(
      real(33, 29, "body_dynamics", "autopilot_actuator_time_constant_s", "ACTUATOR TIME CONSTANT, S",
           "DA6D(29) first-order actuator lag of the margins, s (0: none)", "",
           &in_extras<kAP, &AP::actuator_time_constant_s>),
      0.0));
  f.push_back(with_default(
      integer(real(33, 30, "body_dynamics", "autopilot_points_per_stage",
                   "AUTOPILOT SCHEDULE POINTS PER STAGE", "DA6D(30) gain schedule points per stage 1-3 (1-8)",
                   "", &in_extras<kAP, &AP::points_per_stage>)),
      6.0));

  // ---- data block 45: the hardover words (all required when [hardover.parameters] is given) -----
  using H = HardoverData;
  constexpr auto kH = &DeckExtras::hardover;
  const char* const kP = "hardover.parameters";
  auto hard = [&](int word, const char* key, const char* card_text, const char* what,
                  FieldSlot (*slot)(const FieldTarget&, int, int), Range range, bool deg, bool is_integer) {
    FieldDescription d = required(real(45, word, kP, key, card_text, what, "", slot));
    d.range = range;
    if (deg) d.conversion = C::kDegToRad;
    d.integer = is_integer;
    f.push_back(d);
  };
  hard(1, "stage1_every_nth_step", "STAGE 1 TURN EVERY N-TH STEP",
       "word 1: stage 1 turns every n-th integration step", &in_extras<kH, &H::stage1_every_nth_step>,
       R::kAtLeastOne, false, true);
  hard(2, "max_qbar_alpha_lb_deg_ft2", "(QBAR ALPHA)MAX, LB DEG/FT2", "word 2: (q alpha)max, lb deg/ft^2",
       &in_extras<kH, &H::max_qbar_alpha_lb_rad_ft2>, R::kPositive, true, false);
  hard(3, "stage1_max_attitude_step_deg", "STAGE 1 MAX THETA STEP, DEG",
       "word 3: maximum pitch change per step, deg", &in_extras<kH, &H::stage1_max_attitude_step_rad>,
       R::kPositive, true, false);
  hard(4, "stage1_max_step_s", "STAGE 1 MAX STEP, S", "word 4: maximum integration step, s",
       &in_extras<kH, &H::stage1_max_step_s>, R::kPositive, false, false);
  hard(5, "stage1_min_step_s", "STAGE 1 MIN STEP, S", "word 5: minimum integration step, s",
       &in_extras<kH, &H::stage1_min_step_s>, R::kPositive, false, false);
  hard(6, "stage1_max_steps_per_turn", "STAGE 1 MAX STEPS PER TURN",
       "word 6: maximum integration steps per turn", &in_extras<kH, &H::stage1_max_steps_per_turn>,
       R::kAtLeastOne, false, true);
  hard(7, "stage1_thrust_misalignment_deg", "STAGE 1 MISALIGNMENT, DEG",
       "word 7: stage 1 thrust misalignment, deg", &in_extras_array<kH, &H::thrust_misalignment_rad>, R::kAny,
       true, false);
  hard(
      8, "stage2_thrust_misalignment_deg", "STAGE 2 MISALIGNMENT, DEG",
      "word 8: stage 2 thrust misalignment, deg",
      [](const FieldTarget& t, int, int) { return slot_of(&t.extras->hardover.thrust_misalignment_rad[1]); },
      R::kAny, true, false);
  hard(
      9, "stage3_thrust_misalignment_deg", "STAGE 3 MISALIGNMENT, DEG",
      "word 9: stage 3 thrust misalignment, deg",
      [](const FieldTarget& t, int, int) { return slot_of(&t.extras->hardover.thrust_misalignment_rad[2]); },
      R::kAny, true, false);
  hard(10, "stage1_thrust_station_in", "STAGE 1 THRUST STATION, IN",
       "word 10: stage 1 thrust application station, in", &in_extras<kH, &H::stage1_thrust_station_in>,
       R::kAny, false, false);
  hard(11, "stage1_fin_vane_deflection_deg", "STAGE 1 FIN/VANE DEFLECTION, DEG",
       "word 11: stage 1 fin and vane deflection, deg", &in_extras<kH, &H::stage1_fin_vane_deflection_rad>,
       R::kAny, true, false);
  hard(12, "mode_b_stage2_jet_force_lb", "MODE B STAGE 2 JET FORCE, LB",
       "word 12: mode B stage 2 control jet force, lb", &in_extras_array<kH, &H::mode_b_jet_force_lb>,
       R::kAny, false, false);
  hard(
      13, "mode_b_stage3_jet_force_lb", "MODE B STAGE 3 JET FORCE, LB",
      "word 13: mode B stage 3 control jet force, lb",
      [](const FieldTarget& t, int, int) { return slot_of(&t.extras->hardover.mode_b_jet_force_lb[1]); },
      R::kAny, false, false);
  hard(14, "mode_c_stage2_jet_force_lb", "MODE C STAGE 2 JET FORCE, LB",
       "word 14: mode C stage 2 control jet force, lb", &in_extras_array<kH, &H::mode_c_jet_force_lb>,
       R::kAny, false, false);
  hard(
      15, "mode_c_stage3_jet_force_lb", "MODE C STAGE 3 JET FORCE, LB",
      "word 15: mode C stage 3 control jet force, lb",
      [](const FieldTarget& t, int, int) { return slot_of(&t.extras->hardover.mode_c_jet_force_lb[1]); },
      R::kAny, false, false);
  hard(16, "stage2_thrust_station_in", "STAGE 2 THRUST STATION, IN",
       "word 16: stage 2 thrust application station, in", &in_extras_array<kH, &H::thrust_station_in>,
       R::kAny, false, false);
  hard(
      17, "stage3_thrust_station_in", "STAGE 3 THRUST STATION, IN",
      "word 17: stage 3 thrust application station, in",
      [](const FieldTarget& t, int, int) { return slot_of(&t.extras->hardover.thrust_station_in[1]); },
      R::kAny, false, false);
  hard(18, "stage2_control_jet_station_in", "STAGE 2 JET STATION, IN",
       "word 18: stage 2 control jet application station, in",
       &in_extras_array<kH, &H::control_jet_station_in>, R::kAny, false, false);
  hard(
      19, "stage3_control_jet_station_in", "STAGE 3 JET STATION, IN",
      "word 19: stage 3 control jet application station, in",
      [](const FieldTarget& t, int, int) { return slot_of(&t.extras->hardover.control_jet_station_in[1]); },
      R::kAny, false, false);
  hard(20, "output_interval_s", "OUTPUT INTERVAL, S", "word 20: output interval, s",
       &in_extras<kH, &H::output_interval_s>, R::kPositive, false, false);
  hard(21, "stage2_every_nth_step", "STAGE 2 TURN EVERY N-TH STEP",
       "word 21: stage 2 turns every n-th integration step", &in_extras<kH, &H::stage2_every_nth_step>,
       R::kAtLeastOne, false, true);
  hard(22, "stage3_every_nth_step", "STAGE 3 TURN EVERY N-TH STEP",
       "word 22: stage 3 turns every n-th integration step", &in_extras<kH, &H::stage3_every_nth_step>,
       R::kAtLeastOne, false, true);
  hard(23, "upper_max_attitude_step_deg", "UPPER MAX THETA STEP, DEG",
       "word 23: upper stages maximum pitch change per step, deg",
       &in_extras<kH, &H::upper_max_attitude_step_rad>, R::kPositive, true, false);
  hard(24, "upper_max_step_s", "UPPER MAX STEP, S", "word 24: upper stages maximum integration step, s",
       &in_extras<kH, &H::upper_max_step_s>, R::kPositive, false, false);
  hard(25, "upper_min_step_s", "UPPER MIN STEP, S", "word 25: upper stages minimum integration step, s",
       &in_extras<kH, &H::upper_min_step_s>, R::kPositive, false, false);
  hard(26, "upper_max_steps_per_turn", "UPPER MAX STEPS PER TURN",
       "word 26: upper stages maximum integration steps per turn",
       &in_extras<kH, &H::upper_max_steps_per_turn>, R::kAtLeastOne, false, true);
  return f;
}

std::string replaced(std::string text, const std::string& name, const std::string& value) {
  const std::string token = "{" + name + "}";
  for (std::size_t at = text.find(token); at != std::string::npos; at = text.find(token, at + value.size())) {
    text.replace(at, token.size(), value);
  }
  return text;
}

std::string expanded(const FieldDescription& field, const char* text, int code, int index) {
  // Most texts hold no placeholder: return them as they are (the readers expand the section and
  // the description of every described field for every table they read, so this is hot).
  if (std::strchr(text, '{') == nullptr) return text;
  std::string out = text;
  out = replaced(out, "w", std::to_string(card_word(field, code, index)));
  out = replaced(out, "n", std::to_string(code));
  out = replaced(out, "s", std::to_string(code > 0 ? stage_index(code) : 0));
  out = replaced(out, "i", std::to_string(index + 1));
  out = replaced(out, "x", std::to_string(index));
  out = replaced(out, "kind", (is_powered_stage(code) ? "powered stage " : "coast ") + std::to_string(code));
  return out;
}

// Dispersion codes 1-8 replace the thrust and weight tables of the stage they name.
int thrust_stage(int code) { return (code + 1) / 2; }
int weight_stage(int code) { return (code - 7) / 2; }
int stage_one(int) { return 1; }
int deadband_stage(int code) { return code <= 26 ? 2 : 3; }
int tipoff_stage(int) { return -1; }
// Codes 7-8 and 15-16 name stage 4, or stage 5 of a five-stage vehicle when the card's stage code
// (TOML `stage`) says 5: every stage dispersed without the manual's squeeze.
int stage_4_or_5(int) { return -1; }
int no_stage(int) { return 0; }

std::vector<DispersionCodes> make_dispersion_codes() {
  const DispersionItem thrust{30, 0, 1, "thrust", "time_s", "vacuum_thrust_lbf"};
  const DispersionItem weight{38, 0, 1, "consumable_weight", "time_s", "remaining_lb"};
  return {
      {1,
       6,
       DispersionKind::kThrust,
       "vacuum thrust variation",
       "data blocks 30 and 38 (stage code {stage})",
       {thrust, weight},
       &thrust_stage},
      {7,
       8,
       DispersionKind::kThrust,
       "vacuum thrust variation",
       "data blocks 30 and 38 (stage code 4, or 5 for stage 5's own tables) and, for the stacked five-stage "
       "form (stages 4 and 5 in the stage-4 tables, page 22-30), 55",
       {thrust, weight, {55, 1, 2, "stage_durations_s", "", ""}},
       &stage_4_or_5},
      {9,
       14,
       DispersionKind::kWeightIncrement,
       "weight increment",
       "data block 47 (stage code {stage})",
       {{47, 1, 1, "weight_increment_lb", "", ""}},
       &weight_stage},
      {15,
       16,
       DispersionKind::kWeightIncrement,
       "weight increment",
       "data block 47 (stage code 4 or 5)",
       {{47, 1, 1, "weight_increment_lb", "", ""}},
       &stage_4_or_5},
      {17,
       18,
       DispersionKind::kDrag,
       "drag variation",
       "data block 48",
       {{48, 1, 1, "drag_variation_fraction", "", ""}},
       &no_stage},
      {19,
       20,
       DispersionKind::kPitchingMoment,
       "C_M_alpha variation",
       "data block 35 (complete)",
       {{35, 0, 1, "pitching_moment", "mach", "cm_alpha_per_rad"}},
       &no_stage},
      {21,
       23,
       DispersionKind::kMisalignment,
       "stage 1 thrust misalignment",
       "data block 49 (stage code 1)",
       {{49, 1, 1, "misalignment_deg", "", ""}, {49, 2, 1, "thrust_station_in", "", ""}},
       &stage_one},
      {24,
       29,
       DispersionKind::kDeadband,
       "control system deadband",
       "data block 50 (stage code {stage})",
       {{50, 1, 1, "deadband_deg", "", ""}},
       &deadband_stage},
      {30,
       32,
       DispersionKind::kTipoff,
       "stage 4/5 tip-off",
       "data block 51 (stage code 4 or 5)",
       {{51, 1, 1, "tipoff_deg", "", ""}},
       &tipoff_stage},
      {33,
       33,
       DispersionKind::kLaunchAzimuth,
       "launch azimuth",
       "data block 52",
       {{52, 1, 1, "launch_azimuth_change_deg", "", ""}},
       &no_stage},
      {34,
       35,
       DispersionKind::kLaunchAttitude,
       "launch attitude",
       "data block 52",
       {{52, 1, 1, "launch_attitude_change_deg", "", ""}},
       &no_stage},
      {36,
       38,
       DispersionKind::kWinds,
       "winds",
       "data blocks 53 and 54",
       {{53, 0, 1, "wind_speed", "altitude_ft", "speed_ft_s"},
        {54, 0, 1, "wind_azimuth", "altitude_ft", "azimuth_deg"}},
       &no_stage},
      {40,
       40,
       DispersionKind::kSummary,
       "three-sigma summary",
       "no data (only the block 46 title)",
       {},
       &no_stage},
  };
}

}  // namespace

double to_core(Conversion conversion, double deck_value) {
  switch (conversion) {
    case Conversion::kNone: return deck_value;
    case Conversion::kDegToRad: return deck_value * kDegToRad;
    case Conversion::kPerDegToPerRad: return deck_value / kDegToRad;
    case Conversion::kInchToFt: return deck_value * kFeetPerInch;
  }
  return deck_value;
}

double to_deck(Conversion conversion, double core_value) {
  switch (conversion) {
    case Conversion::kNone: return core_value;
    case Conversion::kDegToRad: return core_value * kRadToDeg;
    case Conversion::kPerDegToPerRad: return core_value * kDegToRad;
    case Conversion::kInchToFt: return core_value / kFeetPerInch;
  }
  return core_value;
}

const std::vector<FieldDescription>& field_descriptions() {
  static const std::vector<FieldDescription> fields = make_fields();
  return fields;
}

bool applies_to_stage(const FieldDescription& field, int code) {
  if (field.stage_coding == StageCoding::kNone) return true;
  switch (field.stages) {
    case StageSet::kAll: return is_powered_stage(code) || is_coast_stage(code);
    case StageSet::kPowered: return is_powered_stage(code);
  }
  return false;
}

int card_word(const FieldDescription& field, int code, int index) {
  if (field.stage_coding == StageCoding::kWordPerStage) return field.word + 2 * (code - 1) + index;
  return field.word + index;
}

int card_stage(const FieldDescription& field, int code) {
  return field.stage_coding == StageCoding::kStageCode ? code : 0;
}

std::vector<int> stage_codes(const FieldDescription& field) {
  if (field.stage_coding == StageCoding::kNone) return {0};
  std::vector<int> codes;
  for (int code = 1; code <= kMaxStages; ++code) {
    if (applies_to_stage(field, code)) codes.push_back(code);
  }
  return codes;
}

const FieldDescription* find_field(int block, int stage, int word, int* index, int* stage_code) {
  for (const FieldDescription& field : field_descriptions()) {
    if (field.block != block) continue;
    for (int code : stage_codes(field)) {
      if (card_stage(field, code) != stage) continue;
      const int first = card_word(field, code, 0);
      if (word >= first && word < first + field.count) {
        if (index != nullptr) *index = word - first;
        if (stage_code != nullptr) *stage_code = code;
        return &field;
      }
    }
  }
  return nullptr;
}

const FieldDescription* find_field(const std::string& section, const std::string& key) {
  for (const FieldDescription& field : field_descriptions()) {
    if (key != field.key) continue;
    for (int code : stage_codes(field)) {
      if (section_of(field, code) == section) return &field;
    }
  }
  return nullptr;
}

std::string section_of(const FieldDescription& field, int code) {
  return expanded(field, field.section, code, 0);
}
std::string card_text_of(const FieldDescription& field, int code, int index) {
  return expanded(field, field.card_text, code, index);
}
std::string what_of(const FieldDescription& field, int code, int index) {
  return expanded(field, field.what, code, index);
}
std::string core_name_of(const FieldDescription& field, int code, int index) {
  return expanded(field, field.core_name, code, index);
}
int message_block(const FieldDescription& field) {
  return field.message_block != 0 ? field.message_block : field.block;
}

double field_value(const FieldDescription& field, const FieldTarget& target, int stage, int index) {
  const FieldSlot slot = field.slot(target, stage, index);
  return slot.real != nullptr ? *slot.real : static_cast<double>(*slot.integer);
}

void set_field_value(const FieldDescription& field, const FieldTarget& target, int stage, int index,
                     double value) {
  const FieldSlot slot = field.slot(target, stage, index);
  if (slot.real != nullptr) *slot.real = value;
  else *slot.integer = static_cast<int>(value);
}

double field_value(const FieldDescription& field, const Mission& mission, int stage, int index) {
  // The slot only forms the address of the member; nothing is written through it here.
  FieldTarget target;
  target.mission = const_cast<Mission*>(&mission);
  return field_value(field, target, stage, index);
}

double default_deck_value(const FieldDescription& field, int stage, int index) {
  if (field.has_default) return field.default_value;
  static const Mission nominal_mission;
  static const DeckExtras nominal_extras;
  FieldTarget nominal;
  // Only forms addresses of members of the nominal data; nothing is written through them.
  nominal.mission = const_cast<Mission*>(&nominal_mission);
  nominal.extras = const_cast<DeckExtras*>(&nominal_extras);
  return to_deck(field.conversion, field_value(field, nominal, stage, index));
}

const std::vector<DispersionCodes>& dispersion_codes() {
  static const std::vector<DispersionCodes> codes = make_dispersion_codes();
  return codes;
}

const DispersionCodes* find_dispersion(int code) {
  for (const DispersionCodes& codes : dispersion_codes()) {
    if (code >= codes.first && code <= codes.last) return &codes;
  }
  return nullptr;
}

int dispersion_stage(int code, int block) {
  const DispersionCodes* codes = find_dispersion(code);
  if (codes == nullptr || block == 55) return 0;  // block 55 (stage 4 and 5 durations) has no stage code
  return codes->stage_of(code);
}

bool dispersion_takes(int code, int block) {
  const DispersionCodes* codes = find_dispersion(code);
  if (codes == nullptr) return false;
  for (const DispersionItem& item : codes->items) {
    if (item.block == block) return true;
  }
  return false;
}

std::string dispersion_blocks(int code) {
  const DispersionCodes* codes = find_dispersion(code);
  if (codes == nullptr) return "no data (only the block 46 title)";
  return replaced(codes->blocks, "stage", std::to_string(codes->stage_of(code)));
}

}  // namespace tolip::ground::deck_detail
