#!/usr/bin/env python3
"""Independent reference data for unclamped and periodic B-spline and NURBS curves: values and
derivatives computed by scipy.interpolate.BSpline (scipy 1.17.1), periodic ones with
extrapolate="periodic", the domain end included (where scipy wraps to the start).

How to run (from the workspace root, with scipy in the environment, e.g. .venv-py):

    .venv-py/bin/python scripts/reference/make_knot_kinds_reference.py

Deterministic (fixed seed, Python's `random`). Written to
`crates/neutrospline/tests/data/knot_kinds_scipy.json`: for each curve its kind (`uniform`:
knots (i - p) / (n - p), `unclamped`: random non-decreasing knots, `periodic`: breakpoints),
degree, knots (the whole vector, made here from the definition in docs/model.md "Knot vectors"
and not by the library), the control rows `[x, y, truth, indeterminacy, falsity]` (for periodic
curves only the distinct ones), NURBS weights, and at the parameters `t` (both domain ends,
random interior ones) the rows of the curve, its first and its second derivative. NURBS
values come from the homogeneous B-spline `(w x, w y, w T, w I, w F, w)` by the quotient rule.
Doubles are written with Python's repr.
"""

import json
import os
import random

import numpy as np
from scipy.interpolate import BSpline

random.seed(20261204)
OUT = os.path.join(os.path.dirname(__file__), "..", "..", "crates", "neutrospline", "tests",
                   "data", "knot_kinds_scipy.json")


def rows(n):
    return [[random.uniform(-3, 3), random.uniform(-3, 3), random.random(), random.random(),
             random.random()] for _ in range(n)]


def periodic_knots(p, breakpoints):
    n = len(breakpoints) - 1
    period = breakpoints[n] - breakpoints[0]
    knots = []
    for i in range(n + 2 * p + 1):
        j = i - p
        if 0 <= j <= n:
            knots.append(breakpoints[j])
        else:
            knots.append(breakpoints[j % n] + (j // n) * period)
    return knots


def evaluate(knots, p, ctrl, weights, ts, extrapolate):
    c = np.array(ctrl, dtype=float)
    if weights is None:
        spline = BSpline(np.array(knots), c, p, extrapolate=extrapolate)
        return [spline(ts, nu).tolist() for nu in (0, 1, 2)]
    w = np.array(weights, dtype=float)
    homogeneous = np.hstack([c * w[:, None], w[:, None]])
    spline = BSpline(np.array(knots), homogeneous, p, extrapolate=extrapolate)
    a0, a1, a2 = (spline(ts, nu) for nu in (0, 1, 2))
    W0, W1, W2 = a0[:, -1:], a1[:, -1:], a2[:, -1:]
    A0, A1, A2 = a0[:, :-1], a1[:, :-1], a2[:, :-1]
    C0 = A0 / W0
    C1 = (A1 - W1 * C0) / W0
    C2 = (A2 - 2 * W1 * C1 - W2 * C0) / W0
    return [C0.tolist(), C1.tolist(), C2.tolist()]


cases = []
for index in range(18):
    kind = ["uniform", "unclamped", "periodic"][index % 3]
    p = random.randint(1, 5)
    rational = index % 2 == 1
    if kind == "periodic":
        n = random.randint(max(p, 2), p + 6)
        inner = sorted(random.uniform(0, 1) for _ in range(n - 1))
        start = random.uniform(-2, 2)
        scale = random.uniform(0.5, 4)
        breakpoints = [start] + [start + scale * x for x in inner] + [start + scale]
        if index == 2:
            breakpoints[2] = breakpoints[1]  # a repeated breakpoint
        knots = periodic_knots(p, breakpoints)
        distinct = rows(n)
        ctrl = [distinct[i % n] for i in range(n + p)]
        w_distinct = [random.uniform(0.3, 3) for _ in range(n)] if rational else None
        weights = [w_distinct[i % n] for i in range(n + p)] if rational else None
        extrapolate = "periodic"
    else:
        n = random.randint(p + 1, p + 7)
        if kind == "uniform":
            knots = [(i - p) / (n - p) for i in range(n + p + 1)]
        else:
            knots = sorted(random.uniform(-1, 2) for _ in range(n + p + 1))
        distinct = rows(n)
        ctrl = distinct
        w_distinct = [random.uniform(0.3, 3) for _ in range(n)] if rational else None
        weights = w_distinct
        breakpoints = None
        extrapolate = False
    a, b = knots[p], knots[len(knots) - 1 - p]
    ts = [a, b] + sorted(random.uniform(a, b) for _ in range(9)) + knots[p + 1:len(knots) - 1 - p]
    ts = [t for t in ts if a <= t <= b]
    values, d1, d2 = evaluate(knots, p, ctrl, weights, np.array(ts), extrapolate)
    cases.append({
        "kind": kind,
        "rational": rational,
        "degree": p,
        "knots": knots,
        "breakpoints": breakpoints,
        "rows": distinct,
        "weights": w_distinct,
        "t": ts,
        "values": values,
        "d1": d1,
        "d2": d2,
    })

with open(OUT, "w") as f:
    json.dump({"generator": "scipy " + __import__("scipy").__version__, "cases": cases}, f,
              indent=1)
    f.write("\n")
print(f"wrote {len(cases)} cases to {os.path.normpath(OUT)}")
