#!/usr/bin/env python3
"""Side-by-side timing of `neutrospline.fit_surface` and scipy's `LSQBivariateSpline`.

One run, one machine, the tools interleaved in rounds (best kept), one thread each
(threadpoolctl limits BLAS; our fit runs on the calling thread):

- scattered least squares of 100,000 height points to 30 x 30 cubic control points: ours
  (`fit_surface(points, degrees, parameters=uv, control_points=(30, 30))`: the whole fit,
  knots at the quantiles of the parameters, the banded normal equations of x, y, z and the
  three degree channels under their bounds, the report) against
  `scipy.interpolate.LSQBivariateSpline(x, y, z, tx, ty)` given the interior knots our fit
  chose (scipy fits z only, and gets the knots for free). The script also checks that both
  give the same z surface (largest difference at 1,000 points, relative to the data's scale).

The data: (x, y) uniform in the unit square (numpy's default_rng(7)), z = sin(3x) cos(2y) +
0.05 N(0, 1), degrees (0.6 + 0.2 x, 0.2, 0.1 + 0.1 y); the parameters are (x, y).

Usage (from the repository, with the package installed in .venv-py by scripts/python-tests and
`.venv-py/bin/pip install threadpoolctl`):
  .venv-py/bin/python bench/compare_surface_fit.py [--rounds R] [--out bench/results]
"""

import argparse
import datetime
import json
import platform
import time
from pathlib import Path

import numpy as np
from scipy.interpolate import LSQBivariateSpline
from threadpoolctl import threadpool_limits

import neutrospline as ns

ROOT = Path(__file__).resolve().parent.parent


def data(n):
    rng = np.random.default_rng(7)
    uv = rng.random((n, 2))
    x, y = uv[:, 0], uv[:, 1]
    z = np.sin(3 * x) * np.cos(2 * y) + 0.05 * rng.standard_normal(n)
    points = np.column_stack([x, y, z])
    degrees = np.column_stack([0.6 + 0.2 * x, np.full(n, 0.2), 0.1 + 0.1 * y])
    return uv, points, degrees


def best(fn, rounds):
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - start)
    return min(times), result


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--out", default=str(ROOT / "bench/results"))
    args = parser.parse_args()
    uv, points, degrees = data(args.points)
    x, y, z = points[:, 0], points[:, 1], points[:, 2]

    def ours():
        return ns.fit_surface(points, degrees, parameters=uv, control_points=(30, 30))

    surface, _ = ours()
    tx, ty = surface.knots_u[4:-4], surface.knots_v[4:-4]

    def theirs():
        return LSQBivariateSpline(x, y, z, tx, ty, kx=3, ky=3, bbox=[0, 1, 0, 1])

    rows = {"ours": [], "scipy": []}
    with threadpool_limits(1):
        for _ in range(args.rounds):
            rows["ours"].append(best(ours, 1)[0])
            rows["scipy"].append(best(theirs, 1)[0])
    ours_s, scipy_s = min(rows["ours"]), min(rows["scipy"])
    reference = theirs()
    check = np.random.default_rng(8).random((1000, 2))
    ours_z = np.array([surface.evaluate(a, b)[2] for a, b in check])
    diff = np.abs(ours_z - reference.ev(check[:, 0], check[:, 1])).max() / np.abs(z).max()
    result = {
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "machine": platform.platform(),
        "points": args.points,
        "control_points": [30, 30],
        "rounds": args.rounds,
        "ours_seconds": ours_s,
        "scipy_seconds": scipy_s,
        "scipy_over_ours": scipy_s / ours_s,
        "largest_z_difference_relative": diff,
    }
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "surface_fit_latest.json").write_text(json.dumps(result, indent=2) + "\n")
    table = (
        "| scattered least squares, 100,000 points to 30 x 30 | seconds (best of "
        f"{args.rounds}) |\n|---|---|\n"
        f"| neutrospline.fit_surface (x, y, z and three degree channels, bounds, report) | "
        f"{ours_s:.4f} |\n"
        f"| scipy LSQBivariateSpline (z only, knots given) | {scipy_s:.4f} |\n"
        f"| scipy / ours | {scipy_s / ours_s:.2f} |\n"
        f"| largest z difference / max abs z | {diff:.1e} |\n"
    )
    (out / "surface_fit_latest.md").write_text(table)
    print(table)


if __name__ == "__main__":
    main()
