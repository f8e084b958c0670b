"""Fixtures of the studio's browser tests: the `neutrospline` binary, a running studio on a
file, and a headless Chromium page (Debian's chromium through Playwright's executable_path).

Environment: NEUTROSPLINE_BIN (the binary, required), STUDIO_E2E_OUT (screenshots and
downloads; default target/studio-e2e), CHROMIUM (default /usr/bin/chromium).
"""

import os
import re
import subprocess
from pathlib import Path

import pytest
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def binary():
    path = os.environ.get("NEUTROSPLINE_BIN")
    if not path:
        pytest.fail("set NEUTROSPLINE_BIN to the neutrospline binary (scripts/studio-e2e does)")
    return Path(path).resolve()


@pytest.fixture(scope="session")
def out_dir():
    path = Path(os.environ.get("STUDIO_E2E_OUT", ROOT / "target" / "studio-e2e"))
    path.mkdir(parents=True, exist_ok=True)
    return path


class Studio:
    """A `neutrospline studio FILE --no-open` process and its URL."""

    def __init__(self, binary, file=None):
        args = [str(binary), "studio", "--no-open", "--port", "0"]
        if file is not None:
            args.append(str(file))
        self.process = subprocess.Popen(
            args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
        )
        line = self.process.stdout.readline()
        match = re.search(r"http://127\.0\.0\.1:(\d+)/", line)
        if not match:
            self.process.kill()
            raise AssertionError(
                f"no URL printed: {line!r} {self.process.stderr.read()!r}"
            )
        self.url = match.group(0)
        self.port = int(match.group(1))

    def stop(self):
        self.process.terminate()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()


@pytest.fixture
def start_studio(binary):
    started = []

    def start(file=None):
        studio = Studio(binary, file)
        started.append(studio)
        return studio

    yield start
    for studio in started:
        assert studio.process.poll() is None, "the studio server exited during the test"
        studio.stop()


@pytest.fixture(scope="session")
def browser():
    with sync_playwright() as pw:
        chromium = pw.chromium.launch(
            executable_path=os.environ.get("CHROMIUM", "/usr/bin/chromium"), headless=True
        )
        yield chromium
        chromium.close()


@pytest.fixture
def page(browser):
    context = browser.new_context(
        viewport={"width": 1600, "height": 1000}, accept_downloads=True,
        # The page forbids eval (Content-Security-Policy); wait_for_function needs it.
        bypass_csp=True,
    )
    page = context.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    yield page
    context.close()
    assert not errors, f"JavaScript errors on the page: {errors}"
