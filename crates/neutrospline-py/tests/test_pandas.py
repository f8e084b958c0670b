"""pandas DataFrames in and out: `fit`, `fit_surface` and `load` read a DataFrame's columns by
name as the command line reads the CSV file with those columns (one reader: the DataFrame is
handed to it as a table's text), and `to_dataframe` writes the columns of `neutrospline eval`."""

import csv
import io
import os
import subprocess

import numpy as np
import pytest

import neutrospline as ns

pd = pytest.importorskip("pandas")


def read_table(path):
    return pd.read_csv(path, comment="#")


def control_values(model):
    return np.column_stack([model.positions, model.membership_degrees])


# ---- fit ----


def test_fit_of_a_dataframe_is_the_fit_of_its_csv_file(root):
    survey = root / "examples/data/survey.csv"
    frame = read_table(survey)
    assert list(frame.columns) == ["x", "y", "truth", "indeterminacy", "falsity"]
    from_frame, report = ns.fit(frame, control_points=12, weights="score")
    from_file, file_report = ns.fit(survey, control_points=12, weights="score")
    assert control_values(from_frame).tolist() == control_values(from_file).tolist()
    assert from_frame.knots.tolist() == from_file.knots.tolist()
    assert report["max_error"] == file_report["max_error"]
    assert report["parameters"].tolist() == file_report["parameters"].tolist()
    assert from_frame.description == "Fitted to a DataFrame (80 points) by neutrospline.fit"
    # The command line's fit of the file: the same control points, every digit.
    assert control_values(from_frame)[0].tolist() == [
        -0.031247791707337068, -0.010148078200256323, 0.9045226295150615,
        0.11777264046023175, 0.05539924146386389,
    ]


def test_columns_by_name_in_any_order_and_case_with_aliases_and_extra_columns(root):
    survey = root / "examples/data/survey.csv"
    frame = read_table(survey)
    shuffled = frame.rename(
        columns={"x": "X", "truth": "T", "indeterminacy": "i", "falsity": "F"}
    )[["F", "y", "T", "X", "i"]].assign(note="fix", station=np.arange(80))
    fitted, _ = ns.fit(shuffled, control_points=10)
    plain, _ = ns.fit(survey, control_points=10)
    assert control_values(fitted).tolist() == control_values(plain).tolist()
    # Extra columns are left out only when asked for with ignore_unknown_columns=False.
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(shuffled, control_points=10, ignore_unknown_columns=False)
    assert str(raised.value) == (
        "DataFrame: unknown column `note` (known columns: x, y, z, truth (T), "
        "indeterminacy (I), falsity (F), weight, name, parameter, u, v) "
        "(its columns: F, y, T, X, i, note, station)"
    )


def test_the_columns_mapping_reads_mu_and_nu_under_the_intuitionistic_rule(root):
    frame = pd.DataFrame(
        {
            "x": [0.0, 1.0, 2.0, 3.0, 4.0],
            "y": [0.0, 1.0, 0.0, 1.0, 0.0],
            "mu": [0.6, 0.7, 0.8, 0.7, 0.6],
            "nu": [0.3, 0.2, 0.1, 0.2, 0.3],
        }
    )
    fitted, _ = ns.fit(
        frame, columns={"truth": "mu", "falsity": "nu"}, membership="intuitionistic",
        interpolate=True, degree=2,
    )
    # The same options as text (the command line's --columns) read the same table.
    same, _ = ns.fit(
        frame, columns="truth=mu,falsity=nu", membership="intuitionistic",
        interpolate=True, degree=2,
    )
    assert control_values(fitted).tolist() == control_values(same).tolist()
    # An interpolating fit passes through the data: hesitation 1 - mu - nu is the
    # indeterminacy.
    _, report = ns.fit(
        frame, columns={"truth": "mu", "falsity": "nu"}, membership="intuitionistic",
        interpolate=True, degree=2,
    )
    values = fitted.evaluate(report["parameters"])
    np.testing.assert_allclose(values[:, 2], frame["mu"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(values[:, 4], frame["nu"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(values[:, 3], 1 - frame["mu"] - frame["nu"], rtol=0, atol=1e-12)
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(frame, columns={"truth": "mu", "falsity": "NU2"}, membership="intuitionistic")
    assert str(raised.value) == (
        "columns falsity=NU2: the DataFrame has no column `NU2` "
        "(its columns: x, y, mu, nu)"
    )


def test_parameter_and_weight_columns(root):
    curve = ns.example1()
    frame = curve.to_dataframe(21)
    # `t` is the alias of truth in a table: the message says how to read it as parameters.
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(frame)
    assert str(raised.value) == (
        "DataFrame: column 4 `truth` repeats column 1 `t` (each field may appear once; T, I and "
        "F are aliases of truth, indeterminacy and falsity) (its columns: t, x, y, truth, "
        "indeterminacy, falsity; `t` reads as truth (T): leave it out with "
        "ignore_columns=[\"t\"], or read it as the parameters of a fit with "
        "columns={\"parameter\": \"t\"})"
    )
    # The curve's own parameters, given as the `parameter` column: a cubic through 21 of its
    # points is the curve again.
    fitted, report = ns.fit(frame, columns={"parameter": "t"}, control_points=4, kind="bezier")
    assert report["parameters"].tolist() == frame["t"].tolist()
    t = np.linspace(0, 1, 7)
    np.testing.assert_allclose(fitted(t), curve(t), rtol=0, atol=1e-12)
    renamed = frame.rename(columns={"t": "parameter"})
    again, _ = ns.fit(renamed, control_points=4, kind="bezier")
    assert control_values(again).tolist() == control_values(fitted).tolist()
    # A weight column is used with weights="column", as for a file.
    weighted = renamed.assign(weight=np.linspace(1.0, 3.0, 21))
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(weighted, control_points=4)
    assert str(raised.value) == (
        "DataFrame has a `weight` column: set weights to column to use it (or remove the column)"
    )
    by_column, _ = ns.fit(weighted, control_points=4, weights="column")
    by_array, _ = ns.fit(
        renamed, control_points=4, weights=weighted["weight"].to_numpy(),
        parameters=renamed["parameter"].to_numpy(),
    )
    assert control_values(by_column).tolist() == control_values(by_array).tolist()


def test_errors_name_the_row_the_missing_column_and_the_columns_present(root):
    frame = read_table(root / "examples/data/survey.csv")
    bad = frame.copy()
    bad.loc[3, "truth"] = 1.5
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(bad)
    assert str(raised.value) == (
        "DataFrame row 3: truth = 1.5 is outside [0, 1] (every degree must be in [0, 1])"
    )
    # The index label is named when it is not the position.
    labelled = bad.set_index(pd.Index([f"fix{k}" for k in range(80)]))
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(labelled)
    assert str(raised.value).startswith("DataFrame row 3 (index 'fix3'): truth = 1.5")
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(frame.drop(columns=["falsity"]))
    assert str(raised.value) == (
        "the DataFrame has no column `falsity` (its columns: x, y, truth, indeterminacy; "
        "neutrosophic rule requires it)"
    )
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(frame.rename(columns={"y": "height"}))
    assert str(raised.value) == (
        "the DataFrame has no column `y` (its columns: x, height, truth, indeterminacy, "
        "falsity; every data point needs x, y and its truth)"
    )
    missing = frame.astype({"x": "float64"})
    missing.loc[5, "x"] = np.nan
    with pytest.raises(ns.ModelError) as raised:
        ns.fit(missing)
    assert str(raised.value) == (
        "DataFrame row 5: column `x`: value `NaN` is not a finite number (NaN and infinities "
        "are not allowed)"
    )
    with pytest.raises(ns.ModelError, match=r"^degrees: the DataFrame's columns give the degrees"):
        ns.fit(frame, np.zeros((80, 3)))
    with pytest.raises(ns.ModelError, match=r"^delimiter: does not apply to a DataFrame"):
        ns.load(frame, delimiter=";")
    with pytest.raises(ns.ModelError, match=r"^columns: is an option of a table"):
        ns.fit(frame[["x", "y"]].to_numpy(), frame[["truth", "indeterminacy", "falsity"]].to_numpy(),
               columns={"truth": "mu"})


def test_a_file_is_read_with_the_same_column_options(root, tmp_path):
    path = tmp_path / "renamed.csv"
    frame = read_table(root / "examples/data/survey.csv").rename(columns={"truth": "mu"})
    frame.assign(note="n").to_csv(path, index=False)
    from_file, _ = ns.fit(path, columns={"truth": "mu"}, ignore_columns=["note"], control_points=9)
    from_frame, _ = ns.fit(frame, columns={"truth": "mu"}, control_points=9)
    assert control_values(from_file).tolist() == control_values(from_frame).tolist()


# ---- fit_surface ----


def test_fit_surface_of_a_dataframe_with_mapped_columns_is_the_files(root):
    hill = root / "examples/data/hill_grid.csv"
    frame = read_table(hill).rename(columns={"z": "height", "truth": "mu"})
    surface, report = ns.fit_surface(
        frame, columns={"z": "height", "truth": "mu"}, grid=(12, 10), control_points=(8, 6)
    )
    from_file, file_report = ns.fit_surface(hill, grid=(12, 10), control_points=(8, 6))
    assert surface.positions.tolist() == from_file.positions.tolist()
    assert surface.membership_degrees.tolist() == from_file.membership_degrees.tolist()
    assert report["max_error"] == file_report["max_error"]
    with pytest.raises(ns.ModelError) as raised:
        ns.fit_surface(frame, columns={"truth": "mu"}, grid=(12, 10))
    assert str(raised.value) == (
        "data: the DataFrame has no column `z` (its columns: x, y, height, mu, indeterminacy, "
        "falsity; a surface needs x, y, z)"
    )
    with pytest.raises(ns.ModelError) as raised:
        ns.fit_surface(frame, columns={"z": "height"}, grid=(12, 10))
    assert str(raised.value) == (
        "the DataFrame has no column `truth` (its columns: x, y, height, mu, indeterminacy, "
        "falsity; every data point needs x, y and its truth)"
    )


# ---- load ----


def test_load_of_a_dataframe_is_load_of_its_csv_file(root):
    frame = read_table(root / "examples/example1.csv")
    model = ns.load(frame)
    assert model == ns.load(root / "examples/example1.csv")
    assert model.point_names == ["C0", "C1", "C2", "C3"]
    assert control_values(model).tolist() == control_values(ns.example1()).tolist()
    knots = [0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1]
    spline_frame = read_table(root / "examples/bspline.csv")
    spline = ns.load(spline_frame, kind="bspline", degree=3, knots=knots)
    assert spline == ns.load(root / "examples/bspline.csv", kind="bspline", degree=3, knots=knots)
    assert spline.knots.tolist() == knots


def test_load_of_a_nurbs_and_a_surface_from_dataframes(root):
    circle = ns.load(root / "examples/nurbs-circle.toml")
    frame = pd.DataFrame(
        {
            "x": circle.positions[:, 0],
            "y": circle.positions[:, 1],
            "truth": circle.membership_degrees[:, 0],
            "indeterminacy": circle.membership_degrees[:, 1],
            "falsity": circle.membership_degrees[:, 2],
            "weight": circle.weights,
        }
    )
    loaded = ns.load(frame, kind="nurbs", degree=circle.degree, knots=circle.knots)
    t = np.linspace(*circle.domain, 33)
    assert loaded(t).tolist() == circle(t).tolist()
    surface = ns.load(root / "examples/surface.toml")
    grid = np.concatenate([surface.positions, surface.membership_degrees], axis=-1).reshape(-1, 6)
    table = pd.DataFrame(grid, columns=["x", "y", "z", "T", "I", "F"])
    again = ns.load(table, kind="bezier-surface", rows=4, cols=4)
    assert again.positions.tolist() == surface.positions.tolist()
    assert again.membership_degrees.tolist() == surface.membership_degrees.tolist()
    with pytest.raises(ns.ModelError) as raised:
        ns.load(table.drop(columns=["z"]), kind="bezier-surface", rows=4, cols=4)
    assert str(raised.value) == (
        "the DataFrame has no column `z` (its columns: x, y, T, I, F; surfaces are 3-D: every "
        "control point needs x, y and z)"
    )
    with pytest.raises(ns.ModelError) as raised:
        ns.load(frame.drop(columns=["weight"]), kind="nurbs", degree=2, knots=circle.knots)
    assert str(raised.value) == (
        "the DataFrame has no column `weight` (its columns: x, y, truth, indeterminacy, "
        "falsity; kind `nurbs` needs a positive weight for every control point)"
    )


def test_load_errors_name_the_row_with_its_index_label(root):
    frame = read_table(root / "examples/example1.csv").set_index("name", drop=False)
    frame.loc["C2", "falsity"] = -0.1
    with pytest.raises(ns.ModelError) as raised:
        ns.load(frame)
    assert str(raised.value) == (
        "DataFrame row 2 (index 'C2'): falsity = -0.1 is outside [0, 1] (every degree must be "
        "in [0, 1])"
    )


# ---- to_dataframe and sample ----


def test_curve_to_dataframe_has_evals_columns_and_values(root, cli):
    curve = ns.load(root / "examples/bspline.toml")
    frame = curve.to_dataframe(11)
    assert list(frame.columns) == ["t", "x", "y", "truth", "indeterminacy", "falsity"]
    t, points = curve.sample(11, parameters=True)
    assert frame["t"].tolist() == t.tolist()
    assert t[0] == 0.0 and t[-1] == 1.0 and np.allclose(t, np.linspace(0, 1, 11), rtol=0, atol=1e-15)
    assert frame.iloc[:, 1:].to_numpy().tolist() == curve.evaluate(t).tolist()
    assert points.tolist() == curve.evaluate(t).tolist()
    # Given parameters; the scores of eval --scores.
    at = np.array([0.0, 0.25, 0.6, 1.0])
    scored = curve.to_dataframe(at, scores=True)
    values = curve.evaluate(at)
    assert scored["t"].tolist() == at.tolist()
    assert scored[["x", "y", "truth", "indeterminacy", "falsity"]].to_numpy().tolist() == values.tolist()
    np.testing.assert_array_equal(scored["score"], ns.score(values[:, 2:]))
    np.testing.assert_array_equal(scored["accuracy"], values[:, 2] - values[:, 4])
    assert scored["certainty"].tolist() == values[:, 2].tolist()
    # The command line's eval table, read by pandas: the same columns and numbers.
    if os.path.exists(cli):
        out = subprocess.run(
            [str(cli), "eval", str(root / "examples/bspline.toml"), "--samples", "11", "--scores"],
            check=True, capture_output=True, text=True,
        ).stdout
        table = pd.read_csv(io.StringIO(out))
        ours = curve.to_dataframe(11, scores=True)
        assert list(table.columns) == list(ours.columns)
        np.testing.assert_allclose(table.to_numpy(), ours.to_numpy(), rtol=0, atol=1e-15)


def test_a_3d_curve_and_a_surface_to_dataframe(root, cli):
    helix = ns.load(root / "examples/helix3d.toml")
    frame = helix.to_dataframe(5)
    assert list(frame.columns) == ["t", "x", "y", "z", "truth", "indeterminacy", "falsity"]
    assert frame.iloc[:, 1:].to_numpy().tolist() == helix.sample(5).tolist()
    one = helix.to_dataframe(0.5)
    assert one.iloc[0, 1:].tolist() == helix(0.5).tolist()
    surface = ns.load(root / "examples/surface.toml")
    grid = surface.to_dataframe(4, 3)
    assert list(grid.columns) == ["u", "v", "x", "y", "z", "truth", "indeterminacy", "falsity"]
    assert len(grid) == 12
    # u varies slowest, as eval --samples lists a surface's grid.
    assert grid["u"].tolist() == [0.0] * 3 + [1 / 3] * 3 + [2 / 3] * 3 + [1.0] * 3
    assert grid["v"].tolist()[:3] == [0.0, 0.5, 1.0]
    assert grid.iloc[:, 2:].to_numpy().tolist() == surface.evaluate(grid["u"].to_numpy(), grid["v"].to_numpy()).tolist()
    u, v = np.array([0.1, 0.9]), np.array([0.3, 0.2])
    pairs = surface.to_dataframe(u, v, scores=True)
    assert pairs.iloc[:, 2:8].to_numpy().tolist() == surface.evaluate(u, v).tolist()
    np.testing.assert_array_equal(pairs["score"], ns.score(surface.evaluate(u, v)[:, 3:]))
    if os.path.exists(cli):
        out = subprocess.run(
            [str(cli), "eval", str(root / "examples/surface.toml"), "--samples", "5"],
            check=True, capture_output=True, text=True,
        ).stdout
        table = pd.read_csv(io.StringIO(out))
        ours = surface.to_dataframe(5)
        assert list(table.columns) == list(ours.columns)
        np.testing.assert_allclose(table.to_numpy(), ours.to_numpy(), rtol=0, atol=1e-15)


def test_sample_with_parameters():
    curve = ns.example1()
    t, points = curve.sample(5, parameters=True)
    assert t.tolist() == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert points.tolist() == curve.sample(5).tolist() == curve.evaluate(t).tolist()
    t, points = curve.derivative().sample(3, parameters=True)
    assert points.tolist() == curve.derivative()(t).tolist()
    empty_t, empty = curve.sample(0, parameters=True)
    assert empty_t.shape == (0,) and empty.shape == (0, 5)


def test_a_curve_round_trips_through_a_dataframe_and_a_csv_file(tmp_path):
    curve = ns.example1()
    frame = curve.to_dataframe(41)
    path = tmp_path / "samples.csv"
    frame.to_csv(path, index=False)
    with open(path, newline="") as f:
        header = next(csv.reader(f))
    assert header == ["t", "x", "y", "truth", "indeterminacy", "falsity"]
    from_file, _ = ns.fit(path, columns="parameter=t", control_points=4, kind="bezier")
    from_frame, _ = ns.fit(frame, columns={"parameter": "t"}, control_points=4, kind="bezier")
    assert control_values(from_file).tolist() == control_values(from_frame).tolist()
    np.testing.assert_allclose(control_values(from_frame), control_values(curve), rtol=0, atol=1e-12)
