#!/usr/bin/env python3
"""Independent reference data for the neutrospline B-spline, NURBS and surface evaluators.

How to run (from the workspace root, /work/main):

    python3 -m venv /tmp/venv-spl \
      && /tmp/venv-spl/bin/pip install numpy scipy mpmath \
      && /tmp/venv-spl/bin/python scripts/reference/make_spline_reference.py

Deterministic (fixed seeds, Python's `random` module, whose `random()` stream is stable
across Python versions).  Written to `crates/neutrospline/tests/data/`:

  spline_bspline.json   random B-spline curves, 2-D and 3-D, degrees 0..7 and a few up to
                        15, clamped and unclamped knots with repeated interior knots (up to
                        multiplicity p, and cases with multiplicity p + 1 = a discontinuity).
                        Values: scipy.interpolate.BSpline (float64 de Boor);
                        first derivatives: BSpline.derivative() (or BSpline(x, nu=1) where
                        scipy refuses derivative() because of a knot of multiplicity p + 1).
                        Cross-checked against an mpmath Cox-de Boor sum at 50 digits.
  spline_nurbs.json     random NURBS curves (weights in [0.1, 10]) and the quarter and full
                        unit circles.  Values and first derivatives from the rational formula
                        R_i = w_i N_i / sum_j w_j N_j with the Cox-de Boor basis in mpmath at
                        50 digits, derivative by the quotient rule; cross-checked against the
                        same formula on scipy's basis in float64.
  surface_random.json   random tensor-product surfaces (Bezier, B-spline, NURBS): values and
                        both partial derivatives from the tensor-product sum
                        S = sum_ij w_ij N_i(u) M_j(v) P_ij / sum_ij w_ij N_i(u) M_j(v), bases in
                        mpmath (Bernstein with exact binomials for Bezier surfaces);
                        cross-checked with a float64 numpy einsum on scipy's bases.

Conventions (the same as the Rust core, and as scipy's BSpline with extrapolate=False):
the domain is [u_p, u_{m-p}]; at an interior knot the value is taken from the right (the
span u_k <= t < u_{k+1}); at the domain end from the left (the last non-empty span).  At a
knot of multiplicity p + 1 the curve jumps; the reference holds the right-hand value there,
and `nextafter(knot, -inf)` parameters are included to exercise the left-hand piece.

Every degree channel (truth, indeterminacy, falsity) is blended exactly like a coordinate
(docs/model.md section 4 and 6).  Doubles are written with Python's repr (round-trip); mpmath results
are rounded to the nearest double through an exact Fraction.

Tolerances used by crates/neutrospline/tests/integration/spline_reference.rs (documented in README.md):
  positions 1e-12 * M (M = largest |control coordinate|), degrees 1e-12 absolute,
  derivatives 1e-12 * p * 2 * M / h * (w_max / w_min) with h the smallest positive
  u_{i+p+1} - u_{i+1} (M = 1 for degrees).  The script asserts its own float64
  cross-check is within 5 % of those tolerances.
"""

import json
import math
import os
import random
from fractions import Fraction

import numpy as np
from mpmath import mp, mpf
from scipy.interpolate import BSpline

mp.dps = 50

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
OUT_DIR = os.path.join(ROOT, "crates", "neutrospline", "tests", "data")

REL_TOL = 1e-12
CHECK_FRACTION = 0.05  # the float64 cross-check must be within 5 % of the tolerance


# --------------------------------------------------------------------------- helpers


def mpf_to_fraction(x):
    sign, man, exp, _bc = x._mpf_
    if man == 0:
        if exp != 0:
            raise ValueError("non-finite mpf %r" % (x,))
        return Fraction(0)
    v = Fraction(man) * (Fraction(2) ** exp)
    return -v if sign else v


def to_double(x):
    """Correctly rounded double of an mpf."""
    return float(mpf_to_fraction(x))


def span_index(knots, p, t):
    """Index k with u_k <= t < u_{k+1} in p..=n-1, or the last non-empty span at the end."""
    n = len(knots) - p - 1
    k = p
    for j in range(p, n):
        if knots[j] <= t:
            k = j
    while k > p and knots[k] == knots[k + 1]:
        k -= 1
    return k


def cox_de_boor(knots, p, t):
    """Values N_{i,p}(t) and derivatives N'_{i,p}(t), i = 0..n-1, in mpmath.

    The degree-0 functions are 1 on the span chosen by `span_index` (from the right at
    interior knots, from the left at the domain end) and 0 elsewhere; 0/0 counts as 0.
    """
    u = [mpf(x) for x in knots]
    t = mpf(t)
    m = len(u) - 1
    k = span_index(knots, p, float(t))
    basis = [mpf(1) if i == k else mpf(0) for i in range(m)]
    lower = basis
    for q in range(1, p + 1):
        lower = basis
        nxt = []
        for i in range(m - q):
            acc = mpf(0)
            d1 = u[i + q] - u[i]
            if d1 != 0:
                acc += (t - u[i]) / d1 * basis[i]
            d2 = u[i + q + 1] - u[i + 1]
            if d2 != 0:
                acc += (u[i + q + 1] - t) / d2 * basis[i + 1]
            nxt.append(acc)
        basis = nxt
    n = m - p
    values = basis[:n]
    if p == 0:
        return values, [mpf(0)] * n
    deriv = []
    for i in range(n):
        acc = mpf(0)
        d1 = u[i + p] - u[i]
        if d1 != 0:
            acc += p / d1 * lower[i]
        d2 = u[i + p + 1] - u[i + 1]
        if d2 != 0:
            acc -= p / d2 * lower[i + 1]
        deriv.append(acc)
    return values, deriv


def bernstein(n, t):
    """Bernstein values B_{n,i}(t) and derivatives, exact binomials, mpmath."""
    t = mpf(t)
    s = 1 - t
    vals = [math.comb(n, i) * t**i * s ** (n - i) for i in range(n + 1)]
    if n == 0:
        return vals, [mpf(0)]
    lower = [math.comb(n - 1, i) * t**i * s ** (n - 1 - i) for i in range(n)]
    der = []
    for i in range(n + 1):
        acc = mpf(0)
        if i > 0:
            acc += n * lower[i - 1]
        if i < n:
            acc -= n * lower[i]
        der.append(acc)
    return vals, der


def rational(values, derivs, weights, rows):
    """sum R_i rows_i and its derivative, R_i = w_i N_i / sum w_j N_j (mpmath)."""
    channels = len(rows[0])
    w = sum(wi * ni for wi, ni in zip(weights, values))
    dw = sum(wi * di for wi, di in zip(weights, derivs))
    a = [sum(wi * ni * r[c] for wi, ni, r in zip(weights, values, rows)) for c in range(channels)]
    da = [sum(wi * di * r[c] for wi, di, r in zip(weights, derivs, rows)) for c in range(channels)]
    value = [ac / w for ac in a]
    deriv = [(dac - dw * vc) / w for dac, vc in zip(da, value)]
    return value, deriv


REVERSED_NOTE = ("scipy on the reversed knot vector (scipy itself evaluates the empty span "
                 "[u_{n-1}, u_n] at a repeated domain-end knot and returns 0)")


def repeated_end(knots, p, t):
    """Whether t is the domain end u_n and u_{n-1} = u_n (unclamped vectors only: a clamped
    end has u_{n-1} < u_n)."""
    n = len(knots) - p - 1
    return t == knots[n] and knots[n - 1] == knots[n]


def reversed_spline(knots, rows, p):
    """The spline s(-x): knots -u_{m-i}, control rows in reverse order."""
    t_rev = -np.array(knots)[::-1]
    return BSpline(t_rev, np.array(rows)[::-1], p, extrapolate=False)


def scipy_basis(knots, p, x):
    """All basis values and derivatives at x from scipy (identity coefficients)."""
    n = len(knots) - p - 1
    if repeated_end(knots, p, x):
        rev = reversed_spline(knots, np.eye(n), p)
        vals = rev(-x)
        ders = -rev(-x, nu=1) if p > 0 else np.zeros(n)
        return np.asarray(vals, dtype=float), np.asarray(ders, dtype=float)
    spl = BSpline(np.array(knots), np.eye(n), p, extrapolate=False)
    vals = spl(x)
    ders = spl(x, nu=1) if p > 0 else np.zeros(n)
    return np.asarray(vals, dtype=float), np.asarray(ders, dtype=float)


def fmt(x):
    return float(x)


# --------------------------------------------------------------------------- random data


def random_degree_value(rng):
    r = rng.random()
    if r < 0.08:
        return 0.0
    if r < 0.16:
        return 1.0
    return rng.random()


def random_point(rng, dim):
    position = [rng.uniform(-10.0, 10.0) for _ in range(dim)]
    degrees = [random_degree_value(rng) for _ in range(3)]
    return position, degrees


def random_knots(rng, p, n, clamped, max_interior, start=None, scale=None):
    """n + p + 1 non-decreasing knots; interior runs <= max_interior, end runs <= p + 1."""
    m = n + p
    if start is None:
        start = rng.uniform(-5.0, 5.0)
    if scale is None:
        scale = rng.choice([0.1, 1.0, 1.0, 10.0])
    gaps = []
    for g in range(m):
        gaps.append(0.0 if rng.random() < 0.3 else rng.uniform(0.05, 1.0))
    if clamped:
        for g in range(p):
            gaps[g] = 0.0
            gaps[m - 1 - g] = 0.0
        gaps[p] = max(gaps[p], 0.3)
        gaps[m - 1 - p] = max(gaps[m - 1 - p], 0.3)
    run = 1
    for g in range(m):
        if gaps[g] == 0.0:
            end_run = g < p or g + 1 > m - p
            limit = p + 1 if end_run else min(max_interior, p + 1)
            if run + 1 > limit:
                gaps[g] = 0.3
                run = 1
            else:
                run += 1
        else:
            run = 1
    if all(g == 0.0 for g in gaps[p : m - p]):
        gaps[p] = 0.3
    knots = [start]
    acc = 0.0
    for g in gaps:
        acc += g
        knots.append(start + scale * acc)
    return knots


def with_discontinuity(rng, knots, p):
    """Raises one interior knot (strictly inside the domain) to multiplicity p + 1, keeping
    the length: the knots after it are shifted by one position."""
    n = len(knots) - p - 1
    a, b = knots[p], knots[n]
    inner = sorted(set(k for k in knots if a < k < b))
    if not inner:
        return None
    value = rng.choice(inner)
    out = [k for k in knots if k != value]
    need = len(knots) - len(out)
    # put p + 1 copies and drop knots from the end side to keep the count
    out = sorted(out + [value] * (p + 1))
    extra = len(out) - len(knots)
    if extra > 0:
        # drop interior knots (not the value itself, not the clamped ends)
        for _ in range(extra):
            cands = [i for i in range(p + 1, len(out) - p - 1) if out[i] != value]
            if not cands:
                return None
            del out[rng.choice(cands)]
    elif extra < 0:
        return None
    del need
    # validity: multiplicities and a non-empty domain
    for v in set(out):
        if out.count(v) > p + 1:
            return None
    if out[p] >= out[len(out) - 1 - p]:
        return None
    return out


def parameters(rng, knots, p, n_random):
    """Domain ends, every distinct knot in the domain, the doubles just left of interior
    knots (the left-hand piece), and random values."""
    n = len(knots) - p - 1
    a, b = knots[p], knots[n]
    ts = {a, b}
    for k in knots:
        if a < k < b:
            ts.add(k)
            ts.add(float(np.nextafter(k, -np.inf)))
    for _ in range(n_random):
        ts.add(rng.uniform(a, b))
    return sorted(ts)


# --------------------------------------------------------------------------- tolerances


def min_positive_span(knots, p):
    """Smallest positive u_{i+p+1} - u_{i+1}, the denominators of the derivative."""
    n = len(knots) - p - 1
    spans = [knots[i + p + 1] - knots[i + 1] for i in range(n - 1)]
    spans = [s for s in spans if s > 0]
    return min(spans) if spans else 1.0


def tolerances(knots, p, positions, weights):
    m_pos = max([abs(x) for pos in positions for x in pos] + [0.0])
    ratio = (max(weights) / min(weights)) if weights else 1.0
    h = min_positive_span(knots, p)
    d_scale = p * 2.0 / h * ratio
    return {
        "value_position": REL_TOL * m_pos,
        "value_degree": REL_TOL,
        "derivative_position": REL_TOL * d_scale * m_pos,
        "derivative_degree": REL_TOL * d_scale,
    }


def check_close(name, t, what, got, want, dim, tol):
    for c, (g, w) in enumerate(zip(got, want)):
        kind = "position" if c < dim else "degree"
        bound = CHECK_FRACTION * tol["%s_%s" % (what, kind)]
        err = abs(g - w)
        if not err <= bound:
            raise AssertionError(
                "%s: t = %r, %s channel %d: cross-check %r vs reference %r, error %g > %g"
                % (name, t, what, c, g, w, err, bound)
            )


# --------------------------------------------------------------------------- curves


def rows_of(points):
    return [pos + deg for pos, deg in points]


def exact(x):
    """A double as the shortest string that round-trips (Python's repr).  Inputs (knots,
    weights, control values, parameters) are written as strings because serde_json's default
    float parser is not correctly rounded: it may move a parameter by one ulp, e.g. from just
    left of a knot onto the knot.  Rust's str::parse::<f64> is correctly rounded."""
    return repr(float(x))


EXACT_NOTE = ("knots, weights, control values and parameters are strings holding the shortest "
              "round-trip decimal of the double; parse them with a correctly rounded parser")


def exact_list(xs):
    return [exact(x) for x in xs]


def point_json(pos, deg):
    return {"position": exact_list(pos), "truth": exact(deg[0]),
            "indeterminacy": exact(deg[1]), "falsity": exact(deg[2])}


def bspline_case(name, dim, p, knots, points, rng, n_random=5, note=None):
    rows = np.array(rows_of(points))
    t_arr = np.array(knots)
    spl = BSpline(t_arr, rows, p, extrapolate=False)
    try:
        dspl = spl.derivative() if p > 0 else None
        derivative_source = "BSpline.derivative()"
    except ValueError:
        dspl = None  # multiplicity p + 1: scipy refuses derivative()
        derivative_source = "BSpline(x, nu=1)"
    if p == 0:
        derivative_source = "zero (degree 0)"
    tol = tolerances(knots, p, [q[0] for q in points], None)
    evaluations = []
    for t in parameters(rng, knots, p, n_random):
        value = spl(t)
        if p == 0:
            deriv = np.zeros(dim + 3)
        elif dspl is not None:
            deriv = dspl(t)
        else:
            deriv = spl(t, nu=1)
        if not (np.all(np.isfinite(value)) and np.all(np.isfinite(deriv))):
            raise AssertionError("%s: scipy gave a non-finite value at %r" % (name, t))
        # independent cross-check: mpmath Cox-de Boor at 50 digits
        vals, ders = cox_de_boor(knots, p, t)
        mp_value = [to_double(sum(v * r for v, r in zip(vals, rows[:, c].tolist())))
                    for c in range(dim + 3)]
        mp_deriv = [to_double(sum(d * r for d, r in zip(ders, rows[:, c].tolist())))
                    for c in range(dim + 3)]
        entry = {"t": exact(t)}
        if repeated_end(knots, p, t):
            # scipy's interval search stops on the EMPTY span [u_{n-1}, u_n] when the domain
            # end of an unclamped vector is a repeated knot, and returns 0 there.  The left
            # limit (the core's convention) is the right limit of the reversed spline.
            rev = reversed_spline(knots, rows, p)
            value = rev(-t)
            deriv = -rev(-t, nu=1) if p > 0 else np.zeros(dim + 3)
            entry["source"] = REVERSED_NOTE
        check_close(name, t, "value", value.tolist(), mp_value, dim, tol)
        check_close(name, t, "derivative", deriv.tolist(), mp_deriv, dim, tol)
        entry["value"] = [fmt(v) for v in value]
        entry["derivative"] = [fmt(v) for v in deriv]
        evaluations.append(entry)
    case = {
        "name": name,
        "dimension": dim,
        "degree": p,
        "clamped": is_clamped(knots, p),
        "knots": exact_list(knots),
        "control_points": [point_json(pos, deg) for pos, deg in points],
        "derivative_source": derivative_source,
        "evaluations": evaluations,
    }
    if note:
        case["note"] = note
    return case


def is_clamped(knots, p):
    return len(set(knots[: p + 1])) == 1 and len(set(knots[-(p + 1):])) == 1


def nurbs_case(name, dim, p, knots, points, weights, ts, note=None):
    rows = rows_of(points)
    mrows = [[mpf(x) for x in r] for r in rows]
    mweights = [mpf(w) for w in weights]
    tol = tolerances(knots, p, [q[0] for q in points], weights)
    evaluations = []
    for t in ts:
        vals, ders = cox_de_boor(knots, p, t)
        value, deriv = rational(vals, ders, mweights, mrows)
        value = [to_double(v) for v in value]
        deriv = [to_double(v) for v in deriv]
        # float64 cross-check on scipy's basis
        sv, sd = scipy_basis(knots, p, t)
        w = np.array(weights)
        r = np.array(rows)
        den = float(np.dot(w, sv))
        dden = float(np.dot(w, sd))
        f_value = (w * sv) @ r / den
        f_deriv = ((w * sd) @ r - dden * f_value) / den
        check_close(name, t, "value", f_value.tolist(), value, dim, tol)
        check_close(name, t, "derivative", f_deriv.tolist(), deriv, dim, tol)
        evaluations.append({"t": exact(t), "value": value, "derivative": deriv})
    case = {
        "name": name,
        "dimension": dim,
        "degree": p,
        "clamped": is_clamped(knots, p),
        "knots": exact_list(knots),
        "control_points": [point_json(pos, deg) for pos, deg in points],
        "weights": exact_list(weights),
        "evaluations": evaluations,
    }
    if note:
        case["note"] = note
    return case


def random_curve_setup(rng, p, dim, clamped, max_interior, extra):
    n = p + 1 + extra
    knots = random_knots(rng, p, n, clamped, max_interior)
    points = [random_point(rng, dim) for _ in range(n)]
    return knots, points


def make_bspline(seed=20240601):
    rng = random.Random(seed)
    cases = []
    degrees = list(range(0, 8)) + [9, 12, 15]
    for p in degrees:
        for dim in (2, 3):
            for clamped in (True, False):
                extra = rng.randint(0 if p else 2, 6) if p <= 7 else rng.randint(0, 3)
                knots, points = random_curve_setup(rng, p, dim, clamped, max(p, 1), extra)
                name = "bspline_d%d_p%d_%s" % (dim, p, "clamped" if clamped else "unclamped")
                n_random = 5 if p <= 7 else 3
                cases.append(bspline_case(name, dim, p, knots, points, rng, n_random))
    # Repeated interior knots at multiplicity exactly p (C0 joints), clamped.
    for p in (2, 3, 5):
        n = 3 * p + 1
        a = 0.0
        knots = [a] * (p + 1) + [1.0] * p + [2.5] * p + [4.0] * (p + 1)
        points = [random_point(rng, 2) for _ in range(n)]
        cases.append(bspline_case("bspline_d2_p%d_c0_joints" % p, 2, p, knots, points, rng, 4,
                                  note="interior knots 1 and 2.5 of multiplicity p (C0)"))
    # Discontinuities: an interior knot of multiplicity p + 1.
    for p in (0, 1, 2, 3, 4, 6):
        for clamped in (True, False):
            for _attempt in range(50):
                extra = rng.randint(p + 1, p + 5)
                knots, points = random_curve_setup(rng, p, 2, clamped, max(p, 1), extra)
                disc = with_discontinuity(rng, knots, p)
                if disc is not None:
                    break
            else:
                raise AssertionError("no discontinuous knot vector for p = %d" % p)
            name = "bspline_d2_p%d_%s_discontinuous" % (p, "clamped" if clamped else "unclamped")
            cases.append(bspline_case(
                name, 2, p, disc, points, rng, 4,
                note="an interior knot of multiplicity p + 1: the value there is the right-hand "
                     "limit (scipy and the core agree); nextafter(knot, -inf) gives the left piece"))
    # Wide-magnitude positions and a tiny knot scale.
    p, n = 3, 8
    knots = random_knots(rng, p, n, True, p, start=1000.0, scale=1e-3)
    points = [([rng.uniform(-1e6, 1e6), rng.uniform(-1e-3, 1e-3)], [rng.random() for _ in range(3)])
              for _ in range(n)]
    cases.append(bspline_case("bspline_d2_p3_wide_magnitudes", 2, p, knots, points, rng, 5,
                              note="positions up to 1e6 and down to 1e-3, knots near 1000 with "
                                   "spacing ~1e-3"))
    return {
        "description": "Random neutrosophic B-spline curves. value: scipy.interpolate.BSpline "
                       "(extrapolate=False) on the control rows (coordinates, then truth, "
                       "indeterminacy, falsity); derivative: d/dt from BSpline.derivative() "
                       "(BSpline(x, nu=1) where derivative() refuses a knot of multiplicity "
                       "p + 1). Cross-checked against an mpmath Cox-de Boor sum at 50 digits. "
                       "Right-hand values at interior knots, left-hand at the domain end.",
        "generator": "scripts/reference/make_spline_reference.py",
        "seed": seed,
        "channels": "value and derivative: coordinates, then truth, indeterminacy, falsity",
        "exact_inputs": EXACT_NOTE,
        "cases": cases,
    }


def make_nurbs(seed=20240602):
    rng = random.Random(seed)
    cases = []
    for p in list(range(0, 8)) + [10, 15]:
        for dim in (2, 3):
            clamped = rng.random() < 0.5
            max_interior = max(p, 1) if rng.random() < 0.8 else p + 1
            extra = rng.randint(0, 6) if p <= 7 else rng.randint(0, 2)
            knots, points = random_curve_setup(rng, p, dim, clamped, max_interior, extra)
            weights = [10.0 ** rng.uniform(-1.0, 1.0) for _ in points]
            if rng.random() < 0.3:
                weights[rng.randrange(len(weights))] = 0.1
                weights[rng.randrange(len(weights))] = 10.0
            name = "nurbs_d%d_p%d_%s" % (dim, p, "clamped" if clamped else "unclamped")
            ts = parameters(rng, knots, p, 5 if p <= 7 else 3)
            cases.append(nurbs_case(name, dim, p, knots, points, weights, ts))
    # A discontinuous NURBS curve.
    for _attempt in range(50):
        knots, points = random_curve_setup(rng, 2, 3, True, 2, 5)
        disc = with_discontinuity(rng, knots, 2)
        if disc is not None:
            break
    weights = [10.0 ** rng.uniform(-1.0, 1.0) for _ in points]
    cases.append(nurbs_case("nurbs_d3_p2_discontinuous", 3, 2, disc, points, weights,
                            parameters(rng, disc, 2, 4),
                            note="an interior knot of multiplicity 3: right-hand value there"))
    # Equal weights (the B-spline): the rational formula collapses to sum N_i P_i.
    knots, points = random_curve_setup(rng, 3, 2, False, 3, 4)
    cases.append(nurbs_case("nurbs_d2_p3_equal_weights", 2, 3, knots, points, [2.5] * len(points),
                            parameters(rng, knots, 3, 4), note="all weights 2.5"))
    # The unit circle: quarter (3 points) and full (9 points, 4 quarter arcs).
    s = math.sqrt(0.5)
    quarter_pts = [([1.0, 0.0], [0.0, 0.5, 0.25]), ([1.0, 1.0], [1.0, 0.5, 0.25]),
                   ([0.0, 1.0], [0.5, 0.5, 0.25])]
    ts = [k / 16.0 for k in range(17)] + [0.1, 0.3, 1.0 / 3.0]
    cases.append(nurbs_case("nurbs_quarter_circle", 2, 2, [0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
                            quarter_pts, [1.0, s, 1.0], sorted(ts),
                            note="unit quarter circle, weights 1, sqrt(1/2), 1: x^2 + y^2 = 1"))
    full = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]]
    full_pts = [([float(x), float(y)], [i / 8.0, 0.5, 1.0 - i / 8.0]) for i, (x, y) in enumerate(full)]
    full_w = [1.0, s, 1.0, s, 1.0, s, 1.0, s, 1.0]
    full_knots = [0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0]
    ts = sorted(set([k / 32.0 for k in range(33)] + [0.1, 0.3, 0.7, 0.9]))
    cases.append(nurbs_case("nurbs_full_circle", 2, 2, full_knots, full_pts, full_w, ts,
                            note="unit circle from 4 quarter arcs, double knots at 1/4, 1/2, 3/4"))
    # the circles really are circles (the exact formula, rounded)
    for case in cases[-2:]:
        for e in case["evaluations"]:
            x, y = e["value"][:2]
            assert abs(math.hypot(x, y) - 1.0) <= 2.3e-16, (case["name"], e["t"], x, y)
    return {
        "description": "Random neutrosophic NURBS curves: the rational formula "
                       "R_i = w_i N_i / sum_j w_j N_j with the Cox-de Boor basis in mpmath at "
                       "50 digits on the exact double inputs, derivative by the quotient rule "
                       "C' = (A' - w' C) / w; cross-checked against the same formula on "
                       "scipy's basis in float64. Right-hand values at interior knots, "
                       "left-hand at the domain end.",
        "generator": "scripts/reference/make_spline_reference.py",
        "seed": seed,
        "channels": "value and derivative: coordinates, then truth, indeterminacy, falsity",
        "exact_inputs": EXACT_NOTE,
        "cases": cases,
    }


# --------------------------------------------------------------------------- surfaces


def surface_case(name, kind, rows, cols, pu, pv, ku, kv, points, weights, params, rng):
    """points: row-major list of (position, degrees); weights None for non-rational."""
    mrows = [[mpf(x) for x in (pos + deg)] for pos, deg in points]
    w_list = weights if weights is not None else [1.0] * (rows * cols)
    mw = [mpf(w) for w in w_list]
    m_pos = max(abs(x) for pos, _ in points for x in pos)
    ratio = max(w_list) / min(w_list)
    tol = {
        "value_position": REL_TOL * m_pos,
        "value_degree": REL_TOL,
    }
    for d, kn, pp in (("u", ku, pu), ("v", kv, pv)):
        scale = pp * 2.0 / min_positive_span(kn, pp) * ratio
        tol["d%s_position" % d] = REL_TOL * scale * m_pos
        tol["d%s_degree" % d] = REL_TOL * scale
    np_rows = np.array([pos + deg for pos, deg in points]).reshape(rows, cols, 6)
    np_w = np.array(w_list).reshape(rows, cols)
    evaluations = []
    for (u, v) in params:
        if kind == "bezier":
            nu, dnu = bernstein(rows - 1, u)
            nv, dnv = bernstein(cols - 1, v)
        else:
            nu, dnu = cox_de_boor(ku, pu, u)
            nv, dnv = cox_de_boor(kv, pv, v)
        # tensor-product sums in mpmath
        h = [mpf(0)] * 6
        hu = [mpf(0)] * 6
        hv = [mpf(0)] * 6
        wsum = wu = wv = mpf(0)
        for i in range(rows):
            for j in range(cols):
                k = i * cols + j
                b, bu, bv = nu[i] * nv[j] * mw[k], dnu[i] * nv[j] * mw[k], nu[i] * dnv[j] * mw[k]
                wsum += b
                wu += bu
                wv += bv
                for c in range(6):
                    h[c] += b * mrows[k][c]
                    hu[c] += bu * mrows[k][c]
                    hv[c] += bv * mrows[k][c]
        value = [hc / wsum for hc in h]
        du = [(huc - wu * vc) / wsum for huc, vc in zip(hu, value)]
        dv = [(hvc - wv * vc) / wsum for hvc, vc in zip(hv, value)]
        value, du, dv = ([to_double(x) for x in vec] for vec in (value, du, dv))
        # float64 cross-check: numpy einsum on scipy bases (Bezier: clamped single-span knots)
        kuu = ku if kind != "bezier" else [0.0] * rows + [1.0] * rows
        kvv = kv if kind != "bezier" else [0.0] * cols + [1.0] * cols
        su, sdu = scipy_basis(kuu, rows - 1 if kind == "bezier" else pu, u)
        sv, sdv = scipy_basis(kvv, cols - 1 if kind == "bezier" else pv, v)
        fw = np.einsum("i,j,ij->", su, sv, np_w)
        fwu = np.einsum("i,j,ij->", sdu, sv, np_w)
        fwv = np.einsum("i,j,ij->", su, sdv, np_w)
        fval = np.einsum("i,j,ij,ijc->c", su, sv, np_w, np_rows) / fw
        fdu = (np.einsum("i,j,ij,ijc->c", sdu, sv, np_w, np_rows) - fwu * fval) / fw
        fdv = (np.einsum("i,j,ij,ijc->c", su, sdv, np_w, np_rows) - fwv * fval) / fw
        for what, got, want in (("value", fval, value), ("du", fdu, du), ("dv", fdv, dv)):
            for c in range(6):
                kindc = "position" if c < 3 else "degree"
                bound = CHECK_FRACTION * tol["%s_%s" % (what, kindc)]
                if not abs(got[c] - want[c]) <= bound:
                    raise AssertionError("%s: (%r, %r) %s channel %d: %r vs %r"
                                         % (name, u, v, what, c, got[c], want[c]))
        evaluations.append({"u": exact(u), "v": exact(v), "value": value, "du": du, "dv": dv})
    case = {
        "name": name,
        "kind": kind,
        "rows": rows,
        "cols": cols,
        "degree_u": pu,
        "degree_v": pv,
        "knots_u": exact_list(ku),
        "knots_v": exact_list(kv),
        "control_points": [point_json(pos, deg) for pos, deg in points],
        "evaluations": evaluations,
    }
    if weights is not None:
        case["weights"] = exact_list(weights)
    return case


def surface_params(rng, ku, pu, kv, pv, n_random):
    (a, b), (c, d) = (ku[pu], ku[len(ku) - 1 - pu]), (kv[pv], kv[len(kv) - 1 - pv])
    out = [(a, c), (a, d), (b, c), (b, d)]
    inner_u = sorted(set(k for k in ku if a < k < b))
    inner_v = sorted(set(k for k in kv if c < k < d))
    for k in inner_u[:3]:
        out.append((k, rng.uniform(c, d)))
    for k in inner_v[:3]:
        out.append((rng.uniform(a, b), k))
    if inner_u and inner_v:
        out.append((inner_u[0], inner_v[-1]))
    for _ in range(n_random):
        out.append((rng.uniform(a, b), rng.uniform(c, d)))
    return out


def make_surfaces(seed=20240603):
    rng = random.Random(seed)
    cases = []
    # Bezier surfaces
    for (rows, cols) in [(1, 1), (2, 2), (3, 4), (4, 3), (6, 5), (8, 8)]:
        points = [random_point(rng, 3) for _ in range(rows * cols)]
        ku = [0.0] * rows + [1.0] * rows
        kv = [0.0] * cols + [1.0] * cols
        params = surface_params(rng, ku, rows - 1, kv, cols - 1, 8)
        cases.append(surface_case("bezier_%dx%d" % (rows, cols), "bezier", rows, cols,
                                  rows - 1, cols - 1, ku, kv, points, None, params, rng))
    # B-spline and NURBS surfaces
    for kind in ("bspline", "nurbs"):
        for (pu, pv) in [(0, 1), (1, 2), (2, 2), (3, 2), (3, 3), (2, 5), (4, 1)]:
            rows = pu + 1 + rng.randint(0, 4)
            cols = pv + 1 + rng.randint(0, 4)
            cu, cv = rng.random() < 0.6, rng.random() < 0.6
            ku = random_knots(rng, pu, rows, cu, max(pu, 1))
            kv = random_knots(rng, pv, cols, cv, max(pv, 1))
            points = [random_point(rng, 3) for _ in range(rows * cols)]
            weights = None
            if kind == "nurbs":
                weights = [10.0 ** rng.uniform(-1.0, 1.0) for _ in range(rows * cols)]
            params = surface_params(rng, ku, pu, kv, pv, 6)
            name = "%s_p%dx%d_%dx%d_%s%s" % (kind, pu, pv, rows, cols,
                                             "c" if cu else "u", "c" if cv else "u")
            cases.append(surface_case(name, kind, rows, cols, pu, pv, ku, kv, points, weights,
                                      params, rng))
    return {
        "description": "Random neutrosophic tensor-product surfaces: "
                       "S = sum_ij w_ij N_i(u) M_j(v) P_ij / sum_ij w_ij N_i(u) M_j(v) "
                       "(w = 1 for bezier and bspline; Bernstein bases with exact binomials "
                       "for bezier) in mpmath at 50 digits, partial derivatives du, dv by the "
                       "quotient rule; cross-checked with a float64 numpy einsum on scipy's "
                       "bases. Control points row-major (row index along u).",
        "generator": "scripts/reference/make_spline_reference.py",
        "seed": seed,
        "channels": "value, du, dv: x, y, z, truth, indeterminacy, falsity",
        "exact_inputs": EXACT_NOTE,
        "cases": cases,
    }


# --------------------------------------------------------------------------- output


def dumps(obj):
    """JSON with one case header, control point or evaluation per line (readable diffs)."""
    header = {k: v for k, v in obj.items() if k != "cases"}
    lines = ["{"]
    for k, v in header.items():
        lines.append(" %s: %s," % (json.dumps(k), json.dumps(v, allow_nan=False)))
    lines.append(' "cases": [')
    case_texts = []
    for case in obj["cases"]:
        parts = []
        for k, v in case.items():
            if k in ("control_points", "evaluations"):
                items = ",\n".join("   " + json.dumps(x, allow_nan=False, separators=(",", ":"))
                                   for x in v)
                parts.append("  %s: [\n%s\n  ]" % (json.dumps(k), items))
            else:
                parts.append("  %s: %s" % (json.dumps(k), json.dumps(v, allow_nan=False,
                                                                     separators=(",", ":"))))
        case_texts.append(" {\n" + ",\n".join(parts) + "\n }")
    lines.append(",\n".join(case_texts))
    lines.append(" ]")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    json.loads(text)  # well-formed
    return text


def write(name, obj):
    path = os.path.join(OUT_DIR, name)
    text = dumps(obj)
    with open(path, "w") as f:
        f.write(text)
    n_eval = sum(len(c["evaluations"]) for c in obj["cases"])
    print("%-22s %3d cases, %5d evaluations, %7d bytes" % (name, len(obj["cases"]), n_eval,
                                                            len(text)))


def main():
    write("spline_bspline.json", make_bspline())
    write("spline_nurbs.json", make_nurbs())
    write("surface_random.json", make_surfaces())


if __name__ == "__main__":
    main()
