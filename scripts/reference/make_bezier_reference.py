#!/usr/bin/env python3
"""Independent reference data for the neutrospline Bezier evaluator.

How to run (from the workspace root, /work/main):

    python3 -m venv /tmp/venv-ref \
      && /tmp/venv-ref/bin/pip install numpy mpmath \
      && /tmp/venv-ref/bin/python scripts/reference/make_bezier_reference.py

The output is deterministic (fixed seeds, Python's `random` module whose
`random()` stream is guaranteed stable across Python versions) and is written to
`crates/neutrospline/tests/data/`:

  example1.json          the paper's Example 1 (docs/model.md section 5, Table 1 data: C3
                         indeterminacy 0.4), evaluated EXACTLY with
                         fractions.Fraction.
  bezier_random.json     random 2-D / 3-D curves of degree 1 .. 400, evaluated
                         with mpmath at 60 significant digits.
  bezier_degree2000.json one 2-D curve of degree 2000 (mpmath, 60 digits).

Method (deliberately different from the Rust core, which uses de Casteljau):
the explicit Bernstein sum

    C(t) = sum_i C(n,i) t^i (1-t)^(n-i) P_i

with exact integer binomials (Python ints), on the exact values of the double
inputs (mpmath.mpf(float) and Fraction(float) are exact).  The first derivative
is the hodograph

    C'(t) = n * sum_i B_{n-1,i}(t) (P_{i+1} - P_i)

summed the same way.  Every degree channel (truth, indeterminacy, falsity) is
blended exactly like a coordinate (docs/model.md section 4).  Results are rounded to the
nearest double (through an exact Fraction, not mpmath's float(), which
truncates) and written with Python's repr, which round-trips.

As a sanity check, the script also evaluates every case with a plain float64
de Casteljau in numpy and asserts it agrees with the reference within the
tolerances the Rust tests use (documented in README.md next to this file).
"""

import json
import math
import os
import random
import sys
from fractions import Fraction

import mpmath
import numpy as np
from mpmath import mp, mpf

mp.dps = 60

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT_DIR = os.path.join(ROOT, "crates", "neutrospline", "tests", "data")

DEGREE_NAMES = ("truth", "indeterminacy", "falsity")

# Tolerances used by crates/neutrospline/tests/integration/reference.rs (kept in sync by hand).
REL_TOL = 1e-12  # values: relative to the largest |control coordinate|; degrees: absolute
REL_TOL_2000 = 1e-11


# --------------------------------------------------------------------------- helpers


def mpf_to_fraction(x):
    """Exact value of an mpf as a Fraction."""
    sign, man, exp, _bc = x._mpf_
    if man == 0:
        if exp != 0:  # inf / nan encodings
            raise ValueError("non-finite mpf %r" % (x,))
        return Fraction(0)
    v = Fraction(man) * (Fraction(2) ** exp)
    return -v if sign else v


def to_double(x):
    """Correctly rounded (nearest, ties to even) double of an mpf or Fraction."""
    if isinstance(x, Fraction):
        return float(x)  # Fraction.__float__ is correctly rounded
    return float(mpf_to_fraction(x))


def frac_str(q):
    q = Fraction(q)
    return str(q.numerator) if q.denominator == 1 else "%d/%d" % (q.numerator, q.denominator)


def bernstein_sum(values, t, one, binom_row):
    """sum_i C(n,i) t^i (1-t)^(n-i) values[i] for a list of channel lists.

    `values` is a list of channels; each channel is a list of n+1 numbers (mpf or
    Fraction).  `t` has the same number type; `one` is 1 in that type.
    Returns one sum per channel.
    """
    n = len(values[0]) - 1
    s = one - t
    # powers computed once, exactly (Fraction) or at mp.dps (mpf)
    tp = [one]
    sp = [one]
    for _ in range(n):
        tp.append(tp[-1] * t)
        sp.append(sp[-1] * s)
    weights = [binom_row[i] * tp[i] * sp[n - i] for i in range(n + 1)]
    out = []
    for ch in values:
        acc = 0 * one
        for w, v in zip(weights, ch):
            acc += w * v
        out.append(acc)
    return out


def binomials(n):
    return [math.comb(n, i) for i in range(n + 1)]


def evaluate_exact(channels, t, one):
    """Value and first derivative of every channel at t (same number type as `one`)."""
    n = len(channels[0]) - 1
    value = bernstein_sum(channels, t, one, [one * c for c in binomials(n)])
    if n == 0:
        deriv = [0 * one for _ in channels]
    else:
        diffs = [[ch[i + 1] - ch[i] for i in range(n)] for ch in channels]
        row = [one * c for c in binomials(n - 1)]
        deriv = [n * d for d in bernstein_sum(diffs, t, one, row)]
    return value, deriv


def de_casteljau_f64(channels, t):
    """Plain float64 de Casteljau (numpy), used only as a sanity check."""
    b = np.array(channels, dtype=np.float64)  # shape (channels, n+1)
    n = b.shape[1] - 1
    if n == 0:
        return b[:, 0].copy(), np.zeros(b.shape[0])
    s = 1.0 - t
    for r in range(n, 1, -1):
        b = s * b[:, :r] + t * b[:, 1 : r + 1]
    # b now has 2 columns: the hodograph end points of the last level
    value = s * b[:, 0] + t * b[:, 1]
    deriv = n * (b[:, 1] - b[:, 0])
    return value, deriv


def point_json(position, degrees):
    return {
        "position": [float(p) for p in position],
        "truth": float(degrees[0]),
        "indeterminacy": float(degrees[1]),
        "falsity": float(degrees[2]),
    }


# --------------------------------------------------------------------------- example 1

EXAMPLE1 = [
    # name, x, y, truth, indeterminacy, falsity  (docs/model.md section 5, Table 1: C3 I = 0.4)
    ("C0", "1", "3", "0.3", "0.6", "0.1"),
    ("C1", "3", "6", "0.8", "0.1", "0.1"),
    ("C2", "6", "2", "0.7", "0.1", "0.2"),
    ("C3", "9", "5", "0.2", "0.4", "0.4"),
]


def make_example1():
    # Channels x, y, truth, indeterminacy, falsity as exact decimals (the paper's values).
    # The Rust side holds the doubles nearest to 0.3, 0.6, ...; the difference is < 1e-16.
    channels = [[Fraction(row[k]) for row in EXAMPLE1] for k in range(1, 6)]
    control_points = []
    for row in EXAMPLE1:
        control_points.append(
            {
                "name": row[0],
                "position": [float(row[1]), float(row[2])],
                "truth": float(row[3]),
                "indeterminacy": float(row[4]),
                "falsity": float(row[5]),
                "exact": {"x": row[1], "y": row[2], "truth": row[3],
                          "indeterminacy": row[4], "falsity": row[5]},
            }
        )

    def entry(t_frac, t_label):
        value, deriv = evaluate_exact(channels, t_frac, Fraction(1))
        names = ("x", "y", "truth", "indeterminacy", "falsity")
        return {
            "t": float(t_frac),
            "t_exact": frac_str(t_frac),
            "t_label": t_label,
            "position": [to_double(value[0]), to_double(value[1])],
            "truth": to_double(value[2]),
            "indeterminacy": to_double(value[3]),
            "falsity": to_double(value[4]),
            "derivative": {
                "position": [to_double(deriv[0]), to_double(deriv[1])],
                "truth": to_double(deriv[2]),
                "indeterminacy": to_double(deriv[3]),
                "falsity": to_double(deriv[4]),
            },
            "exact": {n: frac_str(v) for n, v in zip(names, value)},
            "exact_derivative": {n: frac_str(v) for n, v in zip(names, deriv)},
        }

    quarters = [entry(Fraction(k, 4), "%d/4" % k) for k in range(5)]
    # 0.1 grid: the Rust side evaluates at the double nearest k/10, so the reference is
    # the exact value at that double, Fraction(float) (exact), not at the decimal k/10.
    grid = []
    for k in range(11):
        t = float(Fraction(k, 10))  # correctly rounded: the same double as Rust's 0.1 etc.
        grid.append(entry(Fraction(t), "%d/10 (as double)" % k))

    # the value docs/model.md states at t = 1/2
    half = quarters[2]
    assert half["exact"] == {"x": "37/8", "y": "4", "truth": "5/8",
                             "indeterminacy": "1/5", "falsity": "7/40"}, half["exact"]

    return {
        "description": "Paper Example 1 (docs/model.md section 5, Table 1 data; erratum: C3 "
                       "indeterminacy is 0.4 as in Table 1, not 0.1 as in Table 3). "
                       "Exact rational evaluation (fractions.Fraction) with the control "
                       "values taken as exact decimals; 'grid' parameters are the doubles "
                       "nearest k/10, evaluated exactly at that double. Floats are the "
                       "correctly rounded doubles of the exact values.",
        "generator": "scripts/reference/make_bezier_reference.py",
        "dimension": 2,
        "degree": 3,
        "control_points": control_points,
        "quarters": quarters,
        "grid": grid,
    }


# --------------------------------------------------------------------------- random curves

DEGREES = [1, 2, 3, 4, 5, 7, 10, 15, 20, 30, 50, 100, 200, 300, 400]
FIXED_T = [0.0, 1e-12, 1e-6, 0.1, 0.25, 0.5, 1.0 / 3.0, 0.75, 0.9, 1.0 - 1e-6, 1.0 - 1e-12, 1.0]


def parameters(rng, n_random=4):
    return FIXED_T + [rng.random() for _ in range(n_random)]


def random_degrees(rng, mode):
    if mode == "uniform":
        return [rng.random(), rng.random(), rng.random()]
    if mode == "zero":
        return [0.0, 0.0, 0.0]
    if mode == "one":
        return [1.0, 1.0, 1.0]
    if mode == "mixed01":  # truth all 1, indeterminacy all 0, falsity all 1
        return [1.0, 0.0, 1.0]
    raise ValueError(mode)


def random_position(rng, dim, scale):
    if scale == "unit":
        return [rng.uniform(-10.0, 10.0) for _ in range(dim)]
    if scale == "large":
        return [rng.uniform(-1e6, 1e6) for _ in range(dim)]
    if scale == "offset":  # large offset, small spread: 1e6 + [-10, 10], mixed sign per axis
        return [(1.0 if k % 2 == 0 else -1.0) * (1e6 + rng.uniform(-10.0, 10.0))
                for k in range(dim)]
    if scale == "wide":  # magnitudes 1e-3 .. 1e6, random sign
        return [rng.choice((-1.0, 1.0)) * 10.0 ** rng.uniform(-3.0, 6.0) for _ in range(dim)]
    raise ValueError(scale)


def make_case(rng, name, dim, degree, scale="unit", degree_mode="uniform", n_random=4,
              tol=REL_TOL):
    cps = []
    for _ in range(degree + 1):
        cps.append((random_position(rng, dim, scale), random_degrees(rng, degree_mode)))
    ts = parameters(rng, n_random)
    # channels: x, y, [z], truth, indeterminacy, falsity
    channels_f = [[p[0][k] for p in cps] for k in range(dim)] + \
                 [[p[1][k] for p in cps] for k in range(3)]
    channels = [[mpf(v) for v in ch] for ch in channels_f]  # exact
    max_abs = max(abs(v) for ch in channels_f[:dim] for v in ch)
    evaluations = []
    worst = 0.0
    for t in ts:
        value, deriv = evaluate_exact(channels, mpf(t), mpf(1))
        ev = {
            "t": t,
            "position": [to_double(v) for v in value[:dim]],
            "truth": to_double(value[dim]),
            "indeterminacy": to_double(value[dim + 1]),
            "falsity": to_double(value[dim + 2]),
            "derivative": {
                "position": [to_double(v) for v in deriv[:dim]],
                "truth": to_double(deriv[dim]),
                "indeterminacy": to_double(deriv[dim + 1]),
                "falsity": to_double(deriv[dim + 2]),
            },
        }
        evaluations.append(ev)
        # sanity check against a float64 de Casteljau, with the Rust test's tolerances
        fv, fd = de_casteljau_f64(channels_f, t)
        for c in range(dim + 3):
            scale_v = max_abs if c < dim else 1.0
            ev_v = float(value[c])
            ev_d = float(deriv[c])
            e_v = abs(fv[c] - ev_v) / (tol * scale_v)
            e_d = abs(fd[c] - ev_d) / (tol * degree * scale_v)
            worst = max(worst, e_v, e_d)
            if e_v > 1.0 or e_d > 1.0:
                raise AssertionError("float64 de Casteljau disagrees with the reference: "
                                     "%s t=%r channel %d: %r vs %r, d %r vs %r"
                                     % (name, t, c, fv[c], ev_v, fd[c], ev_d))
    case = {
        "name": name,
        "dimension": dim,
        "degree": degree,
        "control_points": [point_json(p, d) for p, d in cps],
        "evaluations": evaluations,
    }
    return case, worst


def make_random(seed=20240517):
    rng = random.Random(seed)
    cases = []
    report = []
    for dim in (2, 3):
        for n in DEGREES:
            case, worst = make_case(rng, "unit_d%d_n%d" % (dim, n), dim, n)
            cases.append(case)
            report.append((case["name"], worst))
    extra = [
        # name, dim, degree, position scale, degree mode
        ("large_d2_n3", 2, 3, "large", "uniform"),
        ("large_d3_n10", 3, 10, "large", "uniform"),
        ("large_d2_n50", 2, 50, "large", "uniform"),
        ("large_d3_n200", 3, 200, "large", "uniform"),
        ("offset_d2_n5", 2, 5, "offset", "uniform"),
        ("offset_d3_n30", 3, 30, "offset", "uniform"),
        ("wide_d2_n20", 2, 20, "wide", "uniform"),
        ("wide_d3_n100", 3, 100, "wide", "uniform"),
        ("zero_degrees_d2_n5", 2, 5, "unit", "zero"),
        ("one_degrees_d3_n20", 3, 20, "unit", "one"),
        ("one_degrees_d2_n100", 2, 100, "unit", "one"),
        ("zero_degrees_d3_n300", 3, 300, "unit", "zero"),
        ("mixed01_degrees_d2_n7", 2, 7, "large", "mixed01"),
    ]
    for name, dim, n, scale, mode in extra:
        case, worst = make_case(rng, name, dim, n, scale=scale, degree_mode=mode)
        cases.append(case)
        report.append((case["name"], worst))
    return {
        "description": "Random neutrosophic Bezier curves evaluated with the explicit "
                       "Bernstein sum (exact integer binomials) in mpmath at 60 digits on "
                       "the exact double inputs; values are the correctly rounded doubles. "
                       "derivative = first derivative (hodograph) d/dt.",
        "generator": "scripts/reference/make_bezier_reference.py",
        "seed": seed,
        "cases": cases,
    }, report


def make_degree2000(seed=20240518):
    rng = random.Random(seed)
    case, worst = make_case(rng, "unit_d2_n2000", 2, 2000, n_random=0, tol=REL_TOL_2000)
    # keep 7 parameters: 0, 1e-6, 1/3, 0.5, 0.9, 1-1e-12, 1
    keep = {0.0, 1e-6, 1.0 / 3.0, 0.5, 0.9, 1.0 - 1e-12, 1.0}
    case["evaluations"] = [e for e in case["evaluations"] if e["t"] in keep]
    return {
        "description": "One 2-D neutrosophic Bezier curve of degree 2000, positions in "
                       "[-10, 10], evaluated like bezier_random.json (mpmath, 60 digits).",
        "generator": "scripts/reference/make_bezier_reference.py",
        "seed": seed,
        "cases": [case],
    }, [(case["name"], worst)]


# --------------------------------------------------------------------------- main


def write_json(name, obj):
    path = os.path.join(OUT_DIR, name)
    text = json.dumps(obj, indent=1, allow_nan=False)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
        f.write("\n")
    print("wrote %s (%d bytes)" % (os.path.relpath(path, ROOT), len(text) + 1))


def main():
    os.makedirs(OUT_DIR, exist_ok=True)
    write_json("example1.json", make_example1())
    rnd, report = make_random()
    write_json("bezier_random.json", rnd)
    d2000, report2 = make_degree2000()
    write_json("bezier_degree2000.json", d2000)
    print("float64 de Casteljau sanity check, worst error / tolerance per case:")
    for name, worst in report + report2:
        print("  %-26s %.3g" % (name, worst))
    print("numpy %s, mpmath %s, python %s" % (np.__version__, mpmath.__version__,
                                               sys.version.split()[0]))


if __name__ == "__main__":
    main()
