"""Inverse arc length: `parameter_at_length` and `arc_length_parameters` against the command
line's `eval --arc-length-samples` (the same numbers) and against the circle's angles."""

import math
import subprocess

import numpy as np

import neutrospline as ns


def test_arc_length_samples_are_the_command_lines(cli, root):
    path = root / "examples" / "bspline.toml"
    done = subprocess.run([str(cli), "eval", str(path), "--arc-length-samples", "17"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    rows = np.array([[float(v) for v in line.split(",")] for line in done.stdout.splitlines()[1:]])
    curve = ns.load(path)
    ts = curve.arc_length_parameters(17)
    np.testing.assert_array_equal(ts, rows[:, 0])
    # (Python evaluates in the batch engine, the command line point by point: ulps apart.)
    np.testing.assert_allclose(curve(ts), rows[:, 1:], rtol=0, atol=1e-14)
    total = curve.length()
    for k, t in enumerate(ts):
        assert abs(curve.arc_length(0.0, float(t)) - k * total / 16) <= 1e-12 * total


def test_circle_points_by_arc_length_are_at_even_angles(root):
    circle = ns.load(root / "examples" / "nurbs-circle.toml")
    ts = circle.arc_length_parameters(37, accuracy=1e-14)
    points = circle(ts)
    angles = np.unwrap(np.arctan2(points[:, 1], points[:, 0]))
    np.testing.assert_allclose(angles - angles[0], np.linspace(0, 2 * math.pi, 37), rtol=0, atol=1e-12)
    assert abs(circle.parameter_at_length(math.pi / 2) - 0.25) < 1e-15
    try:
        circle.parameter_at_length(7.0)
    except ns.ModelError as error:
        assert str(error) == f"arc length 7 is outside [0, {circle.length()!r}] (the curve's length)"
    else:
        raise AssertionError("no error")
