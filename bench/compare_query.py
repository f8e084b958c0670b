#!/usr/bin/env python3
"""Side-by-side timing of `neutrospline query` (nearest points) and a scipy baseline.

One run, one machine:

- the curve: a seeded random cubic B-spline with 64 pieces (67 control points along a wavy
  path, clamped uniform knots on [0, 1]), five channels (x, y, truth, indeterminacy,
  falsity), written as a CSV model (`--kind bspline --degree 3`);
- the query: 100,000 seeded random points in the curve's bounding box enlarged by 10 % on
  each side, written as CSV;
- neutrospline: `neutrospline query MODEL POINTS.csv -o OUT.csv`, the whole command (reading
  both files, the global nearest point of every query point by branch and bound and Newton,
  writing the table), best of R runs, with all threads (rayon) and with one thread
  (`RAYON_NUM_THREADS=1`);
- scipy: per point, the best of 64 evenly spaced samples of the curve, then
  `scipy.optimize.minimize_scalar(method="bounded")` on the squared distance over the two
  sample intervals around it, the curve evaluated by `scipy.interpolate.BSpline`; one thread
  (BLAS limited), timed once over `--scipy-points` of the points (default all 100,000) and
  scaled to 100,000 when fewer.

The script also compares the answers: the largest amount by which scipy's distance is below
ours (0 when ours is never farther: ours is a global minimum, scipy's a local one from the
best sample) and how many of scipy's distances exceed ours by more than 1e-9 of the curve's
size (points where the best sample led scipy to a local, not global, minimum).

Usage:  python3 bench/compare_query.py [--rounds R] [--scipy-points N] [--out bench/results]

Installs numpy, scipy and threadpoolctl into a virtual environment (default /tmp/venv-bench,
`--venv` to change), builds the release binary, and re-runs itself inside the venv.
"""

import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ["numpy", "scipy", "threadpoolctl"]
POINTS = 100_000
PIECES = 64
DEGREE = 3
SAMPLES = 64
SEED = 20261201


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--rounds", type=int, default=5, help="runs of neutrospline (best kept)")
    p.add_argument("--scipy-points", type=int, default=POINTS,
                   help="query points timed with scipy (scaled to 100,000)")
    p.add_argument("--venv", default="/tmp/venv-bench")
    p.add_argument("--out", default=str(ROOT / "bench" / "results"))
    p.add_argument("--no-build", action="store_true", help="use the existing release binary")
    p.add_argument("--inside-venv", action="store_true", help=argparse.SUPPRESS)
    return p.parse_args()


def ensure_venv(args):
    """Creates the venv and installs the packages, then re-runs this script inside it."""
    venv = Path(args.venv)
    python = venv / "bin" / "python"
    if not python.exists():
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    subprocess.run([str(python), "-m", "pip", "install", "--quiet", *PACKAGES], check=True)
    if not args.no_build:
        subprocess.run(
            ["cargo", "build", "--release", "--locked", "-p", "neutrospline-cli"],
            cwd=ROOT,
            check=True,
        )
    argv = [str(python), str(Path(__file__).resolve()), *sys.argv[1:], "--inside-venv"]
    return subprocess.run(argv).returncode


def machine():
    info = {"platform": platform.platform(), "python": platform.python_version()}
    try:
        lscpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        for line in lscpu.splitlines():
            key, _, value = line.partition(":")
            if key.strip() in ("Model name", "CPU(s)", "L2 cache", "L3 cache"):
                info[key.strip()] = value.strip()
    except OSError:
        pass
    info["load average at start"] = " ".join(f"{x:.2f}" for x in os.getloadavg())
    return info


def curve(np):
    """Control points (67 x 5) and knots of the benchmark's cubic B-spline."""
    rng = np.random.default_rng(SEED)
    n = PIECES + DEGREE
    x = np.arange(n, dtype=float) + rng.uniform(-0.3, 0.3, n)
    y = np.sin(x / 3.0) * 4.0 + rng.uniform(-1.5, 1.5, n)
    degrees = rng.uniform(0.0, 1.0, (n, 3))
    inner = np.arange(1, PIECES) / PIECES
    knots = np.concatenate([[0.0] * (DEGREE + 1), inner, [1.0] * (DEGREE + 1)])
    return np.column_stack([x, y, degrees]), knots


def queries(np, control):
    rng = np.random.default_rng(SEED + 1)
    lo, hi = control[:, :2].min(axis=0), control[:, :2].max(axis=0)
    pad = 0.1 * (hi - lo)
    return rng.uniform(lo - pad, hi + pad, (POINTS, 2))


def scipy_nearest(np, spline, points):
    """Best of 64 samples, then minimize_scalar (bounded) around it: (t, distance) per point."""
    from scipy.optimize import minimize_scalar

    ts = np.linspace(0.0, 1.0, SAMPLES)
    samples = spline(ts)[:, :2]
    out = np.empty((len(points), 2))
    for k, p in enumerate(points):
        d2 = ((samples - p) ** 2).sum(axis=1)
        i = int(np.argmin(d2))
        lo, hi = ts[max(i - 1, 0)], ts[min(i + 1, SAMPLES - 1)]

        def f(t, p=p):
            c = spline(t)
            return (c[0] - p[0]) ** 2 + (c[1] - p[1]) ** 2

        r = minimize_scalar(f, bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
        best_t, best = r.x, r.fun
        for t in (lo, hi):
            v = f(t)
            if v < best:
                best_t, best = t, v
        out[k] = (best_t, np.sqrt(best))
    return out


def main_inside(args):
    import numpy as np
    import scipy
    from scipy.interpolate import BSpline
    from threadpoolctl import threadpool_limits

    binary = ROOT / "target" / "release" / "neutrospline"
    control, knots = curve(np)
    points = queries(np, control)
    size = float(np.linalg.norm(control[:, :2].max(axis=0) - control[:, :2].min(axis=0)))
    results = {
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "machine": machine(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "points": POINTS,
        "pieces": PIECES,
        "degree": DEGREE,
    }
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        model = tmp / "curve.csv"
        with open(model, "w") as f:
            f.write("x,y,truth,indeterminacy,falsity\n")
            for row in control:
                f.write(",".join(repr(float(v)) for v in row) + "\n")
        query = tmp / "points.csv"
        with open(query, "w") as f:
            f.write("x,y\n")
            for p in points:
                f.write(f"{float(p[0])!r},{float(p[1])!r}\n")
        out = tmp / "out.csv"
        command = [str(binary), "query", str(model), str(query), "-o", str(out),
                   "--kind", "bspline", "--degree", str(DEGREE)]
        timings = {}
        for label, env in (("all_threads", {}), ("one_thread", {"RAYON_NUM_THREADS": "1"})):
            best = float("inf")
            for _ in range(args.rounds):
                start = time.perf_counter()
                subprocess.run(command, check=True, env={**os.environ, **env})
                best = min(best, time.perf_counter() - start)
            timings[label] = best
        table = np.loadtxt(out, delimiter=",", skiprows=1)
    ours_t, ours_d = table[:, 1], table[:, 2]

    spline = BSpline(knots, control, DEGREE)
    n = min(args.scipy_points, POINTS)
    with threadpool_limits(limits=1):
        start = time.perf_counter()
        reference = scipy_nearest(np, spline, points[:n])
        scipy_seconds = (time.perf_counter() - start) * POINTS / n
    below = float(np.max(ours_d[:n] - reference[:, 1]))
    worse = int(np.sum(reference[:, 1] > ours_d[:n] + 1e-9 * size))
    results.update({
        "neutrospline_seconds_all_threads": timings["all_threads"],
        "neutrospline_seconds_one_thread": timings["one_thread"],
        "scipy_seconds": scipy_seconds,
        "scipy_points_timed": n,
        "speedup_all_threads": scipy_seconds / timings["all_threads"],
        "speedup_one_thread": scipy_seconds / timings["one_thread"],
        "largest_amount_scipy_is_nearer": below,
        "scipy_local_minima": worse,
        "curve_size": size,
    })
    lines = [
        f"# Nearest points: neutrospline query vs scipy ({results['date']})",
        "",
        f"Machine: {results['machine'].get('Model name', '?')}, "
        f"{results['machine'].get('CPU(s)', '?')} CPUs (load average at start "
        f"{results['machine']['load average at start']}); numpy {np.__version__}, scipy "
        f"{scipy.__version__}.",
        "",
        f"{POINTS:,} random points against a cubic B-spline with {PIECES} pieces:",
        "",
        "| tool | seconds | speedup over scipy |",
        "|---|---:|---:|",
        f"| neutrospline query, whole command, all threads (best of {args.rounds}) | "
        f"{timings['all_threads']:.3f} | {results['speedup_all_threads']:.0f}x |",
        f"| neutrospline query, whole command, one thread (best of {args.rounds}) | "
        f"{timings['one_thread']:.3f} | {results['speedup_one_thread']:.0f}x |",
        f"| scipy: best of 64 samples + minimize_scalar per point, one thread"
        f"{'' if n == POINTS else f' ({n:,} points timed, scaled)'} | {scipy_seconds:.1f} | 1x |",
        "",
        f"Answers: scipy's distance is never below ours by more than {below:.1e} "
        f"(curve size {size:.1f}); at {worse:,} of {n:,} points scipy stopped at a local "
        f"minimum farther than ours by more than 1e-9 of the size.",
        "",
    ]
    text = "\n".join(lines)
    print(text)
    out_dir = Path(args.out)
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "query_latest.json").write_text(json.dumps(results, indent=2) + "\n")
    (out_dir / "query_latest.md").write_text(text)
    return 0


def main():
    args = parse_args()
    if not args.inside_venv:
        return ensure_venv(args)
    return main_inside(args)


if __name__ == "__main__":
    sys.exit(main())
