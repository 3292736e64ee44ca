#!/usr/bin/env python3
"""Generate the second bundled example, examples/strapon/mission.toml and five_elements.toml.

    python3 scripts/make_strapon_example.py [--out DIR]

A vehicle unlike the Scout-class one (docs/user-guide.md "A second example: strap-on boosters"):

* two strap-on boosters burning in parallel with a liquid core, modelled as two powered stages
  back to back (stage 1 = boosters + core, stage 2 = the core alone after the boosters drop; no
  coast between them, the boosters' cases jettisoned at the boundary);
* a short separation coast (7), then a steered upper stage (3) burning 99 s, more than twice
  the Scout's longest burn (45 s) and the longest data block 18 can break into segments (a break is
  coded 100 n + t, so only the first 99 s of a stage can hold one);
* an elliptic target orbit given by three orbit elements: perigee radius (80 n.mi. perigee
  altitude), twice the orbital energy (a 80 x 500 n.mi. orbit) and the inclination (40 deg from
  a 28.5 deg launch site, so the launch azimuth is adjusted);
* a spherical Earth without J2 (inverse flattening 0, J2 0; rotating);
* a crude initial pitch program of a few straight lines, of the kind a user writes first.

five_elements.toml is the same vehicle, site and crude start aimed at a five-element elliptic
target: the three elements above plus the longitude of the ascending node (code 12, 30 deg, reached
by adjusting the launch time of day, parameter 7, from the deck's 15:00 UT) and the argument of
perigee (code 13, 50 deg, about 3.4 deg before the 53.4 deg where the three-element optimum puts
its perigee: the in-plane shape of the ascent places it).

Every figure is illustrative, chosen to be plausible for a small 1960s launcher; none is the data
of a real vehicle. The thrust histories are constant with short ramps, the consumable weight the
exact integral of thrust / Isp over each table interval. Only the Python standard library is used;
the output is deterministic.
"""

import argparse
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_OUT = os.path.join(ROOT, "examples", "strapon")

NMI_FT = 6076.11549
EQUATORIAL_RADIUS_FT = 20925696.0
MU_FT3_S2 = 1.407735e16

# Engines (vacuum): thrust lbf, specific impulse s.
BOOSTER_THRUST_LBF = 66250.0   # each of two, 60 s
BOOSTER_ISP_S = 265.0
CORE_THRUST_LBF = 80000.0      # 150 s: 60 s with the boosters, 90 s alone
CORE_ISP_S = 300.0
UPPER_THRUST_LBF = 23333.33     # 99 s
UPPER_ISP_S = 330.0

TABLE_STEP_S = 5.0

PERIGEE_ALTITUDE_NMI = 80.0
APOGEE_ALTITUDE_NMI = 500.0

NODE_LONGITUDE_DEG = 30.0          # five_elements.toml: inertial, from the vernal equinox
ARGUMENT_OF_PERIGEE_DEG = 50.0     # five_elements.toml


def fmt(value):
    if isinstance(value, int):
        return str(value)
    return repr(float(value))


def array(values, per_line=8):
    items = [fmt(v) for v in values]
    if len(items) <= per_line:
        return "[" + ", ".join(items) + "]"
    lines = []
    for i in range(0, len(items), per_line):
        lines.append("  " + ", ".join(items[i:i + per_line]) + ",")
    return "[\n" + "\n".join(lines) + "\n]"


def thrust_profile(thrust_lbf, burn_s, ramp_up_s, tail_s):
    """Stage time and vacuum thrust: a ramp to full thrust, constant, a linear tail-off. The
    constant part is tabulated every TABLE_STEP_S: Sec. 14's ideal-velocity quadrature (Simpson per
    table interval of T/W, which is not linear) is then exact to 1e-7, so the re-tabulated thrust
    is the input's and does not depend on the payload the case starts from."""
    times = [0.0, ramp_up_s]
    t = ramp_up_s
    while t + TABLE_STEP_S < burn_s - tail_s - 1e-9:
        t = round(t + TABLE_STEP_S, 6)
        times.append(t)
    times += [burn_s - tail_s, burn_s]
    thrust = [0.0] + [thrust_lbf] * (len(times) - 2) + [0.0]
    return times, thrust


def remaining_weight(times, thrust, isp_by_interval, propellant_lb):
    """Consumable weight remaining: the exact integral of the piecewise-linear weight flow T / Isp."""
    remaining = [propellant_lb]
    for k in range(1, len(times)):
        flow = 0.5 * (thrust[k - 1] + thrust[k]) / isp_by_interval[k - 1]
        remaining.append(remaining[-1] - flow * (times[k] - times[k - 1]))
    # The tables must end at zero: the propellant is what the thrust burns.
    return [round(w, 6) if abs(w) > 1e-6 else 0.0 for w in remaining]


def stage_tables():
    # Stage 1: two boosters and the core together for 60 s. The mixture's Isp is the
    # thrust-weighted harmonic mean (weight flows add).
    b_flow = 2 * BOOSTER_THRUST_LBF / BOOSTER_ISP_S
    c_flow = CORE_THRUST_LBF / CORE_ISP_S
    s1_thrust = 2 * BOOSTER_THRUST_LBF + CORE_THRUST_LBF
    s1_isp = s1_thrust / (b_flow + c_flow)
    t1, f1 = thrust_profile(s1_thrust, 60.0, 0.5, 1.0)
    # The boosters tail off in the last second; the core keeps full thrust into stage 2.
    f1[-1] = CORE_THRUST_LBF
    tail_isp = (BOOSTER_THRUST_LBF * 2 + 2 * CORE_THRUST_LBF) / (
        2 * BOOSTER_THRUST_LBF / BOOSTER_ISP_S + 2 * CORE_THRUST_LBF / CORE_ISP_S)
    isp1 = [s1_isp] * (len(t1) - 2) + [tail_isp]
    # Propellant burned in stage 1 (boosters all, core 60 s of its 150), computed from the profile.
    burned1 = 0.0
    for k in range(1, len(t1)):
        burned1 += 0.5 * (f1[k - 1] + f1[k]) / isp1[k - 1] * (t1[k] - t1[k - 1])
    w1 = remaining_weight(t1, f1, isp1, burned1)
    t2 = [float(t) for t in range(0, 90, 5)] + [88.0, 90.0]
    f2 = [CORE_THRUST_LBF] * (len(t2) - 1) + [0.0]
    burned2 = sum(0.5 * (f2[k - 1] + f2[k]) / CORE_ISP_S * (t2[k] - t2[k - 1]) for k in range(1, len(t2)))
    w2 = remaining_weight(t2, f2, [CORE_ISP_S] * (len(t2) - 1), burned2)
    t3, f3 = thrust_profile(UPPER_THRUST_LBF, 99.0, 0.5, 2.0)
    burned3 = sum(0.5 * (f3[k - 1] + f3[k]) / UPPER_ISP_S * (t3[k] - t3[k - 1]) for k in range(1, len(t3)))
    w3 = remaining_weight(t3, f3, [UPPER_ISP_S] * (len(t3) - 1), burned3)
    return (t1, f1, w1, burned1), (t2, f2, w2, burned2), (t3, f3, w3, burned3)


def orbit_targets():
    rp = EQUATORIAL_RADIUS_FT + PERIGEE_ALTITUDE_NMI * NMI_FT
    ra = EQUATORIAL_RADIUS_FT + APOGEE_ALTITUDE_NMI * NMI_FT
    a = 0.5 * (rp + ra)
    return rp, -MU_FT3_S2 / a


def w_stage(w, code, name, note, settings, tables, drag=None):
    """Writes a powered stage's data block 16 entries through `w`: its name, a comment line
    `note`, the `settings` lines as given, the thrust and consumable weight tables of `tables`
    (times, thrust, remaining weight) and, when given, the drag table (its mach and cd lines)."""
    times, thrust, remaining = tables
    w("[stage.%d]" % code)
    w('name = "%s"' % name)
    w("# " + note)
    for line in settings:
        w(line)
    w("")
    w("[stage.%d.thrust]" % code)
    w("time_s = " + array(times))
    w("vacuum_thrust_lbf = " + array(thrust))
    w("")
    w("[stage.%d.consumable_weight]" % code)
    w("time_s = " + array(times))
    w("remaining_lb = " + array(remaining))
    w("")
    if drag is not None:
        w("[stage.%d.drag]  # C_D at alpha = 0, referenced to stage %d area" % (code, code))
        for line in drag:
            w(line)
        w("")


def deck(five_elements=False):
    (t1, f1, w1, p1), (t2, f2, w2, p2), (t3, f3, w3, p3) = stage_tables()
    rp, two_e = orbit_targets()
    out = []
    w = out.append
    w("# TOLIP case deck (TOML; format: docs/deck-format.md).")
    w("# GENERATED by scripts/make_strapon_example.py; edit the generator, not this file.")
    w("#")
    w("# Illustrative strap-on launcher (not the data of any real vehicle): two boosters burning in")
    w("# parallel with a liquid core (stages 1 and 2 back to back, no coast between them), a short")
    w("# separation coast and a long steered upper stage; an elliptic 80 x 500 n.mi. orbit at 40 deg")
    if five_elements:
        w("# inclination, its node at 30 deg and its perigee 50 deg from the node: five orbit elements;")
        w("# a spherical, J2-free, rotating Earth. Launch time and azimuth are adjusted. The optimization")
    else:
        w("# inclination given by its orbit elements; a spherical, J2-free, rotating Earth. The optimization")
    w("# starts from a crude pitch program of four straight lines. docs/user-guide.md describes the case.")
    w("")
    w("[case]")
    if five_elements:
        w('title = "STRAP-ON LAUNCHER (ILLUSTRATIVE), FIVE ORBIT ELEMENTS"')
        w('heading = "80 X 500 NMI, I 40, NODE 30, PERIGEE 50 DEG FROM A CRUDE PROGRAM"')
    else:
        w('title = "STRAP-ON LAUNCHER (ILLUSTRATIVE), 80 X 500 NMI AT 40 DEG"')
        w('heading = "MAXIMUM PAYLOAD FROM A CRUDE FOUR-LINE PITCH PROGRAM"')
    w('date = "2026-12-01"')
    w("")
    w("[options]  # data block 4, IP(n)")
    w("payoff = 0                                   # IP(1) maximum payload")
    w("linearization = true                         # IP(7): the optimum as straight segments (flown back by simulate)")
    w("zero_alpha_window = true                     # IP(11): alpha = 0 through maximum dynamic pressure")
    w("")
    w("[constants]  # data block 10: the manual's values, but a sphere without J2")
    w("inverse_flattening = 0.0                     # CT1(12): 0 = spherical Earth")
    w("j2 = 0.0                                     # CT1(11)")
    w("")
    w("[vehicle]")
    w("sequence = [1, 2, 7, 3]                      # boosters+core, core alone (back to back), coast, upper stage")
    w("payload_lb = 1000.0                          # initial guess; the payoff")
    w("")
    w_stage(w, 1, "two strap-on solid boosters and the liquid core, in parallel",
            "boosters %.0f lbf each at Isp %.0f s, core %.0f lbf at Isp %.0f s (vacuum); propellant burned %.1f lb"
            % (BOOSTER_THRUST_LBF, BOOSTER_ISP_S, CORE_THRUST_LBF, CORE_ISP_S, p1),
            ["duration_s = 60.0",
             "integration_steps = 40",
             "jettison_weight_lb = 3600.0                  # the two booster cases, dropped at 60 s",
             "reference_area_ft2 = 75.4                    # core 8 ft and two 4 ft boosters",
             "nozzle_exit_area_ft2 = 17.0"],
            (t1, f1, w1),
            ("mach = [0.0, 0.6, 0.8, 0.9, 1.0, 1.1, 1.2, 1.5, 2.0, 3.0, 4.0, 6.0, 10.0]",
             "cd = [0.42, 0.42, 0.45, 0.52, 0.68, 0.78, 0.78, 0.72, 0.62, 0.50, 0.44, 0.38, 0.35]"))
    w_stage(w, 2, "liquid core alone after booster separation",
            "core %.0f lbf at Isp %.0f s; propellant %.1f lb" % (CORE_THRUST_LBF, CORE_ISP_S, p2),
            ["duration_s = 90.0",
             "integration_steps = 45",
             "jettison_weight_lb = 4000.0                  # core tanks and engine, interstage, payload fairing",
             "reference_area_ft2 = 50.27                   # 8 ft core",
             "nozzle_exit_area_ft2 = 7.0"],
            (t2, f2, w2),
            ("mach = [0.0, 0.8, 1.0, 1.2, 1.5, 2.0, 3.0, 4.0, 6.0, 10.0]",
             "cd = [0.30, 0.33, 0.50, 0.60, 0.56, 0.47, 0.38, 0.33, 0.28, 0.25]"))
    w("[stage.7]")
    w("# separation coast before the upper stage; above the sensible atmosphere, no aerodynamic tables")
    w("duration_s = 6.0")
    w("integration_steps = 3")
    w("")
    w_stage(w, 3, "long-burning upper stage (steered)",
            "%.2f lbf at Isp %.0f s for 99 s; propellant %.1f lb; the payload is added to its jettison weight"
            % (UPPER_THRUST_LBF, UPPER_ISP_S, p3),
            ["duration_s = 99.0",
             "integration_steps = 40",
             "jettison_weight_lb = 900.0",
             "reference_area_ft2 = 50.27",
             "nozzle_exit_area_ft2 = 3.0"],
            (t3, f3, w3))
    w("[launch]")
    w("# an illustrative site at 28.5 deg (on a sphere geodetic = geocentric)")
    w("liftoff_duration_s = 4.0")
    w("space_age_date_days = 2373.625")
    w("altitude_ft = 10.0")
    w("longitude_deg = -80.6")
    w("geocentric_latitude_deg = 28.5")
    w("velocity_ft_s = 0.0")
    w("azimuth_deg = 55.0                           # crude guess; adjusted (40 deg needs about 60.7)")
    w("flight_path_angle_deg = 90.0")
    w("heading_hold_until_s = 6.0")
    w("")
    w("[control_constraints]  # data block 22: the window starts and ends on integration points (4 s + k 1.4 s)")
    w("zero_alpha_start_s = 12.4")
    w("zero_alpha_end_s = 54.4")
    w("max_pitch_rate_deg_s = 3.0")
    w("min_pitch_rate_deg_s = 0.02")
    w("min_pitch_rate_change_deg_s = 0.02")
    w("")
    w("[misc]  # data block 17")
    w("payload_weighting_factor = 1.0")
    w("")
    w("[[constraint]]  # payoff")
    w("code = 0")
    w("")
    w("[[constraint]]  # perigee radius: 80 n.mi. perigee altitude")
    w("code = 11")
    w("desired_ft = " + fmt(round(rp, 3)))
    w("deadband_optimization_ft = 20000.0")
    w("deadband_linearization_ft = 5000.0")
    w("")
    w("[[constraint]]  # twice the orbital energy, -mu / a of the 80 x 500 n.mi. orbit")
    w("code = 9")
    w("desired_ft2_s2 = " + fmt(round(two_e, 1)))
    w("deadband_optimization_ft2_s2 = 1000000.0     # about 20 ft/s of perigee velocity")
    w("deadband_linearization_ft2_s2 = 250000.0")
    w("")
    w("[[constraint]]  # inclination")
    w("code = 10")
    w("desired_deg = 40.0")
    w("deadband_optimization_deg = 0.2")
    w("deadband_linearization_deg = 0.05")
    w("")
    if five_elements:
        w("[[constraint]]  # longitude of the ascending node (inertial); the launch time places it")
        w("code = 12")
        w("desired_deg = " + fmt(NODE_LONGITUDE_DEG))
        w("deadband_optimization_deg = 0.2")
        w("deadband_linearization_deg = 0.05")
        w("")
        w("[[constraint]]  # argument of perigee; the in-plane shape of the ascent places it")
        w("code = 13")
        w("desired_deg = " + fmt(ARGUMENT_OF_PERIGEE_DEG))
        w("deadband_optimization_deg = 0.5")
        w("deadband_linearization_deg = 0.2")
        w("")
        w("[[adjustable_parameter]]  # launch time of day (the deck's 15:00 UT gives a node near 28 deg)")
        w("code = 7")
        w("weight = 1e-06                               # the manual's recommendation (data block 27)")
        w("")
    w("[[adjustable_parameter]]  # launch azimuth")
    w("code = 6")
    w("weight = 2.0")
    w("")
    w("[linearization]  # data block 18: 100 x stage + s from ignition")
    w("# lift-off end, the zero-alpha window, the rest of stage 1, stage 2 in three, the coast (implicit), stage 3 in three.")
    w("# A break is coded 100 n + t, so a stage can have breaks in its first 99 s only: stage 3 burns 99 s.")
    w("coded_times = [104.0, 112.4, 154.4, 200.0, 230.0, 260.0, 290.0, 300.0, 333.0, 366.0, 399.0]")
    w("")
    w("[convergence]  # data block 28 (lb)")
    w("initial_payoff_improvement = 75.0")
    w("stop_improvement = 1.0")
    w("max_forward_trajectories = 120")
    w("max_linearization_iterations = 4")
    w("")
    w("[pitch_program]  # data block 40: a crude program of four straight lines")
    w("time_s = [0.0, 4.0, 12.0, 150.0, 255.0]")
    w("theta_deg = [90.0, 90.0, 84.0, 30.0, 0.0]")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=DEFAULT_OUT)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "mission.toml"), "w", newline="\n") as f:
        f.write(deck())
    with open(os.path.join(args.out, "five_elements.toml"), "w", newline="\n") as f:
        f.write(deck(five_elements=True))


if __name__ == "__main__":
    main()
