"""Fixtures shared by the Python package's tests: where the sources, the binary and each test's output live.

ctest (tests/python/CMakeLists.txt) sets SHADELAB_SOURCE_DIR, SHADELAB_BINARY and SHADELAB_TEST_OUTPUT; run by
hand, they default to this checkout and its build/ folder."""

import os
import re
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("SHADELAB_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BUILD_DIR = SOURCE_DIR / "build"
SCENES = sorted((SOURCE_DIR / "assets" / "scenes").glob("*.json"))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def binary():
    path = Path(os.environ.get("SHADELAB_BINARY", BUILD_DIR / "shadelab"))
    if not path.exists():
        pytest.skip(f"no shadelab binary at {path}")
    return path


@pytest.fixture
def out_dir(request):
    """A folder for this test's files, unique to it: build/test-output/<ctest name>/<test name>/."""
    root = Path(os.environ.get("SHADELAB_TEST_OUTPUT", BUILD_DIR / "test-output" / "python"))
    path = root / re.sub(r"[^A-Za-z0-9_.-]+", "_", request.node.name)
    path.mkdir(parents=True, exist_ok=True)
    return path


def run_binary(binary, *args):
    """Runs the shadelab binary; returns the completed process (raises with its stderr on failure)."""
    p = subprocess.run([str(binary), *map(str, args)], capture_output=True, text=True)
    if p.returncode not in (0, 1):
        raise AssertionError(f"shadelab {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}")
    return p


def sanitized():
    import shadelab

    return bool(shadelab.build_info["sanitize"])
