"""The wheel installs the `neutrospline` command (a console script over the same command-line
code, linked into the extension module) and carries `__version__`: checked against the cargo
binary, byte for byte."""

import pathlib
import re
import subprocess
import sys

import neutrospline

# The console script sits beside the interpreter of the environment the wheel is installed in.
SCRIPT = pathlib.Path(sys.executable).with_name("neutrospline")


def workspace_version(root):
    text = (root / "Cargo.toml").read_text()
    return re.search(r'^version = "([^"]+)"', text, re.MULTILINE).group(1)


def run(command, cwd):
    return subprocess.run(command, cwd=cwd, capture_output=True, text=True)


def test_version_is_the_workspaces(root):
    assert neutrospline.__version__ == workspace_version(root)
    assert "__version__" in neutrospline.__all__


def test_the_console_script_is_installed_and_reports_the_version(root, cli):
    assert SCRIPT.is_file(), SCRIPT
    ours = run([str(SCRIPT), "--version"], root)
    theirs = run([str(cli), "--version"], root)
    assert ours.returncode == 0
    assert ours.stdout == theirs.stdout == f"neutrospline {workspace_version(root)}\n"


def test_eval_prints_what_the_binary_prints(root, cli):
    args = ["eval", "examples/bspline.toml", "--samples", "7"]
    ours = run([str(SCRIPT), *args], root)
    theirs = run([str(cli), *args], root)
    assert ours.returncode == theirs.returncode == 0, ours.stderr
    assert ours.stdout == theirs.stdout
    # Seven rows and a header, the curve's first point is its first control point (clamped).
    assert len(ours.stdout.splitlines()) == 8


def test_python_dash_m_runs_the_same_command(root, cli):
    ours = run([sys.executable, "-m", "neutrospline", "check", "examples/example1.toml"], root)
    theirs = run([str(cli), "check", "examples/example1.toml"], root)
    assert ours.returncode == theirs.returncode == 0, ours.stderr
    assert ours.stdout == theirs.stdout


def test_errors_and_exit_statuses_are_the_binarys(root, cli, tmp_path):
    missing = tmp_path / "missing.toml"
    ours = run([str(SCRIPT), "eval", str(missing)], root)
    theirs = run([str(cli), "eval", str(missing)], root)
    assert ours.returncode == theirs.returncode == 1
    assert ours.stderr == theirs.stderr
    assert ours.stderr.startswith("error:") and "missing.toml" in ours.stderr
    usage = run([str(SCRIPT), "eval", "--no-such-option"], root)
    assert usage.returncode == 2
    assert "Usage: neutrospline eval" in usage.stderr
