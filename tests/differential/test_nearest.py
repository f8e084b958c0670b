"""`neutrospline query` (the global nearest point) against the independent reference of
reference.py: dense sampling of every knot span, every discrete local minimum that a Lipschitz
bound cannot rule out refined (safeguarded Newton in floats, then Newton in mpmath at 40
digits), the span ends included.

Verdict per query point (reference.judge_nearest): the true distance |C(t) - q| of our
parameter, measured in mpmath, may differ from the reference's minimum by at most 1e-9 of the
curve's size (more: a wrong global minimum; less: the reference missed one); the reported point
and distance are C(t) and |C(t) - q|; minima tied within 1e-13 of the size go to the smallest
parameter. A failing case is shrunk and written to regressions/nearest-*.json, which every run
replays.
"""

import json
import random

import pytest

from conftest import REGRESSIONS, case_budget, first_seed
from harness import CliError, query, shape_from_json, shrink_curve, write_regression
from reference import (
    Curve,
    Surface,
    degenerate_curve,
    degenerate_surface,
    judge_nearest,
    judge_nearest_surface,
    query_points,
    surface_queries,
)

QUERIES_PER_CASE = 16


def curve_verdicts(cli, curve, points):
    """[(point, problem)] for the points where our answer is wrong (problem a text)."""
    try:
        rows = query(cli, curve, points)
    except CliError as err:
        return [(None, f"the command failed on a valid model: {err}")]
    bad = []
    coords = ["x", "y", "z"][: curve.dim]
    for p, r in zip(points, rows):
        problem = judge_nearest(curve, p, r["t"], r["distance"], [r[c] for c in coords])
        if problem:
            bad.append((p, problem))
    return bad


def surface_verdicts(cli, surface, points):
    try:
        rows = query(cli, surface, points)
    except CliError as err:
        return [(None, f"the command failed on a valid model: {err}")]
    bad = []
    for p, r in zip(points, rows):
        problem = judge_nearest_surface(surface, p, r["u"], r["v"], r["distance"], [r["x"], r["y"], r["z"]])
        if problem:
            bad.append((p, problem))
    return bad


def report(shape, bad, prefix="nearest"):
    lines = [f"{len(bad)} wrong nearest point(s) on {json.dumps(shape.model())}"]
    for p, problem in bad[:5]:
        lines.append(f"  query {p}: {problem}")
    return "\n".join(lines)


def record_curve_failure(cli, curve, points, bad, note):
    """Shrink the failure (one query point, a simpler curve still failing) and save it. A
    command that fails or hangs is saved with all its points, unshrunk (each try could take the
    whole timeout)."""
    point = bad[0][0]
    if point is None:
        return write_regression(REGRESSIONS, "nearest", {"shape": curve.to_json(), "queries": points, "note": note, "found": bad[0][1]})

    def fails(c):
        return bool(curve_verdicts(cli, c, [point]))

    small = shrink_curve(curve, fails)
    problem = curve_verdicts(cli, small, [point])
    path = write_regression(
        REGRESSIONS,
        "nearest",
        {"shape": small.to_json(), "queries": [point], "note": note, "found": problem[0][1] if problem else bad[0][1]},
    )
    return path


@pytest.mark.parametrize("case", range(case_budget()))
def test_random_curve_nearest(cli, case):
    rng = random.Random(first_seed() + case)
    curve = degenerate_curve(rng)
    points = query_points(rng, curve, QUERIES_PER_CASE)
    bad = curve_verdicts(cli, curve, points)
    if bad:
        path = record_curve_failure(cli, curve, points, bad, f"test_random_curve_nearest seed {first_seed() + case}")
        pytest.fail(report(curve, bad) + f"\nshrunk to {path}")


@pytest.mark.parametrize("case", range(max(1, case_budget() // 8)))
def test_random_surface_nearest(cli, case):
    rng = random.Random(10**6 + first_seed() + case)
    surface = degenerate_surface(rng)
    points = surface_queries(rng, surface, 8)
    bad = surface_verdicts(cli, surface, points)
    if bad:
        path = write_regression(
            REGRESSIONS,
            "nearest",
            {"shape": surface.to_json(), "queries": points if bad[0][0] is None else [bad[0][0]], "note": f"test_random_surface_nearest seed {10**6 + first_seed() + case}", "found": bad[0][1]},
        )
        pytest.fail(report(surface, bad) + f"\nsaved to {path}")


def test_lead_stationary_ends_cubic(cli):
    """Issue 22's example: (461, 123), (461 - 6e-14, 123 + 4e-14), (111, 319), (111, 319), both
    ends stationary; the curve is nearly the segment between the ends, so points on it and
    beside it have interior nearest points, not an end."""
    curve = Curve("bezier", 3, [(461.0, 123.0), (461 - 6e-14, 123 + 4e-14), (111.0, 319.0), (111.0, 319.0)])
    points = [[286.0, 221.0], [400.0, 157.0], [200.0, 269.0], [300.0, 250.0], [250.0, 200.0], [460.0, 124.0]]
    points += [[float(c) for c in curve.point(t)[0]] for t in (0.1, 0.37, 0.5, 0.8)]
    bad = curve_verdicts(cli, curve, points)
    assert not bad, report(curve, bad)


def test_circle_centre_takes_the_start(cli):
    """Every point of the NURBS unit circle is at distance 1 from the centre: the smallest
    parameter, t = 0, is the answer (docs/model.md section 10)."""
    s = 0.7071067811865476
    circle = Curve(
        "nurbs",
        2,
        [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0), (-1.0, -1.0), (0.0, -1.0), (1.0, -1.0), (1.0, 0.0)],
        [1, s, 1, s, 1, s, 1, s, 1],
        [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
    )
    bad = curve_verdicts(cli, circle, [[0.0, 0.0], [0.5, 0.0], [3.0, 4.0]])
    assert not bad, report(circle, bad)


def regression_files(prefix):
    return sorted(REGRESSIONS.glob(f"{prefix}-*.json"))


# Open defects of the library that the harness found and that are not fixed yet: each stays
# red-on-green (a strict xfail fails the run as soon as it passes, so it is removed then).
KNOWN_DEFECTS: dict = {}


@pytest.mark.parametrize("path", regression_files("nearest"), ids=lambda p: p.name)
def test_nearest_regressions(cli, path, request):
    if path.name in KNOWN_DEFECTS:
        request.applymarker(pytest.mark.xfail(reason=KNOWN_DEFECTS[path.name], strict=True))
    case = json.loads(path.read_text())
    shape = shape_from_json(case["shape"])
    if isinstance(shape, Surface):
        bad = surface_verdicts(cli, shape, case["queries"])
    else:
        bad = curve_verdicts(cli, shape, case["queries"])
    assert not bad, f"{path.name} ({case.get('note')}):\n" + report(shape, bad)


# ---- the reference itself -------------------------------------------------------------------


def test_reference_closed_forms():
    """The reference on curves with closed-form nearest points: the NURBS unit circle (distance
    | |q| - 1 |; its corner weight is sqrt(2)/2 rounded, so the curve is a circle to ~1e-16) and
    the parabola y = x^2, (-1, 1), (0, -1), (1, 1), from (0, h), h > 1/2: nearest at
    x^2 = h - 1/2, distance sqrt(h - 1/4)."""
    import mpmath as mp

    from reference import nearest_curve

    s = 0.7071067811865476
    circle = Curve(
        "nurbs",
        2,
        [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0), (-1.0, -1.0), (0.0, -1.0), (1.0, -1.0), (1.0, 0.0)],
        [1, s, 1, s, 1, s, 1, s, 1],
        [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
    )
    rng = random.Random(7)
    for _ in range(10):
        q = (rng.uniform(-3, 3), rng.uniform(-3, 3))
        best = nearest_curve(circle, q)[0]
        assert abs(best.distance - abs(mp.sqrt(q[0] ** 2 + q[1] ** 2) - 1)) < 1e-15, q
    parabola = Curve("bezier", 2, [(-1.0, 1.0), (0.0, -1.0), (1.0, 1.0)])
    for h in (0.75, 1.0, 1.25, 1.5):
        best = nearest_curve(parabola, (0.0, h))[0]
        assert abs(best.distance - mp.sqrt(mp.mpf(h) - mp.mpf(1) / 4)) < 1e-25, h
        assert abs(abs(2 * best.t - 1) - mp.sqrt(mp.mpf(h) - mp.mpf(1) / 2)) < 1e-12, h
    # beyond h = 3/2 the nearest points are the ends (-1, 1) and (1, 1), a tie: t = 0 first
    best = nearest_curve(parabola, (0.0, 10.0))[0]
    assert best.t == 0 and abs(best.distance - mp.sqrt(82)) < 1e-25
    # below the focus the vertex is nearest
    assert abs(nearest_curve(parabola, (0.0, 0.25))[0].t - mp.mpf(1) / 2) < 1e-12


def test_reference_evaluation_agrees_with_eval(cli):
    """The reference's curves are the command's curves: `neutrospline eval --at` and the mpmath
    evaluation agree to 1e-9 of the size (plus the doubles' resolution) on random degenerate
    curves; otherwise every verdict above would compare different curves."""
    import mpmath as mp

    from harness import run, table
    from reference import ROUNDING, magnitude, write_model

    import pathlib
    import tempfile

    for k in range(12):
        rng = random.Random(first_seed() + 3 * 10**6 + k)
        curve = degenerate_curve(rng)
        lo, hi = curve.domain
        ts = [lo, hi] + [lo + (hi - lo) * rng.random() for _ in range(6)]
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / "m.json"
            write_model(path, curve)
            rows = table(run(cli, ["eval", path, "--at", ",".join(repr(t) for t in ts)]))
        tol = 1e-9 * (curve.size() or 1.0) + ROUNDING * magnitude(curve.points)
        for t, r in zip(ts, rows):
            ref = curve.point(mp.mpf(t))[0]
            ours = [float(r[c]) for c in ("x", "y", "z")[: curve.dim]]
            gap = max(abs(mp.mpf(a) - b) for a, b in zip(ours, ref))
            assert gap <= tol, f"{curve.model()} at t={t!r}: eval {ours}, reference {[mp.nstr(v, 17) for v in ref]}"
