"""The path tracer's seed (render(seed=...), `shadelab render --seed N`): the same seed gives the same bytes, another
seed another noise, seed 0 is the image without one, and Python's bytes are the binary's."""

import subprocess

import numpy as np
import pytest

import shadelab

SIZE = (48, 32)


@pytest.fixture(scope="module")
def cornell():
    return shadelab.data.scene("cornell")


def path_png(scene, **kwargs):
    return shadelab.render(scene, SIZE, renderer="path", spp=4, **kwargs).to_png()


@pytest.mark.parametrize("sampler", ["sobol", "independent"])
def test_same_seed_same_bytes_another_seed_another_noise(cornell, sampler):
    assert path_png(cornell, sampler=sampler, seed=7) == path_png(cornell, sampler=sampler, seed=7, threads=1)
    a = np.asarray(shadelab.render(cornell, SIZE, renderer="path", spp=4, sampler=sampler, seed=7))
    b = np.asarray(shadelab.render(cornell, SIZE, renderer="path", spp=4, sampler=sampler, seed=8))
    # The negative control of the equality above: another seed changes most pixels, by noise, not by a shift of
    # the image: the two estimates agree on average.
    assert (a != b).any(axis=2).mean() > 0.5
    assert abs(float(a.mean()) - float(b.mean())) < 0.1 * float(a.mean())


def test_seed_zero_is_the_image_without_a_seed(cornell):
    assert path_png(cornell, seed=0) == path_png(cornell)
    assert path_png(cornell, seed=1) != path_png(cornell)  # the negative control


def test_the_binarys_seed_is_pythons(cornell, binary, source_dir, tmp_path):
    scene_file = source_dir / "assets" / "scenes" / "cornell.json"
    for seed in (None, 0, 4294967295):
        out = tmp_path / f"seed-{seed}.png"
        args = [str(binary), "render", str(scene_file), "-o", str(out), "--size", "48x32", "--renderer", "path",
                "--spp", "4"] + ([] if seed is None else ["--seed", str(seed)])
        subprocess.run(args, check=True, capture_output=True)
        assert out.read_bytes() == path_png(cornell, seed=seed), seed
    assert (tmp_path / "seed-0.png").read_bytes() == (tmp_path / "seed-None.png").read_bytes()
    assert (tmp_path / "seed-4294967295.png").read_bytes() != (tmp_path / "seed-0.png").read_bytes()


@pytest.mark.parametrize("args,message", [
    (["--renderer", "path", "--seed", "x"], "--seed: expected a whole number from 0 to 4294967295, got 'x'"),
    (["--renderer", "path", "--seed", "-1"], "--seed: expected a whole number from 0 to 4294967295, got '-1'"),
    (["--renderer", "path", "--seed", "4294967296"],
     "--seed: must be a whole number from 0 to 4294967295, got 4294967296"),
    (["--seed", "3"], "--seed: is for the path tracer (renderer path), not raster"),
])
def test_the_binary_refuses_a_bad_seed(binary, source_dir, tmp_path, args, message):
    out = tmp_path / "x.png"
    p = subprocess.run([str(binary), "render", str(source_dir / "assets" / "scenes" / "cornell.json"), "-o", str(out),
                        "--size", "8x8", *args], capture_output=True, text=True)
    assert p.returncode == 2 and message in p.stderr, p.stderr
    assert not out.exists()
