#!/usr/bin/env python3
"""Writes a .glb of N x N UV spheres of 4,096 triangles each (64 slices, 33 stacks; trace_bench's scale model:
N = 32 gives 4,194,304 triangles), one sphere mesh instanced by N x N translated nodes on a unit grid in the
z = 0 plane, and a camera that frames the grid. The importer flattens the instances into world space, so the
tracer sees every triangle. Usage:
    /usr/bin/python3 tools/make_sphere_grid_glb.py OUT.glb [N]
"""
import json, math, struct, sys

import numpy as np

SLICES, STACKS, RADIUS = 64, 33, 0.45


def sphere(slices=SLICES, stacks=STACKS, radius=RADIUS, uvs=False):
    """A UV sphere about the origin (tools/make_layer_gltf.py uses it too): positions, unit normals and triangle
    indices, counter-clockwise seen from outside; with `uvs`, texture coordinates too (u = φ/2π around, v = θ/π from
    the north pole), each ring then closed by a seam vertex of its own at u = 1, so that tangents made from them
    run along the parallels everywhere."""
    ring_size = slices + 1 if uvs else slices
    pos, nrm, uv = [(0.0, radius, 0.0)], [(0.0, 1.0, 0.0)], [(0.5, 0.0)]
    for i in range(1, stacks):
        th = math.pi * i / stacks
        for j in range(ring_size):
            ph = 2 * math.pi * j / slices
            n = (math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph))
            pos.append(tuple(radius * c for c in n))
            nrm.append(n)
            uv.append((j / slices, i / stacks))
    pos.append((0.0, -radius, 0.0))
    nrm.append((0.0, -1.0, 0.0))
    uv.append((0.5, 1.0))
    south = len(pos) - 1
    ring = (lambda i, j: 1 + (i - 1) * ring_size + j) if uvs else (lambda i, j: 1 + (i - 1) * slices + (j % slices))
    idx = []
    for j in range(slices):
        idx += [0, ring(1, j + 1), ring(1, j)]
    for i in range(1, stacks - 1):
        for j in range(slices):
            a, b, c, d = ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1)
            idx += [a, b, d, a, d, c]
    for j in range(slices):
        idx += [south, ring(stacks - 1, j), ring(stacks - 1, j + 1)]
    out = (np.array(pos, "<f4"), np.array(nrm, "<f4"), np.array(idx, "<u4"))
    return out + (np.array(uv, "<f4"),) if uvs else out


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    out, n = sys.argv[1], int(sys.argv[2]) if len(sys.argv) == 3 else 32
    pos, nrm, idx = sphere()
    assert len(idx) == 3 * 4096
    pb, nb, ib = pos.tobytes(), nrm.tobytes(), idx.tobytes()
    blob = pb + nb + ib
    mid = 0.5 * (n - 1)
    nodes = [{"mesh": 0, "translation": [float(j), float(i), 0.0]} for i in range(n) for j in range(n)]
    nodes.append({"camera": 0, "translation": [mid, mid, 1.3 * n]})
    doc = {
        "asset": {"version": "2.0", "generator": "shadelab tools/make_sphere_grid_glb.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(45.0), "znear": 0.1}}],
        "meshes": [{"name": "sphere", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
        "buffers": [{"byteLength": len(blob)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(pb), "target": 34962},
            {"buffer": 0, "byteOffset": len(pb), "byteLength": len(nb), "target": 34962},
            {"buffer": 0, "byteOffset": len(pb) + len(nb), "byteLength": len(ib), "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3",
             "min": pos.min(axis=0).tolist(), "max": pos.max(axis=0).tolist()},
            {"bufferView": 1, "componentType": 5126, "count": len(nrm), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125, "count": len(idx), "type": "SCALAR"},
        ],
    }
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    blob += b"\0" * (-len(blob) % 4)
    glb = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(blob))
    glb += struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(blob), 0x004E4942) + blob
    with open(out, "wb") as f:
        f.write(glb)
    print(f"{out}: {n * n} spheres, {n * n * 4096} triangles")


if __name__ == "__main__":
    main()
