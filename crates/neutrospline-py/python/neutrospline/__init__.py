"""neutrospline: neutrosophic Bézier, B-spline and NURBS curves and surfaces.

Control points carry three degrees, truth, indeterminacy and falsity, blended along the curve
as extra coordinates. Arrays go in and out as numpy float64 arrays; evaluation runs in the
same batch engine as the ``neutrospline`` command line, with the GIL released; models are
saved and loaded in the command line's TOML, JSON and CSV formats; figures are the command
line's, as SVG text, files, or inline in Jupyter.

>>> import neutrospline as ns
>>> curve = ns.example1()
>>> curve(0.5).round(12).tolist()  # x, y, truth, indeterminacy, falsity
[4.625, 4.0, 0.625, 0.2, 0.175]
"""

from ._neutrospline import (
    BSpline,
    BSplineSurface,
    Bezier,
    BezierSurface,
    Curve,
    ModelError,
    Nurbs,
    NurbsSurface,
    Shape,
    Surface,
    __version__,
    accuracy,
    centroid_interval,
    certainty,
    derived_degrees,
    family_rule,
    check_relation,
    example1,
    fit,
    fit_options,
    fit_surface,
    fit_surface_options,
    figure_options,
    import_options,
    table_options,
    transform_options,
    inline,
    instruction_set,
    largest_relation,
    load,
    score,
)

# `Surface.bezier(...)` and the others are the subclasses' constructors under their old names,
# kept for existing code: the same arguments and results as `BezierSurface(...)`.
Surface.bezier = BezierSurface
Surface.bspline = BSplineSurface
Surface.nurbs = NurbsSurface

__all__ = [
    "__version__",
    "BSpline",
    "BSplineSurface",
    "Bezier",
    "BezierSurface",
    "Curve",
    "ModelError",
    "Nurbs",
    "NurbsSurface",
    "Shape",
    "Surface",
    "accuracy",
    "centroid_interval",
    "certainty",
    "derived_degrees",
    "family_rule",
    "check_relation",
    "example1",
    "fit",
    "fit_options",
    "fit_surface",
    "fit_surface_options",
    "figure_options",
    "import_options",
    "table_options",
    "transform_options",
    "inline",
    "instruction_set",
    "largest_relation",
    "load",
    "score",
]

# DataFrames (pandas) and matplotlib axes: methods written in Python, which import pandas and
# matplotlib only when they are called (neither is a dependency of the package).
from . import _matplotlib, _pandas  # noqa: E402

Curve.to_dataframe = _pandas.curve_to_dataframe
Surface.to_dataframe = _pandas.surface_to_dataframe
Curve.plot = _matplotlib.curve_plot
Surface.plot = _matplotlib.surface_plot
