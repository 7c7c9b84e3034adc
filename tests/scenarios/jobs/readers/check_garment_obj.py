#!/usr/bin/env python3
# tests/scenarios/jobs/readers/check_garment_obj.py: opens garment.obj with assimp (assimp-utils) and
# prints key=value facts: meshes, materials, the diffuse texture each mesh uses, UV range, units comment.
import json
import os
import subprocess
import sys
import tempfile

obj = sys.argv[1]
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "garment.json")
    r = subprocess.run(["assimp", "export", obj, out, "-fjson"], capture_output=True, text=True)
    print(f"assimp_exit={r.returncode}")
    if r.returncode != 0:
        print(r.stdout + r.stderr, file=sys.stderr)
        sys.exit(1)
    scene = json.load(open(out))

textures = []
for m in scene.get("materials", []):
    props = {p["key"]: p["value"] for p in m["properties"]}
    textures.append(props.get("$tex.file", ""))
meshes = scene.get("meshes", [])
uv_min, uv_max, uv_count, textured, faces = 1e9, -1e9, 0, 0, 0
for mesh in meshes:
    faces += len(mesh.get("faces", []))
    if textures[mesh["materialindex"]]:
        textured += 1
    for channel in mesh.get("texturecoords", []):
        # Two or three components per vertex: assimp writes uv (and w) flat.
        n = mesh.get("numuvcomponents", [2])[0]
        for i in range(0, len(channel), n):
            for c in channel[i:i + 2]:
                uv_min, uv_max = min(uv_min, c), max(uv_max, c)
            uv_count += 1
units = any("units: mm" in line for line in open(obj))
print(f"meshes={len(meshes)}")
print(f"faces={faces}")
print(f"textured_meshes={textured}")
print(f"textures={','.join(sorted(set(t for t in textures if t)))}")
print(f"uv_count={uv_count}")
print(f"uv_min={uv_min:.6f}")
print(f"uv_max={uv_max:.6f}")
print(f"units_comment={'yes' if units else 'no'}")
