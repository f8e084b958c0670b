#!/usr/bin/env python3
"""Side-by-side timing of the Python package against the `bezier` package and the command
line's own `bench`, in one run on one machine.

For Example 1 (degree 3) and random Bézier curves of degrees 7 and 15, at 1,000,000 evenly
spaced parameters, with every channel evaluated (x, y, truth, indeterminacy, falsity: the
`bezier` package gets the same five channels as a 5-D curve, so both do the same work):

- `curve.evaluate(t)`: the package, allocating its result;
- `curve.evaluate(t, out=buffer)`: into a preallocated Fortran-ordered array, no allocation;
- `curve.sample(n, out=buffer)`: the same at evenly spaced parameters the engine computes, as
  `bench` does (no parameter array read): the cost of the binding alone;
- `numpy.zeros((n, 5), order="F").fill(1.0)`: what a fresh output array costs by itself (the
  kernel zeroes its 40 MB on first touch), the floor of any allocating evaluation;
- `bezier.Curve(nodes, degree).evaluate_multi(t)`: the `bezier` package (dhermes/bezier);
- `neutrospline bench --degree D --threads 0`: the batch engine with no Python in between
  (the same thread count as the package's default; random curves of the same degree are the
  command line's own seeded curves).

Rates are in million parameters per second (Mpts/s), best of `--runs` runs. The targets of the
Python package's issue: evaluate(t) at least 8x `evaluate_multi`, and evaluate with out= at
least 80 % of the `bench` rate.

Usage: python bench/compare_py.py [--runs K] [--out bench/results]  (inside a venv with the
package, numpy and bezier installed: scripts/check's .venv-py has them).
"""

import argparse
import datetime
import json
import pathlib
import subprocess
import time

import bezier
import numpy as np

import neutrospline as ns

ROOT = pathlib.Path(__file__).resolve().parents[1]
POINTS = 1_000_000


def best(function, runs):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def curve_of_degree(degree):
    if degree == 3:
        return ns.example1()
    rng = np.random.default_rng(degree)
    return ns.Bezier(rng.uniform(-1.0, 1.0, (degree + 1, 2)), rng.uniform(0.0, 1.0, (degree + 1, 3)))


def cli_rate(binary, degree):
    done = subprocess.run(
        [str(binary), "bench", "--points", str(POINTS), "--degree", str(degree), "--threads", "0", "--format", "json"],
        capture_output=True, text=True, check=True,
    )
    return json.loads(done.stdout)["mpts_per_s"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=9)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "bench" / "results")
    args = parser.parse_args()
    subprocess.run(["cargo", "build", "--release", "-q", "-p", "neutrospline-cli"], cwd=ROOT, check=True)
    binary = ROOT / "target" / "release" / "neutrospline"
    t = np.linspace(0.0, 1.0, POINTS)
    rows = []
    for degree in [3, 7, 15]:
        curve = curve_of_degree(degree)
        nodes = np.asfortranarray(np.hstack([curve.positions, curve.degrees]).T)
        reference = bezier.Curve(nodes, degree=degree)
        buffer = np.empty((POINTS, 5), order="F")
        check = np.max(np.abs(curve(t) - reference.evaluate_multi(t).T))
        allocate = best(lambda: curve.evaluate(t), args.runs)
        into = best(lambda: curve.evaluate(t, out=buffer), args.runs)
        sampled = best(lambda: curve.sample(POINTS, out=buffer), args.runs)
        fresh = best(lambda: np.zeros((POINTS, 5), order="F").fill(1.0), args.runs)
        package = best(lambda: reference.evaluate_multi(t), max(3, args.runs // 3))
        engine = cli_rate(binary, degree)
        rows.append({
            "degree": degree,
            "evaluate_mpts_per_s": POINTS / allocate / 1e6,
            "evaluate_out_mpts_per_s": POINTS / into / 1e6,
            "sample_out_mpts_per_s": POINTS / sampled / 1e6,
            "fresh_array_ms": fresh * 1e3,
            "bezier_evaluate_multi_mpts_per_s": POINTS / package / 1e6,
            "cli_bench_mpts_per_s": engine,
            "speedup_over_bezier": package / allocate,
            "out_fraction_of_bench": POINTS / into / 1e6 / engine,
            "sample_out_fraction_of_bench": POINTS / sampled / 1e6 / engine,
            "largest_difference": float(check),
        })
    result = {
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "points": POINTS,
        "instruction_set": ns.instruction_set,
        "rows": rows,
    }
    lines = [
        f"# Python package vs bezier and `neutrospline bench` ({result['date']}, {POINTS:,} parameters, {ns.instruction_set})",
        "",
        "| degree | evaluate(t) Mpts/s | evaluate(t, out=) Mpts/s | sample(n, out=) Mpts/s | bezier evaluate_multi Mpts/s | neutrospline bench Mpts/s | evaluate / bezier | evaluate(out=) / bezier | evaluate(out=) / bench | sample(out=) / bench | fresh array alone ms | largest difference |",
        "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(
            f"| {r['degree']} | {r['evaluate_mpts_per_s']:.1f} | {r['evaluate_out_mpts_per_s']:.1f} | "
            f"{r['sample_out_mpts_per_s']:.1f} | {r['bezier_evaluate_multi_mpts_per_s']:.2f} | "
            f"{r['cli_bench_mpts_per_s']:.1f} | {r['speedup_over_bezier']:.1f}x | "
            f"{r['evaluate_out_mpts_per_s'] / r['bezier_evaluate_multi_mpts_per_s']:.1f}x | "
            f"{100 * r['out_fraction_of_bench']:.0f} % | {100 * r['sample_out_fraction_of_bench']:.0f} % | "
            f"{r['fresh_array_ms']:.2f} | {r['largest_difference']:.1e} |"
        )
    text = "\n".join(lines) + "\n"
    print(text)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "py_latest.json").write_text(json.dumps(result, indent=2) + "\n")
    (args.out / "py_latest.md").write_text(text)


if __name__ == "__main__":
    main()
