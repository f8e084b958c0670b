"""`Curve.transform` / `Surface.transform`: the operations of `neutrospline transform`, with
its options and messages, writing the same models (checked byte for byte against the command
line), the pieces of `split` and `to_bezier` as tuples, and a warning when a knot removal
falls short."""

import subprocess
import warnings

import numpy as np
import pytest

import neutrospline as ns


def cli_model(cli, tmp_path, path, *args):
    out = tmp_path / "cli.toml"
    done = subprocess.run([str(cli), "transform", str(path), "-o", str(out), *args], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return out.read_text()


@pytest.mark.parametrize(
    "model, options, flags",
    [
        ("bspline.toml", dict(refine=2), ["--refine", "2"]),
        ("bspline.toml", dict(insert_knot=[0.3, 0.3]), ["--insert-knot", "0.3,0.3"]),
        ("example1.toml", dict(elevate=2), ["--elevate", "2"]),
        ("nurbs-circle.toml", dict(reverse=True), ["--reverse"]),
        ("fuzzy-bspline.toml", dict(reparametrize="0:4"), ["--reparametrize", "0:4"]),
        ("surface.toml", dict(insert_knot=[0.25], direction="v"), ["--insert-knot", "0.25", "--direction", "v"]),
    ],
)
def test_transform_writes_the_command_lines_model(cli, root, tmp_path, model, options, flags):
    path = root / "examples" / model
    shape = ns.load(path).transform(**options)
    ours = tmp_path / "py.toml"
    shape.save(ours)
    assert ours.read_text() == cli_model(cli, tmp_path, path, *flags)


def test_pieces_and_removal(root):
    spline = ns.load(root / "examples" / "bspline.toml")
    left, right = spline.transform(split=0.5)
    np.testing.assert_allclose(left(0.5), right(0.5), rtol=0, atol=1e-15)
    np.testing.assert_allclose(right(0.8), spline(0.8), rtol=0, atol=1e-14)
    pieces = spline.transform(to_bezier=True)
    assert [type(p).__name__ for p in pieces] == ["Bezier"] * 4
    inserted = spline.transform(insert_knot=[0.35, 0.35])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        back = inserted.transform(remove_knot=0.35, tolerance=1e-9)
    assert back.knots.tolist() == spline.knots.tolist()
    with pytest.warns(UserWarning, match=r"knot 0.5 not removed: removing it once would move the curve by more than the tolerance 1e-9"):
        same = spline.transform(remove_knot=0.5, tolerance=1e-9)
    assert same.knots.tolist() == spline.knots.tolist()
    assert spline.transform(reverse=True).point_names == spline.point_names[::-1]


def test_transform_messages(root):
    spline = ns.load(root / "examples" / "bspline.toml")
    surface = ns.load(root / "examples" / "surface.toml")
    for shape, options, message in [
        (spline, dict(), "give one operation: --elevate, --reduce, --insert-knot, --refine, --remove-knot, --split, "
                         "--subsegment, --reverse, --to-bezier, --reparametrize"),
        (spline, dict(split=0.5, reverse=True), "give one operation per call (given: split, reverse)"),
        (spline, dict(remove_knot=0.25, tolerance=1.0), "0.25 is not an interior knot (the interior knots are 0.2, 0.5, 0.7)"),
        (spline, dict(elevate=1, direction="u"), "--direction u is for surfaces; this model is a curve"),
        (surface, dict(elevate=1), "--elevate on a surface needs --direction u or v"),
        (spline, dict(subsegment="0.2"), 'subsegment = "0.2": expected A:B, two numbers'),
    ]:
        with pytest.raises(ns.ModelError) as raised:
            shape.transform(**options)
        assert str(raised.value) == message, options
    assert [o["name"] for o in ns.transform_options()] == [
        "elevate", "reduce", "insert_knot", "refine", "remove_knot", "times", "tolerance", "split",
        "subsegment", "reverse", "to_bezier", "reparametrize", "direction",
    ]


@pytest.mark.parametrize("degree", [1, 2, 3, 5, 8])
def test_elevation_and_reduction_match_the_bezier_package(degree):
    """Degree elevation against `bezier.Curve.elevate` (the control points of every channel,
    positions and degrees as one 5-D curve), and reduction of an elevated curve against
    `bezier.Curve.reduce_` (which takes degrees 2 to 4): both give the original back. (On a curve that is not exactly
    reducible the two differ by design: `reduce_` is least squares on the control points of
    the elevation matrix, ours the nearest piece in L2 over the parameter with the ends kept
    and the degrees within the rule.)"""
    bezier = pytest.importorskip("bezier")
    rng = np.random.default_rng(26 + degree)
    positions = rng.uniform(-4, 4, (degree + 1, 2))
    degrees = rng.uniform(0, 1, (degree + 1, 3))
    ours = ns.Bezier(positions, degrees)
    nodes = np.asfortranarray(np.hstack([positions, degrees]).T)
    theirs = bezier.Curve(nodes, degree=degree).elevate()
    up = ours.transform(elevate=1)
    np.testing.assert_allclose(np.hstack([up.positions, up.membership_degrees]), theirs.nodes.T, rtol=0, atol=1e-14)
    back = up.transform(reduce=1, tolerance=1e-10)
    # The Gram system's condition grows with the degree: 5.7e-12 at degree 9 to 8.
    np.testing.assert_allclose(np.hstack([back.positions, back.membership_degrees]), nodes.T, rtol=0, atol=1e-12 * 2**degree)
    if degree + 1 <= 4:
        np.testing.assert_allclose(theirs.reduce_().nodes, nodes, rtol=0, atol=1e-12)
