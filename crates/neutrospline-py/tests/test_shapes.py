"""The class tree: one base `Shape` with the shared methods, `Curve` and `Surface` extending it,
surface kinds built as the curve kinds are, and the membership array's name
(`membership_degrees`; `degrees` a deprecated alias)."""

import pickle
import warnings

import numpy as np
import pytest

import neutrospline as ns

SHARED = [
    "membership",
    "name",
    "description",
    "degrees",
    "save",
    "to_svg",
    "save_figure",
    "_repr_svg_",
    "__eq__",
    "__reduce__",
]

GRID = [[[0.0, 0.0, 0.0], [0.0, 2.0, 1.0]], [[3.0, 0.0, 0.5], [3.0, 2.0, 2.0]]]
GRID_DEGREES = [[[1.0, 0.0, 0.0], [0.5, 0.5, 0.0]], [[0.0, 0.0, 1.0], [0.2, 0.3, 0.4]]]
WEIGHTS = [[1.0, 2.0], [3.0, 0.5]]


def bilinear_rational(u, v, weights):
    """S(u, v) of a 2 x 2 grid of degree (1, 1), written out: basis (1 - u, u) x (1 - v, v),
    weighted and divided by the weighted basis sum; the degrees blend the same way."""
    rows = np.concatenate([np.array(GRID), np.array(GRID_DEGREES)], axis=2)
    basis_u, basis_v = [1.0 - u, u], [1.0 - v, v]
    top = np.zeros(6)
    bottom = 0.0
    for i in range(2):
        for j in range(2):
            b = basis_u[i] * basis_v[j] * weights[i][j]
            top += b * rows[i, j]
            bottom += b
    return top / bottom


def shapes(root):
    return [
        ns.example1(),
        ns.example1().insert_knot(0.5),
        ns.load(root / "examples" / "nurbs-circle.toml"),
        ns.load(root / "examples" / "surface.toml"),
        ns.BSplineSurface(GRID, GRID_DEGREES, degree=1),
        ns.NurbsSurface(GRID, GRID_DEGREES, WEIGHTS, degree=1),
    ]


def test_the_shared_methods_have_one_body_in_the_base_class(root):
    for name in SHARED:
        assert name in vars(ns.Shape), name
        for cls in [ns.Curve, ns.Bezier, ns.BSpline, ns.Nurbs, ns.Surface, ns.BezierSurface]:
            assert name not in vars(cls), f"{cls.__name__}.{name}"
    for obj in shapes(root):
        assert isinstance(obj, ns.Shape)
        assert ns.Shape.to_svg(obj) == obj.to_svg()
    assert issubclass(ns.Curve, ns.Shape) and issubclass(ns.Surface, ns.Shape)
    assert not issubclass(ns.Surface, ns.Curve) and not issubclass(ns.Curve, ns.Surface)


def test_surface_kinds_are_subclasses_built_like_the_curve_kinds(root):
    u = np.array([0.0, 0.25, 0.5, 0.9, 1.0])
    v = np.array([0.0, 0.6, 0.5, 0.1, 1.0])
    bezier = ns.BezierSurface(GRID, GRID_DEGREES, name="patch", description="two by two")
    assert type(bezier) is ns.BezierSurface and isinstance(bezier, ns.Surface)
    assert bezier.kind == "bezier-surface" and bezier.name == "patch" and bezier.description == "two by two"
    spline = ns.BSplineSurface(GRID, GRID_DEGREES, degree=(1, 1))
    assert type(spline) is ns.BSplineSurface and spline.knots_u.tolist() == [0.0, 0.0, 1.0, 1.0]
    rational = ns.NurbsSurface(GRID, GRID_DEGREES, WEIGHTS, degree=1)
    assert type(rational) is ns.NurbsSurface
    ones = [[1.0, 1.0], [1.0, 1.0]]
    for k in range(len(u)):
        plain = bilinear_rational(u[k], v[k], ones)
        np.testing.assert_allclose(bezier(u[k], v[k]), plain, rtol=0, atol=1e-15)
        np.testing.assert_allclose(spline(u[k], v[k]), plain, rtol=0, atol=1e-15)
        np.testing.assert_allclose(rational(u[k], v[k]), bilinear_rational(u[k], v[k], WEIGHTS), rtol=0, atol=1e-15)
    # The factories are aliases: the same class and the same surface.
    assert type(ns.Surface.bezier(GRID, GRID_DEGREES)) is ns.BezierSurface
    assert ns.Surface.bezier(GRID, GRID_DEGREES, name="patch", description="two by two") == bezier
    assert ns.Surface.bspline(GRID, GRID_DEGREES, 1) == spline
    assert ns.Surface.nurbs(GRID, GRID_DEGREES, WEIGHTS, degree=1) == rational
    # Loading and unpickling give the kind's class.
    loaded = ns.load(root / "examples" / "surface.toml")
    assert type(loaded) is ns.BezierSurface
    assert type(pickle.loads(pickle.dumps(rational))) is ns.NurbsSurface
    with pytest.raises(ns.ModelError, match="^weights: expected an array of shape \\(2, 2\\)"):
        ns.NurbsSurface(GRID, GRID_DEGREES, [1.0, 2.0], degree=1)


def test_membership_degrees_and_the_deprecated_alias(root):
    curve = ns.example1()
    want = [[0.3, 0.6, 0.1], [0.8, 0.1, 0.1], [0.7, 0.1, 0.2], [0.2, 0.4, 0.4]]
    # The truth, indeterminacy, falsity of examples/example1.toml, written out.
    np.testing.assert_array_equal(curve.membership_degrees, want)
    assert curve.degree == 3
    surface = ns.BezierSurface(GRID, GRID_DEGREES)
    np.testing.assert_array_equal(surface.membership_degrees, GRID_DEGREES)
    for obj in [curve, curve.derivative(), surface, ns.load(root / "examples" / "nurbs-circle.toml")]:
        with pytest.warns(DeprecationWarning, match="use `membership_degrees`") as caught:
            old = obj.degrees
        assert len(caught) == 1
        np.testing.assert_array_equal(old, obj.membership_degrees)
        assert old.shape == obj.membership_degrees.shape
    # The new name does not warn.
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        curve.membership_degrees
        surface.membership_degrees
