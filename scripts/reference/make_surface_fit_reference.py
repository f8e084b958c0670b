#!/usr/bin/env python3
"""Independent reference values for surface fitting (crates/neutrospline/tests/integration/surface_fit_reference.rs).

Each case is a data set (points with truth, indeterminacy, falsity) and the options of a
surface fit. Independently of the Rust code, this script computes:

- the parameters: for a grid, each column's (for u) and each row's (for v) chord-length,
  centripetal or uniform parameters averaged (The NURBS Book 9.2.5); for scattered height
  data, (x, y) scaled to [0, 1];
- the knots: averaging (eq. 9.8) for interpolation, eq. 9.68-9.69 for least squares, over
  the grid's parameters or the sorted distinct parameters of scattered data;
- the control values of every channel (x, y, z, truth, indeterminacy, falsity) with scipy:
  `make_interp_spline(..., t=knots, axis=0)` then `axis=1` (grid interpolation),
  `make_lsq_spline(..., axis=0)` then `axis=1` (grid least squares), `LSQBivariateSpline`
  with the same interior knots (scattered least squares, `w = sqrt(weights)`: scipy squares
  its weights), cross-checked against `numpy.linalg.lstsq` on the tensor design matrix
  (`BSpline.design_matrix`); for smoothing, the penalised normal equations with the
  thin-plate Gram matrices (Gauss-Legendre, 8 nodes per span) solved by numpy.

The data keep every degree coefficient strictly inside (0, 1) (asserted), so no bound of the
membership rule is active and the bounded fit must equal the unconstrained one.

Run from the workspace root (the venv of make_fit_reference.py: numpy, scipy):

    .venv-ref/bin/python scripts/reference/make_surface_fit_reference.py

Deterministic (fixed seeds); checked with scipy 1.17.1, numpy 2.4.6.
"""

import json
import pathlib
import sys

import numpy as np
from scipy.interpolate import BSpline, LSQBivariateSpline, make_interp_spline, make_lsq_spline

sys.path.insert(0, str(pathlib.Path(__file__).parent))
from make_fit_reference import interp_knots, lsq_knots  # noqa: E402

OUT = pathlib.Path("crates/neutrospline/tests/data/surface_fit_scipy.json")


def averaged(q, kind, axis):
    """Parameters along `axis` of the grid q (rows x cols x 3), averaged over the other."""
    e = {"uniform": 0.0, "chord-length": 1.0, "centripetal": 0.5}[kind]
    lines = q if axis == 1 else q.transpose(1, 0, 2)
    total, used = np.zeros(lines.shape[1]), 0
    for line in lines:
        steps = np.linalg.norm(np.diff(line, axis=0), axis=1) ** e
        if steps.sum() == 0:
            continue
        used += 1
        total += np.concatenate([[0.0], np.minimum(np.cumsum(steps) / steps.sum(), 1.0)])
    t = total / used
    t[0], t[-1] = 0.0, 1.0
    return t


def channels_of(points, tfi):
    return np.hstack([np.asarray(points, float), np.asarray(tfi, float)])


def design(t, knots, p):
    return BSpline.design_matrix(t, np.asarray(knots), p).toarray()


def gram(knots, p, order):
    n = len(knots) - p - 1
    x, w = np.polynomial.legendre.leggauss(8)
    g = np.zeros((n, n))
    ks = sorted(set(knots[p:len(knots) - p]))
    f = BSpline(np.asarray(knots), np.eye(n), p)
    if order:
        f = f.derivative(order)
    for a, b in zip(ks[:-1], ks[1:]):
        vals = f(a + (b - a) * (x + 1) / 2).T
        g += (vals * (w * (b - a) / 2)) @ vals.T
    return g


def degrees_at(x, y):
    return [0.5 + 0.3 * np.sin(x + 0.5 * y), 0.3 + 0.1 * np.cos(2 * y), 0.2 + 0.1 * np.sin(x * y)]


def grid_case(name, rows, cols, p, q, kind, target, counts=None, weights=None, seed=0):
    rng = np.random.default_rng(seed)
    pts = np.zeros((rows, cols, 3))
    for k in range(rows):
        for l in range(cols):
            x = 3.0 * k / (rows - 1) + 0.1 * np.sin(0.7 * l) + 0.02 * rng.standard_normal()
            y = 2.0 * l / (cols - 1) + 0.05 * np.cos(0.5 * k)
            pts[k, l] = [x, y, np.sin(x) * np.cos(y) + 0.01 * rng.standard_normal()]
    tfi = np.array([[degrees_at(*pts[k, l, :2]) for l in range(cols)] for k in range(rows)])
    u, v = averaged(pts, kind, 0), averaged(pts, kind, 1)
    data = np.concatenate([pts, tfi], axis=2)  # rows x cols x 6
    if target == "interpolate":
        ku, kv = interp_knots(list(u), p), interp_knots(list(v), q)
        c = make_interp_spline(u, data, k=p, t=np.asarray(ku), axis=0).c
        # scipy puts the spline's axis first: back to (u, v, channel).
        c = make_interp_spline(v, c, k=q, t=np.asarray(kv), axis=1).c.transpose(1, 0, 2)
    else:
        ku, kv = lsq_knots(list(u), p, counts[0] - 1), lsq_knots(list(v), q, counts[1] - 1)
        if weights is None:
            c = make_lsq_spline(u, data, np.asarray(ku), p, axis=0).c
            c = make_lsq_spline(v, c, np.asarray(kv), q, axis=1).c.transpose(1, 0, 2)
        else:
            b = np.kron(design(u, ku, p), design(v, kv, q))
            s = np.sqrt(np.asarray(weights))[:, None]
            flat = np.linalg.lstsq(b * s, data.reshape(-1, 6) * s, rcond=None)[0]
            c = flat.reshape(len(ku) - p - 1, len(kv) - q - 1, 6)
    m, n = c.shape[0], c.shape[1]
    return {
        "name": name,
        "shape": "grid",
        "rows": rows,
        "cols": cols,
        "degrees": [p, q],
        "target": target,
        "control_points": [m, n],
        "parametrization": kind,
        "smoothing": 0.0,
        "weights": weights,
        "points": pts.reshape(-1, 3).tolist(),
        "tfi": tfi.reshape(-1, 3).tolist(),
        "params": [[float(a), float(b)] for a in u for b in v],
        "knots_u": list(map(float, ku)),
        "knots_v": list(map(float, kv)),
        "coefficients": c.reshape(m * n, 6).tolist(),
    }


def scattered_case(name, count, p, q, counts, weights=False, smoothing=0.0, seed=1):
    rng = np.random.default_rng(seed)
    x = rng.uniform(-1.0, 2.0, count)
    y = rng.uniform(0.0, 1.5, count)
    z = np.exp(-x * x) * np.cos(2 * y) + 0.01 * rng.standard_normal(count)
    pts = np.stack([x, y, z], axis=1)
    tfi = np.array([degrees_at(a, b) for a, b in zip(x, y)])
    u = (x - x.min()) / (x.max() - x.min())
    v = (y - y.min()) / (y.max() - y.min())
    ku = lsq_knots(sorted(set(u)), p, counts[0] - 1)
    kv = lsq_knots(sorted(set(v)), q, counts[1] - 1)
    data = channels_of(pts, tfi)
    w = rng.uniform(0.5, 2.0, count) if weights else np.ones(count)
    bu, bv = design(u, ku, p), design(v, kv, q)
    b = np.einsum("ki,kj->kij", bu, bv).reshape(count, -1)
    m, n = counts
    if smoothing > 0.0:
        g = [(gram(ku, p, r), gram(kv, q, r)) for r in range(3)]
        r = np.kron(g[2][0], g[0][1]) + 2 * np.kron(g[1][0], g[1][1]) + np.kron(g[0][0], g[2][1])
        c = np.linalg.solve(b.T @ (w[:, None] * b) + smoothing * r, b.T @ (w[:, None] * data))
    else:
        s = np.sqrt(w)[:, None]
        c = np.linalg.lstsq(b * s, data * s, rcond=None)[0]
        for ch in range(6):
            spline = LSQBivariateSpline(
                u, v, data[:, ch], ku[p + 1:-p - 1], kv[q + 1:-q - 1], w=np.sqrt(w), kx=p, ky=q,
                bbox=[0.0, 1.0, 0.0, 1.0])
            ref = spline.get_coeffs()
            scale = np.abs(c[:, ch]).max()
            assert np.abs(ref - c[:, ch]).max() <= 1e-9 * scale, (name, ch)
            c[:, ch] = ref
    return {
        "name": name,
        "shape": "scattered",
        "rows": 0,
        "cols": 0,
        "degrees": [p, q],
        "target": "lsq",
        "control_points": [m, n],
        "parametrization": "chord-length",
        "smoothing": smoothing,
        "weights": w.tolist() if weights else None,
        "points": pts.tolist(),
        "tfi": tfi.tolist(),
        "params": np.stack([u, v], axis=1).tolist(),
        "knots_u": list(map(float, ku)),
        "knots_v": list(map(float, kv)),
        "coefficients": c.tolist(),
    }


def main():
    rng = np.random.default_rng(7)
    cases = [
        grid_case("grid-interpolate-chord", 7, 6, 3, 2, "chord-length", "interpolate"),
        grid_case("grid-interpolate-centripetal", 6, 8, 2, 3, "centripetal", "interpolate"),
        grid_case("grid-lsq-uniform", 15, 12, 3, 3, "uniform", "lsq", (8, 6)),
        grid_case("grid-lsq-chord", 20, 9, 2, 3, "chord-length", "lsq", (9, 7)),
        grid_case("grid-lsq-weighted", 10, 9, 3, 2, "centripetal", "lsq", (6, 5),
                  weights=rng.uniform(0.5, 2.0, 90).tolist()),
        scattered_case("scattered-lsq", 400, 3, 3, (7, 6)),
        scattered_case("scattered-lsq-weighted", 500, 3, 2, (6, 8), weights=True, seed=2),
        scattered_case("scattered-smoothing", 300, 3, 3, (9, 9), smoothing=1e-4, seed=3),
    ]
    for case in cases:
        tfi = np.asarray(case["coefficients"])[:, 3:]
        assert tfi.min() > 0.0 and tfi.max() < 1.0, case["name"]
    doc = {
        "description": "Surface fits: parameters, knots and control values from scipy (see "
                       "scripts/reference/make_surface_fit_reference.py)",
        "cases": cases,
    }
    OUT.write_text(json.dumps(doc) + "\n")
    print(f"wrote {OUT} ({len(cases)} cases)")


if __name__ == "__main__":
    main()
