#!/usr/bin/env python3
"""An independent check of the strap-on example's optimum payload: a direct method.

    python3 scripts/check_strapon_direct.py [--tolip build/ground_tools/tolip] [--deck examples/strapon/mission.toml]

Nothing of the optimizer (adjoints, steering law, Sec. 22 sequence) is used: only `tolip simulate`
as the model. The pitch program is the deck's own data block 40 table with nodes at fixed times
(NODE_TIMES; 90 deg to the end of the lift-off, the zero-alpha window flown as the deck says);
the unknowns are the node attitudes after the lift-off, the launch azimuth and the payload; the
problem is to maximize the payload with every data block 8 constraint at its desired value. It is
solved by Rosen's gradient projection with Newton restoration, all derivatives by forward
differences of `simulate` runs:

* restoration: x += -J^T (J J^T)^-1 c (c the constraint errors in deadbands) until max |c| <= 0.05;
* an ascent step: x += alpha P e_payload, P = I - J^T (J J^T)^-1 J, then restoration; the step is
  accepted when the restored point carries more payload, and alpha grows by 1.5, else it halves;
* it stops when alpha has halved below ALPHA_MIN.

Prints the payload found, the constraint errors and the number of simulate runs. The figures are in
docs/verification.md ("The second example"). Only the Python standard library is used.
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Node times (s from launch): the end of the lift-off (fixed, 90 deg), the window's start and end,
# staging at 60 s, stage 2 every 30 s, the coast, stage 3 every ~25 s to burnout at 255 s.
NODE_TIMES = [0.0, 4.0, 12.4, 54.4, 60.0, 90.0, 120.0, 150.0, 156.0, 180.0, 205.0, 230.0, 255.0]
FIXED_NODES = 2          # 0 s and 4 s stay at 90 deg
PAYLOAD_UNIT_LB = 10.0   # the variable metric: 1 deg of pitch ~ 10 lb of payload
ALPHA_MIN = 0.02
FD_STEP = 1e-3           # forward-difference step in the scaled variables


class Model:
    def __init__(self, tolip, deck):
        self.tolip = tolip
        with open(deck) as f:
            self.text = f.read()
        self.runs = 0
        self.dir = tempfile.mkdtemp(prefix="strapon_direct_")
        self.cache = {}

    def deck_for(self, x):
        thetas = [90.0] * FIXED_NODES + list(x[:len(NODE_TIMES) - FIXED_NODES])
        azimuth = x[-2]
        payload = x[-1] * PAYLOAD_UNIT_LB
        text = self.text
        head = text[:text.index("[pitch_program]")]
        head = replace_value(head, "payload_lb = ", payload)
        head = replace_value(head, "azimuth_deg = ", azimuth)
        table = "[pitch_program]\ntime_s = [%s]\ntheta_deg = [%s]\n" % (
            ", ".join(repr(t) for t in NODE_TIMES), ", ".join(repr(v) for v in thetas))
        return head + table

    def evaluate(self, x):
        key = tuple(x)
        if key in self.cache:
            return self.cache[key]
        path = os.path.join(self.dir, "case.toml")
        with open(path, "w") as f:
            f.write(self.deck_for(x))
        self.runs += 1
        run = subprocess.run([self.tolip, "simulate", path, "--json"], capture_output=True, text=True)
        document = json.loads(run.stdout)
        if document["status"] != "kOk":
            result = None
        else:
            result = [c["error"] / c["tolerance"] for c in document["constraints"]]
        self.cache[key] = result
        return result

    def jacobian(self, x, c):
        columns = []
        for j in range(len(x)):
            y = list(x)
            y[j] += FD_STEP
            cy = self.evaluate(y)
            columns.append([(a - b) / FD_STEP for a, b in zip(cy, c)])
        return [[columns[j][i] for j in range(len(x))] for i in range(len(c))]  # rows: constraints


def replace_value(text, key, value):
    at = text.index(key) + len(key)
    end = at
    while text[end] not in " \n#":
        end += 1
    return text[:at] + repr(float(value)) + text[end:]


def solve(a, b):
    """Gaussian elimination with partial pivoting (a small dense system)."""
    n = len(b)
    m = [list(row) + [b[i]] for i, row in enumerate(a)]
    for k in range(n):
        p = max(range(k, n), key=lambda i: abs(m[i][k]))
        m[k], m[p] = m[p], m[k]
        for i in range(k + 1, n):
            f = m[i][k] / m[k][k]
            for j in range(k, n + 1):
                m[i][j] -= f * m[k][j]
    x = [0.0] * n
    for i in reversed(range(n)):
        x[i] = (m[i][n] - sum(m[i][j] * x[j] for j in range(i + 1, n))) / m[i][i]
    return x


def min_norm(jac, rhs):
    """dx with J dx = rhs and the least |dx|: J^T (J J^T)^-1 rhs."""
    jjt = [[sum(a * b for a, b in zip(ri, rj)) for rj in jac] for ri in jac]
    y = solve(jjt, rhs)
    return [sum(jac[i][j] * y[i] for i in range(len(jac))) for j in range(len(jac[0]))]


def restore(model, x, jac, tolerance=0.05, iterations=6):
    """Newton restoration onto the constraints, the Jacobian refreshed on each iteration."""
    for _ in range(iterations):
        c = model.evaluate(x)
        if c is None:
            return None, None
        if max(abs(v) for v in c) <= tolerance:
            return x, c
        if jac is None:
            jac = model.jacobian(x, c)
        dx = min_norm(jac, [-v for v in c])
        x = [a + b for a, b in zip(x, dx)]
        jac = None
    c = model.evaluate(x)
    if c is not None and max(abs(v) for v in c) <= tolerance:
        return x, c
    return None, None


def crude_start(text):
    """The deck's own crude program sampled at the nodes, its azimuth and payload."""
    table = text[text.index("[pitch_program]"):]
    times = eval(table.split("time_s = ")[1].split("\n")[0])
    thetas = eval(table.split("theta_deg = ")[1].split("\n")[0])

    def at(t):
        for k in range(len(times) - 1):
            if times[k] <= t <= times[k + 1]:
                f = (t - times[k]) / (times[k + 1] - times[k])
                return thetas[k] + f * (thetas[k + 1] - thetas[k])
        return thetas[-1]

    azimuth = float(text.split("azimuth_deg = ")[1].split()[0])
    payload = float(text.split("payload_lb = ")[1].split()[0])
    return [at(t) for t in NODE_TIMES[FIXED_NODES:]] + [azimuth, payload / PAYLOAD_UNIT_LB]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tolip", default=os.path.join(ROOT, "build", "ground_tools", "tolip"))
    parser.add_argument("--deck", default=os.path.join(ROOT, "examples", "strapon", "mission.toml"))
    args = parser.parse_args()
    model = Model(args.tolip, args.deck)
    x, c = restore(model, crude_start(model.text), None, iterations=15)
    if x is None:
        print("restoration from the crude start failed", file=sys.stderr)
        return 1
    alpha = 1.0
    while alpha >= ALPHA_MIN:
        jac = model.jacobian(x, c)
        # P e_payload: the payload direction minus its part the constraints see.
        e = [0.0] * len(x)
        e[-1] = 1.0
        normal = min_norm(jac, [row[-1] for row in jac])
        direction = [a - b for a, b in zip(e, normal)]
        trial = [a + alpha * d for a, d in zip(x, direction)]
        restored, cr = restore(model, trial, jac)
        if restored is not None and restored[-1] > x[-1]:
            x, c = restored, cr
            alpha *= 1.5
        else:
            alpha *= 0.5
    print("payload_lb %.3f" % (x[-1] * PAYLOAD_UNIT_LB))
    print("azimuth_deg %.4f" % x[-2])
    print("constraint_errors_deadbands " + " ".join("%.4f" % v for v in c))
    print("simulate_runs %d" % model.runs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
