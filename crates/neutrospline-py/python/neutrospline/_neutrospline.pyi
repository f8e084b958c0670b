"""Type stubs of the extension module ``neutrospline._neutrospline``.

Every ``ArrayLike`` argument (parameters ``t``, ``u``, ``v``; ``positions``, ``degrees``,
``weights``, ``knots``, ``nodes``, query ``points``, fit data and ``parameters``) takes any numpy
array or nested sequence of real numbers in any layout numpy makes: aligned or unaligned,
native or byte-swapped, C- or Fortran-ordered or strided (negative strides too), read-only or
writeable, a masked array without masked elements; float16/32/64 or long double, signed or
unsigned integers. The answer is exactly the one for a fresh aligned float64 copy (an aligned,
C-contiguous, native float64 array is read without a copy). A 0-d array is one parameter, an
empty array zero rows. ``None``, booleans, complex numbers, strings, masked elements and values
a float64 cannot hold exactly (integers beyond 2**53, long doubles with more digits) raise
``ModelError`` naming the argument and the element, e.g. ``t[3] = None is not a number``.

An ``out`` array must be a float64 array of native byte order, of the result's shape, aligned
and writeable (C-, Fortran-ordered or strided); any other raises ``ModelError`` naming ``out``
and is left untouched.
"""

import os
from typing import (
    TYPE_CHECKING,
    Any,
    ClassVar,
    Dict,
    List,
    Literal,
    Mapping,
    Optional,
    Sequence,
    Tuple,
    Type,
    Union,
    overload,
)

import numpy as np
import numpy.typing as npt
from typing_extensions import deprecated

# Any array or nested sequence of real numbers, of any layout and real dtype (see above).
ArrayLike = npt.ArrayLike
FloatArray = npt.NDArray[np.float64]
PathLike = Union[str, "os.PathLike[str]"]
# A membership family: "neutrosophic", "intuitionistic", "fuzzy", "pythagorean", "fermatean",
# "q-rung:Q", "picture", "spherical", "t-spherical:N" (Q, N integers >= 1), or one of the
# families of two lanes "interval-neutrosophic", "interval-intuitionistic", "interval-type2",
# "bipolar-neutrosophic", whose degree arrays have one column per channel (`Shape.channels`).
Membership = str
ViewName = Literal[
    "all", "controls", "truth", "indeterminacy", "falsity", "plane", "score", "derived", "data", "band"
]
Triple = Tuple[float, float, float]
if TYPE_CHECKING:
    import pandas
    from matplotlib.axes import Axes
# A table's columns read as ours: `{"truth": "mu"}` or the command line's `"truth=mu"`.
ColumnMap = Union[str, Mapping[str, str]]
ColumnList = Union[str, Sequence[str]]
CurveView = Literal["plane", "controls", "truth", "indeterminacy", "falsity", "all", "score"]
SurfaceView = Literal["controls", "truth", "indeterminacy", "falsity", "score", "all", "plane"]

instruction_set: str
# The package's version, the workspace's (Cargo.toml).
__version__: str

def _run_cli(argv: Sequence[str]) -> int:
    """Runs the ``neutrospline`` command line (``argv[0]`` is the program name) and returns its
    exit status; the body of the wheel's ``neutrospline`` console script."""

class ModelError(ValueError): ...

class Shape:
    """The base of every curve and surface: the model and the methods shared by all kinds."""

    @property
    def membership(self) -> Membership: ...
    @property
    def channels(self) -> List[str]:
        """The names of the degree columns of ``evaluate``, ``membership_degrees`` and
        ``bounding_box``: truth, indeterminacy, falsity, or the channels of an interval-valued
        or bipolar family."""
    @property
    def name(self) -> Optional[str]: ...
    @property
    def description(self) -> Optional[str]: ...
    @property
    @deprecated("use membership_degrees")
    def degrees(self) -> FloatArray:
        """Deprecated alias of ``membership_degrees`` (warns with a ``DeprecationWarning``)."""
        ...
    def save(self, path: PathLike) -> None: ...
    def to_svg(
        self,
        view: Optional[ViewName] = None,
        *,
        width: int = 1600,
        height: int = 1200,
        size: Optional[str] = None,
        dpi: Optional[float] = None,
        style: Literal["default", "paper"] = "default",
        no_title: bool = False,
        no_caption: bool = False,
        title: Optional[str] = None,
        caption: Optional[str] = None,
        azimuth: float = -55.0,
        elevation: float = 25.0,
        samples: Optional[int] = None,
        alpha: Sequence[float] = (0.0, 0.5, 1.0),
        color_by: Literal["truth", "indeterminacy", "falsity"] = "truth",
    ) -> str: ...
    def save_figure(
        self,
        path: PathLike,
        view: Optional[ViewName] = None,
        *,
        width: int = 1600,
        height: int = 1200,
        size: Optional[str] = None,
        dpi: Optional[float] = None,
        style: Literal["default", "paper"] = "default",
        no_title: bool = False,
        no_caption: bool = False,
        title: Optional[str] = None,
        caption: Optional[str] = None,
        azimuth: float = -55.0,
        elevation: float = 25.0,
        samples: Optional[int] = None,
        alpha: Sequence[float] = (0.0, 0.5, 1.0),
        color_by: Literal["truth", "indeterminacy", "falsity"] = "truth",
    ) -> None: ...
    def transform(
        self,
        *,
        elevate: Optional[int] = None,
        reduce: Optional[int] = None,
        insert_knot: Optional[Sequence[float]] = None,
        refine: Optional[int] = None,
        remove_knot: Optional[float] = None,
        times: Optional[int] = None,
        tolerance: Optional[float] = None,
        split: Optional[float] = None,
        subsegment: Optional[str] = None,
        reverse: bool = False,
        to_bezier: bool = False,
        reparametrize: Optional[str] = None,
        direction: Optional[Literal["u", "v"]] = None,
    ) -> Any:
        """One operation of ``neutrospline transform``: the new shape, or a tuple of pieces."""
        ...
    def _repr_svg_(self) -> Optional[str]: ...
    def _repr_png_(self) -> Optional[bytes]: ...
    def __eq__(self, value: object, /) -> bool: ...
    def __reduce__(self) -> Tuple[Any, Tuple[str, int]]: ...

class Curve(Shape):
    def evaluate(self, t: ArrayLike, out: Optional[FloatArray] = None) -> FloatArray: ...
    def __call__(self, t: ArrayLike, out: Optional[FloatArray] = None) -> FloatArray: ...
    @overload
    def sample(
        self, count: int, out: Optional[FloatArray] = None, *, parameters: Literal[False] = False
    ) -> FloatArray: ...
    @overload
    def sample(
        self, count: int, out: Optional[FloatArray] = None, *, parameters: Literal[True]
    ) -> Tuple[FloatArray, FloatArray]: ...
    def to_dataframe(self, t: Union[int, ArrayLike] = 101, *, scores: bool = False) -> "pandas.DataFrame": ...
    def plot(
        self,
        ax: Optional["Axes"] = None,
        view: CurveView = "plane",
        *,
        samples: int = 201,
        legend: bool = True,
        labels: bool = True,
    ) -> Any: ...
    def derivative(self, order: int = 1) -> "Curve": ...
    def split(self, t: float) -> Tuple["Curve", "Curve"]: ...
    def elevate(self, times: int = 1) -> "Curve": ...
    def insert_knot(self, u: float, times: int = 1) -> "Curve": ...
    def bounding_box(self) -> FloatArray: ...
    def length(self, accuracy: float = 1e-12) -> float: ...
    def arc_length(self, t0: float, t1: float, accuracy: float = 1e-12) -> float: ...
    def parameter_at_length(self, s: float, accuracy: float = 1e-12) -> float: ...
    def arc_length_parameters(self, count: int, accuracy: float = 1e-12) -> FloatArray: ...
    def curvature(self, t: ArrayLike) -> Union[float, FloatArray]: ...
    def nearest(
        self, points: ArrayLike
    ) -> Tuple[Union[float, FloatArray], Union[float, FloatArray], FloatArray]: ...
    @overload
    def intersections(
        self, other: Optional["Curve"] = None, *, contacts: Literal[False] = False
    ) -> FloatArray: ...
    @overload
    def intersections(
        self, other: Optional["Curve"] = None, *, contacts: Literal[True]
    ) -> Tuple[FloatArray, List[str]]: ...
    @property
    def domain(self) -> Tuple[float, float]: ...
    @property
    def kind(self) -> Literal["bezier", "bspline", "nurbs"]: ...
    @property
    def degree(self) -> int: ...
    @property
    def dimension(self) -> int: ...
    @property
    def order(self) -> int: ...
    @property
    def point_names(self) -> list[Optional[str]]: ...
    @property
    def positions(self) -> FloatArray: ...
    @property
    def membership_degrees(self) -> FloatArray: ...
    @property
    def weights(self) -> Optional[FloatArray]: ...
    @property
    def knots(self) -> Optional[FloatArray]: ...
    @property
    def periodic_count(self) -> Optional[int]: ...
    def __len__(self) -> int: ...

class Bezier(Curve):
    def __init__(
        self,
        positions: ArrayLike,
        degrees: ArrayLike,
        membership: Membership = "neutrosophic",
        *,
        name: Optional[str] = None,
        description: Optional[str] = None,
        point_names: Optional[Sequence[Optional[str]]] = None,
    ) -> None: ...
    @staticmethod
    def from_nodes(
        nodes: ArrayLike, degrees: ArrayLike, membership: Membership = "neutrosophic"
    ) -> "Bezier": ...

class BSpline(Curve):
    def __init__(
        self,
        positions: ArrayLike,
        degrees: ArrayLike,
        degree: int = 3,
        knots: Optional[ArrayLike] = None,
        membership: Membership = "neutrosophic",
        *,
        periodic: bool = False,
        name: Optional[str] = None,
        description: Optional[str] = None,
        point_names: Optional[Sequence[Optional[str]]] = None,
    ) -> None: ...

class Nurbs(Curve):
    def __init__(
        self,
        positions: ArrayLike,
        degrees: ArrayLike,
        weights: ArrayLike,
        degree: int = 3,
        knots: Optional[ArrayLike] = None,
        membership: Membership = "neutrosophic",
        *,
        periodic: bool = False,
        name: Optional[str] = None,
        description: Optional[str] = None,
        point_names: Optional[Sequence[Optional[str]]] = None,
    ) -> None: ...

class Surface(Shape):
    # The subclasses' constructors under their old names (`Surface.bezier(...)`).
    bezier: ClassVar[Type["BezierSurface"]]
    bspline: ClassVar[Type["BSplineSurface"]]
    nurbs: ClassVar[Type["NurbsSurface"]]
    def evaluate(
        self, u: ArrayLike, v: ArrayLike, out: Optional[FloatArray] = None
    ) -> FloatArray: ...
    def __call__(
        self, u: ArrayLike, v: ArrayLike, out: Optional[FloatArray] = None
    ) -> FloatArray: ...
    def normal(self, u: ArrayLike, v: ArrayLike) -> FloatArray: ...
    def to_dataframe(
        self, u: Union[int, ArrayLike] = 101, v: Union[None, int, ArrayLike] = None, *, scores: bool = False
    ) -> "pandas.DataFrame": ...
    def plot(
        self,
        ax: Any = None,
        view: SurfaceView = "truth",
        *,
        samples: int = 30,
        legend: bool = True,
        net: bool = True,
    ) -> Any: ...
    def nearest(
        self, points: ArrayLike
    ) -> Tuple[FloatArray, Union[float, FloatArray], FloatArray]: ...
    @property
    def domain(self) -> Tuple[Tuple[float, float], Tuple[float, float]]: ...
    @property
    def kind(self) -> Literal["bezier-surface", "bspline-surface", "nurbs-surface"]: ...
    @property
    def degree(self) -> Tuple[int, int]: ...
    @property
    def dimension(self) -> int: ...
    @property
    def positions(self) -> FloatArray: ...
    @property
    def membership_degrees(self) -> FloatArray: ...
    @property
    def weights(self) -> Optional[FloatArray]: ...
    @property
    def knots_u(self) -> FloatArray: ...
    @property
    def knots_v(self) -> FloatArray: ...
    def bounding_box(self) -> FloatArray: ...

class BezierSurface(Surface):
    def __init__(
        self,
        positions: ArrayLike,
        degrees: ArrayLike,
        membership: Membership = "neutrosophic",
        *,
        name: Optional[str] = None,
        description: Optional[str] = None,
    ) -> None: ...

class BSplineSurface(Surface):
    def __init__(
        self,
        positions: ArrayLike,
        degrees: ArrayLike,
        degree: Union[int, Tuple[int, int], None] = None,
        knots_u: Optional[ArrayLike] = None,
        knots_v: Optional[ArrayLike] = None,
        membership: Membership = "neutrosophic",
        *,
        name: Optional[str] = None,
        description: Optional[str] = None,
    ) -> None: ...

class NurbsSurface(Surface):
    def __init__(
        self,
        positions: ArrayLike,
        degrees: ArrayLike,
        weights: ArrayLike,
        degree: Union[int, Tuple[int, int], None] = None,
        knots_u: Optional[ArrayLike] = None,
        knots_v: Optional[ArrayLike] = None,
        membership: Membership = "neutrosophic",
        *,
        name: Optional[str] = None,
        description: Optional[str] = None,
    ) -> None: ...

Model = Union[Bezier, BSpline, Nurbs, BezierSurface, BSplineSurface, NurbsSurface]

KnotOption = Union[str, ArrayLike]

def load(
    path: Union[PathLike, "pandas.DataFrame"],
    *,
    kind: Optional[str] = None,
    degree: Optional[int] = None,
    knots: Optional[KnotOption] = None,
    membership: Optional[Membership] = None,
    rows: Optional[int] = None,
    cols: Optional[int] = None,
    degree_u: Optional[int] = None,
    degree_v: Optional[int] = None,
    knots_u: Optional[KnotOption] = None,
    knots_v: Optional[KnotOption] = None,
    periodic: Optional[bool] = None,
    periodic_u: Optional[bool] = None,
    periodic_v: Optional[bool] = None,
    truth: Optional[float] = None,
    indeterminacy: Optional[float] = None,
    falsity: Optional[float] = None,
    entities: Optional[str] = None,
    strict: Optional[bool] = None,
    sheet: Optional[str] = None,
    columns: Optional[ColumnMap] = None,
    ignore_columns: Optional[ColumnList] = None,
    ignore_unknown_columns: Optional[bool] = None,
    delimiter: Optional[str] = None,
    decimal_comma: Optional[bool] = None,
) -> Union[Model, Tuple[List[Union[Bezier, BSpline, Nurbs]], Dict[str, Any]]]: ...
def import_options() -> list[dict[str, Any]]: ...
def table_options() -> list[dict[str, Any]]: ...
def transform_options() -> list[dict[str, Any]]: ...
def inline(
    *,
    reset: bool = False,
    format: Optional[Literal["svg", "png", "both"]] = None,
    view: Optional[ViewName] = None,
    width: Optional[int] = None,
    height: Optional[int] = None,
    size: Optional[str] = None,
    dpi: Optional[float] = None,
    style: Optional[Literal["default", "paper"]] = None,
    no_title: Optional[bool] = None,
    no_caption: Optional[bool] = None,
    title: Optional[str] = None,
    caption: Optional[str] = None,
    azimuth: Optional[float] = None,
    elevation: Optional[float] = None,
    samples: Optional[int] = None,
    alpha: Optional[Sequence[float]] = None,
    color_by: Optional[Literal["truth", "indeterminacy", "falsity"]] = None,
) -> Dict[str, Optional[str]]: ...
def example1() -> Bezier: ...
def score(degrees: ArrayLike, *, membership: Optional[Membership] = None) -> Union[float, FloatArray]:
    """The neutrosophic score of triples, or with ``membership`` the family's score of its
    channel values (shape (..., channel_count))."""
def accuracy(degrees: ArrayLike, *, membership: Optional[Membership] = None) -> Union[float, FloatArray]:
    """The neutrosophic accuracy of triples, or with ``membership`` the family's accuracy of
    its channel values (``ModelError`` for a family without one)."""
def derived_degrees(degrees: ArrayLike, *, membership: Membership) -> Tuple[FloatArray, List[str]]:
    """The degrees a family derives from its channel values, with their names."""
def family_rule(membership: Membership) -> str:
    """The rule of a membership family in one line: the box of every channel, each interval's
    ``lower <= upper``, the sum rule and the derived degrees."""
def certainty(degrees: ArrayLike) -> Union[float, FloatArray]: ...
def centroid_interval(
    x: Sequence[float], lower: Sequence[float], upper: Sequence[float]
) -> Tuple[float, float, float]:
    """The centroid interval ``(c_l, c_r)`` of an interval type-2 fuzzy set sampled at ``x``
    with lower and upper memberships, and its midpoint (the type-reduced value)."""
def largest_relation(
    m: Sequence[Tuple[float, Triple]],
    n: Sequence[Tuple[float, Triple]],
    pairs: Optional[ArrayLike] = None,
) -> Tuple[FloatArray, FloatArray]: ...
def check_relation(
    positions: ArrayLike,
    degrees: ArrayLike,
    m: Sequence[Tuple[float, Triple]],
    n: Sequence[Tuple[float, Triple]],
) -> None: ...
def fit(
    data: Union[ArrayLike, PathLike, "pandas.DataFrame"],
    degrees: Optional[ArrayLike] = None,
    *,
    parameters: Optional[ArrayLike] = None,
    weights: Union[None, Literal["none", "score", "column"], ArrayLike] = None,
    name: Optional[str] = None,
    columns: Optional[ColumnMap] = None,
    ignore_columns: Optional[ColumnList] = None,
    ignore_unknown_columns: Optional[bool] = None,
    degree: int = 3,
    control_points: Optional[int] = None,
    tolerance: Optional[float] = None,
    interpolate: bool = False,
    closed: bool = False,
    parametrization: Literal["uniform", "chord-length", "centripetal"] = "chord-length",
    smoothing: float = 0.0,
    kind: Literal["bspline", "bezier"] = "bspline",
    membership: Membership = "neutrosophic",
) -> Tuple[Union[Bezier, BSpline], dict[str, Any]]: ...
def fit_options() -> list[dict[str, Any]]: ...
def fit_surface(
    data: Union[ArrayLike, PathLike, "pandas.DataFrame"],
    degrees: Optional[ArrayLike] = None,
    *,
    parameters: Optional[ArrayLike] = None,
    weights: Union[None, Literal["none", "score", "column"], ArrayLike] = None,
    name: Optional[str] = None,
    columns: Optional[ColumnMap] = None,
    ignore_columns: Optional[ColumnList] = None,
    ignore_unknown_columns: Optional[bool] = None,
    degree: Union[int, Tuple[int, int]] = 3,
    interpolate: bool = False,
    control_points: Union[None, int, Tuple[int, int]] = None,
    tolerance: Optional[float] = None,
    grid: Union[None, str, Tuple[int, int]] = None,
    scattered: bool = False,
    parametrization: Literal["uniform", "chord-length", "centripetal"] = "chord-length",
    projection: Literal["plane", "xy"] = "plane",
    smoothing: float = 0.0,
    membership: Membership = "neutrosophic",
) -> Tuple[Surface, dict[str, Any]]: ...
def fit_surface_options() -> list[dict[str, Any]]: ...
def figure_options() -> list[dict[str, Any]]: ...
def _restore(text: str, order: int) -> Model: ...
