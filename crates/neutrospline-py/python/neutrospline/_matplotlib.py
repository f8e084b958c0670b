"""The project's views drawn into matplotlib axes (matplotlib is imported only when used).

The same views as `save_figure` and the command line's `plot --view`, with the project's
colours (crates/neutrospline-plot/src/theme.rs) and legend names, as matplotlib artists that
the caller can restyle, combine with their own and save in any of matplotlib's formats:

- `plane` (2-D curve): the crisp curve with a band per degree along it (truth on its left,
  indeterminacy on it, falsity on its right; a band's width is the degree, a full grey lane
  is 1), the control polygon and the named control points;
- `controls`: the control polygon and points, each point labelled with its degrees, and the
  crisp curve;
- `truth`, `indeterminacy`, `falsity`, `score` (2-D curve, 3-D axes): the paper's space curve
  (x(t), y(t), degree(t)), its lifted control polygon (x_i, y_i, degree_i), and the crisp
  curve and control polygon as their shadow on the plane degree = 0;
- `all` (2-D curve, 3-D axes): the three degree curves of the paper's Fig. 5 together;
- 3-D curves and surfaces: the shape in 3-D coloured by the degree (viridis, 0 to 1), with
  its control polygon or net; `all` (and a surface's `plane`, the degree maps over (u, v))
  draws one panel per degree.
"""

import numpy as np

TRUTH = "#004488"
INDETERMINACY = "#c88a12"
FALSITY = "#bb5566"
SCORE = "#228833"
CRISP = "#222222"
CONSTRUCTION = "#6e6e6e"
SHADOW = "#9a9a9a"
SURFACE = "#cfd5dc"
TRACK = "#e6e8eb"

DEGREES = ("truth", "indeterminacy", "falsity")
COLORS = {"truth": TRUTH, "indeterminacy": INDETERMINACY, "falsity": FALSITY, "score": SCORE}
MARKERS = {"truth": "o", "indeterminacy": "s", "falsity": "D", "score": "o"}
CURVE_VIEWS = ("plane", "controls", "truth", "indeterminacy", "falsity", "all", "score")
SURFACE_VIEWS = ("controls", "truth", "indeterminacy", "falsity", "score", "all", "plane")
# The width of a full lane of the plane view, as a fraction of the control polygon's
# bounding-box diagonal, and the gap between lanes (as the figures draw them).
LANE = 0.035
LANE_GAP = 1.15

CURVE_DOCS = """Draws the curve into matplotlib axes in one of the project's views and returns
the axes (a new figure and axes when `ax` is None; matplotlib is imported only here).

`view` is `plane` (2-D curves: the crisp curve with a band per degree along it, a band's
width the degree), `controls` (the control polygon, each point labelled with its degrees),
`truth`, `indeterminacy`, `falsity` or `score` (a 2-D curve on 3-D axes: the space curve
(x(t), y(t), degree(t)), its lifted control polygon and the crisp curve as their shadow on
the degree = 0 plane; a 3-D curve coloured by the degree) or `all` (the paper's Fig. 5:
the three degree curves together; a 3-D curve: one panel per degree, three axes). 3-D views
need axes made with `projection="3d"`. The colours and legend names are the project's
figures' (truth #004488, indeterminacy #c88a12, falsity #bb5566, score #228833, crisp curve
#222222, construction #6e6e6e); `samples` evenly spaced parameters draw the curve;
`legend=False` leaves the legend out; `labels=False` the point names.

>>> import matplotlib
>>> matplotlib.use("Agg")
>>> import neutrospline as ns
>>> ax = ns.example1().plot(view="truth")
>>> [text.get_text() for text in ax.get_legend().get_texts()]
['truth curve', 'control polygon', 'crisp curve (degree 0)', 'crisp control polygon']
"""

SURFACE_DOCS = """Draws the surface into matplotlib axes in one of the project's views and
returns the axes (a new figure when `ax` is None; matplotlib is imported only here).

`view` is `truth`, `indeterminacy`, `falsity` or `score` (the surface on 3-D axes coloured by
the degree, viridis from 0 to 1, with its control net; `ax` made with `projection="3d"`),
`controls` (the surface in grey with its control net), `all` (one 3-D panel per degree) or
`plane` (the degree maps over (u, v), one 2-D panel per degree); for `all` and `plane`, `ax`
is a sequence of three axes, and three are returned. `samples` is the mesh's samples a
direction; `net=False` leaves the control net out (a fitted surface's dense net hides it).

>>> import matplotlib
>>> matplotlib.use("Agg")
>>> import neutrospline as ns
>>> ax = ns.load("examples/surface.toml").plot(view="truth")
>>> [text.get_text() for text in ax.get_legend().get_texts()]
['surface', 'control net']
"""


def pyplot():
    """matplotlib.pyplot, with a message that says how to get it when it is missing."""
    try:
        import matplotlib.pyplot as plt
    except ImportError as error:  # pragma: no cover - matplotlib is installed for the tests
        raise ImportError("neutrospline's plot methods need matplotlib: pip install matplotlib") from error
    return plt


def model_error(message):
    from ._neutrospline import ModelError

    return ModelError(message)


def check_view(view, views, what):
    if view not in views:
        raise model_error(
            f"view = {view!r}: not a view of a {what} (one of {', '.join(views)})"
        )


def axes(ax, three_d, count=1):
    """The caller's axes (checked to be 3-D when the view needs it), or new ones."""
    plt = pyplot()
    if ax is None:
        kwargs = {"projection": "3d"} if three_d else {}
        if count == 1:
            fig = plt.figure(figsize=(8, 6))
            return fig.add_subplot(1, 1, 1, **kwargs)
        fig = plt.figure(figsize=(5 * count, 5))
        return [fig.add_subplot(1, count, k + 1, **kwargs) for k in range(count)]
    many = list(ax) if count > 1 and isinstance(ax, (list, tuple, np.ndarray)) else None
    if count > 1:
        if many is None or len(many) != count:
            raise model_error(f"ax: this view draws {count} panels: give a sequence of {count} axes")
        for a in many:
            check_axes(a, three_d)
        return many
    check_axes(ax, three_d)
    return ax


def check_axes(ax, three_d):
    is_3d = getattr(ax, "name", "") == "3d"
    if three_d and not is_3d:
        raise model_error(
            "ax: this view is drawn in 3-D: give axes made with projection=\"3d\" "
            "(fig.add_subplot(projection=\"3d\"))"
        )
    if not three_d and is_3d:
        raise model_error("ax: this view is drawn in 2-D: give 2-D axes")


def degree_values(rows, view):
    """The degree (or the score) of each row of `rows` (..., 3): truth, indeterminacy,
    falsity."""
    if view == "score":
        return (2.0 + rows[..., 0] - rows[..., 1] - rows[..., 2]) / 3.0
    return rows[..., DEGREES.index(view)]


def point_labels(ax, names, points, three_d):
    for name, p in zip(names, points):
        if not name:
            continue
        if three_d:
            ax.text(*p, f" {name}", color=CRISP, fontweight="bold", fontsize=9)
        else:
            ax.annotate(
                name, p, textcoords="offset points", xytext=(6, 6),
                color=CRISP, fontweight="bold", fontsize=9,
            )


def control_polygon_2d(ax, positions, label="control polygon"):
    return ax.plot(
        positions[:, 0], positions[:, 1], color=CONSTRUCTION, linestyle="--", linewidth=1.2,
        marker="o", markerfacecolor="white", markeredgecolor=CRISP, markersize=6, label=label,
        zorder=4,
    )[0]


def plane_bands(curve, ax, t, rows, positions):
    """The three degree bands along a 2-D curve (the `plane` view)."""
    xy = rows[:, :2]
    tangent = curve.derivative()(t)[:, :2]
    norm = np.hypot(tangent[:, 0], tangent[:, 1])
    if np.any(norm == 0):  # A stationary point: the chord's direction there.
        chord = np.gradient(xy, axis=0)
        tangent = np.where(norm[:, None] == 0, chord, tangent)
        norm = np.hypot(tangent[:, 0], tangent[:, 1])
    normal = np.column_stack([-tangent[:, 1], tangent[:, 0]]) / norm[:, None]
    low, high = positions.min(axis=0), positions.max(axis=0)
    lane = LANE * float(np.hypot(*(high - low)))
    for k, name in enumerate(DEGREES):
        center = xy + ((1 - k) * LANE_GAP * lane) * normal
        half = 0.5 * lane * rows[:, 2 + k][:, None] * normal
        track = 0.5 * lane * normal
        ax.fill(
            *np.concatenate([center + track, (center - track)[::-1]]).T,
            color=TRACK, linewidth=0, label="_nolegend_", zorder=1,
        )
        ax.fill(
            *np.concatenate([center + half, (center - half)[::-1]]).T,
            color=COLORS[name], linewidth=0, label=name, zorder=2,
        )
    return lane


def curve_plot(self, ax=None, view="plane", *, samples=201, legend=True, labels=True):
    check_view(view, CURVE_VIEWS, "curve")
    dimension = self.dimension
    t, rows = self.sample(samples, parameters=True)
    positions = np.asarray(self.positions)
    degrees = np.asarray(self.membership_degrees)
    names = self.point_names if labels else []
    if dimension == 3:
        return curve_plot_3d(self, ax, view, rows, positions, degrees, names, legend)
    if view in ("plane", "controls"):
        ax = axes(ax, False)
        if view == "plane":
            plane_bands(self, ax, t, rows, positions)
        if view == "controls":
            control_polygon_2d(ax, positions)
        ax.plot(rows[:, 0], rows[:, 1], color=CRISP, linewidth=1.4, label="crisp curve", zorder=3)
        if view == "plane":
            control_polygon_2d(ax, positions)
        if view == "controls":
            for p, (tv, iv, fv), name in zip(positions, degrees, names or [""] * len(positions)):
                text = f"T {tv:g}\nI {iv:g}\nF {fv:g}"
                ax.annotate(
                    f"{name}\n{text}" if name else text, p, textcoords="offset points",
                    xytext=(7, -7), va="top", fontsize=8, color=CRISP,
                )
        else:
            point_labels(ax, names, positions, False)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_aspect("equal", adjustable="datalim")
        if legend:
            ax.legend(loc="best")
        return ax
    ax = axes(ax, True)
    shown = DEGREES if view == "all" else (view,)
    for name in shown:
        ax.plot(
            rows[:, 0], rows[:, 1], degree_values(rows[:, 2:], name), color=COLORS[name],
            linewidth=2.0, label=f"{name} curve",
        )
    for k, name in enumerate(shown):
        lifted = degree_values(degrees, name)
        if view == "all":
            polygon_label = "control polygons" if k == 0 else "_nolegend_"
        else:
            polygon_label = "control polygon"
        ax.plot(
            positions[:, 0], positions[:, 1], lifted, color=COLORS[name], linestyle="--",
            linewidth=1.2, marker=MARKERS[name], markersize=6, markeredgecolor=CRISP,
            label=polygon_label,
        )
        for (x, y), z in zip(positions, lifted):
            ax.plot([x, x], [y, y], [0.0, z], color=SHADOW, linestyle=":", linewidth=0.8,
                    label="_nolegend_")
        if view != "all" and labels:
            point_labels(ax, names, np.column_stack([positions, lifted]), True)
    floor = np.zeros(len(rows))
    zero = "score 0" if view == "score" else "degree 0"
    ax.plot(rows[:, 0], rows[:, 1], floor, color=CRISP, linewidth=1.4, label=f"crisp curve ({zero})")
    ax.plot(
        positions[:, 0], positions[:, 1], np.zeros(len(positions)), color=SHADOW,
        linestyle="--", linewidth=1.0, marker=".", label="crisp control polygon",
    )
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("degree" if view == "all" else view)
    ax.set_zlim(0.0, 1.0)
    if legend:
        ax.legend(loc="upper left")
    return ax


def colored_line_3d(ax, points, values):
    """A 3-D polyline coloured by `values` in [0, 1] (viridis), one segment per pair."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection

    segments = np.stack([points[:-1], points[1:]], axis=1)
    line = Line3DCollection(segments, cmap="viridis", linewidth=3.0)
    line.set_array(0.5 * (values[:-1] + values[1:]))
    line.set_clim(0.0, 1.0)
    ax.add_collection(line)
    return line


def curve_plot_3d(self, ax, view, rows, positions, degrees, names, legend):
    if view == "plane":
        raise model_error(
            "view = 'plane': the degree bands lie in the plane of a 2-D curve; a 3-D curve "
            "has the views controls, truth, indeterminacy, falsity, score and all"
        )
    shown = DEGREES if view == "all" else (view,)
    axs = axes(ax, True, len(shown))
    panels = axs if isinstance(axs, list) else [axs]
    points = rows[:, :3]
    for a, name in zip(panels, shown):
        low = float(min(points[:, 2].min(), positions[:, 2].min()))
        if name == "controls":
            a.plot(*points.T, color=CRISP, linewidth=1.6, label="crisp curve")
            a.plot(*positions.T, color=CONSTRUCTION, linestyle="--", marker="o",
                   markerfacecolor="white", markeredgecolor=CRISP, label="control polygon")
        else:
            values = degree_values(rows[:, 3:], name)
            line = colored_line_3d(a, points, values)
            a.plot(*positions.T, color=CONSTRUCTION, linestyle="--", linewidth=1.2,
                   label="control polygon")
            a.scatter(*positions.T, c=degree_values(degrees, name), cmap="viridis",
                      vmin=0.0, vmax=1.0, edgecolors=CRISP, s=40, depthshade=False)
            a.set_title(name)
            if ax is None and len(panels) == 1:
                a.figure.colorbar(line, ax=a, label=name, shrink=0.6)
        a.plot(points[:, 0], points[:, 1], np.full(len(points), low), color=SHADOW,
               linewidth=1.2, label="shadow on the floor")
        point_labels(a, names, positions, True)
        a.set_xlabel("x")
        a.set_ylabel("y")
        a.set_zlabel("z")
        if legend:
            a.legend(loc="upper left")
    return axs


def surface_plot(self, ax=None, view="truth", *, samples=30, legend=True, net=True):
    check_view(view, SURFACE_VIEWS, "surface")
    (u0, u1), (v0, v1) = self.domain
    from ._pandas import uniform

    us, vs = uniform(samples, (u0, u1)), uniform(samples, (v0, v1))
    uu, vv = np.meshgrid(us, vs, indexing="ij")
    grid = self.evaluate(uu, vv)
    show_net = net
    net = np.asarray(self.positions)
    net_degrees = np.asarray(self.membership_degrees)
    if view == "plane":
        axs = axes(ax, False, 3)
        for a, name in zip(axs, DEGREES):
            image = a.pcolormesh(uu, vv, degree_values(grid[..., 3:], name), cmap="viridis",
                                 vmin=0.0, vmax=1.0, shading="gouraud")
            a.set_title(name)
            a.set_xlabel("u")
            a.set_ylabel("v")
        axs[-1].figure.colorbar(image, ax=axs, label="degree", shrink=0.8)
        return axs
    shown = DEGREES if view == "all" else (view,)
    axs = axes(ax, True, len(shown))
    panels = axs if isinstance(axs, list) else [axs]
    from matplotlib import cm, colors
    from matplotlib.patches import Patch

    import matplotlib

    viridis = matplotlib.colormaps["viridis"]
    for a, name in zip(panels, shown):
        if name == "controls":
            a.plot_surface(grid[..., 0], grid[..., 1], grid[..., 2], color=SURFACE,
                           linewidth=0, alpha=0.9)
            fill = "white"
            face = SURFACE
        else:
            values = degree_values(grid[..., 3:], name)
            a.plot_surface(grid[..., 0], grid[..., 1], grid[..., 2],
                           facecolors=viridis(np.clip(values, 0, 1)), linewidth=0,
                           shade=False)
            fill = viridis(np.clip(degree_values(net_degrees, name), 0, 1).reshape(-1))
            face = viridis(0.55)
            a.set_title(name)
        if show_net:
            rows, cols = net.shape[:2]
            for i in range(rows):
                a.plot(*net[i].T, color=CONSTRUCTION, linestyle="--", linewidth=1.0, label="_nolegend_")
            for j in range(cols):
                a.plot(*net[:, j].T, color=CONSTRUCTION, linestyle="--", linewidth=1.0, label="_nolegend_")
            flat = net.reshape(-1, 3)
            a.scatter(*flat.T, c=fill if isinstance(fill, str) else fill, edgecolors=CRISP, s=30,
                      depthshade=False)
        a.set_xlabel("x")
        a.set_ylabel("y")
        a.set_zlabel("z")
        if legend:
            from matplotlib.lines import Line2D

            handles = [Patch(facecolor=colors.to_hex(face), label="surface")]
            if show_net:
                handles.append(Line2D([], [], color=CONSTRUCTION, linestyle="--", marker="o",
                                      markerfacecolor=colors.to_hex(face), markeredgecolor=CRISP,
                                      label="control net"))
            a.legend(handles=handles, loc="upper left")
        if ax is None and name != "controls" and len(panels) == 1:
            mappable = cm.ScalarMappable(norm=colors.Normalize(0.0, 1.0), cmap=viridis)
            a.figure.colorbar(mappable, ax=a, label=name, shrink=0.6)
    return axs


curve_plot.__doc__ = CURVE_DOCS
surface_plot.__doc__ = SURFACE_DOCS
curve_plot.__name__ = surface_plot.__name__ = "plot"
