"""One render request for every front end: Python refuses each bad request of tests/data/bad_render_requests.json
with the field the table names and the very reason the command line gives for it (`spp: R` against `--spp: R`);
the table's valid controls render in both. The C++ side holds the CLI and viewer scripts to the same table
(tests/render_request_frontends_test.cpp)."""

import json
import re
import subprocess

import pytest

import shadelab

from conftest import SOURCE_DIR

CASES = json.loads((SOURCE_DIR / "tests" / "data" / "bad_render_requests.json").read_text())["cases"]
SCENE = SOURCE_DIR / "assets" / "scenes" / "default.json"


def _keywords(case):
    kwargs = {k: v for k, v in case.items() if k not in ("what", "field")}
    kwargs["size"] = tuple(kwargs.get("size", (8, 6)))
    return kwargs


def _flags(case):
    flags = []
    for key, value in case.items():
        if key in ("what", "field"):
            continue
        flags += ["--" + key.replace("_", "-"), "x".join(map(str, value)) if key == "size" else str(value)]
    if "size" not in case:
        flags += ["--size", "8x6"]
    return flags


@pytest.mark.parametrize("case", CASES, ids=[c["what"] for c in CASES])
def test_python_and_the_cli_give_the_same_field_and_reason(case, binary, out_dir):
    cli = subprocess.run([str(binary), "render", str(SCENE), "-o", str(out_dir / "cli.png"), *_flags(case)],
                         capture_output=True, text=True)
    if case["field"] is None:
        assert cli.returncode == 0, cli.stderr
        image = shadelab.render(str(SCENE), **_keywords(case))
        assert image.width == case["size"][0]
        return
    assert cli.returncode == 2, cli.stderr
    flag = "--" + case["field"].replace("_", "-")
    match = re.search(re.escape(flag) + r": (.*)$", cli.stderr.strip(), re.M)
    assert match, f"the command line did not name {flag}: {cli.stderr}"
    with pytest.raises(ValueError) as raised:
        shadelab.render(str(SCENE), **_keywords(case))
    assert str(raised.value) == f"{case['field']}: {match.group(1)}"


def test_both_is_refused_with_the_way_to_compare():
    with pytest.raises(ValueError, match=r"^renderer: 'both' is the command line's side-by-side picture"):
        shadelab.render(str(SCENE), (8, 6), renderer="both")


def test_a_nul_in_a_word_is_escaped_and_the_rest_kept():
    # what() is a C string: the message once ended at the NUL, "renderer: unknown value 'trace".
    with pytest.raises(ValueError) as raised:
        shadelab.render(str(SCENE), (8, 6), renderer="trace\0 and more")
    assert str(raised.value).startswith("renderer: unknown value 'trace\\x00 and more'; expected ")
    # Negative control: the same call without the NUL is refused with the whole word too.
    with pytest.raises(ValueError, match=r"^renderer: unknown value 'trace and more'; expected "):
        shadelab.render(str(SCENE), (8, 6), renderer="trace and more")


def test_a_message_quoting_bytes_that_are_not_utf8_reaches_python(out_dir):
    # A JSON parse error quotes the stray byte; a what() that is not UTF-8 once reached Python as "".
    scene = out_dir / "bytes.json"
    scene.write_bytes(b'{"shadelab": 1, "lights": "\xff"}')
    with pytest.raises(Exception) as raised:
        shadelab.render(str(scene), (8, 6), renderer="trace")
    message = str(raised.value)
    assert "bytes.json" in message and "\\xff" in message, repr(message)
