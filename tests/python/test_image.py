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


def codes_of(srgb_floats):
    """The 8-bit codes of display-ready floats, rounded half up as the PNG's conversion rounds."""
    return np.floor(srgb_floats.astype(np.float64) * 255 + 0.5).astype(np.int32)


@pytest.mark.parametrize("display", [{}, {"exposure": 1.5, "view_transform": "filmic"}, {"exposure": -2},
                                     {"view_transform": "filmic"}])
def test_to_srgb_is_the_pngs_conversion_before_rounding(scene, display, out_dir):
    image = shadelab.render(scene, (96, 64), renderer="trace", **display)
    assert image.exposure == display.get("exposure", 0) and image.view_transform == display.get("view_transform",
                                                                                                "standard")
    srgb_floats = image.to_srgb()
    assert srgb_floats.shape == (64, 96, 3) and srgb_floats.dtype == np.float32
    assert srgb_floats.flags.writeable and srgb_floats.min() >= 0 and srgb_floats.max() <= 1  # a new array
    off = codes_of(srgb_floats) != image.to_uint8()
    # Equal but where float32 rounding of the curve crosses a half level: at most one level, almost nowhere.
    assert np.abs(codes_of(srgb_floats) - image.to_uint8()).max() <= 1 and off.mean() <= 1e-3, off.mean()
    # A pickled image keeps its display, and so the same floats.
    assert np.array_equal(pickle.loads(pickle.dumps(image)).to_srgb(), srgb_floats)
    # The negative control: the same render's floats without its display give other codes, which the check
    # above would see (the Standard case has no display to leave out).
    if display:
        plain = shadelab.render(scene, (96, 64), renderer="trace").to_srgb()
        assert (codes_of(plain) != image.to_uint8()).mean() > 0.05


def test_to_srgb_is_srgb_whatever_the_encoding(scene):
    # encoding="linear" writes levels without the curve; to_srgb() is display-ready sRGB either way.
    srgb_image = shadelab.render(scene, (32, 24), renderer="trace")
    linear_image = shadelab.render(scene, (32, 24), renderer="trace", encoding="linear")
    assert np.array_equal(srgb_image.to_srgb(), linear_image.to_srgb())
    assert not np.array_equal(codes_of(linear_image.to_srgb()), linear_image.to_uint8())  # the curve is there


def test_png_round_trip(scene, out_dir):
    image = shadelab.render(scene, (64, 48))
    path = out_dir / "round.png"
    image.save(path)
    back = shadelab.Image.open(path)
    assert back.source == "file" and back.size == (64, 48)
    assert np.array_equal(back.to_uint8(), image.to_uint8())
    assert image._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    (out_dir / "a_file").write_text("x")  # a missing folder is made; one under a file cannot be
    with pytest.raises(OSError, match="a_file/sub/x.png: cannot create its folder"):
        image.save(out_dir / "a_file" / "sub" / "x.png")


def test_exr_round_trip(scene, out_dir):
    # .exr holds the linear floats: exact in float (values above 1 included), within half precision in half.
    image = shadelab.render(scene, (64, 48), renderer="path", spp=2)
    floats = np.asarray(image)
    bright = shadelab.Image.from_array(np.concatenate([floats, floats * 40.0], axis=1))
    assert np.asarray(bright).max() > 1.0
    path = out_dir / "round.exr"
    bright.save(path)
    back = shadelab.Image.open(path)
    assert back.source == "file" and back.size == (128, 48)
    assert np.array_equal(np.asarray(back), np.asarray(bright))
    assert np.array_equal(back.to_uint8(), bright.to_uint8()), "the 8-bit pixels through the one conversion"
    assert shadelab.Image.open(path, encoding="linear").encoding == "linear"
    half = out_dir / "half.exr"
    bright.save(half, exr_precision="half")
    h = np.asarray(shadelab.Image.open(half))
    assert np.all(np.abs(h - np.asarray(bright)) <= np.abs(np.asarray(bright)) * 2.0**-11 + 6e-8)
    assert not np.array_equal(h, np.asarray(bright)), "control: half is narrower than float"
    # The PNG path is as before: 8-bit, clamped.
    bright.save(out_dir / "bright.png")
    assert np.asarray(shadelab.Image.open(out_dir / "bright.png")).max() <= 1.0


def test_exr_refusals(source_dir, out_dir):
    image = shadelab.Image.from_array(np.full((4, 5, 3), 2.5, dtype=np.float32))
    with pytest.raises(ValueError, match="exr_precision: expected half or float, got 'double'"):
        image.save(out_dir / "x.exr", exr_precision="double")
    with pytest.raises(ValueError, match=r"exr_precision: only for an \.exr path"):
        image.save(out_dir / "x.png", exr_precision="half")
    with pytest.raises(TypeError, match="exr_precision: expected a string, got int"):
        image.save(out_dir / "x.exr", exr_precision=16)
    (out_dir / "a_file").write_text("x")
    with pytest.raises(OSError, match="a_file/sub/x.exr: cannot create its folder"):
        image.save(out_dir / "a_file" / "sub" / "x.exr")
    # Never over an input: the scene file a live Scene was read from, through a link named .exr.
    source = out_dir / "src.json"
    source.write_text((source_dir / "assets" / "scenes" / "default.json").read_text())
    loaded = shadelab.Scene.load(source)
    link = out_dir / "link.exr"
    if link.exists() or link.is_symlink():
        link.unlink()
    link.symlink_to(source.name)
    before = source.read_bytes()
    with pytest.raises(OSError, match="refusing to overwrite an input"):
        image.save(link)
    assert source.read_bytes() == before
    del loaded
    # Hostile files: one line naming the file.
    for name, content in [("text.exr", b"not an image"), ("cut.exr", None)]:
        bad = out_dir / name
        if content is None:
            image.save(out_dir / "whole.exr")
            content = (out_dir / "whole.exr").read_bytes()[:60]
        bad.write_bytes(content)
        with pytest.raises(shadelab.InputError, match=str(bad)) as caught:
            shadelab.Image.open(bad)
        assert "\n" not in str(caught.value)


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


# -- a tampered pickle -------------------------------------------------------------------------------------------

# Each tampered state runs in a child process that goes on to save, compare and read the image, so that a state
# let through to a CHECK (SIGABRT) fails the test instead of ending it.
CHILD = r"""
import pickle, sys
import numpy as np
import shadelab

image = shadelab.Image.from_array(np.full((6, 8, 3), 100, np.uint8))
state = list(image.__getstate__())
exec(sys.argv[1])  # tampers with `state`
tampered = shadelab.Image.__new__(shadelab.Image)
try:
    tampered.__setstate__(tuple(state) if isinstance(state, list) else state)
except ValueError as e:
    print("refused:", e)
    sys.exit(0)
print("accepted:", tampered)
tampered.save(sys.argv[2])
shadelab.compare(tampered, tampered)
np.asarray(tampered).sum()
"""

TAMPERED = [
    ("state[0], state[1] = -8, -6", "width must be 1..16384 pixels, got -8"),  # -8 * -6 = 48, as the original
    ("state[0] = 0", "width must be 1..16384 pixels, got 0"),
    ("state[1] = 0", "height must be 1..16384 pixels, got 0"),
    ("state[0], state[1] = 16385, 1", "width must be 1..16384 pixels, got 16385"),
    ("state[0], state[1] = 2**64 + 8, 6", "width must be 1..16384 pixels, got 18446744073709551624"),
    ("state[2] = 0", "channels must be 3 (RGB) or 4 (RGBA), got 0"),
    ("state[2] = 1", "channels must be 3 (RGB) or 4 (RGBA), got 1"),
    ("state[2] = 4", "pixels must be 192 bytes for a 8x6 image, got 144"),
    ("state[3] = state[3][:-1]", "pixels must be 144 bytes for a 8x6 image, got 143"),
    ("state[4] = state[4] + b'1234'", "linear floats must be 768 bytes for a 8x6 image, got 772"),
    ("state[7] = b'1234'", "coverage must be 192 bytes for a 8x6 image, got 4"),
    ("state[3] = 'text'", "pixels must be bytes, got str"),
    ("state[0] = 8.0", "width, height and channels must be integers"),
    ("state[5] = 'gamma'", "unknown encoding 'gamma'"),
    ("state[6] = 'elsewhere'", "unknown source 'elsewhere'"),
    ("state[8] = None", "draw_ms must be a number, got NoneType"),
    ("state[10] = 40.0", "exposure must be in [-16, 16] stops, got 40"),
    ("state[10] = 'x'", "exposure must be a number, got str"),
    ("state[11] = 'sepia'", "unknown view transform 'sepia'"),
    ("state[11] = 3", "view transform must be a string"),
    ("state.append(1)", "expected a tuple of 12 items, got 13"),
    ("state = state[:11]", "expected a tuple of 12 items, got 11"),
    ("state = state[0]", "expected a tuple of 12 items, got int"),
]


def _child(code, out_dir):
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-c", CHILD, code, str(out_dir / "tampered.png")], capture_output=True,
                          text=True, timeout=60)


@pytest.mark.parametrize("code,reason", TAMPERED, ids=[c for c, _ in TAMPERED])
def test_a_tampered_pickle_is_one_value_error(code, reason, out_dir):
    p = _child(code, out_dir)
    assert p.returncode == 0, f"exit {p.returncode}: {p.stdout}{p.stderr}"
    assert p.stdout == f"refused: shadelab.Image: bad pickle state: {reason}\n", p.stdout + p.stderr


def test_the_tampered_pickle_check_sees_an_abort(out_dir):
    # The negative controls: an untampered state round-trips and the child saves it; a child that aborts, as
    # save() did on the 8x6 image pickled as -8x-6, fails the check above (a negative exit, no "refused").
    ok = _child("pass", out_dir)
    assert ok.returncode == 0 and ok.stdout.startswith("accepted: <shadelab.Image 8x6 srgb from array>"), ok.stderr
    assert (out_dir / "tampered.png").exists()
    aborted = _child("import os; os.abort()", out_dir)
    assert aborted.returncode < 0 and "refused" not in aborted.stdout


# -- argument types ----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs,error,message", [
    ({"spp": 2**31}, ValueError, "spp: expected a perfect square from 1 to 64"),
    ({"spp": 2**31, "renderer": "path"}, ValueError,
     "spp: the path tracer takes 1 to 1048576 samples per pixel, got 2147483648"),
    ({"size": (2**40, 8)}, ValueError, "size: each side must be 1..16384 pixels, got 1099511627776x8"),
    ({"threads": -2**40}, ValueError, "threads: must be in [0, 1024] (0 = every core), got -1099511627776"),
    ({"depth": 2**63, "renderer": "trace"}, ValueError, "depth: must be in [0, 64], got 9223372036854775808"),
    ({"spp": 2.5}, TypeError, "spp: expected a whole number, got float"),
    ({"spp": True}, TypeError, "spp: expected a whole number, got bool"),
    ({"threads": "4"}, TypeError, "threads: expected a whole number, got str"),
    ({"coverage": "yes"}, TypeError, "coverage: expected True or False, got str"),
    ({"coverage": None}, TypeError, "coverage: expected True or False, got NoneType"),
    ({"renderer": 3}, TypeError, "renderer: expected a string, got int"),
    ({"encoding": None}, TypeError, "encoding: expected a string, got NoneType"),
    ({"renderer": "path", "time_limit": "1"}, TypeError, "time_limit: expected a number, got str"),
    ({"renderer": "path", "time_limit": float("nan")}, ValueError, "time_limit: must be in [0.001, 1e7] seconds (leave it out for no limit), got nan"),
    ({"renderer": "path", "estimator": 1}, TypeError, "estimator: expected a string, got int"),
    ({"size": (float("inf"), 8)}, TypeError, "size: width: expected a whole number, got float"),
    ({"size": (32.5, 32)}, TypeError, "size: width: expected a whole number, got float"),
    ({"size": (32, 32.0)}, TypeError, "size: height: expected a whole number, got float"),
    ({"size": (8, "8")}, TypeError, "size: height: expected a whole number, got str"),
    ({"size": (True, 8)}, TypeError, "size: width: expected a whole number, got bool"),
    ({"size": (8,)}, ValueError, "size: expected (width, height) or 'WxH', got (8,)"),
    ({"renderer": "path", "seed": "3"}, TypeError, "seed: expected a whole number, got str"),
    ({"renderer": "path", "seed": 1.0}, TypeError, "seed: expected a whole number, got float"),
    ({"renderer": "path", "seed": -1}, ValueError, "seed: must be a whole number from 0 to 4294967295, got -1"),
    ({"renderer": "path", "seed": 2**32}, ValueError,
     "seed: must be a whole number from 0 to 4294967295, got 4294967296"),
    ({"renderer": "path", "seed": 2**70}, ValueError,
     "seed: must be a whole number from 0 to 4294967295, got 1180591620717411303424"),
    ({"seed": 3}, ValueError, "seed: is for the path tracer (renderer path), not raster"),
    ({"max_memory": 1.5}, TypeError, "max_memory: expected a number of bytes, a size such as '512M' or None, got float"),
])
def test_a_bad_argument_is_one_line_naming_it(scene, kwargs, error, message):
    kwargs = {"size": (8, 8), **kwargs}
    with pytest.raises(error) as raised:
        shadelab.render(scene, **kwargs)
    assert type(raised.value) is error  # not a subclass: pybind11's TypeError is a TypeError too
    text = str(raised.value)
    assert "\n" not in text and text.startswith(message), text


@pytest.mark.parametrize("call,error,message", [
    (lambda a: shadelab.compare(a, a, {"threshold": float("nan")}), ValueError,
     "gates: threshold must be a number, got nan"),
    (lambda a: shadelab.compare(a, a, {"max_fraction_over": float("nan")}), ValueError,
     "gates: max_fraction_over must be a number, got nan"),
    (lambda a: shadelab.compare(a, a, {"max_mean": float("nan")}), ValueError, "gates: max_mean must be a number, got nan"),
    (lambda a: shadelab.compare(a, a, {"hard_max": "16"}), TypeError, "gates: hard_max: expected a number, got str"),
    (lambda a: shadelab.compare(a, a, {"threshold": 2.5}), ValueError,
     "gates: threshold must be a whole number of 8-bit levels, got 2.5"),
    (lambda a: shadelab.compare(a, a, {"threshold": 2**40}), ValueError,
     "compare gates: threshold must be in [0, 255], got 1099511627776"),
    (lambda a: shadelab.compare(a, a, gain=2**40), ValueError, "gain: must be in [1, 255], got 1099511627776"),
    (lambda a: shadelab.compare(a, a, gain=1.5), TypeError, "gain: expected a whole number, got float"),
    (lambda a: shadelab.Image.from_array(a).save(3), TypeError, "path: expected a path (str or os.PathLike), got int"),
    (lambda a: shadelab.Image.open(None), TypeError, "path: expected a path (str or os.PathLike), got NoneType"),
    (lambda a: shadelab.Image.from_array(a, encoding=1), TypeError, "encoding: expected a string, got int"),
    (lambda a: shadelab.Renderer(backend=2), TypeError, "backend: expected a string, got int"),
    (lambda a: shadelab.Scene.load(3), TypeError, "path: expected a path (str or os.PathLike), got int"),
    (lambda a: shadelab.Scene.load(shadelab.data.path("default"), allow_external_paths="yes"), TypeError,
     "allow_external_paths: expected True or False, got str"),
    (lambda a: shadelab.Scene.from_dict({}, base_dir=3), TypeError,
     "base_dir: expected a path (str or os.PathLike), got int"),
    (lambda a: shadelab.Image.from_array("x"), ValueError,
     "from_array: expected a uint8 (levels) or float (linear) array, got dtype <U1"),
])
def test_other_calls_refuse_bad_arguments_in_one_line(call, error, message):
    a = np.zeros((4, 4, 3), np.uint8)
    with pytest.raises(error) as raised:
        call(a)
    text = str(raised.value)
    assert "\n" not in text and text == message, text


def test_whole_number_sizes_and_seeds_of_any_integer_type_are_taken(scene):
    # The negative control of the size and seed refusals above: ints and numpy integers pass.
    assert shadelab.render(scene, (np.int64(8), np.uint16(6))).size == (8, 6)
    assert shadelab.render(scene, (8, 6), renderer="path", spp=1, seed=np.uint32(2**32 - 1)).size == (8, 6)


def test_gates_of_whole_numbers_take_integral_floats():
    a = np.zeros((4, 4, 3), np.uint8)
    assert shadelab.compare(a, a, {"threshold": 4.0, "hard_max": np.int64(20)}).passed


def test_the_one_line_check_sees_pybind11s_message(scene):
    # The negative control: the compiled renderer called directly, as the package called it, still answers a
    # bad type with pybind11's message of several lines, which the checks above would refuse.
    from shadelab import _rendering

    with pytest.raises(TypeError) as raised:
        _rendering.default_core().render(scene._handle, 8, 8, "raster", 2**31)
    assert "incompatible function arguments" in str(raised.value) and "\n" in str(raised.value)
