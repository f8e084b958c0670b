#!/usr/bin/env python3
"""Independent reference values for crates/neutrospline/tests/integration/geometry.rs.

How to run (from the workspace root, /work/main; needs mpmath):

    python3 scripts/reference/make_arc_length_reference.py

It prints Rust constants that geometry.rs holds verbatim (each a correctly rounded double
written with Python's repr). Method, independent of the Rust core (which uses adaptive
10-point Gauss-Legendre on the de Casteljau / de Boor derivative): the cubic Bezier curve
and its degrees are written as explicit power-basis polynomials with exact rational
coefficients (fractions.Fraction from the decimal control values), the speed
|C'(t)| = sqrt(x'(t)^2 + y'(t)^2[ + z'(t)^2]) is integrated with mpmath.quad (tanh-sinh) at
50 significant digits, and the averages are (1/L) * integral of degree(t) |C'(t)| dt.

Curves:
  EXAMPLE1   the paper's Example 1 (neutrospline::example1(): P = (1,3), (3,6), (6,2), (9,5),
             (T, I, F) = (0.3,0.6,0.1), (0.8,0.1,0.1), (0.7,0.1,0.2), (0.2,0.4,0.4)).
  SPATIAL    a 3-D cubic: P = (0,0,0), (1,2,0.5), (3,-1,2), (4,1,-1).
  CIRCLE     examples/nurbs-circle.toml: four rational quadratic Bezier quarters (weights
             1, sqrt(2)/2, 1), degrees blended by the same rational basis; the speed by
             mpmath.diff. Its arc-length averages of truth, indeterminacy, falsity, score
             (printed to 12 significant digits, as `neutrospline check` prints them).
"""
from fractions import Fraction as Fr

import mpmath

mpmath.mp.dps = 50


def bernstein_cubic(values):
    """Power-basis coefficients c0..c3 of sum_i B_{3,i}(t) v_i (exact)."""
    v0, v1, v2, v3 = values
    return [v0, 3 * (v1 - v0), 3 * (v0 - 2 * v1 + v2), v3 - v0 + 3 * (v1 - v2)]


def poly(coefficients, t):
    return sum(mpmath.mpf(c.numerator) / c.denominator * t**k for k, c in enumerate(coefficients))


def dpoly(coefficients, t):
    return sum(k * mpmath.mpf(c.numerator) / c.denominator * t ** (k - 1)
               for k, c in enumerate(coefficients) if k > 0)


def curve(points):
    axes = [bernstein_cubic([Fr(str(p[a])) for p in points]) for a in range(len(points[0]))]
    return lambda t: mpmath.sqrt(sum(dpoly(c, t) ** 2 for c in axes))


def rust_float(x):
    """The double nearest to x: mpf is exactly man * 2**exp, Fraction -> float rounds."""
    x = mpmath.mpf(x)
    mantissa, exponent = int(x.man), int(x.exp)
    value = Fr(mantissa) * (Fr(2) ** exponent)
    return repr(float(value))


def main():
    example_points = [(1, 3), (3, 6), (6, 2), (9, 5)]
    degrees = [(0.3, 0.6, 0.1), (0.8, 0.1, 0.1), (0.7, 0.1, 0.2), (0.2, 0.4, 0.4)]
    speed = curve(example_points)
    length, error = mpmath.quad(speed, [0, 1], error=True)
    assert error < mpmath.mpf(10) ** -30 * length, error
    half = mpmath.quad(speed, [0, mpmath.mpf(1) / 2])
    averages = []
    for k in range(3):
        c = bernstein_cubic([Fr(str(d[k])) for d in degrees])
        averages.append(mpmath.quad(lambda t: poly(c, t) * speed(t), [0, 1]) / length)
    score = (2 + averages[0] - averages[1] - averages[2]) / 3
    print(f"const EXAMPLE1_LENGTH: f64 = {rust_float(length)};")
    print(f"const EXAMPLE1_HALF_LENGTH: f64 = {rust_float(half)};")
    for name, value in zip(["TRUTH", "INDETERMINACY", "FALSITY"], averages):
        print(f"const EXAMPLE1_AVERAGE_{name}: f64 = {rust_float(value)};")
    print(f"const EXAMPLE1_AVERAGE_SCORE: f64 = {rust_float(score)};")
    spatial = curve([(0, 0, 0), (1, 2, 0.5), (3, -1, 2), (4, 1, -1)])
    print(f"const SPATIAL_LENGTH: f64 = {rust_float(mpmath.quad(spatial, [0, 1]))};")
    print(f"const SPATIAL_LENGTH_FROM_0_3_TO_0_8: f64 = "
          f"{rust_float(mpmath.quad(spatial, [mpmath.mpf(0.3), mpmath.mpf(0.8)]))};")
    circle_averages()


def circle_averages():
    w = mpmath.sqrt(2) / 2
    rows = [((1, 0), 1, (0.9, 0.1, 0.0)), ((1, 1), w, (0.8, 0.2, 0.1)), ((0, 1), 1, (0.6, 0.3, 0.2)),
            ((-1, 1), w, (0.3, 0.4, 0.5)), ((-1, 0), 1, (0.1, 0.5, 0.8)), ((-1, -1), w, (0.3, 0.4, 0.5)),
            ((0, -1), 1, (0.6, 0.3, 0.2)), ((1, -1), w, (0.8, 0.2, 0.1)), ((1, 0), 1, (0.9, 0.1, 0.0))]
    length = mpmath.mpf(0)
    weighted = [mpmath.mpf(0)] * 3
    for quarter in range(4):
        piece = rows[2 * quarter: 2 * quarter + 3]

        def blend(u, value):
            basis = [(1 - u) ** 2, 2 * u * (1 - u), u**2]
            den = sum(b * r[1] for b, r in zip(basis, piece))
            return sum(b * r[1] * value(r) for b, r in zip(basis, piece)) / den

        def speed(u):
            dx = mpmath.diff(lambda s: blend(s, lambda r: r[0][0]), u)
            dy = mpmath.diff(lambda s: blend(s, lambda r: r[0][1]), u)
            return mpmath.sqrt(dx**2 + dy**2)

        length += mpmath.quad(speed, [0, 1])
        for k in range(3):
            weighted[k] += mpmath.quad(
                lambda u: blend(u, lambda r: mpmath.mpf(str(r[2][k]))) * speed(u), [0, 1])
    averages = [value / length for value in weighted]
    score = (2 + averages[0] - averages[1] - averages[2]) / 3
    print("circle length", mpmath.nstr(length, 12), "(2 pi =", mpmath.nstr(2 * mpmath.pi, 12), ")")
    print("circle averages (truth, indeterminacy, falsity, score):",
          ", ".join(mpmath.nstr(v, 12) for v in averages + [score]))


if __name__ == "__main__":
    main()
