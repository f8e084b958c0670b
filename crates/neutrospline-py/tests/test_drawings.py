"""`load` of drawings (.svg, .dxf): the curves and the import report, the same as
`neutrospline import` writes and prints, with the command line's options and messages."""

import math
import subprocess

import numpy as np
import pytest

import neutrospline as ns


def test_an_svg_drawing_loads_as_curves_and_a_report(root):
    curves, report = ns.load(root / "examples" / "drawing.svg", truth=0.75, falsity=0.125)
    assert report["imported"] == {"<path>": 1, "<rect>": 1}
    assert {"kind": "<text>", "reason": "not-a-curve", "count": 1} in report["skipped"]
    assert {"kind": "<line>", "reason": "hidden", "count": 1} in report["skipped"]
    assert report["warnings"] == []
    assert report["summary"].startswith("imported 2 curves (1 <path>, 1 <rect>); ")
    boundary, plot = curves
    assert (boundary.name, plot.name) == ("boundary", "plot")
    # The degrees given for every control point.
    degrees = plot.membership_degrees
    assert np.all(degrees == [0.75, 0.0, 0.125])
    # The rounded rectangle x 40..70, y 35..55, corner radius 4: its perimeter in closed
    # form, 2 (w + h) - 8 r + 2 pi r.
    length = plot.length()
    assert length == pytest.approx(2 * (30 + 20) - 8 * 4 + 2 * math.pi * 4, rel=1e-12)


def test_the_report_is_the_command_lines(root, cli, tmp_path):
    drawing = root / "examples" / "drawing.svg"
    run = subprocess.run(
        [cli, "import", drawing, "-o", tmp_path / "c.toml", "--all"],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0, run.stderr
    _, report = ns.load(drawing)
    assert run.stderr == f"{drawing}: {report['summary']}\n"
    assert ns.load(tmp_path / "c-2.toml") == ns.load(drawing)[0][1]


def test_strict_and_entities_are_the_command_lines_options(root):
    drawing = root / "examples" / "drawing.svg"
    with pytest.raises(ns.ModelError, match=r"--strict: .*skipped 1 <text> \(not a curve\)"):
        ns.load(drawing, strict=True)
    curves, report = ns.load(drawing, entities="rect")
    assert [c.name for c in curves] == ["plot"]
    assert {"kind": "<path>", "reason": "excluded", "count": 1} in report["skipped"]
    with pytest.raises(ns.ModelError, match="entities = TEXT: not an element"):
        ns.load(drawing, entities="TEXT")
    with pytest.raises(ns.ModelError, match="degree: is an option of a model table"):
        ns.load(drawing, degree=3)
    with pytest.raises(ns.ModelError, match="strict: is an option of a drawing"):
        ns.load(root / "examples" / "example1.toml", strict=True)
    with pytest.raises(ns.ModelError, match=r"truth = 1\.5 is outside \[0, 1\]"):
        ns.load(drawing, truth=1.5)
    names = [o["name"] for o in ns.import_options()]
    assert names == ["truth", "indeterminacy", "falsity", "entities", "strict"]


def test_a_dxf_export_loads_back(root, cli, tmp_path):
    out = tmp_path / "c.dxf"
    subprocess.run(
        [cli, "export", root / "examples" / "nurbs-circle.toml", "-o", out], check=True
    )
    curves, report = ns.load(out)
    assert report["imported"] == {"SPLINE": 1}
    assert curves == [ns.load(root / "examples" / "nurbs-circle.toml")]
