"""A small program over shadelab's public API, annotated for `mypy --strict` (test_typed_api.py checks it, then
runs it): scenes and their edits, every render keyword, a Renderer, images, compare, the probe, the lighting
maths, the plots and the shadelab.typing aliases.

    python3 api_example.py SCENE.json OUT_DIR
"""

import sys
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

import shadelab
import shadelab.data
import shadelab.lighting
import shadelab.plots
from shadelab.typing import MemorySize, RendererName, SceneLike, Size, ViewTransformName


def render_all(scenes: list[SceneLike], size: Size, renderer: RendererName) -> list[shadelab.Image]:
    with shadelab.Renderer(backend="auto") as r:
        images = [r.render(s, size, renderer=renderer, spp=1, threads=1) for s in scenes]
        assert not r.busy and r.info["gl_version"]
    return images


def main(scene_path: str, out_dir: Path) -> int:
    scene = shadelab.Scene.load(scene_path)
    scene.model = "blinn-phong"
    scene.objects[0].material.s = 64
    first_light: dict[str, object] = scene.lights[0].to_dict()
    edited = shadelab.Scene.from_dict(scene.to_dict(), base_dir=scene.base_dir)
    assert edited == scene and edited.triangle_count == scene.triangle_count and "color" in first_light
    names: list[str] = shadelab.data.scenes()
    shipped: shadelab.Scene = shadelab.data.scene(names[0])
    assert shadelab.data.path(names[0]).is_file() and shadelab.data.folder().is_dir() and len(shipped.objects) > 0

    raster = shadelab.render(scene, (32, 24), coverage=True)
    traced = shadelab.render(scene, "32x24", renderer="trace", spp=4, encoding="srgb", depth=1, threads=2,
                             coverage=True)
    path = scene.render((32, 24), renderer="path", spp=2, encoding="linear", depth=None, threads=0,
                        max_memory="1G", seed=3)
    transform: ViewTransformName = "filmic"
    shown = shadelab.render(scene, (8, 6), exposure=-1.5, view_transform=transform)
    assert scene.render((8, 6), exposure=2, view_transform="standard").size == shown.size
    limit: MemorySize = 1 << 30
    assert shadelab.render(scene, (8, 6), renderer="trace", max_memory=limit).size == (8, 6)
    floats: NDArray[np.float32] = np.asarray(raster, dtype=np.float32)
    pixels: NDArray[np.uint8] = traced.to_uint8()
    display_ready: NDArray[np.float32] = shown.to_srgb()
    assert display_ready.shape == shown.shape and shown.exposure == -1.5 and shown.view_transform == "filmic"
    width, height = raster.size
    assert floats.shape == (height, width, 3) and pixels.shape == traced.shape and path.encoding == "linear"
    ids = raster.coverage
    if ids is not None:
        assert int(ids.max()) >= 1

    report: shadelab.CompareReport = shadelab.compare(raster, traced, gates={"hard_max": 255}, gain=8)
    heat, report_json = report.save(out_dir / "raster-vs-trace")
    reasons: list[str] = report.reasons
    print(report.summary, heat, report_json, report.passed, reasons, sep="\n")
    again = shadelab.Image.open(heat)
    same = shadelab.Image.from_array(again.to_uint8())
    assert same.to_png() == again.to_png()

    hit = shadelab.probe(scene, (16, 12), size=(32, 24))
    print(sorted(hit))

    N, V = np.array([0.0, 0.0, 1.0]), np.array([0.0, 0.0, 1.0])
    L = shadelab.lighting.normalize([0.3, 0.0, 1.0])
    lobe = shadelab.lighting.phong(N, L, V, s=32)
    rgb = shadelab.lighting.shade(N, L, V, md=(0.8, 0.1, 0.1), model="pbr")
    angles, values = shadelab.plots.lobe("blinn-phong", s=16)
    plot = shadelab.plots.lobe_image("phong", s=8, size=64)
    print(float(lobe), rgb.tolist(), angles.shape, values.shape, plot.size)

    for image in render_all([scene, scene_path, scene.to_dict()], (16, 12), "raster"):
        image.save(out_dir / f"{image.source}-{image.width}.png")
    print(shadelab.__version__, shadelab.build_info["build_type"], shadelab.default_gates["threshold"])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], Path(sys.argv[2])))
