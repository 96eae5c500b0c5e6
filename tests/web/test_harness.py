"""The web harness's self-test: CDP and headless Chromium read WebGL2 pixels exactly, input reaches the page,
and console errors are caught; with negative controls (no WebGL2, a wrong colour, a wait that never ends)."""

import json
import time
from pathlib import Path

import pytest

import cdp
import png
from serve import Server

FIXTURES = Path(__file__).resolve().parent / "fixtures"
CLEAR = [51, 102, 204, 255]  # the fixture's left half, a glClear
DRAWN = [255, 128, 0, 255]  # its right half, a GLSL ES 3.00 program's output


@pytest.fixture(scope="module")
def server():
    with Server(FIXTURES) as s:
        yield s


@pytest.fixture
def page(browser, server):
    page = browser.new_page()
    page.navigate(server.url("webgl2.html"))
    yield page
    browser.call("Target.closeTarget", {"targetId": page.target})


def check_webgl2_colours(page, evidence, left=CLEAR, right=DRAWN):
    """The canvas's pixels through readPixels and through a screenshot, exactly; raises AssertionError."""
    got = {"readPixels": {}, "screenshot": {}}
    try:
        got["context"] = page.evaluate("window.contextKind")
        for x in (0, 31, 32, 63):
            got["readPixels"][x] = page.evaluate(f"window.readPixel({x}, 24)")
    except cdp.JsError as e:
        got["error"] = str(e)
    shot = png.decode(page.screenshot(evidence / "screenshot.png", clip=(0, 0, 64, 48)), "screenshot")
    for x in (0, 31, 32, 63):
        got["screenshot"][x] = shot[24, x].tolist()
    (evidence / "pixels.json").write_text(json.dumps(got, indent=1))
    assert got.get("context") == "webgl2" and "error" not in got, f"no WebGL2: {got}"
    expected = {0: left, 31: left, 32: right, 63: right}
    assert got["readPixels"] == expected, f"readPixels {got['readPixels']} != {expected}"
    assert got["screenshot"] == expected, f"screenshot {got['screenshot']} != {expected}"


def test_webgl2_pixels_are_exact(page, evidence):
    check_webgl2_colours(page, evidence)
    assert page.take_errors() == []


def test_wrong_colour_fails(page, evidence):
    with pytest.raises(AssertionError, match="readPixels"):
        check_webgl2_colours(page, evidence, left=[51, 102, 205, 255])
    page.take_errors()


def test_page_without_webgl2_fails(browser, server, evidence):
    page = browser.new_page()
    page.navigate(server.url("no-webgl2.html"))
    # The 2D canvas shows the same colours in a screenshot, but the WebGL2 check must not pass on it.
    shot = png.decode(page.screenshot(evidence / "no-webgl2.png", clip=(0, 0, 64, 48)))
    assert shot[24, 0].tolist() == CLEAR and shot[24, 63].tolist() == DRAWN
    with pytest.raises(AssertionError, match="no WebGL2"):
        check_webgl2_colours(page, evidence)
    browser.call("Target.closeTarget", {"targetId": page.target})


def test_click_key_drag_and_range_reach_the_page(page):
    page.click_selector("#button")
    page.click_selector("#button")
    for key in "03a5Z":
        page.press_key(key)
    page.drag(10, 10, 50, 40, steps=4)
    assert page.set_range("#range", 7.25) == "7.25"
    seen = page.evaluate("window.seen")
    assert seen["clicks"] == 2
    assert seen["keys"] == list("03a5Z")
    assert seen["range"] == [["input", "7.25"], ["change", "7.25"]]
    assert seen["drag"][0] == ["down", 10, 10] and seen["drag"][-1] == ["up", 50, 40]
    assert [e[0] for e in seen["drag"][1:-1]] == ["move"] * 4, seen["drag"]
    assert page.take_errors() == []


def test_file_input_gets_the_file(page, evidence):
    path = evidence / "hello.txt"
    path.write_text("hello from the test")
    page.set_file_input("#file", [path])
    files = page.wait_for("window.seen.files.length && window.seen.files", timeout=10)
    assert files == [["hello.txt", 19, "hello from the test"]]


def test_console_errors_and_uncaught_exceptions_are_collected(page):
    assert page.take_errors() == []
    page.click_selector("#error-button")
    page.click_selector("#throw-button")
    page.wait_for("new Promise(r => setTimeout(() => r(true), 50))")
    errors = page.take_errors()
    assert any("fixture console error" in e for e in errors), errors
    assert any("fixture uncaught" in e for e in errors), errors
    assert page.take_errors() == []


def test_js_exceptions_become_python_exceptions(page):
    with pytest.raises(cdp.JsError, match="nope"):
        page.evaluate("(() => { throw new Error('nope'); })()")
    with pytest.raises(cdp.JsError, match="rejected here"):
        page.evaluate("Promise.reject('rejected here')")
    assert page.evaluate("Promise.resolve({a: [1, 2]})") == {"a": [1, 2]}


def test_waits_end_at_their_timeout(page):
    with pytest.raises(cdp.CdpTimeout):
        page.evaluate("new Promise(() => {})", timeout=1)
    with pytest.raises(cdp.CdpTimeout):
        page.wait_for("false", timeout=0.5)
    # The browser still answers after an abandoned wait.
    assert page.evaluate("6 * 7") == 42


def test_a_crashed_page_fails_at_once(browser, server):
    page = browser.new_page()
    page.navigate(server.url("webgl2.html"))
    try:
        page.call("Page.crash", timeout=2)
    except cdp.CdpError:
        pass  # the reply may never come: the renderer is gone
    started = time.monotonic()
    with pytest.raises(cdp.CdpError, match="crashed"):
        page.evaluate("new Promise(() => {})", timeout=20)
    assert time.monotonic() - started < 10
    # The browser and its other pages go on.
    assert browser.new_page().evaluate("1 + 1") == 2


def test_served_mime_types(server, tmp_path):
    import urllib.request

    with urllib.request.urlopen(server.url("webgl2.html")) as r:
        assert r.headers["Content-Type"].startswith("text/html")
    for name, mime in [("a.wasm", "application/wasm"), ("a.js", "text/javascript"),
                       ("a.json", "application/json"), ("a.glb", "model/gltf-binary"),
                       ("a.gltf", "model/gltf+json")]:
        (tmp_path / name).write_bytes(b"x")
    with Server(tmp_path) as s:
        for name, mime in [("a.wasm", "application/wasm"), ("a.js", "text/javascript"),
                           ("a.json", "application/json"), ("a.glb", "model/gltf-binary"),
                           ("a.gltf", "model/gltf+json")]:
            with urllib.request.urlopen(s.url(name)) as r:
                assert r.headers["Content-Type"] == mime, name


# The processes of a group still running (zombies do not count): the same /proc reading Browser.close waits on.
living_processes_in_group = cdp.living_in_group


def test_browser_is_killed_on_failure(evidence):
    group = None
    with pytest.raises(RuntimeError):
        with cdp.Browser(evidence) as b:
            group = b.proc.pid
            assert living_processes_in_group(group), "the control: Chromium runs inside the block"
            raise RuntimeError("a test failing inside the browser's block")
    assert living_processes_in_group(group) == []
    assert (evidence / "chromium.log").stat().st_size > 0


def test_browser_dies_with_the_test_process(evidence):
    """A test runner that kills pytest (ctest's timeout) leaves no Chromium behind."""
    import signal
    import subprocess
    import sys

    here = Path(__file__).resolve().parent
    script = (f"import sys, time; sys.path.insert(0, {str(here)!r}); import cdp\n"
              f"b = cdp.Browser({str(evidence)!r}).__enter__(); print(b.proc.pid, flush=True); time.sleep(60)")
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    try:
        group = int(child.stdout.readline())
        assert living_processes_in_group(group), "the control: Chromium runs while its parent does"
    finally:
        child.send_signal(signal.SIGKILL)
        child.wait()
    deadline = time.monotonic() + 10
    while living_processes_in_group(group) and time.monotonic() < deadline:
        time.sleep(0.1)
    assert living_processes_in_group(group) == []
