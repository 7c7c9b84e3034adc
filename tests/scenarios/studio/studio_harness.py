# tests/scenarios/studio/studio_harness.py: shared by the studio's checks: the console harness's
# printd launcher and browsers (one launcher for both pages), the garment OBJ as triangles per
# piece and point-to-surface distances.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../console"))
from console_harness import BIN, SKIP, SOURCE, Daemon, chromium, need_browser, read_png, severe_logs  # noqa: E402,F401


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
