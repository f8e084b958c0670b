#!/usr/bin/env python3
"""Side-by-side timing of `neutrospline` fitting and scipy's `make_lsq_spline`.

One run, one machine, the tools interleaved in rounds (best kept), one thread each:

- least squares, cubic, 20 control points, five channels (x, y, truth, indeterminacy,
  falsity), on 1,000 and 100,000 noisy data points: `neutrospline bench-fit` (the whole fit:
  chord-length parameters, knots, Schoenberg-Whitney check, normal equations, refinement, the
  degree channels under their bounds, the report) against `scipy.interpolate.make_lsq_spline`
  given the same parameters and the knots our fit chose (scipy gets the parameters and knots
  for free: only its solve is timed), all five channels in one call. The script also checks
  that both give the same control values (largest difference, relative to the data's scale).
- a tolerance fit of 100,000 noisy points (knot refinement until every position residual is
  within 1e-3 of the data's bounding-box diagonal, the default tolerance), ours only: scipy
  has no tolerance-driven least squares.

The data (also in `crates/neutrospline-cli/src/commands/bench_fit.rs`): point k of n,
s = k / (n - 1), x = 10 s, y = sin(6 s) + a * frac(sin(12.9898 k) * 43758.5453) (a
deterministic noise in (-a, a)), truth 0.5 + 0.3 sin(5 s), indeterminacy 0.3 + 0.1 cos(3 s),
falsity 0.2 + 0.1 s.

Usage:  python3 bench/compare_fit.py [--rounds R] [--runs K] [--out bench/results]

Installs numpy, scipy and threadpoolctl into a virtual environment (default /tmp/venv-bench,
`--venv` to change), builds the release binary, and re-runs itself inside the venv.
"""

import argparse
import datetime
import json
import math
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ["numpy", "scipy", "threadpoolctl"]
SIZES = [1_000, 100_000]
CONTROL_POINTS = 20
DEGREE = 3
NOISE = 0.01
TOLERANCE_NOISE = 0.005


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--rounds", type=int, default=5, help="interleaved rounds (best kept)")
    p.add_argument("--runs", type=int, default=9, help="timed runs per tool per round")
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


def data(np, n, noise):
    """The benchmark's data: parameters-free positions and degrees, shape (n, 5)."""
    k = np.arange(n, dtype=float)
    s = k / (n - 1)
    wobble = np.fmod(np.sin(k * 12.9898) * 43758.5453, 1.0)
    return np.column_stack(
        [
            10.0 * s,
            np.sin(6.0 * s) + noise * wobble,
            0.5 + 0.3 * np.sin(5.0 * s),
            0.3 + 0.1 * np.cos(3.0 * s),
            0.2 + 0.1 * s,
        ]
    )


def chord_length(np, positions):
    steps = np.sqrt((np.diff(positions, axis=0) ** 2).sum(axis=1))
    params = np.concatenate([[0.0], np.cumsum(steps)]) / steps.sum()
    params[-1] = 1.0
    return params


def ours(binary, points, runs, extra=()):
    out = subprocess.run(
        [str(binary), "bench-fit", "--points", str(points), "--runs", str(runs), *extra],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    return json.loads(out)


def best_seconds(fn, runs):
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - start)
    return best


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


def main_inside(args):
    import numpy as np
    import scipy
    from scipy.interpolate import make_lsq_spline
    from threadpoolctl import threadpool_limits

    binary = ROOT / "target" / "release" / "neutrospline"
    results = {
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "machine": machine(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "least_squares": [],
    }
    with threadpool_limits(limits=1):
        for n in SIZES:
            values = data(np, n, NOISE)
            params = chord_length(np, values[:, :2])
            best_ours, best_scipy, fitted = float("inf"), float("inf"), None
            for _ in range(args.rounds):
                fitted = ours(binary, n, args.runs, ["--noise", str(NOISE)])
                best_ours = min(best_ours, fitted["best_seconds"])
                knots = np.array(fitted["knots"])
                best_scipy = min(
                    best_scipy,
                    best_seconds(lambda: make_lsq_spline(params, values, knots, k=DEGREE), args.runs),
                )
            reference = make_lsq_spline(params, values, knots, k=DEGREE).c
            mine = np.array(fitted["coefficients"])
            scale = np.abs(values).max(axis=0)
            difference = float((np.abs(mine - reference) / scale).max())
            results["least_squares"].append(
                {
                    "points": n,
                    "control_points": CONTROL_POINTS,
                    "neutrospline_seconds": best_ours,
                    "scipy_seconds": best_scipy,
                    "speedup": best_scipy / best_ours,
                    "largest_relative_difference": difference,
                    "bounds_active": fitted["at_bound"],
                }
            )
        n = SIZES[-1]
        values = data(np, n, TOLERANCE_NOISE)
        span = values[:, :2].max(axis=0) - values[:, :2].min(axis=0)
        tolerance = 1e-3 * math.hypot(*span)
        best, fitted = float("inf"), None
        for _ in range(args.rounds):
            fitted = ours(
                binary,
                n,
                max(1, args.runs // 3),
                ["--noise", str(TOLERANCE_NOISE), "--tolerance", repr(tolerance)],
            )
            best = min(best, fitted["best_seconds"])
        results["tolerance"] = {
            "points": n,
            "noise": TOLERANCE_NOISE,
            "tolerance": tolerance,
            "neutrospline_seconds": best,
            "control_points": fitted["control_points"],
            "tolerance_met": fitted["tolerance_met"],
            "max_position_error": fitted["max_position_error"],
        }

    lines = [
        f"# Fitting: neutrospline vs scipy ({results['date']})",
        "",
        f"Machine: {results['machine'].get('Model name', '?')}, "
        f"{results['machine'].get('CPU(s)', '?')} CPUs; numpy {np.__version__}, scipy "
        f"{scipy.__version__}; one thread each; best of {args.rounds} rounds x {args.runs} runs.",
        "",
        "Least squares, cubic, 20 control points, 5 channels (x, y, truth, indeterminacy, "
        "falsity), noise 0.01:",
        "",
        "| points | neutrospline (whole fit) | scipy make_lsq_spline (solve only) | speedup | "
        "largest difference / data scale |",
        "|---:|---:|---:|---:|---:|",
    ]
    for row in results["least_squares"]:
        lines.append(
            f"| {row['points']:,} | {row['neutrospline_seconds'] * 1e3:.3f} ms | "
            f"{row['scipy_seconds'] * 1e3:.3f} ms | {row['speedup']:.2f}x | "
            f"{row['largest_relative_difference']:.1e} |"
        )
    tol = results["tolerance"]
    lines += [
        "",
        f"Tolerance fit, {tol['points']:,} points, noise {tol['noise']}, tolerance "
        f"{tol['tolerance']:.4g} (1e-3 of the bounding-box diagonal): "
        f"{tol['neutrospline_seconds'] * 1e3:.1f} ms, {tol['control_points']} control points, "
        f"met: {tol['tolerance_met']}, largest position residual {tol['max_position_error']:.4g}.",
        "",
    ]
    text = "\n".join(lines)
    print(text)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "fit_latest.json").write_text(json.dumps(results, indent=2) + "\n")
    (out / "fit_latest.md").write_text(text)
    return 0


def main():
    args = parse_args()
    if not args.inside_venv:
        return ensure_venv(args)
    return main_inside(args)


if __name__ == "__main__":
    sys.exit(main())
