"""Arrays of every layout numpy makes (issue 22): every function that takes an array gives,
for an unaligned, byte-swapped, strided, negatively strided, read-only, Fortran-ordered,
float16/32/64, integer, 0-d or empty input, or a Python list, exactly the answer it gives for a
fresh aligned C-contiguous float64 copy of that input (the bytes of every result compared), or
the same ModelError. Inputs that are not real numbers (None, complex, strings, booleans,
integers a float64 cannot hold) raise ModelError naming the argument and the element; an
`out=` array that cannot be written in place raises ModelError naming `out` and is left
untouched."""

import struct

import numpy as np
import pytest

import neutrospline as ns

# ---- the layouts, each keeping the values of its input ----


def fresh(a):
    """The reference: a fresh aligned C-contiguous float64 copy."""
    copy = np.array(a, dtype=np.float64, order="C", copy=True)
    assert copy.flags.aligned and copy.flags.c_contiguous
    return copy


def unaligned(a):
    """The values at byte offset 1 of a uint8 buffer (what a network frame gives)."""
    a = np.asarray(a)
    buffer = np.zeros(a.nbytes + 1, dtype=np.uint8)
    view = np.ndarray(a.shape, dtype=a.dtype, buffer=buffer, offset=1)
    view[...] = a
    assert a.size == 0 or a.dtype.itemsize == 1 or not view.flags.aligned
    return view


def unaligned_readonly(a):
    """Read-only and unaligned, as numpy.frombuffer over received bytes gives."""
    a = np.ascontiguousarray(a)
    view = np.frombuffer(b"\0" + a.tobytes(), dtype=a.dtype, offset=1).reshape(a.shape)
    assert not view.flags.writeable
    return view


def byteswapped(a):
    a = np.asarray(a)
    swapped = a.astype(a.dtype.newbyteorder(">" if np.little_endian else "<"))
    assert not swapped.dtype.isnative
    return swapped


def unaligned_byteswapped(a):
    return unaligned(byteswapped(a))


def strided(a):
    """Every axis with stride 2 (a[::2] of a larger array)."""
    a = np.asarray(a)
    if a.ndim == 0:
        return a.copy()
    big = np.zeros(tuple(2 * s for s in a.shape), dtype=a.dtype)
    view = big[(slice(None, None, 2),) * a.ndim]
    view[...] = a
    assert a.size <= 1 or not view.flags.c_contiguous
    return view


def reversed_strides(a):
    """Negative strides on every axis."""
    a = np.asarray(a)
    if a.ndim == 0:
        return a.copy()
    axes = tuple(range(a.ndim))
    return np.flip(np.flip(a, axes).copy(), axes)


def readonly(a):
    copy = np.array(a, copy=True)
    copy.flags.writeable = False
    return copy


def fortran(a):
    return np.asfortranarray(a)


def as_list(a):
    return np.asarray(a).tolist()


def as_tuple(a):
    a = np.asarray(a)
    return tuple(as_tuple(x) for x in a) if a.ndim else a.item()


def masked_unmasked(a):
    """A numpy masked array with no element masked."""
    return np.ma.masked_array(np.array(a, copy=True), mask=False)


LAYOUTS = {
    "unaligned": unaligned,
    "unaligned-readonly": unaligned_readonly,
    "byteswapped": byteswapped,
    "unaligned-byteswapped": unaligned_byteswapped,
    "strided": strided,
    "reversed": reversed_strides,
    "readonly": readonly,
    "fortran": fortran,
    "list": as_list,
    "tuple": as_tuple,
    "masked-array": masked_unmasked,
}

DTYPES = [
    np.float16,
    np.float32,
    np.float64,
    np.longdouble,
    np.int8,
    np.int32,
    np.int64,
    np.uint8,
    np.uint64,
    ">f4",
    ">i8",
]


# ---- comparing results bit for bit ----


def canonical(result):
    """A value equal for two results exactly when they are bit-identical."""
    if isinstance(result, np.ndarray):
        return ("array", result.dtype.str, result.shape, result.tobytes())
    if isinstance(result, float):
        return ("float", struct.pack("<d", result))
    if isinstance(result, (tuple, list)):
        return ("seq", tuple(canonical(r) for r in result))
    if isinstance(result, dict):
        return ("dict", tuple(sorted((k, canonical(v)) for k, v in result.items())))
    if isinstance(result, ns.Curve):
        t = np.linspace(*result.domain, 17)
        parts = [result.positions, result.membership_degrees, result.weights, result.knots, result(t)]
        return ("curve", type(result).__name__, canonical(parts))
    if isinstance(result, ns.Surface):
        (u0, u1), (v0, v1) = result.domain
        u, v = np.meshgrid(np.linspace(u0, u1, 5), np.linspace(v0, v1, 4))
        parts = [result.positions, result.membership_degrees, result.weights, result.knots_u, result.knots_v]
        return ("surface", canonical(parts + [result(u, v)]))
    return ("other", repr(result))


def outcome(call, x):
    try:
        return ("ok", canonical(call(x)))
    except ns.ModelError as error:
        return ("ModelError", str(error))


def assert_same_as_fresh_copy(call, x, must_succeed):
    want = outcome(call, fresh(x))
    if must_succeed:
        assert want[0] == "ok", want
    assert outcome(call, x) == want


# ---- the models ----

BEZIER = ns.example1()
BSPLINE_POSITIONS = np.array(
    [[0.0, 0.0, 0.0], [1.0, 2.0, 0.5], [3.0, 2.0, 1.0], [4.0, 0.0, 1.5], [5.0, 1.0, 2.0]]
)
BSPLINE_DEGREES = np.array(
    [[0.2, 0.3, 0.1], [0.9, 0.1, 0.0], [0.5, 0.5, 0.5], [0.25, 0.0, 0.75], [1.0, 0.0, 0.0]]
)
BSPLINE_KNOTS = np.array([0.0, 0.0, 0.0, 0.0, 0.375, 1.0, 1.0, 1.0, 1.0])
BSPLINE = ns.BSpline(BSPLINE_POSITIONS, BSPLINE_DEGREES, degree=3, knots=BSPLINE_KNOTS)
NURBS_POSITIONS = np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
NURBS_DEGREES = np.array([[1.0, 0.0, 0.0], [0.5, 0.25, 0.25], [0.0, 0.0, 1.0]])
NURBS_WEIGHTS = np.array([1.0, 2.0**-0.5, 1.0])
NURBS = ns.Nurbs(NURBS_POSITIONS, NURBS_DEGREES, NURBS_WEIGHTS, degree=2)
CURVES = {"bezier-2d": BEZIER, "bspline-3d": BSPLINE, "nurbs-2d": NURBS}

GRID = np.array(
    [
        [[0.0, 0.0, 0.0], [0.0, 1.0, 0.5], [0.0, 2.0, 0.0]],
        [[1.0, 0.0, 0.5], [1.0, 1.0, 2.0], [1.0, 2.0, 0.5]],
        [[2.0, 0.0, 0.0], [2.0, 1.0, 0.5], [2.0, 2.0, 0.0]],
    ]
)
GRID_DEGREES = np.array(
    [
        [[1.0, 0.0, 0.0], [0.75, 0.25, 0.0], [0.5, 0.5, 0.0]],
        [[0.5, 0.0, 0.5], [0.25, 0.25, 0.25], [0.0, 1.0, 0.0]],
        [[0.0, 0.0, 1.0], [0.0, 0.25, 0.75], [0.125, 0.5, 0.375]],
    ]
)
GRID_WEIGHTS = np.array([[1.0, 0.5, 1.0], [2.0, 1.0, 0.75], [1.0, 0.5, 1.0]])
KNOTS_UV = np.array([0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
SURFACE = ns.Surface.nurbs(GRID, GRID_DEGREES, GRID_WEIGHTS, degree=2)

T = np.array([0.0, 0.125, 0.3, 0.5, 0.625, 0.875, 1.0])
U = np.array([[0.0, 0.25, 0.5], [0.75, 1.0, 0.3]])
V = np.array([[0.1, 0.0, 1.0], [0.5, 0.625, 0.9]])
DATA_S = np.linspace(0.0, 1.0, 12)
DATA = np.column_stack([4.0 * DATA_S, np.sin(3.0 * DATA_S)])
DATA_DEGREES = np.column_stack([1.0 - DATA_S, 0.5 * DATA_S, 0.25 * DATA_S])
AXIS_M = [(1.0, (0.5, 0.5, 0.5)), (2.0, (0.75, 0.25, 0.5))]
AXIS_N = [(3.0, (0.5, 0.5, 0.5)), (4.0, (1.0, 0.5, 0.25))]


# ---- every array argument: (name, call with the argument x, the argument's base value) ----


def parameter_cases():
    for name, curve in CURVES.items():
        yield f"{name}.evaluate(t)", curve.evaluate, T
        yield f"{name}(t)", curve, T
        yield f"{name}.derivative()(t)", curve.derivative(), T
        yield f"{name}.curvature(t)", curve.curvature, T
    yield "surface.evaluate(u, v=fresh)", lambda u: SURFACE.evaluate(u, V), U
    yield "surface.evaluate(u=fresh, v)", lambda v: SURFACE.evaluate(U, v), V
    yield "surface(u, v) both", lambda uv: SURFACE(uv[0], uv[1]), np.stack([U, V])
    yield "surface.normal(u, v=fresh)", lambda u: SURFACE.normal(u, V), U
    yield "surface.normal(u=fresh, v)", lambda v: SURFACE.normal(U, v), V


def other_cases():
    yield "bezier-2d.nearest(points)", BEZIER.nearest, np.array([[4.625, 4.0], [1.0, 2.5], [8.0, 5.0]])
    yield "bezier-2d.nearest(point)", BEZIER.nearest, np.array([4.5, 4.0])
    yield "bspline-3d.nearest(points)", BSPLINE.nearest, np.array([[1.0, 1.0, 1.0], [4.0, 0.5, 2.0]])
    yield "surface.nearest(points)", SURFACE.nearest, np.array([[0.5, 0.5, 2.0], [1.5, 1.0, -1.0]])
    yield "Bezier(positions)", lambda p: ns.Bezier(p, BEZIER.membership_degrees), BEZIER.positions
    yield "Bezier(degrees)", lambda d: ns.Bezier(BEZIER.positions, d), BEZIER.membership_degrees
    yield "Bezier.from_nodes(nodes)", lambda n: ns.Bezier.from_nodes(n, BEZIER.membership_degrees), BEZIER.positions.T
    yield "Bezier.from_nodes(degrees)", lambda d: ns.Bezier.from_nodes(BEZIER.positions.T, d), BEZIER.membership_degrees
    yield "BSpline(positions)", lambda p: ns.BSpline(p, BSPLINE_DEGREES, 3, BSPLINE_KNOTS), BSPLINE_POSITIONS
    yield "BSpline(degrees)", lambda d: ns.BSpline(BSPLINE_POSITIONS, d, 3, BSPLINE_KNOTS), BSPLINE_DEGREES
    yield "BSpline(knots)", lambda k: ns.BSpline(BSPLINE_POSITIONS, BSPLINE_DEGREES, 3, k), BSPLINE_KNOTS
    yield "Nurbs(positions)", lambda p: ns.Nurbs(p, NURBS_DEGREES, NURBS_WEIGHTS, 2), NURBS_POSITIONS
    yield "Nurbs(degrees)", lambda d: ns.Nurbs(NURBS_POSITIONS, d, NURBS_WEIGHTS, 2), NURBS_DEGREES
    yield "Nurbs(weights)", lambda w: ns.Nurbs(NURBS_POSITIONS, NURBS_DEGREES, w, 2), NURBS_WEIGHTS
    yield "Nurbs(knots)", lambda k: ns.Nurbs(NURBS_POSITIONS, NURBS_DEGREES, NURBS_WEIGHTS, 2, k), np.array([0.0, 0, 0, 1, 1, 1])
    yield "Surface.bezier(positions)", lambda p: ns.Surface.bezier(p, GRID_DEGREES), GRID
    yield "Surface.bezier(degrees)", lambda d: ns.Surface.bezier(GRID, d), GRID_DEGREES
    yield "Surface.nurbs(weights)", lambda w: ns.Surface.nurbs(GRID, GRID_DEGREES, w, 2), GRID_WEIGHTS
    yield "Surface.bspline(knots_u)", lambda k: ns.Surface.bspline(GRID, GRID_DEGREES, 2, k, KNOTS_UV), KNOTS_UV
    yield "Surface.bspline(knots_v)", lambda k: ns.Surface.bspline(GRID, GRID_DEGREES, 2, KNOTS_UV, k), KNOTS_UV
    yield "score(degrees)", ns.score, BSPLINE_DEGREES
    yield "accuracy(degrees)", ns.accuracy, GRID_DEGREES
    yield "certainty(degree)", ns.certainty, BSPLINE_DEGREES[1]
    yield "check_relation(positions)", lambda p: ns.check_relation(p, [[0.5, 0.5, 0.5]], AXIS_M, AXIS_N), np.array([[1.0, 3.0]])
    yield "check_relation(degrees)", lambda d: ns.check_relation([[2.0, 4.0]], d, AXIS_M, AXIS_N), np.array([[0.75, 0.25, 0.25]])
    yield "largest_relation(pairs)", lambda p: ns.largest_relation(AXIS_M, AXIS_N, p), np.array([[2.0, 4.0], [1.0, 3.0]])
    yield "fit(data)", lambda p: ns.fit(p, DATA_DEGREES, control_points=6), DATA
    yield "fit(degrees)", lambda d: ns.fit(DATA, d, control_points=6), DATA_DEGREES
    yield "fit(parameters)", lambda s: ns.fit(DATA, DATA_DEGREES, parameters=s, control_points=6), DATA_S
    yield "fit(weights)", lambda w: ns.fit(DATA, DATA_DEGREES, weights=w, control_points=6), 1.0 + DATA_S


def load_case(root):
    knots = np.array([0, 0, 0, 0, 0.2, 0.5, 0.7, 1, 1, 1, 1])
    path = root / "examples" / "bspline.csv"
    return lambda k: ns.load(path, kind="bspline", degree=3, knots=k), knots


PARAMETER_CASES = {name: (call, base) for name, call, base in parameter_cases()}
ALL_CASES = {**PARAMETER_CASES, **{name: (call, base) for name, call, base in other_cases()}}


@pytest.mark.parametrize("layout", LAYOUTS)
@pytest.mark.parametrize("case", ALL_CASES)
def test_every_layout_gives_the_fresh_copys_answer(case, layout):
    call, base = ALL_CASES[case]
    x = LAYOUTS[layout](base)
    assert_same_as_fresh_copy(call, x, must_succeed=True)
    # Each layout keeps the values, so the answer is also the original's.
    assert outcome(call, x) == outcome(call, base.copy())


@pytest.mark.parametrize("dtype", DTYPES, ids=str)
@pytest.mark.parametrize("case", ALL_CASES)
def test_every_dtype_gives_the_fresh_copys_answer(case, dtype):
    call, base = ALL_CASES[case]
    # Unsigned dtypes of magnitudes (numpy's cast of a negative float to one is undefined).
    x = (np.abs(base) if np.dtype(dtype).kind == "u" else base).astype(dtype)
    # Integer dtypes truncate the base, which may make a model invalid: then both raise the
    # same ModelError.
    assert_same_as_fresh_copy(call, x, must_succeed=np.dtype(dtype).kind == "f")
    assert_same_as_fresh_copy(call, unaligned(x), must_succeed=np.dtype(dtype).kind == "f")


@pytest.mark.parametrize("layout", ["fresh", *LAYOUTS])
def test_load_knots_in_every_layout(root, layout):
    call, base = load_case(root)
    x = base.copy() if layout == "fresh" else LAYOUTS[layout](base)
    assert_same_as_fresh_copy(call, x, must_succeed=True)


def test_unaligned_parameters_give_every_row():
    """The issue's report: an unaligned t gave an empty (0, 5) array, without an error."""
    buffer = np.zeros(5 * 8 + 1, dtype=np.uint8)
    t = np.ndarray((5,), dtype=np.float64, buffer=buffer, offset=1)
    t[:] = [0.0, 0.25, 0.5, 0.75, 1.0]
    assert not t.flags.aligned
    got = BEZIER.evaluate(t)
    assert got.shape == (5, 5)
    # Example 1 at t = 0.5, by hand from Table 1 (the package's doctest value).
    assert got[2].round(12).tolist() == [4.625, 4.0, 0.625, 0.2, 0.175]
    assert got.tobytes() == BEZIER.evaluate(np.array([0.0, 0.25, 0.5, 0.75, 1.0])).tobytes()


ZERO_D = {
    "python-float": lambda v: float(v),
    "python-int": lambda v: int(v),
    "numpy-float64": lambda v: np.float64(v),
    "numpy-float32": lambda v: np.float32(v),
    "0-d": lambda v: np.array(v),
    "0-d-unaligned": unaligned,
    "0-d-byteswapped": lambda v: byteswapped(np.array(v)),
    "0-d-readonly": lambda v: readonly(np.array(v)),
    "0-d-int32": lambda v: np.array(v, dtype=np.int32),
}


CURVE_PARAMETER_CASES = [c for c in PARAMETER_CASES if not c.startswith("surface")]


@pytest.mark.parametrize("form", ZERO_D)
@pytest.mark.parametrize("case", CURVE_PARAMETER_CASES)
def test_zero_d_is_one_parameter(case, form):
    call, _ = PARAMETER_CASES[case]
    value = 1.0 if "int" in form else 0.5
    got = call(ZERO_D[form](np.array(value)))
    assert np.ndim(got) == (0 if "curvature" in case else 1)
    assert canonical(got) == canonical(call(np.float64(value)))
    # One parameter's row is the row of a one-parameter array.
    assert np.asarray(got).tobytes() == np.asarray(call(np.array([value]))).tobytes()


@pytest.mark.parametrize("form", ZERO_D)
def test_zero_d_surface_parameters(form):
    value = 1.0 if "int" in form else 0.5
    for evaluate in (SURFACE.evaluate, SURFACE.normal):
        got = evaluate(ZERO_D[form](np.array(value)), ZERO_D[form](np.array(value)))
        row = evaluate(np.array([value]), np.array([value]))
        assert got.shape == row.shape[1:] and got.tobytes() == row.tobytes()


@pytest.mark.parametrize("layout", ["fresh", *LAYOUTS])
@pytest.mark.parametrize("case", [*CURVE_PARAMETER_CASES, "surface"])
def test_empty_parameters_give_no_rows(case, layout):
    empty = np.empty(0)
    x = empty.copy() if layout == "fresh" else LAYOUTS[layout](empty)
    if case == "surface":
        assert SURFACE.evaluate(x, x).shape == (0, 6)
        assert SURFACE.normal(x, empty).shape == (0, 3)
        return
    call, _ = PARAMETER_CASES[case]
    got = np.asarray(call(x))
    assert got.shape == np.asarray(call(empty)).shape and got.shape[0] == 0


# ---- what is refused, naming the argument and the element ----

REFUSED = [
    ([0.0, 0.5, None, 1.0], r"^t\[2\] = None is not a number$"),
    (np.array([0.0, None], dtype=object), r"^t\[1\] = None is not a number$"),
    ([0.0, "0.5"], r"^t: expected numbers, got strings"),
    (np.array([0.0, "0.5"], dtype=object), r"^t\[1\] = '0.5' is a string, not a number$"),
    (np.array([0.5 + 0j]), r"^t: expected real numbers, got complex numbers"),
    (np.array([0.5, 1j], dtype=object), r"^t\[1\] = 1j is a complex number"),
    (np.array([True, False]), r"^t: expected numbers, got booleans"),
    (np.array([0.0, True], dtype=object), r"^t\[1\] = True is a boolean"),
    (np.array([0, 2**53 + 1], dtype=np.int64), r"^t\[1\] = 9007199254740993 \(int64\) is not exactly a float64"),
    ([0, 2**70 + 1], r"^t\[1\] = 1180591620717411303425 is an integer"),
    (np.array([0, np.int64(2**53 + 1)], dtype=object), r"^t\[1\] = np.int64\(9007199254740993\) is an integer a float64 cannot hold exactly"),
    ([0, 10**400], r"^t\[1\] = 1000000000000000000000.* is an integer too large for a float64$"),
    (np.zeros((2, 2)), r"^t: expected a number or a 1-D array of numbers, got a 2-D array"),
    ([[0.0], [0.5, 1.0]], r"^t: not an array of numbers"),
    (np.array(["2026-01-01"], dtype="datetime64[D]"), r"^t: expected numbers, got an array of dtype"),
    (np.ma.masked_array([0.0, 0.5, 1.0], mask=[False, True, False]), r"^t\[1\] is masked"),
    (object(), r"^t: expected numbers, got an array of dtype object|^t = <object"),
]


@pytest.mark.parametrize("bad, message", REFUSED, ids=range(len(REFUSED)))
@pytest.mark.parametrize("curve", CURVES)
def test_refused_parameters_are_named(curve, bad, message):
    with pytest.raises(ns.ModelError, match=message):
        CURVES[curve].evaluate(bad)


def test_refused_arrays_name_their_argument():
    with pytest.raises(ns.ModelError, match=r"^positions\[1, 0\] = None is not a number$"):
        ns.Bezier([[0.0, 0.0], [None, 1.0]], [[1, 0, 0]] * 2)
    with pytest.raises(ns.ModelError, match=r"^degrees\[0, 2\] = None is not a number$"):
        ns.Bezier([[0.0, 0.0], [1.0, 1.0]], [[1, 0, None], [1, 0, 0]])
    with pytest.raises(ns.ModelError, match=r"^weights\[1\] = None is not a number$"):
        ns.Nurbs(NURBS_POSITIONS, NURBS_DEGREES, [1.0, None, 1.0], 2)
    with pytest.raises(ns.ModelError, match=r"^knots: expected real numbers, got complex"):
        ns.BSpline(BSPLINE_POSITIONS, BSPLINE_DEGREES, 3, BSPLINE_KNOTS.astype(complex))
    with pytest.raises(ns.ModelError, match=r"^u\[0, 1\] = None is not a number$"):
        SURFACE.evaluate([[0.0, None]], [[0.0, 0.5]])
    with pytest.raises(ns.ModelError, match=r"^v: expected numbers, got strings"):
        SURFACE.normal(0.5, "0.5")
    with pytest.raises(ns.ModelError, match=r"^points\[0, 1\] = None is not a number$"):
        BEZIER.nearest([[1.0, None]])
    with pytest.raises(ns.ModelError, match=r"^degrees\[1\] = None is not a number$"):
        ns.score([0.5, None, 0.5])
    with pytest.raises(ns.ModelError, match=r"^parameters\[0\] = None is not a number$"):
        ns.fit(DATA, DATA_DEGREES, parameters=[None] * 12, control_points=6)
    with pytest.raises(ns.ModelError, match=r"^pairs\[1, 1\] = None is not a number$"):
        ns.largest_relation(AXIS_M, AXIS_N, [(1.0, 3.0), (2.0, None)])
    with pytest.raises(ns.ModelError, match=r"^pairs: expected an array of shape \(k, 2\)"):
        ns.largest_relation(AXIS_M, AXIS_N, [1.0, 3.0])
    with pytest.raises(ns.ModelError, match=r"^nodes: expected an array of shape \(dimension, n\)"):
        ns.Bezier.from_nodes([0.0, 1.0], [[1, 0, 0]] * 2)


# ---- out= ----


def out_layouts(shape):
    def strided_out():
        return np.zeros(shape[:-1] + (2 * shape[-1],))[..., ::2]

    return {
        "fortran": lambda: np.zeros(shape, order="F"),
        "c": lambda: np.zeros(shape),
        "strided": strided_out,
        "reversed": lambda: np.zeros(shape)[::-1],
    }


def bad_outs(shape):
    def unaligned_out():
        buffer = np.zeros(int(np.prod(shape)) * 8 + 1, dtype=np.uint8)
        return np.ndarray(shape, dtype=np.float64, buffer=buffer, offset=1)

    def readonly_out():
        out = np.zeros(shape)
        out.flags.writeable = False
        return out

    return {
        "unaligned": (unaligned_out, r"^out: cannot write into the array in place: its memory is not aligned"),
        "readonly": (readonly_out, r"^out: cannot write into the array"),
        "byteswapped": (lambda: np.zeros(shape, dtype=">f8"), r"^out: expected a float64 array"),
        "float32": (lambda: np.zeros(shape, dtype=np.float32), r"^out: expected a float64 array"),
        "wrong-shape": (lambda: np.zeros(shape[:-1] + (shape[-1] + 1,)), r"^out: expected shape"),
        "list": (lambda: np.zeros(shape).tolist(), r"^out: expected a float64 array"),
    }


def out_calls():
    for name, curve in CURVES.items():
        columns = curve.dimension + 3
        yield f"{name}.evaluate", (T.size, columns), lambda out, c=curve: c.evaluate(T, out=out)
        yield f"{name}.sample", (9, columns), lambda out, c=curve: c.sample(9, out=out)
        yield f"{name}.derivative", (T.size, columns), lambda out, c=curve: c.derivative()(T, out=out)
    yield "surface.evaluate", U.shape + (6,), lambda out: SURFACE.evaluate(U, V, out=out)


OUT_CALLS = {name: (shape, call) for name, shape, call in out_calls()}


@pytest.mark.parametrize("call", OUT_CALLS)
def test_out_of_every_writable_layout_is_written_in_place(call):
    shape, evaluate = OUT_CALLS[call]
    want = evaluate(None)
    for layout, make in out_layouts(shape).items():
        out = make()
        assert evaluate(out) is out, layout
        assert out.tobytes() == want.tobytes(), layout


@pytest.mark.parametrize("call", OUT_CALLS)
def test_out_that_cannot_be_written_in_place_is_refused(call):
    shape, evaluate = OUT_CALLS[call]
    for bad, (make, message) in bad_outs(shape).items():
        out = make()
        before = np.array(out, copy=True)
        with pytest.raises(ns.ModelError, match=message):
            evaluate(out)
        assert np.array_equal(np.asarray(out), before), bad


@pytest.mark.parametrize("curve", CURVES)
def test_out_of_a_scalar_parameter_gets_its_row(curve):
    """A scalar t gives one row: out of that shape gets it (it was ignored before)."""
    curve = CURVES[curve]
    columns = curve.dimension + 3
    want = curve(0.625)
    for layout, make in out_layouts((columns,)).items():
        out = make()
        assert curve(0.625, out=out) is out, layout
        assert out.tobytes() == want.tobytes(), layout
    for bad, (make, message) in bad_outs((columns,)).items():
        out = make()
        before = np.array(out, copy=True)
        with pytest.raises(ns.ModelError, match=message):
            curve.evaluate(np.float64(0.625), out=out)
        assert np.array_equal(np.asarray(out), before), bad


def test_fit_names_its_data_argument():
    with pytest.raises(ns.ModelError, match=r"^data\[2, 1\] = None is not a number$"):
        ns.fit([[0.0, 0.0], [1.0, 1.0], [2.0, None], [3.0, 1.0]], [[1, 0, 0]] * 4)
    with pytest.raises(ns.ModelError, match=r"^data: expected an array of shape \(n, 2\) or \(n, 3\)"):
        ns.fit(np.zeros((4, 4)), [[1, 0, 0]] * 4)


def test_the_fast_path_does_not_copy():
    """An aligned C-contiguous float64 t is read in place: numpy allocates nothing while a
    million parameters are evaluated into out (a strided t, which is copied once, allocates
    its 8 MB: the measurement sees copies)."""
    import tracemalloc

    t = np.linspace(0.0, 1.0, 1_000_000)
    out = np.empty((t.size, 5), order="F")
    BEZIER.evaluate(t, out=out)

    def peak(call):
        tracemalloc.start()
        try:
            call()
            return tracemalloc.get_traced_memory()[1]
        finally:
            tracemalloc.stop()

    assert peak(lambda: BEZIER.evaluate(t, out=out)) < 100_000
    strided_t = np.repeat(t, 2)[::2]
    assert peak(lambda: BEZIER.evaluate(strided_t, out=out)) >= t.nbytes


def test_large_integers_a_float64_holds_are_read():
    """2^70 and 2^200 are float64 values: read exactly, like any other integer."""
    for big in (2**70, 2**200):
        want = BEZIER.nearest(np.array([[float(big), 0.0]]))
        assert canonical(BEZIER.nearest([[big, 0]])) == canonical(want)
