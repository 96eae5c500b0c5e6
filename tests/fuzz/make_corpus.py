#!/usr/bin/env python3
"""Writes the hand-made seed corpora of the fuzz targets that read new surfaces, one folder per target:
    hdr_fuzz/           Radiance .hdr: flat and run-length scanlines, tiny sizes, the largest texel (RGBE
                        255,255,255,255), black texels, the #?RGBE magic and header lines the parser skips
    gltf_texture_fuzz/  single-file glTF (buffer and PNG as data: URIs) and one GLB (the PNG in a bufferView),
                        each with KHR_texture_transform: offset, rotation, scale, texCoord, and extremes (1e38,
                        3e38, 1e-45, -0) on the transform and on the texture coordinates
    script_fuzz/        viewer scripts: every action docs/viewer.md lists, in both file forms
The seeds are small (a few KB) and valid, so that mutations start deep in each reader. Deterministic: the same
bytes on every run (ctest's fuzz_corpus_reproducible compares them with tests/fuzz/corpus/). Regenerate with
    /usr/bin/python3 tests/fuzz/make_corpus.py --output tests/fuzz/corpus
"""
import argparse, importlib.util, json, os, struct

HERE = os.path.dirname(os.path.abspath(__file__))


def _tool(name):
    """One of tools/'s generators, as a module (they run as scripts; main() runs only from the command line)."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(HERE, "..", "..", "tools", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# The textured-asset generator's PNG writer, checker image, quad and glTF document builder; the sky generator's
# RGBE packing and run-length encoding.
tex = _tool("make_texture_gltf")
sky = _tool("make_sky_hdr")


def write(folder, name, data):
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


# .hdr ---------------------------------------------------------------------------------------------------
rgbe = sky.rgbe


def hdr_header(w, h, magic=b"#?RADIANCE", extra=b""):
    return magic + b"\n" + extra + b"FORMAT=32-bit_rle_rgbe\n\n" + b"-Y %d +X %d\n" % (h, w)


def flat(pixels):
    return b"".join(bytes(p) for p in pixels)


def rle_scanline(pixels):
    """A new-style run-length scanline: 2, 2, width, then the R, G, B and E planes, each as runs (count > 128)
    of four or more equal bytes and literals (count <= 128) between them."""
    w = len(pixels)
    return bytes((2, 2, w >> 8, w & 0xFF)) + b"".join(sky.rle_plane([p[c] for p in pixels]) for c in range(4))


def hdr_seeds(folder):
    write(folder, "flat_1x1.hdr", hdr_header(1, 1) + flat([rgbe(0.5, 0.25, 0.125)]))
    write(folder, "flat_3x2.hdr", hdr_header(3, 2) + flat(
        [rgbe(1, 0, 0), rgbe(0, 1, 0), rgbe(0, 0, 1), rgbe(4, 4, 4), rgbe(0, 0, 0), rgbe(1e-20, 1e-20, 1e-20)]))
    # Eight wide and more may be run-length encoded; a scanline that does not start 2, 2 is flat.
    write(folder, "flat_wide_9x1.hdr", hdr_header(9, 1) + flat([rgbe(0.1 * k, 0.2, 0.3) for k in range(9)]))
    sky = [[rgbe(0.2 + 0.1 * y, 0.4, 0.9 - 0.05 * x) for x in range(8)] for y in range(2)]
    write(folder, "rle_8x2.hdr", hdr_header(8, 2) + b"".join(rle_scanline(row) for row in sky))
    mixed = [[rgbe(1.0, 1.0, 1.0)] * 6 + [rgbe(0.1 * x, 0.5, 2.0 * y) for x in range(10)] for y in range(4)]
    write(folder, "rle_16x4.hdr", hdr_header(16, 4, extra=b"# made by tests/fuzz/make_corpus.py\nEXPOSURE=1.0\n") +
          b"".join(rle_scanline(row) for row in mixed))
    # The largest texel RGBE holds, 255/256 * 2^127 (1.7e38): held at kMaxRadiance before the prefilter.
    write(folder, "max_texel_2x2.hdr", hdr_header(2, 2) + flat([(255, 255, 255, 255)] * 4))
    write(folder, "rle_max_texel_8x1.hdr", hdr_header(8, 1) + rle_scanline([(255, 255, 255, 255)] * 8))
    write(folder, "rgbe_magic_2x1.hdr", b"#?RGBE\nGAMMA=1\n\n-Y 1 +X 2\n" + flat([(128, 0, 64, 130), (0, 0, 0, 0)]))


# glTF ---------------------------------------------------------------------------------------------------
def compact(d):
    return (json.dumps(d, sort_keys=True, separators=(",", ":")) + "\n").encode()


def gltf_bytes(doc):
    doc.d["buffers"] = [{"byteLength": len(doc.blob),
                         "uri": "data:application/octet-stream;base64," +
                                tex.base64.b64encode(doc.blob).decode()}]
    return compact(doc.d)


def glb_bytes(doc):
    """GLB 2.0: the JSON chunk (padded with spaces) and the BIN chunk (padded with zeros) holding the buffer."""
    blob = doc.blob + b"\x00" * (-len(doc.blob) % 4)
    doc.d["buffers"] = [{"byteLength": len(doc.blob)}]
    text = json.dumps(doc.d, sort_keys=True, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(blob), b"BIN\x00") + blob
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


def transformed(index, xf, tex_coord=None, extra=None):
    info = {"index": index, "extensions": {"KHR_texture_transform": xf}}
    if tex_coord is not None:
        info["texCoord"] = tex_coord
    info.update(extra or {})
    return info


def textured_quad(name, xf, uv0=(0.0, 0.0), uv1=(1.0, 1.0), sampler=None, second_uv=False, tex_coord=None):
    d = tex.Doc(name)
    d.d["asset"]["generator"] = "shadelab tests/fuzz/make_corpus.py"
    d.d["extensionsUsed"] = ["KHR_texture_transform"]
    t = d.texture(tex.checker(), "checker", sampler or tex.NEAREST)
    m = d.material({"name": "transformed", "pbrMetallicRoughness": {
        "baseColorTexture": transformed(t, xf, tex_coord), "metallicFactor": 0.0, "roughnessFactor": 0.5}})
    attrs, idx = tex.quad(uv0=uv0, uv1=uv1)
    if second_uv:
        attrs["TEXCOORD_1"] = [(0.0, 1.0), (0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]
    d.mesh(attrs, idx, m, "quad")
    return d


def all_maps():
    """Every map a material reads, each through its own transform and sampler."""
    d = tex.Doc("all_maps_transform.gltf")
    d.d["asset"]["generator"] = "shadelab tests/fuzz/make_corpus.py"
    d.d["extensionsUsed"] = ["KHR_texture_transform"]
    mirrored = {"magFilter": 9729, "minFilter": 9729, "wrapS": 33648, "wrapT": 33648}
    base = d.texture(tex.checker(), "base", mirrored)
    mr = d.texture(tex.checker(4, 2), "metal_rough", tex.CLAMP)
    normal = d.texture(tex.checker(4, 2), "normal", tex.LINEAR)
    m = d.material({
        "name": "all maps", "alphaMode": "MASK", "alphaCutoff": 0.25, "doubleSided": True,
        "pbrMetallicRoughness": {
            "baseColorTexture": transformed(base, {"offset": [0.5, 0.5], "rotation": 1.5707964, "scale": [2, 2]}),
            "metallicRoughnessTexture": transformed(mr, {"scale": [-1, 3], "texCoord": 1}),
            "metallicFactor": 1.0, "roughnessFactor": 1.0},
        "normalTexture": transformed(normal, {"rotation": -3.14159}, extra={"scale": 2.0}),
        "occlusionTexture": transformed(mr, {"offset": [-0.25, 0.0]}, extra={"strength": 0.5}),
        "emissiveTexture": transformed(base, {"scale": [0.5, 0.5]}), "emissiveFactor": [0.2, 0.1, 0.0]})
    attrs, idx = tex.quad(uv0=(-1.0, -1.0), uv1=(2.0, 2.0))
    attrs["TEXCOORD_1"] = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    d.mesh(attrs, idx, m, "quad")
    return d


def glb_seed():
    """A GLB whose PNG lives in a bufferView of the BIN chunk."""
    d = tex.Doc("textured.glb")
    d.d["asset"]["generator"] = "shadelab tests/fuzz/make_corpus.py"
    d.d["extensionsUsed"] = ["KHR_texture_transform"]
    view = d.view(tex.png(tex.checker()))
    d.d["images"] = [{"bufferView": view, "mimeType": "image/png"}]
    d.d["samplers"] = [tex.LINEAR]
    d.d["textures"] = [{"source": 0, "sampler": 0}]
    m = d.material({"pbrMetallicRoughness": {
        "baseColorTexture": transformed(0, {"offset": [0.1, 0.2], "rotation": 0.3, "scale": [4, 0.25]}),
        "metallicFactor": 0.0, "roughnessFactor": 0.4}})
    d.mesh(*tex.quad(), m, "quad")
    return d


def gltf_seeds(folder):
    seeds = [
        (textured_quad("transform_basic.gltf", {"offset": [0.3, -0.2], "rotation": 0.4, "scale": [1.6, 1.4]}),
         gltf_bytes),
        (textured_quad("transform_extreme.gltf", {"offset": [3e38, -3e38], "rotation": 1e38, "scale": [1e38, -1e38]},
                       sampler=tex.LINEAR), gltf_bytes),
        (textured_quad("transform_tiny.gltf", {"offset": [-0.0, 0.0], "rotation": -0.0, "scale": [1e-45, 1e-38]},
                       uv0=(1e-45, -0.0), uv1=(1e-38, 1e-45), sampler=tex.CLAMP), gltf_bytes),
        # The case docs/cli.md names: a coordinate of 3e38 scaled by 2 overflows.
        (textured_quad("uv_huge.gltf", {"scale": [2, 2]}, uv0=(3e38, -3e38), uv1=(-3e38, 1e38)), gltf_bytes),
        (textured_quad("transform_texcoord.gltf", {"texCoord": 1, "rotation": 0.8}, second_uv=True, tex_coord=0),
         gltf_bytes),
        (all_maps(), gltf_bytes),
        (glb_seed(), glb_bytes),
    ]
    for doc, encode in seeds:
        write(folder, doc.name, encode(doc))


# Viewer scripts -----------------------------------------------------------------------------------------
STATE_ACTIONS = [
    {"action": "setShininess", "object": "gold", "s": 128},
    {"action": "setMaterial", "object": "red plastic", "md": [0.5, 0.1, 0.1], "ms": 0.4, "s": 20, "kr": 0.1,
     "kt": 0.0, "ior": 1.5},
    {"action": "setMaterial", "object": "#1", "baseColor": [0.9, 0.5, 0.2], "metallic": 1, "roughness": 0.3},
    {"action": "preset", "object": "#2", "name": "emerald"},
    {"action": "select", "object": "floor"},
    {"action": "setTerm", "term": "specular", "on": False},
    {"action": "toggleTerm", "term": "shadows"},
    {"frame": 2, "action": "progression", "step": 3},
    {"action": "setModel", "model": "blinn-phong"},
    {"action": "switchModel", "model": "phong", "all": True},
    {"action": "setMode", "mode": "split"},
    {"action": "setEncoding", "encoding": "linear"},
    {"action": "setSplit", "position": 0.25},
    {"action": "setAmbient", "value": [0.1, 0.1, 0.12]},
    {"action": "setRaster", "shadowMapSize": "auto", "depthBias": 1.5, "normalBias": 2, "pcf": True,
     "reflectionCubeSize": 256, "movingPreview": False},
    {"action": "addLight", "type": "directional", "direction": [0, -1, -0.5], "color": [0.3, 0.3, 0.3]},
    {"action": "setLight", "index": 0, "position": [-4, 6, 4], "color": [1, 0.9, 0.8]},
    {"action": "removeLight", "index": 2},
    {"frame": 4, "action": "orbit", "yaw": 30, "pitch": -10},
    {"action": "zoom", "steps": -2.5},
    {"action": "frameAll"},
    {"action": "resetCamera"},
    {"action": "probe", "x": 64, "y": 48},
    {"action": "clearProbe"},
    {"action": "whiteFurnace", "on": True},
    {"action": "whiteFurnace", "on": False},
]
WINDOW_ACTIONS = [
    {"frame": 1, "action": "screenshot", "path": "shot.png"},
    {"action": "waitReference", "timeout": 30},
    {"action": "referenceScreenshot", "path": "reference.png"},
    {"action": "windowScreenshot", "path": "window.png"},
    {"action": "probeReport", "path": "probe.json"},
    {"action": "saveScene", "path": "saved.json"},
    {"action": "undo"},
    {"action": "redo"},
    {"frame": 3, "action": "render", "path": "raster.png"},
    {"action": "render", "path": "trace.png", "renderer": "trace", "size": [64, 48], "spp": 4, "depth": 3,
     "threads": 1},
    {"action": "render", "path": "path.png", "renderer": "path", "size": [32, 24], "spp": 16, "timeLimit": 2.5,
     "estimator": "mis", "lightPaths": "direct"},
    {"action": "smoothScreenshot", "path": "smooth.png", "timeout": 20},
    {"action": "drag", "x0": 10, "y0": 10, "x1": 40, "y1": 20, "steps": 4},
    {"action": "open", "path": "other.json"},
    {"action": "reloadShaders"},
    {"action": "reloadShaders", "dir": "shaders"},
    {"frame": 9, "action": "resizeWindow", "width": 640, "height": 360},
]


def script_seeds(folder):
    write(folder, "state_actions.json", (json.dumps({"actions": STATE_ACTIONS}, indent=1) + "\n").encode())
    write(folder, "window_actions.json", (json.dumps(WINDOW_ACTIONS, indent=1) + "\n").encode())
    # Numbers at their fields' edges: the largest shininess, a split of 0, far lights, huge orbit angles.
    edges = [
        {"action": "setShininess", "object": "red plastic", "s": 10000},
        {"action": "setSplit", "position": 0},
        {"action": "setLight", "index": 1, "direction": [1e-30, -1, 0]},
        {"action": "addLight", "position": [1e15, -1e15, 1e15], "color": [1e15, 0, 0]},
        {"action": "orbit", "yaw": 1e30, "pitch": -1e30},
        {"action": "zoom", "steps": 1e30},
        {"action": "zoom", "steps": -1e30},
        {"frame": 16777216, "action": "probe", "x": 16383, "y": 0},
    ]
    write(folder, "edges.json", (json.dumps({"actions": edges}) + "\n").encode())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--output", required=True, help="folder to write the corpus folders into (created)")
    args = ap.parse_args()
    for target, make in [("hdr_fuzz", hdr_seeds), ("gltf_texture_fuzz", gltf_seeds), ("script_fuzz", script_seeds)]:
        folder = os.path.join(args.output, target)
        os.makedirs(folder, exist_ok=True)
        make(folder)


if __name__ == "__main__":
    main()
