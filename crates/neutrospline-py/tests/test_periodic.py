"""Periodic (closed) and unclamped curves in Python: `BSpline(..., periodic=True)` and
`Nurbs(..., periodic=True)` against scipy's `BSpline(extrapolate="periodic")` on the knot
vector built here from the definition (docs/model.md, "Knot vectors"), the domain end
included; `load(..., periodic=True)` for a table; the example file; transforms that keep the
curve periodic; and the refusals."""

import numpy as np
import pytest
from scipy.interpolate import BSpline as ScipyBSpline

import neutrospline as ns


def periodic_knots(p, breakpoints):
    n = len(breakpoints) - 1
    period = breakpoints[n] - breakpoints[0]
    out = []
    for i in range(n + 2 * p + 1):
        j = i - p
        out.append(breakpoints[j] if 0 <= j <= n else breakpoints[j % n] + (j // n) * period)
    return np.array(out)


@pytest.mark.parametrize("p", [1, 2, 3, 5])
@pytest.mark.parametrize("rational", [False, True])
def test_periodic_curves_match_scipy(p, rational):
    rng = np.random.default_rng(20261204 + p)
    n = p + 4
    positions = rng.uniform(-5, 5, (n, 2))
    degrees = rng.uniform(0, 1, (n, 3))
    breakpoints = np.concatenate([[0.0], np.cumsum(rng.uniform(0.1, 1.0, n))]) + 2.0
    weights = rng.uniform(0.4, 2.5, n)
    if rational:
        curve = ns.Nurbs(positions, degrees, weights, degree=p, knots=breakpoints, periodic=True)
    else:
        curve = ns.BSpline(positions, degrees, degree=p, knots=breakpoints, periodic=True)
    assert curve.periodic_count == n
    assert len(curve) == n + p
    knots = periodic_knots(p, list(breakpoints))
    np.testing.assert_allclose(curve.knots, knots, rtol=0, atol=1e-14)
    wrapped = np.array([i % n for i in range(n + p)])
    rows = np.hstack([positions, degrees])[wrapped]
    w = weights[wrapped] if rational else np.ones(n + p)
    reference = ScipyBSpline(knots, np.hstack([rows * w[:, None], w[:, None]]), p, extrapolate="periodic")
    t = np.concatenate([[breakpoints[0], breakpoints[-1]], rng.uniform(breakpoints[0], breakpoints[-1], 50)])
    homogeneous = reference(t)
    want = homogeneous[:, :-1] / homogeneous[:, -1:]
    got = curve(t)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-12 * np.abs(want).max())
    # The curve closes: scipy wraps the end of the domain to its start.
    np.testing.assert_allclose(got[1], got[0], rtol=0, atol=1e-12 * np.abs(want).max())


def test_the_example_and_a_table(root, tmp_path):
    pond = ns.load(root / "examples" / "closed-bspline.toml")
    assert pond.periodic_count == 6 and len(pond) == 9
    assert pond.point_names[6] == "jetty"
    table = tmp_path / "square.csv"
    table.write_text("x,y,truth,indeterminacy,falsity\n0,0,0.9,0.1,0.1\n2,0,0.5,0.2,0.3\n2,2,0.3,0.2,0.6\n0,2,0.1,0.4,0.8\n")
    square = ns.load(table, kind="bspline", degree=2, periodic=True)
    built = ns.BSpline([[0, 0], [2, 0], [2, 2], [0, 2]], [[0.9, 0.1, 0.1], [0.5, 0.2, 0.3], [0.3, 0.2, 0.6], [0.1, 0.4, 0.8]], degree=2, periodic=True)
    t = np.linspace(0, 1, 17)
    np.testing.assert_array_equal(square(t), built(t))
    # Knot insertion keeps it periodic, removal gives it back.
    more = pond.transform(insert_knot=[0.4])
    assert more.periodic_count == 7
    np.testing.assert_allclose(more(t), pond(t), rtol=0, atol=1e-12)
    back = more.transform(remove_knot=0.4, tolerance=1e-9)
    assert back.periodic_count == 6
    np.testing.assert_allclose(back.knots, pond.knots, rtol=0, atol=1e-15)
    saved = tmp_path / "pond.toml"
    back.save(saved)
    assert "periodic = true" in saved.read_text()


def test_refusals():
    with pytest.raises(ValueError, match=r"knots: a periodic spline of 4 control points takes 5 breakpoints \(the control points \+ 1, from the start of one period to its end\), not 3"):
        ns.BSpline([[0, 0], [1, 0], [1, 1], [0, 1]], [[0.5, 0.5, 0.5]] * 4, degree=2, knots=[0, 0.5, 1], periodic=True)
    with pytest.raises(ValueError, match=r"degree: a periodic spline needs degree >= 1"):
        ns.BSpline([[0, 0], [1, 0]], [[0.5, 0.5, 0.5]] * 2, degree=0, periodic=True)
