#!/usr/bin/env python3
"""Reference geometry of every real file in tests/realfiles/, read by independent readers,
for crates/neutrospline-exchange/tests/realfiles.rs.

How to run (from the workspace root):

    python3 -m venv /work/venv-ref \
      && /work/venv-ref/bin/pip install -r scripts/realfiles/requirements.txt \
      && /work/venv-ref/bin/python scripts/realfiles/make_realfiles_reference.py

It writes tests/realfiles/reference/svg.json and dxf.json (deterministic: same input, same
bytes). `--svg-only` or `--dxf-only` writes one of the two. `--root DIR` reads another folder
laid out as tests/realfiles (DIR/svg/FOLDER/*.svg, DIR/dxf/FOLDER/*.dxf) and writes DIR/reference/:
a check on files the tests have not seen, without committing them (run the Rust test with
NEUTROSPLINE_REALFILES=DIR, crates/neutrospline-exchange/tests/realfiles.rs).

Numbers are written by Python's json module (the shortest repr that reads back to the same
double); the exact SPLINE data are strings of that repr, which the Rust test parses with
the correctly rounded `str::parse::<f64>`.

SVG (svgelements 1.9.6, `SVG.parse(path, reify=True)`):
  * drawn shapes: the Shape objects (path, rect, circle, ellipse, line, polyline, polygon)
    of svgelements' tree. svgelements itself leaves out `display:none`, the content of
    `<defs>`, `<clipPath>` and `<pattern>`, and expands `<use>` (the referenced element is
    a child of the Use object). It draws `<marker>`, `<mask>` and `<symbol>` content in place
    (a known error of the reader, tests/realfiles/README.md): this script moves them into
    `<defs>` before parsing, and Inkscape's `<flowRoot>` too (svgelements draws the frame of
    the flowed text). `visibility:hidden` / `collapse` (inherited through svgelements' values)
    is left out too. svgelements drops degenerate shapes itself (a zero-size rect).
  * coordinates: svgelements maps the root's viewBox onto its viewport (width/height in px);
    the importer produces the root's user units (viewBox coordinates). So every shape is
    mapped back by the inverse of the root's viewport transform (`SVG.viewbox_transform`, a
    scale and translation, so arcs stay exact), then reified again. Nested `<svg>` viewports
    stay applied: they are part of the drawing in root user units.
  * per shape: the kind (`<tag>`), its id, the points of every segment (Move excluded) at
    t = 0, 1/4, 1/2, 3/4, 1 (`segment.point(t)`; consecutive duplicates written once) and
    its length (the segments' `length(error=1e-12)`).
  * not curves: `<text>` and `<image>` counted by kind.

DXF (ezdxf 1.4.5, `ezdxf.readfile`, `ezdxf.recover.readfile` when that fails):
  * drawn entities: modelspace and the active paper space layout (both are the ENTITIES
    section that the file's programs draw), INSERTs expanded recursively
    (`multi_insert()` for arrays, `virtual_entities()`, the ATTRIBs as text). Entities on a
    layer that is off or frozen, or marked invisible (group 60), are left out.
  * curves by closed forms from the entity's data (never ezdxf's own evaluation): LINE,
    CIRCLE, ARC, ELLIPSE, LWPOLYLINE, POLYLINE (2-D with bulges, 3-D), each OCS entity mapped
    to world coordinates by ezdxf's OCS (the arbitrary axis algorithm); the points at
    t = 0, 1/4, 1/2, 3/4, 1 of every segment (arcs by angle, ellipses by their parameter),
    lengths in closed form (ellipse: mpmath.quad).
  * SPLINE: degree, knots, control points, weights exactly as read; points by an exact de
    Boor sum in doubles on the homogeneous points (convex combinations: ~1e-15 of the size) at
    the domain's ends, its quarters and the middle of every non-empty knot span (at most 64
    points); the length by 10-point Gauss-Legendre on every quarter of every span.
    `exact: true` for a SPLINE written in the file as is (not transformed by an INSERT):
    the test requires the importer's curve equal to it bit for bit.
  * ezdxf reads no SPLINE of some R12-style files (AC1009 headers, or SPLINEs without
    subclass markers; a known error of the reader): for a file where ezdxf sees fewer
    SPLINEs than the ENTITIES section holds, the SPLINEs are read by this script's own
    group reader (`raw_splines`, group codes 70-74, 40, 41, 10/20/30 of AutoCAD's DXF
    reference), marked `"reader": "groups"`. The same group reader cross-checks every SPLINE
    that ezdxf does read (the numbers must agree exactly), and the check's result is written
    to the file's `cross_check`.
  * not curves: every other entity kind counted by kind (TEXT, MTEXT, HATCH, DIMENSION,
    POINT, VIEWPORT, ...; polyface and polygon meshes as `POLYLINE` meshes), and a curve
    entity all of whose points coincide (a LINE of length zero, a CIRCLE of radius zero): it
    draws a point, not a curve.

The drawing's size is the diagonal of the bounding box of every reference point of the file.
"""

import bisect
import io
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import ezdxf
import mpmath
import numpy as np
import svgelements as se
from ezdxf import recover
from ezdxf.math import OCS, Vec3

ROOT = os.path.normpath(os.path.join(os.path.dirname(__file__), "..", ".."))
REALFILES = os.path.join(ROOT, "tests", "realfiles")
OUT = os.path.join(REALFILES, "reference")
QUARTERS = [0.0, 0.25, 0.5, 0.75, 1.0]


def files_of(kind):
    """The real files of a format, as paths relative to tests/realfiles/, sorted."""
    out = []
    base = os.path.join(REALFILES, kind)
    for folder in sorted(os.listdir(base)):
        for name in sorted(os.listdir(os.path.join(base, folder))):
            out.append(f"{kind}/{folder}/{name}")
    return out


def append_point(points, p):
    """Appends p unless it repeats the last point exactly."""
    p = [float(c) for c in p]
    if not points or points[-1] != p:
        points.append(p)


def size_of(shapes):
    """The diagonal of the bounding box of every shape's points (0 without points)."""
    pts = [p for s in shapes for p in s["points"]]
    if not pts:
        return 0.0
    a = np.array(pts)
    return float(np.linalg.norm(a.max(axis=0) - a.min(axis=0)))


# ------------------------------------------------------------------------------------- SVG

SVG_NS = "http://www.w3.org/2000/svg"
NOT_IN_PLACE = {"marker", "mask", "symbol", "flowRoot"}


def without_content_in_place(path):
    """The file's bytes with every `<marker>`, `<mask>`, `<symbol>` and Inkscape `<flowRoot>`
    (flowed text: svgelements draws the shapes of its `<flowRegion>`, the frame the text
    flows in, which no renderer draws) moved into a `<defs>` of its own where it stands:
    svgelements keeps an element it does not know (and puts the element's content in the
    tree as drawn), but never draws `<defs>` content, and a `<use>` still finds a moved
    symbol by its id."""
    ET.register_namespace("", SVG_NS)
    ET.register_namespace("xlink", "http://www.w3.org/1999/xlink")
    tree = ET.parse(path)
    moved = 0
    for parent in tree.iter():
        for k, child in enumerate(list(parent)):
            if isinstance(child.tag, str) and child.tag.split("}")[-1] in NOT_IN_PLACE:
                if parent.tag.split("}")[-1] == "defs":
                    continue
                defs = ET.Element(f"{{{SVG_NS}}}defs")
                parent.remove(child)
                defs.append(child)
                parent.insert(k, defs)
                moved += 1
    if moved == 0:
        with open(path, "rb") as f:
            return f.read(), 0
    return ET.tostring(tree.getroot()), moved


def drawn_svg_shapes(node, out, not_curves):
    """Walks svgelements' tree (groups, uses, nested svg): the drawn shapes into out, text
    and images counted into not_curves."""
    for child in node:
        if isinstance(child, se.Shape):
            if child.values.get("visibility", "visible") in ("hidden", "collapse"):
                continue
            out.append(child)
        elif isinstance(child, se.Text):
            if child.values.get("tag") == "text":
                not_curves["<text>"] = not_curves.get("<text>", 0) + 1
        elif isinstance(child, se.Image):
            not_curves["<image>"] = not_curves.get("<image>", 0) + 1
        elif isinstance(child, list):
            drawn_svg_shapes(child, out, not_curves)


def svg_reference(rel):
    path = os.path.join(REALFILES, rel)
    entry = {"file": rel, "shapes": [], "not_curves": {}}
    try:
        data, moved = without_content_in_place(path)
        if moved:
            entry["moved_to_defs"] = moved
        root = se.SVG.parse(io.BytesIO(data), reify=True)
    except Exception as e:  # noqa: BLE001 - the reader's failure is data
        entry["error"] = f"svgelements: {type(e).__name__}: {e}"
        entry["size"] = 0.0
        entry["length"] = 0.0
        return entry
    shapes = []
    if isinstance(root, list):
        drawn_svg_shapes(root, shapes, entry["not_curves"])
    back = None
    if isinstance(root, se.SVG) and root.viewbox_transform:
        back = ~se.Matrix(root.viewbox_transform)
    for index, shape in enumerate(shapes):
        if back is not None:
            shape = shape * back
            shape.reify()
        points = []
        length = 0.0
        for segment in shape.segments(transformed=True):
            # A move draws nothing, nor does a close or line of length zero (the importer
            # records such a subpath as empty).
            if isinstance(segment, se.Move) or (
                isinstance(segment, (se.Line, se.Close)) and segment.start == segment.end
            ):
                continue
            for t in QUARTERS:
                p = segment.point(t)
                append_point(points, [p.x, p.y])
            length += segment.length(error=1e-12)
        if not points or all(p == points[0] for p in points):
            # Nothing drawn, or a point (svgelements keeps a <rect> without a size).
            continue
        entry["shapes"].append(
            {
                "kind": f"<{shape.values.get('tag')}>",
                "id": shape.id,
                "index": index,
                "length": length,
                "points": points,
            }
        )
    entry["size"] = size_of(entry["shapes"])
    entry["length"] = sum(s["length"] for s in entry["shapes"])
    return entry


# ------------------------------------------------------------------------------------- DXF

CURVES = {"LINE", "CIRCLE", "ARC", "ELLIPSE", "LWPOLYLINE", "POLYLINE", "SPLINE"}


def ocs_points(extrusion, points):
    ocs = OCS(extrusion)
    return [list(ocs.to_wcs(Vec3(p))) for p in points]


def arc_points(center, radius, start, sweep):
    """Points at the quarters of the arc from angle `start` over `sweep` (radians), OCS."""
    return [
        (
            center[0] + radius * math.cos(start + t * sweep),
            center[1] + radius * math.sin(start + t * sweep),
            center[2],
        )
        for t in QUARTERS
    ]


def bulge_segment(p1, p2, bulge, z):
    """The points (OCS) and length of a polyline segment from p1 to p2 with `bulge`
    (tan of a quarter of the included angle, positive counterclockwise)."""
    dx, dy = p2[0] - p1[0], p2[1] - p1[1]
    chord = math.hypot(dx, dy)
    if bulge == 0 or chord == 0:
        pts = [(p1[0] + t * dx, p1[1] + t * dy, z) for t in QUARTERS]
        return pts, chord
    theta = 4 * math.atan(bulge)
    radius = chord / (2 * math.sin(abs(theta) / 2))
    # The centre lies on the chord's perpendicular bisector, at distance
    # radius cos(theta / 2) (signed: left of the chord for a counterclockwise arc).
    h = chord / 2 / math.tan(theta / 2)
    mx, my = (p1[0] + p2[0]) / 2, (p1[1] + p2[1]) / 2
    cx, cy = mx - h * dy / chord, my + h * dx / chord
    start = math.atan2(p1[1] - cy, p1[0] - cx)
    pts = arc_points((cx, cy, z), radius, start, theta)
    pts[0] = (p1[0], p1[1], z)
    pts[-1] = (p2[0], p2[1], z)
    return pts, radius * abs(theta)


def polyline_points(vertices, closed, z, extrusion):
    """vertices: (x, y, bulge) in OCS. Points and length of the whole polyline."""
    points, length = [], 0.0
    count = len(vertices)
    segments = count if closed else count - 1
    for k in range(segments):
        a, b = vertices[k], vertices[(k + 1) % count]
        pts, seg_length = bulge_segment(a, b, a[2], z)
        for p in ocs_points(extrusion, pts):
            append_point(points, p)
        length += seg_length
    if count == 1:
        append_point(points, ocs_points(extrusion, [(vertices[0][0], vertices[0][1], z)])[0])
    return points, length


def basis_span(knots, degree, u):
    """The index k with knots[k] <= u < knots[k + 1] inside the domain (the last non-empty
    span for u at the end)."""
    n = len(knots) - degree - 1
    if u >= knots[n]:
        k = n - 1
        while knots[k] == knots[k + 1]:
            k -= 1
        return k
    return bisect.bisect_right(knots, u, degree, n) - 1


def de_boor(knots, degree, homogeneous, u, k):
    """de Boor's algorithm on the span k: the homogeneous point at u (any number type)."""
    d = [list(homogeneous[j + k - degree]) for j in range(degree + 1)]
    for r in range(1, degree + 1):
        for j in range(degree, r - 1, -1):
            i = j + k - degree
            denom = knots[i + degree + 1 - r] - knots[i]
            alpha = (u - knots[i]) / denom
            d[j] = [(1 - alpha) * x + alpha * y for x, y in zip(d[j - 1], d[j])]
    return d[degree]


def spline_point(knots, degree, points, weights, u):
    """C(u) by de Boor's algorithm on the homogeneous points (w x, w y, w z, w), in doubles
    (each step a convex combination: the rounding stays near 1e-15 of the size)."""
    hom = [[c * w for c in p] + [w] for p, w in zip(points, weights)]
    h = de_boor(knots, degree, hom, u, basis_span(knots, degree, u))
    return [c / h[-1] for c in h[:-1]]


def spline_speed(knots, degree, points, weights):
    """u -> |dC/du| (doubles): the homogeneous derivative by the derivative's de Boor sum
    (control points p (Q_{i+1} - Q_i) / (u_{i+p+1} - u_{i+1}), degree p - 1, the knots
    without their ends) and the quotient rule C' = (A' - w' C) / w."""
    hom = [[c * w for c in p] + [w] for p, w in zip(points, weights)]
    dhom = []
    for i in range(len(hom) - 1):
        denom = knots[i + degree + 1] - knots[i + 1]
        scale = degree / denom if denom != 0 else 0.0
        dhom.append([scale * (y - x) for x, y in zip(hom[i], hom[i + 1])])
    dk = knots[1:-1]

    def speed(u):
        if degree == 0:
            return 0.0
        k = basis_span(knots, degree, u)
        a = de_boor(knots, degree, hom, u, k)
        da = de_boor(dk, degree - 1, dhom, u, k - 1)
        w, dw = a[-1], da[-1]
        return math.hypot(*[(da[j] - dw * a[j] / w) / w for j in range(3)])

    return speed


GL_X, GL_W = np.polynomial.legendre.leggauss(10)


def spline_length(knots, degree, points, weights):
    """The length by 10-point Gauss-Legendre on every quarter of every non-empty span."""
    total = 0.0
    speed = spline_speed(knots, degree, points, weights)
    for k in range(degree, len(points)):
        a, b = knots[k], knots[k + 1]
        if b <= a:
            continue
        for q in range(4):
            lo, hi = a + (b - a) * q / 4, a + (b - a) * (q + 1) / 4
            for x, w in zip(GL_X, GL_W):
                total += w * (hi - lo) / 2 * speed((lo + hi) / 2 + (hi - lo) / 2 * x)
    return total


def spline_parameters(knots, degree, count):
    lo, hi = knots[degree], knots[count]
    params = {lo + (hi - lo) * t for t in QUARTERS}
    mids = [
        (knots[k] + knots[k + 1]) / 2
        for k in range(degree, count)
        if knots[k + 1] > knots[k]
    ]
    if len(mids) > 56:
        mids = [mids[round(j * (len(mids) - 1) / 55)] for j in range(56)]
    params.update(mids)
    return sorted(params)


def spline_shape(kind, handle, degree, knots, points, weights, exact, reader):
    wts = weights if weights else [1.0] * len(points)
    params = spline_parameters(knots, degree, len(points))
    ref_points = []
    for u in params:
        append_point(ref_points, spline_point(knots, degree, points, wts, u))
    return {
        "kind": kind,
        "id": handle,
        "length": spline_length(knots, degree, points, wts),
        "points": ref_points,
        "spline": {
            "degree": degree,
            "knots": [repr(float(x)) for x in knots],
            "control_points": [[repr(float(c)) for c in p] for p in points],
            "weights": [repr(float(w)) for w in weights] if weights else None,
            "exact": exact,
            "reader": reader,
        },
    }


def raw_splines(path):
    """The SPLINE entities of the ENTITIES section by their group codes: a list of dicts
    (line, degree, knots, control points, weights, fit point count) in file order."""
    with open(path, "rb") as f:
        data = f.read()
    if data.startswith(b"AutoCAD Binary DXF"):
        return None
    lines = data.decode("latin-1").splitlines()
    pairs = [(lines[i].strip(), lines[i + 1].strip(), i + 1) for i in range(0, len(lines) - 1, 2)]
    out = []
    in_entities = False
    k = 0
    while k < len(pairs):
        code, value, line = pairs[k]
        if code == "2" and value == "ENTITIES" and k > 0 and pairs[k - 1][1] == "SECTION":
            in_entities = True
        elif code == "0" and value == "ENDSEC":
            in_entities = False
        elif in_entities and code == "0" and value == "SPLINE":
            s = {"line": line, "degree": None, "knots": [], "points": [], "weights": [],
                 "fit": 0, "flags": 0}
            k += 1
            while k < len(pairs) and pairs[k][0] != "0":
                c, v, _ = pairs[k]
                if c == "71":
                    s["degree"] = int(v)
                elif c == "70":
                    s["flags"] = int(v)
                elif c == "74":
                    s["fit"] = int(v)
                elif c == "40":
                    s["knots"].append(float(v))
                elif c == "41":
                    s["weights"].append(float(v))
                elif c == "10":
                    s["points"].append([float(v), 0.0, 0.0])
                elif c == "20":
                    s["points"][-1][1] = float(v)
                elif c == "30":
                    s["points"][-1][2] = float(v)
                elif c == "1001":
                    break
                k += 1
            out.append(s)
            continue
        k += 1
    return out


def layer_hidden(doc, name):
    layer = doc.layers.get(name) if name in doc.layers else None
    return layer is not None and (layer.is_off() or layer.is_frozen())


def expand(doc, entities, inserts, out):
    """(entity, chain of INSERT handles, hidden) for every entity, INSERTs expanded."""
    for e in entities:
        hidden = bool(e.dxf.get("invisible", 0)) or layer_hidden(doc, e.dxf.get("layer", "0"))
        if e.dxftype() == "INSERT":
            handle = e.dxf.get("handle") or "virtual"
            if e.mcount > 1:
                expand(doc, list(e.multi_insert()), inserts, out)
                continue
            for attrib in e.attribs:
                out.append((attrib, inserts + [handle], hidden))
            try:
                children = list(e.virtual_entities())
            except Exception as error:  # noqa: BLE001 - a block ezdxf cannot expand
                print(f"  INSERT {handle}: {error}", file=sys.stderr)
                children = []
            before = len(out)
            expand(doc, children, inserts + [handle], out)
            if hidden:
                out[before:] = [(x, c, True) for x, c, _ in out[before:]]
        else:
            out.append((e, inserts, hidden))


def dxf_curve(e, name, exact):
    t = e.dxftype()
    d = e.dxf
    extrusion = d.get("extrusion", Vec3(0, 0, 1))
    if t == "LINE":
        a, b = Vec3(d.start), Vec3(d.end)
        pts = [list(a + (b - a) * q) for q in QUARTERS]
        return {"kind": t, "id": name, "length": (b - a).magnitude, "points": pts}
    if t == "CIRCLE":
        pts = ocs_points(extrusion, arc_points(Vec3(d.center), d.radius, 0.0, 2 * math.pi))
        return {"kind": t, "id": name, "length": 2 * math.pi * d.radius, "points": pts}
    if t == "ARC":
        start = math.radians(d.start_angle)
        sweep = math.radians(d.end_angle) - start
        while sweep <= 0:
            sweep += 2 * math.pi
        while sweep > 2 * math.pi:
            sweep -= 2 * math.pi
        pts = ocs_points(extrusion, arc_points(Vec3(d.center), d.radius, start, sweep))
        return {"kind": t, "id": name, "length": d.radius * sweep, "points": pts}
    if t == "ELLIPSE":
        c, major = Vec3(d.center), Vec3(d.major_axis)
        minor = Vec3(extrusion).normalize().cross(major) * d.ratio
        s, e_ = d.get("start_param", 0.0), d.get("end_param", 2 * math.pi)
        sweep = e_ - s
        while sweep <= 0:
            sweep += 2 * math.pi
        while sweep > 2 * math.pi + 1e-12:
            sweep -= 2 * math.pi
        pts = [list(c + major * math.cos(s + q * sweep) + minor * math.sin(s + q * sweep))
               for q in QUARTERS]
        a, b = major.magnitude, minor.magnitude
        length = float(mpmath.quad(
            lambda u: mpmath.sqrt((a * mpmath.sin(u)) ** 2 + (b * mpmath.cos(u)) ** 2),
            [s, s + sweep]))
        return {"kind": t, "id": name, "length": length, "points": pts}
    if t == "LWPOLYLINE":
        vertices = [(x, y, b) for x, y, b in e.get_points("xyb")]
        pts, length = polyline_points(vertices, e.closed, d.get("elevation", 0.0), extrusion)
        return {"kind": t, "id": name, "length": length, "points": pts}
    if t == "POLYLINE":
        if e.is_polygon_mesh or e.is_poly_face_mesh:
            return None
        # The spline frame's control vertices are not drawn (flag 16).
        verts = [v for v in e.vertices if not v.dxf.get("flags", 0) & 16]
        if e.is_3d_polyline:
            vertices = [list(Vec3(v.dxf.location)) for v in verts]
            pts, length = [], 0.0
            count = len(vertices)
            for k in range(count if e.is_closed else count - 1):
                a, b = Vec3(vertices[k]), Vec3(vertices[(k + 1) % count])
                for q in QUARTERS:
                    append_point(pts, list(a + (b - a) * q))
                length += (b - a).magnitude
            return {"kind": t, "id": name, "length": length, "points": pts}
        vertices = [(v.dxf.location[0], v.dxf.location[1], v.dxf.get("bulge", 0.0))
                    for v in verts]
        z = Vec3(d.get("elevation", (0, 0, 0))).z
        pts, length = polyline_points(vertices, e.is_closed, z, extrusion)
        return {"kind": t, "id": name, "length": length, "points": pts}
    if t == "SPLINE":
        cps = [list(p) for p in e.control_points]
        if not cps:
            return None
        weights = [float(w) for w in e.weights] if len(e.weights) else []
        if len(e.knots) != len(cps) + d.degree + 1:
            return None
        return spline_shape(t, name, d.degree, [float(k) for k in e.knots], cps, weights,
                            exact, "ezdxf")
    return None


def dxf_reference(rel):
    path = os.path.join(REALFILES, rel)
    entry = {"file": rel, "shapes": [], "not_curves": {}, "hidden": 0}
    doc, how = None, "readfile"
    try:
        doc = ezdxf.readfile(path)
    except Exception:  # noqa: BLE001
        try:
            doc, _ = recover.readfile(path)
            how = "recover"
        except Exception as e:  # noqa: BLE001
            entry["error"] = f"ezdxf: {type(e).__name__}: {e}"
    entry["ezdxf"] = how if doc is not None else None
    ezdxf_splines = []
    if doc is not None:
        layouts = [doc.modelspace()]
        paper = doc.layouts.active_layout()
        if paper is not None and paper.name != "Model":
            layouts.append(paper)
        items = []
        for layout in layouts:
            expand(doc, list(layout), [], items)
        for e, inserts, hidden in items:
            t = e.dxftype()
            handle = e.dxf.get("handle") or "virtual"
            name = "/".join(inserts + [handle])
            if hidden:
                entry["hidden"] += 1
                continue
            if t not in CURVES:
                entry["not_curves"][t] = entry["not_curves"].get(t, 0) + 1
                continue
            shape = dxf_curve(e, name, not inserts)
            if shape is None:
                key = f"{t} (mesh, or no control points, or knots not control points + degree + 1)"
                entry["not_curves"][key] = entry["not_curves"].get(key, 0) + 1
                continue
            if t != "SPLINE" and all(p == shape["points"][0] for p in shape["points"]):
                # A LINE of length zero, a CIRCLE or ARC of radius zero: a point, no curve
                # (the importer reports it as drawing nothing).
                key = f"{t} (draws nothing: length zero)"
                entry["not_curves"][key] = entry["not_curves"].get(key, 0) + 1
                continue
            if t == "SPLINE" and not inserts:
                ezdxf_splines.append(shape)
            entry["shapes"].append(shape)
    # The group reader: a cross-check of ezdxf's SPLINEs, and the SPLINEs ezdxf cannot read.
    raw = raw_splines(path)
    if raw is not None:
        readable = [s for s in raw if s["degree"] is not None and s["knots"] and s["points"]
                    and len(s["knots"]) == len(s["points"]) + s["degree"] + 1]
        if len(ezdxf_splines) < len(readable):
            entry["shapes"] = [s for s in entry["shapes"] if s["kind"] != "SPLINE"]
            entry["not_curves"].pop(
                "SPLINE (mesh, or no control points, or knots not control points + degree + 1)",
                None)
            for s in readable:
                weights = s["weights"] if s["flags"] & 4 else []
                entry["shapes"].append(spline_shape(
                    "SPLINE", f"line {s['line']}", s["degree"], s["knots"], s["points"],
                    weights, True, "groups"))
            entry["cross_check"] = (
                f"ezdxf read {len(ezdxf_splines)} of the {len(readable)} SPLINEs of the "
                "ENTITIES section; all read by the group reader")
        else:
            same = sum(
                1 for a, b in zip(ezdxf_splines, readable)
                if a["spline"]["degree"] == b["degree"]
                and a["spline"]["knots"] == [repr(x) for x in b["knots"]]
                and a["spline"]["control_points"] == [[repr(c) for c in p] for p in b["points"]]
            )
            entry["cross_check"] = (
                f"{same} of {len(ezdxf_splines)} SPLINEs equal in ezdxf and the group reader")
        unreadable = len(raw) - len(readable)
        if unreadable:
            entry["not_curves"]["SPLINE (fit points only or no degree)"] = unreadable
    entry["size"] = size_of(entry["shapes"])
    entry["length"] = sum(s["length"] for s in entry["shapes"])
    return entry


def write(name, reader, entries):
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, name), "w") as f:
        json.dump({"reader": reader, "files": entries}, f, separators=(",", ":"))
        f.write("\n")


def main():
    global REALFILES, OUT
    if "--root" in sys.argv:
        REALFILES = os.path.abspath(sys.argv[sys.argv.index("--root") + 1])
        OUT = os.path.join(REALFILES, "reference")
    svg = []
    for rel in files_of("svg") if "--dxf-only" not in sys.argv else []:
        print(rel, file=sys.stderr, flush=True)
        svg.append(svg_reference(rel))
    if svg:
        write("svg.json", f"svgelements {se.SVGELEMENTS_VERSION}", svg)
    dxf = []
    for rel in files_of("dxf") if "--svg-only" not in sys.argv else []:
        print(rel, file=sys.stderr, flush=True)
        dxf.append(dxf_reference(rel))
    if dxf:
        write("dxf.json", f"ezdxf {ezdxf.__version__}", dxf)
    for kind, entries in (("svg", svg), ("dxf", dxf)):
        shapes = sum(len(e["shapes"]) for e in entries)
        errors = sum(1 for e in entries if "error" in e)
        print(f"{kind}: {len(entries)} files, {shapes} drawn shapes, {errors} reader errors")


if __name__ == "__main__":
    main()
