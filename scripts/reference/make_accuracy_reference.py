#!/usr/bin/env python3
"""Reference data for the accuracy of evaluation at high degree (compensated evaluation).

How to run (from the workspace root):

    python3 -m venv .venv-ref \
      && .venv-ref/bin/pip install numpy scipy mpmath \
      && .venv-ref/bin/python scripts/reference/make_accuracy_reference.py

then `cargo test -p neutrospline --lib accuracy -- --nocapture` prints the table of the
README's "Accuracy" section (ours compensated, ours plain, ours fast batch, scipy).

Deterministic (fixed seed, Python's `random` module).  Written to
`crates/neutrospline/tests/data/accuracy.json`:

  sets     one set of control rows per degree p (100, 400, 2000): p + 4 rows of five
           channels x, y (in [-10, 10]), truth, indeterminacy, falsity (in [0, 1]), each an
           integer times 2^-20 (stored as the integer: exact and short); NURBS weights in
           [0.5, 2], integers times 2^-20 too; three interior knots in (0, 1) (repr strings).
  cases    per kind and degree: the Bezier curve of the first p + 1 rows on [0, 1], the
           clamped B-spline of all p + 4 rows over 0^(p+1), the interior knots, 1^(p+1), and
           the NURBS curve with the weights; 14 parameters (0, 1, the interior knots for
           splines, random doubles in (0, 1)) as repr strings; the exact values at those
           doubles, computed with mpmath at 50 digits (Bezier: the Bernstein sum with exact
           integer binomials; splines: the Cox-de Boor basis of the span, rational formula
           sum w_i N_i P_i / sum w_i N_i for NURBS), each as two doubles hi + lo (repr);
           and scipy's scaled error per channel on the same data (scipy.interpolate.BSpline,
           Bezier knots for a Bezier curve, numerator and denominator splines for NURBS).

Scaled error of a channel: max over the parameters of |value - exact| / max_i |c_i|.
"""

import json
import os
import random

import numpy as np
from mpmath import mp, mpf
from scipy.interpolate import BSpline

mp.dps = 50

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "..", "crates", "neutrospline", "tests", "data", "accuracy.json")

SEED = 20261203
DEGREES = [100, 400, 2000]
EXTRA = 3  # interior knots, and rows beyond p + 1
SCALE = 2.0**-20
CHANNELS = 5
RANDOM_PARAMETERS = 10


def make_set(rng, p):
    count = p + 1 + EXTRA
    rows = []
    for _ in range(count):
        rows += [rng.randint(-10 * 2**20, 10 * 2**20), rng.randint(-10 * 2**20, 10 * 2**20)]
        rows += [rng.randint(0, 2**20) for _ in range(3)]
    weights = [rng.randint(2**19, 2**21) for _ in range(count)]
    interior = sorted(rng.uniform(0.05, 0.95) for _ in range(EXTRA))
    return {"degree": p, "rows": rows, "weights": weights, "interior_knots": [repr(k) for k in interior]}


def control(s, count):
    """The control values as a (count, 5) float array (exact)."""
    return np.array(s["rows"][: count * CHANNELS], dtype=float).reshape(count, CHANNELS) * SCALE


def knots_of(s):
    p = s["degree"]
    return [0.0] * (p + 1) + [float(k) for k in s["interior_knots"]] + [1.0] * (p + 1)


def bernstein_exact(c, t):
    n = len(c) - 1
    t = mpf(t)  # exact
    s = 1 - t
    # B_i = C(n, i) t^i s^(n - i), by powers (exact binomials).
    tp = [mpf(1)]
    sp = [mpf(1)]
    for _ in range(n):
        tp.append(tp[-1] * t)
        sp.append(sp[-1] * s)
    binom = 1
    out = [mpf(0)] * CHANNELS
    for i in range(n + 1):
        b = binom * tp[i] * sp[n - i]
        for ch in range(CHANNELS):
            out[ch] += b * mpf(float(c[i][ch]))
        binom = binom * (n - i) // (i + 1)
    return out


def span(knots, p, t):
    """The span k with u_k <= t < u_{k+1}, or the last non-empty one at the domain end."""
    m = len(knots) - 1
    if t >= knots[m - p]:
        k = m - p - 1
        while knots[k] == knots[k + 1]:
            k -= 1
        return k
    k = p
    while knots[k + 1] <= t:
        k += 1
    return k


def basis_exact(knots, p, k, t):
    """N_{k-p..k, p}(t) by the Cox-de Boor triangle (The NURBS Book, A2.2) in mpmath."""
    u = [mpf(x) for x in knots]
    t = mpf(t)
    n = [mpf(1)] + [mpf(0)] * p
    left = [mpf(0)] * (p + 1)
    right = [mpf(0)] * (p + 1)
    for j in range(1, p + 1):
        left[j] = t - u[k + 1 - j]
        right[j] = u[k + j] - t
        saved = mpf(0)
        for r in range(j):
            temp = n[r] / (right[r + 1] + left[j - r])
            n[r] = saved + right[r + 1] * temp
            saved = left[j - r] * temp
        n[j] = saved
    return n


BASIS = {}


def spline_exact(c, w, knots, p, t):
    k = span(knots, p, t)
    key = (tuple(knots), t)
    if key not in BASIS:
        BASIS[key] = basis_exact(knots, p, k, t)
    n = BASIS[key]
    num = [mpf(0)] * CHANNELS
    den = mpf(0)
    for i in range(p + 1):
        row = k - p + i
        wi = mpf(1) if w is None else mpf(float(w[row]))
        b = n[i] * wi
        den += b
        for ch in range(CHANNELS):
            num[ch] += b * mpf(float(c[row][ch]))
    return [v / den for v in num]


def double_double(v):
    """The exact value as `[hi, lo]` (repr strings): hi the nearest double, lo the nearest
    double to v - hi (together about 106 bits)."""
    hi = float(v)
    lo = float(v - mpf(hi))
    return [repr(hi), repr(lo)]


def scaled_errors(values, exact, c):
    scale = np.abs(c).max(axis=0)
    err = np.zeros(CHANNELS)
    for v, e in zip(values, exact):
        for ch in range(CHANNELS):
            err[ch] = max(err[ch], float(abs(mpf(float(v[ch])) - e[ch])) / scale[ch])
    return [float(x) for x in err]


def main():
    rng = random.Random(SEED)
    sets = []
    cases = []
    for p in DEGREES:
        s = make_set(rng, p)
        sets.append(s)
        randoms = [rng.random() for _ in range(RANDOM_PARAMETERS)]
        for kind in ["bezier", "bspline", "nurbs"]:
            if kind == "bezier":
                count = p + 1
                knots = [0.0] * (p + 1) + [1.0] * (p + 1)
                params = [0.0, 1.0] + randoms + [1e-3, 1 - 1e-3]
            else:
                count = p + 1 + EXTRA
                knots = knots_of(s)
                params = [0.0, 1.0] + [float(k) for k in s["interior_knots"]] + randoms[:-1]
            c = control(s, count)
            w = None
            if kind == "nurbs":
                w = np.array(s["weights"], dtype=float) * SCALE
            if kind == "bezier":
                exact = [bernstein_exact(c, t) for t in params]
            else:
                exact = [spline_exact(c, w, knots, p, t) for t in params]
            # scipy on the same data: float64 de Boor (extrapolate=False: the domain only).
            if w is None:
                values = BSpline(np.array(knots), c, p, extrapolate=False)(np.array(params))
            else:
                numerator = BSpline(np.array(knots), c * w[:, None], p, extrapolate=False)
                denominator = BSpline(np.array(knots), w, p, extrapolate=False)
                ts = np.array(params)
                values = numerator(ts) / denominator(ts)[:, None]
            scipy_error = scaled_errors(values, exact, c)
            cases.append(
                {
                    "kind": kind,
                    "degree": p,
                    "parameters": [repr(t) for t in params],
                    "exact": [[double_double(v) for v in e] for e in exact],
                    "scipy_scaled_error": scipy_error,
                }
            )
            print(f"{kind:8} degree {p:5}: scipy scaled error {max(scipy_error):.2e}")
    data = {
        "description": "Bezier, B-spline and NURBS curves of degree 100, 400 and 2000: exact values "
        "(mpmath, 50 digits) at random parameters, and scipy's scaled errors.",
        "generator": "scripts/reference/make_accuracy_reference.py",
        "seed": SEED,
        "scale_exponent": -20,
        "sets": sets,
        "cases": cases,
    }
    with open(OUT, "w") as f:
        json.dump(data, f, separators=(",", ":"))
        f.write("\n")
    print(f"wrote {os.path.relpath(OUT)} ({os.path.getsize(OUT)} bytes)")


if __name__ == "__main__":
    main()
