#!/usr/bin/env python3
# tests/scenarios/console/check_console_firefox.py: the operator console in headless Firefox ESR
# (driven over Marionette) against printd --printer none: the page loads its modules and goes live,
# examples/top-strokes dropped as a zip reaches done, its detail shows the 3D garment (canvas pixels
# beyond background) and the figures, and the tabs switch. Exit 0 when all hold, 77 without Firefox.
import base64
import os
import sys
import tempfile
import time

import console_harness as h
import marionette


def main():
    if not os.path.exists(marionette.FIREFOX):
        print(f"SKIP: {marionette.FIREFOX} is missing (apt-get install firefox-esr)")
        return h.SKIP
    root = tempfile.mkdtemp(prefix="tp-console-ff-")
    check = h.Checks()

    daemon = h.Daemon(root, printer="none")
    ff = None
    try:
        ff = marionette.Firefox(1366, 768)
        print(f"browser={ff.capabilities.get('browserName')} {ff.capabilities.get('browserVersion')}")
        ff.get(daemon.url)
        ff.wait("return document.getElementById('link-state').dataset.state === 'live'", 30)
        check(ff.script("return document.title") == "printd console", "the console loads and its event stream is live")
        overflow = ff.script("return document.documentElement.scrollWidth - window.innerWidth")
        print(f"horizontal_overflow_px={overflow}")
        check(overflow <= 0, "no horizontal scrolling at 1366x768")

        zip_path = h.zip_job(os.path.join(h.SOURCE, "examples/top-strokes"), os.path.join(root, "top-strokes.zip"))
        ff.script("""
          const bytes = Uint8Array.from(atob(arguments[0]), (c) => c.charCodeAt(0));
          const dt = new DataTransfer();
          dt.items.add(new File([bytes], "top-strokes.zip", { type: "application/zip" }));
          for (const type of ["dragenter", "dragover", "drop"])
            document.body.dispatchEvent(new DragEvent(type, { dataTransfer: dt, bubbles: true, cancelable: true }));
        """, base64.b64encode(open(zip_path, "rb").read()).decode())
        job_id = ff.wait("const e = document.querySelector('#submit-log li.ok'); return e && e.dataset.jobId", 60)
        print(f"job_id={job_id}")
        start, values, final = time.time(), set(), None
        while time.time() - start < 400:
            row = ff.script("""const r = document.querySelector(`tr[data-job-id="${arguments[0]}"]`);
              if (!r) return null; const b = r.querySelector(".bar.overall");
              return [r.dataset.state, b ? Number(b.getAttribute("aria-valuenow")) : null];""", job_id)
            if row:
                if row[1] is not None:
                    values.add(row[1])
                if row[0] in ("done", "failed", "cancelled"):
                    final = row[0]
                    break
            time.sleep(0.3)
        print(f"final_state={final} seconds={time.time() - start:.1f} progress_values_seen={len(values)}")
        check(final == "done", "the dropped job reached done in the page")
        check(len([v for v in values if 0 < v < 100]) >= 2, "the overall progress moved while it ran")

        ff.script("document.querySelector(`#history tr[data-job-id=\"${arguments[0]}\"] button[data-open]`).click()", job_id)
        try:
            ready = ff.wait("const v = document.getElementById('detail-garment'); return v && v.dataset.ready !== '0' && v.dataset.ready", 120)
        except TimeoutError:
            ready = "timeout"
            print("detail=" + repr(ff.script("return document.getElementById('detail').innerText.slice(0, 600)")))
        shown = ff.script("return document.getElementById('detail-garment').textContent") or "rendered"
        check(ready == "1", f"the 3D garment loaded in Firefox ({shown})")
        if ready == "1":
            ff.script("document.querySelector('#detail-garment canvas').scrollIntoView({block: 'center'})")
            time.sleep(0.5)
            png = ff.element_png("#detail-garment canvas")
            w, hgt, rows = h.read_png(png)
            bg = (0x1F, 0x25, 0x2C)
            garment = [p[:3] for row in rows for p in row if max(abs(p[i] - bg[i]) for i in range(3)) > 12]
            share = len(garment) / float(w * hgt)
            distinct = len({(r // 16, g // 16, b // 16) for r, g, b in garment})
            print(f"canvas_px={w}x{hgt} garment_share={share:.3f} distinct_colours={distinct}")
            check(share > 0.05 and distinct > 20, "the garment canvas shows the printed garment in Firefox")
        strain = ff.script("const c = document.querySelector('#detail tr[data-figure=\"strain\"] td'); return c && c.textContent")
        print(f"strain_figure={strain}")
        check(bool(strain) and not strain.startswith("–"), "the detail shows the strain figures")
        ff.script("document.getElementById('tab-studio').click()")
        check(ff.wait("return !document.getElementById('view-studio').hidden && document.getElementById('view-ops').hidden", 10),
              "the Studio tab shows its view")
    finally:
        if ff:
            ff.quit()
        daemon.stop()
    return h.finish(check, root, daemon)


if __name__ == "__main__":
    sys.exit(main())
