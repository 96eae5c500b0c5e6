"""shadelab's pytest plugin: screenshot tests against baseline PNGs under the gates of design.md §4.

    def test_default_scene(shadelab_regression):
        image = shadelab.render(shadelab.data.scene("default"), size=(320, 180))
        shadelab_regression.check(image, "default-320")

The baseline is <test file's folder>/baselines/default-320.png (ini option shadelab_baseline_dir). A check
that fails, a render of another size than its baseline included, writes its evidence (the render, the
baseline, the heatmap and the JSON report) beside the test in shadelab-evidence/, a folder the plugin keeps
out of git with a .gitignore of "*" (--shadelab-evidence-dir or ini shadelab_evidence_dir to move it), then
fails the test in plain words. A check's name is a plain file name, so that its files stay inside those
folders: a name with '/' or '\\', or "." or "..", is refused with a ValueError. Before a check runs, the plugin
deletes that check's own evidence from an earlier run, by the four exact names it writes, and nothing else.

A render made with coverage=True carries the object each pixel shows, so a failure also says which objects the
differing pixels lie on (by name when check() is given the scene: check(image, name, scene=scene)). The baseline
PNG carries no object ids: the render's own say where the pixels are.

Baselines are written only with --shadelab-update-baselines (every check's) or
--shadelab-update-baselines=failed (only those that fail), never by a failing test, and never when the new
PNG is byte for byte the old one. A baseline's sidecar <name>.json records the GL_RENDERER and version it was
made with; a raster render from another GL_RENDERER checked against it raises a ShadelabWarning.

Loaded by the `pytest11` entry point once the package is pip-installed; from a build tree, pass
-p shadelab.pytest_plugin (or list it in a conftest's pytest_plugins).
"""

from __future__ import annotations

import json
import os
import re
import shlex
import warnings
from pathlib import Path
from typing import TYPE_CHECKING, Any, Mapping

import pytest

import shadelab

if TYPE_CHECKING:
    from _pytest.terminal import TerminalReporter  # not exported as pytest.TerminalReporter before pytest 7.4
    from numpy.typing import ArrayLike

    from ._types import StrPath
    from .typing import ImageLike

_UPDATE = "--shadelab-update-baselines"
_MODES = ("all", "failed")  # what --shadelab-update-baselines[=MODE] rewrites: every check's baseline, or the failing
_SPELT = pytest.StashKey[bool]()  # set when pytest_load_initial_conftests spelt the bare flag "=all"


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("shadelab", "shadelab screenshot tests")
    # No `choices`: pytest's early, partial parses would reject a test path that follows the bare flag; the bare
    # flag becomes "=all" in pytest_load_initial_conftests, and pytest_configure checks the word.
    group.addoption(_UPDATE, nargs="?", const="all", default=None, metavar="all|failed",
                    help="write the renders of shadelab_regression checks as their baselines (on purpose only): "
                         "all of them, or =failed for only the checks that fail. A byte-identical baseline is "
                         "never rewritten")
    group.addoption("--shadelab-evidence-dir", default=None,
                    help="folder for failing checks' evidence (default: shadelab-evidence/ beside each test)")
    parser.addini("shadelab_baseline_dir", "baseline folder, relative to each test file's folder", default="baselines")
    parser.addini("shadelab_evidence_dir", "evidence folder for failing checks (default: beside each test)",
                  default="")


def pytest_load_initial_conftests(early_config: pytest.Config, parser: pytest.Parser, args: list[str]) -> None:
    # The bare flag takes no value: spelt "=all" here, before pytest's full parse, a test path after it stays a
    # test path instead of being read as the flag's value.
    args[:] = [f"{_UPDATE}=all" if arg == _UPDATE else arg for arg in args]
    early_config.stash[_SPELT] = True


def pytest_configure(config: pytest.Config) -> None:
    mode = config.getoption(_UPDATE)
    if mode is not None and _SPELT not in config.stash and _gave_back_a_test_path(config, mode):
        mode = "all"
        config.option.shadelab_update_baselines = mode
    if mode is not None and mode not in _MODES:
        raise pytest.UsageError(f"{_UPDATE}: expected all or failed (or no value, for all), got {mode!r}")


def _gave_back_a_test_path(config: pytest.Config, value: str) -> bool:
    """Whether the bare flag swallowed the test path after it; if so, gives the path back to the run's paths.

    Loaded from a conftest's pytest_plugins, the plugin is registered while pytest loads the conftests, so its
    pytest_load_initial_conftests never runs: the bare flag stays bare and pytest's full parse reads
    `--shadelab-update-baselines tests/` as the value "tests/". The words pytest parsed, its addopts first as
    it reads them, show whether the value followed the bare flag ("=some", one word with the flag, stays a
    usage error)."""
    words = [*shlex.split(os.environ.get("PYTEST_ADDOPTS", "")), *config.getini("addopts"),
             *config.invocation_params.args]
    at = next((i for i in range(len(words) - 1) if words[i] == _UPDATE and words[i + 1] == value), None)
    if at is None:
        return False
    paths = list(config.option.file_or_dir or [])
    if paths:  # back where it stood: after the paths given before the flag
        before = list(words[:at])
        place = 0
        for path in paths:
            if path not in before:
                break
            before.remove(path)
            place += 1
        config.args = paths[:place] + [value] + paths[place:]
    else:  # without it pytest fell back to testpaths or the current folder
        config.args = [value]
        source = getattr(pytest.Config, "ArgsSource", None)  # pytest >= 7.2
        if source is not None:
            config.args_source = source.ARGS
    config.option.file_or_dir = list(config.args)
    return True


def _safe(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text).strip("_")


# The files a failing check leaves as evidence, <name>-<suffix>: the only files the plugin ever deletes.
_EVIDENCE = ("render.png", "baseline.png", "heat.png", "report.json")
_EVIDENCE_FOLDER = "shadelab-evidence"


def _check_name(name: object) -> str:
    """`name` when it names a file inside the plugin's folders: a non-empty string with no path separator, no
    NUL, and neither "." nor ".."; else one ValueError saying so (TypeError for a name that is no string)."""
    if not isinstance(name, str):
        raise TypeError(f"shadelab_regression.check: name must be a string, got {type(name).__name__}")
    separators = {"/", "\\", os.sep, os.altsep or "/", "\0"}
    if not name or name in (".", "..") or any(s in name for s in separators):
        raise ValueError(f"shadelab_regression.check: name {name!r} must be a plain file name (no '/', '\\', "
                         f"'..' or absolute path): baselines and evidence stay inside their folders")
    return name


def _write_json(path: Path, data: Any) -> None:
    # The binary's atomic writer and its rules: never over a file a live scene reads, never a device.
    shadelab._shadelab._write_file(os.fspath(path), (json.dumps(data, indent=2) + "\n").encode())


def _size_text(size: tuple[int, int] | list[int]) -> str:
    return f"{size[0]}x{size[1]}"


_CHANNELS = {"R": "red", "G": "green", "B": "blue", "A": "alpha"}  # the report's channel letters, in words


def _plain_reasons(report: dict[str, Any]) -> list[str]:
    """The failed gates in plain words. A baseline PNG has no object ids (coverage), so every pixel is compared
    under the gates: what the binary's report calls the "interior" region is here the whole image."""
    region, gates = report["regions"]["interior"], report["gates"]
    lines = []
    allowed = int(gates["max_fraction_over"] * region["pixels"] + 1e-9)
    if region["over_threshold"] > allowed:
        lines.append(f"{region['over_threshold']} of {region['pixels']} pixels "
                     f"({100 * region['fraction_over_threshold']:.2f}%) differ by more than {gates['threshold']}/255 "
                     f"in a colour channel; at most {allowed} ({100 * gates['max_fraction_over']:.2f}%) may")
    if region["over_hard_max"] > 0:
        channel = _CHANNELS.get(region["max_channel"], region["max_channel"])
        lines.append(f"{region['over_hard_max']} pixels differ by more than {gates['hard_max']}/255, which no pixel "
                     f"may; the largest difference is {region['max']}/255 in the {channel} channel at pixel "
                     f"(x={region['max_x']}, y={region['max_y']}) from the top left")
    if gates["max_mean"] is not None and region["mean"] > gates["max_mean"]:
        lines.append(f"the pixels differ by {region['mean']:.3f}/255 on average; at most {gates['max_mean']}/255 "
                     f"is allowed")
    return lines or list(report["reasons"])  # any other gate in the binary's words


def _object_labels(scene: shadelab.Scene | None) -> list[str]:
    """Labels for coverage ids 1, 2, ...: "'red plastic' (sphere 1)", or "sphere 3" for an unnamed object, as
    the viewer and the binary label them (scene.objects lists spheres, planes and meshes in coverage id order)."""
    if scene is None:
        return []
    labels: list[str] = []
    counts: dict[str, int] = {}  # objects of each kind so far
    for obj in scene.to_dict()["objects"]:
        kind = str(obj.get("type", "object"))
        counts[kind] = counts.get(kind, 0) + 1
        where = f"{kind} {counts[kind]}"
        labels.append(f"{obj['name']!r} ({where})" if obj.get("name") else where)
    return labels


def _where_they_differ(image: shadelab.Image, baseline: Path, report: dict[str, Any],
                       scene: shadelab.Scene | None) -> str | None:
    """Which objects the differing pixels lie on, one line, from the render's coverage (the baseline PNG has
    none); for a render without coverage, how to get that line; None for an image read from a file or array."""
    import numpy as np

    if image.coverage is None:
        if image.source in ("file", "array"):
            return None  # no scene behind it to name
        return ("to learn which objects these pixels lie on, render with coverage=True and pass the scene: "
                "check(image, name, scene=scene)")
    ours, theirs = image.to_uint8(), shadelab.Image.open(str(baseline)).to_uint8()
    channels = min(ours.shape[2], theirs.shape[2])
    difference = np.abs(ours[..., :channels].astype(np.int16) - theirs[..., :channels]).max(axis=2)
    threshold = report["gates"]["threshold"]
    differing, what = difference > threshold, f"by more than {threshold}/255"  # the pixels the first gate counts
    if not differing.any():
        differing, what = difference > 0, "at all"  # a failure of the mean gate alone
    ids, counts = np.unique(image.coverage[differing], return_counts=True)
    order = np.argsort(-counts, kind="stable")
    labels = _object_labels(scene)

    def label(object_id: int, first: bool) -> str:
        if object_id == 0:
            return "the background"
        if object_id > len(labels):  # no scene given (or fewer objects than the render had): its place in the list
            return f"scene.objects[{object_id - 1}]"
        return f"object {labels[object_id - 1]}" if first else labels[object_id - 1]

    total = int(counts.sum())
    top = [(int(ids[i]), int(counts[i])) for i in order]  # the most differing pixels first
    shown, rest = top[:3], top[3:]
    others = [f"{n} on {label(i, False)}" for i, n in shown[1:]]
    if rest:
        others.append(f"{sum(n for _, n in rest)} elsewhere")
    if total == 1:
        line = f"the one pixel that differs {what} lies on {label(top[0][0], True)}"
    elif len(top) == 1:
        line = f"the {total} pixels that differ {what} all lie on {label(top[0][0], True)}"
    elif 2 * top[0][1] > total:
        line = (f"the {total} pixels that differ {what} lie mostly on {label(top[0][0], True)}: {top[0][1]} of "
                f"them; " + ", ".join(others))
    else:
        line = (f"the {total} pixels that differ {what} lie on several objects: {top[0][1]} on "
                f"{label(top[0][0], True)}, " + ", ".join(others))
    if scene is None and any(i > 0 for i, _ in top):
        line += " (check(image, name, scene=scene) names them)"
    return line


class ImageRegression:
    """The shadelab_regression fixture: check(image, name) against <baselines>/<name>.png."""

    def __init__(self, request: pytest.FixtureRequest) -> None:
        self._request = request
        self._config = request.config
        self._test_dir = Path(request.node.path).parent

    @property
    def update_mode(self) -> str | None:
        """"all" or "failed" under --shadelab-update-baselines[=failed] (check() writes baselines), else None."""
        mode: str | None = self._config.getoption(_UPDATE)
        return mode

    @property
    def updating(self) -> bool:
        """True when pytest runs with --shadelab-update-baselines (either mode): check() may write baselines."""
        return self.update_mode is not None

    def baseline_path(self, name: str) -> Path:
        """The baseline PNG of the check `name` (a plain file name: no path separator, not "." or "..")."""
        folder: str = self._config.getini("shadelab_baseline_dir")
        return self._test_dir / folder / f"{_check_name(name)}.png"

    def _evidence_root(self) -> tuple[Path, bool]:
        """The evidence folder for every test, and whether it is the plugin's own (the default)."""
        chosen = self._config.getoption("--shadelab-evidence-dir") or self._config.getini("shadelab_evidence_dir")
        return (Path(chosen), False) if chosen else (self._test_dir / _EVIDENCE_FOLDER, True)

    def evidence_dir(self) -> Path:
        """Where this test's failing checks leave their evidence."""
        return self._evidence_root()[0] / _safe(self._request.node.nodeid.split("::", 1)[-1])

    def _make_evidence_dir(self) -> Path:
        # A .gitignore of "*" keeps the evidence out of git: in the default folder always, in a chosen one when
        # the plugin creates it (a folder of yours keeps its own rules).
        root, own = self._evidence_root()
        own = own or not root.exists()
        evidence = self.evidence_dir()
        evidence.mkdir(parents=True, exist_ok=True)
        ignore = root / ".gitignore"
        if own and not ignore.exists():
            shadelab._shadelab._write_file(os.fspath(ignore), b"# shadelab's pytest plugin: test evidence\n*\n")
        return evidence

    def check(self, image: ImageLike, name: str | None = None, *,
              gates: Mapping[str, float | None] | None = None,
              scene: shadelab.Scene | None = None) -> shadelab.CompareReport:
        """Compares `image` (a shadelab.Image, or anything shadelab.compare takes) with the baseline `name`
        (default: the test's name) under `gates` (design.md §4's by default; a dict overrides some) and
        returns the CompareReport. Fails the test, leaving the evidence, when the gates are not met or the sizes
        differ; for a render made with coverage=True the failure says which objects the differing pixels lie
        on, named from `scene` (the scene rendered) when given. With --shadelab-update-baselines it first
        rewrites the baseline (=failed: only when the check would fail; never when the PNG is byte for byte the
        same); the report is then against the baseline as it stands."""
        if scene is not None and not isinstance(scene, shadelab.Scene):
            raise TypeError(f"shadelab_regression.check: scene must be a shadelab.Scene, got {type(scene).__name__}")
        name = _safe(self._request.node.name) if name is None else _check_name(name)
        baseline = self.baseline_path(name)
        if not isinstance(image, shadelab.Image):
            image = _as_image(image)
        stem = self.evidence_dir() / name
        for suffix in _EVIDENCE:  # an earlier failure's evidence, by the exact names it was written under
            old = Path(f"{stem}-{suffix}")
            if old.is_file() or old.is_symlink():
                old.unlink()
        if self.updating:
            self._update(image, baseline, gates)
        if not baseline.exists():
            self._make_evidence_dir()
            image.save(f"{stem}-render.png")
            pytest.fail(f"{name}: there is no baseline {baseline} yet; the render is {stem}-render.png. Run pytest "
                        f"with {_UPDATE} to make it the baseline.", pytrace=False)
        self._warn_if_other_renderer(image, baseline, name)
        outcome = self._compare(image, baseline, gates)
        if isinstance(outcome, str) or not outcome.passed:
            evidence = self._make_evidence_dir()
            image.save(f"{stem}-render.png")
            shadelab._shadelab._write_file(f"{stem}-baseline.png", baseline.read_bytes())
            files = f"{name}-render.png, -baseline.png"
            if isinstance(outcome, str):
                _write_json(Path(f"{stem}-report.json"), {"verdict": "fail", "pass": False, "reasons": [outcome],
                                                           "image_b": str(baseline)})
                files += ", -report.json"
                why = f"{outcome}.\n"
            else:
                outcome.heatmap.save(f"{stem}-heat.png")
                _write_json(Path(f"{stem}-report.json"), outcome.report)
                files += ", -heat.png (where they differ), -report.json (the numbers)"
                where = _where_they_differ(image, baseline, outcome.report, scene)
                lines = "".join(f"  - {line}\n" for line in [*_plain_reasons(outcome.report), where] if line)
                why = f"the render differs from the baseline {baseline}:\n{lines}"
            pytest.fail(f"{name}: {why}evidence in {evidence}: {files}\n"
                        f"If the change is intended, rewrite the baseline with {_UPDATE}=failed.", pytrace=False)
        return outcome

    def _compare(self, image: shadelab.Image, baseline: Path,
                 gates: Mapping[str, float | None] | None) -> shadelab.CompareReport | str:
        """The comparison, or in words why there can be none: a baseline of another size, or no PNG."""
        try:
            expected = shadelab.Image.open(str(baseline))
        except shadelab.InputError as e:
            return f"the baseline cannot be read ({e})"
        if expected.size != image.size:
            return (f"the render is {_size_text(image.size)} pixels but the baseline {baseline} is "
                    f"{_size_text(expected.size)}, so they cannot be compared pixel by pixel; render at "
                    f"size={tuple(expected.size)}, or rewrite the baseline if the new size is intended")
        return shadelab.compare(image, str(baseline), gates)

    def _update(self, image: shadelab.Image, baseline: Path, gates: Mapping[str, float | None] | None) -> None:
        png = image.to_png()
        if baseline.is_file():
            if baseline.read_bytes() == png:
                if not baseline.with_suffix(".json").exists():
                    self._write_sidecar(image, baseline)
                return  # byte for byte the same: never rewritten
            if self.update_mode == "failed":
                outcome = self._compare(image, baseline, gates)
                if not isinstance(outcome, str) and outcome.passed:
                    return
        baseline.parent.mkdir(parents=True, exist_ok=True)
        shadelab._shadelab._write_file(os.fspath(baseline), png)
        self._write_sidecar(image, baseline)
        rewritten: list[str] = self._config.stash.setdefault(_rewritten_key, [])
        rewritten.append(str(baseline))

    def _write_sidecar(self, image: shadelab.Image, baseline: Path) -> None:
        meta = {"shadelab": shadelab.__version__, "size": list(image.size), "encoding": image.encoding,
                "source": image.source}
        if image.source == "raster":
            meta.update(shadelab.default_renderer().info)  # one GL context per process: the one that rendered
        _write_json(baseline.with_suffix(".json"), meta)

    def _warn_if_other_renderer(self, image: shadelab.Image, baseline: Path, name: str) -> None:
        if image.source != "raster":
            return  # the tracers' pixels do not depend on the GL driver
        try:
            made_with = json.loads(baseline.with_suffix(".json").read_text()).get("gl_renderer")
        except (OSError, ValueError, AttributeError):
            return  # no sidecar, or not one of ours: nothing recorded to compare with
        current = shadelab.default_renderer().info.get("gl_renderer")
        if made_with and current and made_with != current:
            warnings.warn(f"{name}: the baseline {baseline} was made with GL_RENDERER {made_with!r}, this render "
                          f"with {current!r}; differences may come from the GPU or driver rather than your change",
                          shadelab.ShadelabWarning, stacklevel=3)


def _as_image(x: StrPath | ArrayLike) -> shadelab.Image:
    if isinstance(x, (str, os.PathLike)):
        return shadelab.Image.open(os.fspath(x))
    return shadelab.Image.from_array(x)


_rewritten_key = pytest.StashKey[list[str]]()  # the baselines this run rewrote


@pytest.fixture
def shadelab_regression(request: pytest.FixtureRequest) -> ImageRegression:
    """Compares renders with baseline PNGs: shadelab_regression.check(image, name)."""
    return ImageRegression(request)


def pytest_terminal_summary(terminalreporter: TerminalReporter, config: pytest.Config) -> None:
    rewritten: list[str] = config.stash.get(_rewritten_key, [])
    if rewritten:
        terminalreporter.write_sep("=", f"shadelab: {len(rewritten)} baseline(s) rewritten ({_UPDATE})")
        for path in rewritten:
            terminalreporter.write_line(path)
