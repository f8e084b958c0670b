"""Shared fixtures: the repository root, the `neutrospline` binary, reference curves."""

import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def root() -> pathlib.Path:
    return ROOT


@pytest.fixture(scope="session")
def cli() -> pathlib.Path:
    """The command line, built by cargo when NEUTROSPLINE_BIN does not name one."""
    given = os.environ.get("NEUTROSPLINE_BIN")
    if given:
        return pathlib.Path(given)
    subprocess.run(
        ["cargo", "build", "-q", "-p", "neutrospline-cli"], cwd=ROOT, check=True
    )
    return ROOT / "target" / "debug" / "neutrospline"


@pytest.fixture
def in_root(monkeypatch):
    """Runs the test in the repository root (doctests name files under examples/)."""
    monkeypatch.chdir(ROOT)
