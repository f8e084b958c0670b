"""neutrospline on a Dask cluster: evaluate a curve at millions of parameters and fit many
curves in parallel, and check that the results are bit-identical to one process's.

    python examples/dask_evaluate.py                       # a local cluster of 2 workers
    python examples/dask_evaluate.py --parameters 1000000 --curves 50
    python examples/dask_evaluate.py --scheduler tcp://scheduler.example:8786

With --scheduler the same script runs on a real cluster (every worker needs the package:
`pip install ./crates/neutrospline-py`). What scales: parameters per block (--block; each
block is one task that evaluates in the batch engine, so blocks of 10^5 to 10^6 parameters
keep the scheduling overhead small) and curves per task (--per-task; each fit takes about a
millisecond, so group tens of them). Curves travel to the workers by pickle (the model as
exact JSON), so a worker evaluates exactly the curve the client built.
"""

import argparse
import sys
import time

import dask.array as da
import dask.bag as db
import numpy as np
from dask.distributed import Client, LocalCluster

import neutrospline as ns


def evaluate_block(t, curve):
    """One block of parameters: the curve's rows (x, y, truth, indeterminacy, falsity)."""
    return curve(t)


def data_set(seed, points=60):
    """A deterministic noisy data set: a wave with degrees that drift along it."""
    rng = np.random.default_rng(seed)
    s = np.linspace(0.0, 1.0, points)
    x = 10.0 * s
    y = np.sin(2.0 * np.pi * s * (1.0 + seed % 5)) + 0.05 * rng.standard_normal(points)
    truth = np.clip(0.9 - 0.5 * s + 0.05 * rng.standard_normal(points), 0.0, 1.0)
    indeterminacy = np.clip(0.1 + 0.3 * s, 0.0, 1.0)
    falsity = np.clip(0.05 + 0.4 * s, 0.0, 1.0)
    return np.column_stack([x, y]), np.column_stack([truth, indeterminacy, falsity])


def fit_one(seed):
    """Fits one data set: the fitted control points, degrees and knots, and the max error."""
    positions, degrees = data_set(seed)
    curve, report = ns.fit(positions, degrees, control_points=12)
    return curve, report["max_error"]["y"]


def fit_many(seeds):
    return [fit_one(seed) for seed in seeds]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--parameters", type=int, default=10_000_000)
    parser.add_argument("--block", type=int, default=1_000_000)
    parser.add_argument("--curves", type=int, default=1_000)
    parser.add_argument("--per-task", type=int, default=25)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--scheduler", help="address of a running scheduler (tcp://host:8786)")
    args = parser.parse_args(argv)

    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(
            n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None
        )
        client = Client(cluster)
    try:
        curve = ns.example1()
        n = args.parameters
        # Parameters k / (n - 1), computed the same way in every block and in one process.
        t = da.arange(n, chunks=args.block, dtype=np.float64) / (n - 1)
        values = t.map_blocks(
            evaluate_block, curve, new_axis=1, chunks=(t.chunks[0], (5,)), dtype=np.float64
        )
        start = time.perf_counter()
        cluster_values = values.compute()
        cluster_seconds = time.perf_counter() - start
        start = time.perf_counter()
        local_values = curve(np.arange(n, dtype=np.float64) / (n - 1))
        local_seconds = time.perf_counter() - start
        same_values = np.array_equal(cluster_values, local_values)
        print(
            f"evaluate {n:,} parameters in {len(t.chunks[0])} blocks: cluster "
            f"{cluster_seconds:.3f} s, one process {local_seconds:.3f} s, "
            f"bit-identical: {same_values}"
        )

        seeds = list(range(args.curves))
        groups = [seeds[k : k + args.per_task] for k in range(0, len(seeds), args.per_task)]
        start = time.perf_counter()
        cluster_fits = [fit for group in db.from_sequence(groups, npartitions=len(groups)).map(fit_many).compute() for fit in group]
        cluster_seconds = time.perf_counter() - start
        start = time.perf_counter()
        local_fits = [fit_one(seed) for seed in seeds]
        local_seconds = time.perf_counter() - start
        same_fits = all(
            a == b
            and np.array_equal(a.positions, b.positions)
            and np.array_equal(a.membership_degrees, b.membership_degrees)
            and ea == eb
            for (a, ea), (b, eb) in zip(cluster_fits, local_fits)
        )
        worst = max(error for _, error in local_fits)
        print(
            f"fit {len(seeds):,} curves in {len(groups)} tasks: cluster {cluster_seconds:.3f} s, "
            f"one process {local_seconds:.3f} s, bit-identical: {same_fits} "
            f"(largest y error {worst:.3g})"
        )
        return 0 if same_values and same_fits else 1
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


if __name__ == "__main__":
    sys.exit(main())
