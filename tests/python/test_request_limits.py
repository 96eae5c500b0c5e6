"""One render request for every front end: Python refuses each bad request of tests/data/bad_render_requests.json
with the field the table names and the very reason the command line gives for it (`spp: R` against `--spp: R`);
the table's valid controls render in both. The C++ side holds the CLI and viewer scripts to the same table
(tests/render_request_frontends_test.cpp)."""

import json
import re
import subprocess
import sys

import pytest

import shadelab

from conftest import SOURCE_DIR, sanitized

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


# -- max_memory: the command line's --max-memory -----------------------------------------------------------------

def _cli(binary, out_dir, scene, *flags, preexec_fn=None):
    return subprocess.run([str(binary), "render", str(scene), "-o", str(out_dir / "cli.png"), *flags],
                          capture_output=True, text=True, preexec_fn=preexec_fn)


def _after(text, marker):
    """The message from `marker` on, on its one line."""
    line = text.strip()
    assert "\n" not in line, line
    assert marker in line, line
    return line[line.index(marker):]


def test_a_limit_below_any_render_is_refused_as_the_cli_refuses_it(binary, out_dir):
    cli = _cli(binary, out_dir, SCENE, "--size", "16384x16384", "--renderer", "path", "--max-memory", "2G")
    assert cli.returncode == 2, cli.stderr
    reason = _after(cli.stderr, "--max-memory: ")[len("--max-memory: "):]
    assert reason.startswith("must be at least ") and reason.endswith("got 2048 MiB")
    with pytest.raises(ValueError) as raised:
        shadelab.render(str(SCENE), (16384, 16384), renderer="path", max_memory="2G")
    assert str(raised.value) == f"max_memory: {reason}"
    # An int is bytes; a string is read as --max-memory reads it, a bare number as MiB.
    with pytest.raises(ValueError, match=r"^max_memory: must be at least \d+ MiB for a 64x48 raster render, "
                                         r"whatever the scene; got 4096 bytes$"):
        shadelab.render(str(SCENE), (64, 48), max_memory=4096)
    assert shadelab.render(str(SCENE), (64, 48), max_memory="4096").size == (64, 48)
    assert shadelab.render(str(SCENE), (64, 48), max_memory=4096 << 20).size == (64, 48)
    for bad in ("lots", "0", "-1G", "1T"):
        cli = _cli(binary, out_dir, SCENE, "--max-memory", bad)
        with pytest.raises(ValueError) as raised:
            shadelab.render(str(SCENE), (64, 48), max_memory=bad)
        assert f"--{raised.value}" in cli.stderr.replace("--max-memory", "--max_memory"), cli.stderr


def test_a_render_over_the_limit_is_refused_as_the_cli_refuses_it(binary, out_dir):
    # The sky's path render needs its environment sampler beyond what any render of the size needs: with the
    # limit at that least, both front ends refuse it from the same estimate, before any pixel.
    sky = SOURCE_DIR / "assets" / "scenes" / "pbr-sky.json"
    flags = ("--size", "1280x720", "--renderer", "path")
    least = re.search(r"must be at least (\d+) MiB", _cli(binary, out_dir, sky, *flags, "--max-memory", "1").stderr)
    limit = f"{least.group(1)}M"
    cli = _cli(binary, out_dir, sky, *flags, "--max-memory", limit)
    assert cli.returncode == 1, cli.stderr
    reason = _after(cli.stderr, "a 1280x720 path render of this scene needs about ")
    assert reason.endswith(f"over the limit of {least.group(1)} MiB (--max-memory)")
    for scene in (str(sky), shadelab.Scene.load(sky)):
        with pytest.raises(shadelab.InputError) as raised:
            shadelab.render(scene, (1280, 720), renderer="path", max_memory=limit)
        assert str(raised.value) == reason.replace("(--max-memory)", "(max_memory)")


AS_LIMIT = 8 << 30  # an address-space limit (ulimit -v): the default becomes at most 6 GiB in both


def _limited():
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (AS_LIMIT, AS_LIMIT))


def test_the_default_is_the_clis(binary, out_dir):
    if sanitized():
        pytest.skip("ASan reserves terabytes of address space: no ulimit -v under it")
    # A 16384² path render (about 20 GiB) under each front end's default limit, in processes whose address
    # space is capped, so that neither can start it on a machine with the memory for it.
    cli = _cli(binary, out_dir, SCENE, "--size", "16384x16384", "--renderer", "path", preexec_fn=_limited)
    assert cli.returncode == 1, cli.stderr
    reason = _after(cli.stderr, "a 16384x16384 path render")
    code = ("import shadelab, sys\n"
            "try:\n"
            f"    shadelab.render({str(SCENE)!r}, (16384, 16384), renderer='path')\n"
            "except shadelab.InputError as e:\n"
            "    print(e)\n")
    py = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, preexec_fn=_limited)
    assert py.returncode == 0, py.stderr
    assert py.stdout.strip() == reason.replace("(--max-memory)", "(max_memory)")
    limit = int(re.search(r"over the limit of (\d+) MiB", reason).group(1))
    assert limit <= (AS_LIMIT >> 20) * 3 // 4
    # In this process, without the cap, the default is the same function's answer.
    assert shadelab._shadelab._memory_limit(None) >= limit << 20


def _write_big_hdr(path, w=4096, h=4096):
    """A run-length .hdr of one colour, w x h (16 Mpixels: 192 MiB of floats) in about 1 MiB."""
    line = bytes([2, 2, w >> 8, w & 255])
    for v in (128, 140, 160, 129):
        for x in range(0, w, 127):
            line += bytes([128 + min(127, w - x), v])
    path.write_bytes(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w) + line * h)


# Renders argv[1] under max_memory=argv[2], then prints its peak resident memory in MiB: VmHWM, this process's
# own (ru_maxrss would count the forking parent's too, carried across exec).
PEAK = ("import re, shadelab, sys\n"
        "try:\n"
        "    shadelab.render(sys.argv[1], (64, 48), renderer='trace', max_memory=sys.argv[2])\n"
        "    print('rendered')\n"
        "except shadelab.InputError as e:\n"
        "    print(e)\n"
        "print(int(re.search(r'VmHWM:\\s*(\\d+)', open('/proc/self/status').read()).group(1)) // 1024)\n")


def test_the_environment_map_is_counted(out_dir):
    _write_big_hdr(out_dir / "big.hdr")
    scene = out_dir / "big.json"
    scene.write_text(json.dumps({"model": "pbr", "environment": {"hdr": "big.hdr"}, "lights": [],
                                 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]}))
    refused = subprocess.run([sys.executable, "-c", PEAK, str(scene), "100M"], capture_output=True, text=True)
    message, peak = refused.stdout.splitlines()
    assert re.fullmatch(r".*big\.hdr: a 4096x4096 environment map needs about \d+ MiB to read and prefilter, "
                        r"over the limit of 100 MiB \(max_memory\)", message), refused.stdout + refused.stderr
    # The negative control: with room for it the map is decoded, and the process holds its 192 MiB of floats.
    rendered = subprocess.run([sys.executable, "-c", PEAK, str(scene), "1G"], capture_output=True, text=True)
    done, rendered_peak = rendered.stdout.splitlines()
    assert done == "rendered", rendered.stdout + rendered.stderr
    if not sanitized():  # ASan's shadow and quarantine are its own
        assert int(peak) < 100 < 192 < int(rendered_peak), (peak, rendered_peak)
