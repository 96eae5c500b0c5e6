"""The web page against the native binary, in headless Chromium: every shipped scene's raster image within
design.md §4's gates and its Whitted reference pixel for pixel, the controls, hostile files, and no console
errors. The page's test API and DOM ids are in tests/web/README.md; one browser serves the whole module.

Sections: locating the page and the binary · native renders and comparisons · the page · a. scenes ·
b. controls · c. hostile files."""

import base64
import json
import math
import os
import shutil
import struct
import subprocess
from pathlib import Path

import numpy as np
import pytest

import cdp
import png
from conftest import SOURCE_DIR, evidence_folder
from serve import Server

SIZE = (320, 180)
SCENES = sorted(p.name for p in (SOURCE_DIR / "assets" / "scenes").glob("*.json"))
READY_TIMEOUT = 180  # s: the first picture, wasm compiled and shaders linked on SwiftShader
RENDER_TIMEOUT = 120  # s: one image from the page, the Whitted reference included

# ---- locating the page and the binary ----


def _path_from_env(name, default):
    value = os.environ.get(name)
    return Path(value) if value else SOURCE_DIR / default


@pytest.fixture(scope="module")
def binary():
    path = _path_from_env("SHADELAB_BIN", "build/shadelab")
    if not path.is_file():
        pytest.fail(f"{path}: no shadelab binary (build it: cmake --build build --target shadelab; "
                    "or set SHADELAB_BIN)", pytrace=False)
    return path


@pytest.fixture(scope="module")
def page_dir():
    path = _path_from_env("SHADELAB_WEB_PAGE", "build-web/page")
    if not (path / "index.html").is_file():
        pytest.fail(f"{path}: no web page (no index.html); build it with scripts/web.sh --build-only, "
                    "or set SHADELAB_WEB_PAGE", pytrace=False)
    return path


# ---- native renders and comparisons ----

_native_cache = {}


def coverage_of(image):
    """Where an image's coverage ids are kept (compare/coverage_image.h): beside it, `<stem>-coverage.png`."""
    image = Path(image)
    return image.with_name(image.stem + "-coverage.png")


def native_render(binary, scene, renderer, out, size=SIZE):
    """`shadelab render SCENE --renderer R --size WxH -o out --coverage`, once per scene file content and
    renderer; the coverage ids go to coverage_of(out)."""
    scene = Path(scene)
    key = (scene.read_bytes(), str(scene.parent), renderer, size)
    if key not in _native_cache:
        folder = evidence_folder(f"native-renders/{len(_native_cache)}")
        target = folder / f"{scene.stem}-{renderer}.png"
        args = [str(binary), "render", str(scene), "--renderer", renderer, "--size", f"{size[0]}x{size[1]}", "-o",
                str(target), "--coverage", str(coverage_of(target))]
        p = subprocess.run(args, capture_output=True, text=True, timeout=300)
        (folder / "command.txt").write_text(" ".join(args) + f"\nexit {p.returncode}\n{p.stdout}{p.stderr}")
        assert p.returncode == 0, f"{' '.join(args)} exited {p.returncode}: {p.stderr}"
        _native_cache[key] = target
    shutil.copyfile(_native_cache[key], out)
    shutil.copyfile(coverage_of(_native_cache[key]), coverage_of(out))
    return Path(out)


def compare_gates(binary, a, b, evidence, name):
    """`shadelab compare a b` under the default gates of design.md §4, with both images' coverage ids
    (coverage_of), so silhouette pixels form the band as in the renderers' own comparisons; returns (passed,
    summary). Leaves the heatmap and the JSON report in the evidence folder."""
    for image in (a, b):
        assert coverage_of(image).is_file(), f"{image}: no coverage beside it ({coverage_of(image).name})"
    args = [str(binary), "compare", str(a), str(b), "--coverage-a", str(coverage_of(a)), "--coverage-b",
            str(coverage_of(b)), "--diff", str(evidence / f"{name}-heat.png"), "--json",
            str(evidence / f"{name}-report.json")]
    p = subprocess.run(args, capture_output=True, text=True, timeout=60)
    summary = (p.stdout + p.stderr).strip()
    (evidence / f"{name}-compare.txt").write_text(" ".join(args) + f"\nexit {p.returncode}\n{summary}\n")
    assert p.returncode in (0, 1), f"compare failed to run (exit {p.returncode}): {summary}"
    return p.returncode == 0, summary


def compare_exact(a, b, evidence, name):
    """Pixel for pixel (RGB and alpha, as decoded); returns (equal, summary) and leaves the numbers."""
    pa, pb = png.read(a), png.read(b)
    if pa.shape != pb.shape:
        summary = f"sizes differ: {pa.shape[1]}x{pa.shape[0]} against {pb.shape[1]}x{pb.shape[0]}"
        equal = False
    else:
        diff = np.abs(pa.astype(int) - pb.astype(int)).max(axis=2)
        count = int((diff > 0).sum())
        equal = count == 0
        summary = f"{count} of {diff.size} pixels differ, by at most {int(diff.max())}/255"
        if not equal:
            y, x = np.unravel_index(int(diff.argmax()), diff.shape)
            summary += f", the most at ({x}, {y}): {pa[y, x].tolist()} against {pb[y, x].tolist()}"
    (evidence / f"{name}-exact.txt").write_text(f"{a}\n{b}\n{summary}\n")
    return equal, summary


# ---- the page ----


class App:
    """The page's test API (README.md) over one CDP page."""

    def __init__(self, page):
        self.page = page

    def js(self, expression, timeout=RENDER_TIMEOUT):
        return self.page.evaluate(expression, timeout=timeout)

    def load_scene(self, name, size=SIZE):
        self.js(f"shadelab.loadScene({json.dumps(name)})")
        self.js(f"shadelab.setSize({size[0]}, {size[1]})")

    def _png(self, call, path):
        url = self.js(call)
        prefix = "data:image/png;base64,"
        assert isinstance(url, str) and url.startswith(prefix), f"{call} gave {str(url)[:60]!r}"
        Path(path).write_bytes(base64.b64decode(url[len(prefix):]))
        return Path(path)

    def image(self, which, path):
        """The page's picture; for the raster, its coverage ids too, at coverage_of(path)."""
        self._png(f"shadelab.imageDataUrl({json.dumps(which)})", path)
        if which == "raster":
            self._png("shadelab.coverageDataUrl('raster')", coverage_of(path))
        return Path(path)

    def export(self, path):
        text = self.js("shadelab.exportScene()")
        Path(path).write_text(text)
        return json.loads(text)

    def message(self):
        return self.js("shadelab.message()")

    def blur(self):
        """Takes keyboard focus off any control, so that a key goes to the page, not to a <select>."""
        self.js("document.activeElement && document.activeElement.blur(), true")


@pytest.fixture(scope="module")
def app(browser, page_dir):
    with Server(page_dir) as server:
        page = browser.new_page()
        page.navigate(server.url("index.html"), timeout=60)
        try:
            page.wait_for("window.shadelab && window.shadelab.ready && true", timeout=60)
        except cdp.CdpTimeout:
            pytest.fail(f"{page_dir}/index.html: no window.shadelab.ready within 60 s of loading "
                        f"(console: {page.console[-5:]})", pytrace=False)
        page.evaluate("shadelab.ready.then(() => true)", timeout=READY_TIMEOUT)
        yield App(page)


@pytest.fixture(autouse=True)
def no_console_errors(request, evidence):
    """d. No uncaught exception or console error during any test (checked after it, into errors.txt)."""
    yield
    if "app" not in request.fixturenames:
        return
    errors = request.getfixturevalue("app").page.take_errors()
    (evidence / "errors.txt").write_text("".join(e + "\n" for e in errors))
    assert errors == [], f"the page logged {len(errors)} error(s) during the test: {errors}"


def test_controls_exist(app):
    """The DOM the tests drive: the scene list holds every shipped scene."""
    dom = app.js("""({
        scenes: [...document.querySelectorAll('#scene option')].map(o => o.value),
        steps: [...document.querySelectorAll('[data-step]')].map(b => b.dataset.step),
        models: [...document.querySelectorAll('#model option')].map(o => o.value),
        shininess: (e => e && [e.type, e.min, e.max])(document.querySelector('#shininess')),
        file: (e => e && e.type)(document.querySelector('#open-file')),
    })""")
    assert set(SCENES) <= set(dom["scenes"]), dom
    assert sorted(dom["steps"]) == list("012345"), dom
    assert set(dom["models"]) >= {"phong", "blinn-phong", "pbr", "disney"}, dom
    assert dom["shininess"] == ["range", "0", "11"], dom
    assert dom["file"] == "file", dom


# ---- a. every shipped scene against the native binary ----


@pytest.mark.parametrize("scene", SCENES)
def test_scene_matches_native(app, binary, evidence, scene):
    app.load_scene(scene)
    assert app.message() == "", f"loading {scene}: {app.message()}"
    page_raster = app.image("raster", evidence / "page-raster.png")
    page_reference = app.image("reference", evidence / "page-reference.png")
    path = SOURCE_DIR / "assets" / "scenes" / scene
    native_raster = native_render(binary, path, "raster", evidence / "native-raster.png")
    native_trace = native_render(binary, path, "trace", evidence / "native-trace.png")
    raster_ok, raster_summary = compare_gates(binary, page_raster, native_raster, evidence, "raster")
    trace_ok, trace_summary = compare_exact(page_reference, native_trace, evidence, "reference")
    assert raster_ok, f"{scene}: the page's raster image is outside the gates of the native one: {raster_summary}"
    assert trace_ok, f"{scene}: the page's reference differs from the native trace: {trace_summary}"


def material_of(scene, obj):
    """An object's material: inline, or named in the scene's "materials" (scene-format.md)."""
    material = obj.get("material", {})
    return scene.get("materials", {}).get(material, {}) if isinstance(material, str) else material


def edited_shininess(before, after):
    """[(object index, s before, s after)] for every object whose material's s the page changed (32 when
    the file leaves it out, scene-format.md)."""
    changed = []
    for i, (a, b) in enumerate(zip(before["objects"], after["objects"])):
        sa, sb = material_of(before, a).get("s", 32), material_of(after, b).get("s", 32)
        if sa != sb:
            changed.append((i, sa, sb))
    return changed


def move_shininess(app, factor):
    """Moves the shininess slider so that s is multiplied by `factor`; returns the new slider value."""
    value = float(app.js("document.querySelector('#shininess').value"))
    return float(app.page.set_range("#shininess", value + math.log2(factor)))


def test_shininess_10_percent_fails_the_gate(app, binary, evidence):
    """a's negative control: s changed by 10 % in the page must fail the gate the scenes pass."""
    app.load_scene("default.json")
    before = app.export(evidence / "before.json")
    move_shininess(app, 1.1)
    after = app.export(evidence / "after.json")
    changed = edited_shininess(before, after)
    (evidence / "shininess.json").write_text(json.dumps(changed))
    assert len(changed) == 1 and changed[0][2] == pytest.approx(changed[0][1] * 1.1, rel=0.01), (
        f"the slider should change one object's s by 10 %: {changed}")
    page_raster = app.image("raster", evidence / "page-raster.png")
    native = native_render(binary, SOURCE_DIR / "assets" / "scenes" / "default.json", "raster",
                           evidence / "native-raster.png")
    passed, summary = compare_gates(binary, page_raster, native, evidence, "raster")
    assert not passed, f"s x 1.1 passed the gates, so they cannot tell a 10 % shininess change: {summary}"


# ---- b. the controls drive the picture ----


def check_control_drives_picture(app, binary, evidence, change):
    """Before and after `change`: the page's new picture is the native render of the scene it exports,
    and the picture from before fails against that render."""
    app.load_scene("default.json")
    old = app.image("raster", evidence / "page-before.png")
    before = app.export(evidence / "scene-before.json")
    change()
    after = app.export(evidence / "scene-after.json")
    assert after != before, "the control changed nothing in the exported scene"
    new = app.image("raster", evidence / "page-after.png")
    native = native_render(binary, evidence / "scene-after.json", "raster", evidence / "native-after.png")
    passed, summary = compare_gates(binary, new, native, evidence, "after")
    assert passed, f"the page's picture after the change is outside the gates of the exported scene's: {summary}"
    passed, summary = compare_gates(binary, old, native, evidence, "before")
    assert not passed, f"the picture from before the change passes too, so the change shows nothing: {summary}"
    return before, after


def test_shininess_slider_drives_the_picture(app, binary, evidence):
    before, after = check_control_drives_picture(app, binary, evidence, lambda: move_shininess(app, 4.0))
    changed = edited_shininess(before, after)
    assert len(changed) == 1 and changed[0][2] == pytest.approx(changed[0][1] * 4, rel=0.01), changed


def test_key_3_drives_the_picture(app, binary, evidence):
    def press():
        app.blur()
        app.page.press_key("3")

    _, after = check_control_drives_picture(app, binary, evidence, press)
    terms = {"ambient": True, "diffuse": True, "specular": True, "shadows": False, "reflections": False}
    assert {k: after.get("terms", {}).get(k, True) for k in terms} == terms, after.get("terms")


def test_blinn_phong_drives_the_picture(app, binary, evidence):
    _, after = check_control_drives_picture(app, binary, evidence,
                                            lambda: app.page.select_option("#model", "blinn-phong"))
    assert after["model"] == "blinn-phong"


# ---- c. hostile files through the file input ----


def _glb(gltf_path):
    """A GLB of a glTF whose one buffer is a data: URI: the JSON chunk, then the buffer as the BIN chunk."""
    gltf = json.loads(Path(gltf_path).read_text())
    (buffer,) = gltf["buffers"]
    data = base64.b64decode(buffer.pop("uri").split(",", 1)[1])
    text = json.dumps(gltf, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def _png_claiming(width, height):
    """A real 8x8 PNG whose IHDR then claims width x height (the CRC left stale: nothing may decode it)."""
    checker = SOURCE_DIR / "assets" / "models" / "textures" / "uv_checker.gltf"
    uri = json.loads(checker.read_text())["images"][0]["uri"]
    data = bytearray(base64.b64decode(uri.split(",", 1)[1]))
    data[16:24] = struct.pack(">II", width, height)
    return bytes(data)


def hostile_files(folder):
    """name -> bytes: each one a file the page must refuse, or warn about, in one line naming it."""
    textures = SOURCE_DIR / "assets" / "models" / "textures"
    glb = _glb(textures / "uv_checker.gltf")
    (folder / "whole.glb").write_bytes(glb)  # the control: the same file untruncated loads
    scene = (SOURCE_DIR / "assets" / "scenes" / "default.json").read_bytes()
    cut = scene.index(b'"title": "') + len(b'"title": "')
    big = json.loads((textures / "uv_checker.gltf").read_text())
    # 16384 x 16384 RGBA: a gigabyte once decoded.
    big["images"][0]["uri"] = "data:image/png;base64," + base64.b64encode(_png_claiming(16384, 16384)).decode()
    return {
        "truncated.glb": glb[:len(glb) // 2],
        "nul.json": scene[:cut] + b"\0" + scene[cut:],
        "gigabyte-image.gltf": json.dumps(big).encode(),
    }


def open_file(app, path, refused):
    """Opens a file through #open-file and waits until the page has taken it: for a file to be refused (or
    warned about), until message() says something; for a good one, until the exported scene changes."""
    app.js("window.__sceneBefore = shadelab.exportScene(), true")
    app.page.set_file_input("#open-file", [path])
    if refused:
        app.page.wait_for("shadelab.message() !== ''", timeout=RENDER_TIMEOUT)
    else:
        app.page.wait_for("shadelab.message() !== '' || shadelab.exportScene() !== window.__sceneBefore",
                          timeout=RENDER_TIMEOUT)


def test_whole_glb_opens(app, binary, evidence):
    """c's control: the GLB the truncated one is cut from opens without a message."""
    hostile_files(evidence)
    native = subprocess.run([str(binary), "render", str(evidence / "whole.glb"), "--size", "32x18", "-o",
                             str(evidence / "whole-native.png")], capture_output=True, text=True, timeout=60)
    assert native.returncode == 0, f"the control GLB does not render natively: {native.stderr}"
    app.load_scene("default.json")
    open_file(app, evidence / "whole.glb", refused=False)
    assert app.message() == ""


@pytest.mark.parametrize("name", ["truncated.glb", "nul.json", "gigabyte-image.gltf"])
def test_hostile_file_is_one_line_and_the_page_renders_on(app, binary, evidence, name):
    path = evidence / name
    path.write_bytes(hostile_files(evidence)[name])
    app.load_scene("default.json")
    open_file(app, path, refused=True)
    message = app.message()
    (evidence / "message.txt").write_text(message)
    assert message and "\n" not in message and name in message, f"message() for {name}: {message!r}"
    # The page renders on: a shipped scene loads, clears the message and matches the native render.
    app.load_scene("default.json")
    assert app.message() == ""
    page_raster = app.image("raster", evidence / "page-raster.png")
    native = native_render(binary, SOURCE_DIR / "assets" / "scenes" / "default.json", "raster",
                           evidence / "native-raster.png")
    passed, summary = compare_gates(binary, page_raster, native, evidence, "raster")
    assert passed, f"after {name} the page's picture is outside the gates: {summary}"


# ---- the views ----


@pytest.mark.parametrize("mode", ["raster", "reference", "split", "difference", "global"])
def test_view_mode_is_accepted(app, evidence, mode):
    """Each view shows without an error (a screenshot of it is left behind); the raster view is restored."""
    app.load_scene("default.json")
    app.js(f"shadelab.setView({json.dumps(mode)})")
    app.page.screenshot(evidence / f"view-{mode}.png")
    assert app.message() == ""
    app.js("shadelab.setView('raster')")


def test_unknown_view_mode_throws(app):
    """The views' control: a mode the page does not have is refused, not ignored."""
    with pytest.raises(cdp.JsError):
        app.js("shadelab.setView('no-such-view')")


# ---- e. more controls: a material colour's strength, a light's intensity, adding and removing a light ----


def set_input(app, selector, value):
    """Sets an input's value and sends the 'input' event a user's drag sends."""
    app.js(f"(() => {{ const e = document.querySelector({json.dumps(selector)}); e.value = {json.dumps(str(value))};"
           f" e.dispatchEvent(new Event('input')); return true; }})()")
    app.js("new Promise((r) => requestAnimationFrame(() => r(true)))")


def select_centre_object(app):
    """Clicks the middle of the picture (the default scene has a sphere there); returns the state's selection."""
    x, y = app.page.center_of("#view")
    app.page.click(x, y)
    app.js("new Promise((r) => requestAnimationFrame(() => r(true)))")
    selected = app.js("document.querySelector('#selected-label').textContent")
    assert selected != "nothing", "clicking the middle of the default scene selected nothing"
    return selected


def test_the_outline_follows_the_selection(app, evidence):
    """A click outlines the object under it: the stage changes when another object is selected (the outline
    moved), and not when the same one is clicked again (the control: the comparison is not blind to noise)."""
    app.load_scene("default.json")
    rect = app.js("(() => { const r = document.querySelector('#stage').getBoundingClientRect();"
                  " return [r.left, r.top, r.width, r.height]; })()")
    left, top, w, h = rect

    def click_and_shoot(fx, fy, name):
        app.page.click(left + fx * w, top + fy * h)
        app.js("new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(true))))")
        label = app.js("document.querySelector('#selected-label').textContent")
        return label, app.page.screenshot(str(evidence / f"{name}.png"), clip=(left, top, w, h))

    green, a = click_and_shoot(0.52, 0.43, "green")   # the default scene's middle sphere
    again, b = click_and_shoot(0.52, 0.43, "green-again")
    red, c = click_and_shoot(0.19, 0.50, "red")       # the left sphere
    assert green == again and green != red, (green, again, red)
    assert a == b, "clicking the selected object again changed the picture"
    assert a != c, f"selecting {red} after {green} left the picture as it was: the outline did not follow"


def test_diffuse_strength_drives_the_picture(app, binary, evidence):
    def change():
        select_centre_object(app)
        set_input(app, "#md", 0.3)

    before, after = check_control_drives_picture(app, binary, evidence, change)
    changed = [(material_of(before, a).get("md"), material_of(after, b).get("md"))
               for a, b in zip(before["objects"], after["objects"])
               if material_of(before, a).get("md") != material_of(after, b).get("md")]
    assert len(changed) == 1 and max(changed[0][1]) == pytest.approx(0.3, abs=1e-6), changed


def test_light_intensity_drives_the_picture(app, binary, evidence):
    before, after = check_control_drives_picture(app, binary, evidence,
                                                 lambda: set_input(app, "#lights .light input[type=range]", -1))
    assert max(after["lights"][0]["color"]) == pytest.approx(0.5, abs=1e-6), after["lights"][0]
    assert after["lights"][1:] == before["lights"][1:]


def test_add_and_remove_light_drive_the_picture(app, binary, evidence):
    before, after = check_control_drives_picture(app, binary, evidence,
                                                 lambda: app.js("document.querySelector('#add-light').click(), true"))
    assert len(after["lights"]) == len(before["lights"]) + 1
    app.js("document.querySelector('#lights .light:last-child button').click(), true")
    app.js("new Promise((r) => requestAnimationFrame(() => r(true)))")
    assert app.export(evidence / "scene-removed.json")["lights"] == before["lights"]


# ---- f. the probe: the same report as the native probe of that pixel ----


def native_probe(scene_path, x, y, size, out):
    """shadelab.probe (the Python package over the same probe code) of one pixel, as JSON."""
    code = ("import json, sys, shadelab\n"
            "s = shadelab.Scene.load(sys.argv[1])\n"
            "print(json.dumps(shadelab.probe(s, (int(sys.argv[2]), int(sys.argv[3])), "
            "size=(int(sys.argv[4]), int(sys.argv[5])), ray_tree=True)))\n")
    env = dict(os.environ)
    python = os.environ.get("SHADELAB_PYTHONPATH", str(SOURCE_DIR / "build" / "python"))
    if not (Path(python) / "shadelab").is_dir():
        pytest.skip(f"{python}: no shadelab Python package (a build with SHADELAB_BUILD_PYTHON=OFF)")
    env["PYTHONPATH"] = python + (":" + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    p = subprocess.run(["/usr/bin/python3", "-c", code, str(scene_path), str(x), str(y), str(size[0]), str(size[1])],
                       capture_output=True, text=True, timeout=120, env=env)
    assert p.returncode == 0, f"the native probe failed (PYTHONPATH={python}): {p.stderr}"
    Path(out).write_text(p.stdout)
    return json.loads(p.stdout)


def report_differences(a, b, path="", rel=1e-5):
    """Where two probe reports differ: the same keys and strings, numbers within `rel` (the page's wasm and
    the native build may round a transcendental function's last bit differently)."""
    if isinstance(a, dict) and isinstance(b, dict):
        if a.keys() != b.keys():
            return [f"{path}: keys {sorted(set(a) ^ set(b))} in one only"]
        return [d for k in a for d in report_differences(a[k], b[k], f"{path}.{k}", rel)]
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return [f"{path}: {len(a)} items against {len(b)}"]
        return [d for i, (x, y) in enumerate(zip(a, b)) for d in report_differences(x, y, f"{path}[{i}]", rel)]
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return [] if math.isclose(a, b, rel_tol=rel, abs_tol=1e-6) else [f"{path}: {a} against {b}"]
    return [] if a == b else [f"{path}: {a!r} against {b!r}"]


@pytest.mark.parametrize("pixel", [(100, 90), (250, 60), (160, 170)])
def test_probe_matches_native(app, evidence, pixel):
    app.load_scene("default.json")
    scene = app.export(evidence / "scene.json")
    x, y = pixel
    page = json.loads(app.js(f"shadelab.probe({x}, {y})"))
    (evidence / "page-probe.json").write_text(json.dumps(page, indent=1))
    native = native_probe(evidence / "scene.json", x, y, SIZE, evidence / "native-probe.json")
    differences = report_differences(page, native)
    assert not differences, f"the page's probe of ({x}, {y}) differs from the native one: {differences[:5]}"
    # The ray tree comes with it, the reference's own: compared above, ray by ray, with the native one.
    assert not page["hit"] or page["ray_tree"]["rays"][0]["kind"] == "primary"
    # The control: the probe of another pixel is another report.
    other = json.loads(app.js(f"shadelab.probe({x + 7}, {y - 5})"))
    assert report_differences(other, native), "two pixels gave the same probe report: the comparison is blind"
    assert scene["objects"]


# ---- g. the shareable link ----


def test_link_round_trips(app, browser, evidence):
    app.load_scene("default.json")
    move_shininess(app, 4.0)
    app.page.select_option("#model", "blinn-phong")
    app.js("shadelab.setView('split')")
    edited = app.js("shadelab.exportScene()")
    (evidence / "edited.json").write_text(edited)
    link = app.js("shadelab.link()")
    (evidence / "link.txt").write_text(link)
    assert len(link) < 8000, f"the link is {len(link)} characters"
    page = browser.new_page()
    page.navigate(link, timeout=60)
    page.wait_for("window.shadelab && window.shadelab.ready && true", timeout=60)
    page.evaluate("shadelab.ready.then(() => true)", timeout=120)
    opened = page.evaluate("shadelab.exportScene()")
    (evidence / "opened.json").write_text(opened)
    assert page.evaluate("shadelab.message()") == ""
    assert opened == edited, "the scene the link opens differs from the one it was made of"
    assert page.evaluate("document.querySelector('#view-mode').value") == "split"
    page.screenshot(evidence / "opened.png")
    assert page.take_errors() == []
    # The control: the unedited default scene is not the edited one, so the equality above says something.
    page.evaluate("shadelab.loadScene('default.json')", timeout=60)
    assert page.evaluate("shadelab.exportScene()") != edited
    page.close()


@pytest.mark.parametrize("damage", ["truncated", "garbage", "altered", "foreign-folder", "missing-folder",
                                    "unknown-view"])
def test_bad_link_shows_the_message_and_the_default_scene(app, browser, evidence, damage):
    app.load_scene("default.json")
    move_shininess(app, 4.0)
    link = app.js("shadelab.link()")
    base, hash_ = link.split("#", 1)
    version, view, folder, scene = hash_.split(",")
    bad = {
        "truncated": f"{version},{view},{folder},{scene[:len(scene) // 2]}",
        "garbage": "v1,raster,%2Fassets%2Fscenes,@@not-base64@@",
        "altered": f"{version},{view},{folder},{scene[:20]}{'A' * 40}{scene[60:]}",
        "foreign-folder": f"{version},{view},%2Fetc,{scene}",
        "missing-folder": f"{version},{view},%2Fassets%2Fno-such-folder,{scene}",
        "unknown-view": f"{version},sideways,{folder},{scene}",
    }[damage]
    (evidence / "link.txt").write_text(f"{base}#{bad}")
    page = browser.new_page()
    page.navigate(f"{base}#{bad}", timeout=60)
    page.wait_for("window.shadelab && window.shadelab.ready && true", timeout=60)
    page.evaluate("shadelab.ready.then(() => true)", timeout=120)
    message = page.evaluate("shadelab.message()")
    (evidence / "message.txt").write_text(message)
    page.screenshot(evidence / "page.png")
    assert message.startswith("link: ") and "\n" not in message, f"a {damage} link: {message!r}"
    default = (SOURCE_DIR / "assets" / "scenes" / "default.json")
    shown = json.loads(page.evaluate("shadelab.exportScene()"))
    assert shown["title"] == json.loads(default.read_text())["title"], "a bad link did not show the default scene"
    assert page.evaluate("document.querySelector('#scene').value") == "default.json"
    assert page.take_errors() == []
    page.close()


def test_dropped_file_opens(app, evidence):
    """A scene file dropped on the page opens as the file input opens it; a bad one is one line."""
    app.load_scene("default.json")
    scene = json.loads((SOURCE_DIR / "assets" / "scenes" / "default.json").read_text())
    scene["title"] = "dropped here"
    drop = """(text, name) => {
        const data = new DataTransfer();
        data.items.add(new File([text], name, { type: 'application/json' }));
        document.querySelector('#view').dispatchEvent(new DragEvent('drop', { dataTransfer: data, bubbles: true }));
        return true; }"""
    app.page.call_function(drop, json.dumps(scene), "dropped.json")
    app.page.wait_for("JSON.parse(shadelab.exportScene()).title === 'dropped here'", timeout=RENDER_TIMEOUT)
    assert app.message() == ""
    app.page.call_function(drop, "{ not json", "broken.json")
    app.page.wait_for("shadelab.message() !== ''", timeout=RENDER_TIMEOUT)
    message = app.message()
    (evidence / "message.txt").write_text(message)
    assert "broken.json" in message and "\n" not in message, message
    assert json.loads(app.js("shadelab.exportScene()"))["title"] == "dropped here", "a bad drop lost the scene shown"


# ---- h. the Global view: the path tracer over the workers ----


def test_global_matches_native_path_tracer(app, binary, evidence):
    """The page's Global picture at 8 samples per pixel, its rows shared between the workers, against
    `shadelab render --renderer path --spp 8`; and at 4 samples it is another picture (the control)."""
    app.load_scene("default.json")
    page = evidence / "page-global.png"
    app._png("shadelab.globalDataUrl(8)", page)
    scene = SOURCE_DIR / "assets" / "scenes" / "default.json"
    native = evidence / "native-path.png"
    args = [str(binary), "render", str(scene), "--renderer", "path", "--spp", "8", "--size", f"{SIZE[0]}x{SIZE[1]}",
            "-o", str(native)]
    p = subprocess.run(args, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    equal, summary = compare_exact(page, native, evidence, "global")
    assert equal, f"the page's Global picture at 8 spp differs from the native path tracer's: {summary}"
    fewer = evidence / "page-global-4.png"
    app._png("shadelab.globalDataUrl(4)", fewer)
    equal, summary = compare_exact(fewer, native, evidence, "global-4")
    assert not equal, "4 samples gave the 8-sample picture: the comparison is blind"
    app.js("shadelab.setView('raster')")


def test_global_resumes_after_a_reference(app, evidence):
    """A reference asked for while Global runs takes the workers; Global then starts again by itself."""
    app.load_scene("default.json")
    app.js("shadelab.setView('global')")
    samples = "parseInt((document.querySelector('#progress').textContent.match(/(\\d+) samples/) || [0, 0])[1])"
    app.page.wait_for(f"{samples} >= 1", timeout=RENDER_TIMEOUT)
    app.image("reference", evidence / "reference.png")
    app.page.wait_for(f"{samples} >= 1", timeout=RENDER_TIMEOUT)
    app.page.screenshot(evidence / "global-again.png")
    app.js("shadelab.setView('raster')")
    assert app.js("document.querySelector('#progress').textContent") == "", "leaving Global left its progress line"
