#!/usr/bin/env python3
"""Side-by-side throughput of neutrospline and the tools users would pick instead.

One run, one machine: the `bezier` package (`Curve.evaluate_multi`), a numpy
Bernstein-matrix evaluation, scipy's `BSpline`, and `neutrospline bench`, each evaluating
the same neutrosophic Bezier curve (positions x, y and the truth, indeterminacy and falsity
degrees: five channels per point) at the same N evenly spaced parameters t_k = k / (N - 1),
for degrees 3 (the paper's Example 1), 7 and 15 (seeded random curves, the generator of
`neutrospline bench`). All on one thread (BLAS limited to one thread); throughput in million
points per second, best of several runs, the tools measured in interleaved rounds so that a
busy moment of the machine does not favour one of them.

Also measured by `neutrospline bench`: the memory-bandwidth reference (a tight loop writing
the same five output arrays) and 1 versus 2 threads at 10,000,000 points.

Splines: a seeded random clamped uniform B-spline of degree 3, 7 and 15 with 64 pieces (the
curve of `neutrospline bench --kind bspline`), against scipy's `BSpline` on the same five
channels; and the NURBS curve of `neutrospline bench --kind nurbs` (the same control points,
weights in [0.5, 2]) against scipy's `BSpline` on the homogeneous channels (w x, w y, w T,
w I, w F, w) followed by the division, the way a scipy user evaluates a NURBS curve.

Usage:  python3 bench/compare.py [--points N] [--rounds R] [--out bench/results]

The script installs its Python packages into a virtual environment (default
/tmp/venv-bench, `--venv` to change), builds the release binary with cargo, and re-runs
itself inside the venv with OPENBLAS_CORETYPE and OPENBLAS_L2_SIZE unset (they select an old
OpenBLAS kernel on some machines; the BLAS kernel numpy then uses is recorded).
"""

import argparse
import datetime
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ["bezier", "numpy", "scipy", "threadpoolctl"]
DEGREES = [3, 7, 15]
PIECES = 64
# The paper's Example 1 (Table 1): x, y, truth, indeterminacy, falsity per control point.
EXAMPLE1 = [
    [1.0, 3.0, 0.3, 0.6, 0.1],
    [3.0, 6.0, 0.8, 0.1, 0.1],
    [6.0, 2.0, 0.7, 0.1, 0.2],
    [9.0, 5.0, 0.2, 0.4, 0.4],
]
MASK = (1 << 64) - 1


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--points", type=int, default=1_000_000)
    p.add_argument("--rounds", type=int, default=3, help="interleaved rounds (best kept)")
    p.add_argument("--runs", type=int, default=3, help="timed runs per tool per round")
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
    subprocess.run(
        [str(python), "-m", "pip", "install", "--quiet", *PACKAGES], check=True
    )
    if not args.no_build:
        subprocess.run(
            ["cargo", "build", "--release", "--locked", "-p", "neutrospline-cli"],
            cwd=ROOT,
            check=True,
        )
    env = dict(os.environ)
    # Only for this benchmark: these pin an old OpenBLAS kernel on some processors.
    env.pop("OPENBLAS_CORETYPE", None)
    env.pop("OPENBLAS_L2_SIZE", None)
    argv = [str(python), str(Path(__file__).resolve()), *sys.argv[1:], "--inside-venv"]
    return subprocess.run(argv, env=env).returncode


def generator(seed):
    """The xorshift generator of `neutrospline bench` (uniform numbers in [0, 1))."""
    state = ((seed * 0x9E3779B97F4A7C15) & MASK) | 1

    def nxt():
        nonlocal state
        state ^= (state << 13) & MASK
        state ^= state >> 7
        state ^= (state << 17) & MASK
        return (state >> 11) / float(1 << 53)

    return nxt


def random_rows(count, nxt):
    rows = []
    for _ in range(count):
        x, y = 10.0 * nxt(), 10.0 * nxt()
        rows.append([x, y, nxt(), nxt(), nxt()])
    return rows


def random_curve(n, seed=1):
    """The control points of `neutrospline bench --degree n --seed seed` (same xorshift)."""
    return random_rows(n + 1, generator(seed))


def random_spline(p, pieces, seed=1):
    """Knots, control rows and NURBS weights of `neutrospline bench --kind bspline|nurbs
    --degree p --pieces pieces --seed seed` (clamped uniform knots on [0, 1])."""
    nxt = generator(seed)
    rows = random_rows(p + pieces, nxt)
    weights = [2.0 ** (2.0 * nxt() - 1.0) for _ in rows]
    knots = [0.0] * (p + 1) + [j / pieces for j in range(1, pieces)] + [1.0] * (p + 1)
    return knots, rows, weights


def machine():
    info = {"platform": platform.platform(), "python": platform.python_version()}
    try:
        lscpu = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        for line in lscpu.splitlines():
            key, _, value = line.partition(":")
            if key.strip() in ("Model name", "CPU(s)", "Thread(s) per core", "L2 cache", "L3 cache"):
                info[key.strip()] = value.strip()
    except OSError:
        pass
    info["load average at start"] = " ".join(f"{x:.2f}" for x in os.getloadavg())
    return info


def best_rate(fn, points, runs):
    """Million points per second of the fastest of `runs` calls of `fn`."""
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - start)
    return points / best / 1e6


def python_tools(np, nodes, points):
    """name -> zero-argument function doing the whole evaluation (same work for each)."""
    import bezier
    from scipy.interpolate import BSpline
    from scipy.special import comb

    n = nodes.shape[1] - 1
    s = np.arange(points, dtype=float) / (points - 1)
    curve5 = bezier.Curve(np.asfortranarray(nodes), degree=n, copy=True, verify=False)
    curve2 = bezier.Curve(np.asfortranarray(nodes[:2]), degree=n, copy=True, verify=False)
    binomials = comb(n, np.arange(n + 1))
    powers = np.arange(n + 1, dtype=float)
    spline = BSpline(np.r_[np.zeros(n + 1), np.ones(n + 1)], nodes.T.copy(), n)

    def numpy_matrix():
        # B[k, i] = C(n, i) t_k^i (1 - t_k)^(n - i); then nodes (5 x n+1) @ B.T.
        basis = binomials * s[:, None] ** powers * (1.0 - s)[:, None] ** (n - powers)
        return nodes @ basis.T

    return {
        "bezier evaluate_multi": lambda: curve5.evaluate_multi(s),
        "numpy Bernstein matrix": numpy_matrix,
        "scipy BSpline": lambda: spline(s),
        "bezier evaluate_multi, x y only": lambda: curve2.evaluate_multi(s),
    }, {
        "bezier": lambda: curve5.evaluate_multi(s),
        "numpy": lambda: numpy_matrix(),
        "scipy": lambda: spline(s).T,
    }


def spline_tools(np, p, points):
    """The scipy evaluations of the bench B-spline and NURBS curves of degree p."""
    from scipy.interpolate import BSpline

    knots, rows, weights = random_spline(p, PIECES)
    c = np.array(rows)
    w = np.array(weights)
    s = np.arange(points, dtype=float) / (points - 1)
    plain = BSpline(np.array(knots), c, p)
    homogeneous = BSpline(np.array(knots), np.c_[c * w[:, None], w], p)

    def rational():
        h = homogeneous(s)
        return h[:, :5] / h[:, 5:6]

    return {"scipy BSpline": lambda: plain(s),
            "scipy BSpline, homogeneous + division": rational}


def neutrospline_bench(binary, degree, points, threads, runs, kind="bezier"):
    out = subprocess.run(
        [
            str(binary), "bench", "--points", str(points), "--degree", str(degree),
            "--threads", str(threads), "--runs", str(runs), "--format", "json",
            "--kind", kind, "--pieces", str(PIECES),
        ],
        capture_output=True, text=True, check=True,
    ).stdout
    return json.loads(out)


def main_inside(args):
    import numpy as np
    from threadpoolctl import threadpool_info, threadpool_limits
    import bezier
    import scipy

    binary = ROOT / "target" / "release" / "neutrospline"
    points = args.points
    info = machine()
    blas = [
        {k: d.get(k) for k in ("internal_api", "version", "architecture", "num_threads")}
        for d in threadpool_info()
    ]
    versions = {
        "bezier": bezier.__version__, "bezier Fortran speedup": bool(bezier._HAS_SPEEDUP),
        "numpy": np.__version__, "scipy": scipy.__version__,
    }
    rows = {}
    splines = {}
    with threadpool_limits(limits=1):
        for degree in DEGREES:
            nodes = np.array(EXAMPLE1 if degree == 3 else random_curve(degree)).T.copy()
            tools, checks = python_tools(np, nodes, points)
            # The tools agree with each other (same curve, same parameters).
            ref = checks["bezier"]()
            for name, fn in checks.items():
                diff = float(np.max(np.abs(fn() - ref)))
                assert diff < 1e-9 * max(1.0, float(np.max(np.abs(nodes)))), (name, diff)
            if degree == 3:
                mid = ref[:, (points - 1) // 2] if points % 2 == 1 else None
                if mid is not None:
                    assert np.allclose(mid, [4.625, 4.0, 0.625, 0.2, 0.175]), mid
            best = {}
            for _ in range(args.rounds):
                for name, fn in tools.items():
                    best[name] = max(best.get(name, 0.0), best_rate(fn, points, args.runs))
                r = neutrospline_bench(binary, degree, points, 1, 2 * args.runs + 1)
                prev = best.get("neutrospline", (0.0, None))
                if r["mpts_per_s"] > prev[0]:
                    best["neutrospline"] = (r["mpts_per_s"], r)
            rows[degree] = best
        # Splines: neutrospline's B-spline and NURBS batches against scipy.
        for degree in DEGREES:
            tools = spline_tools(np, degree, points)
            best = {}
            for _ in range(args.rounds):
                for name, fn in tools.items():
                    best[name] = max(best.get(name, 0.0), best_rate(fn, points, args.runs))
                for kind in ("bspline", "nurbs"):
                    r = neutrospline_bench(binary, degree, points, 1, 2 * args.runs + 1, kind)
                    if r["mpts_per_s"] > best.get(kind, (0.0, None))[0]:
                        best[kind] = (r["mpts_per_s"], r)
            splines[degree] = best
    # Threads: 1 vs 2 at 10,000,000 points, degree 3 (memory-bound) and 15 (compute-bound).
    scaling = {}
    for degree in (3, 15):
        res = {}
        for _ in range(args.rounds):
            for threads in (1, 2):
                r = neutrospline_bench(binary, degree, 10_000_000, threads, 5)
                if r["mpts_per_s"] > res.get(threads, {"mpts_per_s": 0})["mpts_per_s"]:
                    res[threads] = r
        scaling[degree] = res
    info["load average at end"] = " ".join(f"{x:.2f}" for x in os.getloadavg())
    report(args, info, blas, versions, rows, splines, scaling, points)


def report(args, info, blas, versions, rows, splines, scaling, points):
    isa = rows[3]["neutrospline"][1]["instruction_set"]
    lines = []
    when = datetime.datetime.now().strftime("%Y-%m-%d %H:%M")
    lines.append(f"Machine: {info.get('Model name', '?')}, {info.get('CPU(s)', '?')} CPUs "
                 f"(L2 {info.get('L2 cache', '?')}, L3 {info.get('L3 cache', '?')}), "
                 f"{info['platform']}; {when}")
    lines.append(f"Load average at start / end: {info['load average at start']} / "
                 f"{info['load average at end']}")
    lines.append(f"neutrospline kernels: {isa}; Python {info['python']}, " + ", ".join(
        f"{k} {v}" for k, v in versions.items()))
    lines.append("numpy BLAS (OPENBLAS_CORETYPE and OPENBLAS_L2_SIZE unset): " + "; ".join(
        f"{b['internal_api']} {b['version']} kernel {b['architecture']}" for b in blas))
    lines.append("")
    lines.append(f"{points:,} evenly spaced parameters, five channels per point "
                 "(x, y, truth, indeterminacy, falsity), one thread, Mpts/s (best run); "
                 "ratio = neutrospline / tool.")
    lines.append("")
    header = "| tool |" + "".join(f" degree {d} | ratio |" for d in DEGREES)
    lines.append(header)
    lines.append("|---|" + "---:|---:|" * len(DEGREES))
    names = ["neutrospline", "bezier evaluate_multi", "numpy Bernstein matrix", "scipy BSpline",
             "bezier evaluate_multi, x y only"]
    for name in names:
        cells = []
        for d in DEGREES:
            ours = rows[d]["neutrospline"][0]
            v = rows[d][name][0] if name == "neutrospline" else rows[d][name]
            ratio = "" if name == "neutrospline" else f"{ours / v:.1f}x"
            cells.append(f" {v:.1f} | {ratio} |")
        lines.append(f"| {name} |" + "".join(cells))
    lines.append("")
    lines.append(f"Splines: random clamped uniform curves with {PIECES} pieces, the same "
                 f"{points:,} parameters and channels, one thread, Mpts/s; ratio = neutrospline / "
                 "scipy.")
    lines.append("")
    lines.append(header)
    lines.append("|---|" + "---:|---:|" * len(DEGREES))
    for name, ours_key, theirs in [
        ("neutrospline B-spline", "bspline", None),
        ("scipy BSpline", "bspline", "scipy BSpline"),
        ("neutrospline NURBS", "nurbs", None),
        ("scipy BSpline, homogeneous + division", "nurbs",
         "scipy BSpline, homogeneous + division"),
    ]:
        cells = []
        for d in DEGREES:
            ours = splines[d][ours_key][0]
            v = ours if theirs is None else splines[d][theirs]
            ratio = "" if theirs is None else f"{ours / v:.1f}x"
            cells.append(f" {v:.1f} | {ratio} |")
        lines.append(f"| {name} |" + "".join(cells))
    lines.append("")
    lines.append("Memory-bandwidth reference (a tight loop writing the same five arrays, one "
                 "thread, measured alternately with the evaluator):")
    lines.append("")
    lines.append("| degree | neutrospline Mpts/s | write loop Mpts/s | fraction |")
    lines.append("|---:|---:|---:|---:|")
    for d in DEGREES:
        r = rows[d]["neutrospline"][1]
        lines.append(f"| {d} | {r['mpts_per_s']:.1f} | {r['write_reference_mpts_per_s']:.1f} | "
                     f"{100 * r['fraction_of_write_reference']:.0f}% |")
    lines.append("")
    lines.append("Threads, 10,000,000 points:")
    lines.append("")
    lines.append("| degree | 1 thread | 2 threads | speed-up | write loop 1 / 2 threads |")
    lines.append("|---:|---:|---:|---:|---:|")
    for d, res in scaling.items():
        one, two = res[1], res[2]
        lines.append(f"| {d} | {one['mpts_per_s']:.1f} | {two['mpts_per_s']:.1f} | "
                     f"{two['mpts_per_s'] / one['mpts_per_s']:.2f}x | "
                     f"{one['write_reference_mpts_per_s']:.1f} / "
                     f"{two['write_reference_mpts_per_s']:.1f} |")
    text = "\n".join(lines)
    print(text)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "latest.md").write_text(text + "\n")
    raw = {
        "machine": info, "blas": blas, "versions": versions, "points": points,
        "tools": {str(d): {k: (v[1] if k == "neutrospline" else v) for k, v in r.items()}
                  for d, r in rows.items()},
        "splines": {str(d): {k: (v[1] if k in ("bspline", "nurbs") else v) for k, v in r.items()}
                    for d, r in splines.items()},
        "threads": {str(d): {str(t): v for t, v in r.items()} for d, r in scaling.items()},
    }
    (out / "latest.json").write_text(json.dumps(raw, indent=1) + "\n")
    print(f"\nwritten: {out / 'latest.md'}, {out / 'latest.json'}")


if __name__ == "__main__":
    arguments = parse_args()
    if arguments.inside_venv:
        main_inside(arguments)
    else:
        sys.exit(ensure_venv(arguments))
