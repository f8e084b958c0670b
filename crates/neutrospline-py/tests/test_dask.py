"""Dask on a local cluster of two worker processes: the example at a test's size (1,000,000
parameters and 50 curves), and map_blocks of evaluate for every curve kind in 2-D and 3-D and a
surface, with blocks as the workers receive them, unaligned and byte-swapped; the results
bit-identical to one process's, one row per parameter."""

import subprocess
import sys

import cloudpickle
import dask.array as da
import numpy as np
import pytest
from dask.distributed import Client, LocalCluster

import neutrospline as ns


def test_dask_example_is_bit_identical(root):
    done = subprocess.run(
        [
            sys.executable,
            str(root / "examples" / "dask_evaluate.py"),
            "--parameters",
            "1000000",
            "--block",
            "250000",
            "--curves",
            "50",
            "--per-task",
            "10",
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stdout + done.stderr
    lines = done.stdout.splitlines()
    assert lines[0].startswith("evaluate 1,000,000 parameters in 4 blocks")
    assert lines[0].endswith("bit-identical: True")
    assert lines[1].startswith("fit 50 curves in 5 tasks")
    assert "bit-identical: True" in lines[1]


# ---- map_blocks on a cluster of worker processes, every curve kind and a surface ----

# The worker processes do not import this test module: its functions travel by value.
cloudpickle.register_pickle_by_value(sys.modules[__name__])


@pytest.fixture(scope="module")
def client():
    """One local cluster of two worker processes for the module (a start costs seconds)."""
    cluster = LocalCluster(
        n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None
    )
    client = Client(cluster)
    try:
        yield client
    finally:
        client.close()
        cluster.close()


def models(root):
    examples = root / "examples"
    positions = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0], [5.0, 1.5]])
    degrees = np.array(
        [[0.2, 0.3, 0.1], [0.9, 0.1, 0.0], [0.5, 0.5, 0.5], [0.25, 0.0, 0.75], [1.0, 0.0, 0.0]]
    )
    lifted = np.column_stack([positions, [0.0, 0.5, 1.0, 1.5, 2.0]])
    weights = np.array([1.0, 0.5, 2.0, 0.75, 1.0])
    return {
        "bezier-2d": ns.example1(),
        "bezier-3d": ns.Bezier(lifted, degrees),
        "bspline-2d": ns.load(examples / "bspline.toml"),
        "bspline-3d": ns.BSpline(lifted, degrees, degree=3),
        "nurbs-2d": ns.load(examples / "nurbs-circle.toml"),
        "nurbs-3d": ns.Nurbs(lifted, degrees, weights, degree=2),
        "helix-3d": ns.load(examples / "helix3d.toml"),
    }


def unaligned_copy(block):
    """The block at byte offset 1 of a fresh buffer: the layout of a block a worker receives
    in a network frame, made certain here."""
    buffer = np.zeros(block.nbytes + 1, dtype=np.uint8)
    view = np.ndarray(block.shape, dtype=block.dtype, buffer=buffer, offset=1)
    view[...] = block
    return view


def evaluate_block(t, curve, layout):
    if layout == "unaligned":
        t = unaligned_copy(t)
        assert not t.flags.aligned
    elif layout == "byteswapped":
        t = t.astype(">f8")
    return curve.evaluate(t)


def evaluate_surface_block(u, v, surface, layout):
    if layout == "unaligned":
        u, v = unaligned_copy(u), unaligned_copy(v)
    elif layout == "byteswapped":
        u, v = u.astype(">f8"), v.astype(">f8")
    return surface.evaluate(u, v)


# Parameters that travel from the client to the workers (from_array), in blocks of unequal
# sizes: 10,007 parameters in blocks of 1,000 (the last one of 7).
COUNT, BLOCK = 10_007, 1_000


@pytest.mark.parametrize("layout", ["as-received", "unaligned", "byteswapped"])
def test_map_blocks_on_worker_processes_is_bit_identical(client, root, layout):
    s = np.linspace(0.0, 1.0, COUNT)
    s[1::3] = np.sqrt(s[1::3])  # not only the uniform grid
    for name, curve in models(root).items():
        lo, hi = curve.domain
        t = s * (hi - lo) + lo
        # The blocks reach the workers as they are sent (most of them unaligned in the
        # distributed version pinned), and are evaluated as received.
        params = da.from_array(t, chunks=BLOCK)
        assert params.numblocks == (11,)
        local = curve.evaluate(t)
        columns = curve.dimension + 3
        values = params.map_blocks(
            evaluate_block,
            curve,
            layout,
            new_axis=1,
            chunks=(params.chunks[0], (columns,)),
            dtype=np.float64,
        )
        got = client.compute(values).result()
        assert got.shape == (COUNT, columns), name
        assert got.tobytes() == local.tobytes(), name
    # The work ran in the worker processes, not in this one.
    assert len(client.scheduler_info()["workers"]) == 2


@pytest.mark.parametrize("layout", ["as-received", "unaligned", "byteswapped"])
def test_surface_map_blocks_on_worker_processes_is_bit_identical(client, root, layout):
    surface = ns.load(root / "examples" / "nurbs-surface.json")
    (u0, u1), (v0, v1) = surface.domain
    u, v = np.meshgrid(np.linspace(u0, u1, 101), np.linspace(v0, v1, 77), indexing="ij")
    u_blocks = da.from_array(u, chunks=(30, 25))
    v_blocks = da.from_array(v, chunks=(30, 25))
    assert u_blocks.numblocks == (4, 4)
    values = da.map_blocks(
        evaluate_surface_block,
        u_blocks,
        v_blocks,
        surface,
        layout,
        new_axis=2,
        chunks=u_blocks.chunks + ((6,),),
        dtype=np.float64,
    )
    got = client.compute(values).result()
    local = surface.evaluate(u, v)
    assert got.shape == (101, 77, 6)
    assert got.tobytes() == local.tobytes()
