"""Curves and surfaces as pandas DataFrames (pandas is imported only when used).

The columns are those of the command line's `eval` table: `t, x, y[, z], truth,
indeterminacy, falsity` for a curve, `u, v, x, y, z, truth, indeterminacy, falsity` for a
surface, and with `scores=True` the `score, accuracy, certainty` of `eval --scores`. A
DataFrame goes the other way through `load(frame)`, `fit(frame)` and `fit_surface(frame)`,
which read its columns by name as the command line reads a table.
"""

import numpy as np

CURVE_DOCS = """A table of the curve: a pandas DataFrame with the columns of the command line's
`eval` (`t, x, y[, z], truth, indeterminacy, falsity`), one row per parameter.

`t` is an int N (N evenly spaced parameters over the domain, both ends exact, as
`sample(N)` and `eval --samples N`; default 101) or the parameters themselves (a number or a
1-D array, as for `evaluate`). `scores=True` adds the columns `score` ((2 + T - I - F) / 3),
`accuracy` (T - F) and `certainty` (T) of `eval --scores`. A curve of an interval-valued or
bipolar family has its `channels` as the degree columns, and `scores=True` adds its family's
`score` (and `accuracy`, for interval-intuitionistic). pandas is imported only here.

>>> import neutrospline as ns
>>> frame = ns.example1().to_dataframe(3)
>>> list(frame.columns)
['t', 'x', 'y', 'truth', 'indeterminacy', 'falsity']
>>> frame.loc[1, ["t", "x", "y", "truth"]].tolist()
[0.5, 4.625, 4.0, 0.625]
"""

SURFACE_DOCS = """A table of the surface: a pandas DataFrame with the columns of the command
line's `eval` (`u, v, x, y, z, truth, indeterminacy, falsity`), one row per parameter pair.

`u` and `v` are ints (a grid of u x v evenly spaced parameters over the domain, u varying
slowest, as `eval --samples N` does with N x N; `v` defaults to `u`, `u` to 101) or arrays of
parameters of one shape (or shapes that broadcast), flattened in C order. `scores=True` adds
`score, accuracy, certainty`. pandas is imported only here.

>>> import neutrospline as ns
>>> surface = ns.load("examples/surface.toml")
>>> frame = surface.to_dataframe(3)
>>> len(frame), list(frame.columns)[:5]
(9, ['u', 'v', 'x', 'y', 'z'])
"""


def pandas():
    """The pandas module, with a message that says how to get it when it is missing."""
    try:
        import pandas as module
    except ImportError as error:  # pragma: no cover - pandas is installed for the tests
        raise ImportError(
            "neutrospline's DataFrame methods need pandas: pip install pandas"
        ) from error
    return module


def uniform(count, domain):
    """`count` evenly spaced parameters over `domain`, ends exact: the engine's
    `uniform_parameter` (a + (b - a) * (k / (count - 1)), kept inside [a, b])."""
    a, b = domain
    if count < 1:
        return np.empty(0)
    if count == 1:
        return np.array([float(a)])
    k = np.arange(count, dtype=float)
    t = np.minimum(np.maximum(a + (b - a) * (k / (count - 1)), a), b)
    t[0], t[-1] = a, b
    return t


def is_count(value):
    return isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_))


def with_scores(columns, degrees, shape=None):
    from . import _neutrospline as core

    if shape is not None and list(shape.channels) != ["truth", "indeterminacy", "falsity"]:
        # An interval-valued or bipolar family: its own score (and accuracy, if it has one)
        # of its channels.
        family = shape.membership
        columns["score"] = np.asarray(core.score(degrees, membership=family), dtype=float).reshape(-1)
        if family == "interval-intuitionistic":
            columns["accuracy"] = np.asarray(
                core.accuracy(degrees, membership=family), dtype=float
            ).reshape(-1)
        return
    columns["score"] = np.asarray(core.score(degrees), dtype=float).reshape(-1)
    columns["accuracy"] = np.asarray(core.accuracy(degrees), dtype=float).reshape(-1)
    columns["certainty"] = np.asarray(core.certainty(degrees), dtype=float).reshape(-1)


def position_names(dimension):
    return ["x", "y", "z"][:dimension]


def curve_to_dataframe(self, t=101, *, scores=False):
    pd = pandas()
    if is_count(t):
        parameters, points = self.sample(int(t), parameters=True)
    else:
        points = self.evaluate(t)
        parameters = np.asarray(t, dtype=float).reshape(-1)
        points = points.reshape(parameters.size, -1)
    channels = list(self.channels)
    names = ["t"] + position_names(self.dimension) + channels
    columns = {"t": parameters}
    for k, name in enumerate(names[1:]):
        columns[name] = points[:, k]
    if scores:
        with_scores(columns, points[:, self.dimension :], self)
    return pd.DataFrame(columns)


def surface_to_dataframe(self, u=101, v=None, *, scores=False):
    pd = pandas()
    if is_count(u) and (v is None or is_count(v)):
        (u0, u1), (v0, v1) = self.domain
        us = uniform(int(u), (u0, u1))
        vs = uniform(int(u if v is None else v), (v0, v1))
        uu, vv = np.meshgrid(us, vs, indexing="ij")
    else:
        if v is None:
            raise TypeError("to_dataframe(u, v): give both parameter arrays, or counts")
        uu, vv = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
    uu, vv = uu.reshape(-1), vv.reshape(-1)
    channels = list(self.channels)
    points = self.evaluate(uu, vv).reshape(uu.size, 3 + len(channels))
    columns = {"u": uu, "v": vv}
    for k, name in enumerate(["x", "y", "z"] + channels):
        columns[name] = points[:, k]
    if scores:
        with_scores(columns, points[:, 3:], self)
    return pd.DataFrame(columns)


curve_to_dataframe.__doc__ = CURVE_DOCS
surface_to_dataframe.__doc__ = SURFACE_DOCS
curve_to_dataframe.__name__ = surface_to_dataframe.__name__ = "to_dataframe"
