#!/usr/bin/env python3
"""Independent reference values for neutrospline's curve intersections (`intersections`,
`self_intersections`).

How to run (from the repository root):

    python3 -m venv /tmp/venv-ref \
      && /tmp/venv-ref/bin/pip install numpy mpmath \
      && /tmp/venv-ref/bin/python scripts/reference/make_intersection_reference.py

Method (independent of the core's subdivision): both curves are sampled densely (2,000
parameters per Bézier piece) and the crossings of the two polylines found (numpy); each
crossing, and each pair of sampled points closer than 1e-3 of the size (tangential contacts,
end points), starts Newton's method on A(s) - B(t) = 0 in mpmath at 50 digits on the explicit
Cox-de Boor basis sums of the exact double inputs (derivatives by mpmath.diff); where the
Jacobian is singular (a tangency) the system A'(s) x B'(t) = 0, (A(s) - B(t)) . A'(s) = 0 is
solved instead. Converged roots inside the domains with |A - B| < 1e-30 are kept, merged when
within 1e-9 in both parameters; self-intersections keep s < t with t - s > 1e-6. Written to
`crates/neutrospline/tests/data/intersections.json`.

Cases: a line through the unit circle of `examples/nurbs-circle.toml`; the unit circle and
the unit circle centred at (0, 2) (tangent at (0, 1)); a cubic's self-intersection loop; two
cubics meeting at their ends (and crossing once more); seeded random pairs of a cubic
B-spline and a Bézier or NURBS curve.
"""

import json
import os
import random

import mpmath as mp
import numpy as np

mp.mp.dps = 50


def span(knots, p, t):
    n = len(knots) - p - 1
    if t >= knots[n]:
        k = n - 1
        while knots[k] == knots[k + 1]:
            k -= 1
        return k
    if t < knots[p]:
        return p
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


class Curve:
    def __init__(self, kind, degree, points, weights=None, knots=None):
        self.kind, self.degree = kind, degree
        self.points = [tuple(float(c) for c in p) for p in points]
        self.weights = [float(w) for w in weights] if weights else None
        if knots is None:
            knots = [0.0] * (degree + 1) + [1.0] * (degree + 1)
        self.knots = [float(k) for k in knots]
        self.mk = [mp.mpf(k) for k in self.knots]
        self.mp = [[mp.mpf(c) for c in p] for p in self.points]
        self.mw = [mp.mpf(w) for w in self.weights] if self.weights else None
        self.domain = (self.knots[degree], self.knots[len(self.points)])

    def at(self, t, exact=True):
        k = self.mk if exact else self.knots
        pts = self.mp if exact else self.points
        ws = self.mw if exact else self.weights
        n = basis(k, self.degree, t)
        num = [0, 0]
        den = 0
        for i, b in n.items():
            w = ws[i] if ws else 1
            den += w * b
            num[0] += w * b * pts[i][0]
            num[1] += w * b * pts[i][1]
        return [num[0] / den, num[1] / den]

    def d(self, t, order=1):
        return [mp.diff(lambda x: self.at(x)[c], t, order) for c in range(2)]

    def samples(self):
        p = self.degree
        ts = []
        for k in range(p, len(self.points)):
            if self.knots[k] < self.knots[k + 1]:
                ts.extend(np.linspace(self.knots[k], self.knots[k + 1], 2001)[:-1].tolist())
        ts.append(self.domain[1])
        return np.array(ts), np.array([self.at(t, False) for t in ts])

    def json(self):
        return {"kind": self.kind, "degree": self.degree,
                "knots": [repr(k) for k in self.knots],
                "weights": [repr(w) for w in self.weights] if self.weights else None,
                "control_points": [[repr(c) for c in p] for p in self.points]}


def clampd(c, t):
    return min(max(t, mp.mpf(c.domain[0])), mp.mpf(c.domain[1]))


def newton(a, b, s, t):
    s, t = mp.mpf(s), mp.mpf(t)
    for _ in range(100):
        pa, pb = a.at(s), b.at(t)
        f = [pa[0] - pb[0], pa[1] - pb[1]]
        va, vb = a.d(s), b.d(t)
        det = -va[0] * vb[1] + vb[0] * va[1]
        if abs(det) < mp.mpf(10) ** -20 * (1 + abs(va[0]) + abs(va[1])) * (1 + abs(vb[0]) + abs(vb[1])):
            break
        ds = (vb[0] * f[1] - f[0] * vb[1]) / det
        dt = (va[0] * f[1] - f[0] * va[1]) / det
        ns, nt = clampd(a, s - ds), clampd(b, t - dt)
        if abs(ns - s) + abs(nt - t) < mp.mpf(10) ** -45:
            s, t = ns, nt
            break
        s, t = ns, nt
    pa, pb = a.at(s), b.at(t)
    if mp.sqrt((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2) < mp.mpf(10) ** -30:
        return s, t
    # Tangency system.
    for _ in range(100):
        pa, pb = a.at(s), b.at(t)
        f = [pa[0] - pb[0], pa[1] - pb[1]]
        va, vb = a.d(s), b.d(t)
        aa, bb = a.d(s, 2), b.d(t, 2)
        cross = lambda p, q: p[0] * q[1] - p[1] * q[0]
        dot = lambda p, q: p[0] * q[0] + p[1] * q[1]
        g = [cross(va, vb), dot(f, va)]
        j = [[cross(aa, vb), cross(va, bb)], [dot(va, va) + dot(f, aa), -dot(vb, va)]]
        det = j[0][0] * j[1][1] - j[0][1] * j[1][0]
        if det == 0:
            break
        ds = (g[0] * j[1][1] - j[0][1] * g[1]) / det
        dt = (j[0][0] * g[1] - j[1][0] * g[0]) / det
        ns, nt = clampd(a, s - ds), clampd(b, t - dt)
        if abs(ns - s) + abs(nt - t) < mp.mpf(10) ** -45:
            s, t = ns, nt
            break
        s, t = ns, nt
    pa, pb = a.at(s), b.at(t)
    if mp.sqrt((pa[0] - pb[0]) ** 2 + (pa[1] - pb[1]) ** 2) < mp.mpf(10) ** -30:
        return s, t
    return None


def starts(a, b, same):
    ta, pa = a.samples()
    tb, pb = b.samples()
    size = float(np.linalg.norm(np.vstack([pa, pb]).max(axis=0) - np.vstack([pa, pb]).min(axis=0)))
    out = []
    # Crossings of the polylines.
    a0, a1 = pa[:-1], pa[1:]
    for j in range(len(pb) - 1):
        b0, b1 = pb[j], pb[j + 1]
        r = a1 - a0
        q = b1 - b0
        den = r[:, 0] * q[1] - r[:, 1] * q[0]
        w = b0 - a0
        with np.errstate(divide="ignore", invalid="ignore"):
            u = (w[:, 0] * q[1] - w[:, 1] * q[0]) / den
            v = (w[:, 0] * r[:, 1] - w[:, 1] * r[:, 0]) / den
        hits = np.nonzero((den != 0) & (u >= -1e-9) & (u <= 1 + 1e-9) & (v >= -1e-9) & (v <= 1 + 1e-9))[0]
        for i in hits:
            out.append((ta[i] + u[i] * (ta[i + 1] - ta[i]), tb[j] + v[i] * (tb[j + 1] - tb[j])))
    # Near contacts (tangencies, end points): local minima of the sampled distance.
    step = 10
    sa, sb = pa[::step], pb[::step]
    d = np.sqrt(((sa[:, None, :] - sb[None, :, :]) ** 2).sum(axis=2))
    for i, j in zip(*np.nonzero(d < 1e-2 * size)):
        block = d[max(i - 1, 0):i + 2, max(j - 1, 0):j + 2]
        if d[i, j] <= block.min():
            out.append((ta[::step][i], tb[::step][j]))
    # Crossings found twice (at a shared sample) are started once.
    out = sorted(set((round(s, 6), round(t, 6)) for s, t in out))
    return out


def solve(a, b, same=False):
    roots = []
    for s, t in starts(a, b, same):
        r = newton(a, b, s, t)
        if r is None:
            continue
        s, t = r
        if same:
            if s > t:
                s, t = t, s
            if t - s <= 1e-6:
                continue
        if any(abs(s - x) <= 1e-9 and abs(t - y) <= 1e-9 for x, y in roots):
            continue
        roots.append((s, t))
    roots.sort()
    return [{"t_a": repr(float(s)), "t_b": repr(float(t)),
             "x": repr(float(a.at(s)[0])), "y": repr(float(a.at(s)[1]))} for s, t in roots]


def main():
    h = 0.7071067811865476
    ring = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    cw = [1, h, 1, h, 1, h, 1, h, 1]
    ck = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    circle = Curve("nurbs", 2, ring, cw, ck)
    upper = Curve("nurbs", 2, [(x, y + 2) for x, y in ring], cw, ck)
    line = Curve("bezier", 1, [(-2.0, 0.3), (2.0, 0.7)])
    loop = Curve("bezier", 3, [(0, 0), (4, 2), (-1, 2), (3, 0)])
    first = Curve("bezier", 3, [(0, 0), (1, 2), (2, -1), (3, 1)])
    second = Curve("bezier", 3, [(3, 1), (2, 3), (1, -2), (0.5, 1.5)])
    cases = [
        {"name": "line through the circle", "a": line, "b": circle},
        {"name": "tangent circles", "a": circle, "b": upper},
        {"name": "cubic loop", "a": loop, "b": loop, "same": True},
        {"name": "cubics meeting at their ends", "a": first, "b": second},
    ]
    rng = random.Random(20261201)
    for k in range(4):
        n = 6
        pts = [(i * 2.0 + rng.uniform(-0.5, 0.5), rng.uniform(-3, 3)) for i in range(n)]
        inner = [0.0] * 4 + [1 / 3, 2 / 3] + [1.0] * 4
        a = Curve("bspline", 3, pts, knots=inner)
        bpts = [(rng.uniform(0, 10), rng.uniform(-3, 3)) for _ in range(4)]
        if k % 2:
            b = Curve("nurbs", 3, bpts, [rng.uniform(0.5, 2.0) for _ in range(4)],
                      [0, 0, 0, 0, 1, 1, 1, 1])
        else:
            b = Curve("bezier", 3, bpts)
        cases.append({"name": f"random {k}", "a": a, "b": b})
    out = []
    for c in cases:
        same = c.get("same", False)
        roots = solve(c["a"], c["b"], same)
        print(c["name"], [(r["t_a"], r["t_b"]) for r in roots], flush=True)
        out.append({"name": c["name"], "same": same, "a": c["a"].json(), "b": c["b"].json(),
                    "intersections": roots})
    data = {
        "description": "Curve intersections: polyline crossings and near contacts of dense "
                       "samples, Newton's method (or the tangency system) in mpmath at 50 "
                       "digits; self-intersections with t_a < t_b.",
        "generator": "scripts/reference/make_intersection_reference.py",
        "cases": out,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "..", "..", "crates", "neutrospline", "tests", "data",
                        "intersections.json")
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
