"""Render a shadelab scene (.json) with Blender Cycles: the baseline of the path tracer's paths/s benchmark.

Run it through Blender, never as part of shadelab (Blender is a benchmark baseline only):

    blender -b --factory-startup --python-exit-code 1 --python bench/cycles_default.py -- \
        SCENE.json OUT.png|OUT.exr [SPP [THREADS]] [--size WxH] [--bounces N] [--spheres points|mesh] \
        [--falloff quadratic|constant] [--seed N] [--unbiased]

Defaults: 16 spp, 2 threads, 1280x720, 5 bounces (every bounce type), analytic spheres (a point cloud),
inverse-square point lights calibrated at the camera target. Cycles runs on the CPU with no denoising and
no adaptive sampling; everything else (light sampling, caustics, filter, tiles) is left at Cycles' defaults,
unless --unbiased turns off what biases Cycles' estimate or correlates its pixels, so that its error can be
set beside shadelab's (the global-illumination benchmark, bench/cornell_vs_cycles.sh): no sample clamping
(Cycles clamps indirect samples at 10 by default), no Filter Glossy, no light threshold, and a 1-pixel box
pixel filter like shadelab's jitter (Cycles' default is a 1.5-pixel Blackman-Harris, which blurs noise into
neighbouring pixels). --seed sets Cycles' seed (0), for independent references. An OUT ending in .exr is
written as linear 32-bit float RGB OpenEXR (no view transform), as `shadelab render -o x.exr` does.

It prints, on one line each:
    cycles: render time X.XXX s (Cycles' own), render call Y.YYY s, Z.ZZZ Mpaths/s
where "render time" is the "Time:" of Cycles' last render statistics (path tracing, without Blender's
start-up, the scene conversion here or the PNG write) and "render call" is bpy.ops.render.render() as a
whole (Cycles' scene sync and BVH build included). Time the whole process from the shell.

The scene translation (docs/scene-format.md), approximate by design:
- shadelab is +y up, Blender +z up: a shadelab point (x, y, z) is Blender's (x, -z, y).
- camera: eye/target/up/fovY (vertical field of view, aspect from the image size).
- spheres: one point of a point cloud each (Cycles renders points as true spheres), or with
  --spheres mesh a smooth UV sphere of 128 x 64 segments. An emissive sphere is always the mesh: Cycles 3.4
  samples emissive triangles as lights, never points.
- planes: a 20,000-unit square quad centred under the camera target (the horizon gap is under a pixel);
  its checker is laid out in shadelab's tangent basis (shaders/lighting.glsl, planeTangent) through a UV map.
- materials: Diffuse BSDF (md) + Glossy GGX (roughness (2/(s+2))^(1/4), the Walter mapping of
  docs/scene-format.md, colour ms * min(1, 8/(s+2)) so that its highlight peak under a point light equals
  Phong's ms * Il) + a sharp Glossy for kr + a Glass BSDF for kt (ior), added like the lecture's terms;
  `emission` adds an Emission shader of that colour at strength 1 (radiance = emission, as shadelab's; both
  emit from both sides). pbr-only
  materials are mapped to md/ms/s as the scene loader does. ma and the ambient term are ignored: light
  transport replaces them.
- lights: shadelab's point light of colour Il gives irradiance pi*Il*N.L at any distance (no
  attenuation). Cycles' point light of power P gives P/(4 pi d^2)*N.L, so P = 4 pi^2 Il d^2 with d the
  light's distance to the camera target (--falloff quadratic, the default: a plain Cycles lamp), or
  P = 4 pi^2 Il through a Light Falloff node's Constant output (--falloff constant: shadelab's model,
  a shader evaluation per light sample). Point lights have radius 0 (hard shadows). A directional light is
  a Sun of strength pi*Il. attenuation is ignored.
- background: the world colour (a uniform environment of that radiance, seen and lighting the scene);
  environment.intensity scales it. Environment maps (.hdr) and glTF meshes are skipped with a warning.
"""

import argparse
import ctypes
import json
import math
import os
import re
import sys
import tempfile
import time

import bpy


def fail(message, code=1):
    print(f"cycles_default: {message}", file=sys.stderr, flush=True)
    sys.exit(code)


def script_args():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser(prog="blender -b --factory-startup --python bench/cycles_default.py --",
                                description="Render a shadelab scene with Cycles (the paths/s benchmark's baseline).")
    p.add_argument("scene")
    p.add_argument("output")
    p.add_argument("spp", nargs="?", type=int, default=16)
    p.add_argument("threads", nargs="?", type=int, default=2)
    p.add_argument("--size", default="1280x720")
    p.add_argument("--bounces", type=int, default=5)
    p.add_argument("--spheres", choices=["points", "mesh"], default="points")
    p.add_argument("--falloff", choices=["quadratic", "constant"], default="quadratic")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--unbiased", action="store_true")
    a = p.parse_args(argv)
    m = re.fullmatch(r"(\d+)x(\d+)", a.size)
    if not m or not (1 <= int(m[1]) <= 16384 and 1 <= int(m[2]) <= 16384):
        fail(f"--size: expected WxH with sides 1..16384, got '{a.size}'", 2)
    a.width, a.height = int(m[1]), int(m[2])
    if a.spp < 1 or a.threads < 1 or a.bounces < 0:
        fail("SPP and THREADS must be >= 1 and --bounces >= 0", 2)
    return a


# ---- reading the scene ---------------------------------------------------------------------------------

def strip_comments(text):
    """Remove // and /* */ comments outside strings (shadelab accepts them)."""
    out, i, n, in_str = [], 0, len(text), False
    while i < n:
        c = text[i]
        if in_str:
            out.append(c)
            if c == "\\" and i + 1 < n:
                out.append(text[i + 1])
                i += 1
            elif c == '"':
                in_str = False
        elif c == '"':
            in_str = True
            out.append(c)
        elif text.startswith("//", i):
            while i < n and text[i] != "\n":
                i += 1
            continue
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            i = n if end < 0 else end + 2
            continue
        else:
            out.append(c)
        i += 1
    return "".join(out)


def rgb(v, default):
    if v is None:
        return tuple(default)
    if isinstance(v, (int, float)):
        return (float(v),) * 3
    if isinstance(v, list) and len(v) == 3:
        return tuple(float(x) for x in v)
    raise ValueError(f"expected a number or 3 numbers, got {v!r}")


def vec3(v, default=None):
    if v is None:
        return default
    if isinstance(v, list) and len(v) == 3:
        return tuple(float(x) for x in v)
    raise ValueError(f"expected 3 numbers, got {v!r}")


def to_blender(p):
    """shadelab (+y up) to Blender (+z up)."""
    return (p[0], -p[2], p[1])


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    length = math.sqrt(dot(a, a))
    return tuple(x / length for x in a)


def material_params(m):
    """A shadelab material (dict) as md, ms, s, kr, kt, ior (docs/scene-format.md defaults and mapping)."""
    phong = any(k in m for k in ("ma", "md", "ms", "s"))
    pbr = any(k in m for k in ("baseColor", "metallic", "roughness"))
    md = rgb(m.get("md"), (0.7, 0.7, 0.7))
    ms = rgb(m.get("ms"), (0.3, 0.3, 0.3))
    s = float(m.get("s", 32))
    if pbr and not phong:
        base = rgb(m.get("baseColor"), (0.7, 0.7, 0.7))
        metallic = float(m.get("metallic", 0))
        rough = float(m.get("roughness", 0.4925))
        md = tuple(c * (1 - metallic) for c in base)
        ms = tuple(0.04 * (1 - metallic) + c * metallic for c in base)
        s = min(max(2 / max(rough, 1e-4) ** 4 - 2, 1), 10000)
    return {"md": md, "ms": ms, "s": s, "kr": rgb(m.get("kr"), (0, 0, 0)), "kt": rgb(m.get("kt"), (0, 0, 0)),
            "ior": float(m.get("ior", 1.5)), "emission": rgb(m.get("emission"), (0, 0, 0))}


def resolve_material(scene, ref, where):
    if ref is None:
        return {}
    if isinstance(ref, str):
        named = scene.get("materials", {})
        if ref not in named:
            raise ValueError(f"{where}.material: no material named '{ref}'; there are {sorted(named)}")
        return named[ref]
    if isinstance(ref, dict):
        return ref
    raise ValueError(f"{where}.material: expected a name or an object")


# ---- building the Blender scene ------------------------------------------------------------------------

def nonzero(c):
    return max(c) > 0


def make_material(name, p, checker=None):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    for n in list(nt.nodes):
        nt.nodes.remove(n)
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    closures = []
    if nonzero(p["md"]) or checker:
        d = nt.nodes.new("ShaderNodeBsdfDiffuse")
        d.inputs["Color"].default_value = (*p["md"], 1)
        if checker:
            md2, size = checker
            uv = nt.nodes.new("ShaderNodeUVMap")
            ck = nt.nodes.new("ShaderNodeTexChecker")
            ck.inputs["Scale"].default_value = 1.0 / size
            # Cycles' checker (svm_checker) gives Color1 where floor(u) + floor(v) is odd (with w = 0):
            # shadelab's checkerParity 1, the md2 tiles.
            ck.inputs["Color1"].default_value = (*md2, 1)
            ck.inputs["Color2"].default_value = (*p["md"], 1)
            nt.links.new(uv.outputs["UV"], ck.inputs["Vector"])
            nt.links.new(ck.outputs["Color"], d.inputs["Color"])
        closures.append(d)
    if nonzero(p["ms"]):
        g = nt.nodes.new("ShaderNodeBsdfGlossy")
        g.distribution = "GGX"
        # GGX's peak at normal incidence is c * Il * (s+2)/8 with alpha^2 = 2/(s+2); Phong's highlight
        # peak is ms * Il. So c = ms * 8/(s+2) (at most ms) gives the same highlight, where c = ms would
        # turn every shiny sphere into a near-mirror of the floor.
        peak = min(1.0, 8.0 / (p["s"] + 2.0))
        g.inputs["Color"].default_value = (*(c * peak for c in p["ms"]), 1)
        g.inputs["Roughness"].default_value = (2.0 / (p["s"] + 2.0)) ** 0.25
        closures.append(g)
    if nonzero(p["kr"]):
        r = nt.nodes.new("ShaderNodeBsdfGlossy")
        r.distribution = "SHARP"
        r.inputs["Color"].default_value = (*p["kr"], 1)
        closures.append(r)
    if nonzero(p["kt"]):
        t = nt.nodes.new("ShaderNodeBsdfGlass")
        t.distribution = "SHARP"
        t.inputs["Color"].default_value = (*p["kt"], 1)
        t.inputs["IOR"].default_value = p["ior"]
        closures.append(t)
    if nonzero(p["emission"]):
        e = nt.nodes.new("ShaderNodeEmission")
        e.inputs["Color"].default_value = (*p["emission"], 1)
        e.inputs["Strength"].default_value = 1.0
        closures.append(e)
    if not closures:
        closures.append(nt.nodes.new("ShaderNodeBsdfTransparent"))
        closures[0].inputs["Color"].default_value = (0, 0, 0, 1)  # black
    shader = closures[0]
    for c in closures[1:]:
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(shader.outputs[0], add.inputs[0])
        nt.links.new(c.outputs[0], add.inputs[1])
        shader = add
    nt.links.new(shader.outputs[0], out.inputs["Surface"])
    return mat


def add_sphere(name, center, radius, mat, mode):
    if mode == "mesh":
        bpy.ops.mesh.primitive_uv_sphere_add(segments=128, ring_count=64, radius=radius,
                                             location=to_blender(center))
        obj = bpy.context.active_object
        obj.name = name
        bpy.ops.object.shade_smooth()
        obj.data.materials.append(mat)
        return
    # A point cloud of one point, made by geometry nodes: Cycles intersects it as an analytic sphere.
    mesh = bpy.data.meshes.new(name)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    tree = bpy.data.node_groups.new(name, "GeometryNodeTree")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    points = tree.nodes.new("GeometryNodePoints")
    points.inputs["Count"].default_value = 1
    points.inputs["Position"].default_value = to_blender(center)
    points.inputs["Radius"].default_value = radius
    setmat = tree.nodes.new("GeometryNodeSetMaterial")
    setmat.inputs["Material"].default_value = mat
    out = tree.nodes.new("NodeGroupOutput")
    tree.links.new(points.outputs["Geometry"], setmat.inputs["Geometry"])
    tree.links.new(setmat.outputs["Geometry"], out.inputs["Geometry"])
    mod = obj.modifiers.new("sphere", "NODES")
    mod.node_group = tree


def plane_basis(n):
    """shaders/lighting.glsl planeTangent/planeBitangent (Duff et al. 2017), in shadelab coordinates."""
    sgn = 1.0 if n[2] >= 0 else -1.0
    a = -1.0 / (sgn + n[2])
    b = n[0] * n[1] * a
    t = (1.0 + sgn * n[0] * n[0] * a, sgn * b, -sgn * n[0])
    bt = (b, sgn + n[1] * n[1] * a, -n[1])
    return t, bt


def add_plane(name, normal, offset, around, mat):
    n = normalize(normal)
    t, bt = plane_basis(n)
    # Centred on the point of the plane nearest `around` (the camera target).
    p0 = tuple(around[i] - (dot(around, n) - offset) * n[i] for i in range(3))
    half = 10000.0
    corners = []
    for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        corners.append(tuple(p0[i] + su * half * t[i] + sv * half * bt[i] for i in range(3)))
    mesh = bpy.data.meshes.new(name)
    # (t, bt, n) is right-handed (t x bt = n), so this winding faces along n (the plane is two-sided anyway).
    mesh.from_pydata([to_blender(c) for c in corners], [], [(0, 1, 2, 3)])
    uv = mesh.uv_layers.new(name="UVMap")
    for loop in mesh.loops:
        c = corners[loop.vertex_index]
        uv.data[loop.index].uv = (dot(c, t), dot(c, bt))  # checker in world units; Scale = 1/size
    mesh.materials.append(mat)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)


def add_light(i, light, target, falloff):
    kind = light.get("type")
    il = rgb(light.get("color"), (1, 1, 1))
    peak = max(il)
    colour = tuple(c / peak for c in il) if peak > 0 else (1, 1, 1)
    name = light.get("name") or f"light{i}"
    if kind == "directional":
        data = bpy.data.lights.new(name, "SUN")
        data.energy = math.pi * peak  # irradiance (W/m^2) = pi * Il
        data.angle = 0.0
        d = normalize(to_blender(vec3(light.get("direction"), (0, -1, 0))))
        obj = bpy.data.objects.new(name, data)
        # A sun shines along its local -z.
        obj.rotation_mode = "QUATERNION"
        obj.rotation_quaternion = __import__("mathutils").Vector(d).to_track_quat("-Z", "Y")
    elif kind == "point":
        pos = vec3(light.get("position"), (0, 5, 5))
        data = bpy.data.lights.new(name, "POINT")
        data.shadow_soft_size = 0.0
        if falloff == "constant":
            data.energy = 4 * math.pi ** 2 * peak
            data.use_nodes = True
            nt = data.node_tree
            emission = next(n for n in nt.nodes if n.type == "EMISSION")
            fo = nt.nodes.new("ShaderNodeLightFalloff")
            fo.inputs["Strength"].default_value = 1.0
            nt.links.new(fo.outputs["Constant"], emission.inputs["Strength"])
        else:
            d2 = dot(sub(pos, target), sub(pos, target))
            data.energy = 4 * math.pi ** 2 * peak * d2
            print(f"cycles_default: point light '{name}': {data.energy:.1f} W (inverse-square, exact at the "
                  f"camera target, {math.sqrt(d2):.2f} units away)", flush=True)
        obj = bpy.data.objects.new(name, data)
        obj.location = to_blender(pos)
    else:
        raise ValueError(f"lights[{i}].type: unknown light type {kind!r}")
    data.color = colour
    bpy.context.scene.collection.objects.link(obj)


def build_scene(sl, args):
    scene = bpy.context.scene
    # A bare scene: --factory-startup brings a cube, a light and a camera.
    for obj in list(bpy.data.objects):
        bpy.data.objects.remove(obj, do_unlink=True)

    cam = sl.get("camera", {})
    eye = vec3(cam.get("position"), (0, 1.5, 6))
    target = vec3(cam.get("target"), (0, 0.5, 0))
    up = vec3(cam.get("up"), (0, 1, 0))
    fovy = float(cam.get("fovY", 45))
    f = normalize(sub(target, eye))
    r = normalize(cross(f, up))
    u = cross(r, f)
    import mathutils
    # Blender's camera looks along its local -z with +y up: columns (r, u, -f), in Blender coordinates.
    cols = [to_blender(r), to_blender(u), to_blender(tuple(-x for x in f))]
    rot = mathutils.Matrix([[cols[c][row] for c in range(3)] for row in range(3)])
    cdata = bpy.data.cameras.new("camera")
    cdata.sensor_fit = "VERTICAL"
    cdata.angle_y = math.radians(fovy)
    cdata.clip_start = 1e-3
    cdata.clip_end = 1e6
    cobj = bpy.data.objects.new("camera", cdata)
    cobj.matrix_world = mathutils.Matrix.Translation(to_blender(eye)) @ rot.to_4x4()
    scene.collection.objects.link(cobj)
    scene.camera = cobj

    objects = sl.get("objects", [])
    for i, o in enumerate(objects):
        where = f"objects[{i}]"
        kind = o.get("type")
        name = o.get("name") or f"object{i}"
        params = material_params(resolve_material(sl, o.get("material"), where))
        if kind == "sphere":
            mode = "mesh" if nonzero(params["emission"]) else args.spheres
            add_sphere(name, vec3(o["center"]), float(o["radius"]), make_material(name, params), mode)
        elif kind == "plane":
            normal = vec3(o.get("normal"), (0, 1, 0))
            if "point" in o:
                offset = dot(normalize(normal), vec3(o["point"]))
            else:
                offset = float(o.get("offset", 0))
            ck = o.get("checker")
            checker = (rgb(ck.get("md2"), (0.1, 0.1, 0.1)), float(ck.get("size", 1))) if ck is not None else None
            add_plane(name, normal, offset, target, make_material(name, params, checker))
        elif kind == "mesh":
            print(f"cycles_default: warning: {where}: glTF mesh '{o.get('source')}' skipped", flush=True)
        else:
            raise ValueError(f"{where}.type: unknown object type {kind!r}")

    for i, light in enumerate(sl.get("lights", [])):
        add_light(i, light, target, args.falloff)

    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    bg = world.node_tree.nodes["Background"]
    env = sl.get("environment")
    strength = 1.0
    if isinstance(env, dict):
        strength = float(env.get("intensity", 1))
        if "hdr" in env:
            print(f"cycles_default: warning: environment.hdr '{env['hdr']}' skipped; uniform background used",
                  flush=True)
    bg.inputs["Color"].default_value = (*rgb(sl.get("background"), (0, 0, 0)), 1)
    bg.inputs["Strength"].default_value = strength
    scene.world = world


def configure(args):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.max_bounces = args.bounces
    c.diffuse_bounces = args.bounces
    c.glossy_bounces = args.bounces
    c.transmission_bounces = args.bounces
    c.volume_bounces = args.bounces
    c.transparent_max_bounces = args.bounces
    c.seed = args.seed
    if args.unbiased:
        c.sample_clamp_direct = 0.0
        c.sample_clamp_indirect = 0.0
        c.blur_glossy = 0.0
        c.light_sampling_threshold = 0.0
        c.pixel_filter_type = "BOX"
        c.filter_width = 1.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = args.threads
    scene.render.resolution_x = args.width
    scene.render.resolution_y = args.height
    scene.render.resolution_percentage = 100
    scene.render.use_persistent_data = False
    scene.render.dither_intensity = 0.0
    # Linear radiance to sRGB as shadelab writes it: no Filmic tone curve.
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.display_settings.display_device = "sRGB"
    img = scene.render.image_settings
    if args.output.lower().endswith(".exr"):
        img.file_format = "OPEN_EXR"
        img.color_mode = "RGB"
        img.color_depth = "32"
        img.exr_codec = "ZIP"
    else:
        img.file_format = "PNG"
        img.color_mode = "RGB"
        img.color_depth = "8"
        img.compression = 15


def main():
    args = script_args()
    try:
        with open(args.scene, "rb") as fh:
            data = fh.read(64 << 20)
        sl = json.loads(strip_comments(data.decode("utf-8")))
        if not isinstance(sl, dict):
            raise ValueError("expected a JSON object")
        bpy.context.scene.render.engine = "CYCLES"
        build_scene(sl, args)
    except (OSError, ValueError, KeyError, TypeError) as e:
        fail(f"{args.scene}: {e}")
    configure(args)

    # Cycles reports its progress on stdout ("Fra:1 ... | Time:00:13.92 | ... | Sample 16/16", then
    # "... | Finished"); Python cannot hook those lines (render_stats handlers get no text), so stdout goes
    # to a temporary file during the render and the lines are read back.
    libc = ctypes.CDLL(None)
    sys.stdout.flush()
    libc.fflush(None)
    saved = os.dup(1)
    with tempfile.TemporaryFile() as log:
        os.dup2(log.fileno(), 1)
        try:
            t0 = time.perf_counter()
            bpy.ops.render.render(write_still=False)
            call = time.perf_counter() - t0
        finally:
            sys.stdout.flush()
            libc.fflush(None)
            os.dup2(saved, 1)
            os.close(saved)
        log.seek(0)
        lines = log.read().decode("utf-8", "replace").splitlines()

    def clock(line):
        m = re.search(r"\| Time:(?:(\d+):)?(\d+):(\d+(?:\.\d+)?) \|", line)
        return None if not m else int(m[1] or 0) * 3600 + int(m[2]) * 60 + float(m[3])

    render_time = trace_start = None
    for line in lines:
        if trace_start is None and re.search(r"\| (Sample 0/|Rendered 0/)", line):
            trace_start = clock(line)
        if line.rstrip().endswith("| Finished"):
            render_time = clock(line)
    if os.environ.get("CYCLES_DEFAULT_STATS"):
        print("\n".join(lines), flush=True)

    out = os.path.abspath(args.output)
    ext = os.path.splitext(out)[1] or ".png"
    tmp = os.path.join(os.path.dirname(out), f".{os.path.basename(out)}.{os.getpid()}.tmp{ext}")
    bpy.data.images["Render Result"].save_render(tmp)
    os.replace(tmp, out)

    paths = args.width * args.height * args.spp
    if render_time is None:
        print("cycles_default: warning: Cycles printed no final 'Finished' time; using the render call's",
              flush=True)
        render_time = call
    tracing = "" if trace_start is None else f", path tracing alone {render_time - trace_start:.3f} s"
    print(f"cycles: render time {render_time:.3f} s (Cycles' own clock{tracing}), render call {call:.3f} s, "
          f"{paths / render_time / 1e6:.3f} Mpaths/s ({args.width}x{args.height}, {args.spp} spp, "
          f"{args.threads} threads, {args.bounces} bounces)", flush=True)


main()
