#!/usr/bin/env python3
"""Generate the Earth-escape example, examples/escape/mission.toml (Addendum H, codes 100-102).

    python3 scripts/make_escape_example.py [--reference PATH] [--out DIR]

A five-stage vehicle (docs/user-guide.md "An Earth-escape example"): the Scout-class stages 1-4 of
the reference case (tests/reference/scout_reference.json, written by the same code as
examples/scout/mission.toml: scripts/make_scout_examples.py), with stage 4 under continuous control
(IP(9) = 2: it flies the pitch program), and a small spun solid kick stage 5 of this project's own
design on top (about 150 lb, illustrative: 124 lb of propellant at a vacuum Isp of 285 s burning
20 s, a 26 lb case). The spun stage 5 holds the attitudes of data block 17: its pitch DA2(9) and,
with IP(10) = 2, its own yaw DA2(10); both are adjustable (codes 8, 9), with the launch time of day
(code 7), the coast after stage 3 (code 3) and the coast after stage 4 (code 10). After stage 5 an
integrated coast (10) flies the first minutes of the departure (Addendum H: "their effect can be
included by introducing an integrated coast following the final stage"); the constraints apply at
its end.

The mission: maximum payload to a hyperbolic excess velocity of 8,000 ft/s (code 100) with the
outward radial (the asymptote) at right ascension 215 deg (101) and declination -33 deg (102),
from Wallops Island at the reference's azimuth and date, starting from a crude program whose
trajectory is NOT hyperbolic (the optimizer's Addendum H continuation:
docs/theory/optimizer.md "Earth escape from an elliptic start").

Every figure of stage 5 and of the mission is illustrative; none is the data of a real vehicle.
Only the Python standard library is used; the output is deterministic.
"""

import argparse
import copy
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # importing the Scout generator leaves no __pycache__ in scripts/
sys.path.insert(0, HERE)
import make_scout_examples as scout  # noqa: E402  (the Scout-class stages and the deck writer)

ROOT = os.path.dirname(HERE)
DEFAULT_OUT = os.path.join(ROOT, "examples", "escape")

# Stage 5: a spun solid kick motor (illustrative).
STAGE5_THRUST_LBF = 1767.0
STAGE5_ISP_S = 285.0
STAGE5_BURN_S = 20.0
STAGE5_CASE_LB = 26.0
STAGE5_STEPS = 16
STAGE5_RAMP_S = 0.2
STAGE5_TAIL_S = 1.0

# The crude start.
PAYLOAD_LB = 90.0
COAST8_S = 60.0
COAST9_S = 20.0
COAST10_S = 300.0
STAGE5_THETA_DEG = 0.0
STAGE5_CHI_DEG = 0.0
CRUDE_TIMES = [0.0, 3.0, 8.0, 15.0, 45.0, 50.0, 69.0, 88.0, 130.0, 220.0, 260.0]
CRUDE_THETAS = [90.0, 90.0, 80.0, 65.0, 49.0, 33.0, 27.0, 22.0, 18.0, 5.0, 0.0]

# The target (Addendum H: the outward radial, translated to the Earth's centre).
V_INFINITY_FT_S = 8000.0
RIGHT_ASCENSION_DEG = 215.0
DECLINATION_DEG = -33.0


def profile():
    """Stage 5 vacuum thrust and consumable weight remaining: a ramp, constant, a linear tail-off;
    the consumable weight the exact integral of T / Isp."""
    times = [0.0, STAGE5_RAMP_S]
    t = STAGE5_RAMP_S
    while t + 2.0 < STAGE5_BURN_S - STAGE5_TAIL_S - 1e-9:
        t = round(t + 2.0, 6)
        times.append(t)
    times += [STAGE5_BURN_S - STAGE5_TAIL_S, STAGE5_BURN_S]
    thrust = [0.0] + [STAGE5_THRUST_LBF] * (len(times) - 2) + [0.0]
    burned = [0.0]
    for k in range(1, len(times)):
        burned.append(burned[-1] + 0.5 * (thrust[k - 1] + thrust[k]) / STAGE5_ISP_S * (times[k] - times[k - 1]))
    propellant = round(burned[-1], 3)
    remaining = [round(propellant - b, 3) if k + 1 < len(times) else 0.0 for k, b in enumerate(burned)]
    return times, thrust, remaining, propellant


def escape_reference(ref):
    """The reference's vehicle with stage 4 continuous, coasts 9 and 10 and stage 5 added."""
    r = copy.deepcopy(ref)
    vehicle = r["vehicle"]
    vehicle["stage_sequence_block5"] = [1, 6, 2, 7, 3, 8, 4, 9, 5, 10]
    vehicle["payload_carried_in_jettison_of_stage"] = 5
    s4 = vehicle["stages"]["4"]
    s4["name"] = "Altair-class solid motor (stage 4, 18 in diameter; continuous control here, IP(9) = 2)"
    s4["jettison_weight_note"] = "Altair case+nozzle 70, transition section D / stage-5 adapter 55"
    vehicle["stages"]["8"]["note"] = ("coast after stage 3, short for a direct ascent; duration is an "
                                      "adjustable parameter (code 3, block 6)")
    vehicle["stages"]["8"]["duration_s"] = COAST8_S
    times, thrust, remaining, propellant = profile()
    impulse = sum(0.5 * (thrust[k - 1] + thrust[k]) * (times[k] - times[k - 1]) for k in range(1, len(times)))
    vehicle["stages"]["9"] = {
        "kind": "coast", "duration_s": COAST9_S, "integration_steps": 4, "jettison_weight_lb": 0.0,
        "reference_area_ft2": 0.0,
        "note": "coast after stage 4 (continuous control: flies the pitch program); duration is an "
                "adjustable parameter (code 10, block 6)",
    }
    vehicle["stages"]["5"] = {
        "kind": "powered",
        "name": "illustrative spun solid kick motor (stage 5, about 150 lb; spin stabilized, IP(9) = 2)",
        "duration_s": STAGE5_BURN_S, "integration_steps": STAGE5_STEPS,
        "jettison_weight_lb": STAGE5_CASE_LB,
        "jettison_weight_note": "kick-motor case, nozzle and spin table %s lb; the payload is ADDED to this "
                                "jettison weight (manual Sec. 14)" % scout.num(STAGE5_CASE_LB),
        "propellant_weight_lb": propellant, "isp_vacuum_s": STAGE5_ISP_S,
        "total_vacuum_impulse_lbf_s": round(impulse, 3),
        "reference_area_ft2": 1.0, "nozzle_exit_area_ft2": 0.2,
        "thrust_table": {"time_s": times, "vacuum_thrust_lbf": thrust},
        "consumable_weight_table": {"time_s": times, "consumable_weight_remaining_lb": remaining},
    }
    vehicle["stages"]["10"] = {
        "kind": "coast", "duration_s": COAST10_S, "integration_steps": 10, "jettison_weight_lb": 0.0,
        "reference_area_ft2": 0.0,
        "note": "the integrated coast following the final stage (Addendum H): the spent stage 5 and the "
                "payload on the departure path; the constraints apply at its end",
    }
    initial = r["oracle_solution"]["tth_block40_initial_nominal"]
    initial["coast8_s"] = COAST8_S
    initial["payload_lb"] = PAYLOAD_LB
    return r


def build(ref):
    r = escape_reference(ref)
    deck = scout.Deck()
    deck.comment(
        "TOLIP case deck (TOML; format: docs/deck-format.md).",
        "GENERATED by scripts/make_escape_example.py from tests/reference/scout_reference.json;",
        "edit the generator, not this file.",
        "",
        "Earth escape (manual Addendum H): the Scout-class stages 1-4 of examples/scout (stage 4 under",
        "continuous control) and an illustrative spun kick stage 5, to a hyperbolic excess velocity",
        "of %s ft/s with the asymptote at right ascension %s deg, declination %s deg."
        % (f"{V_INFINITY_FT_S:,.0f}", scout.num(RIGHT_ASCENSION_DEG), scout.num(DECLINATION_DEG)),
        "Illustrative engineering data; not official Scout data, stage 5 is this project's own.",
        "",
        "The crude start is NOT hyperbolic: the optimizer steers an energy stand-in for code 100",
        "and defers codes 101-102 until the nominal is (docs/theory/optimizer.md).",
        "Units are in the key names; angles in degrees (the reader converts to radians).",
    )
    deck.table("case", "data blocks 1-3")
    deck.string("title", "FIVE-STAGE EARTH ESCAPE, WALLOPS ISLAND, VINF 8000 FT/S", "block 1, 12A6")
    deck.string("heading", "MAXIMUM PAYLOAD TO THE ASYMPTOTE FROM A CRUDE ELLIPTIC START", "block 2, 12A6")
    deck.string("date", ref["mission"]["launch"]["launch_utc"][:10], "block 3, 2A6")

    deck.table("options", "data block 4, IP(n)")
    deck.number("payoff", 0, "IP(1): payload")
    deck.flag("heating_constraint", False, "IP(2)")
    deck.flag("exchange_ratios", False, "IP(3)")
    deck.number("body_dynamics_6d", 0, "IP(6)")
    deck.flag("linearization", False, "IP(7)")
    deck.number("spin_stages_4_5", 2, "IP(9): stage 4 continuous, stage 5 spun")
    deck.number("stage5_chi", 2, "IP(10): chi5 independent of chi4 (DA2(10))")
    deck.flag("zero_alpha_window", True, "IP(11)")
    deck.flag("alpha_zero_at_stage2_ignition", True, "IP(12)")
    deck.number("qbar_constraint_type", 0, "IP(13)")
    deck.flag("print_input", False, "IP(17)")

    scout.constants_sections(deck, r)
    scout.vehicle_sections(deck, r, "initial")

    mission = r["mission"]
    scout.launch_and_control_sections(deck, mission,
                                      "data blocks 20 and 21: the reference's site, azimuth and date",
                                      "; adjustable parameter 7 (time of day)")

    block17 = mission["block17"]
    deck.table("misc", "data block 17, DA2")
    deck.number("nose_radius_ft", block17["nose_radius_ft"], "DA2(7)")
    deck.number("stage5_theta_deg", STAGE5_THETA_DEG, "DA2(9), spun stage 5 (adjustable parameter 8)")
    deck.number("stage5_chi_deg", STAGE5_CHI_DEG, "DA2(10), spun stage 5 under IP(10) = 2 (adjustable parameter 9)")
    deck.number("payload_weighting_factor", block17["payload_weighting_factor"], "DA2(15)")
    deck.number("coast_change_limit_s", 30.0, "DA2(16)")
    deck.number("minimum_coast_s", 2.0, "DA2(17)")

    deck.blank()
    deck.comment("Data blocks 8, 19, 29: the payoff, then the Addendum H constraints at the end of coast 10.")
    deck.array_table("constraint", "block 8 IB3(2): payload (payoff)")
    deck.number("code", 0)
    for i, (code, unit, desired, optimization, linearization, name) in enumerate((
            (100, "ft_s", V_INFINITY_FT_S, 20.0, 5.0, "hyperbolic excess velocity"),
            (101, "deg", RIGHT_ASCENSION_DEG, 0.1, 0.02, "right ascension of the outward radial"),
            (102, "deg", DECLINATION_DEG, 0.1, 0.02, "declination of the outward radial"))):
        deck.array_table("constraint", "block 8 IB3(%d): %s" % (i + 3, name))
        deck.number("code", code)
        deck.number("desired_" + unit, desired, "block 19 DA4(%d)" % (i + 2))
        deck.number("deadband_optimization_" + unit, optimization, "block 29 DA14(%d)" % (i + 1))
        deck.number("deadband_linearization_" + unit, linearization, "block 29 DA14(%d)" % (i + 14))

    deck.blank()
    deck.comment("Data blocks 6 and 27: the adjustable parameters (weights as Sec. 22 recommends).")
    for code, weight, name in ((3, 1e-4, "length of coast after stage 3"), (7, 1e-6, "launch time of day"),
                               (8, 10.0, "stage 5 pitch angle (spun)"), (9, 10.0, "stage 5 yaw angle (spun)"),
                               (10, 1e-4, "length of coast after stage 4")):
        deck.array_table("adjustable_parameter", "block 6: %s" % name)
        deck.number("code", code)
        deck.number("weight", weight, "block 27 DA12(%d)" % code)

    tlin = mission["pitch_program_definition"]["tlin_block18"]
    coded = tlin[1:] + [400.0, 428.0]
    deck.table("linearization", "data blocks 18 (TLIN) and 26 (ETALIN: default 1.0 per segment)")
    deck.comment("the reference's segments and the continuous stage 4 (ignition, burnout); IP(7) = 0 here")
    deck.number("segment_count", len(coded) - 1, "TLIN(1)")
    deck.array("coded_times", coded, "TLIN(2..): 100 x stage + s from stage ignition")

    deck.table("convergence", "data block 28, DA13 (payoff units: lb)")
    deck.number("initial_payoff_improvement", 5.0, "DA13(1)")
    deck.number("stop_improvement", 0.25, "DA13(2)")
    deck.number("max_forward_trajectories", 60, "DA13(3)")
    deck.number("max_linearization_iterations", 4, "DA13(4)")

    deck.table("output_frequency", "data block 9, IB4: every computed point, all stages")
    deck.number("initial", 1)
    deck.number("intermediate", 1)
    deck.number("final", 1)

    deck.table("pitch_program", "data block 40, TTH: a crude program through stage 4 (held after 260 s)")
    deck.array("time_s", CRUDE_TIMES, "s from launch")
    deck.array("theta_deg", CRUDE_THETAS, "pitch attitude from the launch geodetic horizontal")
    return deck.render()


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--reference", default=scout.DEFAULT_REFERENCE, help="scout_reference.json")
    parser.add_argument("--out", default=DEFAULT_OUT, help="output folder (examples/escape)")
    args = parser.parse_args(argv)
    with open(args.reference, encoding="utf-8") as handle:
        ref = json.load(handle)
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "mission.toml")
    with open(path, "w", encoding="utf-8", newline="\n") as handle:
        handle.write(build(ref))
    print("wrote " + os.path.relpath(path, ROOT))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
