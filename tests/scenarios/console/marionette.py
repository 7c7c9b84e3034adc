#!/usr/bin/env python3
# tests/scenarios/console/marionette.py: a small client of Firefox's Marionette protocol (length-
# prefixed JSON over TCP, the WebDriver commands), so Firefox ESR can be driven without geckodriver,
# which Debian does not package.
import json
import os
import shutil
import socket
import subprocess
import tempfile
import time

FIREFOX = "/usr/bin/firefox-esr"
ELEMENT = "element-6066-11e4-a52e-4f735466cecf"  # the WebDriver element reference key


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Firefox:
    """Headless Firefox with a throwaway profile, listening for Marionette on a free port."""

    def __init__(self, width=1366, height=768):
        self.profile = tempfile.mkdtemp(prefix="tp-firefox-")
        port = free_port()
        prefs = {"marionette.port": port, "browser.shell.checkDefaultBrowser": False,
                 "datareporting.policy.dataSubmissionEnabled": False, "toolkit.telemetry.reportingpolicy.firstRun": False,
                 "browser.startup.homepage_override.mstone": "ignore", "app.update.disabledForTesting": True,
                 "browser.aboutwelcome.enabled": False, "webgl.force-enabled": True}
        with open(os.path.join(self.profile, "user.js"), "w") as f:
            for k, v in prefs.items():
                f.write(f"user_pref({json.dumps(k)}, {json.dumps(v)});\n")
        self.log = open(os.path.join(self.profile, "firefox.log"), "w")
        # Headless Firefox finds no GL driver by itself on a machine without a display: Mesa's
        # software rasteriser through EGL gives it WebGL (as SwiftShader does for Chromium).
        env = dict(os.environ, MOZ_WEBGL_FORCE_EGL="1", LIBGL_ALWAYS_SOFTWARE="1")
        self.proc = subprocess.Popen([FIREFOX, "--headless", "--marionette", "--no-remote", "--profile", self.profile,
                                      f"--window-size={width},{height}", "about:blank"],
                                     stdout=self.log, stderr=subprocess.STDOUT, start_new_session=True, env=env)
        deadline = time.time() + 60
        while True:
            try:
                self.sock = socket.create_connection(("127.0.0.1", port), timeout=120)
                break
            except OSError:
                if time.time() > deadline or self.proc.poll() is not None:
                    raise RuntimeError("Firefox did not open Marionette: " + open(self.log.name).read()[-2000:])
                time.sleep(0.2)
        self.buffer = b""
        self.msg_id = 0
        self._read()  # the server's hello
        session = self.command("WebDriver:NewSession", {"capabilities": {"alwaysMatch": {"acceptInsecureCerts": True}}})
        self.capabilities = session.get("capabilities", {})
        self.command("WebDriver:SetWindowRect", {"width": width, "height": height})

    def _read(self):
        while b":" not in self.buffer:
            self.buffer += self.sock.recv(65536)
        length, rest = self.buffer.split(b":", 1)
        n = int(length)
        while len(rest) < n:
            chunk = self.sock.recv(1 << 20)
            if not chunk:
                raise RuntimeError("Marionette closed the connection")
            rest += chunk
        self.buffer = rest[n:]
        return json.loads(rest[:n])

    def command(self, name, params=None):
        self.msg_id += 1
        data = json.dumps([0, self.msg_id, name, params or {}]).encode()
        self.sock.sendall(str(len(data)).encode() + b":" + data)
        while True:
            reply = self._read()
            if reply[0] == 1 and reply[1] == self.msg_id:
                break
        if reply[2]:
            raise RuntimeError(f"{name}: {reply[2].get('error')}: {reply[2].get('message')}")
        return reply[3]

    def get(self, url):
        self.command("WebDriver:Navigate", {"url": url})

    def script(self, body, *args):
        return self.command("WebDriver:ExecuteScript", {"script": body, "args": list(args)}).get("value")

    def wait(self, body, timeout_s, *args):
        """Polls a script until it returns something truthy; returns it, or raises after timeout_s."""
        deadline = time.time() + timeout_s
        while time.time() < deadline:
            v = self.script(body, *args)
            if v:
                return v
            time.sleep(0.25)
        raise TimeoutError(f"waited {timeout_s} s for: {body.strip()[:120]}")

    def element_png(self, css):
        """A PNG screenshot of the first element matching `css`."""
        import base64
        ref = self.command("WebDriver:FindElement", {"using": "css selector", "value": css})["value"][ELEMENT]
        return base64.b64decode(self.command("WebDriver:TakeScreenshot", {"id": ref, "full": False, "hash": False})["value"])

    def quit(self):
        try:
            self.command("Marionette:Quit", {"flags": ["eForceQuit"]})
        except Exception:
            pass
        try:
            self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(self.proc.pid, 9)
            self.proc.wait()
        self.log.close()
        shutil.rmtree(self.profile, ignore_errors=True)
