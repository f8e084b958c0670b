"""A minimal Chrome DevTools Protocol client over `--remote-debugging-pipe`: a headless
Chromium, pages, and `Runtime.evaluate`. Nothing else is enabled, so the browser does none of
the network and page instrumentation a test driver (Playwright) turns on, which on a two-core
machine costs a page that sends a request per frame several milliseconds a frame."""

import itertools
import json
import os
import subprocess
import tempfile


class Browser:
    """A headless Chromium driven through the pipe (file descriptors 3 and 4)."""

    def __init__(self, executable="/usr/bin/chromium", width=1600, height=1000):
        self.profile = tempfile.TemporaryDirectory(prefix="neutrospline-cdp-")
        to_browser_r, to_browser_w = os.pipe()
        from_browser_r, from_browser_w = os.pipe()

        def child_fds():
            os.dup2(to_browser_r, 3)
            os.dup2(from_browser_w, 4)

        self.process = subprocess.Popen(
            [executable, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
             f"--window-size={width},{height}", f"--user-data-dir={self.profile.name}",
             "--no-first-run", "--no-default-browser-check", "about:blank"],
            preexec_fn=child_fds, close_fds=False,
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        )
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.writer = os.fdopen(to_browser_w, "wb", buffering=0)
        self.reader = os.fdopen(from_browser_r, "rb", buffering=0)
        self.ids = itertools.count(1)
        self.pending = b""

    def _message(self):
        while b"\0" not in self.pending:
            chunk = self.reader.read(1 << 16)
            if not chunk:
                raise EOFError("the browser closed its pipe")
            self.pending += chunk
        message, self.pending = self.pending.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=None):
        """Sends a command and returns its result (events in between are dropped)."""
        ident = next(self.ids)
        command = {"id": ident, "method": method, "params": params or {}}
        if session:
            command["sessionId"] = session
        self.writer.write(json.dumps(command).encode() + b"\0")
        while True:
            message = self._message()
            if message.get("id") == ident:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message["result"]

    def page(self, url):
        target = self.call("Target.createTarget", {"url": url})["targetId"]
        session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})
        return Page(self, session["sessionId"])

    def close(self):
        try:
            self.call("Browser.close")
            self.process.wait(timeout=10)
        except Exception:
            self.process.kill()
        self.profile.cleanup()


class Page:
    def __init__(self, browser, session):
        self.browser = browser
        self.session = session

    def evaluate(self, expression):
        """The value of a JavaScript expression (awaited when it is a promise)."""
        result = self.browser.call(
            "Runtime.evaluate",
            {"expression": expression, "awaitPromise": True, "returnByValue": True},
            self.session,
        )
        if "exceptionDetails" in result:
            raise RuntimeError(result["exceptionDetails"])
        return result["result"].get("value")
