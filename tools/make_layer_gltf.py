#!/usr/bin/env python3
"""Writes shadelab's glTF material-layer test grids into one folder, in the spirit of Khronos's ClearCoatTest,
SheenTest, IORTestGrid and AnisotropyDiscTest (Debian ships only the first): each a single .gltf file with its
buffer embedded as a data: URI, one UV sphere instanced on a grid of nodes, one material per sphere whose name
states its values, a directional KHR_lights_punctual light and a camera that frames the grid.
    clearcoat_grid.gltf   KHR_materials_clearcoat: clearcoatFactor 0, 0.25, 0.5, 0.75, 1 (columns) x
                          clearcoatRoughnessFactor 0, 0.25, 0.5, 1 (rows), over a red paint of roughness 0.6
    sheen_grid.gltf       KHR_materials_sheen: sheenRoughnessFactor 0, 0.25, 0.5, 0.75, 1 (columns) x
                          sheenColorFactor black (none), white, orange, blue (rows), over a dark blue cloth
    ior_grid.gltf         KHR_materials_ior: ior 1.0, 1.2, 1.33, 1.5, 1.8, 2.4 (columns) x roughness 0.1, 0.35,
                          0.7 (rows), a dark dielectric
    specular_grid.gltf    KHR_materials_specular: specularFactor 0, 0.25, 0.5, 0.75, 1 (columns) x
                          specularColorFactor white, red, 2x white (rows), at ior 1.5
    anisotropy_grid.gltf  KHR_materials_anisotropy: anisotropyStrength 0, 0.25, 0.5, 0.75, 1 (columns) x
                          anisotropyRotation 0, pi/4, pi/2 (rows), a steel of roughness 0.35
    transmission_grid.gltf  KHR_materials_transmission: transmissionFactor 0, 0.25, 0.5, 0.75, 1 (columns) x
                          roughness 0, 0.2, 0.5 (rows), thin walls of a pale blue
    attenuation_grid.gltf KHR_materials_volume: attenuationDistance 0.1, 0.3, 1, 3 and none (columns) x
                          attenuationColor orange, green, blue (rows), fully transmitting balls of index 1.5 and
                          roughness 0.1 as thick as they are wide (0.8)
Grid rows run down the image (+y up, the first row on top), columns left to right. Deterministic: the same bytes
on every run (tests/CMakeLists.txt's layer_assets_reproducible compares them with assets/models/layers/).
Regenerate with
    /usr/bin/python3 tools/make_layer_gltf.py --output assets/models/layers
"""
import argparse, base64, json, math, os

import numpy as np

from make_sphere_grid_glb import sphere as uv_sphere

SLICES, STACKS, RADIUS, SPACING = 24, 13, 0.4, 1.0


def sphere():
    """The grid's UV sphere (make_sphere_grid_glb.py's, smaller, with texture coordinates for anisotropy's
    tangents), with 16-bit indices."""
    pos, nrm, idx, uv = uv_sphere(SLICES, STACKS, RADIUS, uvs=True)
    return pos, nrm, idx.astype("<u2"), uv


def grid(title, rows, columns, material):
    """The document for a grid: `material(row, column)` gives each sphere's glTF material (its name included)."""
    pos, nrm, idx, uv = sphere()
    blob = pos.tobytes() + nrm.tobytes() + uv.tobytes() + idx.tobytes()
    extensions = set()
    materials, meshes, nodes = [], [], []
    for r in range(len(rows)):
        for c in range(len(columns)):
            m = material(rows[r], columns[c])
            extensions.update(m.get("extensions", {}).keys())
            materials.append(m)
            meshes.append({"name": m["name"], "primitives": [
                {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3,
                 "material": len(materials) - 1}]})
            x = (c - 0.5 * (len(columns) - 1)) * SPACING
            y = (0.5 * (len(rows) - 1) - r) * SPACING
            nodes.append({"name": m["name"], "mesh": len(meshes) - 1, "translation": [x, y, 0.0]})
    # A camera on +z that frames the grid (45° vertical field, the wider side fitted), and a light from the
    # upper left front.
    half = 0.5 * SPACING * max(len(rows), len(columns) * 9 / 16) + RADIUS
    nodes.append({"name": "camera", "camera": 0, "translation": [0.0, 0.0, round(half / math.tan(math.radians(22.5)) + 0.5, 3)]})
    light_rotation = [-0.3396, -0.283, 0.0, 0.897]  # the light's -z turned toward (0.5, -0.6, -0.6)
    nodes.append({"name": "key light", "rotation": light_rotation,
                  "extensions": {"KHR_lights_punctual": {"light": 0}}})
    doc = {
        "asset": {"version": "2.0", "generator": "shadelab tools/make_layer_gltf.py", "extras": {"title": title}},
        "extensionsUsed": sorted(extensions | {"KHR_lights_punctual"}),
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "color": [1.0, 0.97, 0.92],
                                                            "intensity": 2.5}]}},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "cameras": [{"type": "perspective", "perspective": {"yfov": math.radians(45.0), "znear": 0.1,
                                                            "aspectRatio": 16 / 9}}],
        "meshes": meshes,
        "materials": materials,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": pos.nbytes, "target": 34962},
            {"buffer": 0, "byteOffset": pos.nbytes, "byteLength": nrm.nbytes, "target": 34962},
            {"buffer": 0, "byteOffset": pos.nbytes + nrm.nbytes, "byteLength": uv.nbytes, "target": 34962},
            {"buffer": 0, "byteOffset": pos.nbytes + nrm.nbytes + uv.nbytes, "byteLength": idx.nbytes,
             "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(pos), "type": "VEC3",
             "min": [-RADIUS, -RADIUS, -RADIUS], "max": [RADIUS, RADIUS, RADIUS]},
            {"bufferView": 1, "componentType": 5126, "count": len(nrm), "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": len(uv), "type": "VEC2"},
            {"bufferView": 3, "componentType": 5123, "count": len(idx), "type": "SCALAR"},
        ],
    }
    return doc


def pbr(base, roughness, metallic=0.0):
    return {"baseColorFactor": list(base) + [1.0], "metallicFactor": metallic, "roughnessFactor": roughness}


def clearcoat_grid():
    def material(rough, factor):
        return {"name": f"clearcoat {factor} roughness {rough}", "pbrMetallicRoughness": pbr((0.6, 0.05, 0.04), 0.6),
                "extensions": {"KHR_materials_clearcoat": {"clearcoatFactor": factor,
                                                           "clearcoatRoughnessFactor": rough}}}
    return grid("KHR_materials_clearcoat: factor x roughness", [0.0, 0.25, 0.5, 1.0], [0.0, 0.25, 0.5, 0.75, 1.0],
                material)


def sheen_grid():
    colours = [("none", (0.0, 0.0, 0.0)), ("white", (1.0, 1.0, 1.0)), ("orange", (1.0, 0.5, 0.1)),
               ("blue", (0.2, 0.4, 1.0))]

    def material(colour, rough):
        name, rgb = colour
        return {"name": f"sheen {name} roughness {rough}", "pbrMetallicRoughness": pbr((0.04, 0.05, 0.22), 0.8),
                "extensions": {"KHR_materials_sheen": {"sheenColorFactor": list(rgb), "sheenRoughnessFactor": rough}}}
    return grid("KHR_materials_sheen: colour x roughness", colours, [0.0, 0.25, 0.5, 0.75, 1.0], material)


def ior_grid():
    def material(rough, ior):
        return {"name": f"ior {ior} roughness {rough}", "pbrMetallicRoughness": pbr((0.05, 0.05, 0.06), rough),
                "extensions": {"KHR_materials_ior": {"ior": ior}}}
    return grid("KHR_materials_ior: index x roughness", [0.1, 0.35, 0.7], [1.0, 1.2, 1.33, 1.5, 1.8, 2.4], material)


def specular_grid():
    colours = [("white", (1.0, 1.0, 1.0)), ("red", (1.0, 0.2, 0.2)), ("2x white", (2.0, 2.0, 2.0))]

    def material(colour, factor):
        name, rgb = colour
        return {"name": f"specular {factor} colour {name}", "pbrMetallicRoughness": pbr((0.1, 0.2, 0.5), 0.3),
                "extensions": {"KHR_materials_specular": {"specularFactor": factor, "specularColorFactor": list(rgb)}}}
    return grid("KHR_materials_specular: factor x colour", colours, [0.0, 0.25, 0.5, 0.75, 1.0], material)


def anisotropy_grid():
    def material(rotation, strength):
        name, angle = rotation
        return {"name": f"anisotropy {strength} rotation {name}",
                "pbrMetallicRoughness": pbr((0.8, 0.8, 0.82), 0.35, metallic=1.0),
                "extensions": {"KHR_materials_anisotropy": {"anisotropyStrength": strength,
                                                            "anisotropyRotation": angle}}}
    return grid("KHR_materials_anisotropy: strength x rotation", [("0", 0.0), ("pi/4", round(math.pi / 4, 6)),
                                                                   ("pi/2", round(math.pi / 2, 6))],
                [0.0, 0.25, 0.5, 0.75, 1.0], material)


def transmission_grid():
    def material(rough, factor):
        return {"name": f"transmission {factor} roughness {rough}", "pbrMetallicRoughness": pbr((0.8, 0.9, 1.0), rough),
                "extensions": {"KHR_materials_transmission": {"transmissionFactor": factor}}}
    return grid("KHR_materials_transmission: factor x roughness", [0.0, 0.2, 0.5], [0.0, 0.25, 0.5, 0.75, 1.0],
                material)


def attenuation_grid():
    colours = [("orange", (1.0, 0.5, 0.1)), ("green", (0.3, 0.9, 0.4)), ("blue", (0.2, 0.4, 1.0))]

    def material(colour, distance):
        name, rgb = colour
        volume = {"thicknessFactor": 2 * RADIUS, "attenuationColor": list(rgb)}
        if distance is not None:
            volume["attenuationDistance"] = distance
        return {"name": f"attenuation {name} distance {distance if distance is not None else 'none'}",
                "pbrMetallicRoughness": pbr((1.0, 1.0, 1.0), 0.1),
                "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0},
                               "KHR_materials_volume": volume}}
    return grid("KHR_materials_volume: attenuation distance x colour", colours, [0.1, 0.3, 1.0, 3.0, None], material)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--output", required=True, help="folder to write the grids into (created)")
    args = ap.parse_args()
    os.makedirs(args.output, exist_ok=True)
    for name, doc in [("clearcoat_grid", clearcoat_grid()), ("sheen_grid", sheen_grid()), ("ior_grid", ior_grid()),
                      ("specular_grid", specular_grid()), ("anisotropy_grid", anisotropy_grid()),
                      ("transmission_grid", transmission_grid()), ("attenuation_grid", attenuation_grid())]:
        path = os.path.join(args.output, name + ".gltf")
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            json.dump(doc, f, indent=1, sort_keys=True)
            f.write("\n")
        os.replace(tmp, path)


if __name__ == "__main__":
    main()
