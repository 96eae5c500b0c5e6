"""shadelab.render is byte-identical to `shadelab render`'s PNG for every shipped scene, with both renderers, and
after a from_dict(to_dict()) round trip; one Renderer and two Renderers sharing the context keep it so."""

import numpy as np
import pytest

import shadelab
from conftest import SCENES, run_binary

SIZE = (160, 96)


def binary_png(binary, out_dir, scene, renderer, *flags):
    path = out_dir / f"binary-{renderer}.png"
    run_binary(binary, "render", scene, "-o", path, "--size", f"{SIZE[0]}x{SIZE[1]}", "--renderer", renderer, *flags)
    return path.read_bytes()


@pytest.mark.parametrize("renderer", ["raster", "trace"])
@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_render_equals_the_binary(path, renderer, binary, out_dir):
    expected = binary_png(binary, out_dir, path, renderer)
    image = shadelab.render(path, SIZE, renderer=renderer)
    image.save(out_dir / f"python-{renderer}.png")
    assert image.to_png() == expected, f"see {out_dir}"
    scene = shadelab.Scene.load(path)
    again = shadelab.Scene.from_dict(scene.to_dict(), base_dir=scene.base_dir)
    assert shadelab.render(again, SIZE, renderer=renderer).to_png() == expected


@pytest.mark.parametrize("renderer", ["raster", "trace"])
def test_options_equal_the_binary_flags(renderer, binary, out_dir, source_dir):
    scene = source_dir / "assets" / "scenes" / "default.json"
    expected = binary_png(binary, out_dir, scene, renderer, "--spp", "4", "--encoding", "linear")
    assert shadelab.render(scene, SIZE, renderer=renderer, spp=4, encoding="linear").to_png() == expected
    if renderer == "trace":
        expected = binary_png(binary, out_dir, scene, renderer, "--depth", "1", "--threads", "2")
        assert shadelab.render(scene, SIZE, renderer=renderer, depth=1, threads=2).to_png() == expected


@pytest.mark.parametrize("renderer", ["raster", "trace", "path"])
def test_display_equals_the_binary_flags_and_the_scene_field(renderer, binary, out_dir, source_dir):
    # exposure= and view_transform= are --exposure and --view-transform, byte for byte; a Scene's display is the
    # file's "display" field; the keywords override it; the linear floats are the same whatever the display.
    scene_path = source_dir / "assets" / "scenes" / "cornell.json"
    flags = ("--exposure", "-1.5", "--view-transform", "filmic", "--spp", "4")
    expected = binary_png(binary, out_dir, scene_path, renderer, *flags)
    image = shadelab.render(scene_path, SIZE, renderer=renderer, spp=4, exposure=-1.5, view_transform="filmic")
    image.save(out_dir / f"python-display-{renderer}.png")
    assert image.to_png() == expected, f"see {out_dir}"
    plain = shadelab.render(scene_path, SIZE, renderer=renderer, spp=4)
    assert plain.to_png() != expected, "negative control: the display changed no byte"
    assert (np.asarray(plain) == np.asarray(image)).all(), "the display must not touch the linear floats"
    scene = shadelab.Scene.load(scene_path)
    scene.display = {"exposure": -1.5, "viewTransform": "filmic"}
    assert scene.display.viewTransform == "filmic"
    assert shadelab.render(scene, SIZE, renderer=renderer, spp=4).to_png() == expected
    assert (shadelab.render(scene, SIZE, renderer=renderer, spp=4, exposure=0, view_transform="standard").to_png()
            == plain.to_png())


def test_display_keywords_are_refused_in_one_line(source_dir):
    scene = source_dir / "assets" / "scenes" / "default.json"
    with pytest.raises(ValueError, match=r"^exposure: must be in \[-16, 16\] stops, got 40$"):
        shadelab.render(scene, (8, 6), exposure=40)
    with pytest.raises(ValueError, match=r"^view_transform: unknown value 'aces'"):
        shadelab.render(scene, (8, 6), view_transform="aces")
    with pytest.raises(TypeError, match=r"^exposure: "):
        shadelab.render(scene, (8, 6), exposure="bright")
    s = shadelab.Scene.load(scene)
    with pytest.raises(shadelab.InputError, match=r"display.exposure: must be in \[-16, 16\] stops, got 99"):
        s.display = {"exposure": 99}


def test_path_tracer_equals_the_binary(binary, out_dir, source_dir):
    # The path tracer is deterministic: any sample count (not only squares), any thread count, the same bytes.
    scene = source_dir / "assets" / "scenes" / "local-vs-global.json"
    expected = binary_png(binary, out_dir, scene, "path", "--spp", "3", "--depth", "2", "--threads", "1")
    image = shadelab.render(scene, SIZE, renderer="path", spp=3, depth=2, threads=2)
    image.save(out_dir / "python-path.png")
    assert image.to_png() == expected, f"see {out_dir}"


def test_edits_equal_the_binary_on_the_edited_file(binary, out_dir, source_dir):
    scene = shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")
    scene.model = "blinn-phong"
    scene.objects[0].material.s = 200
    scene.lights[0].color = [1.0, 0.2, 0.2]
    path = out_dir / "edited.json"
    scene.save(path)
    assert shadelab.render(scene, SIZE).to_png() == binary_png(binary, out_dir, path, "raster")


def test_renderers_share_the_context_without_crosstalk(binary, out_dir):
    expected = {p: binary_png(binary, out_dir, p, "raster") for p in SCENES[:2]}
    a, b = shadelab.Renderer(), shadelab.Renderer()
    for _ in range(2):
        for p in SCENES[:2]:
            assert a.render(p, SIZE).to_png() == expected[p]
            assert b.render(p, SIZE).to_png() == expected[p]
    a.close()
    assert b.render(SCENES[0], SIZE).to_png() == expected[SCENES[0]]
    assert a.render(SCENES[1], SIZE).to_png() == expected[SCENES[1]]  # closed: starts again
    b.close()
    a.close()


def test_denoise_equals_the_binary_flag(binary, out_dir, source_dir):
    # denoise= is --denoise, byte for byte; the denoised floats differ from the raw estimate (negative control),
    # and another renderer refuses it in the request's words.
    scene = source_dir / "assets" / "scenes" / "cornell.json"
    expected = binary_png(binary, out_dir, scene, "path", "--spp", "4", "--denoise")
    image = shadelab.render(scene, SIZE, renderer="path", spp=4, denoise=True)
    image.save(out_dir / "python-denoised.png")
    assert image.to_png() == expected, f"see {out_dir}"
    raw = shadelab.render(scene, SIZE, renderer="path", spp=4)
    assert raw.to_png() != expected, "negative control: denoise changed no byte"
    assert np.abs(np.asarray(raw) - np.asarray(image)).mean() > 1e-3
    with pytest.raises(ValueError, match="denoise: is for the path tracer"):
        shadelab.render(scene, SIZE, renderer="raster", denoise=True)
