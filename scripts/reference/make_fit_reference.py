#!/usr/bin/env python3
"""Independent reference values for the fitting tests (crates/neutrospline/tests/integration/fit_reference.rs).

Each case is a data set (points with truth, indeterminacy, falsity) and the options of a fit.
This script computes, independently of the Rust code:

- the parameters (chord length, centripetal or uniform, docs/model.md section 8),
- the knots (averaging, The NURBS Book eq. 9.8, for interpolation; eq. 9.68-9.69 for least
  squares),
- the control values of every channel with scipy: `make_interp_spline(x, y, k, t=knots)` for
  interpolation, `make_lsq_spline(x, y, knots, k, w=sqrt(weights))` for weighted least squares
  (scipy squares its weights: our objective is sum_k w_k r_k^2), and for smoothing the
  penalised normal equations `(B^T W B + lambda R) c = B^T W y` built from scipy's design
  matrix and a dense Gauss-Legendre integration of the second derivatives, solved by
  numpy.linalg.solve; for closed curves `make_interp_spline(..., bc_type='periodic')`,
  compared by value at parameters (the two periodic representations differ).

The data keep every degree coefficient strictly inside (0, 1) (asserted), so no bound of the
membership rule is active and the constrained fit must equal the unconstrained one.

Run from the workspace root:

    python3 -m venv /tmp/venv-fit && /tmp/venv-fit/bin/pip install numpy scipy
    /tmp/venv-fit/bin/python scripts/reference/make_fit_reference.py

Deterministic (fixed seeds); checked with scipy 1.17.1, numpy 2.4.6.
"""

import json
import math
import pathlib

import numpy as np
from scipy.interpolate import BSpline, make_interp_spline, make_lsq_spline

OUT = pathlib.Path("crates/neutrospline/tests/data/fit_scipy.json")


def params_of(points, kind, closed=False):
    e = {"uniform": 0.0, "chord-length": 1.0, "centripetal": 0.5}[kind]
    pts = np.asarray(points, dtype=float)
    steps = [float(np.linalg.norm(pts[i + 1] - pts[i])) ** e for i in range(len(pts) - 1)]
    if closed:
        steps.append(float(np.linalg.norm(pts[0] - pts[-1])) ** e)
    total = sum(steps)
    t, acc = [0.0], 0.0
    for s in steps[: len(pts) - 1]:
        acc += s
        t.append(min(acc / total, 1.0))
    if not closed:
        t[-1] = 1.0
    return t


def clamped(a, b, p, interior):
    out, prev = [a] * (p + 1), a
    for k in interior:
        prev = min(max(k, prev), b)
        out.append(prev)
    return out + [b] * (p + 1)


def interp_knots(t, p):
    m = len(t) - 1
    return clamped(t[0], t[m], p, [sum(t[j:j + p]) / p for j in range(1, m - p + 1)])


def lsq_knots(t, p, n):
    m = len(t) - 1
    d = (m + 1) / (n - p + 1)
    inner = []
    for j in range(1, n - p + 1):
        jd = j * d
        i = min(max(int(math.floor(jd)), 1), m)
        a = jd - i
        inner.append((1 - a) * t[i - 1] + a * t[i])
    return clamped(t[0], t[m], p, inner)


def gram_second(knots, p, n):
    """R_ij = int N_i'' N_j'' over the domain, Gauss-Legendre with 8 nodes per span."""
    x, w = np.polynomial.legendre.leggauss(8)
    r = np.zeros((n, n))
    ks = sorted(set(knots[p:len(knots) - p]))
    second = BSpline(np.asarray(knots), np.eye(n), p).derivative(2)
    for a, b in zip(ks[:-1], ks[1:]):
        ts = a + (b - a) * (x + 1) / 2
        vals = second(ts).T  # n x nodes
        r += (vals * (w * (b - a) / 2)) @ vals.T
    return r


def curve(rng, m, dim, noise):
    s = np.linspace(0, 1, m)
    s = s + rng.uniform(-0.3, 0.3, m) / m
    s.sort()
    xs = [np.cos(2.5 * s), np.sin(3.0 * s) + s, 0.5 * s * s]
    pts = np.stack(xs[:dim], axis=1) * 4.0 + rng.normal(0, noise, (m, dim))
    tru = 0.5 + 0.3 * np.sin(4 * s)
    ind = 0.4 + 0.2 * np.cos(3 * s)
    fal = 0.3 + 0.2 * s
    return pts.tolist(), np.stack([tru, ind, fal], axis=1).tolist()


def main():
    rng = np.random.default_rng(20261201)
    cases = []

    def add_lsq(name, m, dim, p, n, param, noise, weights=None, lam=0.0):
        pts, deg = curve(rng, m, dim, noise)
        t = params_of(pts, param)
        knots = lsq_knots(t, p, n - 1)
        y = np.hstack([np.asarray(pts), np.asarray(deg)])
        w = np.ones(m) if weights is None else np.asarray(weights)
        if lam == 0.0:
            spl = make_lsq_spline(np.asarray(t), y, np.asarray(knots), k=p, w=np.sqrt(w))
            coef = spl.c
        else:
            b = BSpline.design_matrix(np.asarray(t), np.asarray(knots), p).toarray()
            r = gram_second(knots, p, n)
            coef = np.linalg.solve(b.T @ (w[:, None] * b) + lam * r, b.T @ (w[:, None] * y))
        assert np.all((coef[:, dim:] > 1e-6) & (coef[:, dim:] < 1 - 1e-6)), name
        case = {
            "name": name, "target": "control-points", "control_points": n, "degree": p,
            "dimension": dim, "parametrization": param, "smoothing": lam,
            "points": pts, "degrees": deg, "parameters": t, "knots": knots,
            "coefficients": coef.tolist(),
        }
        if weights is not None:
            case["weights"] = list(map(float, weights))
        cases.append(case)

    def add_interp(name, m, dim, p, param):
        pts, deg = curve(rng, m, dim, 0.0)
        t = params_of(pts, param)
        knots = interp_knots(t, p)
        y = np.hstack([np.asarray(pts), np.asarray(deg)])
        spl = make_interp_spline(np.asarray(t), y, k=p, t=np.asarray(knots))
        assert np.all((spl.c[:, dim:] > 0) & (spl.c[:, dim:] < 1)), name
        cases.append({
            "name": name, "target": "interpolate", "degree": p, "dimension": dim,
            "parametrization": param, "smoothing": 0.0, "points": pts, "degrees": deg,
            "parameters": t, "knots": knots, "coefficients": spl.c.tolist(),
        })

    def add_periodic(name, m, dim, p):
        pts, deg = curve(rng, m, dim, 0.0)
        # A closed loop: bend the data round.
        s = np.linspace(0, 1, m, endpoint=False)
        loop = np.stack([np.cos(2 * np.pi * s) * 3 + 0.3 * np.sin(6 * np.pi * s),
                         np.sin(2 * np.pi * s) * 2, np.cos(4 * np.pi * s)], axis=1)[:, :dim]
        pts = loop.tolist()
        deg = np.stack([0.5 + 0.3 * np.sin(2 * np.pi * s), 0.5 + 0.2 * np.cos(2 * np.pi * s),
                        0.4 + 0.1 * np.sin(4 * np.pi * s)], axis=1).tolist()
        t = params_of(pts, "chord-length", closed=True)
        x = np.append(t, 1.0)
        y = np.vstack([np.hstack([pts, deg]), np.hstack([pts[0], deg[0]])])
        spl = make_interp_spline(x, y, k=p, bc_type="periodic")
        samples = np.linspace(0, 1, 41)
        cases.append({
            "name": name, "target": "interpolate", "closed": True, "degree": p,
            "dimension": dim, "parametrization": "chord-length", "smoothing": 0.0,
            "points": pts, "degrees": deg, "parameters": t,
            "samples": samples.tolist(), "values": spl(samples).tolist(),
        })

    add_lsq("lsq_cubic_2d_20", 200, 2, 3, 20, "chord-length", 0.02)
    add_lsq("lsq_cubic_3d_12", 150, 3, 3, 12, "centripetal", 0.01)
    add_lsq("lsq_quadratic_2d_uniform", 90, 2, 2, 15, "uniform", 0.05)
    add_lsq("lsq_quintic_3d", 300, 3, 5, 25, "chord-length", 0.001)
    add_lsq("lsq_linear_2d", 60, 2, 1, 10, "chord-length", 0.03)
    add_lsq("lsq_weighted_2d", 120, 2, 3, 14, "chord-length", 0.05,
            weights=rng.uniform(0.2, 5.0, 120).tolist())
    add_lsq("lsq_smoothing_2d", 150, 2, 3, 30, "chord-length", 0.05, lam=1e-3)
    add_lsq("lsq_smoothing_3d_strong", 100, 3, 4, 20, "chord-length", 0.05, lam=0.1)
    add_interp("interp_cubic_2d", 25, 2, 3, "chord-length")
    add_interp("interp_cubic_3d", 40, 3, 3, "centripetal")
    add_interp("interp_quadratic_2d", 18, 2, 2, "uniform")
    add_interp("interp_degree7_2d", 30, 2, 7, "chord-length")
    add_periodic("closed_cubic_2d", 24, 2, 3)
    add_periodic("closed_quintic_3d", 30, 3, 5)

    OUT.write_text(json.dumps({
        "description": "Fitting references from scipy 1.17 (make_lsq_spline with w = sqrt(weights), "
                       "make_interp_spline, penalised normal equations with numpy; periodic "
                       "interpolation by value). Generated by scripts/reference/make_fit_reference.py.",
        "cases": cases,
    }, indent=1) + "\n")
    print(f"wrote {OUT} ({len(cases)} cases)")


if __name__ == "__main__":
    main()
