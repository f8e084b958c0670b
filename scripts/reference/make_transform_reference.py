#!/usr/bin/env python3
"""Independent reference data for the curve operations of `neutrospline transform`:
knot insertion with multiplicity, knot refinement, splitting and degree elevation of
B-spline and NURBS curves, computed by geomdl 5.3.1 (NURBS-Python), whose algorithms are
The NURBS Book's written independently of ours.

How to run (from the workspace root):

    python3 -m venv /tmp/venv-geomdl \
      && /tmp/venv-geomdl/bin/pip install geomdl==5.3.1 \
      && /tmp/venv-geomdl/bin/python scripts/reference/make_transform_reference.py

Deterministic (fixed seed, Python's `random`). Written to
`crates/neutrospline/tests/data/transform_geomdl.json`: for each curve its degree, knots,
control rows `[x, y, truth, indeterminacy, falsity]` and weights (NURBS), then

  insert   knot u inserted r times (geomdl operations.insert_knot): knots and control rows
  refine   one knot inserted in the middle of every span (geomdl operations.insert_knot at
           each midpoint; geomdl's own refine_knotvector raises every knot to multiplicity p,
           a different operation): knots and control rows
  split    geomdl operations.split_curve at u: both pieces' knots and control rows
  elevate  geomdl operations.degree_operations(+1) on the curve decomposed into Bezier
           pieces (geomdl elevates piece by piece): each piece's control rows

The degree channels are blended like coordinates (docs/model.md section 4), so geomdl treats
each row as a 5-D point; NURBS rows are weighted by geomdl in homogeneous form. Doubles are
written with Python's repr.
"""

import json
import os
import random

from geomdl import BSpline, NURBS, operations

OUT = os.path.join(os.path.dirname(__file__), "..", "..", "crates", "neutrospline", "tests",
                   "data", "transform_geomdl.json")


def curve_of(degree, knots, rows, weights):
    c = NURBS.Curve() if weights is not None else BSpline.Curve()
    c.degree = degree
    if weights is not None:
        c.ctrlptsw = [[v * w for v in row] + [w] for row, w in zip(rows, weights)]
    else:
        c.ctrlpts = [list(r) for r in rows]
    c.knotvector = list(knots)
    return c


def rows_of(c):
    if isinstance(c, NURBS.Curve):
        return [list(p) for p in c.ctrlpts], list(c.weights)
    return [list(p) for p in c.ctrlpts], None


def main():
    rng = random.Random(20261204)
    cases = []
    for k in range(10):
        degree = [2, 3, 3, 4, 5, 2, 3, 4, 3, 2][k]
        rational = k >= 7
        n = degree + 1 + rng.randint(2, 5)
        interior = sorted(round(rng.uniform(0.05, 0.95), 3) for _ in range(n - degree - 1))
        knots = [0.0] * (degree + 1) + interior + [1.0] * (degree + 1)
        rows = [[rng.uniform(-10, 10), rng.uniform(-10, 10),
                 rng.random(), rng.random(), rng.random()] for _ in range(n)]
        weights = [rng.uniform(0.5, 3.0) for _ in range(n)] if rational else None
        u = round(rng.uniform(0.1, 0.9), 4)
        r = rng.randint(1, degree)
        case = dict(degree=degree, knots=knots, rows=rows, weights=weights, u=u, times=r)

        c = curve_of(degree, knots, rows, weights)
        operations.insert_knot(c, [u], [r])
        ins_rows, ins_w = rows_of(c)
        case["insert"] = dict(knots=list(c.knotvector), rows=ins_rows, weights=ins_w)

        c = curve_of(degree, knots, rows, weights)
        breaks = sorted(set(knots))
        for a, b in zip(breaks, breaks[1:]):
            operations.insert_knot(c, [a + (b - a) / 2.0], [1])
        ref_rows, ref_w = rows_of(c)
        case["refine"] = dict(knots=list(c.knotvector), rows=ref_rows, weights=ref_w)

        c = curve_of(degree, knots, rows, weights)
        left, right = operations.split_curve(c, u)
        pieces = []
        for piece in (left, right):
            pr, pw = rows_of(piece)
            pieces.append(dict(knots=list(piece.knotvector), rows=pr, weights=pw))
        case["split"] = pieces

        c = curve_of(degree, knots, rows, weights)
        elevated = operations.degree_operations(operations.decompose_curve(c)[0], [1])
        pieces = []
        for piece in operations.decompose_curve(c):
            e = operations.degree_operations(piece, [1])
            er, ew = rows_of(e)
            pieces.append(dict(rows=er, weights=ew))
        del elevated
        case["elevate"] = pieces
        cases.append(case)
    with open(OUT, "w") as f:
        json.dump(dict(generator="geomdl 5.3.1 (scripts/reference/make_transform_reference.py)",
                       cases=cases), f, indent=1)
    print(f"wrote {len(cases)} cases to {os.path.normpath(OUT)}")


if __name__ == "__main__":
    main()
