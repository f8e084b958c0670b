"""CSV framing against Python's csv module (issue 22).

Files are written with Python's csv module (dialects excel, excel with QUOTE_ALL, QUOTE_MINIMAL
with LF line ends; with and without a byte order mark, written as utf-8-sig) with hostile cells
(quotes, commas, CR, LF, spaces, `#`, a BOM, non-ASCII), comment and empty lines between the
rows, and rows written by hand with a stray quote inside an unquoted name (`C"0`) or a bad
cell. Each file is read by the command line and, independently, by Python's csv module with
the model's rules written out here:

- a UTF-8 byte order mark at the start is dropped;
- where a row could start, a line starting with `#` is a comment, up to its `\\n`;
- cells are trimmed of Unicode White_Space; a row of one empty cell is an empty line;
- the first row is the header; every other row needs one cell per column, numbers are
  decimal numbers (finite), degrees lie in [0, 1];
- a file that ends inside a quoted cell is refused on the line where that row starts;
- a comment after the header that holds a full row (as many comma-separated cells as the
  header, at least 3, no quote, every cell after the first a number) is refused on its line:
  a name starting with `#` written unquoted would otherwise be dropped without a word.

The reader must give the same rows (count, names, numbers) or refuse, exit 1, naming the line
of the first bad row. Three formats: control points (`export FILE -o OUT.dxf`, which keeps the
positions, the degrees and the point names exactly), data tables (`fit DATA --interpolate
--degree 1 --parametrization uniform`: the control points are the data points) and query
points (`query SEGMENT POINTS`: the nearest point of a long horizontal segment). A
disagreement is shrunk (rows, then characters, dropped while it still disagrees) and saved as
`regressions/csv-<format>-<seed>.json`; every saved file is replayed.
"""

import csv
import io
import json
import math
import pathlib
import random
import re
import subprocess
import tempfile

import pytest

# Unicode's White_Space property: what the reader trims (Rust's `str::trim`). Python's
# `str.strip()` also strips U+001C..U+001F, which are not White_Space.
WHITE_SPACE = (
    "\t\n\x0b\x0c\r \x85\xa0\u1680"
    + "".join(chr(c) for c in range(0x2000, 0x200B))
    + "\u2028\u2029\u202f\u205f\u3000"
)

PIECES = [
    '"', '""', ",", "\n", "\r", "\r\n", " ", "\t", "#", "\ufeff", "a", "C", "0", "é",
    "\xa0", "\x1c", 'x"y', "'", ";", "\u2028", "漢",
]

NUMBER = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?")

FORMATS = {
    "model": ["x", "y", "truth", "indeterminacy", "falsity"],
    "data": ["x", "y", "truth", "indeterminacy", "falsity"],
    "points": ["x", "y"],
}


class Refusal:
    """The model's rules refuse the file at `line` (None: the file as a whole)."""

    def __init__(self, line):
        self.line = line

    def __repr__(self):
        return f"Refusal(line={self.line})"


def python_rows(text):
    """The non-empty rows of `text` as Python's csv module reads them, with the line (counted
    by LF) each starts on, cells trimmed; comments skipped; a Refusal when the file ends inside
    a quoted cell."""
    if text.startswith("\ufeff"):
        text = text[1:]
    state = {"at_start": True, "line": 1, "start": 1, "raw": [], "comment": [], "rows": 0}
    comments = []  # (line, text, rows read before it)

    def pieces():
        in_comment = False
        # newline="" splits at \r, \n and \r\n as csv does, and keeps the line ends.
        for piece in io.StringIO(text, newline=""):
            here = state["line"]
            state["line"] += piece.count("\n")
            if state["at_start"]:
                if in_comment or piece.startswith("#"):
                    if not in_comment:
                        state["comment"] = []
                    state["comment"].append(piece)
                    in_comment = not piece.endswith("\n")
                    if not in_comment:
                        comments.append((here, "".join(state["comment"]), state["rows"]))
                    continue
                state["at_start"] = False
                state["start"] = here
                state["raw"] = []
            state["raw"].append(piece)
            yield piece

    rows = []
    last = None
    for cells in csv.reader(pieces()):
        last = (state["start"], "".join(state["raw"]))
        state["at_start"] = True
        cells = [c.strip(WHITE_SPACE) for c in cells]
        if not cells or cells == [""]:
            continue
        rows.append((last[0], cells))
        state["rows"] = len(rows)
    if state["at_start"] and state["comment"] and not "".join(state["comment"]).endswith("\n"):
        # a comment on the last line, without its line end
        comments.append((state["line"], "".join(state["comment"]), state["rows"]))
    state["hidden"] = hidden_row(comments, rows)
    if last is not None:
        # A line end added after a row read to the end of the file changes it only when the
        # file ends inside a quoted cell.
        start, raw = last
        alone = next(csv.reader(io.StringIO(raw, newline="")), [])
        closed = next(csv.reader(io.StringIO(raw + "\n", newline="")), [])
        if alone != closed:
            return rows, Refusal(start), state["hidden"]
    return rows, None, state["hidden"]


def _number(cell):
    """Whether Rust's `f64::from_str` reads `cell` (Python's float, without its underscores)."""
    if not cell or "_" in cell or cell != cell.strip():
        return False
    try:
        float(cell)
    except ValueError:
        return False
    return True


def hidden_row(comments, rows):
    """The line of the first comment after the header that holds a full row, or None."""
    if not rows:
        return None
    count = len(rows[0][1])
    for line, text, before in comments:
        if before < 1 or count < 3:
            continue
        body = text.rstrip("\r\n")
        if '"' in body:
            continue
        cells = [c.strip(WHITE_SPACE) for c in body.split(",")]
        if len(cells) == count and all(_number(c) for c in cells[1:]):
            return line
    return None


def expected(fmt, text):
    """What the command line must report: a list of rows (name, numbers) or a Refusal."""
    rows, eof_refusal, hidden = python_rows(text)
    if not rows:
        return eof_refusal or Refusal(None)
    header = [c.lower() for c in rows[0][1]]
    out = []
    for line, cells in rows[1:]:
        if hidden is not None and hidden < line:
            return Refusal(hidden)
        if len(cells) != len(header):
            return Refusal(line)
        record = dict(zip(header, cells))
        values = []
        for column in FORMATS[fmt]:
            cell = record[column]
            if not NUMBER.fullmatch(cell) or not math.isfinite(float(cell)):
                return Refusal(line)
            value = float(cell)
            if column in ("truth", "indeterminacy", "falsity") and not 0 <= value <= 1:
                return Refusal(line)
            values.append(value)
        name = record.get("name", "")
        out.append((name or None, values))
    if hidden is not None:
        return Refusal(hidden)
    if eof_refusal is not None:
        return eof_refusal
    if not out:
        return Refusal(None)
    return out


# --- what the command line says -------------------------------------------------------------


def decode_dxf_text(text):
    """The escaped text of the DXF extended data (`^J` a control character, `^ ` a caret,
    `\\U+XXXX` a UTF-16 unit)."""
    units = []
    k = 0
    while k < len(text):
        c = text[k]
        nxt = text[k + 1] if k + 1 < len(text) else None
        if c == "^" and nxt == " ":
            units.append(ord("^"))
            k += 2
        elif c == "^" and nxt == "?":
            units.append(0x7F)
            k += 2
        elif c == "^" and nxt is not None and "@" <= nxt <= "_":
            units.append(ord(nxt) - 64)
            k += 2
        elif c == "\\" and re.fullmatch(r"U\+[0-9A-F]{4}", text[k + 1 : k + 7]):
            units.append(int(text[k + 3 : k + 7], 16))
            k += 7
        else:
            units.extend(
                int.from_bytes(c.encode("utf-16-le")[i : i + 2], "little")
                for i in range(0, len(c.encode("utf-16-le")), 2)
            )
            k += 1
    raw = b"".join(u.to_bytes(2, "little") for u in units)
    return raw.decode("utf-16-le")


def model_from_dxf(path):
    """(name, [x, y, truth, indeterminacy, falsity]) per control point of the SPLINE."""
    lines = pathlib.Path(path).read_text(encoding="utf-8").splitlines()
    pairs = [(int(lines[i].strip()), lines[i + 1]) for i in range(0, len(lines) - 1, 2)]
    k = pairs.index((0, "SPLINE"))
    xs, ys = [], []
    while pairs[k][0] != 1001:
        code, value = pairs[k]
        if code == 10:
            xs.append(float(value))
        elif code == 20:
            ys.append(float(value))
        k += 1
    data = pairs[k + 1 :]
    strings = [(code, value) for code, value in data]
    degrees, names = [], [None] * len(xs)
    j = 0
    while j < len(strings):
        code, value = strings[j]
        if code == 1000 and value == "degrees":
            n = int(strings[j + 1][1])
            reals = [float(v) for _, v in strings[j + 2 : j + 2 + 3 * n]]
            degrees = [reals[3 * i : 3 * i + 3] for i in range(n)]
            j += 2 + 3 * n
        elif code == 1000 and value == "point names":
            n = int(strings[j + 1][1])
            j += 2
            names = []
            for _ in range(n):
                count = int(strings[j][1])
                j += 1
                if count < 0:
                    names.append(None)
                    continue
                names.append(decode_dxf_text("".join(v for _, v in strings[j : j + count])))
                j += count
        elif code in (0, 1001) and j > 0 and value != "NEUTROSPLINE":
            break
        else:
            j += 1
    return [(names[i], [xs[i], ys[i], *degrees[i]]) for i in range(len(xs))]


def run_cli(cli, fmt, text_bytes, workdir):
    """The command line's reading of the file: a list of rows or Refusal(line), and the
    output for messages."""
    name = {"model": "m.csv", "data": "d.csv", "points": "p.csv"}[fmt]
    path = pathlib.Path(workdir) / name
    path.write_bytes(text_bytes)
    if fmt == "model":
        args = ["export", name, "-o", "out.dxf"]
    elif fmt == "data":
        args = ["fit", name, "--interpolate", "--degree", "1", "--parametrization", "uniform",
                "-o", "out.json"]
    else:
        (pathlib.Path(workdir) / "segment.csv").write_text(
            "x,y,truth,indeterminacy,falsity\n-4000,0,1,0,0\n4000,0,1,0,0\n"
        )
        args = ["query", "segment.csv", name, "--format", "json"]
    done = subprocess.run([str(cli), *args], cwd=workdir, capture_output=True, timeout=60)
    stderr = done.stderr.decode("utf-8", "replace")
    if done.returncode != 0:
        found = re.match(rf"error: {re.escape(name)}(?::(\d+))?: ", stderr)
        if done.returncode == 1 and found:
            return Refusal(int(found.group(1)) if found.group(1) else None), stderr
        return ("exit", done.returncode), stderr
    if fmt == "model":
        return model_from_dxf(pathlib.Path(workdir) / "out.dxf"), stderr
    if fmt == "data":
        model = json.loads((pathlib.Path(workdir) / "out.json").read_text())
        return [
            (None, [p["x"], p["y"], p["truth"], p["indeterminacy"], p["falsity"]])
            for p in model["control_points"]
        ], stderr
    table = json.loads(done.stdout)
    return [(None, [row["x"], row["distance"]]) for row in table], stderr


def agrees(fmt, want, got):
    if isinstance(want, Refusal):
        return isinstance(got, Refusal) and got.line == want.line
    if fmt == "data" and len(want) < 2:
        # Fitting needs two points at least: refused, whatever the line.
        return isinstance(got, Refusal)
    if not isinstance(got, list) or len(got) != len(want):
        return False
    for (want_name, want_values), (got_name, got_values) in zip(want, got):
        if fmt == "points":
            x, y = want_values
            gx, distance = got_values
            # Far from the segment the nearest x is ill-conditioned (the distance changes by
            # dx^2 / 2|y|): tolerances grow with |y|.
            scale = max(1.0, abs(x), abs(y))
            if abs(gx - x) > 1e-7 * scale or abs(distance - abs(y)) > 1e-9 * scale:
                return False
            continue
        if fmt == "model" and want_name != got_name:
            return False
        if want_values != got_values:
            return False
    return True


# --- files ----------------------------------------------------------------------------------


def hostile_name(rng):
    return "".join(rng.choice(PIECES) for _ in range(rng.randint(0, 6)))


def number(rng, low, high):
    return repr(round(rng.uniform(low, high), rng.randint(0, 17)))


def make_file(fmt, rng):
    """Bytes of a CSV file written by Python's csv module, with hostile cells and lines."""
    dialect = rng.choice(["excel", "excel-all", "minimal-lf"])
    quoting = csv.QUOTE_ALL if dialect == "excel-all" else csv.QUOTE_MINIMAL
    end = "\n" if dialect == "minimal-lf" else "\r\n"
    columns = FORMATS[fmt]
    header = list(columns)
    named = rng.random() < 0.9
    if named:
        header.insert(rng.choice([0, len(header)]), "name")
    out = io.StringIO(newline="")
    writer = csv.writer(out, quoting=quoting, lineterminator=end)
    writer.writerow(header)
    least = 2 if fmt == "data" else 1
    for _ in range(rng.randint(least, 7)):
        gap = rng.random()
        if gap < 0.1:
            out.write(rng.choice(['# a comment, with a " quote', "#", "# ,,,"]) + end)
        elif gap < 0.15:
            out.write(rng.choice(["", "   ", "\t"]) + end)
        values = {
            "x": number(rng, -1000, 1000),
            "y": number(rng, -1000, 1000),
            "truth": number(rng, 0, 1),
            "indeterminacy": number(rng, 0, 1),
            "falsity": number(rng, 0, 1),
        }
        values["name"] = hostile_name(rng)
        cells = [values[c] for c in header]
        hand = rng.random()
        if hand < 0.1 and named:
            # Written by hand: a stray quote inside an unquoted name (issue 22's `C"0`).
            stray = rng.choice(['C"0', 'a"b"c', 'x""', "it's"])
            cells[header.index("name")] = stray
            out.write(",".join(cells) + end)
        elif hand < 0.13:
            out.write(",".join(cells) + "," + end)  # one cell too many
        else:
            writer.writerow(cells)
    if rng.random() < 0.05:
        out.write('"never closed,1,2' + end)
    text = out.getvalue()
    if rng.random() < 0.2:
        text = text.rstrip("\r\n")  # no line end at the end of the file
    encoding = "utf-8-sig" if rng.random() < 0.3 else "utf-8"
    return text.encode(encoding)


# --- shrinking and the regression files -------------------------------------------------------


def disagreement(cli, fmt, data, workdir):
    """None when the command line agrees with Python's reading of `data`, else the two."""
    want = expected(fmt, data.decode("utf-8"))
    got, stderr = run_cli(cli, fmt, data, workdir)
    if agrees(fmt, want, got):
        return None
    return want, got, stderr


def shrink(cli, fmt, data, workdir):
    """Drops lines, then characters, of `data` after its header while the disagreement
    stays."""
    text = data.decode("utf-8")
    still = lambda t: disagreement(cli, fmt, t.encode("utf-8"), workdir) is not None
    changed = True
    while changed:
        changed = False
        lines = text.splitlines(keepends=True)
        for i in range(1, len(lines)):
            candidate = "".join(lines[:i] + lines[i + 1 :])
            if still(candidate):
                text, changed = candidate, True
                break
        if changed:
            continue
        # The header (the first line) stays as written.
        for i in range(len(lines[0]) if lines else 0, len(text)):
            candidate = text[:i] + text[i + 1 :]
            if still(candidate):
                text, changed = candidate, True
                break
    return text.encode("utf-8")


def describe(want):
    if isinstance(want, Refusal):
        return {"refused_at_line": want.line}
    return {"rows": [{"name": name, "values": values} for name, values in want]}


@pytest.mark.parametrize("fmt", sorted(FORMATS))
def test_csv_files_read_as_python_reads_them(cli, budget, seed, regressions, fmt, tmp_path):
    failures = []
    for case in range(budget):
        rng = random.Random(f"{fmt}-{seed + case}")
        data = make_file(fmt, rng)
        if disagreement(cli, fmt, data, tmp_path) is None:
            continue
        small = shrink(cli, fmt, data, tmp_path)
        want, got, stderr = disagreement(cli, fmt, small, tmp_path)
        record = {
            "format": fmt,
            "seed": seed + case,
            "text": small.decode("utf-8"),
            "expected": describe(want),
            "note": f"shrunk from seed {seed + case}; the command line gave {got!r}: {stderr.strip()}",
        }
        path = regressions / f"csv-{fmt}-{seed + case}.json"
        path.write_text(json.dumps(record, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
        failures.append(f"{path.name}: {record['note']}")
        if len(failures) >= 3:
            break
    assert not failures, "\n".join(failures)


def regression_files():
    folder = pathlib.Path(__file__).resolve().parent / "regressions"
    return sorted(folder.glob("csv-*.json"))


@pytest.mark.parametrize("path", regression_files(), ids=lambda p: p.name)
def test_csv_regressions_replay(cli, path, tmp_path):
    record = json.loads(path.read_text(encoding="utf-8"))
    data = record["text"].encode("utf-8")
    want = expected(record["format"], record["text"])
    # The saved answer is Python's reading, computed when the file was saved: it still is.
    assert describe(want) == record["expected"]
    got, stderr = run_cli(cli, record["format"], data, tmp_path)
    assert agrees(record["format"], want, got), (got, stderr)


def test_the_issue_file_reads_four_points(cli, tmp_path):
    """Issue 22: `C"0` in a four-point file read as one control point, exit 0."""
    text = (
        "name,x,y,truth,indeterminacy,falsity\nC\"0,1,3,0.3,0.6,0.1\nC1,3,6,0.8,0.1,0.1\n"
        "C2,6,2,0.7,0.1,0.2\nC3,9,5,0.2,0.4,0.4\n"
    )
    want = expected("model", text)
    assert [name for name, _ in want] == ['C"0', "C1", "C2", "C3"]
    got, stderr = run_cli(cli, "model", text.encode(), tmp_path)
    assert got == want, stderr


def test_the_oracle_reads_what_it_should():
    """The reading written here, on files whose rows are known."""
    assert python_rows("\ufeff# c \"\nname,x\r\n\r\n\"a\nb\",1\n")[0] == [
        (2, ["name", "x"]),
        (4, ["a\nb", "1"]),
    ]
    assert python_rows('x\n"open\n')[1].line == 2
    assert python_rows('x\n"closed"\n')[1] is None
    assert python_rows("x\na\rb\n")[0] == [(1, ["x"]), (2, ["a"]), (2, ["b"])]
    assert isinstance(expected("model", "name,x,y,truth,indeterminacy,falsity\nA,1,2,0,0,2\n"), Refusal)
    assert decode_dxf_text("a^Jb^ \\U+00E9") == "a\nb^é"
