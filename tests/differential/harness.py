"""Running the command line on models and tables for the differential tests, and writing shrunk
failures as regression files (tests/differential/regressions)."""

from __future__ import annotations

import csv
import io
import json
import pathlib
import subprocess
import tempfile

from reference import Curve, Surface, write_model, write_points


class CliError(Exception):
    pass


# seconds a command may take on a test case (the cases are small: milliseconds are normal, but the
# debug build takes up to ~15 s on some tangencies today; more is counted as a hang)
TIMEOUT = 20


def _shown(args):
    return " ".join(pathlib.Path(a).name if isinstance(a, pathlib.Path) else str(a) for a in args)


def run(cli, args):
    try:
        proc = subprocess.run([str(cli), *map(str, args)], capture_output=True, text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        raise CliError(f"`neutrospline {_shown(args)}` did not finish in {TIMEOUT} s") from None
    if proc.returncode != 0:
        raise CliError(f"`neutrospline {_shown(args)}` exited {proc.returncode}: {proc.stderr.strip()}")
    return proc.stdout


def table(text):
    """The rows of a CSV table as dicts (Python's csv module)."""
    return list(csv.DictReader(io.StringIO(text)))


def query(cli, shape, points):
    """`neutrospline query MODEL POINTS.csv`: one dict per point, numbers as floats."""
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        write_model(tmp / "model.json", shape)
        write_points(tmp / "points.csv", points)
        rows = table(run(cli, ["query", tmp / "model.json", tmp / "points.csv"]))
    if len(rows) != len(points):
        raise CliError(f"query gave {len(rows)} rows for {len(points)} points")
    return [{k: (float(v) if k != "contact" and v != "" else v) for k, v in r.items()} for r in rows]


def intersect(cli, a, b=None):
    """`neutrospline intersect A B` (B = A for self-intersections): rows (t_a, t_b, x, y, contact
    or None)."""
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        write_model(tmp / "a.json", a)
        if b is not None:
            write_model(tmp / "b.json", b)
        rows = table(run(cli, ["intersect", tmp / "a.json", tmp / ("b.json" if b is not None else "a.json")]))
    return [(float(r["t_a"]), float(r["t_b"]), float(r["x"]), float(r["y"]), r.get("contact")) for r in rows]


def shape_from_json(d):
    return Surface.from_json(d) if d["kind"].endswith("surface") else Curve.from_json(d)


def write_regression(folder: pathlib.Path, prefix: str, payload: dict) -> pathlib.Path:
    """Write a shrunk failure as folder/prefix-<hash>.json, the hash of the input alone (the
    same case found again keeps its file)."""
    import hashlib

    text = json.dumps(payload, indent=1, sort_keys=True)
    # a case already saved (the same test and seed, maybe shrunk further by hand) keeps its file
    for existing in sorted(folder.glob(f"{prefix}-*.json")):
        try:
            if json.loads(existing.read_text()).get("note") == payload.get("note"):
                return existing
        except ValueError:
            continue
    key = json.dumps({k: v for k, v in payload.items() if k not in ("note", "found")}, sort_keys=True)
    name = f"{prefix}-{hashlib.sha256(key.encode()).hexdigest()[:10]}.json"
    path = folder / name
    path.write_text(text + "\n")
    return path


def _round(x, digits):
    if x == 0:
        return 0.0
    return float(f"{x:.{digits}g}")


def simpler_curves(curve: Curve):
    """Candidate simplifications of a curve: fewer control points, rounder coordinates/weights."""
    pts = curve.points
    # fewer control points
    if curve.kind == "bezier" and len(pts) > 2:
        for i in range(len(pts)):
            q = pts[:i] + pts[i + 1 :]
            yield Curve("bezier", len(q) - 1, q)
    elif curve.kind != "bezier" and len(pts) > curve.degree + 1:
        p = curve.degree
        for i in range(len(pts)):
            q = pts[:i] + pts[i + 1 :]
            w = None if curve.weights is None else curve.weights[:i] + curve.weights[i + 1 :]
            interior = curve.knots[p + 1 : len(curve.knots) - p - 1]
            for j in range(len(interior)):
                kn = curve.knots[: p + 1] + interior[:j] + interior[j + 1 :] + curve.knots[len(curve.knots) - p - 1 :]
                yield Curve(curve.kind, p, q, w, kn)
                break
    # rounder numbers
    for digits in (1, 2, 3, 6, 10):
        q = [tuple(_round(c, digits) for c in p) for p in pts]
        w = None if curve.weights is None else [_round(x, digits) for x in curve.weights]
        if q != pts or w != curve.weights:
            yield Curve(curve.kind, curve.degree, q, w, curve.knots)
    if curve.weights is not None and any(x != 1.0 for x in curve.weights):
        yield Curve("bspline", curve.degree, pts, None, curve.knots)


def shrink_curve(curve: Curve, fails, budget=40):
    """Greedy shrinking: take the first simplification that still fails, until none does or the
    budget of tries is spent. `fails(curve)` is True when the candidate still fails."""
    tries = 0
    improved = True
    while improved and tries < budget:
        improved = False
        for cand in simpler_curves(curve):
            tries += 1
            if tries > budget:
                break
            try:
                if fails(cand):
                    curve = cand
                    improved = True
                    break
            except Exception:
                continue
    return curve
