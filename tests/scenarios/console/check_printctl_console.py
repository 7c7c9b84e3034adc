#!/usr/bin/env python3
# tests/scenarios/console/check_printctl_console.py: `printctl console` starts printsim with printd
# inside it on a free loopback port, prints the console's URL, serves the console page, the studio and
# the API with printsim's printer, and stops both on SIGINT with exit 0. Exit 0 when all hold.
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import urllib.request

import console_harness as h


def main():
    root = tempfile.mkdtemp(prefix="tp-printctl-console-")
    check = h.Checks()

    out = os.path.join(root, "out")
    cmd = [os.path.join(h.BIN, "printctl"), "console", "--out", out, "--port", "0", "--example",
           os.path.join(h.SOURCE, "examples/top-strokes"), "--console-dir", os.path.join(h.SOURCE, "host/console")]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    url, lines = None, []
    try:
        deadline = time.time() + 60
        while time.time() < deadline and url is None:
            line = proc.stdout.readline()
            if not line:
                break
            lines.append(line)
            m = re.search(r"console is running:\s+(http://127\.0\.0\.1:\d+/)", line)
            if m:
                url = m.group(1)
        print(f"url={url}")
        check(url is not None, "printctl console prints the console's URL")
        if url:
            page = urllib.request.urlopen(url).read().decode()
            check("<title>printd console</title>" in page, "the URL serves the console page")
            studio = urllib.request.urlopen(url + "studio/").read().decode()
            check("studio" in studio.lower(), "the studio page is served")
            printer = json.load(urllib.request.urlopen(url + "api/v1/printer"))
            print(f"printer={json.dumps(printer)[:200]}")
            check(isinstance(printer, dict) and printer != {}, "printd reports printsim's printer")
            check(os.path.isfile(os.path.join(out, "printer-model.txt")), "the example's printer model is written")
        os.killpg(proc.pid, signal.SIGINT)
        try:
            code = proc.wait(timeout=40)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            code = proc.wait()
        print(f"exit_code={code}")
        check(code == 0, "Ctrl-C stops printsim and printd and printctl exits 0")
        left = subprocess.run(["pgrep", "-f", out], capture_output=True, text=True).stdout.split()
        check(not left, "no printd or printsim is left running")
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    return h.finish(check, root, log_text="".join(lines[-20:]))


if __name__ == "__main__":
    sys.exit(main())
