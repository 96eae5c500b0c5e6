"""Builds shadelab's compiled module for `pip install .` with CMake: the project's own build, configured without
tests and viewer, target shadelab_python only, for the Python that runs pip (a venv's too). Everything comes
from Debian packages (scripts/install-deps.sh); nothing is downloaded. Metadata lives in pyproject.toml, but for
the version, which is CMakeLists.txt's project(VERSION), as the binary's --version and the module's build_info
have it.

The wheel is portable (docs/python.md "Installing"): tinygltf and stb are compiled into the module and libEGL is
loaded at run time, and tools/wheel_libs.py copies the libraries the module still links beyond the manylinux set
(OpenEXR, zlib), with their licences, into shadelab/_libs/ and tags the wheel manylinux_2_<glibc>. Editable
installs are refused: they would build into the source tree; use the CMake build tree (PYTHONPATH=build/python).

Set CMAKE_CXX_COMPILER_LAUNCHER=ccache (and CMAKE_C_COMPILER_LAUNCHER) in the environment to reuse a cache,
SHADELAB_CMAKE_ARGS for more -D options, and SHADELAB_PREBUILT_MODULE to package a module already built by a
CMake build tree (Release, no sanitizers) instead of building one; the wheel test does that."""

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py
try:
    from setuptools.command.bdist_wheel import bdist_wheel  # setuptools 70.1 and later
except ImportError:
    from wheel.bdist_wheel import bdist_wheel  # Debian 12: python3-wheel

ROOT = Path(__file__).resolve().parent
sys.path.insert(0, str(ROOT / "tools"))
sys.dont_write_bytecode = True  # no tools/__pycache__ in the source tree
import wheel_libs  # noqa: E402  (tools/, beside this file)

# The platform tag the module built in this run can claim (wheel_libs.platform_tag), set by build_ext.
PORTABLE_TAG = []

# The package data behind shadelab.data: assets/ files copied into the package as shadelab/assets/, in the
# repository's layout, so that the scenes' relative paths to their models and sky hold. src/python/CMakeLists.txt
# copies the same files into the build tree's package.
ASSET_PATTERNS = ("scenes/*.json", "models/**/*.gltf", "environments/*.hdr")


def asset_files():
    """The assets/ files the package ships, relative to assets/, sorted."""
    assets = ROOT / "assets"
    return sorted({p.relative_to(assets) for pattern in ASSET_PATTERNS for p in assets.glob(pattern) if p.is_file()})


def cmake_project_version():
    """The VERSION of the project() call in CMakeLists.txt."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"^\s*project\(\s*shadelab\b[^)]*?\bVERSION\s+([0-9][0-9.]*)", text, re.MULTILINE)
    if not match:
        raise RuntimeError("CMakeLists.txt has no project(shadelab VERSION x.y.z)")
    return match.group(1)


(ROOT / "build-pip").mkdir(exist_ok=True)  # egg_base below must exist before setuptools writes into it


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if self.inplace or getattr(self, "editable_mode", False):
            raise SystemExit("shadelab: editable installs (pip install -e) are not supported: they would build into the "
                             "source tree. Build with CMake and use PYTHONPATH=build/python, or pip install . "
                             "(docs/python.md)")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(self.cmake_module(), target)
        try:
            copies = wheel_libs.bundle(target, target.parent)
            PORTABLE_TAG[:] = [wheel_libs.platform_tag(copies)]
        except RuntimeError as e:  # one line naming what is missing, not a traceback
            raise SystemExit(f"shadelab: {e}") from None
        print(f"shadelab: packaged {target.name} with {len(copies) - 1} libraries in shadelab/{wheel_libs.FOLDER}/, "
              f"tag {PORTABLE_TAG[0]}", file=sys.stderr)

    def cmake_module(self):
        """The compiled module: SHADELAB_PREBUILT_MODULE's, or one built now with CMake (several minutes)."""
        prebuilt = os.environ.get("SHADELAB_PREBUILT_MODULE")
        if prebuilt:
            if not Path(prebuilt).is_file():
                raise SystemExit(f"shadelab: SHADELAB_PREBUILT_MODULE: {prebuilt}: no such file")
            return Path(prebuilt)
        build_dir = Path(self.build_temp).resolve() / "cmake"
        configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                     "-DSHADELAB_BUILD_TESTS=OFF", "-DSHADELAB_BUILD_VIEWER=OFF", f"-DPython_EXECUTABLE={sys.executable}"]
        configure += shlex.split(os.environ.get("SHADELAB_CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 2)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "shadelab_python", "-j", jobs], check=True)
        return next((build_dir / "python" / "shadelab").glob("_shadelab*.so"))


class PortableWheel(bdist_wheel):
    """A wheel tagged manylinux_2_<glibc> (the tag wheel_libs computed for the module it packs), not linux_<arch>."""

    def get_tag(self):
        python, abi, plat = super().get_tag()
        return python, abi, PORTABLE_TAG[0] if PORTABLE_TAG else plat


class BuildPyWithAssets(build_py):
    def run(self):
        super().run()
        for relative in asset_files():
            target = Path(self.build_lib) / "shadelab" / "assets" / relative
            target.parent.mkdir(parents=True, exist_ok=True)
            self.copy_file(str(ROOT / "assets" / relative), str(target))


setup(
    version=cmake_project_version(),
    ext_modules=[Extension("shadelab._shadelab", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildPyWithAssets, "bdist_wheel": PortableWheel},
    # Out of build/, which is the CMake build folder of a checkout.
    options={"build": {"build_base": "build-pip"}, "egg_info": {"egg_base": "build-pip"}},
)
