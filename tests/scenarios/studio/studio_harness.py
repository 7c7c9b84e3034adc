#!/usr/bin/env python3
# tests/scenarios/studio/studio_harness.py: shared by the studio's checks: printd (under printsim, or
# alone with --printer none) on a free loopback port, headless Chromium through Selenium, the
# garment OBJ as triangles per piece and point-to-surface distances.
import os
import re
import signal
import subprocess
import sys
import time

SKIP = 77  # ctest SKIP_RETURN_CODE: no browser here
HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("TP_SOURCE_DIR") or os.path.abspath(os.path.join(HERE, "../../.."))
BIN = os.environ.get("TP_BIN_DIR") or os.path.join(SOURCE, "build/bin")
CHROMIUM, CHROMEDRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"


def need_browser():
    """Exits with SKIP naming what is missing when Chromium, its driver or Selenium is absent."""
    missing = [p for p in (CHROMIUM, CHROMEDRIVER) if not os.path.exists(p)]
    try:
        import selenium  # noqa: F401
    except ImportError:
        missing.append("python3-selenium")
    if missing:
        print(f"SKIP: no browser for the studio test: missing {', '.join(missing)}")
        sys.exit(SKIP)


class Daemon:
    """printd with its own state folder; under printsim unless printer == 'none'. .url ends with '/'."""

    def __init__(self, root, printer="sim", example="top-strokes"):
        os.makedirs(root, exist_ok=True)
        self.log_path = os.path.join(root, "printd.log")
        conf = os.path.join(root, "none.conf")
        with open(conf, "w") as f:
            f.write("# the test gives every setting\n")
        printd = [os.path.join(BIN, "printd"), "--state-dir", os.path.join(root, "state"), "--out",
                  os.path.join(root, "out"), "--config", conf, "--listen", "127.0.0.1:0"]
        if printer == "none":
            cmd = printd + ["--printer", "none"]
        else:
            model = os.path.join(root, "printer-model.txt")
            subprocess.run([os.path.join(BIN, "printctl"), "printer-model", os.path.join(SOURCE, "examples", example),
                            "--out", model], check=True, stdout=subprocess.DEVNULL)
            cmd = [os.path.join(BIN, "printsim"), "run", "--job-dirs", "--out", os.path.join(root, "out"),
                   "--printer", model, "--"] + printd
        env = dict(os.environ)
        self.log = open(self.log_path, "w")
        self.proc = subprocess.Popen(cmd, stdout=self.log, stderr=subprocess.STDOUT, start_new_session=True, env=env)
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
    """Headless Chromium with software WebGL (SwiftShader), browser logs kept, downloads refused."""
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


def read_obj(text):
    """An OBJ's vertices and its triangles per group: (vertices, [(group, (a, b, c)), ...])."""
    verts, tris, group = [], [], ""
    for line in text.splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            verts.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] == "g":
            group = parts[1] if len(parts) > 1 else ""
        elif parts[0] == "f":
            idx = [int(p.split("/")[0]) - 1 for p in parts[1:]]
            for i in range(1, len(idx) - 1):
                tris.append((group, (idx[0], idx[i], idx[i + 1])))
    return verts, tris


def _sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def _dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def point_triangle_distance(p, a, b, c):
    """Euclidean distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5)."""
    ab, ac, ap = _sub(b, a), _sub(c, a), _sub(p, a)
    d1, d2 = _dot(ab, ap), _dot(ac, ap)
    def dist(q): return sum((p[i] - q[i]) ** 2 for i in range(3)) ** 0.5
    if d1 <= 0 and d2 <= 0: return dist(a)
    bp = _sub(p, b)
    d3, d4 = _dot(ab, bp), _dot(ac, bp)
    if d3 >= 0 and d4 <= d3: return dist(b)
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        v = d1 / (d1 - d3)
        return dist(tuple(a[i] + v * ab[i] for i in range(3)))
    cp = _sub(p, c)
    d5, d6 = _dot(ab, cp), _dot(ac, cp)
    if d6 >= 0 and d5 <= d6: return dist(c)
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        w = d2 / (d2 - d6)
        return dist(tuple(a[i] + w * ac[i] for i in range(3)))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return dist(tuple(b[i] + w * (c[i] - b[i]) for i in range(3)))
    denom = 1.0 / (va + vb + vc)
    v, w = vb * denom, vc * denom
    return dist(tuple(a[i] + ab[i] * v + ac[i] * w for i in range(3)))


def nearest_on_surface(p, verts, tris):
    """(distance mm, group) of the triangle nearest to p."""
    best = (float("inf"), "")
    for group, (i, j, k) in tris:
        a, b, c = verts[i], verts[j], verts[k]
        # A cheap box test first: skip triangles whose box is farther than the best so far.
        if any(min(a[d], b[d], c[d]) - p[d] > best[0] or p[d] - max(a[d], b[d], c[d]) > best[0] for d in range(3)):
            continue
        d = point_triangle_distance(p, a, b, c)
        if d < best[0]:
            best = (d, group)
    return best
