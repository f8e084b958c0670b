"""The interval-valued and bipolar families in Python (docs/model.md, "Lanes"): the family as
an argument and a property, degree arrays with one column per channel (`channels`), values
checked against a Bernstein blend computed here in numpy, the operations applied to both lanes
alike, files and pickles round-tripping, and the exact refusals."""

import pickle
from math import comb

import numpy as np
import pytest

import neutrospline as ns

POSITIONS = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]])
# truth_lower, truth_upper, indeterminacy_lower, indeterminacy_upper, falsity_lower, falsity_upper
INTERVAL_NEUTROSOPHIC = np.array(
    [
        [0.2, 0.5, 0.1, 0.3, 0.0, 0.4],
        [0.6, 0.9, 0.0, 0.2, 0.1, 0.1],
        [0.3, 0.3, 0.5, 0.7, 0.2, 0.25],
        [0.0, 1.0, 0.4, 0.4, 0.6, 0.8],
    ]
)
# truth_lower, truth_upper, falsity_lower, falsity_upper (truth_upper + falsity_upper <= 1)
INTERVAL_INTUITIONISTIC = np.array(
    [[0.1, 0.3, 0.2, 0.6], [0.5, 0.7, 0.1, 0.2], [0.0, 0.4, 0.3, 0.5], [0.2, 0.2, 0.0, 0.8]]
)
# truth_lower, truth_upper
INTERVAL_TYPE2 = np.array([[0.1, 0.4], [0.5, 0.9], [0.3, 0.3], [0.0, 1.0]])
# truth, indeterminacy, falsity, negative_truth, negative_indeterminacy, negative_falsity
BIPOLAR = np.array(
    [
        [0.7, 0.2, 0.1, -0.3, -0.4, 0.0],
        [0.1, 0.9, 0.5, -1.0, -0.2, -0.6],
        [1.0, 0.0, 0.0, 0.0, -0.5, -0.1],
        [0.4, 0.4, 0.4, -0.8, 0.0, -1.0],
    ]
)
FAMILIES = {
    "interval-neutrosophic": INTERVAL_NEUTROSOPHIC,
    "interval-intuitionistic": INTERVAL_INTUITIONISTIC,
    "interval-type2": INTERVAL_TYPE2,
    "bipolar-neutrosophic": BIPOLAR,
}
CHANNELS = {
    "interval-neutrosophic": [
        "truth_lower",
        "truth_upper",
        "indeterminacy_lower",
        "indeterminacy_upper",
        "falsity_lower",
        "falsity_upper",
    ],
    "interval-intuitionistic": ["truth_lower", "truth_upper", "falsity_lower", "falsity_upper"],
    "interval-type2": ["truth_lower", "truth_upper"],
    "bipolar-neutrosophic": [
        "truth",
        "indeterminacy",
        "falsity",
        "negative_truth",
        "negative_indeterminacy",
        "negative_falsity",
    ],
}


def bernstein(t, n):
    """The Bernstein basis B_i^n(t), shape (len(t), n + 1), from its closed form."""
    t = np.asarray(t, dtype=float)[:, None]
    i = np.arange(n + 1)[None, :]
    coefficients = np.array([comb(n, k) for k in range(n + 1)], dtype=float)[None, :]
    return coefficients * t**i * (1 - t) ** (n - i)


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_a_bezier_curve_blends_every_channel_with_the_bernstein_basis(family):
    channels = FAMILIES[family]
    curve = ns.Bezier(POSITIONS, channels, membership=family)
    assert curve.membership == family
    assert curve.channels == CHANNELS[family]
    count = channels.shape[1]
    control = curve.membership_degrees
    assert control.shape == (4, count)
    np.testing.assert_array_equal(control, channels)
    t = np.linspace(0, 1, 1001)
    values = curve(t)
    assert values.shape == (1001, 2 + count)
    basis = bernstein(t, 3)
    np.testing.assert_allclose(values[:, :2], basis @ POSITIONS, rtol=0, atol=1e-14)
    np.testing.assert_allclose(values[:, 2:], basis @ channels, rtol=0, atol=1e-15)
    # One parameter: one row; sample(): the same rows.
    assert curve(0.25).shape == (2 + count,)
    np.testing.assert_allclose(curve.sample(5), curve(np.linspace(0, 1, 5)), rtol=0, atol=1e-15)
    # out= is filled in place with the same values.
    out = np.empty((1001, 2 + count))
    assert curve.evaluate(t, out=out) is out
    np.testing.assert_array_equal(out, values)
    # The tight bounding box holds every sample and is reached by the curve.
    box = curve.bounding_box()
    assert box.shape == (2, 2 + count)
    assert np.all(box[0] <= values.min(axis=0) + 1e-15)
    assert np.all(box[1] >= values.max(axis=0) - 1e-15)
    np.testing.assert_allclose(box, [values.min(axis=0), values.max(axis=0)], rtol=0, atol=1e-3)


def test_the_bipolar_negative_degrees_stay_negative_and_score_as_the_literature():
    curve = ns.Bezier(POSITIONS, BIPOLAR, membership="bipolar-neutrosophic")
    t = np.linspace(0, 1, 101)
    values = curve(t)[:, 2:]
    assert np.all(values[:, 3:] <= 0) and np.all(values[:, 3:] >= -1)
    assert np.all(values[:, :3] >= 0) and np.all(values[:, :3] <= 1)
    tp, ip, fp, tn, i_n, fn = values.T
    expected = (3 + tp - ip - fp + tn - i_n - fn) / 6
    np.testing.assert_allclose(ns.score(values, membership="bipolar-neutrosophic"), expected, rtol=0, atol=1e-15)
    assert ns.score([1.0, 0.0, 0.0, 0.0, -1.0, -1.0], membership="bipolar-neutrosophic") == 1.0


def test_scores_accuracies_and_derived_degrees_of_the_interval_families():
    values = ns.Bezier(POSITIONS, INTERVAL_INTUITIONISTIC, membership="interval-intuitionistic")(
        np.linspace(0, 1, 11)
    )[:, 2:]
    tl, tu, fl, fu = values.T
    np.testing.assert_allclose(
        ns.score(values, membership="interval-intuitionistic"), (tl - fl + tu - fu) / 2, rtol=0, atol=1e-15
    )
    np.testing.assert_allclose(
        ns.accuracy(values, membership="interval-intuitionistic"), (tl + tu + fl + fu) / 2, rtol=0, atol=1e-15
    )
    derived, names = ns.derived_degrees(values, membership="interval-intuitionistic")
    assert names == ["hesitation_lower", "hesitation_upper"]
    assert derived.shape == (11, 2)
    np.testing.assert_allclose(derived, np.stack([1 - tu - fu, 1 - tl - fl], axis=1), rtol=0, atol=1e-15)
    type2 = ns.Bezier(POSITIONS, INTERVAL_TYPE2, membership="interval-type2")(np.linspace(0, 1, 11))[:, 2:]
    derived, names = ns.derived_degrees(type2, membership="interval-type2")
    assert names == ["type_reduced", "footprint"]
    np.testing.assert_allclose(
        derived, np.stack([(type2[:, 0] + type2[:, 1]) / 2, type2[:, 1] - type2[:, 0]], axis=1), rtol=0, atol=1e-15
    )
    np.testing.assert_allclose(ns.score(type2, membership="interval-type2"), (type2[:, 0] + type2[:, 1]) / 2, rtol=0, atol=1e-15)
    with pytest.raises(
        ValueError,
        match=r"^membership: the interval-neutrosophic family has no accuracy: its literature ranks its values by the score alone$",
    ):
        ns.accuracy(INTERVAL_NEUTROSOPHIC, membership="interval-neutrosophic")
    with pytest.raises(ValueError, match=r"^degrees\[0\]: truth_lower = 0\.5 exceeds truth_upper = 0\.25 \(interval-type2 rule: lower <= upper\)$"):
        ns.score([[0.5, 0.25]], membership="interval-type2")


def test_the_rule_refuses_a_control_point_by_its_index():
    bad = INTERVAL_NEUTROSOPHIC.copy()
    bad[2, 0], bad[2, 1] = 0.6, 0.4
    with pytest.raises(
        ns.ModelError,
        match=r"^degrees\[2\]: truth_lower = 0\.6 exceeds truth_upper = 0\.4 \(interval-neutrosophic rule: lower <= upper\)$",
    ):
        ns.Bezier(POSITIONS, bad, membership="interval-neutrosophic")
    positive = BIPOLAR.copy()
    positive[1, 3] = 0.2
    with pytest.raises(
        ValueError,
        match=r"^degrees\[1\]: negative_truth = 0\.2 is outside \[-1, 0\] \(bipolar-neutrosophic rule\)$",
    ):
        ns.Bezier(POSITIONS, positive, membership="bipolar-neutrosophic")
    grid = np.zeros((2, 2, 3))
    grid[1, :, 0] = 1
    grid[:, 1, 1] = 1
    degrees = np.tile(np.array([0.1, 0.3, 0.2, 0.6]), (2, 2, 1))
    degrees[1, 0] = [0.1, 0.3, 0.2, 0.8]
    with pytest.raises(ValueError, match=r"^degrees\[1, 0\]: truth_upper \+ falsity_upper = 1\.1 exceeds 1 \(interval-intuitionistic rule\)$"):
        ns.BezierSurface(grid, degrees, membership="interval-intuitionistic")
    # The three-column form of the families of one lane is not a form of a wide family.
    with pytest.raises(
        ValueError,
        match=r"^degrees: expected one row per control point \(leading shape \[4\]\) of 6 \(truth_lower, truth_upper, "
        r"indeterminacy_lower, indeterminacy_upper, falsity_lower, falsity_upper\) columns under the "
        r"interval-neutrosophic rule, got shape \[4, 3\]$",
    ):
        ns.Bezier(POSITIONS, INTERVAL_NEUTROSOPHIC[:, :3], membership="interval-neutrosophic")


@pytest.mark.parametrize("family", sorted(FAMILIES))
@pytest.mark.parametrize("extension", ["toml", "json", "csv"])
def test_files_and_pickles_round_trip(tmp_path, family, extension):
    curve = ns.BSpline(POSITIONS, FAMILIES[family], degree=2, membership=family, name="wide")
    path = tmp_path / f"wide.{extension}"
    curve.save(path)
    text = path.read_text()
    for channel in CHANNELS[family]:
        assert channel in text
    if extension == "csv":
        again = ns.load(path, kind="bspline", degree=2, membership=family)
    else:
        again = ns.load(path)
    assert again.membership == family
    np.testing.assert_array_equal(again.membership_degrees, curve.membership_degrees)
    t = np.linspace(0, 1, 9)
    np.testing.assert_array_equal(again(t), curve(t))
    if extension != "csv":
        assert again == curve
    restored = pickle.loads(pickle.dumps(curve))
    assert restored == curve
    np.testing.assert_array_equal(restored(t), curve(t))


def test_the_example_file_loads(tmp_path):
    path = tmp_path / "iv.toml"
    path.write_text(
        'kind = "bezier"\nmembership = "interval-neutrosophic"\n'
        + "".join(
            f"[[control_points]]\nx = {float(x)!r}\ny = {float(y)!r}\n"
            + "".join(f"{name} = {float(value)!r}\n" for name, value in zip(CHANNELS["interval-neutrosophic"], row))
            for (x, y), row in zip(POSITIONS, INTERVAL_NEUTROSOPHIC)
        )
    )
    curve = ns.load(path)
    assert curve.membership == "interval-neutrosophic"
    assert curve == ns.Bezier(POSITIONS, INTERVAL_NEUTROSOPHIC, membership="interval-neutrosophic")


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_geometry_operations_keep_both_lanes(family):
    channels = FAMILIES[family]
    curve = ns.Bezier(POSITIONS, channels, membership=family)
    t = np.linspace(0, 1, 201)
    values = curve(t)
    elevated = curve.elevate(2)
    assert elevated.degree == 5 and elevated.membership == family
    assert elevated.membership_degrees.shape == (6, channels.shape[1])
    np.testing.assert_allclose(elevated(t), values, rtol=0, atol=1e-15)
    spline = curve.insert_knot(0.3, 2)
    assert type(spline).__name__ == "BSpline"
    np.testing.assert_allclose(spline(t), values, rtol=0, atol=1e-15)
    left, right = curve.split(0.4)
    np.testing.assert_allclose(left(t), curve(0.4 * t), rtol=0, atol=1e-15)
    np.testing.assert_allclose(right(t), curve(0.4 + 0.6 * t), rtol=0, atol=1e-15)
    reversed_ = curve.transform(reverse=True)
    assert reversed_.membership == family
    np.testing.assert_allclose(reversed_(t), values[::-1], rtol=0, atol=1e-15)
    finer = ns.BSpline(POSITIONS, channels, degree=2, membership=family).transform(refine=1)
    np.testing.assert_allclose(
        finer(t), ns.BSpline(POSITIONS, channels, degree=2, membership=family)(t), rtol=0, atol=1e-15
    )
    pieces = curve.transform(split=0.5)
    assert len(pieces) == 2 and all(p.membership == family for p in pieces)
    np.testing.assert_allclose(pieces[1](t), curve(0.5 + 0.5 * t), rtol=0, atol=1e-15)
    # The positions' geometry is the same curve's.
    assert curve.length() == ns.Bezier(POSITIONS, [[1, 0, 0]] * 4).length()


def test_a_knot_removal_decides_by_both_lanes():
    # x(t) = 2t with a knot inserted at 0.5: the lower lane (constant degrees) could lose the
    # knot again, the upper lane (degrees 0.2, 0.9, 0.2, 0.9) cannot; the lanes are solved
    # together (docs/model.md, "Lanes"), so the knot stays in both and the model stays one.
    spline = ns.Bezier([[0, 0], [1, 0], [2, 0]], [[1, 0, 0]] * 3).insert_knot(0.5)
    degrees = [[0.1, 0.2], [0.1, 0.9], [0.1, 0.2], [0.1, 0.9]]
    wide = ns.BSpline(spline.positions, degrees, degree=2, knots=spline.knots, membership="interval-type2")
    with pytest.warns(UserWarning, match=r"^knot 0.5 not removed: removing it once would move the curve by more than"):
        kept = wide.transform(remove_knot=0.5, tolerance=1e-9)
    assert kept.knots.tolist() == [0, 0, 0, 0.5, 1, 1, 1]
    np.testing.assert_allclose(kept.membership_degrees, degrees, rtol=0, atol=1e-15)
    # Both lanes constant: the knot goes from both, and the model stays one.
    flat = ns.BSpline(spline.positions, [[0.1, 0.2]] * 4, degree=2, knots=spline.knots, membership="interval-type2")
    removed = flat.transform(remove_knot=0.5, tolerance=1e-9)
    assert removed.knots.tolist() == [0, 0, 0, 1, 1, 1]
    np.testing.assert_allclose(removed.membership_degrees, [[0.1, 0.2]] * 3, rtol=0, atol=1e-15)


def test_the_derivative_gives_the_rates_of_every_channel():
    curve = ns.Bezier(POSITIONS, INTERVAL_NEUTROSOPHIC, membership="interval-neutrosophic")
    t = np.linspace(0, 1, 51)
    rates = curve.derivative()(t)
    assert rates.shape == (51, 8)
    # d/dt sum B_i^3 P_i = 3 sum B_i^2 (P_{i+1} - P_i)
    difference = 3 * np.diff(np.hstack([POSITIONS, INTERVAL_NEUTROSOPHIC]), axis=0)
    np.testing.assert_allclose(rates, bernstein(t, 2) @ difference, rtol=0, atol=1e-14)
    np.testing.assert_allclose(curve.derivative().membership_degrees, difference[:, 2:], rtol=0, atol=1e-15)
    bipolar = ns.Bezier(POSITIONS, BIPOLAR, membership="bipolar-neutrosophic").derivative()(t)
    np.testing.assert_allclose(
        bipolar[:, 2:], bernstein(t, 2) @ (3 * np.diff(BIPOLAR, axis=0)), rtol=0, atol=1e-14
    )


def test_nearest_and_intersections_give_the_channels():
    curve = ns.Bezier(POSITIONS, BIPOLAR, membership="bipolar-neutrosophic")
    t, distance, row = curve.nearest(curve(0.3)[:2])
    assert abs(t - 0.3) < 1e-9 and distance < 1e-12
    np.testing.assert_allclose(row, curve(t), rtol=0, atol=1e-15)
    ts, distances, rows = curve.nearest([[0, 0], [4, 0.5]])
    assert rows.shape == (2, 8)
    np.testing.assert_allclose(rows, curve(ts), rtol=0, atol=1e-15)
    line = ns.Bezier([[0, 1], [4, 1]], [[1, 0, 0], [0, 0, 1]])
    hits = line.intersections(curve)
    assert hits.shape == (2, 4 + 3 + 6)
    for t_a, t_b, x, y, *rest in hits:
        np.testing.assert_allclose(rest[:3], line(t_a)[2:], rtol=0, atol=1e-15)
        np.testing.assert_allclose(rest[3:], curve(t_b)[2:], rtol=0, atol=1e-15)
    assert curve.intersections(line).shape == (2, 4 + 6 + 3)


def test_a_wide_surface_blends_its_channels_bilinearly(tmp_path):
    grid = np.array([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], dtype=float)
    degrees = np.array([[[0.1, 0.3, 0.2, 0.6], [0.5, 0.7, 0.1, 0.2]], [[0.0, 0.4, 0.3, 0.5], [0.2, 0.2, 0.0, 0.8]]])
    surface = ns.BezierSurface(grid, degrees, membership="interval-intuitionistic")
    assert surface.membership == "interval-intuitionistic"
    assert surface.channels == CHANNELS["interval-intuitionistic"]
    assert surface.membership_degrees.shape == (2, 2, 4)
    np.testing.assert_array_equal(surface.membership_degrees, degrees)
    u, v = np.meshgrid(np.linspace(0, 1, 7), np.linspace(0, 1, 5), indexing="ij")
    values = surface(u, v)
    assert values.shape == (7, 5, 7)
    weights = np.stack([(1 - u) * (1 - v), (1 - u) * v, u * (1 - v), u * v], axis=-1)
    expected = weights @ np.hstack([grid.reshape(4, 3), degrees.reshape(4, 4)])
    np.testing.assert_allclose(values, expected, rtol=0, atol=1e-15)
    box = surface.bounding_box()
    assert box.shape == (2, 7)
    np.testing.assert_array_equal(box[:, 3:], [degrees.reshape(4, 4).min(axis=0), degrees.reshape(4, 4).max(axis=0)])
    uv, distance, row = surface.nearest([0.5, 0.5, 2.0])
    np.testing.assert_allclose(row, surface(uv[0], uv[1]), rtol=0, atol=1e-15)
    path = tmp_path / "surface.json"
    surface.save(path)
    assert ns.load(path) == surface
    spline = ns.BSplineSurface(grid, degrees, degree=1, membership="interval-intuitionistic")
    finer = spline.transform(insert_knot=[0.5], direction="u")
    np.testing.assert_allclose(finer(u, v), spline(u, v), rtol=0, atol=1e-15)
    assert finer.membership_degrees.shape == (3, 2, 4)


def test_figures_draw_the_band():
    curve = ns.Bezier(POSITIONS, INTERVAL_TYPE2, membership="interval-type2")
    svg = curve.to_svg()
    assert "lower membership" in svg and "upper membership" in svg
    assert "Interval type-2 fuzzy Bézier curve" in svg
    assert curve._repr_svg_() is not None and curve._repr_png_() is not None
    with pytest.raises(
        ValueError,
        match=r"^the view `falsity` does not draw interval-type2 models: interval type-2 degrees are a lower "
        r"and an upper membership",
    ):
        curve.to_svg(view="falsity")


def test_fit_solves_every_channel_under_the_whole_rule(tmp_path):
    t = np.linspace(0.0, 1.0, 40)
    points = np.stack([4 * t, np.sin(3 * t)], axis=1)
    # Memberships collapsed at 1 and wide from 0 in turn: a free fit of each lane rings past
    # [0, 1] and the lanes cross.
    high = (np.arange(40) // 5) % 2 == 0
    degrees = np.where(high[:, None], [1.0, 1.0], [0.0, 0.5])
    curve, report = ns.fit(points, degrees, membership="interval-type2", control_points=9)
    assert curve.membership == "interval-type2"
    control = curve.membership_degrees
    assert control.shape == (9, 2)
    assert np.all(control[:, 0] >= 0) and np.all(control[:, 0] <= control[:, 1])
    assert np.all(control[:, 1] <= 1)
    assert any(c[0] == c[1] for c in control) or any(c[1] == 1.0 for c in control)
    assert sorted(report["max_error"]) == ["truth_lower", "truth_upper", "x", "y"]
    # The same data as a file: the same fit.
    path = tmp_path / "t2.csv"
    rows = ["x,y,truth_lower,truth_upper"] + [
        ",".join(repr(float(v)) for v in (*p, *d)) for p, d in zip(points, degrees)
    ]
    path.write_text("\n".join(rows) + "\n")
    from_file, _ = ns.fit(str(path), membership="interval-type2", control_points=9)
    np.testing.assert_array_equal(from_file.membership_degrees, control)
    # A bipolar surface from arrays of shape (rows, cols, 6).
    u, v = np.meshgrid(np.linspace(0, 1, 6), np.linspace(0, 1, 5), indexing="ij")
    grid = np.stack([u, v, u * v], axis=-1)
    alternate = ((np.arange(6)[:, None] + np.arange(5)[None, :]) % 2 == 0)[..., None]
    bipolar = np.where(alternate, [1.0, 0.0, 0.0, -1.0, 0.0, 0.0], [0.0, 1.0, 1.0, 0.0, -1.0, -1.0])
    surface, report = ns.fit_surface(grid, bipolar, membership="bipolar-neutrosophic", control_points=(4, 4))
    values = surface.membership_degrees
    assert values.shape == (4, 4, 6)
    assert np.all((values[..., :3] >= 0) & (values[..., :3] <= 1))
    assert np.all((values[..., 3:] >= -1) & (values[..., 3:] <= 0))
    assert "negative_falsity" in report["max_error"]
    with pytest.raises(ValueError, match=r"^degrees\[1\]: truth_lower = 0\.5 exceeds truth_upper = 0\.4 \(interval-type2 rule: lower <= upper\)$"):
        ns.fit(points[:3], np.array([[0.1, 0.2], [0.5, 0.4], [0.2, 0.3]]), membership="interval-type2", degree=2, interpolate=True)


def test_to_dataframe_has_the_channel_columns():
    pd = pytest.importorskip("pandas")
    curve = ns.Bezier(POSITIONS, INTERVAL_NEUTROSOPHIC, membership="interval-neutrosophic")
    frame = curve.to_dataframe(5, scores=True)
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == ["t", "x", "y"] + CHANNELS["interval-neutrosophic"] + ["score"]
    values = curve(np.linspace(0, 1, 5))[:, 2:]
    expected = (4 + values[:, 0] + values[:, 1] - values[:, 2:].sum(axis=1)) / 6
    np.testing.assert_allclose(frame["score"], expected, rtol=0, atol=1e-15)
