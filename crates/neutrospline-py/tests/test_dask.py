"""The Dask example at a test's size: 1,000,000 parameters and 50 curves on a local cluster of
two worker processes, the results bit-identical to one process's."""

import subprocess
import sys


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
