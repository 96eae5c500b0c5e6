"""Fixtures shared by the web tests: each test's evidence folder, and one headless Chromium per test module.

ctest (tests/CMakeLists.txt) sets SHADELAB_TEST_OUTPUT; run by hand, evidence goes under build/test-output/web/."""

import os
import re
import shutil
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

import cdp  # noqa: E402

SOURCE_DIR = Path(__file__).resolve().parents[2]
OUTPUT_ROOT = Path(os.environ.get("SHADELAB_TEST_OUTPUT", SOURCE_DIR / "build" / "test-output" / "web"))


def evidence_folder(name):
    """An empty folder for one test's (or one module's) files: <test output>/<name>/ ('/' nests folders)."""
    path = OUTPUT_ROOT.joinpath(*(re.sub(r"[^A-Za-z0-9_.-]+", "_", part) for part in name.split("/")))
    shutil.rmtree(path, ignore_errors=True)
    path.mkdir(parents=True)
    return path


@pytest.fixture
def evidence(request):
    """This test's evidence folder: what it compared, so that a failure can be read afterwards."""
    return evidence_folder(request.node.name)


@pytest.fixture(scope="module")
def browser(request):
    """One headless Chromium for the whole module (its log in <test output>/<module>-browser/)."""
    with cdp.Browser(evidence_folder(Path(request.module.__file__).stem + "-browser"), width=1024,
                     height=768) as b:
        yield b
