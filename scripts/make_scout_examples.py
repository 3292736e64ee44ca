#!/usr/bin/env python3
"""Generate the bundled Scout example decks from the reference mission.

    python3 scripts/make_scout_examples.py [--reference PATH] [--out DIR]

reads tests/reference/scout_reference.json (the independent reference case; see its
README.md) and writes, in the TOML deck format of docs/deck-format.md:

* examples/scout/mission.toml -- the maximum-payload optimization case, starting from the crude
  initial program the oracle started from (oracle_solution.tth_block40_initial_nominal: the
  block 40 theta table, stage-4 theta -20 deg, coast 8 = 450 s, payload 250 lb), with every
  mission datum and the optional-computation data (6D blocks 33-37, radar 41, impact 42-43,
  hardover 44-45, dispersions 46-55);
* examples/scout/reference_optimum.toml -- the same mission flying the oracle's optimum: the
  pitch table through the optimized nodes, the optimized stage-4 theta, coast-8 duration (steps
  stay 40) and payload;
* examples/scout/mission_qalpha.toml -- mission.toml with a q-bar x alpha load limit of 3,500
  lb deg/ft^2 (options.qbar_alpha_limit_lb_deg_ft2, an extension of this project, issue 15);
* examples/scout/mission.dat -- mission.toml as a heritage card deck (80-column card images, the
  card format of docs/deck-format.md "The card deck"), punched from the TOML deck with the same
  rules as `tolip convert mission.toml --to mission.dat` (a test checks both agree and that the
  card deck loads to the same case as mission.toml);
* examples/scout/cases.dat -- a card deck of two cases, as decks were stacked in 1966: mission.dat,
  then a second case of its changed words only (a new case heading and a 260 lb initial payload,
  data blocks 2 and 15), for docs/user-guide.md "decks of several cases".

Every TOML number is written with repr(), i.e. the shortest text that reads back to the same
double; a card field holds the shortest text of at most 12 columns that reads back to the same
double, else the most digits that fit. Only the Python standard library is used (tomllib: 3.11). The output is deterministic; re-running the script on
an unchanged reference leaves the files byte-identical.
"""

import argparse
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_REFERENCE = os.path.join(ROOT, "tests", "reference", "scout_reference.json")
DEFAULT_OUT = os.path.join(ROOT, "examples", "scout")

WRAP = 96  # characters per array line


# ---- TOML emission ----------------------------------------------------------------------------

def num(value):
    """A TOML number: integers as integers, floats via repr (round-trips exactly)."""
    if isinstance(value, bool):
        raise TypeError("boolean where a number was expected")
    if isinstance(value, int):
        return str(value)
    value = float(value)
    if not math.isfinite(value):
        raise ValueError("non-finite number %r" % value)
    text = repr(value)
    return text


def text(value):
    return json.dumps(value, ensure_ascii=True)  # JSON basic strings are TOML basic strings


def boolean(value):
    return "true" if value else "false"


class Deck:
    def __init__(self):
        self.lines = []

    def blank(self):
        if self.lines and self.lines[-1] != "":
            self.lines.append("")

    def comment(self, *lines):
        for line in lines:
            self.lines.append(("# " + line).rstrip())

    def table(self, name, comment=None):
        self.blank()
        self.lines.append("[%s]%s" % (name, "  # " + comment if comment else ""))

    def array_table(self, name, comment=None):
        self.blank()
        self.lines.append("[[%s]]%s" % (name, "  # " + comment if comment else ""))

    def key(self, key, rendered, comment=None):
        line = "%s = %s" % (key, rendered)
        if comment:
            line = "%-44s # %s" % (line, comment)
        self.lines.append(line)

    def number(self, key, value, comment=None):
        self.key(key, num(value), comment)

    def string(self, key, value, comment=None):
        self.key(key, text(value), comment)

    def flag(self, key, value, comment=None):
        self.key(key, boolean(value), comment)

    def array(self, key, values, comment=None, render=num):
        items = [render(v) for v in values]
        one_line = "%s = [%s]" % (key, ", ".join(items))
        if len(one_line) <= WRAP:
            self.key(key, "[%s]" % ", ".join(items), comment)
            return
        if comment:
            self.lines.append("# " + comment)
        self.lines.append("%s = [" % key)
        line = "  "
        for item in items:
            piece = item + ","
            if len(line) + len(piece) + 1 > WRAP and line.strip():
                self.lines.append(line.rstrip())
                line = "  "
            line += piece + " "
        if line.strip():
            self.lines.append(line.rstrip())
        self.lines.append("]")

    def render(self):
        return "\n".join(self.lines).rstrip() + "\n"


# ---- units of the constraint codes (data blocks 8, 19, 29) -------------------------------------

TERMINAL_UNITS = {
    0: ("lb", "payload"), 1: ("ft_s", "inertial velocity"), 2: ("deg", "inertial flight-path angle"),
    3: ("ft_s", "V_I minus local circular velocity"), 4: ("ft", "radius"), 5: ("ft_s", "aerodynamic velocity"),
    6: ("deg", "aerodynamic flight-path angle"), 7: ("ft", "altitude"), 8: ("nmi", "downrange distance"),
    9: ("ft2_s2", "2E"), 10: ("deg", "orbit inclination"), 11: ("ft", "perigee radius"),
    12: ("deg", "longitude of the ascending node"), 13: ("deg", "argument of perigee"),
    14: ("btu_ft2", "total heating"),
}


def constraint_unit(code):
    if code in TERMINAL_UNITS:
        return TERMINAL_UNITS[code]
    raise ValueError("constraint code %d not handled by the generator" % code)


def deck_value(value, unit):
    """Block 19/29 values are in the manual's pure units (rad); the deck spells angles in degrees."""
    return math.degrees(value) if unit == "deg" else value


# ---- the decks ------------------------------------------------------------------------------

OPTION_KEYS = {  # IP(n) -> (deck key, binary)
    1: ("payoff", False), 2: ("heating_constraint", True), 3: ("exchange_ratios", True),
    6: ("body_dynamics_6d", False), 7: ("linearization", True), 9: ("spin_stages_4_5", False),
    10: ("stage5_chi", False), 11: ("zero_alpha_window", True), 12: ("alpha_zero_at_stage2_ignition", True),
    13: ("qbar_constraint_type", False), 15: ("memory_dump", True), 17: ("print_input", True),
    21: ("dispersions", True), 22: ("hardover", True), 23: ("impact", True), 24: ("radar", True),
}

CONSTANT_KEYS = [  # JSON key, deck key, CT1 word
    ("earth_rotation_rate_rad_per_s", "earth_rotation_rate_rad_s", 1),
    ("gravitational_parameter_ft3_per_s2", "gravitational_parameter_ft3_s2", 2),
    ("earth_equatorial_radius_ft", "earth_equatorial_radius_ft", 3),
    ("gas_constant_ft2_per_s2_R", "gas_constant_ft2_s2_R", 4),
    ("g0_weight_to_mass_ft_per_s2", "g0_ft_s2", 5),
    ("sea_level_pressure_lbf_per_ft2", "sea_level_pressure_lbf_ft2", 6),
    ("haero_aero_bypass_altitude_ft", "haero_ft", 7),
    ("lines_per_page", "lines_per_page", 8),
    ("deg_to_rad_as_printed", "deg_to_rad_as_printed", 9),
    ("time_epsilon_s", "time_epsilon_s", 10),
    ("j2", "j2", 11),
    ("inverse_flattening", "inverse_flattening", 12),
    ("ct1_13", "ct1_13", 13),
]

HARDOVER_WORDS = [  # block 45 word -> deck key (docs/deck-format.md)
    "stage1_every_nth_step", "max_qbar_alpha_lb_deg_ft2", "stage1_max_attitude_step_deg", "stage1_max_step_s",
    "stage1_min_step_s", "stage1_max_steps_per_turn", "stage1_thrust_misalignment_deg",
    "stage2_thrust_misalignment_deg", "stage3_thrust_misalignment_deg", "stage1_thrust_station_in",
    "stage1_fin_vane_deflection_deg", "mode_b_stage2_jet_force_lb", "mode_b_stage3_jet_force_lb",
    "mode_c_stage2_jet_force_lb", "mode_c_stage3_jet_force_lb", "stage2_thrust_station_in",
    "stage3_thrust_station_in", "stage2_control_jet_station_in", "stage3_control_jet_station_in",
    "output_interval_s", "stage2_every_nth_step", "stage3_every_nth_step", "upper_max_attitude_step_deg",
    "upper_max_step_s", "upper_min_step_s", "upper_max_steps_per_turn",
]

# The load limit of examples/scout/mission_qalpha.toml, lb deg/ft^2 (issue 15).
QALPHA_LIMIT_LB_DEG_FT2 = 3500.0
# Its forward-run budget DA13(3): the reference's 30 ends one run short (the q-alpha guidance takes 8
# runs after the limit joins; docs/theory/constraints-and-ics.md).
QALPHA_BUDGET = (40, "the reference's 30 ends the q-alpha case one run short")

# Its data block 18: the reference's breaks with stage 1 cut into 3 s segments up to the zero-alpha
# window's start and 7-8 s ones over it. With the reference's two stage-1 segments the straight
# program cannot keep the limit (its peak 5,877 lb deg/ft^2 at 15 s; one free break value over the
# load window); docs/theory/linearization.md "The q-bar x alpha limit".
QALPHA_TLIN = [14, 103.0, 106.0, 109.0, 112.0, 115.0, 122.0, 130.0, 138.0, 145.0, 200.0, 219.0, 238.0,
               300.0, 318.0, 336.0]
QALPHA_TLIN_NOTE = ("14 linear segments: the reference's, with stage 1 cut at 6, 9, 12, 15, 22, 30 and 38 s "
                    "so that the straight segments can keep the q-bar x alpha limit (docs/theory/linearization.md)")

# Adjustable-parameter codes of block 6 -> keys of the reference's weighting_block27.
WEIGHT_KEYS = {1: "stage4_theta", 3: "coast_after_stage3"}

# The reference optimum's pitch nodes (brief and README section 3).
OPTIMUM_NODE_TIMES = [3.0, 8.0, 15.0, 45.0, 50.0, 69.0, 88.0, 94.0, 112.0, 130.0]


def header(deck, ref, variant):
    deck.comment(
        "TOLIP case deck (TOML; format: docs/deck-format.md).",
        "GENERATED by scripts/make_scout_examples.py from tests/reference/scout_reference.json;",
        "edit the generator, not this file.",
        "",
        ref["title"] + ".",
        ref["disclaimer"].split(".")[0] + ".",
        "",
    )
    if variant == "qalpha":
        deck.comment(
            "The maximum-payload optimization case of examples/scout/mission.toml (the crude initial",
            "program, stage-4 theta -20 deg, coast 8 = 450 s, payload 250 lb) with a structural load",
            "limit |q-bar x alpha| <= %s lb deg/ft^2 over the phases with aerodynamic lift (an" % f"{QALPHA_LIMIT_LB_DEG_FT2:,.0f}",
            "extension of this project, not in the manual: docs/theory/constraints-and-ics.md).",
        )
    elif variant == "initial":
        deck.comment(
            "The maximum-payload optimization case as the oracle started it: the crude initial",
            "pitch program (data block 40), stage-4 theta -20 deg, coast 8 = 450 s, payload 250 lb.",
            "The oracle's optimum is examples/scout/reference_optimum.toml.",
        )
    else:
        deck.comment(
            "The same mission flying the oracle's optimum (oracle_solution): pitch nodes as flown,",
            "optimized stage-4 theta, coast-8 duration (40 steps kept) and payload.",
        )
    deck.comment("Units are in the key names; angles in degrees (the reader converts to radians).")


def case_section(deck, variant, ref):
    deck.table("case", "data blocks 1-3")
    deck.string("title", "SCOUT-CLASS 4-STAGE, WALLOPS ISLAND TO 300 NMI CIRCULAR ORBIT", "block 1, 12A6")
    if variant == "qalpha":
        heading = "MAXIMUM PAYLOAD, QBAR*ALPHA <= %.0f LB DEG/FT2" % QALPHA_LIMIT_LB_DEG_FT2
    elif variant == "initial":
        heading = "MAXIMUM PAYLOAD FROM THE CRUDE INITIAL PITCH PROGRAM"
    else:
        heading = "REFERENCE OPTIMUM, PAYLOAD %.3f LB" % ref["oracle_solution"]["payload_lb"]
    deck.string("heading", heading, "block 2, 12A6")
    deck.string("date", ref["mission"]["launch"]["launch_utc"][:10], "block 3, 2A6")


def options_section(deck, ref, variant):
    deck.table("options", "data block 4, IP(n)")
    for key, value in ref["mission"]["block4_options_IP"].items():
        n = int(key.split("_")[0])
        if n not in OPTION_KEYS:
            raise ValueError("option %s has no deck key" % key)
        name, binary = OPTION_KEYS[n]
        if binary:
            if value not in (0, 1):
                raise ValueError("option %s is not 0/1" % key)
            deck.flag(name, value == 1, "IP(%d)" % n)
        else:
            deck.number(name, value, "IP(%d)" % n)
    if variant == "qalpha":
        deck.number("qbar_alpha_limit_lb_deg_ft2", QALPHA_LIMIT_LB_DEG_FT2,
                    "extension (issue 15): |q-bar x alpha| limit, lb deg/ft^2 (0 or absent: none)")


def constants_sections(deck, ref):
    deck.table("constants", "data block 10, CT1(1..13) (the manual's nominal values)")
    ct1 = ref["constants_block10_CT1"]
    if set(ct1) != {k for k, _, _ in CONSTANT_KEYS}:
        raise ValueError("unexpected block 10 keys: %s" % sorted(ct1))
    for json_key, deck_key, word in CONSTANT_KEYS:
        deck.number(deck_key, ct1[json_key], "CT1(%d)" % word)

    atm = ref["atmosphere_blocks11_14_ARDC"]
    deck.table("atmosphere", "data blocks 11-14, the 1962 ARDC table of Sec. 19 (8 layers)")
    deck.array("base_geopotential_altitude_ft", atm["base_geopotential_altitude_ft"], "block 11, CT2")
    deck.array("base_molecular_temperature_R", atm["base_molecular_temperature_R"], "block 12, CT3")
    deck.array("lapse_rate_R_per_ft", atm["lapse_rate_R_per_geopotential_ft"], "block 13, CT4")
    deck.array("base_density_slug_ft3", atm["base_density_slug_per_ft3"], "block 14, CT5")


def vehicle_sections(deck, ref, variant):
    vehicle = ref["vehicle"]
    sequence = list(vehicle["stage_sequence_block5"])
    if sequence and sequence[-1] == 0:
        sequence.pop()
    payload = ref["oracle_solution"]["tth_block40_initial_nominal"]["payload_lb"] if variant == "initial" \
        else ref["oracle_solution"]["payload_lb"]
    if vehicle["payload_carried_in_jettison_of_stage"] != max(c for c in sequence if c <= 5):
        raise ValueError("payload must ride in the last powered stage")

    deck.table("vehicle", "data block 5 and the payload")
    deck.array("sequence", sequence, "block 5 ISTGE (the card's terminating 0 is optional)")
    deck.number("payload_lb", payload,
                "added to the jettison weight of stage %d, the last powered stage (Sec. 14)"
                % vehicle["payload_carried_in_jettison_of_stage"])

    lift = vehicle["aerodynamics"]["lift_curve_slope_table"]
    deck.table("vehicle.lift_curve_slope", "data block 32, TL1")
    deck.comment(lift["note"])
    deck.array("mach", lift["mach"])
    deck.array("cl_alpha_per_rad", lift["cl_alpha_per_rad"])
    deck.array("used_in_stages", lift["used_in_stages"])

    drags = vehicle["aerodynamics"]["drag_coefficient_tables"]
    coast8 = ref["oracle_solution"]["tth_block40_initial_nominal"]["coast8_s"] if variant == "initial" \
        else ref["oracle_solution"]["coast8_duration_s"]
    for code in sequence:
        stage = vehicle["stages"][str(code)]
        if stage["kind"] == "powered":
            deck.table("stage.%d" % code, "powered stage %d: data blocks 16, 39, 30, 38%s"
                       % (code, ", 31" if "stage_%d" % code in drags else ""))
            deck.string("name", stage["name"])
            deck.comment("propellant %s lb, vacuum Isp %s s, total vacuum impulse %s lbf s"
                         % (num(stage["propellant_weight_lb"]), num(stage["isp_vacuum_s"]),
                            num(stage["total_vacuum_impulse_lbf_s"])))
            deck.number("duration_s", stage["duration_s"], "block 16 DA1(%d) = last thrust-table time" % (2 * code - 1))
            deck.number("integration_steps", stage["integration_steps"],
                        "block 16 DA1(%d)%s" % (2 * code, " (after the lift-off interval)" if code == 1 else ""))
            deck.comment(stage["jettison_weight_note"])
            deck.number("jettison_weight_lb", stage["jettison_weight_lb"], "block 39 SG%d(1)" % code)
            deck.number("reference_area_ft2", stage["reference_area_ft2"], "block 39 SG%d(2)" % code)
            deck.number("nozzle_exit_area_ft2", stage["nozzle_exit_area_ft2"], "block 39 SG%d(3)" % code)
            thrust = stage["thrust_table"]
            deck.table("stage.%d.thrust" % code, "data block 30: stage time vs vacuum thrust")
            deck.array("time_s", thrust["time_s"])
            deck.array("vacuum_thrust_lbf", thrust["vacuum_thrust_lbf"])
            weight = stage["consumable_weight_table"]
            deck.table("stage.%d.consumable_weight" % code, "data block 38: consumable weight remaining")
            deck.array("time_s", weight["time_s"])
            deck.array("remaining_lb", weight["consumable_weight_remaining_lb"])
        else:
            deck.table("stage.%d" % code, "coast after stage %d: data blocks 16, 39%s"
                       % (code - 5, ", 31" if "stage_%d" % code in drags else ""))
            deck.comment(stage["note"])
            duration = coast8 if code == 8 else stage["duration_s"]
            note = "block 16 DA1(%d)" % (2 * code - 1)
            if stage.get("duration_is_initial_guess_of_adjustable_parameter"):
                note += ("; adjustable parameter (initial guess)" if variant == "initial"
                         else "; the oracle's optimized value")
            deck.number("duration_s", duration, note)
            deck.number("integration_steps", stage["integration_steps"], "block 16 DA1(%d)" % (2 * code))
            deck.number("jettison_weight_lb", stage["jettison_weight_lb"], "block 39 SG%d(1)" % code)
            deck.number("reference_area_ft2", stage["reference_area_ft2"], "block 39 SG%d(2)" % code)
        key = "stage_%d" % code
        if key in drags:
            deck.table("stage.%d.drag" % code, "data block 31, TD%d: C_D at alpha = 0 vs Mach" % code)
            deck.comment(drags[key]["note"])
            deck.array("mach", drags[key]["mach"])
            deck.array("cd", drags[key]["cd"])


def launch_and_control_sections(deck, mission, launch_note="data blocks 20 and 21", date_note=""):
    """[launch] (data blocks 20 and 21: the reference's site, azimuth and date) and
    [control_constraints] (data block 22), as every deck built on the reference mission has them;
    launch_note heads [launch], date_note is added to the note of the launch date."""
    launch = mission["launch"]
    ic = mission["initial_conditions_block21"]
    deck.table("launch", launch_note)
    deck.comment("%s; geodetic latitude %s deg; %s UT" % (launch["site"], num(launch["geodetic_latitude_deg"]),
                                                          launch["launch_utc"]))
    deck.number("liftoff_duration_s", mission["liftoff_duration_s_block20_word1"], "block 20 DA5(1)")
    deck.number("space_age_date_days", mission["launch_date_space_age_days_block20_word2"],
                "block 20 DA5(2), Julian date - 2436934.5" + date_note)
    deck.number("altitude_ft", ic["altitude_ft"], "block 21 DA6(1)")
    deck.number("longitude_deg", ic["longitude_deg"], "block 21 DA6(2), east positive")
    deck.number("geocentric_latitude_deg", ic["geocentric_latitude_deg"], "block 21 DA6(3)")
    deck.number("velocity_ft_s", ic["velocity_ft_per_s"], "block 21 DA6(4), must be 0")
    deck.number("azimuth_deg", ic["azimuth_deg"], "block 21 DA6(5), east of north")
    deck.number("flight_path_angle_deg", ic["flight_path_angle_deg"], "block 21 DA6(6), must be 90")
    deck.number("heading_hold_until_s", mission["heading_hold_until_s"],
                "extension: dpsi/dt = 0 on steps starting before this time")

    block22 = mission["block22_control_constraints"]
    deck.table("control_constraints", "data block 22, DA7")
    deck.number("zero_alpha_start_s", block22["alpha_zero_start_s"], "DA7(1), s from launch")
    deck.number("zero_alpha_end_s", block22["alpha_zero_end_s"], "DA7(2), s from launch")
    deck.number("max_pitch_rate_deg_s", block22["max_pitch_rate_deg_per_s"], "DA7(3)")
    deck.number("min_pitch_rate_deg_s", block22["min_pitch_rate_deg_per_s"], "DA7(4)")
    deck.number("min_pitch_rate_change_deg_s", block22["min_change_in_pitch_rate_deg_per_s"], "DA7(5)")


def mission_sections(deck, ref, variant, budget=None, segments=None):
    mission = ref["mission"]
    oracle = ref["oracle_solution"]
    launch_and_control_sections(deck, mission)

    block17 = mission["block17"]
    theta4 = oracle["tth_block40_initial_nominal"]["theta4_deg"] if variant == "initial" else oracle["stage4_theta_deg"]
    if variant == "initial" and theta4 != block17["stage4_theta_deg_initial"]:
        raise ValueError("block 17 and the initial nominal disagree on stage-4 theta")
    chi4 = block17["stage4_chi_deg"] if variant == "initial" else oracle["stage4_chi_deg"]
    deck.table("misc", "data block 17, DA2")
    deck.number("stage4_theta_deg", theta4, "DA2(5), spun stage 4 (adjustable parameter 1)")
    deck.number("stage4_chi_deg", chi4, "DA2(6)")
    deck.number("nose_radius_ft", block17["nose_radius_ft"], "DA2(7)")
    deck.number("gyro_uncage_s_before_launch", block17["gyro_uncage_s_before_launch"], "DA2(8)")
    deck.number("payload_weighting_factor", block17["payload_weighting_factor"], "DA2(15)")
    deck.number("coast_change_limit_s", block17["coast_change_limit_per_iteration_s"], "DA2(16)")
    deck.number("minimum_coast_s", block17["minimum_coast_duration_s"], "DA2(17)")

    terminal = mission["terminal_constraints"]
    codes = terminal["block8_codes"]
    count, codes = codes[0], codes[1:]
    if count != len(codes):
        raise ValueError("block 8 count disagrees with its list")
    desired = terminal["block19_desired_values"]
    optimization = terminal["block29_allowed_deviations_optimization"]
    linearization = terminal["block29_allowed_deviations_linearization"]
    deck.blank()
    deck.comment("Data blocks 8, 19, 29: the payoff first, then the terminal constraints, applied at the",
                 terminal["applied_at"] + ".",
                 "desired_* is block 19, deadband_* block 29 (optimization DA14(1..12), linearization",
                 "DA14(14..25)); the unit is in the key (angles in deg; block 19/29 hold radians).")
    for i, code in enumerate(codes):
        unit, name = constraint_unit(code)
        deck.array_table("constraint", "block 8 IB3(%d): %s%s" % (i + 2, name, " (payoff)" if i == 0 else ""))
        deck.number("code", code)
        if i == 0:
            continue
        deck.number("desired_" + unit, deck_value(desired[i], unit), "block 19 DA4(%d)" % (i + 1))
        rad = " = %s rad" if unit == "deg" else ""
        deck.number("deadband_optimization_" + unit, deck_value(optimization[i - 1], unit),
                    "block 29 DA14(%d)%s" % (i, rad % num(optimization[i - 1]) if rad else ""))
        deck.number("deadband_linearization_" + unit, deck_value(linearization[i - 1], unit),
                    "block 29 DA14(%d)%s" % (i + 13, rad % num(linearization[i - 1]) if rad else ""))

    adjustable = mission["adjustable_parameters_block6"]["codes"]
    count, adjustable = adjustable[0], adjustable[1:]
    if count != len(adjustable):
        raise ValueError("block 6 count disagrees with its list")
    deck.blank()
    deck.comment("Data blocks 6 and 27: " + mission["adjustable_parameters_block6"]["meaning"] + ".")
    for i, code in enumerate(adjustable):
        deck.array_table("adjustable_parameter", "block 6 IB1(%d)" % (i + 2))
        deck.number("code", code)
        deck.number("weight", mission["weighting_block27"][WEIGHT_KEYS[code]], "block 27 DA12(%d)" % code)

    pitch = mission["pitch_program_definition"]
    tlin = pitch["tlin_block18"]
    deck.table("linearization", "data blocks 18 (TLIN) and 26 (ETALIN: default 1.0 per segment)")
    if segments is not None:  # (TLIN, note) of a variant
        tlin, note = segments
        deck.comment(note)
    else:
        deck.comment(pitch["tlin_note"])
    deck.number("segment_count", tlin[0], "TLIN(1)")
    deck.array("coded_times", tlin[1:], "TLIN(2..): 100 x stage + s from stage ignition")

    block28 = mission["block28_convergence"]
    deck.table("convergence", "data block 28, DA13 (payoff units: lb)")
    deck.number("initial_payoff_improvement", block28["initial_payoff_improvement_lb"], "DA13(1)")
    deck.number("stop_improvement", block28["stop_when_attempt_below_lb"], "DA13(2)")
    if budget is None:
        deck.number("max_forward_trajectories", block28["max_forward_trajectories"], "DA13(3)")
    else:
        deck.number("max_forward_trajectories", budget[0], "DA13(3): " + budget[1])
    deck.number("max_linearization_iterations", block28["max_linearization_iterations"], "DA13(4)")

    deck.table("output_frequency", "data block 9, IB4: every computed point, all stages")
    deck.number("initial", 1)
    deck.number("intermediate", 1)
    deck.number("final", 1)

    if variant == "initial":
        tth = oracle["tth_block40_initial_nominal"]
        deck.table("pitch_program", "data block 40, TTH: the oracle's crude starting program")
        times, thetas = tth["time_s"], tth["theta_deg"]
    else:
        flown = oracle["pitch_program"]
        if flown["node_times_s"] != OPTIMUM_NODE_TIMES:
            raise ValueError("the oracle's pitch nodes moved: %s" % flown["node_times_s"])
        deck.table("pitch_program", "data block 40, TTH: the oracle's optimum (theta as flown at the nodes)")
        deck.comment("Between 15 and 45 s the zero-alpha rule (IP(11), block 22) is flown, not the straight line.")
        times = [0.0] + OPTIMUM_NODE_TIMES
        thetas = [90.0] + flown["theta_deg_as_flown"]
    deck.array("time_s", times, "s from launch")
    deck.array("theta_deg", thetas, "pitch attitude from the launch geodetic horizontal")


def body_dynamics_sections(deck, ref):
    body = ref["body_dynamics_6D"]
    da6d = body["block33_DA6D"]
    deck.table("body_dynamics", "data block 33, DA6D (6D simulation; body stations in inches)")
    deck.comment(body["note"])

    def staged(key, stages):
        return [da6d[key]["stage_%d" % s] for s in stages]

    deck.array("position_gain_deg_per_deg", staged("position_gain_K_theta_deg_per_deg", (1, 2, 3)), "DA6D(1-3)")
    deck.array("rate_gain_s", staged("rate_gain_K_q_s", (1, 2, 3)), "DA6D(4-6)")
    deck.array("control_station_in", staged("jet_vane_and_fin_station_in", (1, 2, 3)), "DA6D(7-9)")
    deck.number("jet_vane_effectiveness_per_deg_per_vane",
                da6d["jet_vane_effectiveness_lb_per_lb_vacuum_thrust_per_deg_per_vane"], "DA6D(10)")
    deck.number("moment_reference_station_in", da6d["moment_reference_station_X_FS_in"], "DA6D(11) X_FS")
    deck.array("integration_frequency_multiplier", staged("integration_frequency_multiplier", (1, 2, 3, 4)),
               "DA6D(12-15)")
    deck.number("reference_length_ft", da6d["reference_length_ft"], "DA6D(16)")
    deck.array("impact_every_nth_step", staged("impact_every_nth_step", (1, 2, 3)), "DA6D(17-19)")

    fin = body["block34_fin_normal_force_per_delta"]
    deck.table("body_dynamics.fin_normal_force", "data block 34, CNDELTA (reference area %s ft^2)"
               % num(fin["reference_area_ft2"]))
    deck.array("mach", fin["mach"])
    deck.array("cn_delta_per_rad_per_fin", fin["cn_delta_per_rad_per_fin"])

    cma = body["block35_pitching_moment_per_alpha_about_X_FS"]
    deck.table("body_dynamics.pitching_moment", "data block 35, CMALPHA about X_FS")
    deck.comment("built from the lift table (%s) with the centre-of-pressure stations" % cma["normal_force_slope"])
    deck.comment("x_cp (in) = " + ", ".join(num(v) for v in cma["center_of_pressure_station_in_used"]))
    deck.array("mach", cma["mach"])
    deck.array("cm_alpha_per_rad", cma["cm_alpha_per_rad"])

    cmd = body["block36_fin_pitching_moment_per_delta_about_X_FS"]
    deck.table("body_dynamics.fin_pitching_moment", "data block 36, CMDELTA about X_FS")
    deck.array("mach", cmd["mach"])
    deck.array("cm_delta_per_rad_per_fin", cmd["cm_delta_per_rad_per_fin"])

    for stage in (1, 2, 3, 4):
        cg = body["block37_center_of_gravity_station_in"]["stage_%d" % stage]
        deck.table("body_dynamics.cg.%d" % stage, "data block 37, XCG%d" % stage)
        deck.array("stage_time_s", cg["stage_time_s"])
        deck.array("station_in", cg["cg_station_in"])


def radar_sections(deck, ref):
    deck.blank()
    deck.comment("Data block 41: radar stations (one card each).")
    for station in ref["radar_stations_block41"]:
        deck.array_table("radar_station", "block 41")
        deck.string("id", station["id"], "2A6")
        deck.string("name", station["name"])
        deck.number("geodetic_latitude_deg", station["geodetic_latitude_deg"])
        deck.number("longitude_deg", station["longitude_deg"], "east positive")
        deck.number("altitude_ft", station["altitude_ft"])


def impact_sections(deck, ref):
    impact = ref["impact"]
    deck.blank()
    deck.comment("Data blocks 42-43: impact drag tables (Mach from 0). " + impact["note"])
    for group, block, json_key in (("failure_drag", 42, "block42_failure_mode_cd"),
                                   ("casing_drag", 43, "block43_expended_casing_cd")):
        for stage in (1, 2, 3):
            table = impact[json_key]["stage_%d" % stage]
            deck.table("impact.%s.%d" % (group, stage), "data block %d, CD%d%s" % (block, stage, "F" if block == 42 else "E"))
            deck.comment(table["configuration"])
            deck.number("reference_area_ft2", table["reference_area_ft2"])
            if block == 43:
                deck.number("casing_weight_lb", table["casing_weight_lb"])
            deck.array("mach", table["mach"])
            deck.array("cd", table["cd"])


def hardover_sections(deck, ref):
    hardover = ref["hardover"]
    deck.blank()
    deck.comment("Data blocks 44-45: failure-mode hardover turns. " + hardover["note"])
    for stage in (1, 2, 3):
        table = hardover["block44_pitch_inertia_slug_ft2"]["stage_%d" % stage]
        deck.table("hardover.pitch_inertia.%d" % stage, "data block 44, IYY%d" % stage)
        deck.array("stage_time_s", table["stage_time_s"])
        deck.array("iyy_slug_ft2", table["iyy_slug_ft2"])
    damping = hardover["block44_stage1_pitch_damping_CMQ_per_rad"]
    deck.table("hardover.pitch_damping", "data block 44 (stage code 4): stage 1 CMQ")
    deck.array("mach", damping["mach"])
    deck.array("cmq_per_rad", damping["cmq_per_rad"])
    deck.table("hardover.parameters", "data block 45, words 1-26")
    words = hardover["block45"]
    if len(words) != len(HARDOVER_WORDS):
        raise ValueError("block 45 must have 26 words")
    for key in sorted(words):
        index = int(key[1:3])
        deck.number(HARDOVER_WORDS[index - 1], words[key], "word %d" % index)


def dispersion_sections(deck, ref):
    disp = ref["dispersions"]
    deck.blank()
    deck.comment("Data blocks 46-55: dispersed trajectories, one [[dispersion]] per block 46 card, in",
                 "increasing code order. " + disp["note"],
                 "Signs (the manual: data carry their sign): high +, low -, yaw +.")
    thrust = disp["codes_1_8_vacuum_thrust_variation"]
    titles = {1: "THRUST HI", 2: "THRUST LO"}
    for code in range(1, 9):
        stage = (code + 1) // 2
        high = code % 2 == 1
        table = thrust["tables"]["stage_%d_%s" % (stage, "high" if high else "low")]
        deck.array_table("dispersion", "block 46: vacuum thrust %s, stage %d (%s)"
                         % ("high" if high else "low", stage, thrust["rule"].split(";")[0 if high else 1].strip()))
        deck.number("code", code)
        deck.string("title", "%s S%d" % (titles[1 if high else 2], stage))
        deck.table("dispersion.thrust", "block 30 replacement table, stage %d" % stage)
        deck.array("time_s", table["time_s"])
        deck.array("vacuum_thrust_lbf", table["vacuum_thrust_lbf"])
        deck.table("dispersion.consumable_weight", "block 38 replacement table, stage %d" % stage)
        deck.array("time_s", table["time_s"])
        deck.array("remaining_lb", table["consumable_weight_remaining_lb"])

    weights = disp["codes_9_16_block47_weight_increment_lb"]
    for code in range(9, 17):
        stage = (code - 7) // 2
        high = code % 2 == 1
        deck.array_table("dispersion", "block 46: weight increment %s, stage %d" % ("high" if high else "low", stage))
        deck.number("code", code)
        deck.string("title", "WEIGHT %s S%d" % ("HI" if high else "LO", stage))
        value = weights["stage_%d" % stage]
        deck.number("weight_increment_lb", value if high else -value, "block 47")

    drag = disp["codes_17_18_block48_drag_variation_fraction"]
    for code, sign in ((17, 1.0), (18, -1.0)):
        deck.array_table("dispersion", "block 46: drag variation %s" % ("high" if sign > 0 else "low"))
        deck.number("code", code)
        deck.string("title", "DRAG %s" % ("HIGH" if sign > 0 else "LOW"))
        deck.number("drag_variation_fraction", sign * drag, "block 48")

    # Codes 19-20: block 35 rebuilt with the centre of pressure moved 10 in forward / aft.
    body = ref["body_dynamics_6D"]
    cma = body["block35_pitching_moment_per_alpha_about_X_FS"]
    lift = ref["vehicle"]["aerodynamics"]["lift_curve_slope_table"]
    x_fs = body["block33_DA6D"]["moment_reference_station_X_FS_in"]
    length_in = 40.0  # DA6D(16) = 3.33333 ft, the 40 in diameter, as the nominal table was built
    if lift["mach"] != cma["mach"]:
        raise ValueError("block 35 and the lift table must share their Mach numbers")
    for cn, cp, cm in zip(lift["cl_alpha_per_rad"], cma["center_of_pressure_station_in_used"], cma["cm_alpha_per_rad"]):
        if abs(cn * (x_fs - cp) / length_in - cm) > 1e-9:
            raise ValueError("block 35 is not C_N_alpha (X_FS - x_cp) / 40 in")
    shift = disp["codes_19_20_block35_cm_alpha_variation"]
    for code, delta in ((19, -shift["center_of_pressure_shift_in"]), (20, shift["center_of_pressure_shift_in"])):
        values = [round(cn * (x_fs - (cp + delta)) / length_in, 9)
                  for cn, cp in zip(lift["cl_alpha_per_rad"], cma["center_of_pressure_station_in_used"])]
        deck.array_table("dispersion", "block 46: C_M_alpha %s (%s)"
                         % ("forward" if delta < 0 else "aft", shift["rule"].split(";")[0 if delta < 0 else 1].strip()))
        deck.number("code", code)
        deck.string("title", "CMA %s" % ("FORWARD" if delta < 0 else "AFT"))
        deck.table("dispersion.pitching_moment", "complete block 35 table")
        deck.array("mach", cma["mach"])
        deck.array("cm_alpha_per_rad", values)

    mis = disp["codes_21_23_block49_stage1_thrust_misalignment"]
    for code, sign, kind in ((21, 1.0, "HI"), (22, -1.0, "LO"), (23, 1.0, "YAW")):
        deck.array_table("dispersion", "block 46: stage 1 thrust misalignment %s" % kind.lower())
        deck.number("code", code)
        deck.string("title", "MISALIGN %s" % kind)
        deck.number("misalignment_deg", sign * mis["angle_deg"], "block 49 word 1")
        deck.number("thrust_station_in", mis["thrust_application_station_in"], "block 49 word 2")

    deadband = disp["codes_24_29_block50_control_deadband_deg"]
    for code in range(24, 30):
        stage = 2 if code <= 26 else 3
        kind = ("HI", "LO", "YAW")[(code - 24) % 3]
        sign = -1.0 if kind == "LO" else 1.0
        deck.array_table("dispersion", "block 46: control deadband %s, stage %d" % (kind.lower(), stage))
        deck.number("code", code)
        deck.string("title", "DBAND %s S%d" % (kind, stage))
        deck.number("deadband_deg", sign * deadband["stage_%d" % stage], "block 50")

    for code, kind in ((30, "HI"), (31, "LO"), (32, "YAW")):
        sign = -1.0 if kind == "LO" else 1.0
        deck.array_table("dispersion", "block 46: stage 4 tip-off %s" % kind.lower())
        deck.number("code", code)
        deck.string("title", "TIPOFF %s" % kind)
        deck.number("tipoff_deg", sign * disp["codes_30_32_block51_stage4_tipoff_deg"], "block 51")

    deck.array_table("dispersion", "block 46: launch azimuth (yaw)")
    deck.number("code", 33)
    deck.string("title", "LAUNCH AZ")
    deck.number("launch_azimuth_change_deg", disp["code_33_block52_launch_azimuth_change_deg"], "block 52")
    for code, sign, kind in ((34, 1.0, "HI"), (35, -1.0, "LO")):
        deck.array_table("dispersion", "block 46: launch attitude %s" % kind.lower())
        deck.number("code", code)
        deck.string("title", "LAUNCH ATT %s" % kind[0])
        deck.number("launch_attitude_change_deg", sign * disp["codes_34_35_block52_launch_attitude_change_deg"],
                    "block 52")

    winds = disp["codes_36_38_winds"]
    azimuths = winds["block54_wind_vector_azimuth_deg"]
    for code, key, kind in ((36, "code_36_high_headwind", "HIGH"), (37, "code_37_low_tailwind", "LOW"),
                            (38, "code_38_yaw_crosswind", "YAW")):
        deck.array_table("dispersion", "block 46: winds %s (%s)" % (kind.lower(), key.split("_", 3)[3]))
        deck.number("code", code)
        deck.string("title", "WINDS %s" % kind)
        deck.table("dispersion.wind_speed", "block 53, WINDVL")
        deck.array("altitude_ft", winds["block53_altitude_ft"])
        deck.array("speed_ft_s", winds["block53_wind_speed_ft_per_s"])
        deck.table("dispersion.wind_azimuth", "block 54, WINDAZ")
        if code == 36:
            deck.comment(winds["azimuth_convention"])
        deck.array("altitude_ft", winds["block53_altitude_ft"])
        deck.array("azimuth_deg", azimuths[key])

    deck.array_table("dispersion", "block 46: three-sigma summary")
    deck.number("code", 40)
    deck.string("title", "NOMINAL TRAJ")
    if disp.get("block55_stage4_5_durations_s") is not None:
        raise ValueError("block 55 data present: the generator writes it only for five-stage vehicles")


def build(ref, variant):
    deck = Deck()
    header(deck, ref, variant)
    case_section(deck, variant, ref)
    options_section(deck, ref, variant)
    flown = "initial" if variant == "qalpha" else variant  # the q-alpha deck flies the initial case
    constants_sections(deck, ref)
    vehicle_sections(deck, ref, flown)
    mission_sections(deck, ref, flown, QALPHA_BUDGET if variant == "qalpha" else None,
                     (QALPHA_TLIN, QALPHA_TLIN_NOTE) if variant == "qalpha" else None)
    deck.blank()
    deck.comment("=" * 94)
    deck.comment("Optional computations (IP(6), IP(21)-IP(24)): data blocks 33-37 and 41-55.")
    deck.comment("=" * 94)
    body_dynamics_sections(deck, ref)
    radar_sections(deck, ref)
    impact_sections(deck, ref)
    hardover_sections(deck, ref)
    dispersion_sections(deck, ref)
    return deck.render()


# ---- card deck emission (docs/deck-format.md "The card deck"; ground_tools/src/deck/card_*.cpp) --
#
# The card deck is punched from the TOML deck exactly as `tolip convert` does it
# (card_writer.cpp): the words each TOML key stands for, then header cards (4I3 and the block's
# title as a comment from column 13) and data cards, the optional groups the options select after
# the blank card ending the case, each ended by a blank card, and the 999 card.

CARD_TITLES = {  # card_blocks.cpp make_blocks()
    1: "MAIN HEADING", 2: "CASE HEADING", 3: "DATE", 4: "OPTIONS IP", 5: "STAGE SEQUENCE ISTGE",
    6: "ADJUSTABLE PARAMETERS IB1", 8: "TRAJECTORY CONSTRAINT PARAMETERS IB3", 9: "OUTPUT FREQUENCY IB4",
    10: "NOMINAL CONSTANTS CT1", 11: "ATMOSPHERE CT2 BASE GEOPOTENTIAL ALTITUDE",
    12: "ATMOSPHERE CT3 BASE MOLECULAR TEMPERATURE", 13: "ATMOSPHERE CT4 LAPSE RATE",
    14: "ATMOSPHERE CT5 BASE DENSITY", 15: "EXTENSIONS: PAYLOAD, HEADING HOLD, LIFT STAGES",
    16: "STAGE DURATIONS AND INTEGRATION STEPS DA1", 17: "INPUT DATA DA2",
    18: "PITCH PROGRAM LINEARIZATION TIMES TLIN", 19: "TRAJECTORY CONSTRAINT MAGNITUDES DA4",
    20: "INITIAL TIMES DA5", 21: "INITIAL CONDITIONS DA6", 22: "CONTROL VARIABLE CONSTRAINTS DA7",
    23: "IMPACT EXTENSIONS: REFERENCE AREAS, CASING WEIGHT", 26: "LINEARIZATION SEGMENT WEIGHTS ETALIN",
    27: "OPTIMIZATION PARAMETER WEIGHTS DA12", 28: "CONVERGENCE DATA DA13", 29: "CONSTRAINT DEVIATIONS DA14",
    30: "VACUUM THRUST TABLE", 31: "DRAG COEFFICIENT TABLE (ALPHA = 0)", 32: "LIFT COEFFICIENT PER ALPHA TABLE TL1",
    33: "DATA FOR 6D SIMULATION DA6D", 34: "FIN NORMAL FORCE COEFFICIENT PER DELTA",
    35: "PITCHING MOMENT COEFFICIENT PER ALPHA", 36: "FIN PITCHING MOMENT COEFFICIENT PER DELTA",
    37: "STAGE CENTER OF GRAVITY HISTORY", 38: "CONSUMABLE WEIGHT REMAINING TABLE", 39: "STAGE DATA SG",
    40: "THETA HISTORY FOR NOMINAL TRAJECTORY TTH", 41: "RADAR STATION LOCATIONS",
    42: "IMPACT FAILURE MODE DRAG TABLE", 43: "IMPACT EXPENDED CASING DRAG TABLE",
    44: "HARDOVER IYY (STAGES 1-3) OR CMQ (CODE 4) TABLE", 45: "HARDOVER DATA",
    46: "DISPERSION TRAJECTORY CODE AND TITLE", 47: "STAGE WEIGHT INCREMENT", 48: "PERCENTAGE DRAG VARIATION",
    49: "STAGE 1 THRUST MISALIGNMENT", 50: "CONTROL SYSTEM DEADBAND ANGLE", 51: "FOURTH OR FIFTH STAGE TIPOFF",
    52: "LAUNCH DISPERSIONS", 53: "WIND VELOCITY WINDVL", 54: "WIND AZIMUTH WINDAZ", 55: "STAGE 4 AND 5 DURATIONS",
}
CARD_STAGE_CODED = {23, 30, 31, 37, 38, 39, 42, 43, 44, 47, 49, 50, 51}
CARD_TABLES = {31, 32, 34, 35, 36, 37, 40, 42, 43, 44, 53, 54}  # blank, x, y, ..., 1.0E10
CARD_PAIRS = {30, 38}                                            # x, y, ... (complete per stage)
CARD_TEXT = {1, 2, 3, 46}
CARD_INTEGER = {5, 6, 8, 9}
TABLE_END = 1.0e10
DISPERSION_NAMES = [  # deck_common.cpp dispersion_name()
    (range(1, 9), "vacuum thrust variation"), (range(9, 17), "weight increment"), (range(17, 19), "drag variation"),
    (range(19, 21), "C_M_alpha variation"), (range(21, 24), "stage 1 thrust misalignment"),
    (range(24, 30), "control system deadband"), (range(30, 33), "stage 4/5 tip-off"), (range(33, 34), "launch azimuth"),
    (range(34, 36), "launch attitude"), (range(36, 39), "winds"), (range(40, 41), "three-sigma summary"),
]
OPTION_IP = {  # deck key -> IP(n)
    key: n for n, (key, _) in OPTION_KEYS.items()
}
SCALAR_WORDS = [  # (block, word, TOML section, key): card_blocks.cpp scalar_keys()
    (10, 1, "constants", "earth_rotation_rate_rad_s"), (10, 2, "constants", "gravitational_parameter_ft3_s2"),
    (10, 3, "constants", "earth_equatorial_radius_ft"), (10, 4, "constants", "gas_constant_ft2_s2_R"),
    (10, 5, "constants", "g0_ft_s2"), (10, 6, "constants", "sea_level_pressure_lbf_ft2"), (10, 7, "constants", "haero_ft"),
    (10, 8, "constants", "lines_per_page"), (10, 9, "constants", "deg_to_rad_as_printed"),
    (10, 10, "constants", "time_epsilon_s"), (10, 11, "constants", "j2"), (10, 12, "constants", "inverse_flattening"),
    (10, 13, "constants", "ct1_13"),
    (20, 1, "launch", "liftoff_duration_s"), (20, 2, "launch", "space_age_date_days"), (21, 1, "launch", "altitude_ft"),
    (21, 2, "launch", "longitude_deg"), (21, 3, "launch", "geocentric_latitude_deg"), (21, 4, "launch", "velocity_ft_s"),
    (21, 5, "launch", "azimuth_deg"), (21, 6, "launch", "flight_path_angle_deg"), (15, 2, "launch", "heading_hold_until_s"),
    (22, 1, "control_constraints", "zero_alpha_start_s"), (22, 2, "control_constraints", "zero_alpha_end_s"),
    (22, 3, "control_constraints", "max_pitch_rate_deg_s"), (22, 4, "control_constraints", "min_pitch_rate_deg_s"),
    (22, 5, "control_constraints", "min_pitch_rate_change_deg_s"),
    (17, 5, "misc", "stage4_theta_deg"), (17, 6, "misc", "stage4_chi_deg"), (17, 7, "misc", "nose_radius_ft"),
    (17, 8, "misc", "gyro_uncage_s_before_launch"), (17, 9, "misc", "stage5_theta_deg"), (17, 10, "misc", "stage5_chi_deg"),
    (17, 15, "misc", "payload_weighting_factor"), (17, 16, "misc", "coast_change_limit_s"),
    (17, 17, "misc", "minimum_coast_s"),
    (28, 1, "convergence", "initial_payoff_improvement"), (28, 2, "convergence", "stop_improvement"),
    (28, 3, "convergence", "max_forward_trajectories"), (28, 4, "convergence", "max_linearization_iterations"),
]
BODY_SCALARS = [(10, "jet_vane_effectiveness_per_deg_per_vane"), (11, "moment_reference_station_in"),
                (16, "reference_length_ft")]
BODY_ARRAYS = [(1, "position_gain_deg_per_deg"), (4, "rate_gain_s"), (7, "control_station_in"),
               (12, "integration_frequency_multiplier"), (17, "impact_every_nth_step")]


def dispersion_name(code):
    for codes, name in DISPERSION_NAMES:
        if code in codes:
            return name
    raise ValueError("unknown dispersion code %d" % code)


def card_render(value, precision):
    """value rounded to `precision` significant digits, with a decimal point (card_blocks.cpp render)."""
    text = "%.*e" % (precision - 1, value)
    negative = text.startswith("-")
    if negative:
        text = text[1:]
    mantissa, exponent = text.split("e")
    exponent = int(exponent)
    digits = mantissa.replace(".", "").rstrip("0") or "0"
    if digits == "0":
        return "0."
    sign = "-" if negative else ""
    exp_form = sign + digits[0] + "." + digits[1:] + "E" + str(exponent)
    if exponent >= 0:
        if exponent + 1 >= len(digits):
            fixed = digits + "0" * (exponent + 1 - len(digits)) + "."
        else:
            fixed = digits[:exponent + 1] + "." + digits[exponent + 1:]
    else:
        fixed = "." + "0" * (-exponent - 1) + digits
    fixed = sign + fixed
    return fixed if len(fixed) <= 12 or len(fixed) <= len(exp_form) else exp_form


def card_real(value, width=12):
    """The text of an E12.8 field: exact when it fits, else the most digits that fit."""
    value = float(value)
    if not math.isfinite(value):
        raise ValueError("non-finite number %r" % value)
    if value == 0.0:
        return "0."
    if value == TABLE_END:
        return "1.0E10"
    best = ""
    for precision in range(1, 18):
        text = card_render(value, precision)
        if len(text) > width:
            continue
        best = text
        if float(text) == value:
            return text
    return best or card_render(value, 1)


class CardWords:
    """Words of data blocks: {(block, stage): {word: number or text}} (card_model.hpp BlockSet)."""

    def __init__(self):
        self.blocks = {}

    def set(self, block, stage, word, value):
        self.blocks.setdefault((block, stage), {})[word] = value

    def text(self, block, stage, first, words, text):
        for w in range(words):
            self.set(block, stage, first + w, text[6 * w:6 * w + 6].ljust(6))

    def table(self, block, stage, xs, ys):
        word = 1
        if block not in CARD_PAIRS:
            self.set(block, stage, word, 0.0)
            word += 1
        for x, y in zip(xs, ys):
            self.set(block, stage, word, x)
            self.set(block, stage, word + 1, y)
            word += 2
        if block not in CARD_PAIRS:
            self.set(block, stage, word, TABLE_END)


def card_words(deck):
    """The words of a TOML deck (card_writer.cpp FromToml)."""
    opt, impact, hardover = CardWords(), CardWords(), CardWords()
    case = deck["case"]
    opt.text(1, 0, 1, 12, case["title"])
    if "heading" in case:
        opt.text(2, 0, 1, 12, case["heading"])
    if "date" in case:
        opt.text(3, 0, 1, 2, case["date"])
    if "options" in deck:
        for ip in range(1, 25):
            key = OPTION_KEYS.get(ip, (None, None))[0]
            opt.set(4, 0, ip, int(deck["options"].get(key, 0)) if key else 0)
    for block, word, section, key in SCALAR_WORDS:
        if key in deck.get(section, {}):
            opt.set(block, 0, word, deck[section][key])
    if "atmosphere" in deck:
        for block, key in ((11, "base_geopotential_altitude_ft"), (12, "base_molecular_temperature_R"),
                           (13, "lapse_rate_R_per_ft"), (14, "base_density_slug_ft3")):
            for i, value in enumerate(deck["atmosphere"].get(key, [])):
                opt.set(block, 0, i + 1, value)
    vehicle = deck["vehicle"]
    sequence = list(vehicle["sequence"])
    if sequence and sequence[-1] == 0:
        sequence.pop()
    for i, code in enumerate(sequence):
        opt.set(5, 0, i + 1, code)
    if len(sequence) < 11:
        opt.set(5, 0, len(sequence) + 1, 0)
    if vehicle["payload_lb"] != 0:
        opt.set(15, 0, 1, vehicle["payload_lb"])
    if "lift_curve_slope" in vehicle:
        lift = vehicle["lift_curve_slope"]
        opt.table(32, 0, lift["mach"], lift["cl_alpha_per_rad"])
        if "used_in_stages" in lift:
            used = set(lift["used_in_stages"])
            opt.set(15, 0, 3, 16 if used >= {1, 6} else 1 if 1 in used else 6 if 6 in used else 0)
    for code in range(1, 11):
        stage = deck["stage"].get(str(code))
        if stage is None:
            continue
        if "duration_s" in stage:
            opt.set(16, 0, 2 * code - 1, stage["duration_s"])
        if "integration_steps" in stage:
            opt.set(16, 0, 2 * code, stage["integration_steps"])
        for word, key in enumerate(("jettison_weight_lb", "reference_area_ft2", "nozzle_exit_area_ft2"), 1):
            if key in stage:
                opt.set(39, code, word, stage[key])
        for block, key, x_key, y_key in ((30, "thrust", "time_s", "vacuum_thrust_lbf"),
                                         (38, "consumable_weight", "time_s", "remaining_lb"),
                                         (31, "drag", "mach", "cd")):
            if key in stage:
                opt.table(block, code, stage[key][x_key], stage[key][y_key])
    entries = deck.get("constraint", [])
    if entries:
        heating = len(entries) > 1 and entries[-1]["code"] == 14
        opt.set(8, 0, 1, len(entries) - (1 if heating else 0))
        for e, entry in enumerate(entries):
            opt.set(8, 0, e + 2, entry["code"])
            unit = constraint_unit(entry["code"])[0]
            for block, word, key in ((19, e + 1, "desired"), (29, e, "deadband_optimization"),
                                     (29, e + 13, "deadband_linearization")):
                if block == 29 and e == 0:
                    continue
                name = key + "_" + unit
                if name in entry:
                    value = entry[name]
                    opt.set(block, 0, word, value * (math.pi / 180.0) if unit == "deg" else value)
    if "adjustable_parameter" in deck:
        parameters = deck["adjustable_parameter"]
        opt.set(6, 0, 1, len(parameters))
        for i, entry in enumerate(parameters):
            opt.set(6, 0, i + 2, entry["code"])
            if "weight" in entry:
                # Data block 27 by code number (Sec. 22): DA12(k) weights code k.
                opt.set(27, 0, entry["code"], entry["weight"])
    if "linearization" in deck:
        times = deck["linearization"]["coded_times"]
        opt.set(18, 0, 1, len(times) - 1)
        for i, value in enumerate(times):
            opt.set(18, 0, i + 2, value)
        for i, value in enumerate(deck["linearization"].get("segment_weights", [])):
            opt.set(26, 0, i + 1, value)
    if "output_frequency" in deck:
        for k, key in enumerate(("initial", "intermediate", "final")):
            values = deck["output_frequency"].get(key, 1)
            for stage in range(1, 11):
                value = values if isinstance(values, int) else values[stage - 1]
                opt.set(9, 0, 4 * (stage - 1) + 1 + k, value)
                opt.set(9, 0, 4 * stage, stage)
    opt.table(40, 0, deck["pitch_program"]["time_s"], deck["pitch_program"]["theta_deg"])
    body = deck.get("body_dynamics")
    if body is not None:
        for first, key in BODY_ARRAYS:
            for i, value in enumerate(body.get(key, [])):
                opt.set(33, 0, first + i, value)
        for word, key in BODY_SCALARS:
            if key in body:
                opt.set(33, 0, word, body[key])
        for block, key, y_key in ((34, "fin_normal_force", "cn_delta_per_rad_per_fin"),
                                  (35, "pitching_moment", "cm_alpha_per_rad"),
                                  (36, "fin_pitching_moment", "cm_delta_per_rad_per_fin")):
            if key in body:
                opt.table(block, 0, body[key]["mach"], body[key][y_key])
        for stage in range(1, 5):
            cg = body.get("cg", {}).get(str(stage))
            if cg is not None:
                opt.table(37, stage, cg["stage_time_s"], cg["station_in"])
    for group, block, area_word in (("failure_drag", 42, 1), ("casing_drag", 43, 2)):
        for stage in range(1, 4):
            entry = deck.get("impact", {}).get(group, {}).get(str(stage))
            if entry is None:
                continue
            impact.table(block, stage, entry["mach"], entry["cd"])
            if "reference_area_ft2" in entry:
                impact.set(23, stage, area_word, entry["reference_area_ft2"])
            if "casing_weight_lb" in entry:
                impact.set(23, stage, 3, entry["casing_weight_lb"])
    if "hardover" in deck:
        for stage in range(1, 4):
            table = deck["hardover"].get("pitch_inertia", {}).get(str(stage))
            if table is not None:
                hardover.table(44, stage, table["stage_time_s"], table["iyy_slug_ft2"])
        if "pitch_damping" in deck["hardover"]:
            damping = deck["hardover"]["pitch_damping"]
            hardover.table(44, 4, damping["mach"], damping["cmq_per_rad"])
        for word, key in enumerate(HARDOVER_WORDS, 1):
            if key in deck["hardover"].get("parameters", {}):
                hardover.set(45, 0, word, deck["hardover"]["parameters"][key])
    dispersions = []
    for entry in deck.get("dispersion", []):
        code = entry["code"]
        title, words = CardWords(), CardWords()
        title.text(46, 0, 1, 2, entry.get("title", ""))
        if 1 <= code <= 8:
            stage = (code + 1) // 2
            words.table(30, stage, entry["thrust"]["time_s"], entry["thrust"]["vacuum_thrust_lbf"])
            words.table(38, stage, entry["consumable_weight"]["time_s"], entry["consumable_weight"]["remaining_lb"])
            for i, value in enumerate(entry.get("stage_durations_s", [])[:2]):
                words.set(55, 0, i + 1, value)
        elif 9 <= code <= 16:
            words.set(47, (code - 7) // 2, 1, entry["weight_increment_lb"])
        elif code in (17, 18):
            words.set(48, 0, 1, entry["drag_variation_fraction"])
        elif code in (19, 20):
            words.table(35, 0, entry["pitching_moment"]["mach"], entry["pitching_moment"]["cm_alpha_per_rad"])
        elif 21 <= code <= 23:
            words.set(49, 1, 1, entry["misalignment_deg"])
            words.set(49, 1, 2, entry["thrust_station_in"])
        elif 24 <= code <= 29:
            words.set(50, 2 if code <= 26 else 3, 1, entry["deadband_deg"])
        elif 30 <= code <= 32:
            words.set(51, entry.get("stage", 4), 1, entry["tipoff_deg"])
        elif code == 33:
            words.set(52, 0, 1, entry["launch_azimuth_change_deg"])
        elif code in (34, 35):
            words.set(52, 0, 1, entry["launch_attitude_change_deg"])
        elif 36 <= code <= 38:
            words.table(53, 0, entry["wind_speed"]["altitude_ft"], entry["wind_speed"]["speed_ft_s"])
            words.table(54, 0, entry["wind_azimuth"]["altitude_ft"], entry["wind_azimuth"]["azimuth_deg"])
        dispersions.append((code, title.blocks[(46, 0)], words))
    return opt, impact, hardover, dispersions, deck.get("radar_station", [])


class CardPunch:
    """Card images (card_writer.cpp Punch)."""

    def __init__(self):
        self.cards = []

    def card(self, text):
        self.cards.append(text[:80].rstrip())

    def header(self, block, first, last, stage, note):
        self.card("%3d%3d%3d%s  %s" % (block, first, last, "%3d" % stage if stage else "   ", note))

    @staticmethod
    def field(block, word, value):
        if block in CARD_TEXT:
            return value.ljust(6)[:6]
        if block == 4:
            return "%1d" % value
        if block in CARD_INTEGER:
            return "%3d" % value
        if block in CARD_TABLES and word == 1 and value == 0:
            return " " * 12
        return card_real(value).rjust(12)

    def words(self, block, stage, words, first, last, header_stage, note):
        self.header(block, first, last, header_stage, note)
        per_card = 12 if block in CARD_TEXT else 24 if (block == 4 or block in CARD_INTEGER) else 6
        line = ""
        for n, w in enumerate(range(first, last + 1)):
            line += self.field(block, w, words[w])
            if (n + 1) % per_card == 0:
                self.card(line)
                line = ""
        if line:
            self.card(line)

    def block(self, block, stage, words):
        note = CARD_TITLES[block] + (" STAGE %d" % stage if block in CARD_STAGE_CODED else "")
        present = sorted(words)
        w = 0
        while w < len(present):
            end = w
            while end + 1 < len(present) and present[end + 1] == present[end] + 1:
                end += 1
            self.words(block, stage, words, present[w], present[end], stage, note)
            w = end + 1

    def blocks(self, card_words, skip=()):
        for (block, stage) in sorted(card_words.blocks):
            if block not in skip:
                self.block(block, stage, card_words.blocks[(block, stage)])


def build_cards(toml_text):
    """The card deck of a TOML deck (one case)."""
    try:
        import tomllib
    except ImportError as error:  # Python < 3.11
        raise SystemExit("the card deck needs Python 3.11 or later (tomllib): %s" % error)
    deck = tomllib.loads(toml_text)
    opt, impact, hardover, dispersions, radar = card_words(deck)
    ip = lambda n: opt.blocks.get((4, 0), {}).get(n, 0) == 1  # noqa: E731
    punch = CardPunch()
    punch.blocks(opt)
    punch.card("")
    if ip(21):
        for code, title, words in dispersions:
            punch.words(46, 0, title, 1, 2, code, "DISPERSION " + dispersion_name(code))
            punch.blocks(words)
        punch.card("")
    body = opt.blocks.get((33, 0), {})
    if ip(22):
        punch.blocks(hardover)
        part = {w: v for w, v in body.items() if 7 <= w <= 16}
        punch.block(33, 0, part)
        for stage in range(1, 5):
            if (37, stage) in opt.blocks:
                punch.block(37, stage, opt.blocks[(37, stage)])
        punch.card("")
    if ip(23):
        punch.blocks(impact)
        punch.block(33, 0, {w: v for w, v in body.items() if 17 <= w <= 19})
        punch.card("")
    if ip(24):
        for start in range(0, len(radar), 20):
            part = radar[start:start + 20]
            punch.header(41, 1, 5, len(part), "RADAR STATION LOCATIONS")
            for station in part:
                punch.card(station["id"].ljust(12)[:12] +
                           "".join(card_real(station[key]).rjust(12)
                                   for key in ("geodetic_latitude_deg", "longitude_deg", "altitude_ft")) +
                           " " + station.get("name", "")[:31])
        punch.card("")
    punch.card("999")
    return "\n".join(punch.cards) + "\n"


# The second case of cases.dat: its changed words only (blocks 2 and 15), everything else carried
# over from the first case.
SECOND_CASE_CARDS = [
    "  2  1 12     CASE HEADING",
    "SECOND CASE: INITIAL PAYLOAD 260 LB",
    " 15  1  1     EXTENSIONS: PAYLOAD",
    "        260.",
]


def build_two_cases(cards_text):
    """The card deck of one case followed by SECOND_CASE_CARDS: the first case through its blank
    card and its optional groups, then the second case's changes, its blank card and the optional
    groups again, then the 999 card."""
    cards = cards_text.rstrip("\n").split("\n")
    if cards[-1] != "999":
        raise ValueError("the card deck does not end with the 999 card")
    end = next(i for i, card in enumerate(cards) if card.strip() == "")  # the blank card ending case 1
    first, groups = cards[:end + 1], cards[end + 1:-1]
    return "\n".join(first + groups + SECOND_CASE_CARDS + [""] + groups + ["999"]) + "\n"


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--reference", default=DEFAULT_REFERENCE, help="scout_reference.json")
    parser.add_argument("--out", default=DEFAULT_OUT, help="output folder (examples/scout)")
    args = parser.parse_args(argv)
    with open(args.reference, encoding="utf-8") as handle:
        ref = json.load(handle)
    if ref.get("schema") != "tolip-scout-reference/1":
        raise SystemExit("unexpected reference schema %r" % ref.get("schema"))
    os.makedirs(args.out, exist_ok=True)
    for name, variant in (("mission.toml", "initial"), ("reference_optimum.toml", "optimum"),
                          ("mission_qalpha.toml", "qalpha")):
        path = os.path.join(args.out, name)
        text = build(ref, variant)
        with open(path, "w", encoding="utf-8", newline="\n") as handle:
            handle.write(text)
        print("wrote " + os.path.relpath(path, ROOT))
        if variant == "initial":
            path = os.path.join(args.out, "mission.dat")
            cards = build_cards(text)
            with open(path, "w", encoding="ascii", newline="\n") as handle:
                handle.write(cards)
            print("wrote " + os.path.relpath(path, ROOT))
            path = os.path.join(args.out, "cases.dat")
            with open(path, "w", encoding="ascii", newline="\n") as handle:
                handle.write(build_two_cases(cards))
            print("wrote " + os.path.relpath(path, ROOT))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
