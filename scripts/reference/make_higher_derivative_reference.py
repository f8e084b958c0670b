#!/usr/bin/env python3
"""Independent reference values for the higher derivatives of neutrospline curves and surfaces.

How to run (from the repository root):

    python3 -m venv /tmp/venv-ref \
      && /tmp/venv-ref/bin/pip install sympy \
      && /tmp/venv-ref/bin/python scripts/reference/make_higher_derivative_reference.py

Method (independent of the Rust core's de Boor / Leibniz code): every input double is turned
into its exact rational value; on the span that holds the parameter (the right-hand span at an
interior knot, the last non-empty span at the domain end, as the core does) the basis
functions are built symbolically by the Cox-de Boor recursion as polynomials with rational
coefficients (Bernstein polynomials with exact binomials for Bézier kinds); the curve or
surface is the explicit sum (for NURBS the explicit quotient sum w_i N_i P_i / sum w_i N_i),
differentiated symbolically by sympy and evaluated exactly at the rational parameter. The
exact results are rounded once to the nearest double (Python's correctly rounded int / int).

Written to `crates/neutrospline/tests/data/higher_derivatives.json`: for each curve case the
derivatives of orders 1, 2, 3 of every channel (coordinates, truth, indeterminacy, falsity)
at a few parameters; for each surface case the partials d^(a+b) / du^a dv^b, a + b = 1..3.
Cases: the paper's Example 1 (Bézier), `examples/bspline.toml`, the unit circle
`examples/nurbs-circle.toml`, the Bézier hill `examples/surface.toml`, the quarter cylinder
`examples/nurbs-surface.json` and a bi-quadratic B-spline surface with an interior knot.
Deterministic: no random input.
"""

import json
import os
from fractions import Fraction

import sympy as sp

X = sp.Symbol("x")
U, V = sp.symbols("u v")


def q(text):
    """The exact rational value of the double nearest to `text`."""
    f = Fraction(float(text))
    return sp.Rational(f.numerator, f.denominator)


def to_double(value):
    value = sp.nsimplify(value) if not isinstance(value, sp.Rational) else value
    value = sp.Rational(value)
    return repr(int(value.p) / int(value.q)) if value.q != 1 else repr(float(int(value.p)))


def span(knots, p, t):
    """Index k with knots[k] <= t < knots[k+1]; the last non-empty span at the domain end."""
    n = len(knots) - p - 1
    end = knots[n]
    if t >= end:
        k = n - 1
        while knots[k] == knots[k + 1]:
            k -= 1
        return k
    k = p
    while not (knots[k] <= t < knots[k + 1]):
        k += 1
    return k


def basis(knots, p, k, x):
    """The polynomials N_{i,p} on span k (Cox-de Boor), for every i (zero off the span)."""
    m = len(knots) - 1
    n = [sp.Integer(1) if i == k else sp.Integer(0) for i in range(m)]
    for d in range(1, p + 1):
        nxt = []
        for i in range(m - d):
            term = sp.Integer(0)
            den = knots[i + d] - knots[i]
            if den != 0 and n[i] != 0:
                term += (x - knots[i]) / den * n[i]
            den = knots[i + d + 1] - knots[i + 1]
            if den != 0 and n[i + 1] != 0:
                term += (knots[i + d + 1] - x) / den * n[i + 1]
            nxt.append(sp.expand(term))
        n = nxt
    return n


def clamped_uniform(p, count):
    inner = count - p - 1
    return [sp.Integer(0)] * (p + 1) + [sp.Rational(i, inner + 1) for i in range(1, inner + 1)] + [sp.Integer(1)] * (p + 1)


def curve_case(name, kind, degree, knots, points, weights, params, dim):
    """points: list of rows [x, y, (z), T, I, F] as exact rationals."""
    out = {"name": name, "kind": kind, "degree": degree, "dimension": dim,
           "knots": [to_double(k) for k in knots] if knots is not None else None,
           "weights": [to_double(w) for w in weights] if weights is not None else None,
           "control_points": [[to_double(c) for c in row] for row in points],
           "evaluations": []}
    if knots is None:
        knots = [sp.Integer(0)] * (degree + 1) + [sp.Integer(1)] * (degree + 1)
    for text in params:
        t = q(text)
        k = span(knots, degree, t)
        n = basis(knots, degree, k, X)
        ws = weights if weights is not None else [sp.Integer(1)] * len(points)
        denominator = sum(ws[i] * n[i] for i in range(len(points)))
        channels = []
        for c in range(dim + 3):
            numerator = sum(ws[i] * n[i] * points[i][c] for i in range(len(points)))
            channels.append(numerator / denominator)
        orders = []
        for order in (1, 2, 3):
            orders.append([to_double(sp.simplify(sp.diff(f, X, order).subs(X, t))) for f in channels])
        out["evaluations"].append({"t": text, "d1": orders[0], "d2": orders[1], "d3": orders[2]})
    return out


def surface_case(name, kind, rows, cols, pu, pv, knots_u, knots_v, points, weights, params):
    out = {"name": name, "kind": kind, "rows": rows, "cols": cols,
           "degree_u": pu, "degree_v": pv,
           "knots_u": [to_double(k) for k in knots_u], "knots_v": [to_double(k) for k in knots_v],
           "weights": [to_double(w) for w in weights] if weights is not None else None,
           "control_points": [[to_double(c) for c in row] for row in points],
           "evaluations": []}
    for tu, tv in params:
        u, v = q(tu), q(tv)
        nu = basis(knots_u, pu, span(knots_u, pu, u), U)
        nv = basis(knots_v, pv, span(knots_v, pv, v), V)
        ws = weights if weights is not None else [sp.Integer(1)] * len(points)
        den = sum(ws[i * cols + j] * nu[i] * nv[j] for i in range(rows) for j in range(cols))
        channels = []
        for c in range(6):
            num = sum(ws[i * cols + j] * nu[i] * nv[j] * points[i * cols + j][c]
                      for i in range(rows) for j in range(cols))
            channels.append(num / den)
        partials = {}
        for total in (1, 2, 3):
            for a in range(total, -1, -1):
                b = total - a
                key = "u" * a + "v" * b
                values = []
                for f in channels:
                    g = f
                    if a:
                        g = sp.diff(g, U, a)
                    if b:
                        g = sp.diff(g, V, b)
                    values.append(to_double(sp.simplify(g.subs({U: u, V: v}))))
                partials[key] = values
        out["evaluations"].append({"u": tu, "v": tv, "partials": partials})
    return out


def rows_of(table):
    return [[q(c) for c in row] for row in table]


def main():
    cases = []
    example1 = rows_of([["1", "3", "0.3", "0.6", "0.1"], ["3", "6", "0.8", "0.1", "0.1"],
                        ["6", "2", "0.7", "0.1", "0.2"], ["9", "5", "0.2", "0.4", "0.4"]])
    cases.append(curve_case("example1", "bezier", 3, None, example1, None,
                            ["0", "0.3", "0.5", "0.9", "1"], 2))
    quintic = rows_of([["0", "0", "1", "0.1", "0.2", "0.3"], ["1", "2", "-1", "0.5", "0.1", "0"],
                       ["2", "-1", "0.5", "0.9", "0.4", "0.2"], ["4", "3", "2", "0.2", "0.8", "0.6"],
                       ["5", "1", "-2", "1", "0", "0.5"], ["7", "2", "0", "0.4", "0.3", "1"]])
    cases.append(curve_case("quintic_3d", "bezier", 5, None, quintic, None,
                            ["0", "0.125", "0.7", "1"], 3))
    bspline = rows_of([["0", "0", "0.9", "0.1", "0.0"], ["1", "2", "0.8", "0.2", "0.1"],
                       ["3", "3", "0.6", "0.3", "0.2"], ["4", "1", "0.4", "0.5", "0.3"],
                       ["6", "0", "0.5", "0.4", "0.3"], ["7", "2", "0.7", "0.2", "0.2"],
                       ["9", "3", "0.9", "0.1", "0.1"]])
    bknots = [q(k) for k in ["0", "0", "0", "0", "0.2", "0.5", "0.7", "1", "1", "1", "1"]]
    cases.append(curve_case("examples/bspline.toml", "bspline", 3, bknots, bspline, None,
                            ["0", "0.1", "0.35", "0.5", "0.6", "0.85", "1"], 2))
    h = "0.7071067811865476"
    circle = rows_of([["1", "0", "0.9", "0.1", "0.0"], ["1", "1", "0.8", "0.2", "0.1"],
                      ["0", "1", "0.6", "0.3", "0.2"], ["-1", "1", "0.3", "0.4", "0.5"],
                      ["-1", "0", "0.1", "0.5", "0.8"], ["-1", "-1", "0.3", "0.4", "0.5"],
                      ["0", "-1", "0.6", "0.3", "0.2"], ["1", "-1", "0.8", "0.2", "0.1"],
                      ["1", "0", "0.9", "0.1", "0.0"]])
    cweights = [q(w) for w in ["1", h, "1", h, "1", h, "1", h, "1"]]
    cknots = [q(k) for k in ["0", "0", "0", "0.25", "0.25", "0.5", "0.5", "0.75", "0.75", "1", "1", "1"]]
    cases.append(curve_case("examples/nurbs-circle.toml", "nurbs", 2, cknots, circle, cweights,
                            ["0", "0.1", "0.3", "0.5", "0.6", "0.9", "1"], 2))

    surfaces = []
    hill_z = [["0", "0.5", "0.5", "0"], ["0.5", "2", "2", "0.5"], ["0.5", "2", "1.5", "0.5"],
              ["0", "0.5", "0.5", "0"]]
    hill = []
    for i in range(4):
        for j in range(4):
            hill.append([str(i), str(j), hill_z[i][j], ["0.9", "0.7", "0.5", "0.3"][i],
                         ["0.1", "0.2", "0.3", "0.4"][j],
                         ["0.0", "0.05", "0.1", "0.15", "0.2", "0.25", "0.3"][i + j]])
    bez3 = [sp.Integer(0)] * 4 + [sp.Integer(1)] * 4
    surfaces.append(surface_case("examples/surface.toml", "bezier-surface", 4, 4, 3, 3, bez3, bez3,
                                 rows_of(hill), None,
                                 [("0", "0"), ("0.25", "0.75"), ("0.5", "0.5"), ("1", "0.3")]))
    cyl = [["1", "0", "0", "0.9", "0.1", "0.05"], ["1", "0", "1", "0.6", "0.1", "0.35"],
           ["1", "0", "2", "0.3", "0.1", "0.65"], ["1", "1", "0", "0.9", "0.3", "0.05"],
           ["1", "1", "1", "0.6", "0.3", "0.35"], ["1", "1", "2", "0.3", "0.3", "0.65"],
           ["0", "1", "0", "0.9", "0.5", "0.05"], ["0", "1", "1", "0.6", "0.5", "0.35"],
           ["0", "1", "2", "0.3", "0.5", "0.65"]]
    cyl_w = [q(w) for w in ["1", "1", "1", h, h, h, "1", "1", "1"]]
    surfaces.append(surface_case("examples/nurbs-surface.json", "nurbs-surface", 3, 3, 2, 1,
                                 [q(k) for k in ["0", "0", "0", "1", "1", "1"]],
                                 clamped_uniform(1, 3), rows_of(cyl), cyl_w,
                                 [("0", "0"), ("0.3", "0.2"), ("0.5", "0.5"), ("0.8", "1")]))
    grid = []
    for i in range(4):
        for j in range(3):
            z = str([0, 1, -1, 2, 0.5, 1.5, -0.5, 0, 2, 1, 1, 0][i * 3 + j])
            grid.append([str(i), str(j * 1.5), z, str(0.1 + 0.2 * i), str(0.05 * (i + j)),
                         str(0.9 - 0.1 * j)])
    ku = [q(k) for k in ["0", "0", "0", "0.4", "1", "1", "1"]]
    kv = [q(k) for k in ["0", "0", "0", "1", "1", "1"]]
    surfaces.append(surface_case("biquadratic_bspline", "bspline-surface", 4, 3, 2, 2, ku, kv,
                                 rows_of(grid), None,
                                 [("0", "0"), ("0.2", "0.7"), ("0.4", "0.5"), ("0.9", "0.1"),
                                  ("1", "1")]))
    data = {
        "description": "Higher derivatives (orders 1-3) of curves and mixed partials (total "
                       "order 1-3) of surfaces: exact symbolic differentiation in sympy of the "
                       "explicit basis sums on the exact double inputs, rounded once to double. "
                       "Right-hand values at interior knots, left-hand at the domain end.",
        "generator": "scripts/reference/make_higher_derivative_reference.py",
        "channels": "coordinates, then truth, indeterminacy, falsity",
        "curves": cases,
        "surfaces": surfaces,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    path = os.path.join(here, "..", "..", "crates", "neutrospline", "tests", "data",
                        "higher_derivatives.json")
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    print("wrote", os.path.normpath(path))


if __name__ == "__main__":
    main()
