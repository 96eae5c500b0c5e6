"""Scenes: from_dict(to_dict()) is exact on every shipped scene, errors are the scene file's (ValueError naming
the JSON path), attribute edits go through the scene reader and its name tables."""

import json
import pickle
import warnings

import pytest

import shadelab
from conftest import SCENES


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_round_trip_is_exact(path):
    scene = shadelab.Scene.load(path)
    again = shadelab.Scene.from_dict(scene.to_dict(), base_dir=scene.base_dir)
    assert again.to_dict() == scene.to_dict()
    # The scene file text both write, float for float.
    assert again._handle.to_json() == scene._handle.to_json()
    assert again.triangle_count == scene.triangle_count


def _scene_dict(**changes):
    d = {
        "camera": {"position": [0, 1, 5], "target": [0, 0, 0]},
        "lights": [{"type": "point", "position": [0, 4, 2]}, {"type": "directional", "direction": [0, -1, 0]},
                   {"type": "point", "position": [1, 1, 1], "color": [1, 1, 1]}],
        "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"s": 32}},
                    {"type": "plane", "normal": [0, 1, 0], "offset": -1}],
    }
    d.update(changes)
    return d


def _with(path, value):
    d = _scene_dict()
    node = d
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return d


# (document, the message: JSON path and reason, exactly as a scene file's error reads after "<file>: ")
ERROR_CASES = [
    (_with(["lights", 2, "color"], [1, 1]), "lights[2].color: expected 3 numbers, got 2"),
    (_scene_dict(model="toon"), "model: unknown shading model 'toon'; expected phong, blinn-phong, pbr or disney"),
    (_with(["objects", 0, "material", "s"], -1), "objects[0].material.s: must be in [0, 10000], got -1"),
    (_with(["lights", 0, "type"], "area"),
     "lights[0].type: unknown light type 'area'; expected point, directional or spot"),
    (_with(["lights", 0, "type"], "spot"), "lights[0].direction: missing required field"),
    (_with(["lights", 0], {"type": "spot", "position": [0, 4, 2], "direction": [0, -1, 0], "innerConeAngle": 0.6,
                          "outerConeAngle": 0.5}),
     "lights[0].innerConeAngle: must not exceed outerConeAngle (0.500000)"),
    (_with(["lights", 0], {"type": "spot", "position": [0, 4, 2], "direction": [0, -1, 0], "outerConeAngle": 2}),
     "lights[0].outerConeAngle: must be in [0, 1.5708], got 2"),
    (_with(["lights", 0], {"type": "spot", "position": [0, 4, 2], "direction": [0, -1, 0], "range": -1}),
     "lights[0].range: must be > 0, got -1"),
    (_with(["objects", 0, "radius"], 0), "objects[0].radius: must be > 0, got 0"),
    (_with(["camera", "fovY"], 180), "camera.fovY: must be in (0, 180), got 180"),
    (_scene_dict(terms={"shadows": 1}), "terms.shadows: expected true or false, got number"),
    (_scene_dict(maxDepth=2.5), "maxDepth: expected an integer, got 2.5"),
    (_with(["objects", 1, "type"], "cube"), "objects[1].type: unknown object type 'cube'; expected sphere, plane or mesh"),
    (_with(["lights", 1], {"type": "directional"}), "lights[1].direction: missing required field"),
    (_with(["objects", 0, "material", "md"], "red"),
     "objects[0].material.md: expected 3 numbers or one number, got string"),
]


@pytest.mark.parametrize("document,message", ERROR_CASES, ids=[m.split(":")[0] for _, m in ERROR_CASES])
def test_errors_name_the_json_path(document, message, out_dir):
    with pytest.raises(ValueError) as raised:
        shadelab.Scene.from_dict(document)
    assert isinstance(raised.value, shadelab.InputError)
    assert str(raised.value) == message
    # The scene file with the same content fails with the same words, after its name.
    path = out_dir / "scene.json"
    path.write_text(json.dumps(document))
    with pytest.raises(ValueError) as from_file:
        shadelab.Scene.load(path)
    assert str(from_file.value) == f"{path}: {message}"


def test_nan_is_refused_at_its_path():
    with pytest.raises(ValueError, match=r"^ambient: must be finite"):
        shadelab.Scene.from_dict(_scene_dict(ambient=float("nan")))
    with pytest.raises(ValueError, match=r"^objects\[0\]\.center\[1\]: cannot be written in a scene: object"):
        shadelab.Scene.from_dict(_with(["objects", 0, "center"], [0, object(), 0]))


def test_unknown_fields_warn_as_in_a_file():
    with pytest.warns(shadelab.ShadelabWarning, match=r"unknown field 'ligts' \(ignored\); did you mean 'lights'\?"):
        shadelab.Scene.from_dict(_scene_dict(ligts=[]))


@pytest.fixture
def scene(source_dir):
    return shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")


def test_attribute_edits(scene):
    scene.objects[0].material.s = 64
    assert scene.objects[0].material.s == 64.0
    assert scene.to_dict()["objects"][0]["material"]["s"] == 64.0
    scene.model = "blinn"  # an alias in the name table; read back by its canonical name
    assert scene.model == "blinn-phong"
    scene.terms.shadows = False
    assert scene.terms.shadows is False and scene.terms.diffuse is True
    n = len(scene.lights)
    scene.lights.append({"type": "point", "position": [0, 4, 2], "color": [1, 0.5, 0.25]})
    assert len(scene.lights) == n + 1
    assert scene.lights[-1].color == (1.0, 0.5, 0.25)
    assert scene.lights[-1].attenuation == (1.0, 0.0, 0.0)  # the reader's default
    del scene.lights[0]
    assert len(scene.lights) == n
    scene.camera.fovY = 30
    scene.objects[1].material.md = [0.1, 0.2, 0.3]
    assert scene.objects[1].material.md == (0.1, 0.2, 0.3)
    scene.lights[0] = {"type": "directional", "direction": [0, 0, -2]}
    assert scene.lights[0].direction == (0.0, 0.0, -1.0)  # normalised as on load


def test_spot_lights_edit_and_render_as_in_a_file(scene):
    scene.lights.clear()
    scene.lights.append({"type": "spot", "position": [0, 4, 1], "direction": [0, -1, 0], "innerConeAngle": 0.2,
                         "outerConeAngle": 0.4, "range": 9})
    spot = scene.lights[0]
    assert spot.type == "spot" and spot.innerConeAngle == pytest.approx(0.2) and spot.range == 9.0
    scene.terms.shadows = False
    scene.terms.reflections = False
    narrow = shadelab.render(scene, (96, 64), renderer="trace")
    spot.outerConeAngle = 0.8
    assert scene.to_dict()["lights"][0]["outerConeAngle"] == pytest.approx(0.8)
    wide = shadelab.render(scene, (96, 64), renderer="trace")
    assert not shadelab.compare(narrow, wide).passed  # a wider cone lights more of the scene
    report = shadelab.compare(shadelab.render(scene, (96, 64), coverage=True),
                              shadelab.render(scene, (96, 64), renderer="trace", depth=1, coverage=True))
    assert report.passed, report.summary
    with pytest.raises(ValueError, match=r"^lights\[0\]\.innerConeAngle: must not exceed outerConeAngle"):
        spot.innerConeAngle = 1.0
    assert spot.innerConeAngle == pytest.approx(0.2)  # a rejected edit leaves the scene as it was


def test_numpy_values_are_accepted(scene):
    np = pytest.importorskip("numpy")
    scene.objects[0].material.md = np.array([0.5, 0.25, 0.125])
    scene.objects[0].material.s = np.float32(8)
    assert scene.objects[0].material.md == (0.5, 0.25, 0.125)
    assert scene.objects[0].material.s == 8.0


def test_rejected_edits_leave_the_scene_unchanged(scene):
    before = scene.to_dict()
    with pytest.raises(ValueError, match=r"^lights\[1\]\.color: expected 3 numbers, got 2$"):
        scene.lights[1].color = [1, 2]
    with pytest.raises(ValueError, match=r"^model: unknown shading model 'toon'"):
        scene.model = "toon"
    with pytest.raises(ValueError, match=r"^lights\[2\]\.type: unknown light type 'area'"):
        scene.lights.append({"type": "area"})
    with pytest.raises(AttributeError, match=r"^objects\[0\]\.material: unknown field 'shininess'$"):
        scene.objects[0].material.shininess = 3
    with pytest.raises(AttributeError, match=r"objects\[0\]\.material has no field 's2'"):
        scene.objects[0].material.s2
    with pytest.raises(IndexError):
        scene.objects[99]
    assert scene.to_dict() == before


def test_views_follow_the_scene(scene):
    light = scene.lights[1]
    scene.lights[1].color = [0.5, 0.5, 0.5]
    assert light.color == (0.5, 0.5, 0.5)
    assert "color" in dir(light)


def test_mesh_edits_keep_geometry(source_dir):
    scene = shadelab.Scene.load(source_dir / "assets" / "scenes" / "torus.json")
    triangles = scene.triangle_count
    assert triangles > 0
    mesh = next(o for o in scene.objects if o.type == "mesh")
    mesh.material.s = 8
    assert mesh.material.s == 8.0
    scene.objects[0].material.s = 16
    assert scene.triangle_count == triangles


def test_copy_and_pickle(scene):
    other = scene.copy()
    other.objects[0].material.s = 1
    assert scene.objects[0].material.s == 32.0
    again = pickle.loads(pickle.dumps(scene))
    assert again == scene and again.base_dir == scene.base_dir


def test_gltf_models_are_scenes(source_dir):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        scene = shadelab.Scene.load(source_dir / "assets" / "models" / "torus.gltf")
    assert scene.objects[0].type == "mesh" and len(scene.lights) == 2
    assert shadelab.Scene.from_dict(scene.to_dict()).triangle_count == scene.triangle_count


def test_load_errors_name_the_file(out_dir):
    with pytest.raises(ValueError, match=r"no such file"):
        shadelab.Scene.load(out_dir / "missing.json")
    bad = out_dir / "bad.json"
    bad.write_text('{"lights": [}')
    with pytest.raises(ValueError, match=r"bad\.json: line 1, column 13"):
        shadelab.Scene.load(bad)


# -- the list views' pop, reverse and clear ----------------------------------------------------------------------

# Every list view the package has (scene._CONTAINERS), each in a scene with three entries or more.
@pytest.mark.parametrize("name,file", [("objects", "default.json"), ("lights", "three-lights.json")])
def test_pop_returns_the_removed_entry_as_a_copy_that_stays_valid(source_dir, name, file):
    scene = shadelab.Scene.load(source_dir / "assets" / "scenes" / file)
    view = getattr(scene, name)
    entries = view.to_list()
    assert len(entries) >= 3
    first = view.pop(0)
    assert first == entries[0] and view.to_list() == entries[1:]
    last = view.pop()
    assert last == entries[-1] and view.to_list() == entries[1:-1]
    view.pop(0)  # later edits leave the copies as they were
    scene.model = "blinn-phong"
    assert first == entries[0] and last == entries[-1]
    view.insert(0, first)  # and they go back in as entries
    assert view.to_list()[0] == entries[0]
    with pytest.raises(IndexError, match=rf"^{name}\[99\]: there are"):
        view.pop(99)


def test_the_pop_check_sees_the_views_moving(source_dir):
    # The negative control: MutableSequence's own pop, which the views inherited, returns a view by position:
    # after the removal it shows the next object, and the last one's raises as soon as it is used.
    from collections.abc import MutableSequence

    scene = shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")
    entries = scene.objects.to_list()
    moved = MutableSequence.pop(scene.objects, 0)
    assert moved != entries[0] and moved == entries[1]
    gone = MutableSequence.pop(scene.objects)
    with pytest.raises(IndexError):
        gone.to_dict()


def test_reverse_and_clear_edit_the_list_in_one_step(source_dir):
    scene = shadelab.Scene.load(source_dir / "assets" / "scenes" / "three-lights.json")
    lights = scene.lights.to_list()
    assert len(lights) == 3
    scene.lights.reverse()  # MutableSequence's reverse copied views it had already overwritten: a, b, a
    assert scene.lights.to_list() == lights[::-1]
    # (Objects keep the reader's order, spheres, planes, meshes, whatever order they are given in.)
    scene.lights.clear()
    scene.objects.clear()
    assert scene.lights.to_list() == [] and scene.objects.to_list() == []


def test_no_illumination_shows_the_unlit_colours(scene):
    for term in ("ambient", "diffuse", "specular", "shadows", "reflections"):
        setattr(scene.terms, term, False)
    raster = shadelab.render(scene, (96, 64), coverage=True)
    traced = shadelab.render(scene, (96, 64), renderer="trace", depth=1, coverage=True)
    report = shadelab.compare(raster, traced)
    assert report.passed, report.summary
    scene.terms.diffuse = True  # negative control: a lit render is not the unlit one
    assert not shadelab.compare(raster, shadelab.render(scene, (96, 64), renderer="trace")).passed
