"""shadelab.Image: the linear floats, the 8-bit pixels made from them by the binary's conversion, PNG in and out,
arrays in, coverage, pickling, and the render arguments' checks."""

import pickle

import numpy as np
import pytest

import shadelab


@pytest.fixture(scope="module")
def scene(source_dir):
    return shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")


def srgb(linear):
    # IEC 61966-2-1, as image/encode.h documents it, then rounding to the nearest level.
    c = np.clip(linear, 0.0, 1.0).astype(np.float64)
    e = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1 / 2.4) - 0.055)
    return np.floor(e * 255.0 + 0.5).astype(np.int32)


@pytest.mark.parametrize("renderer", ["raster", "trace"])
def test_floats_and_pixels(scene, renderer):
    image = shadelab.render(scene, (96, 64), renderer=renderer)
    floats = np.asarray(image)
    assert floats.shape == (64, 96, 3) and floats.dtype == np.float32 and image.shape == floats.shape
    assert not floats.flags.writeable
    assert floats.max() > 0.5 and floats.min() >= 0.0  # not a blank image
    pixels = image.to_uint8()
    assert pixels.shape == (64, 96, 3) and pixels.dtype == np.uint8
    # The 8-bit pixels are the floats through the sRGB curve (to within the curve's float rounding).
    assert np.abs(srgb(floats) - pixels.astype(np.int32)).max() <= 1
    linear = shadelab.render(scene, (96, 64), renderer=renderer, encoding="linear")
    assert np.array_equal(np.asarray(linear), floats)
    assert np.abs(np.floor(np.clip(floats, 0, 1) * 255 + 0.5) - linear.to_uint8()).max() <= 1


def test_png_round_trip(scene, out_dir):
    image = shadelab.render(scene, (64, 48))
    path = out_dir / "round.png"
    image.save(path)
    back = shadelab.Image.open(path)
    assert back.source == "file" and back.size == (64, 48)
    assert np.array_equal(back.to_uint8(), image.to_uint8())
    assert image._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(OSError, match="no_such_dir"):
        image.save(out_dir / "no_such_dir" / "x.png")


def test_from_array():
    pixels = np.zeros((4, 5, 3), dtype=np.uint8)
    pixels[1, 2] = (255, 128, 0)
    image = shadelab.Image.from_array(pixels)
    assert np.array_equal(image.to_uint8(), pixels)
    assert np.asarray(image)[1, 2, 0] == pytest.approx(1.0)
    floats = np.full((2, 3, 3), 0.5, dtype=np.float32)
    encoded = shadelab.Image.from_array(floats).to_uint8()
    assert (encoded == 188).all()  # linear 0.5 in sRGB
    assert (shadelab.Image.from_array(floats, encoding="linear").to_uint8() == 128).all()
    with pytest.raises(ValueError, match="shape"):
        shadelab.Image.from_array(np.zeros((4, 4), dtype=np.uint8))
    with pytest.raises(ValueError, match="got dtype int64"):
        shadelab.Image.from_array(np.zeros((4, 4, 3), dtype=np.int64))


def test_coverage_and_pickle(scene):
    image = shadelab.render(scene, (64, 48), coverage=True)
    ids = image.coverage
    assert ids.shape == (48, 64) and ids.dtype == np.uint32
    assert ids[0, 0] == 0 and len(np.unique(ids)) > 3  # background at the top, several objects
    assert shadelab.render(scene, (64, 48)).coverage is None
    again = pickle.loads(pickle.dumps(image))
    assert np.array_equal(again.to_uint8(), image.to_uint8())
    assert np.array_equal(np.asarray(again), np.asarray(image))
    assert np.array_equal(again.coverage, ids)


@pytest.mark.parametrize("kwargs,message", [
    ({"size": (0, 10)}, r"^size: each side must be 1\.\.16384 pixels, got 0x10$"),
    ({"size": "64by64"}, r"^size: expected WxH"),
    ({"spp": 2}, r"^spp: expected a perfect square from 1 to 64"),
    ({"renderer": "path", "spp": 0}, r"^spp: the path tracer takes 1 to 1048576 samples per pixel, got 0$"),
    ({"renderer": "photon"}, r"^renderer: unknown value 'photon'; expected raster, trace, both or path$"),
    ({"encoding": "gamma"}, r"^encoding: unknown value 'gamma'; expected srgb or linear$"),
    ({"depth": 65, "renderer": "trace"}, r"^depth: must be in \[0, 64\], got 65$"),
])
def test_bad_arguments(scene, kwargs, message):
    kwargs = {"size": (8, 8), **kwargs}
    with pytest.raises(ValueError, match=message):
        shadelab.render(scene, **kwargs)


def test_scene_arguments(source_dir):
    path = source_dir / "assets" / "scenes" / "shininess-row.json"
    by_path = shadelab.render(path, (32, 16))
    by_str = shadelab.render(str(path), "32x16")
    by_dict = shadelab.render(shadelab.Scene.load(path).to_dict(), (32, 16))
    assert by_path.to_png() == by_str.to_png() == by_dict.to_png()
    with pytest.raises(TypeError):
        shadelab.render(42, (8, 8))
