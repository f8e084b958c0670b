#!/usr/bin/env python3
"""How fast the studio redraws while a control point is dragged, in a plain headless Chromium.

The curve: a degree-20 Bézier curve (tests/studio/drag.py). The drag: 120 pointer moves, one
every 16 ms (a 60 Hz mouse), sent from inside the page to point 10; every move that arrives
while a frame is drawn replaces the one before. Each frame asks the server for the views shown
as display lists and paints them on canvases; the drag ends on the settled SVG figures. Two
layouts: the six views of the paper side by side (plane, controls, truth, indeterminacy,
falsity, all), and the plane view alone, large. R rounds of each, interleaved.

Measures (ms, per frame; the median and 90th percentile of each round, then the median over
the rounds):
- latency: from the pointer event to the views painted and laid out anew;
- shown: from the pointer event to the end of the first browser frame after that;
- work: from the request to drawn; interval: between frames; server: the server's own time.

The browser is Debian's chromium driven through bench/cdp_pipe.py (no test driver, whose
network instrumentation slows the page on every request).

Usage:  python3 bench/studio_drag.py [--rounds R] [--out bench/results]
        (NEUTROSPLINE_BIN: the binary, default a fresh release build; CHROMIUM: the browser)
"""

import argparse
import datetime
import json
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "studio"))
sys.path.insert(0, str(ROOT / "bench"))

from cdp_pipe import Browser  # noqa: E402
from drag import DRAG_JS, degree20, summarise  # noqa: E402

LAYOUTS = {"grid": "six views side by side", "large": "the plane view alone, large"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--out", default=str(ROOT / "bench" / "results"))
    parser.add_argument("--layouts", default="grid,large",
                        help="the layouts to time, in this order each round (grid, large)")
    args = parser.parse_args()
    layouts = args.layouts.split(",")
    unknown = [layout for layout in layouts if layout not in LAYOUTS]
    if unknown:
        parser.error(f"unknown layout {unknown[0]!r}: give grid or large")
    binary = os.environ.get("NEUTROSPLINE_BIN")
    if not binary:
        subprocess.run(["cargo", "build", "--release", "-p", "neutrospline-cli"], cwd=ROOT, check=True)
        binary = str(ROOT / "target" / "release" / "neutrospline")
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "degree20.json"
        degree20(model)
        server = subprocess.Popen([binary, "studio", str(model), "--no-open", "--port", "0"],
                                  stdout=subprocess.PIPE, text=True)
        url = re.search(r"http://\S+", server.stdout.readline()).group(0)
        browser = Browser(os.environ.get("CHROMIUM", "/usr/bin/chromium"))
        try:
            rounds = measure(browser.page(url), args.rounds, layouts)
        finally:
            browser.close()
            server.terminate()
    report(rounds, Path(args.out))


def measure(page, rounds, layouts):
    deadline = time.time() + 30
    while not page.evaluate("!!(window.studio && document.querySelector('[data-point-index]'))"):
        if time.time() > deadline:
            raise RuntimeError("the studio page did not load")
        time.sleep(0.1)
    results = {layout: [] for layout in layouts}
    for _ in range(rounds):
        for layout in layouts:
            page.evaluate(
                f"(() => {{ const s = document.querySelector('#layout'); s.value = '{layout}';"
                " s.dispatchEvent(new Event('change')); return window.studio.idle(); })()"
            )
            timings = page.evaluate(f"({DRAG_JS})([10, 120, 16])")
            results[layout].append(summarise(timings, 120, 16))
    return results


def report(rounds, out):
    keys = ["latency_ms", "shown_ms", "work_ms", "interval_ms", "server_ms"]
    summary = {}
    for layout, runs in rounds.items():
        summary[layout] = {
            key: {
                "median": round(statistics.median(r[key]["median"] for r in runs), 1),
                "p90": round(statistics.median(r[key]["p90"] for r in runs), 1),
                "round_medians": [r[key]["median"] for r in runs],
            }
            for key in keys
        }
        summary[layout]["frames"] = [r["frames"] for r in runs]
        summary[layout]["views_per_frame"] = runs[0]["views_per_frame"]
    meta = {
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "machine": f"{platform.machine()}, {os.cpu_count()} CPUs, {platform.platform()}",
        "browser": subprocess.run([os.environ.get("CHROMIUM", "/usr/bin/chromium"), "--version"],
                                  capture_output=True, text=True).stdout.strip(),
        "load_average_after": os.getloadavg(),
        "rounds": len(next(iter(rounds.values()))),
    }
    out.mkdir(parents=True, exist_ok=True)
    (out / "studio_latest.json").write_text(json.dumps({"meta": meta, "summary": summary, "rounds": rounds}, indent=1))
    lines = [
        "# Studio: redraws while dragging a point of a degree-20 Bézier curve",
        "",
        f"{meta['date']}; {meta['machine']}; {meta['browser']}; {meta['rounds']} rounds; "
        "120 moves at 60 Hz per round. Milliseconds per frame: the median over the rounds of "
        "each round's median (and of its 90th percentile).",
        "",
        "| layout | views | latency | shown | work | interval | server |",
        "|---|---|---|---|---|---|---|",
    ]
    for layout, s in summary.items():
        cells = [f"{s[k]['median']} ({s[k]['p90']})" for k in keys]
        lines.append(f"| {LAYOUTS[layout]} | {s['views_per_frame']} | " + " | ".join(cells) + " |")
    lines += ["", "Round medians of latency: " + "; ".join(
        f"{layout} {summary[layout]['latency_ms']['round_medians']}" for layout in summary)]
    (out / "studio_latest.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
