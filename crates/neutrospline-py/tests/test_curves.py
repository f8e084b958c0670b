"""The Python package against independent references: the command line's own output, scipy's
B-splines, the `bezier` package, and closed forms; shapes, dtypes, errors, files, pickling,
figures, threads."""

import csv
import io
import pickle
import subprocess
import threading

import bezier
import numpy as np
import pytest
import scipy.interpolate

import neutrospline as ns

RNG = np.random.default_rng(20261201)


def run_cli(cli, *args, cwd=None):
    done = subprocess.run(
        [str(cli), *map(str, args)], capture_output=True, text=True, cwd=cwd
    )
    return done


def cli_table(cli, *args, cwd=None):
    done = run_cli(cli, *args, cwd=cwd)
    assert done.returncode == 0, done.stderr
    rows = list(csv.reader(io.StringIO(done.stdout)))
    return rows[0], np.array(rows[1:], dtype=float)


def assert_close(got, want, scale=None, rel=1e-13):
    got = np.asarray(got)
    want = np.asarray(want)
    assert got.shape == want.shape
    scale = np.max(np.abs(want)) if scale is None else scale
    assert np.max(np.abs(got - want), initial=0.0) <= rel * max(scale, 1.0)


def random_degrees(n):
    return RNG.uniform(0.0, 1.0, size=(n, 3))


# ---- values against the command line and independent libraries ----


@pytest.mark.parametrize(
    "model", ["example1.toml", "bspline.toml", "nurbs-circle.toml", "helix3d.toml"]
)
def test_curves_match_the_command_line(cli, root, model):
    path = root / "examples" / model
    header, table = cli_table(cli, "eval", path, "--samples", 257)
    curve = ns.load(path)
    assert header[0] == "t" and len(header) == curve.dimension + 4
    t = table[:, 0]
    # The batch engine (SIMD kernels) against eval's output: equal to rounding.
    assert_close(curve.sample(257), table[:, 1:], rel=1e-15)
    assert_close(curve.evaluate(t), table[:, 1:], rel=1e-15)


def test_bspline_against_scipy():
    for degree, count, dimension in [(1, 5, 2), (2, 9, 3), (3, 12, 2), (5, 20, 3)]:
        positions = RNG.uniform(-100.0, 100.0, size=(count, dimension))
        degrees = random_degrees(count)
        inner = np.sort(RNG.uniform(0.0, 1.0, size=count - degree - 1))
        knots = np.concatenate([np.zeros(degree + 1), inner, np.ones(degree + 1)])
        curve = ns.BSpline(positions, degrees, degree=degree, knots=knots)
        reference = scipy.interpolate.BSpline(
            knots, np.hstack([positions, degrees]), degree
        )
        t = np.concatenate([RNG.uniform(0.0, 1.0, 1000), [0.0, 1.0], inner])
        want = reference(t)
        got = curve(t)
        assert_close(got[:, :dimension], want[:, :dimension])
        assert_close(got[:, dimension:], want[:, dimension:], scale=1.0)
        np.testing.assert_array_equal(curve.knots, knots)


def test_nurbs_against_scipy_homogeneous():
    degree, count = 3, 10
    positions = RNG.uniform(-10.0, 10.0, size=(count, 3))
    degrees = random_degrees(count)
    weights = RNG.uniform(0.2, 5.0, size=count)
    curve = ns.Nurbs(positions, degrees, weights, degree=degree)
    knots = curve.knots
    homogeneous = np.hstack([np.hstack([positions, degrees]) * weights[:, None], weights[:, None]])
    reference = scipy.interpolate.BSpline(knots, homogeneous, degree)
    t = np.linspace(0.0, 1.0, 2001)
    h = reference(t)
    want = h[:, :-1] / h[:, -1:]
    got = curve(t)
    assert_close(got[:, :3], want[:, :3], rel=1e-13)
    assert_close(got[:, 3:], want[:, 3:], scale=1.0, rel=1e-13)


def test_bezier_against_the_bezier_package():
    for n in [2, 4, 8, 16]:
        nodes = RNG.uniform(-5.0, 5.0, size=(2, n))
        degrees = random_degrees(n)
        curve = ns.Bezier.from_nodes(nodes, degrees)
        assert curve == ns.Bezier(nodes.T, degrees)
        s = np.linspace(0.0, 1.0, 1001)
        positions = bezier.Curve(np.asfortranarray(nodes), degree=n - 1).evaluate_multi(s)
        blended = bezier.Curve(np.asfortranarray(degrees.T), degree=n - 1).evaluate_multi(s)
        got = curve(s)
        assert_close(got[:, :2], positions.T)
        assert_close(got[:, 2:], blended.T, scale=1.0)
        # The first derivative is the hodograph.
        for k in [0, 500, 1000]:
            hodograph = bezier.Curve(np.asfortranarray(nodes), degree=n - 1).evaluate_hodograph(s[k])
            assert_close(curve.derivative()(s[k])[:2], hodograph[:, 0])


def test_example1_closed_forms():
    curve = ns.example1()
    assert curve.name == "Example 1"
    assert curve.point_names == ["C0", "C1", "C2", "C3"]
    # C(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8 in every column.
    p = np.hstack([curve.positions, curve.membership_degrees])
    assert_close(curve(0.5), (p[0] + 3 * p[1] + 3 * p[2] + p[3]) / 8, scale=1.0, rel=1e-15)
    # The second derivative at 0 is 6 (P2 - 2 P1 + P0).
    assert_close(curve.derivative(2)(0.0), 6 * (p[2] - 2 * p[1] + p[0]), rel=1e-15)
    assert curve.derivative().derivative() == curve.derivative(2)
    # The length, from scripts/reference/make_arc_length_reference.py (mpmath).
    assert abs(curve.length() - 8.786730707839524) <= 1e-12 * 8.786730707839524


def test_circle_closed_forms(root):
    circle = ns.load(root / "examples" / "nurbs-circle.toml")
    t = np.linspace(*circle.domain, 1001)
    xy = circle(t)[:, :2]
    assert np.max(np.abs(np.hypot(xy[:, 0], xy[:, 1]) - 1.0)) <= 1e-15
    assert np.max(np.abs(circle.curvature(t) - 1.0)) <= 1e-12
    assert abs(circle.length() - 2 * np.pi) <= 1e-12 * 2 * np.pi


def test_operations_keep_the_curve():
    curve = ns.BSpline(RNG.uniform(-1, 1, (8, 2)), random_degrees(8), degree=3)
    t = np.linspace(0.0, 1.0, 301)
    want = curve(t)
    assert_close(curve.elevate(2)(t), want, scale=1.0, rel=1e-14)
    inserted = curve.insert_knot(0.3, times=2)
    assert len(inserted) == len(curve) + 2
    assert_close(inserted(t), want, scale=1.0, rel=1e-14)
    left, right = curve.split(0.4)
    assert left.domain == (0.0, 0.4) and right.domain == (0.4, 1.0)
    assert_close(left(t[t <= 0.4]), want[t <= 0.4], scale=1.0, rel=1e-14)
    assert_close(right(t[t >= 0.4]), want[t >= 0.4], scale=1.0, rel=1e-14)
    box = curve.bounding_box()
    assert np.all(box[0] <= want.min(axis=0) + 1e-15)
    assert np.all(box[1] >= want.max(axis=0) - 1e-15)
    assert_close(box[0, :2], want[:, :2].min(axis=0), scale=1.0, rel=1e-3)


def test_bezier_insert_knot_is_a_bspline():
    curve = ns.example1()
    spline = curve.insert_knot(0.25)
    assert isinstance(spline, ns.BSpline) and isinstance(spline, ns.Curve)
    t = np.linspace(0.0, 1.0, 101)
    assert_close(spline(t), curve(t), scale=1.0, rel=1e-14)


# ---- shapes, dtypes and the out= convention ----


def test_shapes_and_dtypes():
    curve = ns.example1()
    t = np.linspace(0.0, 1.0, 11)
    want = curve(t)
    assert want.shape == (11, 5) and want.dtype == np.float64
    assert want.flags["F_CONTIGUOUS"]
    assert curve(0.5).shape == (5,)
    np.testing.assert_array_equal(curve(0.5), want[5])
    np.testing.assert_array_equal(curve(list(t)), want)
    np.testing.assert_array_equal(curve(t.astype(np.float32)), curve(t.astype(np.float32).astype(float)))
    strided = np.linspace(0.0, 1.0, 21)[::2]
    assert not strided.flags["C_CONTIGUOUS"]
    np.testing.assert_array_equal(curve(strided), want)
    frozen = t.copy()
    frozen.flags.writeable = False
    np.testing.assert_array_equal(curve(frozen), want)
    assert curve(np.empty(0)).shape == (0, 5)
    assert curve.sample(0).shape == (0, 5)


def test_out_is_written_in_place():
    curve = ns.example1()
    t = np.linspace(0.0, 1.0, 50_001)
    want = curve(t)
    fortran = np.empty((t.size, 5), order="F")
    assert curve.evaluate(t, out=fortran) is fortran
    np.testing.assert_array_equal(fortran, want)
    c_order = np.zeros((t.size, 5))
    assert curve(t, out=c_order) is c_order
    np.testing.assert_array_equal(c_order, want)
    view = np.zeros((t.size, 10))[:, ::2]
    curve(t, out=view)
    np.testing.assert_array_equal(view, want)
    sampled = np.empty((t.size, 5), order="F")
    assert curve.sample(t.size, out=sampled) is sampled
    np.testing.assert_array_equal(sampled, curve.sample(t.size))
    assert_close(sampled, want, rel=1e-15)
    with pytest.raises(ns.ModelError, match=r"out: expected shape \(50001, 5\), got \[50001, 4\]"):
        curve(t, out=np.empty((t.size, 4)))
    with pytest.raises(ns.ModelError, match="out: expected a float64 array"):
        curve(t, out=np.empty((t.size, 5), dtype=np.float32))
    readonly = np.empty((t.size, 5))
    readonly.flags.writeable = False
    with pytest.raises(ns.ModelError, match="out: cannot write into the array"):
        curve(t, out=readonly)


def test_bad_parameters_are_named():
    curve = ns.example1()
    with pytest.raises(ValueError, match=r"^t\[2\]: parameter t = NaN is not a finite number$"):
        curve([0.0, 0.5, np.nan, 0.7])
    with pytest.raises(ns.ModelError, match=r"^t\[1\]: parameter t = 1.5 is outside the domain \[0, 1\]$"):
        curve([0.0, 1.5])
    with pytest.raises(ns.ModelError, match=r"^t: expected a number or a 1-D array"):
        curve(np.zeros((2, 2)))
    with pytest.raises(ns.ModelError, match=r"^t: expected numbers, got strings \(dtype <U4\)$"):
        curve("half")


def test_bad_models_have_the_command_line_messages(cli, tmp_path):
    with pytest.raises(ns.ModelError) as caught:
        ns.Bezier([[0, 0], [1, 1]], [[0.2, 0.2, 0.2], [1.2, 0.0, 0.0]])
    assert str(caught.value) == (
        "degrees[1]: truth = 1.2 is outside [0, 1] (every degree must be in [0, 1])"
    )
    assert isinstance(caught.value, ValueError)
    with pytest.raises(ns.ModelError, match=r"^positions: expected an array of shape \(n, 2\) or \(n, 3\)"):
        ns.Bezier([[0, 0, 0, 0]], [[0, 0, 0]])
    with pytest.raises(ns.ModelError, match="^knots: "):
        ns.BSpline([[0, 0], [1, 1], [2, 0]], [[0, 0, 0]] * 3, degree=2, knots=[0, 0, 0, 1, 0.5, 1])
    with pytest.raises(ns.ModelError, match="weight = -1 is not a positive finite number"):
        ns.Nurbs([[0, 0], [1, 1], [2, 0]], [[0, 0, 0]] * 3, [1, -1, 1], degree=2)
    with pytest.raises(ns.ModelError, match="^membership: "):
        ns.Bezier([[0, 0]], [[0, 0, 0]], membership="crisp")
    bad = tmp_path / "bad.toml"
    bad.write_text(
        'kind = "bezier"\n[[control_points]]\nx = 0\ny = 0\ntruth = 1.5\n'
        "indeterminacy = 0\nfalsity = 0\n"
    )
    with pytest.raises(ns.ModelError) as caught:
        ns.load(bad)
    done = run_cli(cli, "check", bad)
    assert done.returncode == 1
    assert done.stderr.strip() == f"error: {caught.value}"


def test_membership_rules():
    intuitionistic = ns.Bezier([[0, 0], [1, 0]], [[0.5, 0.2], [0.1, 0.7]], membership="intuitionistic")
    np.testing.assert_allclose(intuitionistic.membership_degrees, [[0.5, 0.3, 0.2], [0.1, 0.2, 0.7]], rtol=0, atol=1e-15)
    fuzzy = ns.BSpline([[0, 0], [1, 0], [2, 1]], [0.2, 0.4, 0.9], degree=2, membership="fuzzy")
    assert fuzzy.membership == "fuzzy"
    np.testing.assert_array_equal(fuzzy.membership_degrees[:, 1:], 0.0)
    with pytest.raises(ns.ModelError, match="intuitionistic rule"):
        ns.Bezier([[0, 0]], [[0.6, 0.6]], membership="intuitionistic")
    # Operations keep the rule: the intuitionistic indeterminacy is re-derived after blending.
    left, _ = intuitionistic.elevate(3).split(0.3)
    np.testing.assert_allclose(left.membership_degrees.sum(axis=1), 1.0, rtol=0, atol=1e-15)


# ---- scores and relations ----


def test_scores_vectorised():
    d = random_degrees(24).reshape(2, 3, 4, 3)
    t, i, f = d[..., 0], d[..., 1], d[..., 2]
    assert_close(ns.score(d), (2 + t - i - f) / 3, scale=1.0, rel=1e-15)
    assert_close(ns.accuracy(d), t - f, scale=1.0, rel=1e-15)
    np.testing.assert_array_equal(ns.certainty(d), t)
    assert ns.score(d).shape == (2, 3, 4)
    assert ns.score([1, 0, 0]) == 1.0
    with pytest.raises(ns.ModelError, match=r"^degrees\[1\]: falsity = -0.5 is outside \[0, 1\]"):
        ns.score([[0, 0, 0], [0, 0, -0.5]])
    with pytest.raises(ns.ModelError, match=r"shape \(\.\.\., 3\)"):
        ns.score([[0, 0]])


def test_point_relation_of_def_4():
    m = [(1.0, (0.3, 0.6, 0.1)), (2.0, (0.9, 0.1, 0.5))]
    n = [(3.0, (0.5, 0.2, 0.4)), (4.0, (0.2, 0.8, 0.0))]
    positions, degrees = ns.largest_relation(m, n)
    np.testing.assert_array_equal(positions, [[1, 3], [1, 4], [2, 3], [2, 4]])
    np.testing.assert_array_equal(
        degrees, [[0.3, 0.2, 0.1], [0.2, 0.6, 0.0], [0.5, 0.1, 0.4], [0.2, 0.1, 0.0]]
    )
    ns.check_relation(positions, degrees, m, n)
    pairs_positions, pairs_degrees = ns.largest_relation(m, n, pairs=[(2.0, 4.0), (1.0, 3.0)])
    np.testing.assert_array_equal(pairs_degrees, degrees[[3, 0]])
    worse = degrees.copy()
    worse[2, 1] = 0.15
    with pytest.raises(ns.ModelError, match=r"^pair 2 at \(2, 3\): indeterminacy = 0.15 exceeds 0.1, the indeterminacy of M"):
        ns.check_relation(positions, worse, m, n)
    curve = ns.Bezier(positions, degrees)
    assert len(curve) == 4


# ---- files, pickling, equality ----


@pytest.mark.parametrize("extension", ["toml", "json", "csv"])
def test_save_and_load_round_trip(tmp_path, root, extension):
    models = [
        ns.example1(),
        ns.load(root / "examples" / "nurbs-circle.toml"),
        ns.BSpline(RNG.uniform(-1, 1, (7, 3)), random_degrees(7), degree=2, name="spline"),
    ]
    if extension != "csv":
        models.append(ns.load(root / "examples" / "nurbs-surface.json"))
    for k, model in enumerate(models):
        path = tmp_path / f"model{k}.{extension}"
        model.save(path)
        if extension == "csv":
            options = {"kind": model.kind, "membership": model.membership}
            if model.knots is not None:
                options.update(degree=model.degree, knots=model.knots)
            back = ns.load(path, **options)
        else:
            back = ns.load(path)
        assert type(back) is type(model)
        if extension == "csv":
            # A CSV table holds the control points, knots and weights, not the names.
            for field in ["positions", "membership_degrees", "weights", "knots", "membership"]:
                np.testing.assert_array_equal(getattr(back, field), getattr(model, field))
        else:
            assert back == model
    with pytest.raises(ns.ModelError, match="model.txt"):
        ns.example1().save(tmp_path / "model.txt")
    assert not (tmp_path / "model.txt").exists()


def test_pickle_round_trip(root):
    objects = [
        ns.example1(),
        ns.example1().derivative(2),
        ns.load(root / "examples" / "nurbs-circle.toml"),
        ns.load(root / "examples" / "nurbs-circle.toml").derivative(),
        ns.load(root / "examples" / "surface.toml"),
    ]
    for obj in objects:
        back = pickle.loads(pickle.dumps(obj))
        assert back == obj and type(back) is type(obj)
    assert ns.example1() != ns.example1().elevate()
    assert ns.example1() != "Example 1"


def test_surface_against_the_command_line(cli, root):
    path = root / "examples" / "surface.toml"
    surface = ns.load(path)
    assert isinstance(surface, ns.Surface)
    u = np.array([0.0, 0.25, 0.5, 1.0])
    v = np.array([0.0, 0.75, 0.5, 1.0])
    at = ",".join(f"{a}:{b}" for a, b in zip(u, v))
    _, table = cli_table(cli, "eval", path, "--at", at, "--normal")
    got = surface(u, v)
    np.testing.assert_array_equal(got, table[:, 2:8])
    np.testing.assert_allclose(surface.normal(u, v), table[:, 8:11], rtol=0, atol=1e-15)
    grid_u, grid_v = np.meshgrid(u, v)
    assert surface(grid_u, grid_v).shape == (4, 4, 6)
    out = np.empty((4, 4, 6))
    assert surface.evaluate(grid_u, grid_v, out=out) is out
    with pytest.raises(ns.ModelError, match=r"^\(u, v\)\[1\]: parameter"):
        surface([0.0, 2.0], [0.0, 0.0])


def test_surfaces_from_grids():
    grid = RNG.uniform(-1, 1, (4, 5, 3))
    degrees = RNG.uniform(0, 1, (4, 5, 3))
    weights = RNG.uniform(0.5, 2.0, (4, 5))
    patch = ns.Surface.nurbs(grid, degrees, weights, degree=(2, 3))
    assert patch.degree == (2, 3) and patch.positions.shape == (4, 5, 3)
    np.testing.assert_array_equal(patch.weights, weights)
    corner = patch(0.0, 0.0)
    np.testing.assert_allclose(corner, np.concatenate([grid[0, 0], degrees[0, 0]]), rtol=0, atol=1e-15)
    with pytest.raises(ns.ModelError, match=r"^degrees\[2, 3\]: truth = 2 is outside"):
        bad = degrees.copy()
        bad[2, 3, 0] = 2.0
        ns.Surface.bspline(grid, bad)


# ---- figures ----


def test_figures_are_the_command_lines(cli, root, tmp_path):
    path = root / "examples" / "example1.toml"
    for view in ["all", "truth", "plane", "score"]:
        out = tmp_path / f"{view}.svg"
        done = run_cli(cli, "plot", path, "--view", view, "-o", out)
        assert done.returncode == 0, done.stderr
        assert ns.load(path).to_svg(view) == out.read_text()
    curve = ns.load(path)
    # The inline figure is `all` at a notebook size; only its root is made responsive
    # (test_inline.py).
    inline = curve._repr_svg_()
    plain = curve.to_svg("all", width=800, height=600)
    assert inline.split(">", 2)[2] == plain.split(">", 2)[2]
    png = tmp_path / "figure.png"
    curve.save_figure(png, view="controls", width=640, height=480)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ns.ModelError) as raised:
        curve.to_svg("sideways")
    assert str(raised.value) == (
        'view = "sideways": expected one of controls, truth, indeterminacy, falsity, all, plane, '
        "score, derived, data, band"
    )
    # The figure options are neutrospline plot's, with its messages (crates/neutrospline-plot).
    assert curve.to_svg("truth", azimuth=-30, elevation=40) == curve.to_svg(view="truth", azimuth=-30.0, elevation=40.0)
    assert curve.to_svg("truth", azimuth=-30) != curve.to_svg("truth")
    for options, message in [
        (dict(elevation=95), "camera elevation = 95 degrees is not supported (must be between -90 and 90)"),
        (dict(alpha=[0, 1.5]), "alpha level 1.5 is outside [0, 1] (the band view draws alpha-cuts at levels in [0, 1])"),
        (dict(width="800"), 'width = "800": expected a whole number'),
        (
            dict(colour="red"),
            'unknown option "colour" (the options are view, width, height, size, dpi, style, '
            "no-title, no-caption, title, caption, azimuth, elevation, samples, alpha, color-by)",
        ),
    ]:
        with pytest.raises(ns.ModelError) as raised:
            curve.to_svg("truth", **options)
        assert str(raised.value) == message, options
    assert {o["name"] for o in ns.figure_options()} >= {"width", "azimuth", "color_by", "alpha"}
    with pytest.raises(ns.ModelError) as raised:
        curve.save_figure(tmp_path / "figure.gif")
    assert str(raised.value) == f"{tmp_path / 'figure.gif'}: unsupported figure extension (accepted: .svg, .png, .pdf)"
    # For a paper: a PDF one column wide with the font embedded, no title; the command line's
    # bytes for the same options.
    pdf = tmp_path / "figure.pdf"
    curve.save_figure(pdf, view="all", style="paper")
    data = pdf.read_bytes()
    assert data.startswith(b"%PDF-1.7") and b"/FontFile2" in data
    assert b"/MediaBox [0 0 240.944882 198.425197]" in data
    cli_pdf = tmp_path / "cli.pdf"
    done = run_cli(cli, "plot", path, "-o", cli_pdf, "--view", "all", "--style", "paper")
    assert done.returncode == 0, done.stderr
    assert cli_pdf.read_bytes() == data
    sized = curve.to_svg("truth", size="8.5cmx6cm", no_title=True)
    assert 'width="8.5cm" height="6cm" viewBox="0 0 241 170"' in sized
    assert "<title>" not in sized and 'class="title"' not in sized
    png = tmp_path / "print.png"
    curve.save_figure(png, view="truth", size="3.5inx2.5in", dpi=200)
    header = png.read_bytes()
    assert header[16:24] == (700).to_bytes(4, "big") + (500).to_bytes(4, "big")
    assert b"pHYs" in header[:64]
    with pytest.raises(ns.ModelError) as raised:
        curve.to_svg("truth", size="8.5cm")
    assert str(raised.value) == (
        'size = "8.5cm": expected WIDTHxHEIGHT in pixels or with a unit (px, pt, mm, cm, in), '
        "for example 1600x1200 or 8.5cmx6cm"
    )
    with pytest.raises(ns.ModelError, match="derivative"):
        curve.derivative().to_svg()


# ---- fitting ----


def test_fit_matches_the_command_line(cli, root, tmp_path):
    data = root / "examples" / "data" / "survey.csv"
    out = tmp_path / "fitted.toml"
    done = run_cli(cli, "fit", "examples/data/survey.csv", "--control-points", 8, "-o", out, cwd=root)
    assert done.returncode == 0, done.stderr
    want = ns.load(out)
    curve, report = ns.fit(str(data), control_points=8)
    np.testing.assert_array_equal(curve.positions, want.positions)
    np.testing.assert_array_equal(curve.membership_degrees, want.membership_degrees)
    np.testing.assert_array_equal(curve.knots, want.knots)
    assert report["control_points"] == 8 and report["degree"] == 3
    assert set(report["max_error"]) == {"x", "y", "truth", "indeterminacy", "falsity"}
    points = [line for line in data.read_text().splitlines() if line[:1].isdigit() or line[:1] == "-"]
    assert len(points) == 80
    assert report["parameters"].shape == (80,)
    assert report["parameters"][0] == 0.0 and report["parameters"][-1] == 1.0


def test_fit_interpolates_and_reports():
    t = np.linspace(0.0, 1.0, 40)
    positions = np.column_stack([np.cos(3 * t), np.sin(3 * t), t])
    degrees = np.column_stack([t, 0.5 * (1 - t), 1 - t])
    curve, report = ns.fit(positions, degrees, interpolate=True)
    got = curve(report["parameters"])
    np.testing.assert_allclose(got[:, :3], positions, rtol=0, atol=1e-12)
    np.testing.assert_allclose(got[:, 3:], degrees, rtol=0, atol=1e-12)
    with pytest.raises(ns.ModelError, match="exclude each other"):
        ns.fit(positions, degrees, interpolate=True, control_points=5)
    with pytest.raises(ns.ModelError, match="^degrees: missing"):
        ns.fit(positions)
    with pytest.raises(ns.ModelError, match="^parametrization = "):
        ns.fit(positions, degrees, parametrization="arc")


TARGETS = "(give one target: interpolate, control-points or tolerance)"


@pytest.mark.parametrize(
    "options, message",
    [
        # The same messages as `neutrospline fit` and the studio print (crates/neutrospline-cli/tests/fit.rs).
        (dict(interpolate=True, control_points=4), f"interpolate and control-points exclude each other {TARGETS}"),
        (dict(tolerance=0.5, control_points=4), f"control-points and tolerance exclude each other {TARGETS}"),
        (dict(interpolate=True, tolerance=0.5), f"interpolate and tolerance exclude each other {TARGETS}"),
        (dict(tolerance=0), "tolerance = 0: the tolerance must be a positive finite number"),
        (dict(smoothing=-1), "smoothing = -1: the smoothing weight must be a non-negative finite number"),
        (dict(degree=5.0), "degree = 5.0: expected a whole number"),
        (dict(degree=-1), "degree = -1: expected a whole number"),
        (dict(degree="5"), 'degree = "5": expected a whole number'),
        (dict(closed="yes"), 'closed = "yes": expected true or false'),
        (dict(parametrization="arc"), 'parametrization = "arc": expected one of uniform, chord-length, centripetal'),
        (
            dict(controlpoints=4),
            'unknown option "controlpoints" (the options are degree, interpolate, control-points, '
            "tolerance, closed, parametrization, weights, smoothing, kind, membership)",
        ),
    ],
)
def test_fit_options_are_refused_with_the_librarys_messages(options, message):
    t = np.linspace(0.0, 1.0, 10)
    positions = np.column_stack([t, t * t])
    degrees = np.column_stack([t, 0.5 * np.ones_like(t), 1 - t])
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(positions, degrees, **options)
    assert str(raised.value) == message


def test_a_weight_column_is_used_only_when_asked_for(tmp_path):
    data = tmp_path / "d.csv"
    data.write_text("x,y,T,I,F,weight\n0,0,1,0,0,1\n1,1,1,0,0,2\n2,0,1,0,0,1\n3,1,1,0,0,1\n")
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(str(data), control_points=3, degree=2)
    assert str(raised.value) == (
        f"{data} has a `weight` column: set weights to column to use it (or remove the column)"
    )
    curve, report = ns.fit(str(data), control_points=3, degree=2, weights="column")
    plain = tmp_path / "p.csv"
    plain.write_text("x,y,T,I,F\n0,0,1,0,0\n1,1,1,0,0\n2,0,1,0,0\n3,1,1,0,0\n")
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(str(plain), weights="column")
    assert str(raised.value) == f"weights = column: {plain} has no `weight` column"


def test_fit_options_are_the_librarys_and_the_stubs_defaults(cli, root):
    import ast

    options = {o["name"]: o for o in ns.fit_options()}
    assert options["degree"]["default"] == 3 and options["degree"]["option"] == "degree"
    assert options["control_points"]["default"] is None
    assert options["parametrization"]["choices"] == ["uniform", "chord-length", "centripetal"]
    # The stub documents the same defaults.
    stub = ast.parse((root / "crates/neutrospline-py/python/neutrospline/_neutrospline.pyi").read_text())
    fit = next(n for n in stub.body if isinstance(n, ast.FunctionDef) and n.name == "fit")
    documented = {a.arg: ast.literal_eval(d) for a, d in zip(fit.args.kwonlyargs, fit.args.kw_defaults)}
    for name, option in options.items():
        # `weights` also takes the weights themselves; None is the rule "none".
        want = None if name == "weights" else option["default"]
        assert documented[name] == want, name
    # And the command line shows them in its help.
    helptext = run_cli(cli, "fit", "--help", cwd=root).stdout
    for option in options.values():
        assert f"--{option['option']}" in helptext
        if option["kind"] != "bool" and option["default"] is not None:
            assert f"[default: {option['default_text']}]" in helptext


# ---- threads ----


def test_four_threads_give_the_same_results():
    curve = ns.BSpline(RNG.uniform(-1, 1, (64, 2)), random_degrees(64), degree=3)
    t = RNG.uniform(0.0, 1.0, 400_000)
    want = curve(t)
    results = [None] * 4

    def work(k):
        results[k] = curve(t)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for got in results:
        np.testing.assert_array_equal(got, want)


# ---- nearest points and intersections, against the command line ----


def test_nearest_matches_query(cli, root, tmp_path):
    for model, dimension in [("bspline.toml", 2), ("nurbs-circle.toml", 2), ("helix3d.toml", 3), ("surface.toml", 3)]:
        path = root / "examples" / model
        shape = ns.load(path)
        points = RNG.uniform(-3.0, 3.0, size=(40, dimension))
        table = tmp_path / f"points{dimension}.csv"
        header = "x,y,z" if dimension == 3 else "x,y"
        np.savetxt(table, points, delimiter=",", header=header, comments="", fmt="%.17g")
        columns, want = cli_table(cli, "query", path, table)
        if isinstance(shape, ns.Surface):
            uv, distance, rows = shape.nearest(points)
            np.testing.assert_array_equal(uv, want[:, 1:3])
            offset = 3
        else:
            t, distance, rows = shape.nearest(points)
            np.testing.assert_array_equal(t, want[:, 1])
            offset = 2
        np.testing.assert_array_equal(distance, want[:, offset])
        np.testing.assert_array_equal(rows, want[:, offset + 1 : offset + 1 + rows.shape[1]])
    with pytest.raises(ns.ModelError, match=r"^points: expected an array of shape \(m, 2\)"):
        ns.example1().nearest([[0.0, 0.0, 0.0]])


def test_intersections_match_intersect(cli, root, tmp_path):
    line = ns.Bezier([[-2, -0.5], [0, 0.7], [2, 0.1]], [[1, 0, 0], [0.5, 0.5, 0], [0, 0, 1]])
    a = tmp_path / "line.toml"
    line.save(a)
    circle = root / "examples" / "nurbs-circle.toml"
    done = run_cli(cli, "intersect", a, circle)
    assert done.returncode == 0, done.stderr
    table = list(csv.reader(io.StringIO(done.stdout)))
    assert table[0][-1] == "contact"
    want = np.array([r[:-1] for r in table[1:]], dtype=float)
    got = line.intersections(ns.load(circle))
    assert got.shape == (2, 10)
    np.testing.assert_array_equal(got, want[:, 1:])
    rows, contacts = line.intersections(ns.load(circle), contacts=True)
    np.testing.assert_array_equal(rows, got)
    done = run_cli(cli, "intersect", a, circle)
    assert contacts == [r[-1] for r in csv.reader(io.StringIO(done.stdout))][1:]
    assert contacts == ["crossing", "crossing"]
    loop = ns.Bezier([[0, 0], [3, 3], [-1, 3], [2, 0]], [[0.2, 0.2, 0.2]] * 4)
    crossing = loop.intersections()
    assert crossing.shape == (1, 10)
    t_a, t_b = crossing[0, :2]
    np.testing.assert_allclose(loop(t_a)[:2], loop(t_b)[:2], rtol=0, atol=1e-12)
    with pytest.raises(ns.ModelError, match="the curves overlap"):
        line.intersections(line)


# ---- fuzzy positions (spreads) ----


def test_spreads_are_carried_through_operations(cli, root, tmp_path):
    path = root / "examples" / "fuzzy-bspline.toml"
    curve = ns.load(path)
    band = tmp_path / "band.svg"
    assert run_cli(cli, "plot", path, "--view", "band", "-o", band).returncode == 0
    assert curve.to_svg("band") == band.read_text()
    assert pickle.loads(pickle.dumps(curve)) == curve

    def cut(model_path, t, alpha):
        _, table = cli_table(cli, "eval", model_path, "--at", t, "--alpha", alpha)
        return table[0, -4:]  # x_lo, x_hi, y_lo, y_hi

    left, right = curve.split(0.4)
    elevated = curve.elevate()
    inserted = curve.insert_knot(0.55, times=2)
    for k, (piece, t_piece, t_whole) in enumerate(
        [(left, 0.2, 0.2), (right, 0.7, 0.7), (elevated, 0.3, 0.3), (inserted, 0.6, 0.6)]
    ):
        saved = tmp_path / f"piece{k}.toml"
        piece.save(saved)
        for alpha in ["0", "0.5"]:
            np.testing.assert_allclose(
                cut(saved, t_piece, alpha), cut(path, t_whole, alpha), rtol=0, atol=1e-12
            )
