#!/usr/bin/env python3
"""Writes shadelab's textured glTF test assets into one folder, each a single .gltf file with its
buffer and PNG images embedded as data: URIs. Every case the texture code handles has an asset:
    uv_checker.gltf           a quad, an sRGB colour checker (nearest, repeat, UVs over 0..2)
    wrap_modes.gltf           three quads, UVs over -1..2: repeat, mirrored repeat, clamp to edge (bilinear)
    normal_bump.gltf          a curved patch with a tangent-space normal map of domes, with TANGENT, scale 1.5
    normal_bump_no_tangents.gltf   the same without TANGENT (tangents are generated, MikkTSpace convention)
    texture_transform.gltf    a quad, the checker through KHR_texture_transform (offset, rotation, scale)
    alpha_mask.gltf           a quad cut out by its base colour's alpha (MASK, cutoff 0.5) over a backing quad
    alpha_blend.gltf          a half-transparent quad (BLEND, alpha 0.5 x texture) over a backing quad
    second_uv.gltf            a quad whose base colour reads TEXCOORD_1, and whose occlusion reads TEXCOORD_0
                              with a KHR_texture_transform texCoord override to 1
    metal_rough.gltf          a quad with metallic-roughness stripes (B metal, G rough) and occlusion (strength 0.8)
    emissive.gltf             a dark quad whose emissive texture (sRGB) times emissiveFactor glows in a ring
Deterministic: the same bytes on every run (tests/CMakeLists.txt's texture_assets_reproducible compares them
with assets/models/textures/). Regenerate with
    /usr/bin/python3 tools/make_texture_gltf.py --output assets/models/textures
"""
import argparse, base64, json, math, os, struct, zlib

import numpy as np


def png(rgba):
    """8-bit RGBA PNG bytes of an (h, w, 4) uint8 array: filter 0 rows, zlib level 9, no ancillary chunks."""
    h, w, _ = rgba.shape
    raw = b"".join(b"\x00" + rgba[y].tobytes() for y in range(h))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def to8(a):
    return np.clip(np.round(a * 255.0), 0, 255).astype(np.uint8)


# Images ------------------------------------------------------------------------------------------------
def checker(n=8, cells=4):
    """n x n texels, cells x cells squares: the squares' colours step in red with u and in blue with v, the
    dark ones grey, so orientation, order and wrap show."""
    img = np.zeros((n, n, 4))
    for y in range(n):
        for x in range(n):
            cx, cy = x * cells // n, y * cells // n
            if (cx + cy) % 2 == 0:
                img[y, x] = [0.25 + 0.75 * cx / (cells - 1), 0.8, 0.25 + 0.75 * cy / (cells - 1), 1.0]
            else:
                img[y, x] = [0.1, 0.1, 0.1, 1.0]
    return to8(img)


def domes(n=64):
    """A tangent-space normal map of four domes (height h = cos² bumps): n = normalize(-dh/dx, -dh/dy, 1) with
    x along +u and y the image's up (-v), stored as (n + 1)/2."""
    y, x = np.mgrid[0:n, 0:n]
    u, v = (x + 0.5) / n, (y + 0.5) / n
    h = np.zeros((n, n))
    dhdu = np.zeros((n, n))
    dhdv = np.zeros((n, n))
    for cu, cv in [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)]:
        du, dv = u - cu, v - cv
        r = np.sqrt(du * du + dv * dv)
        inside = r < 0.2
        k = math.pi / 0.4
        h += np.where(inside, np.cos(k * r) ** 2, 0.0) * 0.08
        g = np.where(inside & (r > 0), -2 * np.cos(k * r) * np.sin(k * r) * k * 0.08 / np.maximum(r, 1e-9), 0.0)
        dhdu += g * du
        dhdv += g * dv
    nx, ny, nz = -dhdu * 4.0, dhdv * 4.0, np.ones((n, n))  # dh/dy = -dh/dv
    ln = np.sqrt(nx * nx + ny * ny + nz * nz)
    img = np.stack([nx / ln * 0.5 + 0.5, ny / ln * 0.5 + 0.5, nz / ln * 0.5 + 0.5, np.ones((n, n))], axis=-1)
    return to8(img)


def cutout(n=32):
    """White with a red ring; alpha 1 inside a disc of radius 0.35 and a ramp to 0 outside it."""
    y, x = np.mgrid[0:n, 0:n]
    u, v = (x + 0.5) / n - 0.5, (y + 0.5) / n - 0.5
    r = np.sqrt(u * u + v * v)
    ring = (r > 0.2) & (r < 0.3)
    img = np.stack([np.ones((n, n)), np.where(ring, 0.2, 1.0), np.where(ring, 0.2, 1.0),
                    np.clip((0.45 - r) / 0.2, 0.0, 1.0)], axis=-1)
    return to8(img)


def gradient(n=16):
    """Red rising with u, green with v: which coordinate set a map reads shows in the colour."""
    y, x = np.mgrid[0:n, 0:n]
    img = np.stack([(x + 0.5) / n, (y + 0.5) / n, np.full((n, n), 0.3), np.ones((n, n))], axis=-1)
    return to8(img)


def stripes(n=32):
    """Metallic-roughness: blue (metal) in vertical bands 0, 1; green (rough) rising with v."""
    y, x = np.mgrid[0:n, 0:n]
    metal = np.where((x * 4 // n) % 2 == 0, 1.0, 0.0)
    rough = 0.15 + 0.8 * (y + 0.5) / n
    return to8(np.stack([np.zeros((n, n)), rough, metal, np.ones((n, n))], axis=-1))


def vignette(n=32):
    """Occlusion: red 1 in the middle falling to 0.2 at the corners."""
    y, x = np.mgrid[0:n, 0:n]
    u, v = (x + 0.5) / n - 0.5, (y + 0.5) / n - 0.5
    ao = np.clip(1.0 - 1.6 * (u * u + v * v) * 2, 0.2, 1.0)
    return to8(np.stack([ao, ao, ao, np.ones((n, n))], axis=-1))


# Geometry ----------------------------------------------------------------------------------------------
def quad(x0=-1.0, x1=1.0, y0=-1.0, y1=1.0, z=0.0, uv0=(0.0, 0.0), uv1=(1.0, 1.0)):
    """A +z facing quad; (u, v) = uv0 at the top left, uv1 at the bottom right (glTF's v grows downwards)."""
    pos = [(x0, y1, z), (x1, y1, z), (x1, y0, z), (x0, y0, z)]
    uv = [(uv0[0], uv0[1]), (uv1[0], uv0[1]), (uv1[0], uv1[1]), (uv0[0], uv1[1])]
    return {"POSITION": pos, "NORMAL": [(0.0, 0.0, 1.0)] * 4, "TEXCOORD_0": uv,
            "TANGENT": [(1.0, 0.0, 0.0, 1.0)] * 4}, [0, 3, 2, 0, 2, 1]


def patch(n=16, half=0.8):
    """A cylinder patch bent about y: x = sin θ, z = cos θ − 1, θ in [−half, half]; u along θ, v down y."""
    pos, nrm, uv, tan, idx = [], [], [], [], []
    for j in range(n + 1):
        yv = 1.0 - 2.0 * j / n
        for i in range(n + 1):
            t = -half + 2 * half * i / n
            pos.append((math.sin(t), yv, math.cos(t) - 1.0))
            nrm.append((math.sin(t), 0.0, math.cos(t)))
            uv.append((i / n, j / n))
            tan.append((math.cos(t), 0.0, -math.sin(t), 1.0))
    for j in range(n):
        for i in range(n):
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            idx += [a, d, c, a, c, b]
    return {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv, "TANGENT": tan}, idx


# Documents ---------------------------------------------------------------------------------------------
class Doc:
    def __init__(self, name):
        self.name = name
        self.blob = b""
        self.d = {"asset": {"version": "2.0", "generator": "shadelab tools/make_texture_gltf.py"}, "scene": 0,
                  "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [], "accessors": [],
                  "bufferViews": [], "buffers": []}

    def view(self, data, target=None):
        while len(self.blob) % 4:
            self.blob += b"\x00"
        v = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target:
            v["target"] = target
        self.blob += data
        self.d["bufferViews"].append(v)
        return len(self.d["bufferViews"]) - 1

    def accessor(self, values, kind):
        comps = {"VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        data = b"".join(struct.pack("<%df" % comps, *v) for v in values)
        a = {"bufferView": self.view(data, 34962), "componentType": 5126, "count": len(values), "type": kind}
        if kind == "VEC3":
            a["min"] = [min(v[k] for v in values) for k in range(3)]
            a["max"] = [max(v[k] for v in values) for k in range(3)]
        self.d["accessors"].append(a)
        return len(self.d["accessors"]) - 1

    def mesh(self, attrs, idx, material, name, drop=()):
        prim = {"attributes": {}, "material": material}
        kinds = {"POSITION": "VEC3", "NORMAL": "VEC3", "TEXCOORD_0": "VEC2", "TEXCOORD_1": "VEC2", "TANGENT": "VEC4"}
        for key in ["POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "TEXCOORD_1"]:
            if key in attrs and key not in drop:
                prim["attributes"][key] = self.accessor(attrs[key], kinds[key])
        data = b"".join(struct.pack("<H", k) for k in idx)
        self.d["accessors"].append({"bufferView": self.view(data, 34963), "componentType": 5123, "count": len(idx),
                                    "type": "SCALAR"})
        prim["indices"] = len(self.d["accessors"]) - 1
        self.d["meshes"].append({"name": name, "primitives": [prim]})
        self.d["nodes"].append({"mesh": len(self.d["meshes"]) - 1, "name": name})
        self.d["scenes"][0]["nodes"].append(len(self.d["nodes"]) - 1)

    def texture(self, rgba, name, sampler):
        self.d.setdefault("images", []).append(
            {"name": name, "uri": "data:image/png;base64," + base64.b64encode(png(rgba)).decode()})
        self.d.setdefault("samplers", []).append(sampler)
        self.d.setdefault("textures", []).append(
            {"source": len(self.d["images"]) - 1, "sampler": len(self.d["samplers"]) - 1})
        return len(self.d["textures"]) - 1

    def material(self, m):
        self.d["materials"].append(m)
        return len(self.d["materials"]) - 1

    def write(self, folder):
        self.d["buffers"] = [{"byteLength": len(self.blob),
                              "uri": "data:application/octet-stream;base64," + base64.b64encode(self.blob).decode()}]
        with open(os.path.join(folder, self.name), "w") as f:
            json.dump(self.d, f, indent=1, sort_keys=True)
            f.write("\n")


NEAREST = {"magFilter": 9728, "minFilter": 9728, "wrapS": 10497, "wrapT": 10497}
LINEAR = {"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}
CLAMP = {"magFilter": 9729, "minFilter": 9987, "wrapS": 33071, "wrapT": 33071}


def grey(extra=None):
    m = {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0,
                                  "roughnessFactor": 0.5}}
    m.update(extra or {})
    return m


def uv_checker():
    d = Doc("uv_checker.gltf")
    t = d.texture(checker(), "checker", NEAREST)
    m = d.material({"name": "checker", "pbrMetallicRoughness": {"baseColorTexture": {"index": t},
                                                                "metallicFactor": 0.0, "roughnessFactor": 0.5}})
    d.mesh(*quad(uv1=(2.0, 2.0)), m, "quad")
    return d


def wrap_modes():
    d = Doc("wrap_modes.gltf")
    for k, (name, mode) in enumerate([("repeat", 10497), ("mirrored", 33648), ("clamp", 33071)]):
        t = d.texture(checker(), "checker_" + name, {"magFilter": 9729, "minFilter": 9729, "wrapS": mode, "wrapT": mode})
        m = d.material({"name": name, "pbrMetallicRoughness": {"baseColorTexture": {"index": t},
                                                               "metallicFactor": 0.0, "roughnessFactor": 0.6}})
        x0 = -1.6 + 1.1 * k
        d.mesh(*quad(x0, x0 + 1.0, -0.5, 0.5, uv0=(-1.0, -1.0), uv1=(2.0, 2.0)), m, name)
    return d


def normal_bump(tangents):
    d = Doc("normal_bump.gltf" if tangents else "normal_bump_no_tangents.gltf")
    t = d.texture(domes(), "domes", LINEAR)
    m = d.material(grey({"name": "bumps", "normalTexture": {"index": t, "scale": 1.5}}))
    d.mesh(*patch(), m, "patch", drop=() if tangents else ("TANGENT",))
    return d


def texture_transform():
    d = Doc("texture_transform.gltf")
    t = d.texture(checker(), "checker", NEAREST)
    xf = {"KHR_texture_transform": {"offset": [0.3, -0.2], "rotation": 0.4, "scale": [1.6, 1.4]}}
    m = d.material({"name": "transformed", "pbrMetallicRoughness": {
        "baseColorTexture": {"index": t, "extensions": xf}, "metallicFactor": 0.0, "roughnessFactor": 0.5}})
    d.d["extensionsUsed"] = ["KHR_texture_transform"]
    d.mesh(*quad(), m, "quad")
    return d


def alpha(mode):
    d = Doc("alpha_mask.gltf" if mode == "MASK" else "alpha_blend.gltf")
    t = d.texture(cutout(), "cutout", LINEAR)
    front = {"name": "cutout", "alphaMode": mode, "doubleSided": True, "pbrMetallicRoughness": {
        "baseColorTexture": {"index": t}, "baseColorFactor": [1.0, 1.0, 1.0, 1.0 if mode == "MASK" else 0.5],
        "metallicFactor": 0.0, "roughnessFactor": 0.5}}
    if mode == "MASK":
        front["alphaCutoff"] = 0.5
    m = d.material(front)
    back = d.material(grey({"name": "backing", "pbrMetallicRoughness": {
        "baseColorFactor": [0.2, 0.35, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.5}}))
    d.mesh(*quad(-1.4, 1.4, -1.4, 1.4, z=-0.6), back, "backing")
    d.mesh(*quad(), m, "cutout")
    return d


def second_uv():
    d = Doc("second_uv.gltf")
    base = d.texture(gradient(), "gradient", CLAMP)
    ao = d.texture(vignette(), "vignette", CLAMP)
    attrs, idx = quad()
    attrs["TEXCOORD_1"] = [(0.0, 1.0), (0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]  # TEXCOORD_0 turned a quarter
    xf = {"KHR_texture_transform": {"texCoord": 1}}
    m = d.material({"name": "second set", "occlusionTexture": {"index": ao, "texCoord": 0, "strength": 1.0,
                                                                "extensions": xf},
                    "pbrMetallicRoughness": {"baseColorTexture": {"index": base, "texCoord": 1},
                                             "metallicFactor": 0.0, "roughnessFactor": 0.5}})
    d.d["extensionsUsed"] = ["KHR_texture_transform"]
    d.mesh(attrs, idx, m, "quad")
    return d


def metal_rough():
    d = Doc("metal_rough.gltf")
    mr = d.texture(stripes(), "metal_rough", CLAMP)
    ao = d.texture(vignette(), "occlusion", CLAMP)
    m = d.material({"name": "striped", "occlusionTexture": {"index": ao, "strength": 0.8},
                    "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.6, 0.3, 1.0], "metallicFactor": 1.0,
                                             "roughnessFactor": 1.0, "metallicRoughnessTexture": {"index": mr}}})
    d.mesh(*quad(), m, "quad")
    return d


def emissive():
    d = Doc("emissive.gltf")
    t = d.texture(cutout(), "glow", LINEAR)
    m = d.material({"name": "glowing", "emissiveTexture": {"index": t}, "emissiveFactor": [1.0, 0.8, 0.5],
                    "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.1, 0.1, 1.0], "metallicFactor": 0.0,
                                             "roughnessFactor": 0.5}})
    d.mesh(*quad(), m, "quad")
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--output", required=True, help="folder to write the .gltf files into (created)")
    args = ap.parse_args()
    os.makedirs(args.output, exist_ok=True)
    for doc in [uv_checker(), wrap_modes(), normal_bump(True), normal_bump(False), texture_transform(),
                alpha("MASK"), alpha("BLEND"), second_uv(), metal_rough(), emissive()]:
        doc.write(args.output)


if __name__ == "__main__":
    main()
