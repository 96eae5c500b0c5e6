"""The pytest plugin's shadelab_regression fixture, run on inner test sessions (pytester): it passes on an
unchanged render, fails on a changed one (the negative control) leaving its evidence in a folder git ignores,
fails in plain words on a render of another size, names the objects the differing pixels lie on, writes
baselines only with --shadelab-update-baselines (=failed: only the failing ones; never a byte-identical one; the
bare flag also when a conftest loads the plugin), returns a report in every mode and warns when the GL_RENDERER
differs from the baseline's."""

import json
import re
import shutil
import subprocess

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
    result.stdout.fnmatch_lines(["*there is no baseline*--shadelab-update-baselines*"])
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
    result.stdout.fnmatch_lines(["*default-96: the render differs from the baseline*default-96.png:",
                                 "*  - * of 6144 pixels (*%) differ by more than 3/255 in a colour channel; at most 6*",
                                 "*evidence in *test_render: default-96-render.png, -baseline.png, -heat.png*",
                                 "*rewrite the baseline with --shadelab-update-baselines=failed*"])
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


# -- sizes, modes, reports, evidence out of git, renderer warnings, plain words -------------------------------------

SIZED = """
import shadelab

def test_render(shadelab_regression):
    scene = shadelab.data.scene("default")
    {edit}
    report = shadelab_regression.check(shadelab.render(scene, size={size}), "default", gates={gates})
    assert isinstance(report, shadelab.CompareReport) and report.passed
    with open("report-max.txt", "w") as f:
        f.write(str(report.report["regions"]["interior"]["max"]))
"""


def write_sized(pytester, size=(96, 64), edit="pass", gates=None, name="test_inner"):
    pytester.makepyfile(**{name: SIZED.format(size=size, edit=edit, gates=gates)})


def test_a_size_mismatch_is_an_ordinary_failure_with_evidence(pytester):
    write_sized(pytester)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    run(pytester).assert_outcomes(passed=1)  # the negative control: the same size passes
    write_sized(pytester, size=(80, 64))
    result = run(pytester)
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*default: the render is 80x64 pixels but the baseline *default.png is 96x64, so "
                                 "they cannot be compared pixel by pixel; render at size=(96, 64), or rewrite the "
                                 "baseline if the new size is intended.",
                                 "*evidence in *: default-render.png, -baseline.png, -report.json",
                                 "*--shadelab-update-baselines=failed*"])
    assert "InputError" not in result.stdout.str() and "Traceback" not in result.stdout.str()
    evidence = pytester.path / "shadelab-evidence" / "test_render"
    assert shadelab_image_size(evidence / "default-render.png") == (80, 64)
    assert shadelab_image_size(evidence / "default-baseline.png") == (96, 64)
    report = json.loads((evidence / "default-report.json").read_text())
    assert report["verdict"] == "fail" and "cannot be compared" in report["reasons"][0]
    # With =failed the new size is a failing check, so its baseline is rewritten.
    run(pytester, "--shadelab-update-baselines=failed").assert_outcomes(passed=1)
    assert shadelab_image_size(pytester.path / "baselines" / "default.png") == (80, 64)


def shadelab_image_size(path):
    import shadelab

    return tuple(shadelab.Image.open(str(path)).size)


def test_check_returns_a_report_in_every_mode(pytester):
    write_sized(pytester)
    report_max = pytester.path / "report-max.txt"
    for args in (("--shadelab-update-baselines",), ("--shadelab-update-baselines=failed",), ()):
        report_max.unlink(missing_ok=True)
        run(pytester, *args).assert_outcomes(passed=1)
        assert report_max.read_text() == "0", args  # the same render as the baseline: no pixel differs
    # The negative control: a changed render within loosened gates. =failed keeps the baseline (the check passes),
    # and the report is the real comparison with it: it sees the difference.
    write_sized(pytester, edit="scene.lights[0].color = [0.8, 0.8, 0.7]",
                gates={"hard_max": 255, "max_fraction_over": 1.0})
    run(pytester, "--shadelab-update-baselines=failed").assert_outcomes(passed=1)
    assert int(report_max.read_text()) > 0


def test_failed_mode_rewrites_only_failing_baselines(pytester):
    pytester.makepyfile(test_inner="""
import shadelab

def test_both(shadelab_regression):
    scene = shadelab.data.scene("default")
    shadelab_regression.check(shadelab.render(scene, size=(64, 48)), "same")
    scene.lights[0].color = {color}
    shadelab_regression.check(shadelab.render(scene, size=(64, 48)), "changed")
""".format(color=None).replace("scene.lights[0].color = None", "pass"))
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    baselines = pytester.path / "baselines"
    before = {p.name: (p.stat().st_mtime_ns, p.read_bytes()) for p in baselines.iterdir()}
    assert set(before) == {"same.png", "same.json", "changed.png", "changed.json"}
    pytester.makepyfile(test_inner=(pytester.path / "test_inner.py").read_text().replace(
        "    pass\n", "    scene.lights[0].color = [0.2, 0.9, 0.9]\n"))
    run(pytester).assert_outcomes(failed=1)  # the negative control: "changed" fails without an update
    result = run(pytester, "--shadelab-update-baselines=failed")
    result.assert_outcomes(passed=1)
    result.stdout.fnmatch_lines(["*shadelab: 1 baseline(s) rewritten*", "*changed.png"])
    after = {p.name: (p.stat().st_mtime_ns, p.read_bytes()) for p in baselines.iterdir()}
    assert after["same.png"] == before["same.png"] and after["same.json"] == before["same.json"]
    assert after["changed.png"][1] != before["changed.png"][1]
    run(pytester).assert_outcomes(passed=1)


def test_an_unchanged_baseline_is_never_rewritten(pytester):
    write_sized(pytester)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    baseline = pytester.path / "baselines" / "default.png"
    sidecar = baseline.with_suffix(".json")
    stamps = (baseline.stat().st_mtime_ns, baseline.stat().st_ino, sidecar.stat().st_mtime_ns)
    # The bare flag followed by a test path: the path stays a path.
    result = run(pytester, "--shadelab-update-baselines", "test_inner.py")
    result.assert_outcomes(passed=1)
    assert "baseline(s) rewritten" not in result.stdout.str()
    assert (baseline.stat().st_mtime_ns, baseline.stat().st_ino, sidecar.stat().st_mtime_ns) == stamps
    # The negative control: a changed render is rewritten (the atomic writer makes a new file).
    write_sized(pytester, edit="scene.lights[0].color = [0.2, 0.9, 0.9]")
    run(pytester, "--shadelab-update-baselines").stdout.fnmatch_lines(["*1 baseline(s) rewritten*"])
    assert (baseline.stat().st_mtime_ns, baseline.stat().st_ino) != stamps[:2]


def test_an_unknown_update_mode_is_a_usage_error(pytester):
    write_sized(pytester)
    result = run(pytester, "--shadelab-update-baselines=some")
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    result.stderr.fnmatch_lines(["*--shadelab-update-baselines: expected all or failed (or no value, for all), "
                                 "got 'some'"])
    assert not (pytester.path / "baselines").exists()
    run(pytester, "--shadelab-update-baselines=all").assert_outcomes(passed=1)  # the negative control


def git_untracked(folder):
    out = subprocess.run(["git", "status", "--porcelain", "--untracked-files=all"], cwd=folder, check=True,
                         capture_output=True, text=True).stdout
    return sorted(line[3:] for line in out.splitlines())


def test_evidence_stays_out_of_git(pytester):
    if not shutil.which("git"):
        pytest.skip("git is not installed")
    subprocess.run(["git", "init", "-q"], cwd=pytester.path, check=True)
    write_sized(pytester)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    write_sized(pytester, edit="scene.lights[0].color = [0.2, 0.9, 0.9]")
    run(pytester).assert_outcomes(failed=1)
    evidence = pytester.path / "shadelab-evidence"
    assert (evidence / ".gitignore").read_text().splitlines()[-1] == "*"
    assert (evidence / "test_render" / "default-heat.png").exists()
    untracked = git_untracked(pytester.path)
    assert not [p for p in untracked if p.startswith("shadelab-evidence")], untracked
    assert "baselines/default.png" in untracked  # baselines are meant to be committed
    # The negative control: without the plugin's .gitignore, git would list the evidence.
    (evidence / ".gitignore").unlink()
    assert "shadelab-evidence/test_render/default-heat.png" in git_untracked(pytester.path)

    # A chosen folder the plugin creates is ignored too; one that exists already keeps its own rules.
    made = pytester.path / "made-by-plugin"
    run(pytester, f"--shadelab-evidence-dir={made}").assert_outcomes(failed=1)
    assert (made / ".gitignore").exists()
    yours = pytester.path / "yours"
    yours.mkdir()
    run(pytester, f"--shadelab-evidence-dir={yours}").assert_outcomes(failed=1)
    assert not (yours / ".gitignore").exists() and (yours / "test_render" / "default-heat.png").exists()


def test_a_baseline_from_another_gl_renderer_warns(pytester):
    write_sized(pytester)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    result = run(pytester, "-W", "always")
    result.assert_outcomes(passed=1, warnings=0)
    assert "GL_RENDERER" not in result.stdout.str()  # the negative control: the same renderer, no warning
    sidecar = pytester.path / "baselines" / "default.json"
    meta = json.loads(sidecar.read_text())
    real = meta["gl_renderer"]
    meta["gl_renderer"] = "Another GPU 9000"
    sidecar.write_text(json.dumps(meta))
    result = run(pytester, "-W", "always")
    result.assert_outcomes(passed=1, warnings=1)
    result.stdout.fnmatch_lines([f"*ShadelabWarning: default: the baseline *default.png was made with GL_RENDERER "
                                 f"'Another GPU 9000', this render with {real!r}; differences may come from the GPU "
                                 f"or driver rather than your change"])


def test_failure_messages_are_in_plain_words(pytester):
    write_sized(pytester)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    write_sized(pytester, edit="scene.lights[0].color = [0.2, 0.9, 0.9]")
    result = run(pytester)
    result.assert_outcomes(failed=1)
    failure = result.stdout.str()
    for jargon in ("interior", "band", "no coverage", "coverage id", "coverage differs"):
        assert jargon not in failure, jargon
    assert re.search(r"pixels differ by more than 16/255, which no pixel may; the largest difference is \d+/255 in "
                     r"the (red|green|blue) channel at pixel \(x=\d+, y=\d+\) from the top left", failure), failure
    # A render without coverage says how to learn the objects (the word is render()'s keyword here).
    assert "to learn which objects these pixels lie on, render with coverage=True and pass the scene" in failure
    # The negative control: the binary's own words, in the evidence's report, do use them.
    report = (pytester.path / "shadelab-evidence" / "test_render" / "default-report.json").read_text()
    assert "interior" in report and "coverage" in report


# -- the objects the differing pixels lie on -----------------------------------------------------------------------

OBJECTS = """
import shadelab

def test_render(shadelab_regression):
    scene = shadelab.data.scene("default")
    {edit}
    image = shadelab.render(scene, size=(96, 64), coverage={coverage})
    shadelab_regression.check(image, "default", scene={scene})
"""


def write_objects(pytester, edit="pass", coverage=True, scene="scene"):
    pytester.makepyfile(test_inner=OBJECTS.format(edit=edit, coverage=coverage, scene=scene))


def objects_line(result):
    """The failure's line about objects, after checking that it counts the pixels the first gate counts."""
    text = result.stdout.str()
    over = re.search(r"- (\d+) of 6144 pixels \(.*\) differ by more than 3/255", text)
    line = next(line for line in text.splitlines() if "pixels that differ by more than 3/255" in line)
    counted = re.search(r"- the (\d+) pixels that differ by more than 3/255 ", line)
    assert over and counted and counted.group(1) == over.group(1), text
    return line


def test_the_failure_names_the_object_the_pixels_lie_on(pytester):
    # The default scene's objects: spheres 'red plastic', 'shiny blue', 'matte green', 'gold', 'mirror', then the
    # plane 'floor'. The baseline PNG has no object ids; the render's coverage says where the pixels are.
    write_objects(pytester)
    run(pytester, "--shadelab-update-baselines").assert_outcomes(passed=1)
    write_objects(pytester, edit="scene.objects[0].material.md = (0.1, 0.8, 0.1)")
    result = run(pytester)
    result.assert_outcomes(failed=1)
    line = objects_line(result)
    assert re.search(r"lie (mostly )?on object 'red plastic' \(sphere 1\)", line), line
    assert "shiny blue" not in line and "floor" not in line, line
    # The negative control: another object's material changed, the line names that one and not the first.
    write_objects(pytester, edit="scene.objects[1].material.md = (0.8, 0.8, 0.1)")
    result = run(pytester)
    result.assert_outcomes(failed=1)
    line = objects_line(result)
    assert re.search(r"lie (mostly )?on object 'shiny blue' \(sphere 2\)", line), line
    assert "red plastic" not in line, line
    # Without the scene, the objects are named by their place in scene.objects, with a word on how to name them.
    write_objects(pytester, edit="scene.objects[1].material.md = (0.8, 0.8, 0.1)", scene=None)
    line = objects_line(run(pytester))
    assert re.search(r"lie (mostly )?on scene\.objects\[1\]", line), line
    assert line.endswith("(check(image, name, scene=scene) names them)"), line
    # Without coverage there is nothing to name them by: the failure says how to get it instead.
    write_objects(pytester, edit="scene.objects[1].material.md = (0.8, 0.8, 0.1)", coverage=False)
    result = run(pytester)
    result.assert_outcomes(failed=1)
    assert "pixels that differ by more than" not in result.stdout.str()
    result.stdout.fnmatch_lines(["*  - to learn which objects these pixels lie on, render with coverage=True and "
                                 "pass the scene: check(image, name, scene=scene)"])


def test_a_scene_that_is_no_scene_is_refused(pytester):
    write_objects(pytester, scene="scene.to_dict()")
    result = run(pytester, "--shadelab-update-baselines")
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*TypeError: shadelab_regression.check: scene must be a shadelab.Scene, got dict"])
    assert not (pytester.path / "baselines").exists()


# -- the bare flag when a conftest loads the plugin -----------------------------------------------------------------

def test_the_bare_flag_works_when_a_conftest_loads_the_plugin(pytester):
    # No -p: the conftest's pytest_plugins loads the plugin, after pytest_load_initial_conftests has run.
    pytester.makeconftest('pytest_plugins = ["shadelab.pytest_plugin"]')
    pytester.makepyfile(test_inner=ARRAY_TEST.format(name="x"), test_other=ARRAY_TEST.format(name="other"))
    baselines = pytester.path / "baselines"

    def conftest_run(*args):
        return pytester.runpytest("-p", "no:cacheprovider", *args)

    # The negative control: without the flag, nothing is written.
    conftest_run("test_inner.py").assert_outcomes(failed=1)
    assert not baselines.exists()
    # The bare flag followed by a test path: the path stays a path (only that file runs) and "all" is the mode.
    result = conftest_run("--shadelab-update-baselines", "test_inner.py")
    result.assert_outcomes(passed=1)
    result.stdout.fnmatch_lines(["*shadelab: 1 baseline(s) rewritten*", "*x.png"])
    assert sorted(p.name for p in baselines.iterdir()) == ["x.json", "x.png"]
    # A path before it and one after: both run, in the order given.
    (baselines / "x.png").unlink()
    result = conftest_run("-v", "test_other.py", "--shadelab-update-baselines", "test_inner.py")
    result.assert_outcomes(passed=2)
    result.stdout.fnmatch_lines(["*test_other.py::test_render PASSED*", "*test_inner.py::test_render PASSED*"])
    assert (baselines / "x.png").exists() and (baselines / "other.png").exists()
    # The bare flag last, and =failed, work as they do under -p; an unknown mode is still a usage error.
    for path in baselines.iterdir():
        path.unlink()
    conftest_run("--shadelab-update-baselines").assert_outcomes(passed=2)
    assert (baselines / "x.png").exists() and (baselines / "other.png").exists()
    conftest_run("--shadelab-update-baselines=failed", "test_inner.py").assert_outcomes(passed=1)
    result = conftest_run("--shadelab-update-baselines=some", "test_inner.py")
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    result.stderr.fnmatch_lines(["*expected all or failed (or no value, for all), got 'some'"])


def test_the_bare_flag_under_a_conftest_needs_the_path_given_back(pytester, monkeypatch):
    # The negative control for the test above: without giving the path back, pytest's parse reads the test path as
    # the flag's value, and the run stops with a usage error.
    import shadelab.pytest_plugin

    monkeypatch.setattr(shadelab.pytest_plugin, "_gave_back_a_test_path", lambda config, value: False)
    pytester.makeconftest('pytest_plugins = ["shadelab.pytest_plugin"]')
    pytester.makepyfile(test_inner=ARRAY_TEST.format(name="x"))
    result = pytester.runpytest("-p", "no:cacheprovider", "--shadelab-update-baselines", "test_inner.py")
    assert result.ret == pytest.ExitCode.USAGE_ERROR
    result.stderr.fnmatch_lines(["*expected all or failed (or no value, for all), got 'test_inner.py'"])
    assert not (pytester.path / "baselines").exists()
    # Under -p the plugin spells the bare flag "=all" before the parse, so it needs no giving back.
    run(pytester, "--shadelab-update-baselines", "test_inner.py").assert_outcomes(passed=1)
