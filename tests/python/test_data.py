"""shadelab.data: the shipped scenes, models and sky inside the package, usable from any folder.

The build tree's package (src/python/CMakeLists.txt's copies) and what `pip install .` ships (setup.py's
asset_files) hold the same files, byte for byte the repository's assets/; a scene loaded by name renders from a
folder where the repository's relative paths do not resolve."""

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest

import shadelab
import shadelab.data


def setup_py_asset_files(source_dir):
    """setup.py's list of the files it ships, taken out of the file (importing setup.py would run setup())."""
    tree = ast.parse((source_dir / "setup.py").read_text())
    wanted = [n for n in tree.body if (isinstance(n, ast.FunctionDef) and n.name == "asset_files")
              or (isinstance(n, ast.Assign) and any(getattr(t, "id", "") == "ASSET_PATTERNS" for t in n.targets))]
    assert len(wanted) == 2, "setup.py has no ASSET_PATTERNS and asset_files()"
    scope = {"ROOT": source_dir}
    exec(compile(ast.Module(body=wanted, type_ignores=[]), "setup.py", "exec"), scope)
    return [str(p) for p in scope["asset_files"]()]


def package_files():
    root = shadelab.data.folder()
    return sorted(str(p.relative_to(root)) for p in root.rglob("*") if p.is_file())


def test_scenes_are_the_repositorys(source_dir):
    expected = sorted(p.stem for p in (source_dir / "assets" / "scenes").glob("*.json"))
    assert shadelab.data.scenes() == expected
    assert "default" in expected and "torus" in expected and "pbr-sky" in expected
    # Negative control: a scene list missing one, or with one more, is not equal.
    assert shadelab.data.scenes() != expected[1:] and shadelab.data.scenes() != expected + ["extra"]


def test_package_holds_what_setup_py_ships_byte_for_byte(source_dir):
    shipped = setup_py_asset_files(source_dir)
    # What the scenes reference is among them: the torus model and the sky.
    assert {"models/torus.gltf", "environments/sky.hdr", "scenes/default.json"} <= set(shipped)
    assert package_files() == shipped
    root = shadelab.data.folder()
    for relative in shipped:
        assert (root / relative).read_bytes() == (source_dir / "assets" / relative).read_bytes(), relative
    # Negative control: the comparison notices a file that differs.
    assert (root / "scenes" / "default.json").read_bytes() != (source_dir / "assets" / "scenes" / "torus.json").read_bytes()


def test_path_is_the_scene_file(source_dir):
    path = shadelab.data.path("default")
    assert isinstance(path, Path) and path.is_absolute() and path.name == "default.json"
    assert path.read_bytes() == (source_dir / "assets" / "scenes" / "default.json").read_bytes()


def test_scene_loads_a_new_scene_each_call():
    a = shadelab.data.scene("default")
    b = shadelab.data.scene("default")
    a.model = "blinn-phong"
    assert isinstance(a, shadelab.Scene) and b.model == "phong"


@pytest.mark.parametrize("name", ["defualt", "default.json", "", "../scenes/default", "scenes/default"])
def test_unknown_name_lists_the_names(name):
    with pytest.raises(ValueError) as caught:
        shadelab.data.path(name)
    message = str(caught.value)
    assert "\n" not in message and repr(name) in message
    assert "the scenes are " + ", ".join(shadelab.data.scenes()) in message
    with pytest.raises(ValueError):
        shadelab.data.scene(name)
    if name == "default.json":
        assert "without .json: 'default'" in message


def test_known_name_is_no_error():
    # The negative control of the test above: the names it lists are accepted.
    for name in shadelab.data.scenes():
        assert shadelab.data.path(name).is_file()


def test_name_of_another_type_is_a_type_error():
    with pytest.raises(TypeError, match=r"^shadelab.data: a scene name must be a string, got int$"):
        shadelab.data.path(3)


OUTSIDE = r"""
import sys
import shadelab
out = sys.argv[1]
torus = shadelab.data.scene("torus")          # a glTF mesh by a relative path: ../models/torus.gltf
assert torus.triangle_count > 0, torus.triangle_count
shadelab.render(torus, (64, 36)).save(out + "/torus.png")
sky = shadelab.data.scene("pbr-sky")          # the sky by a relative path: ../environments/sky.hdr
shadelab.render(sky, (64, 36), renderer="trace").save(out + "/pbr-sky.png")
try:
    shadelab.Scene.load("assets/scenes/torus.json")   # the repository's relative path: not from here
except (OSError, ValueError) as e:
    print("repository path refused:", e)
print("ok")
"""


def test_runs_from_another_folder(tmp_path, source_dir, binary):
    work = tmp_path / "elsewhere"
    work.mkdir()
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p)
    p = subprocess.run([sys.executable, "-c", OUTSIDE, str(tmp_path)], cwd=work, capture_output=True, text=True,
                       env=env)
    assert p.returncode == 0, p.stderr
    assert p.stdout.endswith("ok\n")
    # The negative control: from that folder the repository's relative path does not resolve.
    assert "repository path refused:" in p.stdout
    # The renders are the binary's of the repository's files: the same scenes.
    for name, renderer in (("torus", "raster"), ("pbr-sky", "trace")):
        ref = tmp_path / f"{name}-binary.png"
        subprocess.run([str(binary), "render", str(source_dir / "assets" / "scenes" / f"{name}.json"), "-o", str(ref),
                        "--size", "64x36", "--renderer", renderer], check=True, capture_output=True)
        assert (tmp_path / f"{name}.png").read_bytes() == ref.read_bytes(), name
