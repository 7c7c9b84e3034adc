#!/usr/bin/env python3
# tests/scenarios/jobs/readers/check_garment_viewer.py: opens a job's garment.obj (with garment.mtl
# and garment.png) in headless Chromium through three.js, screenshots it and prints key=value facts
# about the rendered garment's colours against the texture's. Exit 0 when it shows the print.
# Usage: check_garment_viewer.py OUT_DIR [SCREENSHOT.png]
import colorsys
import functools
import http.server
import os
import struct
import sys
import tempfile
import threading
import time
import zlib

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait

THREE = "/usr/share/javascript/three"
HERE = os.path.dirname(os.path.abspath(__file__))
RENDERER_JS = """
const gl = document.createElement("canvas").getContext("webgl");
if (!gl) return "none";
const info = gl.getExtension("WEBGL_debug_renderer_info");
return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
"""


def read_png(data):
    """8-bit RGB or RGBA PNG (non-interlaced) -> (width, height, rows of (r, g, b, a) tuples)."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or ctype not in (2, 6) or interlace:
                raise ValueError(f"unsupported PNG: depth {depth} colour type {ctype} interlace {interlace}")
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, prev, rows, i = zlib.decompress(idat), width * bpp, bytearray(width * bpp), [], 0
    for _ in range(height):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x:x + 3]) + ((line[x + 3],) if bpp == 4 else (255,)) for x in range(0, stride, bpp)])
        prev = line
    return width, height, rows


def lit_share(path):
    """Share of a screenshot's pixels that are not the viewer's black background."""
    w, h, rows = read_png(open(path, "rb").read())
    return sum(1 for row in rows for p in row if max(p[:3]) > 8) / max(w * h, 1)


def hue_bins(pixels, bins=12):
    """Share of saturated pixels per hue bin, and the mean saturation of all."""
    hist, sat_sum, n = [0] * bins, 0.0, 0
    for r, g, b in pixels:
        h, s, v = colorsys.rgb_to_hsv(r / 255, g / 255, b / 255)
        sat_sum += s
        n += 1
        if s > 0.15 and v > 0.1:
            hist[int(h * bins) % bins] += 1
    total = max(sum(hist), 1)
    return [c / total for c in hist], sat_sum / max(n, 1)


def main():
    out = os.path.abspath(sys.argv[1])
    shot = sys.argv[2] if len(sys.argv) > 2 else os.path.join(out, "garment-viewer.png")
    with tempfile.TemporaryDirectory() as root:
        os.symlink(THREE, os.path.join(root, "three"))
        os.symlink(os.path.join(HERE, "garment_viewer.html"), os.path.join(root, "viewer.html"))
        for name in ("garment.obj", "garment.mtl", "garment.png"):
            os.symlink(os.path.join(out, name), os.path.join(root, name))
        class Quiet(http.server.SimpleHTTPRequestHandler):
            def log_message(self, *args):
                pass

        handler = functools.partial(Quiet, directory=root)
        server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        threading.Thread(target=server.serve_forever, daemon=True).start()
        opts = webdriver.ChromeOptions()
        opts.binary_location = "/usr/bin/chromium"
        for a in ("--headless=new", "--no-sandbox", "--use-gl=swiftshader", "--enable-unsafe-swiftshader",
                  "--disable-dev-shm-usage", "--window-size=640,800", "--hide-scrollbars"):
            opts.add_argument(a)
        driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)
        try:
            driver.set_window_size(640, 800)
            driver.get(f"http://127.0.0.1:{server.server_address[1]}/viewer.html?view=front")
            WebDriverWait(driver, 60).until(lambda d: d.title.startswith(("ready", "error")))
            title = driver.title
            print(f"viewer_title={title}")
            print(f"webgl={driver.execute_script(RENDERER_JS)}")
            # The drawing buffer read back, then the screenshot. A loaded machine has shown a
            # screenshot of the black page after the "ready" frame; each is retried a few times, and
            # the attempts are printed, before the check reads the picture.
            lit, attempts = 0.0, 0
            while title.startswith("ready") and attempts < 5:
                attempts += 1
                lit = driver.execute_script("return window.viewerLitShare()")
                if lit > 0.05:
                    driver.save_screenshot(shot)
                    if lit_share(shot) > 0.05:
                        break
                time.sleep(1)
                driver.execute_script("window.viewerRender()")
                title = driver.title
            else:
                driver.save_screenshot(shot)
            print(f"canvas_lit_share={lit:.3f}")
            print(f"attempts={attempts}")
            logs = driver.get_log("browser")
            errors = [e["message"] for e in logs if e.get("level") == "SEVERE"]
            print(f"console_errors={len(errors)}")
            for e in errors[:5]:
                print(f"console_error={e}")
            if lit <= 0.05:
                for e in logs[:10]:
                    print(f"console_{e.get('level', '').lower()}={e['message']}")
        finally:
            driver.quit()
            server.shutdown()
    print(f"screenshot={shot}")
    if not title.startswith("ready"):
        return 1
    w, h, rows = read_png(open(shot, "rb").read())
    garment = [p[:3] for row in rows for p in row if max(p[:3]) > 8]  # not the black background
    share = len(garment) / (w * h)
    render_hist, render_sat = hue_bins(garment)
    _, _, trows = read_png(open(os.path.join(out, "garment.png"), "rb").read())
    texture = [p[:3] for row in trows[::4] for p in row[::4] if p[3] > 250]
    tex_hist, tex_sat = hue_bins(texture)
    overlap = sum(min(a, b) for a, b in zip(render_hist, tex_hist))
    distinct = len({(r // 16, g // 16, b // 16) for r, g, b in garment})
    print(f"garment_share={share:.3f}")
    print(f"distinct_colours={distinct}")
    print(f"render_saturation={render_sat:.3f}")
    print(f"texture_saturation={tex_sat:.3f}")
    print(f"hue_overlap={overlap:.3f}")
    ok = share > 0.05 and distinct > 20 and render_sat > 0.5 * tex_sat and overlap > 0.5
    print(f"shows_print={'yes' if ok else 'no'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
