"""shadelab.compare returns `shadelab compare --json`'s report and heatmap, with its gates and negative controls;
shadelab.probe returns the probe report."""

import json

import numpy as np
import pytest

import shadelab
from conftest import run_binary

SIZE = (96, 64)


@pytest.fixture(scope="module")
def scene(source_dir):
    return shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")


def changed(scene, **edit):
    other = scene.copy()
    for key, value in edit.items():
        if key == "s":
            other.objects[0].material.s = value
        elif key == "light":
            other.lights[0].color = value
        elif key == "model":
            other.model = value
    return other


@pytest.mark.parametrize("flags,gates", [
    ([], None),
    (["--threshold", "1", "--max-fraction", "0.05", "--hard-max", "40", "--max-mean", "0.5"],
     {"threshold": 1, "max_fraction_over": 0.05, "hard_max": 40, "max_mean": 0.5}),
])
def test_report_equals_the_binary(scene, binary, out_dir, flags, gates):
    a, b = out_dir / "a.png", out_dir / "b.png"
    shadelab.render(scene, SIZE).save(a)
    shadelab.render(changed(scene, s=64.0), SIZE).save(b)
    p = run_binary(binary, "compare", a, b, "--json", out_dir / "cli.json", "--diff", out_dir / "cli_heat.png", *flags)
    report = shadelab.compare(a, b, gates)
    assert report.report == json.loads((out_dir / "cli.json").read_text())
    assert report.passed == (p.returncode == 0)
    assert np.array_equal(report.heatmap.to_uint8(), shadelab.Image.open(out_dir / "cli_heat.png").to_uint8())
    assert report.summary in p.stdout
    # Images in memory give the same report, less the file names.
    in_memory = shadelab.compare(shadelab.Image.open(a), shadelab.Image.open(b), gates).report
    assert {k: v for k, v in report.report.items() if k not in ("image_a", "image_b")} == in_memory


def test_identical_renders_pass(scene):
    report = shadelab.compare(shadelab.render(scene, SIZE), shadelab.render(scene, SIZE))
    assert report.passed and report.reasons == [] and report.report["regions"]["all"]["max"] == 0
    assert not np.asarray(report.heatmap).any()


@pytest.mark.parametrize("edit", [{"s": 32.0 * 1.1}, {"light": [0.5, 0.9, 0.9]}, {"model": "blinn-phong"}],
                         ids=["shininess+10%", "light colour", "phong vs blinn-phong"])
def test_negative_controls_fail(scene, edit, out_dir):
    size = (320, 180)  # the 10 % shininess change shows on enough pixels at this size
    a = shadelab.render(scene, size)
    b = shadelab.render(changed(scene, **edit), size)
    report = shadelab.compare(a, b)
    if report.passed:
        report.save(str(out_dir / "control"))
    assert not report.passed, report.summary
    assert report.reasons


def test_raster_against_reference_with_coverage(scene):
    raster = shadelab.render(scene, SIZE, coverage=True)
    traced = shadelab.render(scene, SIZE, renderer="trace", depth=1, coverage=True)
    report = shadelab.compare(raster, traced)
    assert report.report["coverage"]["present"]
    assert report.report["coverage"]["band_pixels"] > 0


def test_gates_are_checked(scene):
    image = shadelab.render(scene, (8, 8))
    with pytest.raises(ValueError, match="unknown gate"):
        shadelab.compare(image, image, {"thresold": 2})
    with pytest.raises(ValueError, match="sizes differ"):
        shadelab.compare(image, shadelab.render(scene, (8, 9)))
    assert shadelab.default_gates["threshold"] == 3 and shadelab.default_gates["hard_max"] == 16


def test_probe_report(scene):
    report = shadelab.probe(scene, (24, 40), SIZE)
    assert report["hit"] and report["pixel"] == [24, 40] and report["size"] == list(SIZE)
    N, V = np.array(report["N"]), np.array(report["V"])
    assert np.linalg.norm(N) == pytest.approx(1.0, abs=1e-5)
    assert report["object"]["kind"] in ("sphere", "plane", "mesh")
    for light in report["lights"]:
        L, R, H = (np.array(light[k]) for k in ("L", "R", "H"))
        assert light["NoL"] == pytest.approx(float(N @ L), abs=1e-5)
        assert light["RoV"] == pytest.approx(float(R @ V), abs=1e-5)
        assert light["NoH"] == pytest.approx(float(N @ H), abs=1e-5)
        assert np.allclose(R, 2 * N * (N @ L) - L, atol=1e-5)
        for key in ("spec_phong", "spec_blinn", "diffuse", "specular_phong", "specular_blinn", "visibility"):
            assert key in light
    assert set(report["total"]) == {"phong", "blinn_phong", "pbr", "disney"}
    # The probe's object is the one the coverage buffer shows there.
    ids = shadelab.render(scene, SIZE, renderer="trace", coverage=True).coverage
    assert report["object"]["id"] == ids[40, 24]
    assert not shadelab.probe(scene, (5, 0), SIZE)["hit"]  # the sky
    with pytest.raises(ValueError, match="outside"):
        shadelab.probe(scene, (96, 0), SIZE)


def test_probe_ray_tree_is_the_tracers(scene):
    """The ray tree beside the probe: rooted at the primary ray that the probe's own hit ends, each child
    starting where its parent hit; without ray_tree it is absent (the control)."""
    report = shadelab.probe(scene, (24, 40), SIZE, ray_tree=True)
    rays = report["ray_tree"]["rays"]
    assert rays[0]["kind"] == "primary" and rays[0]["parent"] == -1
    assert rays[0]["t"] == pytest.approx(report["t"], rel=1e-6)
    assert rays[0]["object"] == report["object"]["id"]
    for ray in rays[1:]:
        parent = rays[ray["parent"]]
        hit = np.array(parent["origin"]) + parent["t"] * np.array(parent["dir"])
        assert np.linalg.norm(np.array(ray["origin"]) - hit) < 1e-2, ray["line"]
    shadows = [r for r in rays if r["kind"] == "shadow"]
    assert len(shadows) >= 1 and all(isinstance(r["blocked"], bool) for r in shadows)
    assert "ray_tree" not in shadelab.probe(scene, (24, 40), SIZE)
