#!/usr/bin/env python3
"""The `bezier` package's column of the accuracy table (docs/correctness.md, README): its
scaled error on the Bézier curves of crates/neutrospline/tests/data/accuracy.json (degrees 100,
400, 2000; exact values from mpmath at 50 digits, stored as double-doubles), measured the
same way as ours and scipy's: max over the parameters of |value - exact| / max_i |c_i|, worst
channel of x, y, truth, indeterminacy, falsity. `bezier.Curve.evaluate_multi` evaluates each
channel as a 1-D curve (its nodes are a (dimension, n) array, so the five channels are one
5-D curve).

How to run (from the workspace root, with numpy and bezier 2024.6.20, e.g. .venv-py):

    .venv-py/bin/python scripts/reference/bezier_package_accuracy.py
"""

import json
import os

import bezier
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "crates", "neutrospline", "tests", "data", "accuracy.json")

data = json.load(open(DATA))
scale_exponent = data["scale_exponent"]
sets = {s["degree"]: s for s in data["sets"]}
print(f"bezier {bezier.__version__}")
for case in data["cases"]:
    if case["kind"] != "bezier":
        continue
    p = case["degree"]
    rows = np.array(sets[p]["rows"][: (p + 1) * 5], dtype=float).reshape(p + 1, 5) * 2.0**scale_exponent
    curve = bezier.Curve(np.asfortranarray(rows.T), degree=p)
    ts = np.array([float(t) for t in case["parameters"]])
    values = curve.evaluate_multi(ts).T
    scale = np.abs(rows).max(axis=0)
    worst = 0.0
    for v, exact in zip(values, case["exact"]):
        for ch in range(5):
            hi, lo = (float(x) for x in exact[ch])
            worst = max(worst, abs((v[ch] - hi) - lo) / scale[ch])
    print(f"Bezier degree {p:5}: bezier scaled error {worst:.1e}")
