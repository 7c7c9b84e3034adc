#!/usr/bin/env python3
# tests/scenarios/console/measure_console.py: figures of the console for docs/console.md: the bytes
# of the page's assets (with and without three.js, as the browser fetched them) and the first
# contentful paint with 100 jobs in the history (seeded into printd's job store), in headless
# Chromium with the Performance API. Prints key=value lines; exit 0 when the page shows the 100 jobs.
import os
import sqlite3
import statistics
import sys
import tempfile
import time

import console_harness as h

RUNS = 5
JOBS = 100


def seed(db_path, n):
    """n ended jobs (done, failed, cancelled), each with its eight stages, as printd records them."""
    db = sqlite3.connect(db_path, timeout=30)
    now = int(time.time() * 1000)
    stages = ["intake", "pattern", "mesh", "garment", "design", "marker", "print", "outputs"]
    for i in range(n):
        state = "failed" if i % 10 == 3 else "cancelled" if i % 17 == 5 else "done"
        error = "design: job.json /design/layers/0/image: no such file 'motif.png'" if state == "failed" else ""
        t0 = now - (n - i) * 60000
        cur = db.execute("INSERT INTO jobs (name, package, out_dir, origin, state, stage, error, submitted_ms, updated_ms) "
                         "VALUES (?, '', ?, 'http', ?, 'outputs', ?, ?, ?)",
                         (f"seeded-{i:03d}", f"/nonexistent/seeded-{i:03d}", state, error, t0, t0 + 42000))
        for s in stages:
            db.execute("INSERT INTO job_stages (job_id, stage, state, seconds) VALUES (?, ?, ?, ?)",
                       (cur.lastrowid, s, "done" if state == "done" else "fresh", 1.5))
    db.commit()
    db.close()


def main():
    h.need_browser()
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait

    root = tempfile.mkdtemp(prefix="tp-console-fig-")
    daemon = h.Daemon(root, printer="none")
    driver = None
    ok = True
    try:
        seed(os.path.join(daemon.state, "jobs.db"), JOBS)
        driver = h.chromium(1366, 768)
        fcp, listed = [], []
        for run in range(RUNS):
            # A fresh load each time without the cache, so every asset is fetched again.
            driver.execute_cdp_cmd("Network.setCacheDisabled", {"cacheDisabled": True})
            driver.get(daemon.url)
            WebDriverWait(driver, 30).until(
                lambda d: len(d.find_elements(By.CSS_SELECTOR, "#history tbody tr")) >= JOBS)
            t = driver.execute_script("""
              const p = performance.getEntriesByName("first-contentful-paint")[0];
              const m = performance.getEntriesByName("tp-jobs-rendered")[0];
              return [p ? p.startTime : null, m ? m.startTime : null];""")
            fcp.append(t[0])
            listed.append(t[1])
        rows = len(driver.find_elements(By.CSS_SELECTOR, "#history tbody tr"))
        print(f"history_rows={rows}")
        ok = rows >= JOBS and all(v is not None for v in fcp)
        print(f"first_contentful_paint_ms_median={statistics.median(fcp):.0f} min={min(fcp):.0f} max={max(fcp):.0f} runs={RUNS}")
        print(f"history_rendered_ms_median={statistics.median(listed):.0f} min={min(listed):.0f} max={max(listed):.0f}")
        # What the first load fetched from the console (not the API), then with the 3D viewer's three.js.
        page = driver.execute_script("""
          return performance.getEntriesByType("resource").concat(performance.getEntriesByType("navigation"))
            .filter((e) => !e.name.includes("/api/")).map((e) => [e.name, e.decodedBodySize]);""")
        page_bytes = sum(b for _, b in page)
        print(f"page_assets_files={len(page)} page_assets_bytes={page_bytes}")
        driver.execute_script("import('/js/ops/garment_view.js').then(() => { window.__three = 'ok'; },"
                              " (e) => { window.__three = String(e); });")
        WebDriverWait(driver, 60).until(lambda d: d.execute_script("return window.__three"))
        print(f"three_import={driver.execute_script('return window.__three')}")
        three = driver.execute_script("""
          return performance.getEntriesByType("resource").filter((e) => e.name.includes("/vendor/three/")
            || e.name.includes("garment_view")).map((e) => [e.name, e.decodedBodySize]);""")
        three_bytes = sum(b for _, b in three)
        print(f"three_files={len(three)} three_and_viewer_bytes={three_bytes}")
        print(f"total_assets_bytes={page_bytes + three_bytes}")
        src = os.path.join(h.SOURCE, "host/console")
        own = sum(os.path.getsize(os.path.join(r, f)) for r, _, fs in os.walk(src) if "/studio" not in r + "/"
                  for f in fs)
        print(f"console_source_bytes_without_studio={own}")
    finally:
        if driver:
            driver.quit()
        daemon.stop()
    h.cleanup(root)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
