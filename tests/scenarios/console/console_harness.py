#!/usr/bin/env python3
# tests/scenarios/console/console_harness.py: shared by the console's browser checks: a printd under
# printsim (or alone with --printer none) on a free loopback port, headless Chromium via Selenium,
# zipping an example job, and reading PNG screenshots.
import os
import re
import shutil
import signal
import subprocess
import sys
import time
import zipfile

SKIP = 77  # ctest SKIP_RETURN_CODE: no browser on this machine
HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("TP_SOURCE_DIR") or os.path.abspath(os.path.join(HERE, "../../.."))
BIN = os.environ.get("TP_BIN_DIR") or os.path.join(SOURCE, "build/bin")
sys.path.insert(0, os.path.join(SOURCE, "tests/scenarios/jobs/readers"))


def read_png(data):
    """The viewer check's PNG reader (it imports Selenium, so only loaded when a browser test runs)."""
    from check_garment_viewer import read_png as reader
    return reader(data)

CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"


def need_browser():
    """Exits with SKIP and says why when Chromium, its driver or Selenium is missing."""
    missing = [p for p in (CHROMIUM, CHROMEDRIVER) if not os.path.exists(p)]
    try:
        import selenium  # noqa: F401
    except ImportError:
        missing.append("python3-selenium")
    if missing:
        print(f"SKIP: no browser to test the console with: missing {', '.join(missing)} "
              "(apt-get install chromium chromium-driver python3-selenium)")
        sys.exit(SKIP)


def zip_job(folder, zip_path):
    """The job folder as a .zip, the way a designer would send it."""
    with zipfile.ZipFile(zip_path, "w", zipfile.ZIP_DEFLATED) as z:
        for root, _, files in os.walk(folder):
            for f in sorted(files):
                full = os.path.join(root, f)
                z.write(full, os.path.relpath(full, folder))
    return zip_path


class Daemon:
    """printd (under printsim unless printer='none') with its own state; .port is the HTTP port."""

    def __init__(self, root, printer="sim", example="top-strokes", extra=(), scenario=None):
        self.root = root
        os.makedirs(root, exist_ok=True)
        self.log_path = os.path.join(root, "printd.log")
        self.state = os.path.join(root, "state")
        conf = os.path.join(root, "none.conf")
        with open(conf, "w") as f:
            f.write("# the test gives every setting\n")
        printd = [os.path.join(BIN, "printd"), "--state-dir", self.state, "--out", os.path.join(root, "out"),
                  "--config", conf, "--listen", "127.0.0.1:0"] + list(extra)
        if printer == "none":
            cmd = printd + ["--printer", "none"]
        else:
            model = os.path.join(root, "printer-model.txt")
            subprocess.run([os.path.join(BIN, "printctl"), "printer-model", os.path.join(SOURCE, "examples", example),
                            "--out", model], check=True, stdout=subprocess.DEVNULL)
            cmd = [os.path.join(BIN, "printsim"), "run", "--job-dirs", "--out", os.path.join(root, "out"),
                   "--printer", model]
            if scenario:
                path = os.path.join(root, "scenario.json")
                with open(path, "w") as f:
                    f.write(scenario)
                cmd += ["--scenario", path]
            cmd += ["--"] + printd
        self.log = open(self.log_path, "w")
        self.proc = subprocess.Popen(cmd, stdout=self.log, stderr=subprocess.STDOUT, start_new_session=True)
        self.port = 0
        deadline = time.time() + 30
        while time.time() < deadline and not self.port:
            m = re.search(r"HTTP API on http://[^ ]+:(\d+)", open(self.log_path).read())
            if m:
                self.port = int(m.group(1))
            elif self.proc.poll() is not None:
                break
            else:
                time.sleep(0.1)
        if not self.port:
            self.stop()
            raise RuntimeError("printd did not start:\n" + open(self.log_path).read()[-3000:])
        self.url = f"http://127.0.0.1:{self.port}/"

    def stop(self):
        if self.proc.poll() is None:
            os.killpg(self.proc.pid, signal.SIGTERM)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.proc.pid, signal.SIGKILL)
                self.proc.wait()
        self.log.close()


def chromium(width=1366, height=768):
    """Headless Chromium with software WebGL (SwiftShader), browser console logs kept."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    opts = webdriver.ChromeOptions()
    opts.binary_location = CHROMIUM
    for a in ("--headless=new", "--no-sandbox", "--use-gl=swiftshader", "--enable-unsafe-swiftshader",
              "--disable-dev-shm-usage", f"--window-size={width},{height}", "--hide-scrollbars"):
        opts.add_argument(a)
    opts.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=opts)
    driver.set_window_size(width, height)
    return driver


def severe_logs(driver):
    return [e["message"] for e in driver.get_log("browser") if e.get("level") == "SEVERE"]


def cleanup(path):
    shutil.rmtree(path, ignore_errors=True)


class Checks:
    """The named checks of one test: each prints ok or FAIL with what it checks; failures lists the failed ones."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, what):
        print(f"{'ok' if ok else 'FAIL'}: {what}")
        if not ok:
            self.failures.append(what)


def finish(checks, root, daemon=None, log_text=None):
    """The test's exit code: 1 when a check failed (printd's log or `log_text` named, `root` kept to look at), else 0
    with `root` removed."""
    if checks.failures:
        if daemon:
            print(f"printd log: {daemon.log_path}")
        if log_text:
            print(log_text)
        return 1
    cleanup(root)
    return 0
