#!/usr/bin/env python3
"""Independent reference values for neutrospline's nearest points (`NearestPoint::nearest`).

How to run (from the repository root):

    python3 -m venv /tmp/venv-ref \
      && /tmp/venv-ref/bin/pip install numpy mpmath \
      && /tmp/venv-ref/bin/python scripts/reference/make_nearest_reference.py

Method (independent of the core's branch and bound): each curve is evaluated by the explicit
Cox-de Boor basis sum (rational quotient for NURBS) in mpmath at 40 digits on the exact double
inputs. For every query point the distance is sampled densely (2,000 parameters per Bézier
piece, ends included, in float64 with numpy); every sampled local minimum whose distance is
within 1e-6 of the scale of the smallest is refined by golden-section search in mpmath on its
bracket of neighbouring samples (70 digits of working precision, 200 iterations), ends kept
as candidates. The global minimum is the smallest refined distance; distances within 1e-12
of the curve's scale are ties, broken by the smaller parameter. `unique` is false when
another local minimum, at a parameter more than 1e-6 away, comes within 1e-9 of the scale of
the minimum (then only the distance is compared).

Cases: the paper's Example 1 (Bézier) with points on it, at and beyond its ends and far
away; a cubic with a cusp at t = 1/2 and points at and near it; `examples/bspline.toml`;
the unit circle `examples/nurbs-circle.toml` with its centre (every point nearest: the start
is reported), points outside on the seam (t = 0 and t = 1 tie: 0 is reported) and inside;
the helix `examples/helix3d.toml` (3-D); seeded random B-spline and NURBS curves with random
query points. Written to `crates/neutrospline/tests/data/nearest.json`.
"""

import json
import os
import random

import mpmath as mp
import numpy as np

mp.mp.dps = 70


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


def basis(knots, p, k, t):
    """Cox-de Boor values N_{i,p}(t) on span k, as a dict i -> value (any number type)."""
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


class Curve:
    def __init__(self, name, kind, degree, points, weights=None, knots=None):
        self.name, self.kind, self.degree = name, kind, degree
        self.points = points  # list of (x, y[, z]) floats
        self.weights = weights
        if knots is None:
            knots = [0.0] * (degree + 1) + [1.0] * (degree + 1)
        self.knots = knots
        self.dim = len(points[0])
        self.mknots = [mp.mpf(k) for k in knots]
        self.mpoints = [[mp.mpf(c) for c in p] for p in points]
        self.mweights = [mp.mpf(w) for w in weights] if weights else None
        lo = np.min(np.array(points), axis=0)
        hi = np.max(np.array(points), axis=0)
        self.scale = float(np.linalg.norm(hi - lo))

    def at(self, t, exact=True):
        knots = self.mknots if exact else self.knots
        k = span(knots, self.degree, t)
        n = basis(knots, self.degree, k, t)
        pts = self.mpoints if exact else self.points
        ws = self.mweights if exact else self.weights
        num = [0] * self.dim
        den = 0
        for i, b in n.items():
            w = ws[i] if ws else 1
            den += w * b
            for a in range(self.dim):
                num[a] += w * b * pts[i][a]
        return [x / den for x in num]

    def pieces(self):
        p = self.degree
        u = self.knots
        return [(u[k], u[k + 1]) for k in range(p, len(u) - p - 1) if u[k] < u[k + 1]]


def dist(curve, t, q, exact=True):
    c = curve.at(t, exact)
    return mp.sqrt(sum((c[a] - q[a]) ** 2 for a in range(curve.dim))) if exact else \
        float(np.sqrt(sum((c[a] - q[a]) ** 2 for a in range(curve.dim))))


def golden(curve, q, a, b):
    a, b = mp.mpf(a), mp.mpf(b)
    g = (mp.sqrt(5) - 1) / 2
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = dist(curve, c, q), dist(curve, d, q)
    for _ in range(200):
        if fc <= fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = dist(curve, c, q)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = dist(curve, d, q)
    t = (a + b) / 2
    return t, dist(curve, t, q)


def nearest(curve, q):
    ts = []
    for (a, b) in curve.pieces():
        ts.extend(np.linspace(a, b, 2001)[:-1].tolist())
    ts.append(curve.pieces()[-1][1])
    ds = [dist(curve, t, q, exact=False) for t in ts]
    dmin = min(ds)
    window = 1e-6 * max(curve.scale, dmin)
    qm = [mp.mpf(x) for x in q]
    # The two ends of the domain are always candidates.
    candidates = [(mp.mpf(ts[0]), dist(curve, mp.mpf(ts[0]), qm)),
                  (mp.mpf(ts[-1]), dist(curve, mp.mpf(ts[-1]), qm))]
    minima = []
    for i, d in enumerate(ds):
        if d > dmin + window:
            continue
        left = ds[i - 1] if i > 0 else float("inf")
        right = ds[i + 1] if i + 1 < len(ds) else float("inf")
        if d <= left and d <= right:
            minima.append((d, i))
    # At most the 20 nearest sampled minima are refined (a circle seen from its centre has
    # thousands, all ties with the start).
    for d, i in sorted(minima)[:20]:
        lo = ts[max(i - 1, 0)]
        hi = ts[min(i + 1, len(ts) - 1)]
        candidates.append(golden(curve, qm, lo, hi))
    best = min(d for _, d in candidates)
    tie = 1e-12 * curve.scale
    chosen = min((t for t, d in candidates if d <= best + tie))
    others = [d for t, d in candidates if abs(t - chosen) > 1e-6]
    unique = all(d > best + 1e-9 * curve.scale for d in others)
    return float(chosen), float(dist(curve, chosen, qm)), unique


def case_json(curve, queries):
    out = {"name": curve.name, "kind": curve.kind, "degree": curve.degree,
           "dimension": curve.dim, "scale": repr(curve.scale),
           "knots": [repr(float(k)) for k in curve.knots],
           "weights": [repr(float(w)) for w in curve.weights] if curve.weights else None,
           "control_points": [[repr(float(c)) for c in p] for p in curve.points],
           "queries": []}
    for q in queries:
        t, d, unique = nearest(curve, q)
        out["queries"].append({"point": [repr(float(c)) for c in q], "t": repr(t),
                               "distance": repr(d), "unique": unique})
        print(curve.name, q, t, d, unique)
    return out


def clamped_uniform(p, count):
    inner = count - p - 1
    return [0.0] * (p + 1) + [i / (inner + 1) for i in range(1, inner + 1)] + [1.0] * (p + 1)


def main():
    rng = random.Random(20261201)
    cases = []
    ex1 = Curve("example1", "bezier", 3, [(1.0, 3.0), (3.0, 6.0), (6.0, 2.0), (9.0, 5.0)])
    on = [float(c) for c in ex1.at(mp.mpf(0.5))]
    on2 = [float(c) for c in ex1.at(mp.mpf("0.8125"))]
    cases.append(case_json(ex1, [tuple(on), tuple(on2), (1.0, 3.0), (9.0, 5.0), (0.0, 2.0),
                                 (10.0, 6.0), (1000.0, -500.0), (-1e4, 3e4), (4.0, 5.0),
                                 (5.0, 3.0), (6.0, 4.5), (2.0, 4.0)]))
    cusp = Curve("cusp", "bezier", 3, [(0.0, 0.0), (2.0, 2.0), (0.0, 2.0), (2.0, 0.0)])
    cases.append(case_json(cusp, [(1.0, 1.5), (1.0, 1.7), (1.0, 1.4), (1.2, 1.5), (0.9, 1.6),
                                  (3.0, -1.0)]))
    bsp = Curve("examples/bspline.toml", "bspline", 3,
                [(0, 0), (1, 2), (3, 3), (4, 1), (6, 0), (7, 2), (9, 3)],
                knots=[0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1])
    cases.append(case_json(bsp, [(2.0, 1.0), (4.5, 3.0), (5.0, 0.0), (8.0, 1.0), (-1.0, -1.0),
                                 (10.0, 4.0), (4.5, -20.0), (3.3, 2.1)]))
    h = 0.7071067811865476
    circle = Curve("examples/nurbs-circle.toml", "nurbs", 2,
                   [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)],
                   weights=[1, h, 1, h, 1, h, 1, h, 1],
                   knots=[0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1])
    cases.append(case_json(circle, [(0.0, 0.0), (2.0, 0.0), (0.0, 3.0), (0.3, 0.4),
                                    (-0.6, -0.8), (0.5, -0.1), (-3.0, 0.5), (100.0, 1.0)]))
    helix = Curve("examples/helix3d.toml", "bezier", 3,
                  [(1.0, 0.0, 0.0), (1.0, 0.5522847498, 0.25), (0.5522847498, 1.0, 0.5),
                   (0.0, 1.0, 0.75)])
    cases.append(case_json(helix, [(0.0, 0.0, 0.0), (1.0, 1.0, 1.0), (0.7, 0.7, 0.4),
                                   (2.0, 0.0, -1.0), (0.0, 2.0, 2.0)]))
    for index in range(4):
        p = [2, 3, 3, 5][index]
        count = p + 1 + rng.randint(1, 6)
        pts = [(rng.uniform(-10, 10), rng.uniform(-10, 10)) for _ in range(count)]
        rational = index % 2 == 1
        weights = [rng.uniform(0.3, 3.0) for _ in range(count)] if rational else None
        curve = Curve(f"random_{index}", "nurbs" if rational else "bspline", p, pts,
                      weights=weights, knots=clamped_uniform(p, count))
        queries = [(rng.uniform(-15, 15), rng.uniform(-15, 15)) for _ in range(8)]
        cases.append(case_json(curve, queries))
    data = {
        "description": "Nearest points: dense sampling (2,000 per piece) then golden-section "
                       "refinement in mpmath at 70 digits of every near local minimum; ties "
                       "within 1e-12 of the scale go to the smaller parameter.",
        "generator": "scripts/reference/make_nearest_reference.py",
        "cases": cases,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "..", "..", "crates", "neutrospline", "tests", "data", "nearest.json")
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
