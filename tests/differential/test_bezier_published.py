"""Every published curve-curve intersection case of dhermes/bezier (its tests/functional/
curves.json and curve_intersections.json) through `neutrospline intersect`: each expected
contact once, tangencies included, no other row.

The JSON files are not in the `bezier` sdist on PyPI (bezier-2024.6.20.tar.gz holds only the
package sources) and are not committed here (data of another project). Point
NEUTROSPLINE_BEZIER_FUNCTIONAL at a folder holding both files, e.g. a checkout's
`tests/functional`; without it the test is skipped and says so.

Numbers in the files are integers, fractions "p/q" or hexadecimal doubles "0x1.8p-1"; a
fraction becomes the nearest double, so the curves are the double curves (an exact tangency of
the rational curves may become two crossings a few 1e-9 apart or a miss by about 1e-17; both
count as the one tangent contact, docs/model.md section 11). Cases of type `coincident` whose
listed parameters span an interval inside both domains must be refused as an overlap.
"""

import fractions
import json
import os
import pathlib
import subprocess
import tempfile

import pytest

from reference import Curve, write_model

FOLDER = os.environ.get("NEUTROSPLINE_BEZIER_FUNCTIONAL")
REASON = (
    "NEUTROSPLINE_BEZIER_FUNCTIONAL is not set: point it at a folder with dhermes/bezier's "
    "tests/functional/curves.json and curve_intersections.json (not in the PyPI sdist)"
)


def number(v):
    if isinstance(v, int):
        return float(v)
    if v.startswith(("0x", "-0x")):
        return float.fromhex(v)
    return float(fractions.Fraction(v))


def load():
    folder = pathlib.Path(FOLDER)
    curves = json.loads((folder / "curves.json").read_text())
    cases = json.loads((folder / "curve_intersections.json").read_text())
    return curves, cases


def bezier_curve(entry):
    xs, ys = entry["control_points"]
    pts = [(number(x), number(y)) for x, y in zip(xs, ys)]
    return Curve("bezier", len(pts) - 1, pts)


def cases():
    if not FOLDER:
        return []
    return load()[1]


def run_intersect(cli, a, b):
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        write_model(tmp / "a.json", a)
        write_model(tmp / "b.json", b)
        proc = subprocess.run([str(cli), "intersect", tmp / "a.json", tmp / "b.json"], capture_output=True, text=True, timeout=30)
    return proc


def parse_rows(text):
    import csv
    import io

    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.skipif(not FOLDER, reason=REASON)
@pytest.mark.parametrize("case", cases(), ids=lambda c: f"id{c['id']}-{c['type']}-{c['curve1']}x{c['curve2']}")
def test_published_intersection(cli, case):
    curves, _ = load()
    a, b = bezier_curve(curves[case["curve1"]]), bezier_curve(curves[case["curve2"]])
    proc = run_intersect(cli, a, b)
    s_expected = [number(v) for v in case.get("curve1_params", [])]
    t_expected = [number(v) for v in case.get("curve2_params", [])]
    context = f"bezier case {case['id']} ({case['type']}): A = {a.points}, B = {b.points}"
    overlap = case["type"] == "coincident" and "intersections" not in case
    if case["type"] == "coincident":
        # an overlap inside both domains when the note's intervals lie in [0, 1]
        note = case.get("note", "")
        overlap = "([1, 2])" not in note
    if overlap:
        assert proc.returncode != 0 and "overlap" in proc.stderr, f"{context}: expected an overlap refusal, got {proc.returncode}: {proc.stdout}{proc.stderr}"
        return
    assert proc.returncode == 0, f"{context}: exit {proc.returncode}: {proc.stderr}"
    rows = parse_rows(proc.stdout)
    got = [(float(r["t_a"]), float(r["t_b"])) for r in rows]
    tol = 1e-6 if case["type"] == "tangent" else 1e-9
    problems = []
    used = [0] * len(got)
    for s, t in zip(s_expected, t_expected):
        matches = [k for k, (sa, tb) in enumerate(got) if abs(sa - s) <= tol and abs(tb - t) <= tol]
        if not matches:
            problems.append(f"missed (s, t) = ({s!r}, {t!r})")
        elif len(matches) > 1:
            problems.append(f"(s, t) = ({s!r}, {t!r}) reported {len(matches)} times: {[got[k] for k in matches]}")
        for k in matches:
            used[k] += 1
    for k, g in enumerate(got):
        if not used[k]:
            problems.append(f"extra row {g}")
    assert not problems, f"{context}: " + "; ".join(problems) + f"; rows {got}"
