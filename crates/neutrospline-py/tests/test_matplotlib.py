"""`plot` draws the project's views into matplotlib axes (Agg backend): the artists hold the
curve's own values (checked against `evaluate` to 1e-12), in the figures' colours, with the
figures' legend names."""

import numpy as np
import pytest

import neutrospline as ns

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import to_hex  # noqa: E402

TRUTH, INDETERMINACY, FALSITY, SCORE = "#004488", "#c88a12", "#bb5566", "#228833"
CRISP, CONSTRUCTION = "#222222", "#6e6e6e"
COLORS = {"truth": TRUTH, "indeterminacy": INDETERMINACY, "falsity": FALSITY, "score": SCORE}


@pytest.fixture(autouse=True)
def close_figures():
    yield
    plt.close("all")


def legend_texts(ax):
    return [t.get_text() for t in ax.get_legend().get_texts()]


def line(ax, label):
    found = [a for a in ax.get_lines() if a.get_label() == label]
    assert len(found) == 1, (label, [a.get_label() for a in ax.get_lines()])
    return found[0]


def test_the_truth_view_is_the_papers_space_curve_with_its_shadow():
    curve = ns.example1()
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d")
    assert curve.plot(ax, view="truth", samples=101) is ax
    assert legend_texts(ax) == [
        "truth curve", "control polygon", "crisp curve (degree 0)", "crisp control polygon",
    ]
    t = np.linspace(0.0, 1.0, 101)
    values = curve.evaluate(t)
    x, y, z = line(ax, "truth curve").get_data_3d()
    np.testing.assert_allclose(np.column_stack([x, y, z]), values[:, [0, 1, 2]], rtol=0, atol=1e-12)
    assert to_hex(line(ax, "truth curve").get_color()) == TRUTH
    # The lifted control polygon: (x_i, y_i, T_i) of Table 1.
    px, py, pz = line(ax, "control polygon").get_data_3d()
    assert np.column_stack([px, py, pz]).tolist() == [
        [1, 3, 0.3], [3, 6, 0.8], [6, 2, 0.7], [9, 5, 0.2],
    ]
    # The crisp curve and polygon are the shadows on the plane degree = 0.
    sx, sy, sz = line(ax, "crisp curve (degree 0)").get_data_3d()
    np.testing.assert_allclose(np.column_stack([sx, sy]), values[:, :2], rtol=0, atol=1e-12)
    assert np.all(sz == 0)
    assert to_hex(line(ax, "crisp curve (degree 0)").get_color()) == CRISP
    cx, cy, cz = line(ax, "crisp control polygon").get_data_3d()
    assert np.column_stack([cx, cy]).tolist() == curve.positions.tolist() and np.all(cz == 0)
    assert ax.get_zlim() == (0.0, 1.0) and ax.get_zlabel() == "truth"


@pytest.mark.parametrize("view", ["indeterminacy", "falsity", "score"])
def test_each_degree_view_lifts_its_own_degree(view):
    curve = ns.example1()
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d")
    curve.plot(ax, view=view, samples=51)
    t = np.linspace(0.0, 1.0, 51)
    values = curve.evaluate(t)
    expected = {
        "indeterminacy": values[:, 3],
        "falsity": values[:, 4],
        "score": ns.score(values[:, 2:]),
    }[view]
    curve_line = line(ax, f"{view} curve")
    _, _, z = curve_line.get_data_3d()
    np.testing.assert_allclose(z, expected, rtol=0, atol=1e-12)
    assert to_hex(curve_line.get_color()) == COLORS[view]
    zero = "score 0" if view == "score" else "degree 0"
    assert legend_texts(ax) == [
        f"{view} curve", "control polygon", f"crisp curve ({zero})", "crisp control polygon",
    ]


def test_the_all_view_draws_the_three_degree_curves_of_fig_5():
    curve = ns.BSpline(
        [[0, 0], [1, 2], [3, 2], [4, 0], [5, 1]],
        [[0.9, 0.1, 0.0], [0.7, 0.2, 0.1], [0.5, 0.3, 0.2], [0.3, 0.2, 0.5], [0.1, 0.1, 0.8]],
        degree=3,
    )
    ax = curve.plot(view="all", samples=64)
    assert ax.name == "3d"
    assert legend_texts(ax) == [
        "truth curve", "indeterminacy curve", "falsity curve", "control polygons",
        "crisp curve (degree 0)", "crisp control polygon",
    ]
    t, values = curve.sample(64, parameters=True)
    for k, name in enumerate(["truth", "indeterminacy", "falsity"]):
        x, y, z = line(ax, f"{name} curve").get_data_3d()
        np.testing.assert_allclose(
            np.column_stack([x, y, z]), values[:, [0, 1, 2 + k]], rtol=0, atol=1e-12
        )
        assert to_hex(line(ax, f"{name} curve").get_color()) == COLORS[name]
    assert ax.get_zlabel() == "degree"


def test_the_plane_view_draws_bands_along_the_crisp_curve():
    curve = ns.example1()
    fig, ax = plt.subplots()
    assert curve.plot(ax, view="plane", samples=41) is ax
    assert legend_texts(ax) == ["truth", "indeterminacy", "falsity", "crisp curve", "control polygon"]
    t = np.linspace(0.0, 1.0, 41)
    values = curve.evaluate(t)
    crisp = line(ax, "crisp curve")
    np.testing.assert_allclose(np.column_stack(crisp.get_data()), values[:, :2], rtol=0, atol=1e-12)
    assert to_hex(crisp.get_color()) == CRISP
    polygon = line(ax, "control polygon")
    assert np.column_stack(polygon.get_data()).tolist() == curve.positions.tolist()
    assert to_hex(polygon.get_color()) == CONSTRUCTION
    # Each band: the lane's centre line offset along the unit normal, half the degree's
    # width on either side (truth on the left of the curve, falsity on its right).
    tangent = curve.derivative()(t)[:, :2]
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]]) / np.hypot(*tangent.T)[:, None]
    positions = curve.positions
    lane = 0.035 * np.hypot(*(positions.max(axis=0) - positions.min(axis=0)))
    bands = {p.get_label(): p for p in ax.patches if not p.get_label().startswith("_")}
    assert list(bands) == ["truth", "indeterminacy", "falsity"]
    for k, name in enumerate(["truth", "indeterminacy", "falsity"]):
        center = values[:, :2] + (1 - k) * 1.15 * lane * normal
        half = 0.5 * lane * values[:, 2 + k][:, None] * normal
        want = np.concatenate([center + half, (center - half)[::-1]])
        got = bands[name].get_xy()
        np.testing.assert_allclose(got[: len(want)], want, rtol=0, atol=1e-12)
        assert to_hex(bands[name].get_facecolor()) == COLORS[name]


def test_the_controls_view_labels_each_point_with_its_degrees():
    curve = ns.example1()
    ax = curve.plot(view="controls")
    assert ax.name != "3d"
    assert legend_texts(ax) == ["control polygon", "crisp curve"]
    texts = [t.get_text() for t in ax.texts]
    assert texts[0] == "C0\nT 0.3\nI 0.6\nF 0.1"
    assert texts[3] == "C3\nT 0.2\nI 0.4\nF 0.4"


def test_a_3d_curve_is_coloured_by_the_degree():
    helix = ns.Bezier(
        [[1, 0, 0], [1, 0.5, 0.25], [0.5, 1, 0.5], [0, 1, 0.75]],
        [[0.9, 0.1, 0.0], [0.6, 0.2, 0.2], [0.3, 0.3, 0.5], [0.1, 0.2, 0.8]],
    )
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d")
    helix.plot(ax, view="truth", samples=33)
    assert legend_texts(ax) == ["control polygon", "shadow on the floor"]
    collection = ax.collections[0]
    t = np.linspace(0.0, 1.0, 33)
    values = helix.evaluate(t)
    segments = np.asarray(collection._segments3d)
    np.testing.assert_allclose(segments[:, 0], values[:-1, :3], rtol=0, atol=1e-12)
    np.testing.assert_allclose(segments[:, 1], values[1:, :3], rtol=0, atol=1e-12)
    np.testing.assert_allclose(
        collection.get_array(), 0.5 * (values[:-1, 3] + values[1:, 3]), rtol=0, atol=1e-12
    )
    axes = helix.plot(view="all")
    assert len(axes) == 3 and [a.get_title() for a in axes] == ["truth", "indeterminacy", "falsity"]
    with pytest.raises(ns.ModelError, match=r"^view = 'plane': the degree bands lie in the plane"):
        helix.plot(view="plane")


def test_a_surface_is_drawn_with_its_control_net(root):
    surface = ns.load(root / "examples/surface.toml")
    fig = plt.figure()
    ax = fig.add_subplot(projection="3d")
    assert surface.plot(ax, view="truth", samples=9) is ax
    assert legend_texts(ax) == ["surface", "control net"]
    # The control net's lines are the rows and columns of the control points.
    net = [np.column_stack(a.get_data_3d()) for a in ax.get_lines()]
    assert len(net) == 8
    assert net[0].tolist() == surface.positions[0].tolist()
    assert net[4].tolist() == surface.positions[:, 0].tolist()
    maps = surface.plot(view="plane", samples=9)
    assert [a.get_title() for a in maps] == ["truth", "indeterminacy", "falsity"]
    u = np.linspace(0.0, 1.0, 9)
    uu, vv = np.meshgrid(u, u, indexing="ij")
    truth = surface.evaluate(uu, vv)[..., 3]
    np.testing.assert_allclose(
        np.asarray(maps[0].collections[0].get_array()).reshape(9, 9), truth, rtol=0, atol=1e-12
    )


def test_views_and_axes_are_checked():
    curve = ns.example1()
    with pytest.raises(ns.ModelError) as raised:
        curve.plot(view="band")
    assert str(raised.value) == (
        "view = 'band': not a view of a curve (one of plane, controls, truth, indeterminacy, "
        "falsity, all, score)"
    )
    fig, flat = plt.subplots()
    with pytest.raises(ns.ModelError, match=r'^ax: this view is drawn in 3-D: give axes made with projection="3d"'):
        curve.plot(flat, view="truth")
