"""The tutorial notebook examples/tutorial.ipynb runs from start to end in a Jupyter kernel of
this Python (nbclient; a kernel spec written for the test runs sys.executable, so the kernel
imports the installed wheel whatever other kernels the machine has), within its time budget,
and its outputs show the library's values."""

import ast
import json
import re
import sys
import time

import numpy as np
import pytest

import neutrospline as ns

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")
pytest.importorskip("matplotlib")
pd = pytest.importorskip("pandas")


KERNEL = "neutrospline-tutorial-test"


@pytest.fixture(scope="module")
def executed(root, tmp_path_factory):
    notebook = nbformat.read(root / "examples/tutorial.ipynb", as_version=4)
    assert notebook.metadata.kernelspec.name == "python3"
    # A kernel spec of this interpreter, first on JUPYTER_PATH: the kernel is the test's Python.
    kernels = tmp_path_factory.mktemp("jupyter")
    spec = kernels / "kernels" / KERNEL
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python (tests)",
        "language": "python",
    }))
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("JUPYTER_PATH", str(kernels))
        started = time.perf_counter()
        client = nbclient.NotebookClient(
            notebook,
            timeout=120,
            kernel_name=KERNEL,
            resources={"metadata": {"path": str(root / "examples")}},
        )
        client.execute()
        elapsed = time.perf_counter() - started
    return notebook, elapsed


def cell(notebook, tag):
    found = [c for c in notebook.cells if tag in c.get("metadata", {}).get("tags", [])]
    assert len(found) == 1, tag
    return found[0]


def text(notebook, tag):
    return "".join(o.get("text", "") for o in cell(notebook, tag).outputs if o.output_type == "stream")


def value_after(output, label):
    """The Python literal printed after `label` on its line."""
    line = next(line for line in output.splitlines() if line.startswith(label))
    return ast.literal_eval(line[len(label):].strip())


def html_table(html):
    """The header and the rows (index label, then cells) of a DataFrame's HTML output."""
    from html.parser import HTMLParser

    class Table(HTMLParser):
        def __init__(self):
            super().__init__()
            self.rows, self.cell = [], None

        def handle_starttag(self, tag, attrs):
            if tag == "tr":
                self.rows.append([])
            elif tag in ("td", "th"):
                self.cell = ""

        def handle_data(self, data):
            if self.cell is not None:
                self.cell += data

        def handle_endtag(self, tag):
            if tag in ("td", "th") and self.cell is not None:
                self.rows[-1].append(self.cell.strip())
                self.cell = None

    parser = Table()
    parser.feed(html)
    header, *rows = [r for r in parser.rows if r]
    return header[1:], rows


def test_the_notebook_runs_without_errors_within_its_budget(executed):
    notebook, elapsed = executed
    errors = [o for c in notebook.cells if c.cell_type == "code" for o in c.outputs if o.output_type == "error"]
    assert errors == []
    assert elapsed < 30, elapsed
    # The kernel imported the package under test (the same version, from this interpreter).
    assert text(notebook, "imports").strip() == ns.__version__


def test_example_1_outputs_are_the_librarys(executed):
    notebook, _ = executed
    curve = ns.example1()
    middle = value_after(text(notebook, "example1-middle"), "C(0.5) =")
    assert middle == curve(0.5).tolist()
    assert value_after(text(notebook, "example1-middle"), "score(0.5) =") == float(ns.score(curve(0.5)[2:]))
    # The table is the DataFrame of to_dataframe(11, scores=True), rounded to 6 decimals.
    columns, rows = html_table(cell(notebook, "example1-table").outputs[0]["data"]["text/html"])
    want = curve.to_dataframe(11, scores=True).round(6)
    assert columns == list(want.columns)
    shown = np.array([[float(v) for v in row[1:]] for row in rows])
    np.testing.assert_allclose(shown, want.to_numpy(), rtol=0, atol=5e-7)
    assert [float(v) for v in rows[5][:5]] == [5, 0.5, 4.625, 4.0, 0.625]
    columns, rows = html_table(cell(notebook, "example1-controls").outputs[0]["data"]["text/html"])
    assert columns == ["x", "y", "truth", "indeterminacy", "falsity"]
    assert rows[3][0] == "C3" and [float(v) for v in rows[3][1:]] == [9, 5, 0.2, 0.4, 0.4]
    legend = value_after(text(notebook, "example1-figure"), "")
    assert legend == [
        "truth curve", "indeterminacy curve", "falsity curve", "control polygons",
        "crisp curve (degree 0)", "crisp control polygon",
    ]
    assert any("image/png" in o.get("data", {}) for o in cell(notebook, "example1-figure").outputs)


def test_the_survey_fit_and_the_surface_are_the_librarys(executed, root):
    notebook, _ = executed
    fitted, report = ns.fit(root / "examples/data/survey.csv", control_points=12, weights="score")
    output = text(notebook, "survey-fit")
    assert output.splitlines()[0] == "BSpline 12 control points, degree 3"
    assert value_after(output, "rms error of y:") == report["rms_error"]["y"]
    assert value_after(output, "max error of truth:") == report["max_error"]["truth"]
    terrain, surface_report = ns.fit_surface(
        root / "examples/data/topobathy_grid.csv", grid=(60, 46), control_points=(20, 16)
    )
    output = text(notebook, "surface-fit")
    assert output.splitlines()[0] == "bspline-surface [20, 16]"
    assert value_after(output, "rms error of z (km):") == surface_report["rms_error"]["z"]
    assert value_after(output, "S(0.5, 0.5) =") == terrain.evaluate(0.5, 0.5).tolist()
    for tag in ["survey-figure", "surface-figure", "scores"]:
        assert any("image/png" in o.get("data", {}) for o in cell(notebook, tag).outputs), tag


def test_the_export_round_trips_and_the_scores_are_the_librarys(executed, root):
    notebook, _ = executed
    output = text(notebook, "export")
    assert value_after(output, "round trip equal:") is True
    assert value_after(output, "files:") == ["survey-curve.csv", "survey.svg", "survey.toml"]
    fitted, _ = ns.fit(root / "examples/data/survey.csv", control_points=12, weights="score")
    samples = fitted.to_dataframe(400, scores=True)
    worst = samples.loc[samples["score"].idxmin()]
    match = re.search(r"lowest score ([0-9.]+) at x = ([0-9.]+)", text(notebook, "scores"))
    assert float(match.group(1)) == round(worst["score"], 6)
    assert float(match.group(2)) == round(worst["x"], 3)
