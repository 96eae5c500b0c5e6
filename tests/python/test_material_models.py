"""A material's own model and its given and derived fields, from Python: a sweep of s under pbr narrows the
highlight because roughness is derived from s (and the same through a scene file edited and reloaded), a field
given explicitly is never re-derived (the negative control), `material.derived` names what is derived, and a
material's "model" shades that object alone with it; the disney model's parameters edit in place like any field."""

import json

import numpy as np
import pytest

import shadelab

SIZE = (480, 270)
SWEEP = [1, 8, 64, 512, 2048]


def highlight_width(scene, object_id=1):
    """Pixels of the object brighter than half-way from its median to its peak: the highlight's area."""
    image = shadelab.render(scene, SIZE, coverage=True)
    lum = np.asarray(image)[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
    values = lum[np.asarray(image.coverage) == object_id]
    floor = float(np.median(values))
    return int((values - floor > 0.5 * (float(values.max()) - floor)).sum())


@pytest.fixture()
def pbr_default():
    scene = shadelab.data.scene("default")
    scene.model = "pbr"
    return scene


def test_a_sweep_of_s_under_pbr_narrows_the_highlight(pbr_default):
    assert pbr_default.objects[0].material.derived == ("baseColor", "metallic", "roughness")
    widths = []
    for s in SWEEP:
        pbr_default.objects[0].material.s = s
        widths.append(highlight_width(pbr_default))
    assert all(a > b for a, b in zip(widths, widths[1:])), widths
    assert pbr_default.objects[0].material.derived == ("baseColor", "metallic", "roughness")


def test_the_same_through_a_scene_file_edited_and_reloaded(pbr_default, tmp_path):
    widths = []
    for s in (8, 512):
        pbr_default.objects[0].material.s = s
        path = tmp_path / f"s{s}.json"
        pbr_default.save(path)
        saved = json.loads(path.read_text())
        # Saving writes only the given fields: roughness, derived from s, is derived again on loading.
        assert "roughness" not in saved["objects"][0]["material"]
        widths.append(highlight_width(shadelab.Scene.load(path)))
    assert widths[0] > widths[1], widths


def test_a_given_roughness_is_never_re_derived(pbr_default):
    pbr_default.objects[0].material.roughness = 0.5
    assert "roughness" not in pbr_default.objects[0].material.derived
    pbr_default.objects[0].material.s = 1
    first = np.asarray(shadelab.render(pbr_default, (160, 90)))
    pbr_default.objects[0].material.s = 2048
    assert pbr_default.objects[0].material.roughness == 0.5
    # The negative control of the sweep: with roughness given, s no longer moves the pbr picture.
    assert np.array_equal(first, np.asarray(shadelab.render(pbr_default, (160, 90))))


def test_a_materials_own_model_shades_that_object_alone(pbr_default):
    phong = shadelab.data.scene("default")
    mixed = shadelab.data.scene("default")
    mixed.objects[0].material.model = "pbr"
    a = shadelab.render(mixed, (160, 90), coverage=True)
    wide = np.asarray(shadelab.render(pbr_default, (160, 90)))
    rest = np.asarray(shadelab.render(phong, (160, 90)))
    cov = np.asarray(a.coverage)
    pixels = np.asarray(a)
    assert np.array_equal(pixels[cov == 1], wide[cov == 1])  # the sphere as a scene-wide pbr render has it
    assert not np.array_equal(pixels[cov == 1], rest[cov == 1])  # control: not as Phong has it
    with pytest.raises(shadelab.InputError, match=r"objects\[0\]\.material\.model: unknown shading model 'phong2'"):
        mixed.objects[0].material.model = "phong2"


def test_a_sweep_of_s_under_disney_narrows_the_highlight_too(pbr_default):
    pbr_default.model = "disney"  # disney reads pbr's fields, derived from s alike
    widths = []
    # From s = 8: at s = 1 (roughness 0.90) the lobe has merged into the diffuse, whose retro-reflection
    # (Burley's Fd90 grows with roughness) then holds the brightest pixels, so there is no highlight to measure.
    for s in SWEEP[1:]:
        pbr_default.objects[0].material.s = s
        widths.append(highlight_width(pbr_default))
    assert all(a > b for a, b in zip(widths, widths[1:])), widths


def test_disney_parameters_edit_in_place_and_change_that_object_alone(pbr_default):
    pbr_default.model = "disney"
    material = pbr_default.objects[0].material
    assert material.disney.specular == 0.5 and material.disney.clearcoat == 0.0  # Burley's defaults
    before = shadelab.render(pbr_default, (160, 90), coverage=True)
    material.disney.clearcoat = 1.0
    material.disney.sheen = 1.0
    after = np.asarray(shadelab.render(pbr_default, (160, 90)))
    cov = np.asarray(before.coverage)
    pixels = np.asarray(before)
    assert not np.array_equal(pixels[cov == 1], after[cov == 1])
    assert np.array_equal(pixels[cov == 2], after[cov == 2])  # control: another sphere is untouched
    saved = pbr_default.to_dict()["objects"][0]["material"]["disney"]
    assert saved["clearcoat"] == 1.0 and saved["sheen"] == 1.0
    with pytest.raises(shadelab.InputError, match=r"objects\[0\]\.material\.disney\.sheen: must be in \[0, 1\]"):
        material.disney.sheen = 2
    assert pbr_default.objects[0].material.disney.sheen == 1.0  # nothing lost


def test_a_material_extension_not_shaded_is_a_warning(tmp_path):
    # glTF's iridescence is not shaded yet; the clear coat is (control: its asset loads without a warning).
    path = tmp_path / "iridescence.gltf"
    path.write_text('{"asset": {"version": "2.0"}, "scenes": [{"nodes": []}], "scene": 0, "materials": '
                    '[{"extensions": {"KHR_materials_iridescence": {"iridescenceFactor": 1}}}]}')
    with pytest.warns(shadelab.ShadelabWarning, match=r"KHR_materials_iridescence is not shaded"):
        try:
            shadelab.Scene.load(str(path))
        except shadelab.InputError:
            pass  # a file with no triangles may be refused after its warnings
    coated = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf"
    import os
    import warnings

    if not os.path.exists(coated):
        pytest.skip("assimp-testmodels is not installed")
    with warnings.catch_warnings():
        warnings.simplefilter("error", shadelab.ShadelabWarning)
        shadelab.Scene.load(coated)


def test_the_clearcoat_edits_in_place_under_pbr(pbr_default):
    material = pbr_default.objects[0].material
    assert material.clearcoat.factor == 0.0 and material.clearcoat.roughness == 0.0  # no coat by default
    before = shadelab.render(pbr_default, (160, 90), coverage=True)
    material.clearcoat.factor = 1.0
    material.clearcoat.roughness = 0.05
    after = np.asarray(shadelab.render(pbr_default, (160, 90)))
    cov = np.asarray(before.coverage)
    pixels = np.asarray(before)
    assert not np.array_equal(pixels[cov == 1], after[cov == 1])
    assert np.array_equal(pixels[cov == 2], after[cov == 2])  # control: another sphere is untouched
    saved = pbr_default.to_dict()["objects"][0]["material"]["clearcoat"]
    assert saved == {"factor": 1.0, "roughness": 0.05}
    with pytest.raises(shadelab.InputError, match=r"objects\[0\]\.material\.clearcoat\.factor: must be in \[0, 1\]"):
        material.clearcoat.factor = 1.5
    assert pbr_default.objects[0].material.clearcoat.factor == 1.0  # nothing lost


def test_the_sheen_edits_in_place_under_pbr(pbr_default):
    material = pbr_default.objects[0].material
    assert material.sheen.color == (0.0, 0.0, 0.0) and material.sheen.roughness == 0.0  # no sheen by default
    before = shadelab.render(pbr_default, (160, 90), coverage=True)
    material.sheen.color = (1.0, 0.8, 0.6)
    material.sheen.roughness = 0.3
    after = np.asarray(shadelab.render(pbr_default, (160, 90)))
    cov = np.asarray(before.coverage)
    pixels = np.asarray(before)
    assert not np.array_equal(pixels[cov == 1], after[cov == 1])
    assert np.array_equal(pixels[cov == 2], after[cov == 2])  # control: another sphere is untouched
    saved = pbr_default.to_dict()["objects"][0]["material"]["sheen"]
    assert saved["color"] == [1.0, 0.8, 0.6] or tuple(saved["color"]) == (1.0, 0.8, 0.6)
    assert saved["roughness"] == 0.3
    with pytest.raises(shadelab.InputError, match=r"objects\[0\]\.material\.sheen\.roughness: must be in \[0, 1\]"):
        material.sheen.roughness = 1.5
    assert pbr_default.objects[0].material.sheen.roughness == 0.3  # nothing lost


def test_transmission_and_volume_edit_in_place_under_pbr(pbr_default):
    material = pbr_default.objects[0].material
    assert material.transmission.factor == 0.0 and material.volume.thickness == 0.0  # none by default
    assert "attenuationDistance" not in pbr_default.to_dict()["objects"][0]["material"]["volume"]  # infinite
    before = shadelab.render(pbr_default, (160, 90), coverage=True)
    material.transmission.factor = 1.0
    material.volume.thickness = 1.0
    material.volume.attenuationDistance = 0.5
    material.volume.attenuationColor = (0.2, 0.6, 0.3)
    after = np.asarray(shadelab.render(pbr_default, (160, 90)))
    cov = np.asarray(before.coverage)
    pixels = np.asarray(before)
    assert not np.array_equal(pixels[cov == 1], after[cov == 1])
    assert np.array_equal(pixels[cov == 2], after[cov == 2])  # control: another sphere is untouched
    saved = pbr_default.to_dict()["objects"][0]["material"]
    assert saved["transmission"]["factor"] == 1.0 and saved["volume"]["attenuationDistance"] == 0.5
    with pytest.raises(shadelab.InputError, match=r"objects\[0\]\.material\.transmission\.factor: must be in \[0, 1\]"):
        material.transmission.factor = 2
    assert pbr_default.objects[0].material.transmission.factor == 1.0  # nothing lost


def test_layers_another_model_hides_are_said_once():
    # A glTF grid of sheens rendered under the lecture's phong: one ShadelabWarning names the layer and the way to
    # see it; under pbr nothing is said (control).
    scene = shadelab.Scene.load(str(shadelab.data.folder() / "models" / "layers" / "sheen_grid.gltf"))
    scene.model = "phong"
    with pytest.warns(shadelab.ShadelabWarning, match=r"glTF's sheen shades only under pbr.*scene\.model = \"pbr\""):
        shadelab.render(scene, (32, 18))
    scene.model = "pbr"
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", shadelab.ShadelabWarning)
        shadelab.render(scene, (32, 18))


def test_the_anisotropy_edits_in_place_under_pbr(pbr_default):
    material = pbr_default.objects[0].material
    assert material.anisotropy.strength == 0.0 and material.anisotropy.rotation == 0.0  # isotropic by default
    before = shadelab.render(pbr_default, (160, 90), coverage=True)
    material.anisotropy.strength = 0.8
    stretched = np.asarray(shadelab.render(pbr_default, (160, 90)))
    material.anisotropy.rotation = 1.2
    turned = np.asarray(shadelab.render(pbr_default, (160, 90)))
    cov = np.asarray(before.coverage)
    pixels = np.asarray(before)
    assert not np.array_equal(pixels[cov == 1], stretched[cov == 1])
    assert not np.array_equal(stretched[cov == 1], turned[cov == 1])
    assert np.array_equal(pixels[cov == 2], turned[cov == 2])  # control: another sphere is untouched
    saved = pbr_default.to_dict()["objects"][0]["material"]["anisotropy"]
    assert saved == {"strength": 0.8, "rotation": 1.2} or (abs(saved["strength"] - 0.8) < 1e-6
                                                           and abs(saved["rotation"] - 1.2) < 1e-6)
    with pytest.raises(shadelab.InputError, match=r"objects\[0\]\.material\.anisotropy\.strength: must be in \[0, 1\]"):
        material.anisotropy.strength = 2
    assert pbr_default.objects[0].material.anisotropy.strength == pytest.approx(0.8)  # nothing lost


def test_the_specular_layer_and_ior_edit_in_place_under_pbr(pbr_default):
    material = pbr_default.objects[0].material
    assert material.specular.factor == 1.0 and material.specular.color == (1.0, 1.0, 1.0)  # glTF's defaults
    before = shadelab.render(pbr_default, (160, 90), coverage=True)
    material.ior = 2.4  # a diamond's F0, 0.17 instead of 0.04
    brighter = np.asarray(shadelab.render(pbr_default, (160, 90)))
    material.specular.factor = 0.0  # no dielectric specular lobe at all
    dull = np.asarray(shadelab.render(pbr_default, (160, 90)))
    cov = np.asarray(before.coverage)
    pixels = np.asarray(before)
    assert brighter[cov == 1].sum(dtype=np.float64) > pixels[cov == 1].sum(dtype=np.float64)
    assert dull[cov == 1].sum(dtype=np.float64) < pixels[cov == 1].sum(dtype=np.float64)
    assert np.array_equal(pixels[cov == 2], dull[cov == 2])  # control: another sphere is untouched
    saved = pbr_default.to_dict()["objects"][0]["material"]
    assert saved["specular"]["factor"] == 0.0 and saved["ior"] == 2.4
    with pytest.raises(shadelab.InputError, match=r"objects\[0\]\.material\.specular\.factor: must be in \[0, 1\]"):
        material.specular.factor = -0.5
    assert pbr_default.objects[0].material.specular.factor == 0.0  # nothing lost
