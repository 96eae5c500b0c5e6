#!/usr/bin/python3
"""Structural glTF mutation fuzzer: mutates the JSON and GLB structure of real models (counts,
offsets, strides, URIs, component types, indices, node links), renders each mutant with the shadelab binary,
and checks the promises for bad input: exit 0 or 1, at most one error line, every line within the cap,
within 10 s and 1 GiB. Failing mutants and their output are kept in the output folder.

usage: gltf_mutate.py SHADELAB [--cases N] [--seed S] [--out DIR] [MODEL ...]
Models default to assets/models/torus.gltf, four of the generated textured assets (assets/models/textures/:
tangents generated, alpha mask, metallic-roughness + occlusion, emissive) and a few of Debian's
assimp-testmodels (glTF and GLB)."""

import argparse
import json
import os
import random
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

CAP = 300                                       # util/error_line.h kMaxErrorLineChars
PREFIXES = ("shadelab: error: ", "shadelab: warning: ", "shadelab: usage error: ")
TIME_LIMIT_S = 10.0
MEMORY_LIMIT_MIB = 1024.0
ASSIMP = "/usr/share/assimp/models/glTF2"
DEFAULT_MODELS = [
    "assets/models/torus.gltf",
    "assets/models/textures/normal_bump_no_tangents.gltf",
    "assets/models/textures/alpha_mask.gltf",
    "assets/models/textures/metal_rough.gltf",
    "assets/models/textures/emissive.gltf",
    ASSIMP + "/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
    ASSIMP + "/BoxTextured-glTF/BoxTextured.gltf",
    ASSIMP + "/BoxTextured-glTF-Binary/BoxTextured.glb",
    ASSIMP + "/BoxTextured-glTF-Embedded/BoxTextured.gltf",
    ASSIMP + "/textureTransform/TextureTransformTest.gltf",
]

# Values a hostile file would try, by the kind of field they replace.
NUMBERS = [0, 1, -1, 2, 3, 4, 7, 255, 65535, 65536, 2**31 - 1, 2**31, 2**32 - 1, 2**32, 2**53, -2**31, 1e300,
           0.5, -0.0]
COMPONENT_TYPES = [5120, 5121, 5122, 5123, 5125, 5126, 5124, 0, 1, 9999]
TYPES = ["SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4", "VEC5", "", 3]
URIS = [".", "..", "/", "", "\u0000", "a\u0000.bin", "/dev/zero", "/dev/stdin", "/etc/passwd", "../../../etc/passwd",
        "data:", "data:application/octet-stream;base64,", "data:application/octet-stream;base64,!!!!",
        "data:;base64," + "A" * 10000, "x" * 5000, "%2e%2e/%2e%2e/etc/passwd", "file:///etc/passwd", "nonexistent.bin",
        "\n\x1b[31m"]
NUMERIC_KEYS = {"count", "byteOffset", "byteLength", "byteStride", "buffer", "bufferView", "indices", "material",
                "mesh", "mode", "source", "sampler", "camera", "skin", "POSITION", "NORMAL", "TEXCOORD_0", "scene",
                "index", "texCoord", "yfov", "znear", "zfar", "aspectRatio"}


def load_model(path):
    """(json document, bin chunk or None, is_glb)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        length = struct.unpack_from("<I", data, 12)[0]
        doc = json.loads(data[20:20 + length])
        rest = data[20 + length:]
        binary = rest[8:8 + struct.unpack_from("<I", rest, 0)[0]] if len(rest) >= 8 else b""
        return doc, binary, True
    return json.loads(data), None, False


def write_model(path, doc, binary, glb):
    text = json.dumps(doc).encode()
    if not glb:
        with open(path, "wb") as f:
            f.write(text)
        return
    text += b" " * (-len(text) % 4)
    binary = binary + b"\0" * (-len(binary) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
    with open(path, "wb") as f:
        f.write(struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks)


def places(node, path=()):
    """Every (container, key) in the document."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield node, k, path + (k,)
            yield from places(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield node, i, path + (i,)
            yield from places(v, path + (i,))


def mutate(doc, rng):
    """One structural change; returns its description."""
    spots = list(places(doc))
    rng.shuffle(spots)
    for container, key, path in spots:
        value = container[key]
        name = key if isinstance(key, str) else (path[-2] if len(path) > 1 else "")
        where = "/".join(str(p) for p in path)
        if name == "componentType":
            container[key] = rng.choice(COMPONENT_TYPES)
        elif name == "type" and isinstance(value, str) and value.isupper():
            container[key] = rng.choice(TYPES)
        elif name == "uri":
            container[key] = rng.choice(URIS)
        elif name in NUMERIC_KEYS or (isinstance(value, (int, float)) and not isinstance(value, bool)):
            container[key] = rng.choice(NUMBERS) if rng.random() < 0.7 else (value if isinstance(value, (int, float)) else 0) + rng.choice([-1, 1, 3, 4, 1000])
        elif name in ("children", "nodes") and isinstance(value, list):
            choice = rng.random()
            if choice < 0.4 and value:
                container[key] = value * rng.choice([2, 16])          # instancing
            elif choice < 0.7:
                container[key] = value + [rng.choice([0, -1, len(doc.get("nodes", [])), 2**31])]
            else:
                container[key] = []
        elif isinstance(value, list) and value and rng.random() < 0.3:
            container[key] = value[: rng.randrange(len(value))]       # truncated array
        elif isinstance(value, dict) and value and rng.random() < 0.2:
            value.pop(rng.choice(list(value)))                        # missing field
        elif isinstance(value, str) and rng.random() < 0.1:
            container[key] = rng.choice(["", "\n\x1b[2J", "x" * 3000, 7, None])
        else:
            continue
        return where
    return "nothing"


def run_case(binary, model, out_png):
    """(exit code, output lines, seconds, the peak resident memory of any case so far in MiB)."""
    start = time.monotonic()
    proc = subprocess.Popen([binary, "render", model, "-o", out_png, "--size", "32x24"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=TIME_LIMIT_S)
        timed_out = False
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        timed_out = True
    seconds = time.monotonic() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024.0
    code = 124 if timed_out else proc.returncode
    return code, out.decode("utf-8", "replace").splitlines(), seconds, peak


def check(code, lines, seconds):
    problems = []
    if code not in (0, 1):
        problems.append(f"exit code {code}")
    errors = [l for l in lines if l.startswith("shadelab: error: ")]
    if len(errors) > 1 or (code == 1 and len(errors) != 1):
        problems.append(f"{len(errors)} error lines")
    for l in lines:
        body = next((l[len(p):] for p in PREFIXES if l.startswith(p)), None)
        if body is None:
            problems.append("a line without shadelab's prefix: " + l[:80])
        elif len(body.encode()) > CAP + 3:
            problems.append(f"a line of {len(body.encode())} bytes")
    if seconds > TIME_LIMIT_S:
        problems.append(f"{seconds:.1f} s")
    return problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("shadelab")
    ap.add_argument("models", nargs="*")
    ap.add_argument("--cases", type=int, default=3000)
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--out", default=None, help="folder for failing mutants (default: a temporary folder)")
    args = ap.parse_args()
    models = [m for m in (args.models or DEFAULT_MODELS) if os.path.exists(m)]
    if not models:
        print("gltf_mutate: no models found", file=sys.stderr)
        return 2
    originals = [(m, *load_model(m)) for m in models]
    rng = random.Random(args.seed)
    out_dir = args.out or tempfile.mkdtemp(prefix="gltf_mutate_")
    os.makedirs(out_dir, exist_ok=True)
    work = tempfile.mkdtemp(prefix="gltf_mutate_work_")
    failures, codes, slowest, peak = 0, {}, 0.0, 0.0
    for case in range(args.cases):
        path, doc, binary, glb = rng.choice(originals)
        mutant = json.loads(json.dumps(doc))
        changes = [mutate(mutant, rng) for _ in range(rng.choice([1, 1, 2, 3]))]
        # Side files (buffers, images) stay next to the mutant, so relative URIs still resolve.
        folder = os.path.dirname(os.path.abspath(path))
        name = os.path.join(work, f"case{case}" + (".glb" if glb else ".gltf"))
        for entry in os.listdir(folder):
            target = os.path.join(work, entry)
            if not os.path.lexists(target) and not entry.endswith((".gltf", ".glb")):
                os.symlink(os.path.join(folder, entry), target)
        write_model(name, mutant, binary, glb)
        code, lines, seconds, peak_now = run_case(args.shadelab, name, os.path.join(work, "out.png"))
        codes[code] = codes.get(code, 0) + 1
        slowest, peak = max(slowest, seconds), max(peak, peak_now)
        problems = check(code, lines, seconds)
        if problems:
            failures += 1
            kept = os.path.join(out_dir, os.path.basename(name))
            shutil.copy(name, kept)
            with open(kept + ".txt", "w") as f:
                f.write(f"model {path}\nchanges {changes}\nproblems {problems}\n" + "\n".join(lines) + "\n")
            print(f"case {case}: {'; '.join(problems)} ({path}: {changes}) -> {kept}", file=sys.stderr)
        os.remove(name)
    shutil.rmtree(work, ignore_errors=True)
    print(f"gltf_mutate: {args.cases} cases, exit codes {dict(sorted(codes.items()))}, slowest {slowest:.2f} s, "
          f"peak {peak:.0f} MiB (limit {MEMORY_LIMIT_MIB:.0f})")
    if peak > MEMORY_LIMIT_MIB:
        failures += 1
        print(f"gltf_mutate: peak memory {peak:.0f} MiB over {MEMORY_LIMIT_MIB:.0f} MiB", file=sys.stderr)
    print(f"{args.cases - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
