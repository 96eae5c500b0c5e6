"""The pytest plugin's shadelab_regression fixture, run on inner test sessions (pytester): it passes on an
unchanged render, fails on a changed one (the negative control) leaving its evidence, and writes baselines only
with --shadelab-update-baselines."""

import json

import pytest

INNER = """
import shadelab

SCENE = {scene!r}

def test_render(shadelab_regression):
    scene = shadelab.Scene.load(SCENE)
    {edit}
    shadelab_regression.check(shadelab.render(scene, size=(96, 64)), "default-96")
"""


def write_test(pytester, source_dir, edit="pass"):
    scene = str(source_dir / "assets" / "scenes" / "default.json")
    pytester.makepyfile(test_inner=INNER.format(scene=scene, edit=edit))


def run(pytester, *args):
    return pytester.runpytest("-p", "shadelab.pytest_plugin", "-p", "no:cacheprovider", *args)


def test_baselines_are_written_only_on_purpose(pytester, source_dir):
    write_test(pytester, source_dir)
    baseline = pytester.path / "baselines" / "default-96.png"
    result = run(pytester)
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*no baseline*--shadelab-update-baselines*"])
    assert not baseline.exists()
    assert (pytester.path / "shadelab-evidence" / "test_render" / "default-96-render.png").exists()

    result = run(pytester, "--shadelab-update-baselines")
    result.assert_outcomes(passed=1)
    result.stdout.fnmatch_lines(["*shadelab: 1 baseline(s) rewritten*", "*default-96.png"])
    assert baseline.exists()
    meta = json.loads(baseline.with_suffix(".json").read_text())
    assert meta["gl_renderer"] and meta["gl_version"] and meta["size"] == [96, 64]


def test_unchanged_passes_changed_fails_with_evidence(pytester, source_dir):
    write_test(pytester, source_dir)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    baseline = pytester.path / "baselines" / "default-96.png"
    original = baseline.read_bytes()

    run(pytester).assert_outcomes(passed=1)
    evidence = pytester.path / "shadelab-evidence" / "test_render"
    assert not evidence.exists() or not any(evidence.iterdir())

    # The negative control: one light's colour changed. The check fails, says why, leaves the evidence and
    # does not touch the baseline.
    write_test(pytester, source_dir, edit="scene.lights[0].color = [0.2, 0.9, 0.9]")
    result = run(pytester)
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*the render differs from*", "*FAIL*", "*--shadelab-update-baselines*"])
    for suffix in ("render.png", "baseline.png", "heat.png", "report.json"):
        assert (evidence / f"default-96-{suffix}").exists(), suffix
    report = json.loads((evidence / "default-96-report.json").read_text())
    assert report["verdict"] == "fail" and report["reasons"]
    assert baseline.read_bytes() == original

    # Evidence goes where it is asked to.
    elsewhere = pytester.path / "elsewhere"
    run(pytester, f"--shadelab-evidence-dir={elsewhere}").assert_outcomes(failed=1)
    assert (elsewhere / "test_render" / "default-96-heat.png").exists()

    # Rewritten on purpose, the changed render becomes the baseline and passes.
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    assert baseline.read_bytes() != original
    run(pytester).assert_outcomes(passed=1)


def test_gates_can_be_loosened(pytester, source_dir):
    write_test(pytester, source_dir)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    pytester.makepyfile(test_inner=INNER.format(
        scene=str(source_dir / "assets" / "scenes" / "default.json"),
        edit="scene.lights[0].color = [0.2, 0.9, 0.9]").replace(
            '"default-96")', '"default-96", gates={"hard_max": 255, "max_fraction_over": 1.0})'))
    run(pytester).assert_outcomes(passed=1)


# -- names and clean-up: the plugin's files stay inside its folders -----------------------------------------------

ARRAY_TEST = """
import numpy as np
import shadelab

def test_render(shadelab_regression):
    shadelab_regression.check(shadelab.Image.from_array(np.full((4, 6, 3), 100, np.uint8)), {name!r})
"""

BAD_NAMES = ["../../../outside/x", "../outside/x", "..", ".", "sub/x", "/tmp/x", "a\\b", "x\0y", ""]


@pytest.mark.parametrize("name", BAD_NAMES)
def test_a_name_that_leaves_the_folders_is_refused(pytester, name):
    outside = pytester.path / "outside"
    outside.mkdir()
    (outside / "x-important.txt").write_text("not the plugin's")
    pytester.makepyfile(test_inner=ARRAY_TEST.format(name=name))
    for args in ((), ("--shadelab-update-baselines",)):
        result = run(pytester, *args)
        result.assert_outcomes(failed=1)
        result.stdout.fnmatch_lines(["*ValueError: shadelab_regression.check: name * must be a plain file name*"])
    assert (outside / "x-important.txt").read_text() == "not the plugin's"
    written = {p.relative_to(pytester.path).as_posix() for p in pytester.path.rglob("*") if p.is_file()}
    assert written == {"test_inner.py", "outside/x-important.txt"}, written


def test_the_name_check_sees_an_escape(pytester, monkeypatch):
    # The negative control: with the name check switched off for the inner session (it runs in this process),
    # "../outside/x" writes its baseline into outside/, next to the unrelated file: the check above would see it.
    import shadelab.pytest_plugin

    outside = pytester.path / "outside"
    outside.mkdir()
    (outside / "x-important.txt").write_text("not the plugin's")
    monkeypatch.setattr(shadelab.pytest_plugin, "_check_name", lambda name: name)
    pytester.makepyfile(test_inner=ARRAY_TEST.format(name="../outside/x"))
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    assert (outside / "x.png").exists() and (outside / "x.json").exists()


def test_clean_up_deletes_only_the_checks_own_evidence(pytester):
    pytester.makepyfile(test_inner=ARRAY_TEST.format(name="x"))
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    evidence = pytester.path / "shadelab-evidence" / "test_render"
    evidence.mkdir(parents=True)
    own = [evidence / f"x-{suffix}" for suffix in ("render.png", "baseline.png", "heat.png", "report.json")]
    others = [evidence / "x-b-render.png",  # check "x-b"'s evidence
              evidence / "x-notes.txt", evidence / "x-*", evidence / "y-render.png"]
    for path in own + others:
        path.write_text("old")
    # The negative control: the old clean-up, evidence.glob("x-*"), would have taken all but y's.
    assert set(evidence.glob("x-*")) == set(own) | set(others[:3])
    run(pytester).assert_outcomes(passed=1)
    assert not any(path.exists() for path in own)
    assert all(path.read_text() == "old" for path in others)
