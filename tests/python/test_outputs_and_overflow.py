"""The Python package keeps two of the command line's promises: no image goes black in silence (a render
with pixels that have no finite value raises a ShadelabWarning with the command line's words), and no output
replaces a file a live scene reads or escapes through a device stem. Each check has its negative control."""

import gc
import os
import shutil
import warnings

import pytest

import shadelab

from conftest import SOURCE_DIR

SCENE = {
    "camera": {"position": [0, 0, 6], "target": [0, 0, 0]},
    "lights": [{"type": "point", "position": [2, 3, 4], "color": 1}],
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}],
}


def _nan_shaders(out_dir):
    """A copy of shaders/ whose sphere fragment shader writes NaN: the scene bounds leave no file-borne
    overflow to show, so the renderer is made to produce one."""
    shaders = out_dir / "shaders"
    shutil.copytree(SOURCE_DIR / "shaders", shaders, dirs_exist_ok=True)
    frag = (shaders / "sphere.frag").read_text()
    line = "o_color = vec4(I, 1.0f);"
    assert line in frag, "sphere.frag changed; update this test"
    (shaders / "sphere.frag").write_text(frag.replace(line, "o_color = vec4(I * sqrt(-1.0f - dot(I, I)), 1.0f);"))
    return shaders


def test_a_render_with_non_finite_pixels_warns_in_the_binarys_words(out_dir, monkeypatch):
    monkeypatch.setenv("SHADELAB_SHADER_DIR", str(_nan_shaders(out_dir)))
    with shadelab.Renderer() as r:
        with pytest.warns(shadelab.ShadelabWarning, match=r"raster: \d+ of 1200 pixels .* have no finite value"):
            image = r.render(shadelab.Scene.from_dict(SCENE), (40, 30))
    assert image.non_finite_pixels > 0


@pytest.mark.parametrize("renderer", ["raster", "trace", "path"])
def test_negative_control_an_ordinary_render_does_not_warn(renderer):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        image = shadelab.render(shadelab.Scene.from_dict(SCENE), (40, 30), renderer=renderer)
    assert image.non_finite_pixels == 0


def test_outputs_never_replace_a_live_scenes_files(out_dir):
    scene_path = out_dir / "scene.json"
    shadelab.Scene.from_dict(SCENE).save(scene_path)
    before = scene_path.read_bytes()
    scene = shadelab.Scene.load(scene_path)
    image = shadelab.render(scene, (8, 6))
    with pytest.raises(OSError, match="refusing to overwrite an input"):  # Image.save's errors are OSErrors
        image.save(scene_path)
    with pytest.raises(shadelab.InputError, match="refusing to overwrite an input"):
        scene.save(scene_path)
    with pytest.raises(shadelab.InputError, match="refusing to overwrite an input"):
        shadelab._shadelab._write_file(os.fspath(scene_path), b"{}")
    assert scene_path.read_bytes() == before
    # Negative control: once no scene read from the file is alive, it is an ordinary file again.
    del scene
    gc.collect()
    image.save(scene_path)
    assert scene_path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_compare_report_names_do_not_escape_through_a_device(out_dir):
    image = shadelab.render(shadelab.Scene.from_dict(SCENE), (8, 6))
    report = shadelab.compare(image, image)
    with pytest.raises(shadelab.InputError, match="not a file stem"):
        report.save("/dev/null")
    assert not os.path.exists("/dev/null_heat.png") and not os.path.exists("/dev/null_report.json")
    # Negative control: an ordinary stem writes both files.
    heat, json_path = report.save(out_dir / "ok")
    assert os.path.exists(heat) and os.path.exists(json_path)


def test_saving_into_a_missing_folder_creates_it_as_the_command_line_does(tmp_path):
    # The README's first snippet saves to out/python.png in a fresh clone, where out/ does not exist yet.
    scene = shadelab.Scene.from_dict(SCENE)
    image = shadelab.render(scene, (16, 12))
    image.save(tmp_path / "out" / "python.png")
    image.save(tmp_path / "out" / "deeper" / "linear.exr")
    scene.save(tmp_path / "scenes" / "copy.json")
    assert (tmp_path / "out" / "python.png").read_bytes() == image.to_png()
    assert (tmp_path / "out" / "deeper" / "linear.exr").stat().st_size > 0
    assert shadelab.Scene.load(tmp_path / "scenes" / "copy.json").to_dict() == scene.to_dict()
    # The negative control: a folder that cannot be made (its parent is a file) is one OSError naming the path,
    # and nothing is written.
    (tmp_path / "file").write_text("x")
    with pytest.raises(OSError, match=r"file/sub/out\.png: cannot create its folder .*file/sub"):
        image.save(tmp_path / "file" / "sub" / "out.png")
    assert (tmp_path / "file").read_text() == "x"
