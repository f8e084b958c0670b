#!/usr/bin/env python3
"""Independent reference values for the nearest points of neutrospline surfaces
(`Surface::nearest`).

How to run (from the repository root):

    python3 -m venv /tmp/venv-ref \
      && /tmp/venv-ref/bin/pip install numpy scipy mpmath \
      && /tmp/venv-ref/bin/python scripts/reference/make_surface_nearest_reference.py

Method (independent of the core's branch and bound): the surface is the explicit
tensor-product Cox-de Boor sum (rational quotient for NURBS) on the exact double inputs. For
each query point the distance is sampled on a 121 x 121 grid of every Bézier patch (numpy,
float64); from the 12 best sampled local minima scipy.optimize.minimize (L-BFGS-B, bounded to
the domain) descends in float64, then Newton's method in mpmath at 40 digits (gradient and
Hessian by mpmath.diff) polishes each result, keeping a coordinate on the domain's edge where
the gradient points out. The global minimum is the smallest polished distance; distances
within 1e-12 of the surface's scale are ties, broken by the smallest u, then v. `unique` is
false when another minimum more than 1e-6 away in (u, v) comes within 1e-9 of the scale.

Cases: the bicubic Bézier hill `examples/surface.toml`, the quarter cylinder
`examples/nurbs-surface.json` (closed form: the distance from (x, y, z) with 0 <= z <= 2 and
the direction inside the quarter is | sqrt(x^2 + y^2) - 1 |; a point on the axis is at
distance 1 from a whole arc: u = 0 is reported) and a bi-quadratic B-spline surface with an
interior knot. Written to `crates/neutrospline/tests/data/surface_nearest.json`.
"""

import json
import os

import mpmath as mp
import numpy as np
from scipy.optimize import minimize

mp.mp.dps = 40


def span(knots, p, t):
    n = len(knots) - p - 1
    if t >= knots[n]:
        k = n - 1
        while knots[k] == knots[k + 1]:
            k -= 1
        return k
    k = p
    while not (knots[k] <= t < knots[k + 1]):
        k += 1
    return k


def basis(knots, p, t):
    k = span(knots, p, t)
    n = {k: 1}
    for d in range(1, p + 1):
        nxt = {}
        for i in range(k - d, k + 1):
            v = 0
            den = knots[i + d] - knots[i]
            if den != 0 and n.get(i, 0) != 0:
                v += (t - knots[i]) / den * n[i]
            den = knots[i + d + 1] - knots[i + 1]
            if den != 0 and n.get(i + 1, 0) != 0:
                v += (knots[i + d + 1] - t) / den * n[i + 1]
            nxt[i] = v
        n = nxt
    return n


class Surface:
    def __init__(self, name, kind, rows, cols, p, q, ku, kv, points, weights=None):
        self.name, self.kind = name, kind
        self.rows, self.cols, self.p, self.q = rows, cols, p, q
        self.ku, self.kv = [float(k) for k in ku], [float(k) for k in kv]
        self.points = [[float(c) for c in pt] for pt in points]
        self.weights = [float(w) for w in weights] if weights else None
        self.mku = [mp.mpf(k) for k in self.ku]
        self.mkv = [mp.mpf(k) for k in self.kv]
        self.mpoints = [[mp.mpf(c) for c in pt] for pt in self.points]
        self.mweights = [mp.mpf(w) for w in self.weights] if self.weights else None
        arr = np.array(self.points)
        self.scale = float(np.linalg.norm(arr.max(axis=0) - arr.min(axis=0)))
        self.du = (self.ku[p], self.ku[rows])
        self.dv = (self.kv[q], self.kv[cols])

    def at(self, u, v, exact):
        ku, kv = (self.mku, self.mkv) if exact else (self.ku, self.kv)
        pts = self.mpoints if exact else self.points
        ws = self.mweights if exact else self.weights
        nu, nv = basis(ku, self.p, u), basis(kv, self.q, v)
        num = [0, 0, 0]
        den = 0
        for i, bu in nu.items():
            for j, bv in nv.items():
                k = i * self.cols + j
                w = ws[k] if ws else 1
                den += w * bu * bv
                for a in range(3):
                    num[a] += w * bu * bv * pts[k][a]
        return [x / den for x in num]

    def dist(self, u, v, q, exact=False):
        c = self.at(u, v, exact)
        s = sum((c[a] - q[a]) ** 2 for a in range(3))
        return mp.sqrt(s) if exact else float(np.sqrt(s))


def spans(knots, p, count):
    return [(knots[k], knots[k + 1]) for k in range(p, count) if knots[k] < knots[k + 1]]


def polish(s, q, u, v):
    qm = [mp.mpf(x) for x in q]
    lo = [mp.mpf(s.du[0]), mp.mpf(s.dv[0])]
    hi = [mp.mpf(s.du[1]), mp.mpf(s.dv[1])]
    x = [mp.mpf(u), mp.mpf(v)]

    def f(a, b):
        a = min(max(a, lo[0]), hi[0])
        b = min(max(b, lo[1]), hi[1])
        c = s.at(a, b, True)
        return sum((c[k] - qm[k]) ** 2 for k in range(3))

    for _ in range(40):
        g = [mp.diff(f, (x[0], x[1]), (1, 0)), mp.diff(f, (x[0], x[1]), (0, 1))]
        h = [[mp.diff(f, (x[0], x[1]), (2, 0)), mp.diff(f, (x[0], x[1]), (1, 1))],
             [mp.diff(f, (x[0], x[1]), (1, 1)), mp.diff(f, (x[0], x[1]), (0, 2))]]
        held = [(x[c] <= lo[c] and g[c] > 0) or (x[c] >= hi[c] and g[c] < 0) for c in range(2)]
        step = [mp.mpf(0), mp.mpf(0)]
        if held[0] and held[1]:
            break
        if held[0] or held[1]:
            c = 1 if held[0] else 0
            step[c] = -g[c] / h[c][c]
        else:
            det = h[0][0] * h[1][1] - h[0][1] ** 2
            step = [-(h[1][1] * g[0] - h[0][1] * g[1]) / det,
                    -(h[0][0] * g[1] - h[0][1] * g[0]) / det]
        nxt = [min(max(x[c] + step[c], lo[c]), hi[c]) for c in range(2)]
        if max(abs(nxt[c] - x[c]) for c in range(2)) < mp.mpf(10) ** -30:
            x = nxt
            break
        x = nxt
    return x, s.dist(x[0], x[1], qm, True)


def nearest(s, q):
    samples = []
    for (u0, u1) in spans(s.ku, s.p, s.rows):
        for (v0, v1) in spans(s.kv, s.q, s.cols):
            for u in np.linspace(u0, u1, 121):
                for v in np.linspace(v0, v1, 121):
                    samples.append((s.dist(u, v, q), u, v))
    samples.sort()
    starts = [(u, v) for _, u, v in samples[:12]]
    candidates = []
    bounds = [s.du, s.dv]
    for u, v in starts:
        r = minimize(lambda x: s.dist(x[0], x[1], q) ** 2, [u, v], method="L-BFGS-B",
                     bounds=bounds, options={"ftol": 1e-15, "gtol": 1e-12})
        candidates.append(polish(s, q, r.x[0], r.x[1]))
    # The corners of the domain too.
    for u in s.du:
        for v in s.dv:
            candidates.append(([mp.mpf(u), mp.mpf(v)], s.dist(mp.mpf(u), mp.mpf(v), [mp.mpf(c) for c in q], True)))
    best = min(d for _, d in candidates)
    tie = 1e-12 * s.scale
    near = sorted(((x[0], x[1]) for x, d in candidates if d <= best + tie))
    chosen = near[0]
    others = [d for x, d in candidates
              if max(abs(x[0] - chosen[0]), abs(x[1] - chosen[1])) > 1e-6]
    unique = all(d > best + 1e-9 * s.scale for d in others)
    return [float(chosen[0]), float(chosen[1])], float(s.dist(chosen[0], chosen[1], [mp.mpf(c) for c in q], True)), unique


def case_json(s, queries):
    out = {"name": s.name, "kind": s.kind, "rows": s.rows, "cols": s.cols,
           "degree_u": s.p, "degree_v": s.q, "scale": repr(s.scale),
           "knots_u": [repr(k) for k in s.ku], "knots_v": [repr(k) for k in s.kv],
           "weights": [repr(w) for w in s.weights] if s.weights else None,
           "control_points": [[repr(c) for c in pt] for pt in s.points], "queries": []}
    for q in queries:
        uv, d, unique = nearest(s, q)
        out["queries"].append({"point": [repr(float(c)) for c in q], "u": repr(uv[0]),
                               "v": repr(uv[1]), "distance": repr(d), "unique": unique})
        print(s.name, q, uv, d, unique, flush=True)
    return out


def main():
    hill_z = [[0, 0.5, 0.5, 0], [0.5, 2, 2, 0.5], [0.5, 2, 1.5, 0.5], [0, 0.5, 0.5, 0]]
    hill_pts = [(i, j, hill_z[i][j]) for i in range(4) for j in range(4)]
    bez = [0, 0, 0, 0, 1, 1, 1, 1]
    hill = Surface("examples/surface.toml", "bezier-surface", 4, 4, 3, 3, bez, bez, hill_pts)
    on = [float(c) for c in hill.at(mp.mpf("0.3"), mp.mpf("0.6"), True)]
    cases = [case_json(hill, [tuple(on), (1.5, 1.5, 3.0), (1.5, 1.5, -1.0), (0.0, 0.0, 0.0),
                              (-1.0, -1.0, 0.5), (4.0, 1.0, 0.2), (1.0, 4.0, 1.0),
                              (20.0, -10.0, 5.0), (0.7, 2.2, 1.2)])]
    h = 0.7071067811865476
    cyl_pts = [(1, 0, 0), (1, 0, 1), (1, 0, 2), (1, 1, 0), (1, 1, 1), (1, 1, 2),
               (0, 1, 0), (0, 1, 1), (0, 1, 2)]
    cyl = Surface("examples/nurbs-surface.json", "nurbs-surface", 3, 3, 2, 1,
                  [0, 0, 0, 1, 1, 1], [0, 0, 0.5, 1, 1], cyl_pts,
                  weights=[1, 1, 1, h, h, h, 1, 1, 1])
    cases.append(case_json(cyl, [(0.0, 0.0, 1.0), (2.0, 2.0, 0.5), (0.3, 0.4, 1.5),
                                 (-1.0, -1.0, 1.0), (1.0, 0.2, 3.0), (0.6, 0.8, 1.0)]))
    grid = []
    zs = [0, 1, -1, 2, 0.5, 1.5, -0.5, 0, 2, 1, 1, 0]
    for i in range(4):
        for j in range(3):
            grid.append((float(i), j * 1.5, float(zs[i * 3 + j])))
    bsp = Surface("biquadratic_bspline", "bspline-surface", 4, 3, 2, 2,
                  [0, 0, 0, 0.4, 1, 1, 1], [0, 0, 0, 1, 1, 1], grid)
    cases.append(case_json(bsp, [(1.0, 1.0, 3.0), (2.0, 2.0, -2.0), (0.5, 0.5, 0.0),
                                 (3.5, 3.5, 0.5), (1.7, 0.4, 0.9)]))
    data = {
        "description": "Nearest points of surfaces: 121 x 121 samples per patch, L-BFGS-B from "
                       "the 12 best, Newton polish in mpmath at 40 digits; ties within 1e-12 of "
                       "the scale go to the smallest u, then v.",
        "generator": "scripts/reference/make_surface_nearest_reference.py",
        "cases": cases,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "..", "..", "crates", "neutrospline", "tests", "data",
                        "surface_nearest.json")
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
