"""The README's two quickstarts run as printed: the Python block executes and prints what its
comment says, and every command of the command-line block (but `studio`, which serves a page
until stopped) exits 0 and writes the files it names."""

import contextlib
import io
import os
import re
import shlex
import subprocess

import numpy as np
import pytest


def block_after(readme, heading, language):
    section = readme.split(heading, 1)[1]
    return re.search(rf"```{language}\n(.*?)```", section, re.DOTALL).group(1)


@pytest.fixture
def workdir(root, tmp_path, monkeypatch):
    """A scratch directory with the repository's examples, as the README's commands expect."""
    (tmp_path / "examples").symlink_to(root / "examples")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_the_python_quickstart_runs_and_prints_its_comment(root, workdir):
    code = block_after((root / "README.md").read_text(), "## Quickstart in Python", "python")
    printed = io.StringIO()
    namespace = {}
    with contextlib.redirect_stdout(printed):
        exec(compile(code, "README.md", "exec"), namespace)
    # The printed row is the paper's curve at t = 0.5 (Example 1; docs/model.md section 4).
    assert printed.getvalue().strip() == "[4.625 4.    0.625 0.2   0.175]"
    np.testing.assert_allclose(namespace["rows"][5], [4.625, 4.0, 0.625, 0.2, 0.175], atol=1e-15)
    assert (workdir / "survey.toml").is_file()
    assert "<svg" in (workdir / "survey.svg").read_text()
    assert namespace["report"]["control_points"] == 12


def test_the_command_line_quickstart_runs(root, cli, workdir):
    script = block_after((root / "README.md").read_text(), "## Quickstart on the command line", "sh")
    script = script.replace("\\\n", " ")
    ran = 0
    for line in script.splitlines():
        command = shlex.split(line, comments=True)
        if not command or command[1] == "studio":
            continue
        assert command[0] == "neutrospline", line
        result = subprocess.run(
            [str(cli), *command[1:]], capture_output=True, text=True, env=os.environ
        )
        assert result.returncode == 0, (line, result.stderr)
        ran += 1
    assert ran == 9
    for written in ["figures/figure1.svg", "helix.png", "survey.toml", "survey.svg",
                    "survey.dxf", "field-1.toml", "field-2.toml", "fig5.pdf",
                    "finer.toml"]:
        assert (workdir / written).stat().st_size > 0, written
