"""Independent references for the differential harness: curves and surfaces evaluated from
their definitions, nearest points by dense sampling and refinement, intersections by Newton's
method from a dense set of starts. Nothing here imports or mirrors the library's code.

The mathematics (docs/model.md sections 2-4, 10 and 11):

* A Bézier curve of degree n is C(t) = sum_i B_{n,i}(t) P_i with the Bernstein polynomials
  B_{n,i}(t) = C(n, i) t^i (1 - t)^(n - i), binomials exact (`math.comb`); its derivative is the
  Bézier curve of degree n - 1 with control points n (P_{i+1} - P_i) (the hodograph).
* A B-spline curve of degree p over knots u_0 <= ... <= u_m is C(t) = sum_i N_{i,p}(t) P_i on
  the domain [u_p, u_{m-p}]; the basis is the Cox-de Boor recursion
  N_{i,0} = 1 on [u_i, u_{i+1}), N_{i,d} = (t - u_i)/(u_{i+d} - u_i) N_{i,d-1}
  + (u_{i+d+1} - t)/(u_{i+d+1} - u_{i+1}) N_{i+1,d-1} (0/0 = 0), evaluated on one knot span
  at a time (so a piece is a polynomial up to both of its ends, derivatives one-sided there);
  its derivative is the B-spline of degree p - 1 over u_1 ... u_{m-1} with control points
  p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1}).
* A NURBS curve is the B-spline of the homogeneous points (w_i P_i, w_i) divided by its last
  coordinate: C = A / W, C' = (A' - C W') / W, C'' = (A'' - 2 C' W' - C W'') / W.
* A tensor-product surface S(u, v) = sum_i sum_j N_i(u) M_j(v) P_ij (row index i along u) is
  evaluated as the u-curve of the v-curves of its rows, rational the same way.

Every function here takes its parameter either as a float / numpy array (dense sampling and
float refinement) or as an mpmath number at `mp.dps = DIGITS` (the final polish and every
distance used for a verdict). Inputs are the exact doubles of the model files.
"""

from __future__ import annotations

import json
import math
import random
from dataclasses import dataclass, field

import mpmath as mp
import numpy as np

DIGITS = 40
mp.mp.dps = DIGITS

# --------------------------------------------------------------------------------------------
# Evaluation
# --------------------------------------------------------------------------------------------


def _diff_bezier(ctrl):
    """The hodograph's control points: n (P_{i+1} - P_i)."""
    n = len(ctrl) - 1
    return [[n * (b - a) for a, b in zip(p, q)] for p, q in zip(ctrl[:-1], ctrl[1:])]


def _diff_bspline(ctrl, knots, p):
    """The derivative B-spline: degree p - 1, knots u_1 ... u_{m-1}, points
    p (P_{i+1} - P_i) / (u_{i+p+1} - u_{i+1}) (0 where that span is empty)."""
    out = []
    for i in range(len(ctrl) - 1):
        den = knots[i + p + 1] - knots[i + 1]
        if den == 0:
            out.append([0 * c for c in ctrl[i]])
        else:
            out.append([p * (b - a) / den for a, b in zip(ctrl[i], ctrl[i + 1])])
    return out, knots[1:-1]


def bernstein_sum(ctrl, t):
    """sum_i C(n, i) t^i (1 - t)^(n - i) P_i, one list entry per coordinate."""
    n = len(ctrl) - 1
    s = 1 - t
    total = [0 * t for _ in ctrl[0]]
    for i, point in enumerate(ctrl):
        b = math.comb(n, i) * t**i * s ** (n - i)
        total = [acc + b * c for acc, c in zip(total, point)]
    return total


def cox_de_boor(knots, p, k, t):
    """N_{k-p,p}(t) ... N_{k,p}(t) on the span [u_k, u_{k+1}] by the recursion (0/0 = 0)."""
    basis = [1 + 0 * t]  # N_{k,0}
    for d in range(1, p + 1):
        nxt = []
        for i in range(k - d, k + 1):
            value = 0 * t
            # N_{i,d-1} is basis[i - (k - d + 1)] when k - d + 1 <= i <= k
            left = basis[i - (k - d + 1)] if k - d + 1 <= i <= k else None
            right = basis[i + 1 - (k - d + 1)] if k - d + 1 <= i + 1 <= k else None
            den = knots[i + d] - knots[i]
            if left is not None and den != 0:
                value = value + (t - knots[i]) / den * left
            den = knots[i + d + 1] - knots[i + 1]
            if right is not None and den != 0:
                value = value + (knots[i + d + 1] - t) / den * right
            nxt.append(value)
        basis = nxt
    return basis


def bspline_sum(ctrl, knots, p, k, t):
    basis = cox_de_boor(knots, p, k, t)
    total = [0 * t for _ in ctrl[0]]
    for b, point in zip(basis, ctrl[k - p : k + 1]):
        total = [acc + b * c for acc, c in zip(total, point)]
    return total


class Poly:
    """One homogeneous polynomial piece source: a Bézier curve or a B-spline, with its first two
    derivative curves, control points given as lists of coordinates (any number type)."""

    def __init__(self, ctrl, degree, knots=None):
        self.degree = degree
        self.knots = knots
        self.levels = [ctrl]
        if knots is None:
            c = ctrl
            for _ in range(2):
                c = _diff_bezier(c) if len(c) > 1 else [[0 * x for x in c[0]]]
                self.levels.append(c)
        else:
            c, kn, p = ctrl, knots, degree
            self.level_knots = [knots]
            for _ in range(2):
                if p == 0:
                    c, kn = [[0 * x for x in q] for q in c], kn
                else:
                    c, kn = _diff_bspline(c, kn, p)
                    p -= 1
                self.levels.append(c)
                self.level_knots.append(kn)

    def eval(self, span, t, order=2):
        """Values and derivatives up to `order` at t on knot span `span` (ignored for Bézier)."""
        out = []
        for r in range(order + 1):
            ctrl = self.levels[r]
            if self.knots is None:
                if self.degree - r < 0:
                    out.append([0 * t for _ in ctrl[0]])
                else:
                    out.append(bernstein_sum(ctrl, t))
            else:
                p = self.degree - r
                if p < 0:
                    out.append([0 * t for _ in ctrl[0]])
                else:
                    out.append(bspline_sum(ctrl, self.level_knots[r], p, span - r, t))
        return out


def _rational(h, order):
    """Cartesian value and derivatives from homogeneous ones (last coordinate the weight)."""
    a = [v[:-1] for v in h]
    w = [v[-1] for v in h]
    c0 = [x / w[0] for x in a[0]]
    out = [c0]
    if order >= 1:
        c1 = [(x1 - x0 * w[1]) / w[0] for x0, x1 in zip(c0, a[1])]
        out.append(c1)
    if order >= 2:
        c2 = [(x2 - 2 * y1 * w[1] - x0 * w[2]) / w[0] for x0, y1, x2 in zip(c0, c1, a[2])]
        out.append(c2)
    return out


@dataclass
class Curve:
    """A curve as its model file gives it: kind 'bezier' | 'bspline' | 'nurbs', control points
    (2 or 3 coordinates), weights (NURBS), knots (B-spline and NURBS)."""

    kind: str
    degree: int
    points: list
    weights: list | None = None
    knots: list | None = None
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def dim(self):
        return len(self.points[0])

    def model(self):
        cps = []
        for i, p in enumerate(self.points):
            cp = {"x": p[0], "y": p[1]}
            if len(p) == 3:
                cp["z"] = p[2]
            if self.kind == "nurbs":
                cp["weight"] = self.weights[i]
            cp.update({"truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125})
            cps.append(cp)
        m = {"kind": self.kind, "control_points": cps}
        if self.kind != "bezier":
            m["degree"] = self.degree
            m["knots"] = list(self.knots)
        return m

    def to_json(self):
        return {
            "kind": self.kind,
            "degree": self.degree,
            "points": [list(p) for p in self.points],
            "weights": self.weights,
            "knots": self.knots,
        }

    @staticmethod
    def from_json(d):
        return Curve(d["kind"], d["degree"], [tuple(p) for p in d["points"]], d.get("weights"), d.get("knots"))

    @property
    def domain(self):
        if self.kind == "bezier":
            return (0.0, 1.0)
        p = self.degree
        return (self.knots[p], self.knots[len(self.knots) - 1 - p])

    def spans(self):
        """(span index, start, end) of every non-empty knot span of the domain."""
        if self.kind == "bezier":
            return [(0, 0.0, 1.0)]
        p, kn = self.degree, self.knots
        n = len(self.points) - 1
        return [(k, kn[k], kn[k + 1]) for k in range(p, n + 1) if kn[k] < kn[k + 1]]

    def size(self):
        pts = np.array(self.points, dtype=float)
        return float(np.linalg.norm(pts.max(axis=0) - pts.min(axis=0)))

    def _poly(self, exact):
        key = "mp" if exact else "float"
        if key not in self._cache:
            conv = mp.mpf if exact else float
            w = self.weights if self.kind == "nurbs" else [1.0] * len(self.points)
            ctrl = [[conv(wi) * conv(c) for c in p] + [conv(wi)] for p, wi in zip(self.points, w)]
            knots = None if self.kind == "bezier" else [conv(k) for k in self.knots]
            self._cache[key] = Poly(ctrl, self.degree, knots)
        return self._cache[key]

    def eval(self, span, t, order=2):
        """[C, C', C''] (up to order) at t on the given span; mp when t is an mpf."""
        exact = isinstance(t, mp.mpf)
        return _rational(self._poly(exact).eval(span, t, order), order)

    def point(self, t, order=0):
        """C(t) on the span holding t (the right one at an interior knot, the last at the end)."""
        spans = self.spans()
        chosen = spans[-1][0]
        for k, a, b in spans:
            if a <= t < b:
                chosen = k
                break
        return self.eval(chosen, t, order)

    def sample(self, span, a, b, count):
        ts = np.linspace(a, b, count)
        pts = self.eval(span, ts, 0)[0]
        return ts, np.stack([np.broadcast_to(c, ts.shape) for c in pts], axis=1)


@dataclass
class Surface:
    """A tensor-product surface: kind 'bezier-surface' | 'bspline-surface' | 'nurbs-surface',
    grid[i][j] (row i along u) of 3-D points, optional weights grid, knots_u / knots_v."""

    kind: str
    degree_u: int
    degree_v: int
    grid: list
    weights: list | None = None
    knots_u: list | None = None
    knots_v: list | None = None

    def model(self):
        rows, cols = len(self.grid), len(self.grid[0])
        cps = []
        for i in range(rows):
            for j in range(cols):
                x, y, z = self.grid[i][j]
                cp = {"x": x, "y": y, "z": z}
                if self.kind == "nurbs-surface":
                    cp["weight"] = self.weights[i][j]
                cp.update({"truth": 0.5, "indeterminacy": 0.25, "falsity": 0.125})
                cps.append(cp)
        m = {"kind": self.kind, "rows": rows, "cols": cols, "degree_u": self.degree_u, "degree_v": self.degree_v, "control_points": cps}
        if self.kind != "bezier-surface":
            m["knots_u"] = list(self.knots_u)
            m["knots_v"] = list(self.knots_v)
        return m

    def to_json(self):
        return {
            "kind": self.kind,
            "degree_u": self.degree_u,
            "degree_v": self.degree_v,
            "grid": self.grid,
            "weights": self.weights,
            "knots_u": self.knots_u,
            "knots_v": self.knots_v,
        }

    @staticmethod
    def from_json(d):
        return Surface(d["kind"], d["degree_u"], d["degree_v"], d["grid"], d.get("weights"), d.get("knots_u"), d.get("knots_v"))

    def _curve(self, kind, degree, pts, weights, knots):
        return Curve(kind, degree, pts, weights, knots)

    def row_curve(self, i):
        """The v-curve of row i (as a curve object of the same kind along v)."""
        kind = self.kind.replace("-surface", "")
        w = self.weights[i] if self.weights else None
        return Curve(kind, self.degree_v, [tuple(p) for p in self.grid[i]], w, self.knots_v)

    def size(self):
        pts = np.array([p for row in self.grid for p in row], dtype=float)
        return float(np.linalg.norm(pts.max(axis=0) - pts.min(axis=0)))

    def _spans(self, degree, knots, count):
        if knots is None:
            return [(0, 0.0, 1.0)]
        return [(k, knots[k], knots[k + 1]) for k in range(degree, count) if knots[k] < knots[k + 1]]

    def spans_u(self):
        return self._spans(self.degree_u, self.knots_u, len(self.grid))

    def spans_v(self):
        return self._spans(self.degree_v, self.knots_v, len(self.grid[0]))

    def domain_u(self):
        s = self.spans_u()
        return (s[0][1], s[-1][2])

    def domain_v(self):
        s = self.spans_v()
        return (s[0][1], s[-1][2])

    def _polys(self, exact):
        conv = mp.mpf if exact else float
        rows = []
        for i, row in enumerate(self.grid):
            w = self.weights[i] if self.weights else [1.0] * len(row)
            ctrl = [[conv(wi) * conv(c) for c in p] + [conv(wi)] for p, wi in zip(row, w)]
            kv = None if self.knots_v is None else [conv(k) for k in self.knots_v]
            rows.append(Poly(ctrl, self.degree_v, kv))
        ku = None if self.knots_u is None else [conv(k) for k in self.knots_u]
        return rows, ku

    def eval(self, su, u, sv, v):
        """S, S_u, S_v, S_uu, S_uv, S_vv at (u, v) on spans (su, sv)."""
        exact = isinstance(u, mp.mpf)
        key = "mp" if exact else "float"
        cache = self.__dict__.setdefault("_cache", {})
        if key not in cache:
            cache[key] = self._polys(exact)
        rows, ku = cache[key]
        along_v = [r.eval(sv, v, 2) for r in rows]  # per row: [Q, Q_v, Q_vv]
        h = {}
        for r in range(3):
            ctrl = [av[r] for av in along_v]
            poly = Poly(ctrl, self.degree_u, ku)
            vals = poly.eval(su, u, 2 - r)
            for q in range(len(vals)):
                h[(q, r)] = vals[q]
        # rational: H = (A, W); S = A / W and partials by differentiating A = S W
        def split(x):
            return x[:-1], x[-1]

        A = {k: split(v)[0] for k, v in h.items()}
        W = {k: split(v)[1] for k, v in h.items()}
        w0 = W[(0, 0)]
        S = [a / w0 for a in A[(0, 0)]]
        Su = [(a - s * W[(1, 0)]) / w0 for a, s in zip(A[(1, 0)], S)]
        Sv = [(a - s * W[(0, 1)]) / w0 for a, s in zip(A[(0, 1)], S)]
        Suu = [(a - 2 * su_ * W[(1, 0)] - s * W[(2, 0)]) / w0 for a, su_, s in zip(A[(2, 0)], Su, S)]
        Svv = [(a - 2 * sv_ * W[(0, 1)] - s * W[(0, 2)]) / w0 for a, sv_, s in zip(A[(0, 2)], Sv, S)]
        Suv = [
            (a - su_ * W[(0, 1)] - sv_ * W[(1, 0)] - s * W[(1, 1)]) / w0
            for a, su_, sv_, s in zip(A[(1, 1)], Su, Sv, S)
        ]
        return S, Su, Sv, Suu, Suv, Svv


# --------------------------------------------------------------------------------------------
# Nearest point on a curve
# --------------------------------------------------------------------------------------------


# Doubles carry about 1.1e-16 of their magnitude: far from the origin (a curve of size 1e-12 at
# x = 5887) no answer can be closer than a few units of that, so every tolerance adds this
# multiple of the largest coordinate in play.
ROUNDING = 1e-14


def magnitude(*point_lists):
    return max(abs(float(c)) for pts in point_lists for p in pts for c in p)


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _sub(a, b):
    return [x - y for x, y in zip(a, b)]


@dataclass
class Minimum:
    t: object
    distance: object  # mpf
    point: list


# Where g = (C - q) . C' is sampled inside a bracket [lo, hi] (as fractions of it): evenly, and
# geometrically towards both ends, where a stationary end (C' = 0) hides a sign change of g
# next to the end from the end's own value g = 0.
_SUBGRID = np.unique(
    np.concatenate(([0.0, 1.0], np.linspace(0, 1, 17), 10.0 ** -np.arange(1, 15), 1 - 10.0 ** -np.arange(1, 15)))
)


def _refine_curve_min(curve, span, lo, hi, q, exact_q):
    """Local minima of |C(t) - q|^2 on [lo, hi] of one span: the bracket's ends, and every root
    of g = (C - q) . C' where g goes from - to + between points of a sub-grid of the bracket
    (safeguarded Newton in floats)."""

    def g_and_dg(t):
        c, c1, c2 = curve.eval(span, t, 2)
        r = _sub(c, q)
        return _dot(r, c1), _dot(c1, c1) + _dot(r, c2)

    found = [lo, hi]
    ts = lo + (hi - lo) * _SUBGRID
    ts[-1] = hi
    gs, _ = g_and_dg(ts)
    gs = np.broadcast_to(gs, ts.shape)
    for i in np.nonzero((gs[:-1] < 0) & (gs[1:] >= 0))[0]:
        a, b = float(ts[i]), float(ts[i + 1])
        t = 0.5 * (a + b)
        for _ in range(80):
            g, dg = g_and_dg(t)
            if g == 0:
                break
            if g < 0:
                a = t
            else:
                b = t
            step_ok = False
            if dg > 0:
                nt = t - g / dg
                if a < nt < b:
                    step_ok = True
            if not step_ok:
                nt = 0.5 * (a + b)
            if abs(nt - t) <= 1e-17 * max(1.0, abs(t)) or b - a <= 1e-16 * max(1.0, abs(t)):
                t = nt
                break
            t = nt
        found.append(t)
    return found


def nearest_curve(curve: Curve, q, samples_per_span=None, cap=6):
    """Every candidate local minimum of |C(t) - q| (ends of the spans included), measured in mpf.
    Returns the list of Minimum sorted by distance, then parameter."""
    spans = curve.spans()
    n = samples_per_span or max(64, min(400, 24 * (curve.degree + 1)))
    qf = np.array(q, dtype=float)
    exact_q = [mp.mpf(c) for c in q]
    cands = []
    best = math.inf
    all_ts = []
    for k, a, b in spans:
        ts, pts = curve.sample(k, a, b, n)
        d = np.linalg.norm(pts - qf, axis=1)
        chord = np.linalg.norm(np.diff(pts, axis=0), axis=1)
        reach = np.zeros_like(d)
        reach[:-1] = chord
        reach[1:] = np.maximum(reach[1:], chord)
        left = np.concatenate(([np.inf], d[:-1]))
        right = np.concatenate((d[1:], [np.inf]))
        is_min = (d <= left) & (d <= right)
        best = min(best, float(d.min()))
        for i in np.nonzero(is_min)[0]:
            lo = float(ts[max(i - 1, 0)])
            hi = float(ts[min(i + 1, n - 1)])
            cands.append((float(d[i] - reach[i]), float(d[i]), float(ts[i]), k, lo, hi))
        all_ts.append((k, a, b))
    eligible = [c for c in cands if c[0] <= best * (1 + 1e-12) + 1e-300]
    by_bound = sorted(eligible, key=lambda c: (c[0], c[2]))[:cap]
    by_dist = sorted(eligible, key=lambda c: (c[1], c[2]))[: cap // 2]
    by_t = sorted(eligible, key=lambda c: c[2])[:2]
    chosen = {id(c): c for c in by_bound + by_dist + by_t}.values()
    found = []
    for _, _, _, k, lo, hi in chosen:
        for t in _refine_curve_min(curve, k, lo, hi, [float(x) for x in q], exact_q):
            c = np.array([float(x) for x in curve.eval(k, t, 0)[0]])
            found.append((float(np.linalg.norm(c - qf)), t, k, lo, hi))
    # measure in mpf only what can matter for a verdict: within 1e-7 of the size (plus the
    # doubles' resolution) of the best float distance
    size = curve.size() or 1.0
    best_f = min(f[0] for f in found)
    margin = 1e-7 * size + 1e-12 * magnitude(curve.points, [q])
    results = []
    for dist_f, t, k, lo, hi in found:
        if dist_f > best_f + margin:
            continue
        tm = mp.mpf(t)
        if lo < t < hi:
            # two Newton steps on g = (C - q) . C' in mpf, kept inside [lo, hi]
            for _ in range(2):
                c, c1, c2 = curve.eval(k, tm, 2)
                r = _sub(c, exact_q)
                g, dg = _dot(r, c1), _dot(c1, c1) + _dot(r, c2)
                if dg <= 0:
                    break
                nt = tm - g / dg
                if not (lo <= nt <= hi) or abs(nt - tm) > 1e-6 * (hi - lo):
                    break
                tm = nt
        c = curve.eval(k, tm, 0)[0]
        dist = mp.sqrt(_dot(_sub(c, exact_q), _sub(c, exact_q)))
        results.append(Minimum(tm, dist, c))
    results.sort(key=lambda m: (m.distance, m.t))
    return results


def true_distance(curve: Curve, t, q):
    """|C(t) - q| in mpf, C on the span holding t (the right one at an interior knot)."""
    tm = mp.mpf(t)
    c = curve.point(tm, 0)[0]
    r = _sub(c, [mp.mpf(x) for x in q])
    return mp.sqrt(_dot(r, r)), c


def judge_nearest(curve, q, ours_t, ours_distance, ours_point, tol_rel=1e-9, tie_rel=1e-13):
    """None when our answer is right, else a text naming what is wrong.

    Rules: the true distance of our parameter |C(t) - q| (mpf) may exceed the reference's
    minimum by at most tol_rel * size (more is a wrong global minimum) and may be below it by at
    most that (less would mean the reference missed a minimum); the reported point and distance
    agree with C(t); when several minima tie within tie_rel * size, ours is the smallest
    parameter (ambiguous near-ties, within tol_rel but not tie_rel, accept either)."""
    size = curve.size() or 1.0
    tol = tol_rel * size + ROUNDING * magnitude(curve.points, [q])
    mins = nearest_curve(curve, q)
    ref = mins[0]
    d_ours, c_ours = true_distance(curve, ours_t, q)
    # the best a double parameter can do: the reference's parameter rounded, or a neighbour
    # (on a narrow domain far from 0 one unit in the last place can move the point far)
    lo_d, hi_d = curve.domain
    t_d = float(ref.t)
    best_double = min(
        true_distance(curve, min(max(t, lo_d), hi_d), q)[0]
        for t in (t_d, math.nextafter(t_d, -math.inf), math.nextafter(t_d, math.inf))
    )
    problems = []
    if d_ours > best_double + tol:
        problems.append(
            f"wrong global minimum: ours t={ours_t!r} at distance {mp.nstr(d_ours, 17)}, "
            f"reference t={mp.nstr(ref.t, 17)} at distance {mp.nstr(ref.distance, 17)} "
            f"(best double parameter: {mp.nstr(best_double, 17)})"
        )
    if d_ours < ref.distance - tol:
        # Ours nearer than the reference's minimum is no disagreement: `d_ours` is the
        # reference's own evaluation at our parameter, so ours is a true point of the curve and
        # the reference's sampling missed a narrow dip (NURBS with weights 1e-3..3e2). The tie
        # rule below compares with the reference's minima, so it is not applied.
        gap = max(abs(mp.mpf(a) - b) for a, b in zip(ours_point, c_ours))
        if gap > tol:
            problems.append(f"reported point {ours_point} is not C(t) = {[mp.nstr(c, 17) for c in c_ours]} (gap {mp.nstr(gap, 5)})")
        if abs(mp.mpf(ours_distance) - d_ours) > tol:
            problems.append(f"reported distance {ours_distance!r} is not |C(t) - q| = {mp.nstr(d_ours, 17)}")
        return "; ".join(problems) or None
    gap = max(abs(mp.mpf(a) - b) for a, b in zip(ours_point, c_ours))
    if gap > tol:
        problems.append(f"reported point {ours_point} is not C(t) = {[mp.nstr(c, 17) for c in c_ours]} (gap {mp.nstr(gap, 5)})")
    if abs(mp.mpf(ours_distance) - d_ours) > tol:
        problems.append(f"reported distance {ours_distance!r} is not |C(t) - q| = {mp.nstr(d_ours, 17)}")
    if not problems:
        lo, hi = curve.domain
        width = hi - lo
        # the library measures distances in doubles: differences below `noise` are not
        # resolvable, so the tie rule is checked only on ties clearly inside 1e-13 of the size
        noise = 8 * 1.2e-16 * (float(ref.distance) + magnitude(curve.points, [q]))
        if noise > 0.5 * tie_rel * size:
            return None
        ties = [m for m in mins if m.distance <= ref.distance + tie_rel * size - noise]
        near = [m for m in mins if m.distance <= ref.distance + tol]
        tie_ts = sorted(set(float(m.t) for m in ties))
        # tied minima are distinct only when the distance rises above the tie between them (a
        # flat stretch, such as a run of coincident control points, is one minimum)
        qf = np.array(q, dtype=float)

        def rises_between(t0, t1):
            for t in np.linspace(t0, t1, 65)[1:-1]:
                c = np.array([float(x) for x in curve.point(float(t))[0]])
                if np.linalg.norm(c - qf) > float(ref.distance) + 4 * tie_rel * size + 1e-15 * size:
                    return True
            return False

        distinct = []
        for t in tie_ts:
            if not distinct or (t - distinct[-1] > 1e-9 * width and rises_between(distinct[-1], t)):
                distinct.append(t)
        if len(distinct) > 1 and abs(ours_t - distinct[0]) > 1e-7 * width:
            ambiguous = any(
                m.distance > ref.distance + tie_rel * size and abs(float(m.t) - ours_t) <= 1e-7 * width for m in near
            )
            if not ambiguous and ours_t > distinct[0]:
                problems.append(f"tie not broken by the smallest parameter: ours t={ours_t!r}, tied minima at t={distinct}")
    return "; ".join(problems) or None


# --------------------------------------------------------------------------------------------
# Nearest point on a surface
# --------------------------------------------------------------------------------------------


def _boundary_curves(surface: Surface):
    """The four edges as curves (clamped knot vectors, or Bézier): u = start / end (the first /
    last row), v = start / end (the first / last column), with how to map back to (u, v)."""
    kind = surface.kind.replace("-surface", "")
    g, w = surface.grid, surface.weights
    rows, cols = len(g), len(g[0])
    out = []
    u0, u1 = surface.domain_u()
    v0, v1 = surface.domain_v()
    for i, u in ((0, u0), (rows - 1, u1)):
        c = Curve(kind, surface.degree_v, [tuple(p) for p in g[i]], w[i] if w else None, surface.knots_v)
        out.append((c, lambda t, u=u: (u, t)))
    for j, v in ((0, v0), (cols - 1, v1)):
        c = Curve(kind, surface.degree_u, [tuple(g[i][j]) for i in range(rows)], [w[i][j] for i in range(rows)] if w else None, surface.knots_u)
        out.append((c, lambda t, v=v: (t, v)))
    return out


def nearest_surface(surface: Surface, q, grid=32):
    """Candidate minima of |S(u, v) - q|: interior ones by Newton on the gradient from the
    discrete minima of a dense grid on every patch (floats, then mpf), and every edge's
    minima by `nearest_curve` on the edge curves (clamped knots assumed). Sorted by distance,
    then u, then v; each (u, v, distance, point)."""
    qf = np.array(q, dtype=float)
    exact_q = [mp.mpf(c) for c in q]
    results = []
    best_sample = math.inf
    cands = []
    for su, ua, ub in surface.spans_u():
        for sv, va, vb in surface.spans_v():
            us = np.linspace(ua, ub, grid)
            vs = np.linspace(va, vb, grid)
            U, V = np.meshgrid(us, vs, indexing="ij")
            S = surface.eval(su, U, sv, V)[0]
            pts = np.stack([np.broadcast_to(c, U.shape) for c in S], axis=-1)
            d = np.linalg.norm(pts - qf, axis=-1)
            best_sample = min(best_sample, float(d.min()))
            step = max(
                float(np.max(np.linalg.norm(np.diff(pts, axis=0), axis=-1))),
                float(np.max(np.linalg.norm(np.diff(pts, axis=1), axis=-1))),
            )
            pad = np.pad(d, 1, constant_values=np.inf)
            is_min = np.ones_like(d, dtype=bool)
            for di in (-1, 0, 1):
                for dj in (-1, 0, 1):
                    if di or dj:
                        is_min &= d <= pad[1 + di : 1 + di + grid, 1 + dj : 1 + dj + grid]
            for i, j in zip(*np.nonzero(is_min)):
                # minima on the edges start Newton too (an interior minimum may lie next to the
                # edge); the edge curves give the minima on the edges themselves
                if True:
                    cands.append((float(d[i, j]) - step, float(d[i, j]), su, sv, float(us[i]), float(vs[j]), (ua, ub, va, vb)))
    eligible = sorted((c for c in cands if c[0] <= best_sample), key=lambda c: c[1])[:5]
    (ua, ub), (va, vb) = surface.domain_u(), surface.domain_v()
    spans_u, spans_v = surface.spans_u(), surface.spans_v()

    def local(u, v):
        su, sv = _pick(spans_u, u), _pick(spans_v, v)
        S, Su, Sv, Suu, Suv, Svv = surface.eval(su, u, sv, v)
        r = _sub(S, qf)
        grad = (_dot(r, Su), _dot(r, Sv))
        hess = (_dot(Su, Su) + _dot(r, Suu), _dot(Su, Sv) + _dot(r, Suv), _dot(Sv, Sv) + _dot(r, Svv))
        return _dot(r, r), grad, hess, su, sv

    for _, _, su, sv, u, v, box in eligible:
        # Levenberg-Marquardt on |S - q|^2, projected onto the domain, steps kept when they
        # lower the distance
        f, (gu, gv), (huu, huv, hvv), su, sv = local(u, v)
        lam = 0.0
        for it in range(60):
            a, b, c = huu + lam, huv, hvv + lam
            det = a * c - b * b
            if det <= 0 or a <= 0:
                lam = max(2 * lam, 1e-3 * (abs(huu) + abs(hvv)) + 1e-300)
                continue
            du = (c * gu - b * gv) / det
            dv = (a * gv - b * gu) / det
            nu = min(max(u - du, ua), ub)
            nv = min(max(v - dv, va), vb)
            nf, ng, nh, nsu, nsv = local(nu, nv)
            if nf <= f:
                moved = abs(nu - u) + abs(nv - v)
                u, v, f, (gu, gv), (huu, huv, hvv), su, sv = nu, nv, nf, ng, nh, nsu, nsv
                lam *= 0.25
                if moved <= 1e-16 * (ub - ua + vb - va):
                    break
            else:
                lam = max(4 * lam, 1e-6 * (abs(huu) + abs(hvv)) + 1e-300)
                if lam > 1e30 * (abs(huu) + abs(hvv) + 1e-300):
                    break
        um, vm = mp.mpf(u), mp.mpf(v)
        for _ in range(3):
            S, Su, Sv, Suu, Suv, Svv = surface.eval(su, um, sv, vm)
            r = _sub(S, exact_q)
            gu, gv = _dot(r, Su), _dot(r, Sv)
            huu = _dot(Su, Su) + _dot(r, Suu)
            huv = _dot(Su, Sv) + _dot(r, Suv)
            hvv = _dot(Sv, Sv) + _dot(r, Svv)
            det = huu * hvv - huv * huv
            if det <= 0:
                break
            du = (hvv * gu - huv * gv) / det
            dv = (huu * gv - huv * gu) / det
            if abs(du) + abs(dv) > 1e-8:
                break
            um, vm = um - du, vm - dv
        S = surface.eval(su, um, sv, vm)[0]
        r = _sub(S, exact_q)
        results.append((um, vm, mp.sqrt(_dot(r, r)), S))
    for edge, to_uv in _boundary_curves(surface):
        for m in nearest_curve(edge, q, cap=4)[:4]:
            u, v = to_uv(m.t)
            results.append((mp.mpf(u), mp.mpf(v), m.distance, m.point))
    results.sort(key=lambda r: (r[2], r[0], r[1]))
    return results


def _pick(spans, x):
    for k, a, b in spans:
        if a <= x < b:
            return k
    return spans[-1][0]


def surface_point(surface: Surface, u, v):
    um, vm = mp.mpf(u), mp.mpf(v)
    return surface.eval(_pick(surface.spans_u(), um), um, _pick(surface.spans_v(), vm), vm)[0]


def judge_nearest_surface(surface, q, u, v, distance, point, tol_rel=1e-9):
    size = surface.size() or 1.0
    tol = tol_rel * size + ROUNDING * magnitude([p for row in surface.grid for p in row], [q])
    ref = nearest_surface(surface, q)[0]
    s = surface_point(surface, u, v)
    r = _sub(s, [mp.mpf(c) for c in q])
    d_ours = mp.sqrt(_dot(r, r))
    problems = []
    if d_ours > ref[2] + tol:
        problems.append(
            f"wrong global minimum: ours (u, v)=({u!r}, {v!r}) at {mp.nstr(d_ours, 17)}, reference "
            f"({mp.nstr(ref[0], 17)}, {mp.nstr(ref[1], 17)}) at {mp.nstr(ref[2], 17)}"
        )
    # Ours nearer than the reference's minimum is no disagreement: `d_ours` is the reference's
    # own evaluation at our parameters, so ours is a true point of the surface, and the
    # reference's refinement missed (it samples creases coarsely).
    gap = max(abs(mp.mpf(a) - b) for a, b in zip(point, s))
    if gap > tol:
        problems.append(f"reported point {point} is not S(u, v) (gap {mp.nstr(gap, 5)})")
    if abs(mp.mpf(distance) - d_ours) > tol:
        problems.append(f"reported distance {distance!r} is not |S - q| = {mp.nstr(d_ours, 17)}")
    return "; ".join(problems) or None


# --------------------------------------------------------------------------------------------
# Intersections of plane curves
# --------------------------------------------------------------------------------------------


@dataclass
class Contact:
    s: object
    t: object
    point: list
    kind: str  # crossing | tangent | end
    gap: object  # |A(s) - B(t)| (mpf)
    ambiguous: bool = False  # a near miss or near merge that a tolerance may count either way


def _locate(curve, t):
    for k, a, b in curve.spans():
        if a <= t <= b:
            return k, a, b
    return curve.spans()[-1]


def _newton_crossing(A, B, s, t, exact=False):
    """Newton on F(s, t) = A(s) - B(t) = 0 kept in the domains; returns (s, t, converged)."""
    (a0, a1), (b0, b1) = A.domain, B.domain
    conv = mp.mpf if exact else float
    s, t = conv(s), conv(t)
    iters = 6 if exact else 80
    for _ in range(iters):
        ka = _locate(A, float(s))[0]
        kb = _locate(B, float(t))[0]
        pa, da = A.eval(ka, s, 1)
        pb, db = B.eval(kb, t, 1)
        fx, fy = pa[0] - pb[0], pa[1] - pb[1]
        # J = [A', -B']
        j11, j12, j21, j22 = da[0], -db[0], da[1], -db[1]
        det = j11 * j22 - j12 * j21
        if det == 0:
            return s, t, False
        ds = (j22 * fx - j12 * fy) / det
        dt = (-j21 * fx + j11 * fy) / det
        s = min(max(s - ds, conv(a0)), conv(a1))
        t = min(max(t - dt, conv(b0)), conv(b1))
        if abs(ds) + abs(dt) < (1e-30 if exact else 1e-15):
            break
    return s, t, True


def _newton_tangency(A, B, s, t, exact=False):
    """Newton on A'(s) x B'(t) = 0, (A(s) - B(t)) . A'(s) = 0 (regular at a tangency of curves
    of different curvature), finite differences for the Jacobian in floats, and in mpf."""
    (a0, a1), (b0, b1) = A.domain, B.domain
    conv = mp.mpf if exact else float
    s, t = conv(s), conv(t)

    def G(s, t):
        ka = _locate(A, float(s))[0]
        kb = _locate(B, float(t))[0]
        pa, da, dda = A.eval(ka, s, 2)
        pb, db, ddb = B.eval(kb, t, 2)
        r = _sub(pa, pb)
        g1 = da[0] * db[1] - da[1] * db[0]
        g2 = _dot(r, da)
        # partials
        g1s = dda[0] * db[1] - dda[1] * db[0]
        g1t = da[0] * ddb[1] - da[1] * ddb[0]
        g2s = _dot(da, da) + _dot(r, dda)
        g2t = -_dot(db, da)
        return g1, g2, g1s, g1t, g2s, g2t

    for _ in range(8 if exact else 80):
        g1, g2, g1s, g1t, g2s, g2t = G(s, t)
        det = g1s * g2t - g1t * g2s
        if det == 0:
            return s, t, False
        ds = (g2t * g1 - g1t * g2) / det
        dt = (-g2s * g1 + g1s * g2) / det
        s = min(max(s - ds, conv(a0)), conv(a1))
        t = min(max(t - dt, conv(b0)), conv(b1))
        if abs(ds) + abs(dt) < (1e-30 if exact else 1e-15):
            break
    return s, t, True


def _mp_gap(A, B, s, t):
    s, t = mp.mpf(s), mp.mpf(t)
    pa = A.eval(_locate(A, float(s))[0], s, 0)[0]
    pb = B.eval(_locate(B, float(t))[0], t, 0)[0]
    r = _sub(pa, pb)
    return mp.sqrt(_dot(r, r)), pa


def _polyline(curve, per_span):
    ts, ps, spans = [], [], []
    for k, a, b in curve.spans():
        t, p = curve.sample(k, a, b, per_span)
        ts.append(t)
        ps.append(p)
    return np.concatenate(ts), np.concatenate(ps)


def _segment_crossings(pa, pb, same=False):
    """Index pairs (i, j) of polyline segments that cross or nearly touch."""
    a0, a1 = pa[:-1], pa[1:]
    b0, b1 = pb[:-1], pb[1:]
    da = a1 - a0
    db = b1 - b0
    # solve a0 + u da = b0 + v db for all pairs
    A0 = a0[:, None, :]
    DA = da[:, None, :]
    B0 = b0[None, :, :]
    DB = db[None, :, :]
    den = DA[..., 0] * DB[..., 1] - DA[..., 1] * DB[..., 0]
    w = B0 - A0
    with np.errstate(divide="ignore", invalid="ignore"):
        u = (w[..., 0] * DB[..., 1] - w[..., 1] * DB[..., 0]) / den
        v = (w[..., 0] * DA[..., 1] - w[..., 1] * DA[..., 0]) / den
    eps = 1e-6
    hit = (u >= -eps) & (u <= 1 + eps) & (v >= -eps) & (v <= 1 + eps) & np.isfinite(u) & np.isfinite(v)
    idx = np.argwhere(hit)
    return [(int(i), int(j), float(np.clip(u[i, j], 0, 1)), float(np.clip(v[i, j], 0, 1))) for i, j in idx]


def intersect_reference(A: Curve, B: Curve | None, per_span=None, contact_rel=1e-10, merge_rel=1e-6):
    """The contacts of two plane curves (B None: self-intersections of A, s < t).

    Starts: every crossing of the two sampled polylines and every local minimum of the distance
    between sampled points closer than 2 % of the size. From each start, Newton on
    A(s) = B(t) and Newton on the tangency system, both in floats then polished in mpf at 40
    digits. A root with |A(s) - B(t)| <= contact_rel * size is a contact; roots within merge_rel
    of the domains in both parameters are one contact (then `tangent`: two crossings that close
    are a tangency perturbed by the rounding of the input). A contact is `end` at an end of
    either domain (1e-9 of the domain), `tangent` when |A' x B'| <= 1e-6 |A'| |B'| or merged,
    else `crossing`. Marked ambiguous: near misses with gaps in (1e-13, 1e-8) of the size and
    pairs of contacts 1e-6 to 1e-3 apart, which a tolerance may legitimately count either way."""
    same = B is None
    if same:
        B = A
    size = max(A.size(), B.size()) or 1.0
    n = per_span or max(48, 16 * (max(A.degree, B.degree) + 1))
    ta, pa = _polyline(A, n)
    tb, pb = _polyline(B, n)
    starts = []
    for i, j, u, v in _segment_crossings(pa, pb, same):
        if same and abs(i - j) <= 1:
            continue
        starts.append((ta[i] + u * (ta[i + 1] - ta[i]), tb[j] + v * (tb[j + 1] - tb[j])))
    d = np.linalg.norm(pa[:, None, :] - pb[None, :, :], axis=-1)
    close = d < 0.02 * size
    pad = np.pad(d, 1, constant_values=np.inf)
    is_min = close.copy()
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                is_min &= d <= pad[1 + di : 1 + di + d.shape[0], 1 + dj : 1 + dj + d.shape[1]]
    for i, j in np.argwhere(is_min):
        if same and abs(int(i) - int(j)) <= 2:
            continue
        starts.append((float(ta[i]), float(tb[j])))
    if same:
        # small loops (near cusps) hide between two samples: from every local minimum of the
        # sampled speed, start at (t - h, t + h) for h from a tenth of the span down to 1e-7
        for k, lo_k, hi_k in A.spans():
            ts_k = np.linspace(lo_k, hi_k, 4 * n)
            speed = np.linalg.norm(np.stack([np.broadcast_to(v, ts_k.shape) for v in A.eval(k, ts_k, 1)[1]], axis=1), axis=1)
            for i in range(len(ts_k)):
                if (i == 0 or speed[i] <= speed[i - 1]) and (i == len(ts_k) - 1 or speed[i] <= speed[i + 1]):
                    for h in 10.0 ** -np.arange(1, 8):
                        h *= hi_k - lo_k
                        starts.append((max(float(ts_k[i]) - h, A.domain[0]), min(float(ts_k[i]) + h, A.domain[1])))
    roots = []
    (a0, a1), (b0, b1) = A.domain, B.domain
    wa, wb = a1 - a0, b1 - b0
    seen = []
    for s0, t0 in starts:
        if any(abs(s0 - s) < 1e-4 * wa and abs(t0 - t) < 1e-4 * wb for s, t in seen):
            continue
        seen.append((s0, t0))
        for solver in (_newton_crossing, _newton_tangency):
            s, t, ok = solver(A, B, s0, t0)
            if not ok or not (math.isfinite(s) and math.isfinite(t)):
                continue
            sm, tm, ok = solver(A, B, s, t, exact=True)
            gap, point = _mp_gap(A, B, sm, tm)
            if gap > 1e-8 * size:
                sm, tm = mp.mpf(s), mp.mpf(t)
                gap, point = _mp_gap(A, B, sm, tm)
            if gap > 1e-8 * size:
                continue
            if same and abs(sm - tm) <= 1e-6 * wa:
                continue
            if same and sm > tm:
                sm, tm = tm, sm
            roots.append((sm, tm, gap, point, solver is _newton_tangency))
    # snap to the ends when the curves meet there
    contacts = []
    for sm, tm, gap, point, from_tangency in sorted(roots, key=lambda r: (r[0], r[1])):
        merged = False
        for c in contacts:
            if abs(c.s - sm) <= merge_rel * wa and abs(c.t - tm) <= merge_rel * wb:
                if gap < c.gap:
                    c.s, c.t, c.gap, c.point = sm, tm, gap, point
                if abs(c.s - sm) > 1e-14 * wa or abs(c.t - tm) > 1e-14 * wb:
                    c._members += 1  # a second, distinct root: a perturbed tangency
                merged = True
                break
        if merged:
            continue
        c = Contact(sm, tm, point, "crossing", gap)
        c._members = 1
        contacts.append(c)
    out = []
    for c in contacts:
        if c.gap > contact_rel * size:
            # a near miss: counted only if within 1e-8 (ambiguous between)
            if c.gap <= 1e-8 * size:
                c.ambiguous = True
                c.kind = "tangent"
                out.append(c)
            continue
        if c.gap > 1e-13 * size:
            c.ambiguous = c.ambiguous or False
        ka = _locate(A, float(c.s))[0]
        kb = _locate(B, float(c.t))[0]
        da = A.eval(ka, c.s, 1)[1]
        db = B.eval(kb, c.t, 1)[1]
        cross = abs(da[0] * db[1] - da[1] * db[0])
        norm = mp.sqrt(_dot(da, da) * _dot(db, db))
        at_end = min(abs(c.s - a0), abs(c.s - a1)) <= 1e-9 * wa or min(abs(c.t - b0), abs(c.t - b1)) <= 1e-9 * wb
        if at_end:
            c.kind = "end"
        elif c._members > 1 or norm == 0 or cross <= 1e-6 * norm:
            c.kind = "tangent"
        out.append(c)
    if same:
        # a closed curve's seam is no self-intersection
        out = [c for c in out if not (abs(c.s - a0) <= 1e-9 * wa and abs(c.t - a1) <= 1e-9 * wa)]
    out.sort(key=lambda c: (c.s, c.t))
    for x, y in zip(out, out[1:]):
        if abs(x.s - y.s) <= 1e-3 * wa and abs(x.t - y.t) <= 1e-3 * wb:
            x.ambiguous = y.ambiguous = True
    return out


def _ulp_neighbours(t, domain):
    lo, hi = domain
    return [min(max(x, lo), hi) for x in (t, math.nextafter(t, -math.inf), math.nextafter(t, math.inf))]


def judge_intersections(A, B, rows, tol_rel=1e-9, tangent_rel=1e-5, check_kinds=True):
    """Compare our rows [(t_a, t_b, x, y, contact or None)] with the reference's contacts: each
    unambiguous contact once, no row off every contact, each row's point A(t_a) = B(t_b).
    Crossings must match to tol_rel * size in position; tangencies to tangent_rel * size (a
    contact of order k is determined by double inputs only to about eps^(1/k))."""
    same = B is None
    ref = intersect_reference(A, B)
    Bc = A if same else B
    size = max(A.size(), Bc.size()) or 1.0
    floor = ROUNDING * magnitude(A.points, Bc.points)
    problems = []
    used = [0] * len(ref)
    for row in rows:
        ta, tb, x, y = row[:4]
        # within a unit in the last place of the parameters (one ulp can move a point far on a
        # narrow domain far from 0)
        gap_a = min(true_distance(A, t, (x, y))[0] for t in _ulp_neighbours(ta, A.domain))
        gap_b = min(true_distance(Bc, t, (x, y))[0] for t in _ulp_neighbours(tb, Bc.domain))
        if gap_a > tangent_rel * size + floor or gap_b > tangent_rel * size + floor:
            problems.append(f"row {row}: the point is not on both curves (|A(t_a) - p| = {mp.nstr(gap_a, 5)}, |B(t_b) - p| = {mp.nstr(gap_b, 5)})")
        best, best_k = None, None
        for k, c in enumerate(ref):
            dist = max(abs(mp.mpf(x) - c.point[0]), abs(mp.mpf(y) - c.point[1]))
            if best is None or dist < best:
                best, best_k = dist, k
        if best is None:
            problems.append(f"extra row {row}: the reference finds no contact")
            continue
        c = ref[best_k]
        limit = (tol_rel if c.kind == "crossing" else tangent_rel) * size + floor
        if best > limit:
            if gap_a <= tol_rel * size + floor and gap_b <= tol_rel * size + floor:
                # A point on both curves to the crossing precision, evaluated here in mpmath,
                # and apart from every contact the reference has: the reference's dense
                # starts missed it (two contacts closer than its clustering, say).
                continue
            problems.append(f"extra row {row}: nearest reference contact at {[mp.nstr(v, 17) for v in c.point]} ({c.kind}), {mp.nstr(best, 5)} away")
            continue
        used[best_k] += 1
        if check_kinds and len(row) > 4 and row[4] is not None and not c.ambiguous and row[4] != c.kind:
            problems.append(f"row {row}: contact `{row[4]}`, the reference says `{c.kind}`")
    for k, c in enumerate(ref):
        desc = f"s={mp.nstr(c.s, 17)} t={mp.nstr(c.t, 17)} at {[mp.nstr(v, 17) for v in c.point]} ({c.kind}, gap {mp.nstr(c.gap, 3)})"
        if used[k] == 0 and not c.ambiguous:
            problems.append(f"missed contact {desc}")
        if used[k] > 1 and not c.ambiguous:
            problems.append(f"contact reported {used[k]} times: {desc}")
    return "; ".join(problems) or None, ref


# --------------------------------------------------------------------------------------------
# Random cases aimed at the degenerate ones
# --------------------------------------------------------------------------------------------


def _knots(rng, p, count, repeated=False, jumps=True):
    """A clamped knot vector (domain often not [0, 1]) with interior knots, some repeated up to
    multiplicity p (p + 1 for p = 1 when `jumps`: a jump of a polyline), some spans tiny."""
    interior = count - p - 1
    lo = rng.choice([0.0, 0.0, -1.0, 2.5, 1e-3, 100.0])
    width = rng.choice([1.0, 1.0, 3.0, 1e-2, 50.0])
    vals = sorted(lo + width * rng.random() for _ in range(interior))
    if repeated and interior >= 2 and (jumps or p >= 2):
        # repeat some knots (multiplicity up to p), giving C0 joints and empty spans
        i = rng.randrange(interior)
        m = rng.randint(2, max(2, p))
        for r in range(1, m):
            if i + r < interior:
                vals[i + r] = vals[i]
    vals = [max(lo, min(lo + width, v)) for v in vals]
    # avoid interior knots on the domain's ends (they would make multiplicity > p + 1)
    vals = [v if lo < v < lo + width else lo + width / 2 for v in vals]
    vals.sort()
    return [lo] * (p + 1) + vals + [lo + width] * (p + 1)


def random_points(rng, count, dim, scale, offset):
    pts = [[offset[d] + scale * rng.uniform(-1, 1) for d in range(dim)] for _ in range(count)]
    return pts


def degenerate_curve(rng: random.Random, dim: int | None = None, kind: str | None = None) -> Curve:
    """A random curve drawn to hit the degenerate cases: coincident and nearly coincident control
    points (ends and inside), cusps and stationary ends, collinear / coplanar nets, repeated
    knots and zero-length pieces, weights 1e-3 to 1e3, sizes 1e-8 to 1e8, degrees 1 to 30."""
    dim = dim or rng.choice([2, 3])
    kind = kind or rng.choice(["bezier", "bspline", "nurbs"])
    r = rng.random()
    degree = rng.randint(1, 4) if r < 0.6 else rng.randint(5, 12) if r < 0.9 else rng.randint(13, 30)
    if kind == "bezier":
        count = degree + 1
    else:
        count = degree + 1 + rng.randint(0, 6)
    scale = 10 ** rng.uniform(-8, 8) if rng.random() < 0.5 else rng.choice([1.0, 100.0, 1e-3])
    offset = [rng.choice([0.0, 0.0, scale * rng.uniform(-5, 5), 1e3 * scale * rng.uniform(-1, 1)]) for _ in range(dim)]
    style = rng.choice(["random", "collinear", "coplanar", "cusp", "stationary", "coincident", "near", "zero-piece"])
    pts = random_points(rng, count, dim, scale, offset)
    if style == "collinear":
        a = [rng.uniform(-1, 1) for _ in range(dim)]
        pts = [[offset[d] + scale * s * a[d] for d in range(dim)] for s in (rng.uniform(-1, 1) for _ in range(count))]
    elif style == "coplanar" and dim == 3:
        for p in pts:
            p[2] = offset[2] + 0.3 * (p[0] - offset[0]) - 0.7 * (p[1] - offset[1])
    elif style == "cusp" and count >= 4:
        # a cubic-like cusp: the control polygon crosses itself symmetrically
        i = rng.randrange(0, count - 3)
        base = [[0, 0], [1, 1], [0, 1], [1, 0]]
        for k in range(4):
            pts[i + k][0] = offset[0] + scale * base[k][0]
            pts[i + k][1] = offset[1] + scale * base[k][1]
            if dim == 3:
                pts[i + k][2] = offset[2]
    elif style == "stationary":
        pts[1] = list(pts[0])
        if count > 2:
            pts[-2] = list(pts[-1])
    elif style == "coincident":
        i = rng.randrange(count - 1)
        pts[i + 1] = list(pts[i])
    elif style == "near":
        i = rng.randrange(count - 1)
        pts[i + 1] = [c + scale * rng.uniform(-1, 1) * 1e-13 for c in pts[i]]
    elif style == "zero-piece":
        i = rng.randrange(count)
        m = min(count - i, degree + 1)
        for k in range(1, m):
            pts[i + k] = list(pts[i])
    pts = [tuple(float(c) for c in p) for p in pts]
    weights = None
    knots = None
    if kind == "nurbs":
        spread = rng.choice([0.5, 1.0, 3.0])
        weights = [10 ** rng.uniform(-spread, spread) for _ in range(count)]
    if kind != "bezier":
        knots = _knots(rng, degree, count, repeated=rng.random() < 0.4 or style == "zero-piece")
    return Curve(kind, degree, pts, weights, knots)


def query_points(rng: random.Random, curve: Curve, count: int):
    """Points on the curve, at control points, at centres of curvature, near and far, at cusps
    (where the sampled speed is smallest)."""
    size = curve.size() or 1.0
    pts = np.array(curve.points, dtype=float)
    centre = (pts.max(axis=0) + pts.min(axis=0)) / 2
    lo, hi = curve.domain
    out = []
    for k in range(count):
        kind = k % 6
        t = lo + (hi - lo) * rng.random()
        if kind == 0:
            p = [float(c) for c in curve.point(t)[0]]
        elif kind == 1:
            c, c1, c2 = (np.array([float(x) for x in v]) for v in curve.point(t, 2))
            speed = np.linalg.norm(c1)
            if speed == 0:
                p = list(c)
            else:
                tang = c1 / speed
                normal = c2 - np.dot(c2, tang) * tang
                kappa = np.linalg.norm(normal) / speed**2
                p = list(c + normal / np.linalg.norm(normal) / kappa) if kappa > 1e-12 / size else list(c)
        elif kind == 2:
            p = list(pts[rng.randrange(len(pts))])
        elif kind == 3:
            direction = np.array([rng.gauss(0, 1) for _ in range(curve.dim)])
            p = list(centre + 1e3 * size * direction)
        elif kind == 4:
            p = [float(c) + size * rng.uniform(-0.5, 0.5) for c in centre]
        else:
            c = np.array([float(x) for x in curve.point(t)[0]])
            p = list(c + size * 1e-6 * np.array([rng.gauss(0, 1) for _ in range(curve.dim)]))
        out.append([float(x) for x in p])
    # and the point where the sampled speed is smallest (a cusp, a stationary end or a run of
    # coincident control points), drawing nothing from rng so that the points above stay put
    best = None
    for k, a, b in curve.spans():
        ts = np.linspace(a, b, 257)
        speed = np.linalg.norm(np.stack([np.broadcast_to(v, ts.shape) for v in curve.eval(k, ts, 1)[1]], axis=1), axis=1)
        i = int(np.argmin(speed))
        if best is None or speed[i] < best[0]:
            best = (speed[i], k, float(ts[i]))
    out.append([float(x) for x in curve.eval(best[1], best[2], 0)[0]])
    return out


def degenerate_surface(rng: random.Random) -> Surface:
    kind = rng.choice(["bezier-surface", "bspline-surface", "nurbs-surface"])
    du, dv = rng.randint(1, 4), rng.randint(1, 4)
    if kind == "bezier-surface":
        rows, cols = du + 1, dv + 1
    else:
        rows, cols = du + 1 + rng.randint(0, 3), dv + 1 + rng.randint(0, 3)
    scale = 10 ** rng.uniform(-6, 6) if rng.random() < 0.4 else 1.0
    style = rng.choice(["random", "flat", "collapsed-edge", "coincident"])
    grid = [[[scale * (i + rng.uniform(-0.4, 0.4)), scale * (j + rng.uniform(-0.4, 0.4)), scale * rng.uniform(-1, 1)] for j in range(cols)] for i in range(rows)]
    if style == "flat":
        for row in grid:
            for p in row:
                p[2] = 0.25 * p[0] - 0.5 * p[1]
    elif style == "collapsed-edge":
        for j in range(cols):
            grid[0][j] = list(grid[0][0])
    elif style == "coincident":
        i, j = rng.randrange(rows - 1), rng.randrange(cols)
        grid[i + 1][j] = list(grid[i][j])
    grid = [[[float(c) for c in p] for p in row] for row in grid]
    weights = [[10 ** rng.uniform(-1.5, 1.5) for _ in range(cols)] for _ in range(rows)] if kind == "nurbs-surface" else None
    ku = kv = None
    if kind != "bezier-surface":
        # no jumps on surfaces: the reference's patches do not hold the limits across a jump
        ku = _knots(rng, du, rows, repeated=rng.random() < 0.3, jumps=False)
        kv = _knots(rng, dv, cols, repeated=rng.random() < 0.3, jumps=False)
    return Surface(kind, du, dv, grid, weights, ku, kv)


def surface_queries(rng, surface: Surface, count):
    size = surface.size() or 1.0
    pts = np.array([p for row in surface.grid for p in row], dtype=float)
    centre = (pts.max(axis=0) + pts.min(axis=0)) / 2
    (u0, u1), (v0, v1) = surface.domain_u(), surface.domain_v()
    out = []
    for k in range(count):
        kind = k % 4
        if kind == 0:
            s = surface_point(surface, u0 + (u1 - u0) * rng.random(), v0 + (v1 - v0) * rng.random())
            out.append([float(c) for c in s])
        elif kind == 1:
            out.append([float(c) for c in pts[rng.randrange(len(pts))]])
        elif kind == 2:
            out.append([float(c + size * rng.uniform(-0.7, 0.7)) for c in centre])
        else:
            out.append([float(c + 1e3 * size * rng.gauss(0, 1)) for c in centre])
    return out


# --------------------------------------------------------------------------------------------
# Files
# --------------------------------------------------------------------------------------------


def write_model(path, shape):
    path.write_text(json.dumps(shape.model()))


def write_points(path, points):
    cols = ["x", "y", "z"][: len(points[0])]
    lines = [",".join(cols)] + [",".join(repr(float(c)) for c in p) for p in points]
    path.write_text("\n".join(lines) + "\n")
