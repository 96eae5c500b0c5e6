#!/usr/bin/env python3
"""Writes assets/models/torus.gltf: a smooth torus (indexed, with normals, one metallic-roughness material),
buffer embedded as a data: URI. shadelab's own test and demo model; regenerate with
    python3 tools/make_torus_gltf.py assets/models/torus.gltf
"""
import base64, json, math, struct, sys

R, r, U, V = 1.0, 0.38, 96, 48   # ring radius, tube radius, segments around the ring and the tube
pos, nrm, idx = [], [], []
for i in range(U):
    u = 2 * math.pi * i / U
    cu, su = math.cos(u), math.sin(u)
    for j in range(V):
        v = 2 * math.pi * j / V
        cv, sv = math.cos(v), math.sin(v)
        pos.append(((R + r * cv) * cu, r * sv, (R + r * cv) * su))
        nrm.append((cv * cu, sv, cv * su))
for i in range(U):
    for j in range(V):
        a, b = i * V + j, ((i + 1) % U) * V + j
        c, d = ((i + 1) % U) * V + (j + 1) % V, i * V + (j + 1) % V
        idx += [a, d, b, b, d, c]   # counter-clockwise seen from outside

pb = b"".join(struct.pack("<3f", *p) for p in pos)
nb = b"".join(struct.pack("<3f", *n) for n in nrm)
ib = b"".join(struct.pack("<H", k) for k in idx)
blob = pb + nb + ib
lo = [min(p[k] for p in pos) for k in range(3)]
hi = [max(p[k] for p in pos) for k in range(3)]
doc = {
    "asset": {"version": "2.0", "generator": "shadelab tools/make_torus_gltf.py"},
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "torus", "rotation": [0.2588190, 0.0, 0.0, 0.9659258]}],
    "meshes": [{"name": "torus", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
    "materials": [{"name": "copper", "pbrMetallicRoughness": {
        "baseColorFactor": [0.95, 0.64, 0.54, 1.0], "metallicFactor": 0.6, "roughnessFactor": 0.35}}],
    "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(pb), "target": 34962},
        {"buffer": 0, "byteOffset": len(pb), "byteLength": len(nb), "target": 34962},
        {"buffer": 0, "byteOffset": len(pb) + len(nb), "byteLength": len(ib), "target": 34963}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3", "min": lo, "max": hi},
        {"bufferView": 1, "componentType": 5126, "count": len(nrm), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5123, "count": len(idx), "type": "SCALAR"}],
}
with open(sys.argv[1] if len(sys.argv) > 1 else "assets/models/torus.gltf", "w") as f:
    json.dump(doc, f, separators=(",", ":"))
print(f"{len(idx) // 3} triangles, {len(pos)} vertices")
