#!/usr/bin/env python3
# tests/scenarios/studio/check_studio_firefox.py: the design studio in headless Firefox ESR (driven
# over Marionette) against printd --printer none: a sample garment is sewn and shown, a planar image
# is placed by a pointer click on the garment (W3C pointer actions), and the 3D preview changes at
# the click and not in the canvas corner (canvas screenshots). Exit 0 when all hold, 77 without Firefox.
import os
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../console"))
import console_harness as h  # noqa: E402
import marionette  # noqa: E402


def region_change(a, b, x, y, r):
    """Mean absolute RGB difference of two canvas shots in the square of half-size r at (x, y)."""
    total, n = 0, 0
    for j in range(max(0, y - r), min(a[1], y + r)):
        for i in range(max(0, x - r), min(a[0], x + r)):
            pa, pb = a[2][j][i], b[2][j][i]
            total += abs(pa[0] - pb[0]) + abs(pa[1] - pb[1]) + abs(pa[2] - pb[2])
            n += 1
    return total / max(n, 1) / 3


PREVIEW_DONE = """const v = document.getElementById('st-view').dataset; const s = window.studio.state;
    return Number(v.applied || 0) > arguments[0] && s.pendingSince === null && Number(v.applied) === s.seq
           ? Number(v.applied) : 0"""


def main():
    if not os.path.exists(marionette.FIREFOX):
        print(f"SKIP: {marionette.FIREFOX} is missing (apt-get install firefox-esr)")
        return h.SKIP
    root = tempfile.mkdtemp(prefix="tp-studio-ff-")
    check = h.Checks()

    daemon = h.Daemon(root, printer="none")
    ff = None
    try:
        ff = marionette.Firefox(1366, 768)
        print(f"browser={ff.capabilities.get('browserName')} {ff.capabilities.get('browserVersion')}")
        ff.get(daemon.url + "studio/")
        ff.wait("return document.getElementById('st-sew') !== null && window.studio !== undefined", 30)
        ff.script("const s = document.getElementById('st-sample'); s.value = 'simple_top';"
                  "s.dispatchEvent(new Event('change')); document.getElementById('st-sew').click()")
        ff.wait("return window.studio.state.garment !== null", 300)
        first = ff.wait(PREVIEW_DONE, 120, 0)
        g = ff.script("return window.studio.state.garment")
        print(f"garment_id={g['id']} pieces={len(g['pieces'])} vertices={g['vertices']}")
        check(len(g["pieces"]) >= 2, "the sewn garment has its pieces")
        rect = ff.script("return document.querySelector('.st-canvas').getBoundingClientRect().toJSON()")
        before = h.read_png(ff.element_png(".st-canvas"))
        # Canvas pixels per CSS pixel (the screenshot is at the device pixel ratio).
        scale = before[0] / rect["width"]

        ff.script("document.querySelector('button[data-add=planar]').click()")
        cx, cy = rect["x"] + rect["width"] / 2, rect["y"] + 0.42 * rect["height"]
        hit = ff.script("return window.studio.pick(arguments[0], arguments[1])", cx, cy)
        check(hit is not None, "the click point is on the garment")
        t0 = time.time()
        ff.command("WebDriver:PerformActions", {"actions": [{
            "type": "pointer", "id": "mouse", "parameters": {"pointerType": "mouse"},
            "actions": [{"type": "pointerMove", "duration": 0, "x": int(cx), "y": int(cy), "origin": "viewport"},
                        {"type": "pointerDown", "button": 0}, {"type": "pause", "duration": 20},
                        {"type": "pointerUp", "button": 0}]}]})
        ff.command("WebDriver:ReleaseActions")
        ff.wait(PREVIEW_DONE, 60, first)
        print(f"click_to_preview_s={time.time() - t0:.2f}")
        layer = ff.script("return window.studio.design().layers.find(l => l.type === 'planar') || null")
        check(layer is not None and hit is not None and
              all(abs(layer["centre"][i] - hit["point"][i]) < 1 for i in range(3)),
              "the planar layer is centred on the clicked surface point")
        # The newest preview is drawn on a later animation frame, and under load the page may still
        # be sending the click's own preview after the one for the added layer: look until the
        # newest applied preview shows the image at the click (15 s at most).
        lx, ly = int((cx - rect["x"]) * scale), int((cy - rect["y"]) * scale)
        deadline = time.time() + 15
        while True:
            time.sleep(0.3)
            ff.wait(PREVIEW_DONE, 60, 0)
            placed = h.read_png(ff.element_png(".st-canvas"))
            here = region_change(before, placed, lx, ly, int(25 * scale))
            if here > 8 or time.time() > deadline:
                break
        corner = region_change(before, placed, int(15 * scale), int(15 * scale), int(10 * scale))
        print(f"planar_change_at_click={here:.1f} planar_change_in_corner={corner:.1f}")
        check(here > 8 and corner < 1, "the preview changed at the click and not in the corner")
    finally:
        if ff:
            ff.quit()
        daemon.stop()
    return h.finish(check, root, daemon)


if __name__ == "__main__":
    sys.exit(main())
