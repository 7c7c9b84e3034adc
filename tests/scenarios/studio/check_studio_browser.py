#!/usr/bin/env python3
# tests/scenarios/studio/check_studio_browser.py: the design studio in headless Chromium against printd
# under printsim: sew a sample garment, place a planar image by a click, paint a stroke across a seam
# with synthetic mouse events, check the 3D preview changed where the tools touched it (screenshot
# pixels), time ten changes to the updated preview, save the job and check it with `printctl
# validate`, that the painted stroke lies on the studio's garment within 1 mm and reaches two pieces,
# then print it and check the saved stroke lies on the garment the job sewed within 1 mm. Prints
# key=value figures; exit 0 when every check holds. TP_STUDIO_SHOTS=DIR keeps screenshots.
import base64
import io
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
import zipfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from studio_harness import BIN, SOURCE, Daemon, chromium, nearest_on_surface, need_browser, read_obj  # noqa: E402

sys.path.insert(0, os.path.join(SOURCE, "tests/scenarios/jobs/readers"))

failures = []


def check(ok, what):
    print(f"{'ok' if ok else 'FAIL'}: {what}")
    if not ok:
        failures.append(what)


def wait(driver, cond, timeout, what):
    end = time.time() + timeout
    while time.time() < end:
        v = driver.execute_script(cond)
        if v:
            return v
        time.sleep(0.05)
    raise RuntimeError(f"timed out after {timeout} s waiting for {what}")


def applied(driver):
    return int(driver.execute_script("return Number(document.getElementById('st-view').dataset.applied || 0)"))


def wait_preview(driver, after, timeout=60):
    """Waits until a preview newer than `after` is on the garment and none is pending."""
    return wait(driver, f"""const v = document.getElementById('st-view').dataset;
        return Number(v.applied || 0) > {after} && window.studio.state.pendingSince === null &&
               Number(v.applied) === window.studio.state.seq ? Number(v.applied) : 0""", timeout, "the preview")


def screenshot(driver, shots, name):
    from check_garment_viewer import read_png
    png = driver.get_screenshot_as_png()
    if shots:
        with open(os.path.join(shots, name), "wb") as f:
            f.write(png)
    return read_png(png)


def region_change(a, b, x, y, r):
    """Mean absolute RGB difference of two screenshots in the square of half-size r at (x, y)."""
    total, n = 0, 0
    for j in range(max(0, y - r), min(len(a[2]), y + r)):
        for i in range(max(0, x - r), min(a[0], x + r)):
            pa, pb = a[2][j][i], b[2][j][i]
            total += abs(pa[0] - pb[0]) + abs(pa[1] - pb[1]) + abs(pa[2] - pb[2])
            n += 1
    return total / max(n, 1) / 3


def reddish(p):
    return p[0] > 120 and p[0] > 2 * p[1] and p[0] > 2 * p[2]


def pointer_path(driver, points):
    """Press at the first client point, move through the rest, release (W3C pointer actions)."""
    from selenium.webdriver.common.action_chains import ActionChains
    from selenium.webdriver.common.actions.action_builder import ActionBuilder
    from selenium.webdriver.common.actions.mouse_button import MouseButton
    actions = ActionChains(driver, duration=10)
    ptr = actions.w3c_actions.pointer_action
    ptr.move_to_location(int(points[0][0]), int(points[0][1]))
    ptr.pointer_down(MouseButton.LEFT)
    for x, y in points[1:]:
        ptr.move_to_location(int(x), int(y))
    ptr.pointer_up(MouseButton.LEFT)
    actions.perform()


def main():
    need_browser()
    shots = os.environ.get("TP_STUDIO_SHOTS")
    if shots:
        os.makedirs(shots, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="studio-browser-") as root:
        daemon = Daemon(os.path.join(root, "d"), printer="sim")
        driver = None
        try:
            driver = chromium()
            t0 = time.time()
            driver.get(daemon.url + "studio/")
            wait(driver, "return document.getElementById('st-sew') !== null", 30, "the studio page")
            driver.find_element("id", "st-sample").send_keys("simple_top")
            driver.find_element("id", "st-sew").click()
            wait(driver, "return window.studio.state.garment !== null", 180, "the sewn garment")
            first = wait_preview(driver, 0, 60)
            g = driver.execute_script("return window.studio.state.garment")
            print(f"garment_id={g['id']} pieces={len(g['pieces'])} vertices={g['vertices']} sew_s={g['sew_s']:.2f}")
            print(f"page_to_first_preview_s={time.time() - t0:.2f}")
            rect = driver.execute_script("return document.querySelector('.st-canvas').getBoundingClientRect().toJSON()")
            cx, cy = rect["x"] + rect["width"] / 2, rect["y"] + rect["height"] / 2
            before = screenshot(driver, shots, "studio-0-garment.png")

            # A planar image placed by one click on the front of the garment.
            driver.find_element("css selector", "button[data-add=planar]").click()
            hit = driver.execute_script(f"return window.studio.pick({cx}, {cy - 0.08 * rect['height']})")
            check(hit is not None, "the click point is on the garment")
            px, py = cx, cy - 0.08 * rect["height"]
            pointer_path(driver, [(px, py)])
            n = wait_preview(driver, first)
            placed = screenshot(driver, shots, "studio-1-planar.png")
            layer = driver.execute_script("return window.studio.design().layers.find(l => l.type === 'planar')")
            check(layer is not None and abs(layer["centre"][0] - hit["point"][0]) < 1 and abs(layer["centre"][1] - hit["point"][1]) < 1,
                  "the planar layer is centred on the clicked surface point")
            change_here = region_change(before, placed, int(px), int(py), 25)
            change_far = region_change(before, placed, int(rect["x"] + 15), int(rect["y"] + 15), 10)
            print(f"planar_change_at_click={change_here:.1f} planar_change_in_corner={change_far:.1f}")
            check(change_here > 8 and change_far < 1, "the preview changed at the click and not in the corner")

            # A stroke painted across the centre-front seam (front_l | front_r) below the motif.
            sy = cy + 0.14 * rect["height"]
            path = [(cx - 0.12 * rect["width"] + i * 0.24 * rect["width"] / 24, sy) for i in range(25)]
            ends = [driver.execute_script(f"return window.studio.pick({x}, {y})") for x, y in (path[0], path[-1])]
            check(all(ends) and ends[0]["piece"] != ends[1]["piece"],
                  f"the stroke's ends are on two pieces ({[e and e['piece'] for e in ends]})")
            driver.find_element("css selector", "button[data-add=stroke]").click()
            pointer_path(driver, path)
            n = wait_preview(driver, n)
            stroked = screenshot(driver, shots, "studio-2-stroke.png")
            # Just below the path: the path itself carries the selected stroke's guide line.
            red_before = sum(reddish(placed[2][int(y) + 5][int(x)]) for x, y in path)
            red_after = sum(reddish(stroked[2][int(y) + 5][int(x)]) for x, y in path)
            print(f"stroke_path_red_before={red_before} stroke_path_red_after={red_after} of {len(path)}")
            check(red_after >= 0.8 * len(path) and red_before < 0.2 * len(path), "the stroke shows red along its path")

            # Hidden, the stroke leaves the preview; shown again, it is back.
            driver.find_element("css selector", "#st-layers li[data-layer]:last-child button[aria-label^=Hide]").click()
            n = wait_preview(driver, n)
            hidden = screenshot(driver, shots, "studio-3-hidden.png")
            red_hidden = sum(reddish(hidden[2][int(y) + 5][int(x)]) for x, y in path)
            driver.find_element("css selector", "#st-layers li[data-layer]:last-child button[aria-label^=Show]").click()
            n = wait_preview(driver, n)
            print(f"stroke_path_red_hidden={red_hidden}")
            check(red_hidden < 0.2 * len(path), "a hidden stroke is not in the preview")

            # The planar image dragged to the wearer's right with the Place tool moves along the surface.
            driver.find_element("css selector", "#st-layers li[data-layer]:first-child .st-name").click()
            driver.find_element("css selector", "button[data-tool=place]").click()
            pointer_path(driver, [(px, py)] + [(px - 8 * i, py) for i in range(1, 6)])
            n = wait_preview(driver, n)
            moved = driver.execute_script("return window.studio.design().layers.find(l => l.type === 'planar').centre")
            print(f"planar_moved_from={[round(v) for v in hit['point']]} to={[round(v) for v in moved]}")
            check(moved[0] < hit["point"][0] - 10, "dragging moved the planar image across the garment")

            # Ten changes (the planar width), each timed by the page from the edit to the texture applied.
            driver.find_element("css selector", "#st-layers li[data-layer]:first-child .st-name").click()  # the planar layer
            driver.execute_script("window.studio.state.timings.length = 0")
            for i in range(10):
                driver.execute_script(f"""const el = document.querySelector('#st-form input[data-key=width]');
                    el.value = {160 + 10 * i}; el.dispatchEvent(new Event('input'));""")
                n = wait_preview(driver, n)
            timings = driver.execute_script("return window.studio.state.timings")
            ms = sorted(t["ms"] for t in timings)
            p95 = ms[min(len(ms) - 1, int(round(0.95 * (len(ms) - 1))))]
            daemon_ms = sorted(t["parse_ms"] + t["build_ms"] + t["render_ms"] + t["encode_ms"] for t in timings)
            daemon_p95 = daemon_ms[min(len(daemon_ms) - 1, int(round(0.95 * (len(daemon_ms) - 1))))]
            parts = {k: statistics.median(t[k] for t in timings) for k in ("parse_ms", "build_ms", "render_ms", "encode_ms")}
            print(f"change_to_preview_ms_median={statistics.median(ms):.0f} change_to_preview_ms_p95={p95:.0f} "
                  f"changes={len(ms)} daemon_ms_median={statistics.median(daemon_ms):.0f} daemon_ms_p95={daemon_p95:.0f} "
                  + " ".join(f"{k}_median={v:.0f}" for k, v in parts.items()))
            check(len(ms) == 10, "ten timed changes")

            # Save: the zip the page offers for download, checked by printctl and against the garment.
            driver.find_element("id", "st-dpi").send_keys("150")
            driver.find_element("id", "st-name").clear()
            driver.find_element("id", "st-name").send_keys("studio-test")
            driver.execute_script("document.getElementById('st-download').click = () => {}")  # no download dialog
            save_t0 = time.monotonic()
            driver.find_element("id", "st-save").click()
            wait(driver, "return !document.getElementById('st-download').hidden", 60, "the saved package")
            # The print garment was sewn in the background since the garment was chosen.
            print(f"save_s={time.monotonic() - save_t0:.1f}")
            data = driver.execute_async_script("""const done = arguments[arguments.length - 1];
                fetch(document.getElementById('st-download').href).then(r => r.arrayBuffer()).then(b => {
                  let s = ''; const u = new Uint8Array(b); for (let i = 0; i < u.length; ++i) s += String.fromCharCode(u[i]);
                  done(btoa(s)); });""")
            zip_path = os.path.join(root, "studio-test.zip")
            with open(zip_path, "wb") as f:
                f.write(base64.b64decode(data))
            v = subprocess.run([os.path.join(BIN, "printctl"), "validate", zip_path], capture_output=True, text=True)
            print(f"validate={v.stdout.strip() or v.stderr.strip()}")
            check(v.returncode == 0, "printctl validate accepts the saved job")
            job = json.loads(zipfile.ZipFile(zip_path).read("job.json"))
            strokes = [l for l in job["design"]["layers"] if l["type"] == "stroke"]
            check(len(strokes) == 1 and len(strokes[0]["points"]) >= 5, "the saved job holds the painted stroke")
            # As painted: the page's stroke lies on the studio's sewn (preview) garment.
            painted = driver.execute_script("return window.studio.design().layers.filter(l => l.type === 'stroke')")
            obj = urllib.request.urlopen(daemon.url.rstrip("/") + g["urls"]["mesh"]).read().decode()
            verts, tris = read_obj(obj)
            near = [nearest_on_surface(tuple(p), verts, tris) for p in painted[0]["points"]] if painted else []
            worst = max((d for d, _ in near), default=float("inf"))
            groups = sorted({grp for _, grp in near})
            print(f"stroke_points={len(near)} stroke_max_distance_mm={worst:.4f} stroke_pieces={','.join(groups)}")
            check(worst <= 1.0, "every painted stroke point lies on the studio's sewn garment within 1 mm")
            check(len(groups) >= 2, "the stroke reaches two pieces")
            check(len(strokes) == 1 and len(painted) == 1 and len(strokes[0]["points"]) == len(painted[0]["points"]),
                  "the saved stroke has the painted stroke's points")
            saved = job["garment"]
            print(f"saved_garment={json.dumps(saved, sort_keys=True)}")
            check("mesh_edge" not in saved and "drape" not in saved,
                  "the saved job prints with the product's garment settings, not the preview's 25 mm undraped mesh")

            # Print: the same package submitted from the page runs to done under printsim.
            driver.find_element("id", "st-print").click()
            jid = wait(driver, "const m = document.querySelector('.st-status').textContent.match(/job (\\d+)/); return m && m[1]",
                       60, "the submitted job")
            state = ""
            end = time.time() + 600
            while time.time() < end and state not in ("done", "failed", "cancelled"):
                state = json.load(urllib.request.urlopen(f"{daemon.url}api/v1/jobs/{jid}"))["job"]["state"]
                time.sleep(1)
            print(f"printed_job={jid} state={state} print_wait_s={time.time() - end + 600:.0f}")
            check(state == "done", "the printed job is done")
            # The garment the job printed (sewn at the product's mesh edge): the stroke lies on it too.
            printed = [os.path.join(d, "garment.obj") for d, _, files in os.walk(os.path.join(root, "d", "out"))
                       if "garment.obj" in files]
            if printed and strokes:
                pv, pt = read_obj(open(sorted(printed)[0]).read())
                on_print = [nearest_on_surface(tuple(p), pv, pt) for p in strokes[0]["points"]]
                far = max(d for d, _ in on_print)
                print_groups = sorted({grp for _, grp in on_print})
                print(f"printed_garment_vertices={len(pv)} stroke_max_distance_printed_mm={far:.4f} "
                      f"printed_stroke_pieces={','.join(print_groups)}")
                check(far <= 1.0, "every saved stroke point lies on the printed garment within 1 mm")
                check(len(print_groups) >= 2, "the saved stroke reaches two pieces of the printed garment")
            else:
                check(False, f"the printed job's garment.obj is in the outputs ({printed})")
            errors = [e["message"] for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
            for e in errors[:5]:
                print(f"console_error={e}")
            check(not errors, "no errors in the browser console")
        finally:
            if driver:
                driver.quit()
            daemon.stop()
    print(f"checks failed: {len(failures)}" if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
