#!/usr/bin/env python3
"""Writes a shadelab scene of spheres, planes and point lights as POV-Ray 3.7 scene text, for timing the two
tracers on the same work (bench/trace_vs_povray.sh). The same camera (POV-Ray's `angle` is horizontal: from
fovY and the aspect), the same objects, point lights with hard shadows, the Phong terms as POV-Ray's finish
(ambient ma / Ia, diffuse md, phong ms with phong_size s, reflection kr), a checker plane, the same
background, and max_trace_level = maxDepth + 1 (POV-Ray counts the primary ray). No antialiasing, as
`shadelab render --spp 1`. The pictures are close, not equal: the point is equal work per pixel.

    bench/scene_to_pov.py bench/spheres40.json OUT.pov WIDTH HEIGHT
"""
import json
import math
import sys


def rgb(v):
    if isinstance(v, (int, float)):
        v = [v, v, v]
    return "rgb <%g, %g, %g>" % tuple(v)


def vec(v):
    # shadelab's coordinates as they are: the camera's negative `right` makes POV-Ray's frame right-handed.
    return "<%g, %g, %g>" % (v[0], v[1], v[2])


def finish(m, ambient):
    ma = m.get("ma", [0.1] * 3)
    ma = [ma] * 3 if isinstance(ma, (int, float)) else ma
    a = [ma[i] * ambient[i] for i in range(3)]
    ms = m.get("ms", 0)
    ms = ms if isinstance(ms, (int, float)) else max(ms)
    kr = m.get("kr", 0)
    kr = kr if isinstance(kr, (int, float)) else max(kr)
    return "finish { ambient %s diffuse 1 phong %g phong_size %g reflection { %g } }" % (
        rgb(a), ms, m.get("s", 1), kr)


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: scene_to_pov.py SCENE.json OUT.pov WIDTH HEIGHT")
    scene = json.load(open(sys.argv[1]))
    width, height = int(sys.argv[3]), int(sys.argv[4])
    cam = scene["camera"]
    fov_y = math.radians(cam.get("fovY", 45))
    angle = math.degrees(2 * math.atan(math.tan(fov_y / 2) * width / height))
    ambient = scene.get("ambient", [0.1] * 3)
    ambient = [ambient] * 3 if isinstance(ambient, (int, float)) else ambient
    out = ["// written by bench/scene_to_pov.py from %s" % sys.argv[1],
           "global_settings { max_trace_level %d assumed_gamma 1 ambient_light rgb 1 }" % (scene.get("maxDepth", 5) + 1),
           "background { %s }" % rgb(scene.get("background", [0, 0, 0])),
           "camera { perspective location %s look_at %s up <0, 1, 0> right <-%g, 0, 0> angle %g }" % (
               vec(cam["position"]), vec(cam["target"]), width / height, angle)]
    for light in scene.get("lights", []):
        if light.get("type", "point") != "point":
            sys.exit("scene_to_pov: only point lights")
        out.append("light_source { %s color %s }" % (vec(light["position"]), rgb(light.get("color", [1, 1, 1]))))
    for o in scene["objects"]:
        m = o.get("material", {})
        md = m.get("md", [0.8] * 3)
        if o["type"] == "sphere":
            out.append("sphere { %s, %g pigment { %s } %s }" % (vec(o["center"]), o["radius"], rgb(md),
                                                                finish(m, ambient)))
        elif o["type"] == "plane":
            pigment = "color %s" % rgb(md)
            if "checker" in o:
                size = o["checker"].get("size", 1)
                pigment = "checker color %s color %s scale %g" % (rgb(md), rgb(o["checker"].get("md2", 0.1)), size)
            out.append("plane { %s, %g pigment { %s } %s }" % (vec(o["normal"]), o.get("offset", 0), pigment,
                                                              finish(m, ambient)))
        else:
            sys.exit("scene_to_pov: only spheres and planes, got %s" % o["type"])
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
