#!/usr/bin/env python3
"""Independent readers check `neutrospline export`.

Exports the repository's examples with the binary given, then reads every file with a reader
that shares no code with neutrospline and compares against `neutrospline eval` at the same
parameters:

- ezdxf reads each DXF file (auditor: no errors), its SPLINE entity has the model's degree,
  knots, weights and control points, and ezdxf's own B-spline evaluation of it gives the eval
  positions to 1e-12 of the bounding box's diagonal; the same evaluation of the control points'
  truth, indeterminacy and falsity (from the NEUTROSPLINE extended data) gives the eval degrees
  to 1e-12. A surface's POLYFACE mesh has the sample grid's vertices, with their degrees.
- plyfile reads binary and ASCII PLY files: the properties and counts docs/cli.md states, the
  eval positions and degrees exactly (doubles).
- ezdxf writes DXF R2000 splines (open and rational, plane and spatial) that
  `neutrospline import` reads back: `eval` of the imported curves agrees with ezdxf's
  evaluation to 1e-12 of scale, with the default degrees given on the command line.
- pygltflib reads .glb and .gltf files: the accessors of POSITION, _TRUTH, _INDETERMINACY and
  _FALSITY hold the eval values rounded to float32, exactly; the Khronos glTF validator
  (npm `gltf-validator`) reports no errors.
- OpenCASCADE (cadquery-ocp, the OCP bindings) reads each STEP file (STEPControl_Reader,
  TransferRoots; no message from its load and entity checks, a valid shape for BRepCheck) of
  every TOML and JSON example, and of two generated surfaces (unclamped knots, a boundary
  collapsed to a point): a curve is one edge whose Geom_BSplineCurve, a surface one face whose
  Geom_BSplineSurface, has the model's degree(s), poles (u index outer), weights, knots and
  multiplicities exactly, and OCC's Value(t) / Value(u, v) gives the eval positions to 1e-12 of
  the bounding box's diagonal; the CARTESIAN_POINT names (read through OCC's StepModel) carry
  the model's point names and degrees, and OCC's B-spline of those degrees (same knots and
  weights) gives the eval degrees to 1e-12. The maximum deviation is printed per example.
- A real viewer: three.js (npm `three`) loads the .glb of the example surface in headless
  Chromium and draws it with its vertex colours, blue-dominant where the truth is low and
  green-dominant where it is high (viridis). Skipped when Chromium is not installed, unless
  NEUTROSPLINE_REQUIRE_BROWSER=1.

Usage: check_exports.py BIN EXAMPLES_DIR WORK_DIR NODE_MODULES_DIR
Exit status 0 when every check passes, 1 on a failed check, 77 when a reader is missing.
"""

import csv
import functools
import http.server
import io
import json
import math
import os
import shutil
import subprocess
import sys
import threading
import tomllib  # Python 3.11 or later

MISSING = 77

try:
    import ezdxf
    import numpy as np
    import pygltflib
    from ezdxf.math import BSpline
    from plyfile import PlyData
    from OCP.BRep import BRep_Tool
    from OCP.BRepCheck import BRepCheck_Analyzer
    from OCP.Geom import Geom_BSplineCurve, Geom_BSplineSurface
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.Interface import Interface_CheckTool
    from OCP.STEPControl import STEPControl_Reader
    from OCP.StepBasic import StepBasic_Product
    from OCP.StepGeom import StepGeom_CartesianPoint
    from OCP.collections import Array1_double, Array1_gp_Pnt, Array1_int, Array2_double, Array2_gp_Pnt
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer
    from OCP.TopoDS import TopoDS
    from OCP.gp import gp_Pnt
except ImportError as error:
    print(f"missing reader: {error}", file=sys.stderr)
    sys.exit(MISSING)

BIN, EXAMPLES, WORK, NODE_MODULES = sys.argv[1:5]
VALIDATOR = os.path.join(NODE_MODULES, "gltf-validator")
for package in ["gltf-validator", "three"]:
    if not os.path.isdir(os.path.join(NODE_MODULES, package)):
        print(f"missing reader: npm package {package} is not in {NODE_MODULES}", file=sys.stderr)
        sys.exit(MISSING)

CHECKS = 0


def check(condition, message):
    global CHECKS
    CHECKS += 1
    if not condition:
        raise AssertionError(message)


def run(*args):
    result = subprocess.run([BIN, *args], capture_output=True, text=True)
    check(result.returncode == 0, f"neutrospline {' '.join(args)}: {result.stderr}")
    return result.stdout


def export(model, out, *options):
    path = os.path.join(WORK, out)
    run("export", os.path.join(EXAMPLES, model), "-o", path, *options)
    return path


def eval_table(model, samples):
    """The rows of `neutrospline eval MODEL --samples N` as dictionaries of floats."""
    text = run("eval", os.path.join(EXAMPLES, model), "--samples", str(samples))
    return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(io.StringIO(text))]


def model_info(model):
    """The model file's own data (TOML or JSON), read without neutrospline."""
    path = os.path.join(EXAMPLES, model)
    if path.endswith(".json"):
        with open(path) as f:
            return json.load(f)
    with open(path, "rb") as f:
        return tomllib.load(f)


def degree_of(point, *names):
    for name in names:
        if name in point:
            return float(point[name])
    return 0.0


def control_rows(model):
    info = model_info(model)
    rows = []
    for p in info["control_points"]:
        rows.append(
            (
                [float(p["x"]), float(p["y"]), float(p.get("z", 0.0))],
                [
                    degree_of(p, "truth", "T"),
                    degree_of(p, "indeterminacy", "I"),
                    degree_of(p, "falsity", "F"),
                ],
                float(p.get("weight", 1.0)),
            )
        )
    if info.get("periodic"):
        # A periodic curve lists its distinct points; the spline repeats the first `degree`.
        n = len(rows)
        rows += [rows[i % n] for i in range(info["degree"])]
    return info, rows


def check_dxf_curve(model):
    path = export(model, model.rsplit(".", 1)[0] + ".dxf")
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    check(not auditor.errors, f"{path}: ezdxf audit: {[e.message for e in auditor.errors]}")
    entities = list(doc.modelspace())
    check([e.dxftype() for e in entities] == ["SPLINE"], f"{path}: one SPLINE")
    spline = entities[0]
    info, rows = control_rows(model)
    n = len(rows)
    check(spline.dxf.degree == info.get("degree", n - 1), f"{path}: degree")
    knots = list(spline.knots)
    if info["kind"] == "bezier":
        check(knots == [0.0] * n + [1.0] * n, f"{path}: a Bezier curve's clamped knots")
    else:
        check(knots == [float(k) for k in info["knots"]], f"{path}: knots")
    weights = list(spline.weights)
    expected_weights = [w for _, _, w in rows] if info["kind"] == "nurbs" else []
    check(weights == expected_weights, f"{path}: weights {weights}")
    points = [list(p) for p in spline.control_points]
    check(points == [p for p, _, _ in rows], f"{path}: control points")
    # The degrees of the extended data: after "degrees", the count, then the triples.
    xdata = [(tag.code, tag.value) for tag in spline.get_xdata("NEUTROSPLINE")]
    at = xdata.index((1000, "degrees"))
    check(xdata[at + 1] == (1071, n), f"{path}: degree count")
    degrees = [v for _, v in xdata[at + 2 : at + 2 + 3 * n]]
    check(degrees == [d for _, triple, _ in rows for d in triple], f"{path}: XDATA degrees")
    # ezdxf's evaluation of the positions and of the degrees against eval.
    table = eval_table(model, 41)
    kwargs = {"order": spline.dxf.degree + 1, "knots": knots}
    if weights:
        kwargs["weights"] = weights
    position_curve = BSpline(points, **kwargs)
    degree_curve = BSpline([triple for _, triple, _ in rows], **kwargs)
    lo = np.min([p for p, _, _ in rows], axis=0)
    hi = np.max([p for p, _, _ in rows], axis=0)
    scale = float(np.linalg.norm(hi - lo))
    worst_position = worst_degree = 0.0
    for row in table:
        x = position_curve.point(row["t"])
        d = degree_curve.point(row["t"])
        expected = [row["x"], row["y"], row.get("z", 0.0)]
        worst_position = max(worst_position, max(abs(a - b) for a, b in zip(x, expected)))
        got = [d.x, d.y, d.z]
        want = [row["truth"], row["indeterminacy"], row["falsity"]]
        worst_degree = max(worst_degree, max(abs(a - b) for a, b in zip(got, want)))
    check(worst_position <= 1e-12 * scale, f"{path}: ezdxf positions off by {worst_position}")
    check(worst_degree <= 1e-12, f"{path}: ezdxf degrees off by {worst_degree}")
    print(f"ok  {os.path.basename(path)}: ezdxf SPLINE degree {spline.dxf.degree}, "
          f"{len(knots)} knots, {len(weights)} weights; positions within {worst_position:.1e}, "
          f"degrees within {worst_degree:.1e} of eval")


def check_dxf_mesh():
    path = export("surface.toml", "surface-mesh.dxf", "--mesh", "--samples", "6")
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    check(not auditor.errors, f"{path}: ezdxf audit: {[e.message for e in auditor.errors]}")
    entities = list(doc.modelspace())
    check([e.dxftype() for e in entities] == ["POLYLINE"], f"{path}: one POLYLINE")
    mesh = entities[0]
    check(mesh.is_poly_face_mesh, f"{path}: a polyface mesh")
    vertices = [v for v in mesh.vertices if v.is_poly_face_mesh_vertex]
    faces = list(mesh.faces())
    check((len(vertices), len(faces)) == (36, 50), f"{path}: {len(vertices)} vertices, {len(faces)} faces")
    table = eval_table("surface.toml", 6)
    expected = {(r["x"], r["y"], r["z"]): (r["truth"], r["indeterminacy"], r["falsity"]) for r in table}
    for v in vertices:
        location = tuple(v.dxf.location)
        check(location in expected, f"{path}: vertex {location} is not an eval sample")
        xdata = [tag.value for tag in v.get_xdata("NEUTROSPLINE")]
        check(tuple(xdata[-3:]) == expected[location], f"{path}: degrees of vertex {location}")
    print(f"ok  {os.path.basename(path)}: ezdxf POLYFACE mesh, 36 vertices with their degrees, 50 faces")


PLY_CURVE = ["x", "y", "z", "red", "green", "blue", "truth", "indeterminacy", "falsity"]


def check_ply(model, samples, *options):
    suffix = "-ascii" if "--ascii" in options else ""
    path = export(model, model.rsplit(".", 1)[0] + suffix + ".ply", "--samples", str(samples), *options)
    ply = PlyData.read(path)
    check(ply.text == ("--ascii" in options), f"{path}: text or binary")
    vertex = ply["vertex"]
    names = [p.name for p in vertex.properties]
    table = eval_table(model, samples)
    surface = "u" in table[0]
    expected_names = PLY_CURVE[:3] + (["nx", "ny", "nz"] if surface else []) + PLY_CURVE[3:]
    check(names == expected_names, f"{path}: properties {names}")
    check(vertex.count == len(table), f"{path}: {vertex.count} vertices")
    for k, row in enumerate(table):
        got = [float(vertex[name][k]) for name in ["x", "y", "z", "truth", "indeterminacy", "falsity"]]
        want = [row["x"], row["y"], row.get("z", 0.0), row["truth"], row["indeterminacy"], row["falsity"]]
        check(got == want, f"{path}: vertex {k}: {got} != {want}")
    if surface:
        faces = ply["face"]
        check(faces.count == 2 * (samples - 1) ** 2, f"{path}: {faces.count} faces")
        check(all(len(f) == 3 for f in faces["vertex_indices"]), f"{path}: triangles")
    else:
        edges = ply["edge"]
        check(edges.count == samples - 1, f"{path}: {edges.count} edges")
        check(list(edges["vertex1"]) == list(range(samples - 1)), f"{path}: edges")
    print(f"ok  {os.path.basename(path)}: plyfile, {vertex.count} vertices equal to eval")


def accessor_values(gltf, index):
    accessor = gltf.accessors[index]
    view = gltf.bufferViews[accessor.bufferView]
    data = gltf.binary_blob() if gltf.buffers[0].uri is None else gltf.get_data_from_buffer_uri(gltf.buffers[0].uri)
    components = {"SCALAR": 1, "VEC3": 3}[accessor.type]
    start = view.byteOffset + (accessor.byteOffset or 0)
    values = np.frombuffer(data, dtype="<f4", count=accessor.count * components, offset=start)
    return values.reshape(accessor.count, components)


def check_gltf(model, samples, out):
    path = export(model, out, "--samples", str(samples))
    gltf = pygltflib.GLTF2().load(path)
    primitive = gltf.meshes[0].primitives[0]
    table = eval_table(model, samples)
    surface = "u" in table[0]
    check(primitive.mode == (4 if surface else 3), f"{path}: mode {primitive.mode}")
    attributes = primitive.attributes
    positions = accessor_values(gltf, attributes.POSITION)
    want = np.array([[r["x"], r["y"], r.get("z", 0.0)] for r in table], dtype=np.float32)
    check(np.array_equal(positions, want), f"{path}: POSITION")
    custom = {"_TRUTH": "truth", "_INDETERMINACY": "indeterminacy", "_FALSITY": "falsity"}
    for attribute, column in custom.items():
        values = accessor_values(gltf, getattr(attributes, attribute))[:, 0]
        check(np.array_equal(values, np.array([r[column] for r in table], dtype=np.float32)), f"{path}: {attribute}")
    if surface:
        check(attributes.NORMAL is not None, f"{path}: NORMAL")
    check(gltf.asset.extras.get("kind") == model_info(model)["kind"], f"{path}: asset.extras")
    report = json.loads(
        subprocess.run(
            ["node", "-e", VALIDATE, path],
            capture_output=True,
            text=True,
            check=True,
            env={**os.environ, "NODE_PATH": NODE_MODULES},
        ).stdout
    )
    issues = report["issues"]
    errors = [m for m in issues["messages"] if m["severity"] == 0]
    check(issues["numErrors"] == 0, f"{path}: glTF validator errors: {errors}")
    print(f"ok  {os.path.basename(path)}: pygltflib, {len(table)} vertices equal to eval in float32; "
          f"glTF validator: {issues['numErrors']} errors, {issues['numWarnings']} warnings")


VALIDATE = """
const validator = require('gltf-validator');
const fs = require('fs');
const path = process.argv[1];
validator.validateBytes(new Uint8Array(fs.readFileSync(path)))
  .then((report) => console.log(JSON.stringify(report)))
  .catch((error) => { console.error(error); process.exit(1); });
"""


def check_ezdxf_import():
    """Splines written by ezdxf, imported by neutrospline, evaluated by both."""
    doc = ezdxf.new("R2000")
    msp = doc.modelspace()
    plane = [(0, 0, 0), (1, 2, 0), (3, 3, 0), (4, 1, 0), (6, 0, 0)]
    spatial = [(1, 0, 0), (1, 0.5, 0.25), (0.5, 1, 0.5), (0, 1, 0.75), (-0.5, 1, 1)]
    weights = [1, 0.5, 2, 0.75, 1]
    knots = [0, 0, 0, 0, 0.4, 1, 1, 1, 1]
    splines = [
        msp.add_open_spline(plane, degree=3, knots=knots),
        msp.add_rational_spline(spatial, weights, degree=2, knots=[0, 0, 0, 0.25, 0.5, 1, 1, 1]),
    ]
    path = os.path.join(WORK, "ezdxf.dxf")
    doc.saveas(path)
    out = os.path.join(WORK, "ezdxf.json")
    run("import", path, "-o", out, "--all", "--truth", "0.5", "--indeterminacy", "0.25", "--falsity", "0.125")
    for k, spline in enumerate(splines, start=1):
        model = os.path.join(WORK, f"ezdxf-{k}.json")
        with open(model) as f:
            data = json.load(f)
        check(data["kind"] == ("nurbs" if k == 2 else "bspline"), f"{model}: kind {data['kind']}")
        tool = spline.construction_tool()
        ts = [i / 20 for i in range(21)]
        text = run("eval", model, "--at", ",".join(repr(t) for t in ts))
        rows = [{key: float(v) for key, v in row.items()} for row in csv.DictReader(io.StringIO(text))]
        points = [list(p) for p in spline.control_points]
        scale = float(np.linalg.norm(np.max(points, axis=0) - np.min(points, axis=0)))
        worst = 0.0
        for row in rows:
            x = tool.point(row["t"])
            worst = max(worst, abs(x.x - row["x"]), abs(x.y - row["y"]), abs(x.z - row.get("z", 0.0)))
            check((row["truth"], row["indeterminacy"], row["falsity"]) == (0.5, 0.25, 0.125), f"{model}: degrees")
        check(("z" in rows[0]) == (k == 2), f"{model}: a plane curve has no z")
        check(worst <= 1e-12 * scale, f"{model}: eval off ezdxf by {worst}")
        print(f"ok  {os.path.basename(model)}: imported from ezdxf, eval within {worst:.1e} of ezdxf")


def periodic_knots(info, degree, count):
    """The knots of a periodic curve (docs/model.md, "Knot vectors"): its breakpoints tau_0 ..
    tau_n (listed, uniform, or chord-length along the closed control polygon) extended by the
    period T: u_{p+j} = tau_j, then tau_{j mod n} + floor(j / n) T."""
    n = count - degree
    rule = info.get("knots", "uniform")
    if rule == "uniform":
        breakpoints = [j / n for j in range(n + 1)]
    elif rule == "chord-length":
        points = [[float(p["x"]), float(p["y"])] + ([float(p["z"])] if "z" in p else []) for p in info["control_points"]]
        steps = [math.sqrt(sum((a - b) * (a - b) for a, b in zip(points[k], points[(k + 1) % n]))) for k in range(n)]
        total = sum(steps)
        breakpoints, acc = [0.0], 0.0
        for step in steps[:-1]:
            acc += step
            breakpoints.append(min(acc / total, 1.0))
        breakpoints.append(1.0)
    else:
        check(isinstance(rule, list), f"periodic knot rule {rule!r} is not one this check knows")
        breakpoints = [float(k) for k in rule]
    period = breakpoints[n] - breakpoints[0]
    knots = []
    for i in range(n + 2 * degree + 1):
        j = i - degree
        knots.append(breakpoints[j] if 0 <= j <= n else breakpoints[j % n] + (j // n) * period)
    return knots


def model_knots(info, key, degree, count):
    """A direction's knots from the model file: listed, the rule `clamped-uniform`, a periodic
    curve's ([`periodic_knots`]), or a Bezier one's p + 1 zeros and p + 1 ones."""
    if key == "knots" and info.get("periodic"):
        return periodic_knots(info, degree, count)
    knots = info.get(key)
    if knots is None:
        return [0.0] * (degree + 1) + [1.0] * (degree + 1)
    if knots == "clamped-uniform":
        spans = count - degree
        return [0.0] * (degree + 1) + [j / spans for j in range(1, spans)] + [1.0] * (degree + 1)
    check(isinstance(knots, list), f"knot rule {knots!r} is not one this check knows")
    return [float(k) for k in knots]


def flat_knots(knot_values, multiplicities):
    return [k for k, m in zip(knot_values, multiplicities) for _ in range(m)]


def read_step(path):
    """OCC's shape of the file and the (name, coordinates) of its CARTESIAN_POINTs; checks
    that its one PRODUCT has the model's name (or kind) and description."""
    reader = STEPControl_Reader()
    check(reader.ReadFile(path) == IFSelect_RetDone, f"{path}: OCC could not read the file")
    # OCC's checks of the file as it loaded it (syntax) and of every entity against the
    # schema (parameter counts and types): no failure and no warning.
    check(reader.WS().ModelCheckList().IsEmpty(False), f"{path}: OCC's load check has messages")
    check(Interface_CheckTool(reader.StepModel()).CompleteCheckList().IsEmpty(False),
          f"{path}: OCC's entity check has messages")
    check(reader.TransferRoots() == 1, f"{path}: OCC transferred no shape")
    check(BRepCheck_Analyzer(reader.OneShape()).IsValid(), f"{path}: OCC's shape is not valid (BRepCheck)")
    model = reader.StepModel()
    points = []
    products = []
    for k in range(1, model.NbEntities() + 1):
        entity = model.Value(k)
        if isinstance(entity, StepBasic_Product):
            products.append((entity.Name().ToCString(), entity.Description().ToCString()))
        if isinstance(entity, StepGeom_CartesianPoint):
            coordinates = [entity.CoordinatesValue(c) for c in range(1, entity.NbCoordinates() + 1)]
            points.append((entity.Name().ToCString(), coordinates))
    info = model_info_of(path)
    expected = (info.get("name", info["kind"]), info.get("description", ""))
    check(products == [expected], f"{path}: products {products}, not {[expected]}")
    return reader.OneShape(), points


def subshapes(shape, kind, cast):
    found = []
    explorer = TopExp_Explorer(shape, kind)
    while explorer.More():
        found.append(cast(explorer.Current()))
        explorer.Next()
    return found


def check_point_names(path, points, rows):
    """The CARTESIAN_POINTs named `NAME T=t I=i F=f`, in the model's order, at the model's
    control points; returns their degrees."""
    info = model_info_of(path)
    named = [(name, xyz) for name, xyz in points if " T=" in name]
    check(len(named) == len(rows), f"{path}: {len(named)} named points, {len(rows)} control points")
    degrees = []
    for k, ((name, xyz), (position, triple, _)) in enumerate(zip(named, rows)):
        fields = name.split(" ")
        label = " ".join(fields[:-3])
        # A periodic curve's repeated points carry the names of the points they repeat.
        listed = info["control_points"]
        expected_label = listed[k % len(listed)].get("name", f"P{k}")
        check(label == expected_label, f"{path}: point {k} is named {label!r}, not {expected_label!r}")
        check([f[:2] for f in fields[-3:]] == ["T=", "I=", "F="], f"{path}: point name {name!r}")
        values = [float(f[2:]) for f in fields[-3:]]
        check(values == triple, f"{path}: point {k}: degrees {values} != {triple}")
        check(xyz == position, f"{path}: point {k} at {xyz}, not {position}")
        degrees.append(values)
    return degrees


STEP_MODELS = {}


def model_info_of(path):
    return model_info(STEP_MODELS[path])


def scale_of(rows):
    lo = np.min([p for p, _, _ in rows], axis=0)
    hi = np.max([p for p, _, _ in rows], axis=0)
    return float(np.linalg.norm(hi - lo))


def real_array(values):
    array = Array1_double(1, len(values))
    for k, v in enumerate(values, start=1):
        array.SetValue(k, float(v))
    return array


def int_array(values):
    array = Array1_int(1, len(values))
    for k, v in enumerate(values, start=1):
        array.SetValue(k, int(v))
    return array


def curve_knots(curve):
    values = [curve.Knot(k) for k in range(1, curve.NbKnots() + 1)]
    multiplicities = [curve.Multiplicity(k) for k in range(1, curve.NbKnots() + 1)]
    return values, multiplicities


def check_step_curve(model):
    path = export(model, os.path.basename(model).replace(".", "-") + ".step")
    STEP_MODELS[path] = model
    shape, points = read_step(path)
    edges = subshapes(shape, TopAbs_EDGE, TopoDS.Edge)
    check(len(edges) == 1, f"{path}: {len(edges)} edges, not 1")
    curve = BRep_Tool.Curve_s(edges[0], 0.0, 0.0)
    check(isinstance(curve, Geom_BSplineCurve), f"{path}: OCC's curve is a {type(curve).__name__}")
    info, rows = control_rows(model)
    n = len(rows)
    degree = info.get("degree", n - 1)
    check(curve.Degree() == degree, f"{path}: degree {curve.Degree()} != {degree}")
    poles = [list(curve.Pole(k).Coord()) for k in range(1, curve.NbPoles() + 1)]
    check(poles == [p for p, _, _ in rows], f"{path}: poles {poles}")
    weights = [curve.Weight(k) for k in range(1, curve.NbPoles() + 1)]
    check(weights == [w for _, _, w in rows], f"{path}: weights {weights}")
    check(curve.IsRational() == (info["kind"] == "nurbs"), f"{path}: rational")
    values, multiplicities = curve_knots(curve)
    knots = model_knots(info, "knots", degree, n)
    check(flat_knots(values, multiplicities) == knots, f"{path}: knots {values} x {multiplicities}")
    degrees = check_point_names(path, points, rows)
    # OCC's B-spline of the degrees: the same knots and weights, the degrees as poles.
    degree_poles = Array1_gp_Pnt(1, n)
    for k, triple in enumerate(degrees, start=1):
        degree_poles.SetValue(k, gp_Pnt(*triple))
    degree_curve = Geom_BSplineCurve(
        degree_poles, real_array(weights), real_array(values), int_array(multiplicities), degree
    )
    table = eval_table(model, 41)
    scale = scale_of(rows)
    worst_position = worst_degree = 0.0
    for row in table:
        x = curve.Value(row["t"]).Coord()
        d = degree_curve.Value(row["t"]).Coord()
        expected = [row["x"], row["y"], row.get("z", 0.0)]
        worst_position = max(worst_position, max(abs(a - b) for a, b in zip(x, expected)))
        want = [row["truth"], row["indeterminacy"], row["falsity"]]
        worst_degree = max(worst_degree, max(abs(a - b) for a, b in zip(d, want)))
    check(worst_position <= 1e-12 * scale, f"{path}: OCC positions off by {worst_position}")
    check(worst_degree <= 1e-12, f"{path}: OCC degrees off by {worst_degree}")
    print(f"ok  {os.path.basename(path)}: OCC Geom_BSplineCurve degree {degree}, {n} poles, "
          f"{len(values)} distinct knots; positions within {worst_position:.1e} "
          f"({worst_position / scale:.1e} of scale), degrees within {worst_degree:.1e} of eval")


def named_curve():
    """A model file in WORK whose names need STEP's string encoding: quotes, a backslash,
    characters outside ASCII and beyond the Basic Multilingual Plane, a line break."""
    text = "\n".join([
        'kind = "bspline"',
        'name = "caf\u00e9 \u03a9 \U0001F600 \'q\' \\\\ end"',
        'description = "two\\nlines"',
        "degree = 1",
        "knots = [0, 0, 1, 1]",
        "control_points = [",
        '  { name = "\u00c4 1", x = 0, y = 0, truth = 0.5, indeterminacy = 0.25, falsity = 0 },',
        "  { x = 1, y = -1e-9, truth = 1, indeterminacy = 0, falsity = 0 },",
        "]", "",
    ])
    path = os.path.join(os.path.abspath(WORK), "named-curve.toml")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def unclamped_surface():
    """A model file in WORK: a biquadratic B-spline surface over unclamped uniform knots, whose
    STEP boundaries are iso-parameter curves rather than rows of the grid."""
    points = []
    for i in range(4):
        for j in range(3):
            t = i / 3
            points.append(f'  {{ x = {i}, y = {j}, z = {(i * j) % 3 * 0.5}, truth = {t!r}, '
                          f'indeterminacy = 0.25, falsity = {1 - t!r} }},')
    text = "\n".join([
        'kind = "bspline-surface"',
        'name = "unclamped patch"',
        "rows = 4", "cols = 3", "degree_u = 2", "degree_v = 2",
        "knots_u = [0, 1, 2, 3, 4, 5, 6]",
        "knots_v = [0, 0.5, 1, 1.5, 2, 2.5]",
        "control_points = [", *points, "]", "",
    ])
    path = os.path.join(os.path.abspath(WORK), "unclamped-surface.toml")
    with open(path, "w") as f:
        f.write(text)
    return path


def apex_surface():
    """A model file in WORK: a bicubic Bezier surface whose first row is one point (an apex),
    so the STEP face is bounded by three edges."""
    points = []
    for i in range(4):
        for j in range(4):
            x, y, z = (0.0, 1.5, 2.0) if i == 0 else (float(i), float(j), float((i + j) % 2))
            points.append(f"  {{ x = {x!r}, y = {y!r}, z = {z!r}, truth = {0.25 * j!r}, "
                          f"indeterminacy = 0.5, falsity = {0.125 * i!r} }},")
    text = "\n".join(['kind = "bezier-surface"', "rows = 4", "cols = 4",
                      "control_points = [", *points, "]", ""])
    path = os.path.join(os.path.abspath(WORK), "apex-surface.toml")
    with open(path, "w") as f:
        f.write(text)
    return path


def check_step_surface(model):
    path = export(model, os.path.basename(model).replace(".", "-") + ".stp")
    STEP_MODELS[path] = model
    shape, points = read_step(path)
    faces = subshapes(shape, TopAbs_FACE, TopoDS.Face)
    check(len(faces) == 1, f"{path}: {len(faces)} faces, not 1")
    surface = BRep_Tool.Surface_s(faces[0])
    check(isinstance(surface, Geom_BSplineSurface), f"{path}: OCC's surface is a {type(surface).__name__}")
    info, rows = control_rows(model)
    nu, nv = int(info["rows"]), int(info["cols"])
    du, dv = info.get("degree_u", nu - 1), info.get("degree_v", nv - 1)
    check((surface.UDegree(), surface.VDegree()) == (du, dv), f"{path}: degrees")
    check((surface.NbUPoles(), surface.NbVPoles()) == (nu, nv), f"{path}: a {nu} x {nv} grid")
    # Pole (i, j) of OCC is the model's row i (along u), column j (along v): row by row.
    for i in range(nu):
        for j in range(nv):
            position, _, weight = rows[i * nv + j]
            pole = list(surface.Pole(i + 1, j + 1).Coord())
            check(pole == position, f"{path}: pole ({i}, {j}) {pole} != {position}")
            check(surface.Weight(i + 1, j + 1) == weight, f"{path}: weight ({i}, {j})")
    u_values = [surface.UKnot(k) for k in range(1, surface.NbUKnots() + 1)]
    u_mults = [surface.UMultiplicity(k) for k in range(1, surface.NbUKnots() + 1)]
    v_values = [surface.VKnot(k) for k in range(1, surface.NbVKnots() + 1)]
    v_mults = [surface.VMultiplicity(k) for k in range(1, surface.NbVKnots() + 1)]
    check(flat_knots(u_values, u_mults) == model_knots(info, "knots_u", du, nu), f"{path}: knots_u")
    check(flat_knots(v_values, v_mults) == model_knots(info, "knots_v", dv, nv), f"{path}: knots_v")
    degrees = check_point_names(path, points, rows)
    degree_poles = Array2_gp_Pnt(1, nu, 1, nv)
    weights = Array2_double(1, nu, 1, nv)
    for i in range(nu):
        for j in range(nv):
            degree_poles.SetValue(i + 1, j + 1, gp_Pnt(*degrees[i * nv + j]))
            weights.SetValue(i + 1, j + 1, rows[i * nv + j][2])
    degree_surface = Geom_BSplineSurface(
        degree_poles, weights, real_array(u_values), real_array(v_values),
        int_array(u_mults), int_array(v_mults), du, dv,
    )
    table = eval_table(model, 13)  # steps of 1/12 of each domain: not binary fractions
    scale = scale_of(rows)
    worst_position = worst_degree = 0.0
    for row in table:
        x = surface.Value(row["u"], row["v"]).Coord()
        d = degree_surface.Value(row["u"], row["v"]).Coord()
        expected = [row["x"], row["y"], row["z"]]
        worst_position = max(worst_position, max(abs(a - b) for a, b in zip(x, expected)))
        want = [row["truth"], row["indeterminacy"], row["falsity"]]
        worst_degree = max(worst_degree, max(abs(a - b) for a, b in zip(d, want)))
    check(worst_position <= 1e-12 * scale, f"{path}: OCC positions off by {worst_position}")
    check(worst_degree <= 1e-12, f"{path}: OCC degrees off by {worst_degree}")
    edges = subshapes(faces[0], TopAbs_EDGE, TopoDS.Edge)
    print(f"ok  {os.path.basename(path)}: OCC Geom_BSplineSurface degrees {du} x {dv}, {nu} x {nv} "
          f"poles, a face of {len(edges)} edges; positions within {worst_position:.1e} "
          f"({worst_position / scale:.1e} of scale), degrees within {worst_degree:.1e} of eval")



VIEWER = """<!doctype html>
<html><head><style>body { margin: 0; background: #fff; }</style>
<script type="importmap">{"imports": {"three": "./three/build/three.module.js",
  "three/addons/": "./three/examples/jsm/"}}</script></head>
<body><pre id="result">pending</pre><script type="module">
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
const out = document.getElementById("result");
const renderer = new THREE.WebGLRenderer({ preserveDrawingBuffer: true });
renderer.setSize(400, 300);
renderer.setClearColor(0xffffff);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.add(new THREE.AmbientLight(0xffffff, 1.5));
const light = new THREE.DirectionalLight(0xffffff, 2);
light.position.set(3, 5, 4);
scene.add(light);
new GLTFLoader().load("./model.glb", (gltf) => {
  scene.add(gltf.scene);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const c = box.getCenter(new THREE.Vector3());
  const s = box.getSize(new THREE.Vector3()).length();
  const camera = new THREE.PerspectiveCamera(40, 4 / 3, s / 100, s * 10);
  camera.position.set(c.x + 0.6 * s, c.y + 0.6 * s, c.z + 0.9 * s);
  camera.lookAt(c);
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const pixels = new Uint8Array(400 * 300 * 4);
  gl.readPixels(0, 0, 400, 300, gl.RGBA, gl.UNSIGNED_BYTE, pixels);
  let drawn = 0, green = 0, blue = 0;
  for (let k = 0; k < pixels.length; k += 4) {
    const [r, g, b] = [pixels[k], pixels[k + 1], pixels[k + 2]];
    if (r > 250 && g > 250 && b > 250) continue;
    drawn++;
    if (g > r + 20 && g > b + 20) green++;
    if (b > r + 20 && b > g + 5) blue++;
  }
  out.textContent = JSON.stringify({ drawn, green, blue });
}, undefined, (error) => { out.textContent = JSON.stringify({ error: String(error) }); });
</script></body></html>
"""


def check_browser():
    """three.js draws the exported surface in headless Chromium, in its vertex colours."""
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        if os.environ.get("NEUTROSPLINE_REQUIRE_BROWSER") == "1":
            check(False, "NEUTROSPLINE_REQUIRE_BROWSER=1 but no chromium on the PATH")
        print("skipped: the three.js view (chromium is not installed)")
        return
    site = os.path.join(WORK, "site")
    os.makedirs(site, exist_ok=True)
    export("surface.toml", os.path.join("site", "model.glb"))
    with open(os.path.join(site, "index.html"), "w") as f:
        f.write(VIEWER)
    link = os.path.join(site, "three")
    if not os.path.exists(link):
        os.symlink(os.path.abspath(os.path.join(NODE_MODULES, "three")), link)
    handler = functools.partial(QuietHandler, directory=site)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        url = f"http://127.0.0.1:{server.server_address[1]}/index.html"
        result = subprocess.run(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
             "--enable-unsafe-swiftshader", "--no-first-run", "--disable-background-networking",
             "--disable-component-update", "--disable-sync", "--virtual-time-budget=10000",
             f"--user-data-dir={os.path.join(WORK, 'profile')}", "--dump-dom", url],
            capture_output=True, text=True, timeout=120,
        )
    finally:
        server.shutdown()
    dom = result.stdout
    start = dom.find('<pre id="result">')
    check(start >= 0, f"chromium printed no page: {result.stderr[-2000:]}")
    text = dom[start + len('<pre id="result">'):dom.find("</pre>", start)]
    check(text != "pending", "three.js did not finish drawing the model")
    counts = json.loads(text)
    check("error" not in counts, f"three.js could not load the export: {counts}")
    check(counts["drawn"] > 0.1 * 400 * 300, f"the surface covers too little of the view: {counts}")
    check(counts["green"] > 1000 and counts["blue"] > 1000, f"the vertex colours are not viridis: {counts}")
    print(f"ok  surface.glb in three.js (headless Chromium): {counts['drawn']} pixels drawn, "
          f"{counts['green']} green-dominant (high truth), {counts['blue']} blue-dominant (low truth)")


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    """Serves the viewer's files without a log line per request."""

    def log_message(self, format, *args):
        pass


def main():
    os.makedirs(WORK, exist_ok=True)
    for model in ["example1.toml", "helix3d.toml", "bspline.toml", "nurbs-circle.toml"]:
        check_dxf_curve(model)
    check_dxf_mesh()
    check_ezdxf_import()
    check_ply("example1.toml", 21)
    check_ply("helix3d.toml", 17, "--ascii")
    check_ply("surface.toml", 7)
    check_ply("nurbs-surface.json", 5, "--ascii")
    check_gltf("example1.toml", 33, "example1.glb")
    check_gltf("helix3d.toml", 9, "helix3d.gltf")
    check_gltf("surface.toml", 8, "surface.glb")
    check_gltf("nurbs-surface.json", 6, "nurbs-surface.gltf")
    # Every TOML and JSON model of the examples (the CSV tables are curves of these).
    step_models = sorted(f for f in os.listdir(EXAMPLES) if f.endswith((".toml", ".json")))
    check(len(step_models) >= 8, f"only {len(step_models)} example models in {EXAMPLES}")
    for model in step_models:
        if model_info(model)["kind"].endswith("-surface"):
            check_step_surface(model)
        else:
            check_step_curve(model)
    check_step_curve(named_curve())
    check_step_surface(unclamped_surface())
    check_step_surface(apex_surface())
    check_browser()
    print(f"{CHECKS} checks passed")


if __name__ == "__main__":
    try:
        main()
    except AssertionError as error:
        print(f"FAILED: {error}", file=sys.stderr)
        sys.exit(1)
