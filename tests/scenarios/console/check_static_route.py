#!/usr/bin/env python3
# tests/scenarios/console/check_static_route.py: printd's static route over plain HTTP (no browser):
# MIME types, cache headers and 304 revalidation, three.js through Debian's inner links, 404s, and
# refusals of every way out of the asset folders (.., encoded .., absolute, symlinks), token mode.
import http.client
import os
import shutil
import sys
import tempfile

import console_harness as h


def get(port, path, headers=None):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    c.request("GET", path, headers=headers or {})
    r = c.getresponse()
    body = r.read()
    c.close()
    return r.status, {k.lower(): v for k, v in r.getheaders()}, body


def main():
    root = tempfile.mkdtemp(prefix="tp-console-static-")
    failures = []

    def check(ok, what):
        print(f"{'ok' if ok else 'FAIL'}: {what}")
        if not ok:
            failures.append(what)

    # A console folder of our own with a symlink in it, and a vendor folder whose link leads out.
    console = os.path.join(root, "console")
    shutil.copytree(os.path.join(h.SOURCE, "host/console"), console, ignore=shutil.ignore_patterns("studio"))
    secret = os.path.join(root, "secret.txt")
    open(secret, "w").write("not for the web\n")
    os.symlink(secret, os.path.join(console, "link.txt"))
    vendor = os.path.join(root, "three")
    os.makedirs(os.path.join(vendor, "build"))
    open(os.path.join(vendor, "three.module.js"), "w").write("export const REVISION = 'test';\n")
    os.symlink("../three.module.js", os.path.join(vendor, "build/three.module.js"))
    os.symlink(secret, os.path.join(vendor, "build/out.js"))
    daemon = h.Daemon(os.path.join(root, "d1"), printer="none", extra=["--console-dir", console, "--three-dir", vendor])
    try:
        p = daemon.port
        st, hd, body = get(p, "/")
        check(st == 200 and hd.get("content-type") == "text/html; charset=utf-8" and b"<title>printd console" in body,
              f"/ is the console page as text/html ({st} {hd.get('content-type')})")
        check(hd.get("cache-control") == "no-cache" and hd.get("etag", "").startswith('W/"'),
              f"the page is revalidated: Cache-Control {hd.get('cache-control')}, ETag {hd.get('etag')}")
        st304, _, body304 = get(p, "/", {"If-None-Match": hd.get("etag", "")})
        check(st304 == 304 and not body304, f"If-None-Match with its ETag answers 304 ({st304})")
        for path, mime in (("/console.css", "text/css; charset=utf-8"), ("/js/app.js", "text/javascript; charset=utf-8"),
                           ("/js/ops/queue.js", "text/javascript; charset=utf-8")):
            st, hd, _ = get(p, path)
            check(st == 200 and hd.get("content-type") == mime and hd.get("x-content-type-options") == "nosniff",
                  f"{path}: {st} {hd.get('content-type')}")
        st, hd, body = get(p, "/vendor/three/build/three.module.js")
        check(st == 200 and b"REVISION" in body and hd.get("content-type", "").startswith("text/javascript") and
              "max-age" in hd.get("cache-control", ""), f"three.js through build/'s link inside the folder ({st}, {hd.get('cache-control')})")
        for path in ("/vendor/three/build/out.js", "/link.txt", "/js/../../secret.txt", "/js/%2e%2e/%2e%2e/secret.txt",
                     "/vendor/three/..%2f..%2fsecret.txt", "/vendor/three//etc/passwd", "/js/a%5cb.js", "/vendor/three/%2e%2e/x"):
            st, _, body = get(p, path)
            check(st in (400, 404) and b"not for the web" not in body and b"root:" not in body,
                  f"{path} refused ({st}: {body.decode(errors='replace')[:90]})")
        st, _, body = get(p, "/link.txt")
        check(st == 400 and b"symlink" in body, "a symlink among the console's assets is named as such")
        st, hd, body = get(p, "/nothing-here.js")
        check(st == 404 and hd.get("content-type") == "application/json", f"a missing asset is a JSON 404 ({st})")
        st, _, body = get(p, "/api/v1/nothing")
        check(st == 404 and b"no route" in body, "an unknown /api/ path is still the API's 404, not an asset")
        st, _, _ = get(p, "/api/v1/jobs")
        check(st == 200, "the API answers beside the console")
    finally:
        daemon.stop()

    # Without assets: a clear 404 naming the option; with tokens: the page is public, the API is not.
    d2 = h.Daemon(os.path.join(root, "d2"), printer="none",
                  extra=["--console-dir", os.path.join(root, "missing"), "--require-token"])
    try:
        st, _, body = get(d2.port, "/")
        check(st == 404 and b"--console-dir" in body, f"no console installed: 404 naming --console-dir ({body[:80]!r})")
        st, _, _ = get(d2.port, "/vendor/three/build/three.module.js")
        check(st == 200, "three.js is public with --require-token")
        st, _, _ = get(d2.port, "/api/v1/jobs")
        check(st == 401, f"the API still needs the token ({st})")
    finally:
        d2.stop()
    if not failures:
        h.cleanup(root)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
