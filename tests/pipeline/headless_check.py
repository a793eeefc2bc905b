#!/usr/bin/env python3
"""Open an HTML file in headless Chromium and report what a reader would meet: console errors,
uncaught exceptions, failed loads, and every <img> that did not resolve to a decoded image.

    headless_check.py FILE.html [--chromium PATH]

Talks to the browser over the DevTools protocol on a pipe (--remote-debugging-pipe: fd 3 in,
fd 4 out, messages ended by NUL), so it needs nothing beyond the standard library. The flags are
those of a shared build machine or a CI container run as root (no sandbox, no GPU, no network
services, /tmp rather than a small /dev/shm, a fresh profile). Prints one
line per problem and a summary; exits 0 when the page loaded with no error and every image has a
natural size, 1 otherwise, 2 when the browser could not be driven.
"""
import argparse
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage", "--remote-debugging-pipe"]


class Browser:
    def __init__(self, chromium, profile):
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()
        # The browser reads fd 3 and writes fd 4: dup the pipe ends there in the child (dup2
        # makes them inheritable; close_fds would close them again after preexec_fn).
        def child_fds():
            read, write = os.dup(to_browser_r), os.dup(from_browser_w)  # above 4: no overlap
            os.dup2(read, 3)
            os.dup2(write, 4)
        self.process = subprocess.Popen(
            [chromium, *FLAGS, f"--user-data-dir={profile}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            preexec_fn=child_fds, close_fds=False)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.buffer = b""
        self.next_id = 0
        self.events = []

    def send(self, method, params=None, session=None):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        return self.next_id

    def receive(self, deadline):
        """The next message, or None at the deadline."""
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.from_browser], [], [], left)[0]:
                return None
            chunk = os.read(self.from_browser, 1 << 16)
            if not chunk:
                raise RuntimeError("the browser closed its pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, session=None, timeout=30):
        wanted = self.send(method, params, session)
        deadline = time.monotonic() + timeout
        while True:
            message = self.receive(deadline)
            if message is None:
                raise RuntimeError(f"no answer to {method} within {timeout} s")
            if message.get("id") == wanted:
                if "error" in message:
                    raise RuntimeError(f"{method}: {message['error']}")
                return message.get("result", {})
            self.events.append(message)

    def wait_for(self, method, timeout):
        deadline = time.monotonic() + timeout
        if any(message.get("method") == method for message in self.events):
            return True
        while True:
            message = self.receive(deadline)
            if message is None:
                return False
            self.events.append(message)
            if message.get("method") == method:
                return True

    def close(self):
        try:
            self.send("Browser.close")
            self.process.wait(timeout=10)
        except (OSError, subprocess.TimeoutExpired):
            self.process.kill()
            self.process.wait()


def problems_of(events):
    found = []
    for event in events:
        method, params = event.get("method"), event.get("params", {})
        if method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in params["args"])
            found.append(f"console.{params['type']}: {text}")
        elif method == "Runtime.exceptionThrown":
            details = params.get("exceptionDetails", {})
            found.append("uncaught exception: " + details.get("exception", {}).get(
                "description", details.get("text", "")))
        elif method == "Log.entryAdded" and params.get("entry", {}).get("level") == "error":
            entry = params["entry"]
            found.append(f"console error ({entry.get('source')}): {entry.get('text')} "
                         f"{entry.get('url', '')}".rstrip())
    return found


IMAGES = """JSON.stringify(Array.from(document.images).map(
    i => ({src: i.getAttribute('src'), complete: i.complete, width: i.naturalWidth})))"""


def check(page, chromium):
    with tempfile.TemporaryDirectory(prefix="headless-check-") as profile:
        browser = Browser(chromium, profile)
        try:
            targets = browser.call("Target.getTargets")["targetInfos"]
            target = next(t["targetId"] for t in targets if t["type"] == "page")
            session = browser.call("Target.attachToTarget",
                                   {"targetId": target, "flatten": True})["sessionId"]
            for domain in ("Runtime", "Log", "Page"):
                browser.call(f"{domain}.enable", session=session)
            browser.call("Page.navigate", {"url": page.resolve().as_uri()}, session=session)
            if not browser.wait_for("Page.loadEventFired", timeout=60):
                return ["the page did not finish loading within 60 s"], []
            images = json.loads(browser.call("Runtime.evaluate", {"expression": IMAGES},
                                             session=session)["result"]["value"])
            browser.wait_for("never", timeout=0.5)  # late console messages
            problems = problems_of(browser.events)
        finally:
            browser.close()
    problems += [f"image does not resolve: {i['src']}" for i in images
                 if not i["complete"] or i["width"] == 0]
    return problems, images


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("page", type=Path)
    parser.add_argument("--chromium", default=shutil.which("chromium") or "chromium")
    args = parser.parse_args()
    if not args.page.is_file():
        sys.exit(f"headless_check.py: no file {args.page}")
    try:
        problems, images = check(args.page, args.chromium)
    except (OSError, RuntimeError, StopIteration) as error:
        print(f"headless_check.py: cannot drive {args.chromium}: {error!r}", file=sys.stderr)
        return 2
    for problem in problems:
        print(f"FAIL {args.page.name}: {problem}")
    print(f"headless_check.py: {args.page}: {len(images)} images, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
