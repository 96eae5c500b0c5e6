"""shadelab's pytest plugin: screenshot tests against baseline PNGs under the gates of design.md §4.

    def test_default_scene(shadelab_regression):
        image = shadelab.render("assets/scenes/default.json", size=(320, 180))
        shadelab_regression.check(image, "default-320")

The baseline is <test file's folder>/baselines/default-320.png (ini option shadelab_baseline_dir). A check
that fails writes its evidence, the render, the baseline, the heatmap and the JSON report, beside the test
in shadelab-evidence/ (--shadelab-evidence-dir or ini shadelab_evidence_dir to move it), then fails the test
with the binary's summary. A check's name is a plain file name, so that its files stay inside those folders:
a name with '/' or '\\', or "." or "..", is refused with a ValueError. Before a check runs, the plugin deletes
that check's own evidence from an earlier run, by the four exact names it writes, and nothing else.
Baselines are written only with --shadelab-update-baselines, never by a failing test; a baseline's sidecar
<name>.json records the GL_RENDERER and version it was made with.

Loaded by the `pytest11` entry point once the package is pip-installed; from a build tree, pass
-p shadelab.pytest_plugin (or list it in a conftest's pytest_plugins).
"""

from __future__ import annotations

import json
import os
import re
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


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("shadelab", "shadelab screenshot tests")
    group.addoption(_UPDATE, action="store_true", default=False,
                    help="write the renders of shadelab_regression checks as their baselines (on purpose only)")
    group.addoption("--shadelab-evidence-dir", default=None,
                    help="folder for failing checks' evidence (default: shadelab-evidence/ beside each test)")
    parser.addini("shadelab_baseline_dir", "baseline folder, relative to each test file's folder", default="baselines")
    parser.addini("shadelab_evidence_dir", "evidence folder for failing checks (default: beside each test)",
                  default="")


def _safe(text: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", text).strip("_")


# The files a failing check leaves as evidence, <name>-<suffix>: the only files the plugin ever deletes.
_EVIDENCE = ("render.png", "baseline.png", "heat.png", "report.json")


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


class ImageRegression:
    """The shadelab_regression fixture: check(image, name) against <baselines>/<name>.png."""

    def __init__(self, request: pytest.FixtureRequest) -> None:
        self._request = request
        self._config = request.config
        self._test_dir = Path(request.node.path).parent

    @property
    def updating(self) -> bool:
        """True when pytest runs with --shadelab-update-baselines: check() writes baselines instead."""
        return bool(self._config.getoption(_UPDATE))

    def baseline_path(self, name: str) -> Path:
        """The baseline PNG of the check `name` (a plain file name: no path separator, not "." or "..")."""
        folder: str = self._config.getini("shadelab_baseline_dir")
        return self._test_dir / folder / f"{_check_name(name)}.png"

    def evidence_dir(self) -> Path:
        """Where this test's failing checks leave their evidence."""
        chosen = self._config.getoption("--shadelab-evidence-dir") or self._config.getini("shadelab_evidence_dir")
        root = Path(chosen) if chosen else self._test_dir / "shadelab-evidence"
        return root / _safe(self._request.node.nodeid.split("::", 1)[-1])

    def check(self, image: ImageLike, name: str | None = None, *,
              gates: Mapping[str, float | None] | None = None) -> shadelab.CompareReport | None:
        """Compares `image` (a shadelab.Image, or anything shadelab.compare takes) with the baseline `name`
        (default: the test's name) under `gates` (design.md §4's by default; a dict overrides some) and
        returns the CompareReport. Fails the test, leaving the evidence, when the gates are not met. With
        --shadelab-update-baselines it writes the baseline instead and returns None."""
        name = _safe(self._request.node.name) if name is None else _check_name(name)
        baseline = self.baseline_path(name)
        if not isinstance(image, shadelab.Image):
            image = _as_image(image)
        if self.updating:
            self._write_baseline(image, baseline)
            return None
        evidence = self.evidence_dir()
        stem = evidence / name
        for suffix in _EVIDENCE:  # an earlier failure's evidence, by the exact names it was written under
            old = Path(f"{stem}-{suffix}")
            if old.is_file() or old.is_symlink():
                old.unlink()
        if not baseline.exists():
            evidence.mkdir(parents=True, exist_ok=True)
            image.save(f"{stem}-render.png")
            pytest.fail(f"no baseline {baseline}; the render is {stem}-render.png. Run pytest with {_UPDATE} to "
                        f"make it the baseline.", pytrace=False)
        report = shadelab.compare(image, str(baseline), gates)
        if not report.passed:
            evidence.mkdir(parents=True, exist_ok=True)
            image.save(f"{stem}-render.png")
            shadelab._shadelab._write_file(f"{stem}-baseline.png", Path(baseline).read_bytes())
            report.heatmap.save(f"{stem}-heat.png")
            _write_json(Path(f"{stem}-report.json"), report.report)
            pytest.fail(f"{name}: the render differs from {baseline}:\n{report.summary}"
                        f"evidence: {stem}-render.png, -baseline.png, -heat.png, -report.json\n"
                        f"(if the change is intended, rewrite it with {_UPDATE})", pytrace=False)
        return report

    def _write_baseline(self, image: shadelab.Image, baseline: Path) -> None:
        baseline.parent.mkdir(parents=True, exist_ok=True)
        image.save(str(baseline))
        meta = {"shadelab": shadelab.__version__, "size": list(image.size), "encoding": image.encoding,
                "source": image.source}
        if image.source == "raster":
            meta.update(shadelab.default_renderer().info)  # one GL context per process: the one that rendered
        _write_json(baseline.with_suffix(".json"), meta)
        rewritten: list[str] = self._config.stash.setdefault(_rewritten_key, [])
        rewritten.append(str(baseline))


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
