#!/usr/bin/env python3
"""Compares the flight demo's output on the host and on the Cortex-M7 (under QEMU).

  compare_outputs.py exec HOST TARGET
      Every line that is not a "TRAJ " or "TARGET " line (the executor, loader and control-law
      lines) must be byte-for-byte identical, in the same order.

  compare_outputs.py traj HOST TARGET [--relative R]
      The "TRAJ " lines must name the same quantities in the same order; each value (read from its
      exact IEEE-754 bit pattern, the last token) must agree within R relative:
      |target - host| <= R * max(|host|, 1). The largest difference found is printed.

  compare_outputs.py opt HOST TARGET [--payoff-relative P] [--state-relative S]
      The "OPT " lines (the reference optimization) must have the same structure in the same
      order. Lines without a bit pattern (status, converged, forward/backward run counts, the kind
      and success of every forward run, parameter and constraint codes, point and stage counts of
      the final trajectory) must be identical. Values named "final_*" (the final trajectory's
      burnout: time, state, weight) must agree within S relative, the others (payload,
      payoff, corrected payoff, per-run payloads, adjustable parameters, constraint values) within
      P relative, both as |target - host| <= R * max(|host|, 1).
"""
import argparse
import struct
import sys


def read_lines(path):
    with open(path, "rb") as f:
        return f.read().split(b"\n")


def exec_lines(lines):
    return [l for l in lines if not l.startswith((b"TRAJ ", b"TARGET ", b"OPT "))]


def compare_exec(host, target):
    h = exec_lines(read_lines(host))
    t = exec_lines(read_lines(target))
    if not any(l.startswith(b"EXEC t=") for l in h):
        print("FAIL: the host output has no executor lines")
        return 1
    for i, (a, b) in enumerate(zip(h, t)):
        if a != b:
            print(f"FAIL: line {i + 1} differs\n  host:   {a.decode(errors='replace')}\n  target: {b.decode(errors='replace')}")
            return 1
    if len(h) != len(t):
        print(f"FAIL: {len(h)} host lines, {len(t)} target lines")
        return 1
    cycles = [l for l in h if l.startswith(b"EXEC cycles")]
    print(f"OK: {len(h)} executor/loader lines identical byte for byte"
          + (f"; {cycles[0].decode()}" if cycles else ""))
    return 0


def traj_values(lines, prefix=b"TRAJ "):
    values = []
    for l in lines:
        if not l.startswith(prefix):
            continue
        tokens = l.decode().split()
        if len(tokens) == 4 and len(tokens[3]) == 16:
            bits = int(tokens[3], 16)
            values.append((tokens[1], struct.unpack("<d", struct.pack("<Q", bits))[0]))
        else:
            values.append((l.decode(), None))
    return values


def compare_traj(host, target, relative):
    h = traj_values(read_lines(host))
    t = traj_values(read_lines(target))
    numeric = [v for v in h if v[1] is not None]
    if len(numeric) < 10:
        print("FAIL: the host output has too few trajectory values")
        return 1
    if len(h) != len(t):
        print(f"FAIL: {len(h)} host TRAJ lines, {len(t)} target TRAJ lines")
        return 1
    worst = (0.0, "")
    identical = 0
    for (name_h, a), (name_t, b) in zip(h, t):
        if name_h != name_t:
            print(f"FAIL: host line '{name_h}' vs target line '{name_t}'")
            return 1
        if a is None:
            continue
        diff = abs(b - a) / max(abs(a), 1.0)
        identical += a == b
        if diff > worst[0]:
            worst = (diff, name_h)
        if not diff <= relative:
            print(f"FAIL: {name_h}: host {a!r}, target {b!r}, relative difference {diff:.3e} > {relative:g}")
            return 1
    print(f"OK: {len(numeric)} trajectory values within {relative:g} relative; "
          f"{identical} bit-identical; largest difference {worst[0]:.3e} ({worst[1] or 'none'})")
    return 0


def compare_opt(host, target, payoff_relative, state_relative):
    h = traj_values(read_lines(host), b"OPT ")
    t = traj_values(read_lines(target), b"OPT ")
    names = [v[0] for v in h if v[1] is not None]
    for required in ("payload_lb", "final_velocity_ft_s"):
        if required not in names:
            print(f"FAIL: the host output has no OPT {required} value")
            return 1
    if not any(v[1] is None and v[0].startswith("OPT converged ") for v in h):
        print("FAIL: the host output has no 'OPT converged' line")
        return 1
    if len(h) != len(t):
        print(f"FAIL: {len(h)} host OPT lines, {len(t)} target OPT lines")
        return 1
    worst = {"payoff": (0.0, ""), "state": (0.0, "")}
    counts = {"payoff": 0, "state": 0}
    identical = 0
    payload = None
    for (name_h, a), (name_t, b) in zip(h, t):
        if name_h != name_t:
            print(f"FAIL: host line '{name_h}' vs target line '{name_t}'")
            return 1
        if a is None:
            continue
        kind = "state" if name_h.startswith("final_") else "payoff"
        limit = state_relative if kind == "state" else payoff_relative
        diff = abs(b - a) / max(abs(a), 1.0)
        identical += a == b
        counts[kind] += 1
        if name_h == "payload_lb":
            payload = (a, b, diff)
        if diff > worst[kind][0]:
            worst[kind] = (diff, name_h)
        if not diff <= limit:
            print(f"FAIL: {name_h}: host {a!r}, target {b!r}, relative difference {diff:.3e} > {limit:g}")
            return 1
    runs = next(v[0] for v in h if v[1] is None and v[0].startswith("OPT converged "))
    print(f"OK: {runs[4:]} (identical on host and target)")
    print(f"OK: payload host {payload[0]!r} lb, target {payload[1]!r} lb, relative difference {payload[2]:.3e}")
    print(f"OK: {counts['payoff']} payoff/parameter values within {payoff_relative:g} relative, largest "
          f"difference {worst['payoff'][0]:.3e} ({worst['payoff'][1] or 'none'}); {counts['state']} final "
          f"burnout values within {state_relative:g}, largest {worst['state'][0]:.3e} "
          f"({worst['state'][1] or 'none'}); {identical} of {counts['payoff'] + counts['state']} bit-identical")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["exec", "traj", "opt"])
    parser.add_argument("host")
    parser.add_argument("target")
    parser.add_argument("--relative", type=float, default=1e-9)
    parser.add_argument("--payoff-relative", type=float, default=1e-6)
    parser.add_argument("--state-relative", type=float, default=1e-9)
    args = parser.parse_args()
    if args.mode == "exec":
        return compare_exec(args.host, args.target)
    if args.mode == "opt":
        return compare_opt(args.host, args.target, args.payoff_relative, args.state_relative)
    return compare_traj(args.host, args.target, args.relative)


if __name__ == "__main__":
    sys.exit(main())
