"""Shared fixtures of the differential harness: the `neutrospline` binary, the case budget and
the seed.

The harness checks the library against references that share no code with it (mpmath, sympy,
Python's csv module, brute force written here). `scripts/check` runs it with a small budget;
`scripts/differential --long` runs the long budget (see docs/correctness.md).

Environment:
  NEUTROSPLINE_BIN         the command line (default: target/debug/neutrospline, built when missing)
  NEUTROSPLINE_DIFF_CASES  random cases per test (default 40; the long run uses 5000)
  NEUTROSPLINE_DIFF_SEED   the first seed (default 2026); case k uses seed + k
"""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
REGRESSIONS = pathlib.Path(__file__).resolve().parent / "regressions"


@pytest.fixture(scope="session")
def root() -> pathlib.Path:
    return ROOT


@pytest.fixture(scope="session")
def regressions() -> pathlib.Path:
    """The folder of shrunk failures, one JSON file each, replayed by every run."""
    return REGRESSIONS


@pytest.fixture(scope="session")
def cli() -> pathlib.Path:
    """The command line, built by cargo when NEUTROSPLINE_BIN does not name one."""
    given = os.environ.get("NEUTROSPLINE_BIN")
    if given:
        return pathlib.Path(given)
    subprocess.run(["cargo", "build", "-q", "-p", "neutrospline-cli"], cwd=ROOT, check=True)
    return ROOT / "target" / "debug" / "neutrospline"


def case_budget() -> int:
    return int(os.environ.get("NEUTROSPLINE_DIFF_CASES", "40"))


def first_seed() -> int:
    return int(os.environ.get("NEUTROSPLINE_DIFF_SEED", "2026"))


@pytest.fixture(scope="session")
def budget() -> int:
    return case_budget()


@pytest.fixture(scope="session")
def seed() -> int:
    return first_seed()
