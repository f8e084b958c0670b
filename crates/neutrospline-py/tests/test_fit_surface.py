"""`fit_surface`: tensor-product B-spline surfaces fitted to arrays or a data file, as
`neutrospline fit --surface` fits them, checked against closed forms, scipy's
`LSQBivariateSpline` and the command line's own report."""

import json
import subprocess

import numpy as np
import pytest
from scipy.interpolate import LSQBivariateSpline

import neutrospline as ns


def scattered(count, seed):
    rng = np.random.default_rng(seed)
    uv = rng.random((count, 2))
    uv[:4] = [[0, 0], [0, 1], [1, 0], [1, 1]]
    return uv


def test_a_bicubic_polynomial_is_reproduced_from_scattered_points():
    """Data on z = u^3 - 2 u v^2 + v with bilinear degrees lie in the spline space of degree
    (3, 3) on any knots: least squares at the given (u, v) reproduces them everywhere."""
    uv = scattered(400, 1)
    u, v = uv[:, 0], uv[:, 1]
    points = np.column_stack([u, v, u**3 - 2 * u * v**2 + v])
    degrees = np.column_stack([0.2 + 0.5 * u, 0.1 + 0.2 * v, 0.1 + 0.1 * u * v])
    surface, report = ns.fit_surface(points, degrees, parameters=uv, control_points=(6, 5))
    assert report["control_points"] == [6, 5]
    assert report["degrees"] == [3, 3]
    assert report["parameters"].shape == (400, 2)
    check = scattered(50, 2)
    for a, b in check:
        row = surface.evaluate(a, b)
        want = [a, b, a**3 - 2 * a * b**2 + b, 0.2 + 0.5 * a, 0.1 + 0.2 * b, 0.1 + 0.1 * a * b]
        assert np.allclose(row, want, rtol=0, atol=1e-12), (a, b, row - want)


def test_scattered_heights_match_scipy_lsq_bivariate_spline_on_the_same_knots():
    uv = scattered(2000, 3)
    x, y = uv[:, 0], uv[:, 1]
    rng = np.random.default_rng(4)
    z = np.sin(3 * x) * np.cos(2 * y) + 0.05 * rng.standard_normal(len(x))
    points = np.column_stack([x, y, z])
    degrees = np.tile([0.6, 0.2, 0.1], (len(x), 1))
    surface, report = ns.fit_surface(points, degrees, parameters=uv, control_points=(7, 6))
    tx, ty = surface.knots_u[4:-4], surface.knots_v[4:-4]
    assert len(tx) == 3 and len(ty) == 2
    reference = LSQBivariateSpline(x, y, z, tx, ty, kx=3, ky=3, bbox=[0, 1, 0, 1])
    grid = scattered(200, 5)
    ours = np.array([surface.evaluate(a, b)[2] for a, b in grid])
    theirs = reference.ev(grid[:, 0], grid[:, 1])
    scale = np.abs(theirs).max()
    assert np.abs(ours - theirs).max() <= 1e-10 * scale
    # Our residuals are scipy's (the same least-squares problem).
    rms_theirs = np.sqrt(np.mean((reference.ev(x, y) - z) ** 2))
    assert report["rms_error"]["z"] <= rms_theirs * (1 + 1e-9)


def test_a_grid_array_interpolates_every_point():
    u, v = np.meshgrid(np.linspace(0, 2, 7), np.linspace(-1, 1, 5), indexing="ij")
    points = np.stack([u, v, np.exp(-u * u - v * v)], axis=-1)
    degrees = np.stack([0.9 - 0.3 * u, 0.1 + 0 * u, 0.05 + 0.1 * v * v], axis=-1)
    surface, report = ns.fit_surface(points, degrees, interpolate=True, degree=(3, 2))
    assert report["control_points"] == [7, 5] and report["two_pass"]
    for k, (a, b) in enumerate(report["parameters"]):
        row = surface.evaluate(a, b)
        i, j = divmod(k, 5)
        assert np.allclose(row[:3], points[i, j], rtol=0, atol=1e-12)
        assert np.allclose(row[3:], degrees[i, j], rtol=0, atol=1e-12)


def test_a_data_file_gives_the_command_lines_report(root, cli, tmp_path):
    hill = root / "examples/data/hill_grid.csv"
    surface, report = ns.fit_surface(hill, grid=(12, 10), control_points=(8, 6))
    run = subprocess.run(
        [cli, "fit", hill, "--surface", "--grid", "12x10", "--control-points", "8,6",
         "--report", "json", "-o", tmp_path / "hill.toml"],
        capture_output=True, text=True, check=True,
    )
    theirs = json.loads(run.stderr)
    ours = {k: v for k, v in report.items() if k != "parameters"}
    assert ours == theirs
    assert ns.load(tmp_path / "hill.toml").positions.tolist() == surface.positions.tolist()


def test_bad_input_is_refused_with_the_rule():
    u, v = np.meshgrid(np.linspace(0, 1, 5), np.linspace(0, 1, 5), indexing="ij")
    points = np.stack([u, v, u * v], axis=-1).reshape(-1, 3)
    degrees = np.tile([0.5, 0.2, 0.1], (25, 1))
    with pytest.raises(ns.ModelError, match=r"a grid of 4 x 6 points does not hold 25 points"):
        ns.fit_surface(points, degrees, grid=(4, 6))
    bad = points.copy()
    bad[7, 2] = np.nan
    with pytest.raises(ns.ModelError, match=r"not a finite number"):
        ns.fit_surface(bad, degrees)
    with pytest.raises(ns.ModelError, match=r"a surface is fitted to points in 3-D"):
        ns.fit_surface(points[:, :2], degrees)
    with pytest.raises(ns.ModelError, match=r"degrees"):
        ns.fit_surface(points)
    with pytest.raises(ns.ModelError, match=r"parameters"):
        ns.fit_surface(points, degrees, parameters=np.zeros((25, 3)))
    with pytest.raises(ns.ModelError, match=r"interpolate"):
        ns.fit_surface(points, degrees, interpolate=True, control_points=(4, 4))


def test_data_that_leaves_the_domain_empty_warns_and_smoothing_settles_it():
    rng = np.random.default_rng(9)
    cluster = 0.3 * rng.random((200, 2))
    uv = np.vstack([cluster, [[0, 0], [1, 1], [1, 0], [0, 1]]])
    points = np.column_stack([uv, uv.sum(axis=1)])
    degrees = np.tile([0.5, 0.2, 0.1], (len(uv), 1))
    with pytest.warns(RuntimeWarning, match=r"data: the least-squares system is nearly singular"):
        _, report = ns.fit_surface(points, degrees, projection="xy", control_points=(10, 10))
    assert report["condition_estimate"] > 1e10
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, report = ns.fit_surface(
            points, degrees, projection="xy", control_points=(10, 10), smoothing=1e-6
        )
    assert report["condition_estimate"] < 1e10


def test_a_dataframe_is_read_by_its_column_names(root):
    pandas = pytest.importorskip("pandas")
    hill = root / "examples/data/hill_grid.csv"
    frame = pandas.read_csv(hill, comment="#")
    # Columns in another order, an extra one, names in capitals: read by name.
    frame = frame[["falsity", "Z" if "Z" in frame else "z", "truth", "x", "y", "indeterminacy"]]
    frame = frame.rename(columns={"z": "Z"}).assign(note="survey 2026")
    surface, report = ns.fit_surface(frame, grid=(12, 10), control_points=(8, 6))
    from_file, file_report = ns.fit_surface(hill, grid=(12, 10), control_points=(8, 6))
    assert surface.positions.tolist() == from_file.positions.tolist()
    assert surface.membership_degrees.tolist() == from_file.membership_degrees.tolist()
    assert report["max_error"] == file_report["max_error"]
    with pytest.raises(ns.ModelError, match=r"the DataFrame has no column `z`"):
        ns.fit_surface(frame.drop(columns=["Z"]))
    with pytest.raises(ns.ModelError, match=r"degrees"):
        ns.fit_surface(frame, np.zeros((120, 3)))


def test_a_fitted_surface_sampled_and_refitted_comes_back():
    """Fit noisy data at parameters P; sample that surface at P and fit again at P: the knots
    depend only on P and the control-point counts, so the data now lie in the spline space and
    the second fit returns the first surface's control values (to 1e-10 of scale)."""
    uv = scattered(600, 11)
    rng = np.random.default_rng(12)
    u, v = uv[:, 0], uv[:, 1]
    points = np.column_stack([3 * u, 2 * v, np.sin(3 * u) * v + 0.05 * rng.standard_normal(len(u))])
    degrees = np.column_stack([0.3 + 0.4 * u, 0.2 + 0.1 * v, 0.1 + 0.2 * u * v])
    first, _ = ns.fit_surface(points, degrees, parameters=uv, control_points=(7, 6))
    rows = np.array([first.evaluate(a, b) for a, b in uv])
    again, report = ns.fit_surface(rows[:, :3], rows[:, 3:], parameters=uv, control_points=(7, 6))
    assert again.knots_u.tolist() == first.knots_u.tolist()
    assert again.knots_v.tolist() == first.knots_v.tolist()
    scale = np.abs(first.positions).max()
    assert np.abs(again.positions - first.positions).max() <= 1e-10 * scale
    assert np.abs(again.membership_degrees - first.membership_degrees).max() <= 1e-10
    assert report["max_error"]["z"] <= 1e-12 * scale
