"""One version, written once: CMakeLists.txt's project(shadelab VERSION x.y.z). The package's __version__ (the
compiled module's build_info), the binary's --version and setup.py's metadata all read it."""

import ast
import re
import subprocess

import shadelab


def cmake_version(source_dir):
    text = (source_dir / "CMakeLists.txt").read_text()
    match = re.search(r"^\s*project\(\s*shadelab\s[^)]*VERSION\s+([0-9][0-9.]*)", text, re.MULTILINE)
    assert match, "no project(shadelab VERSION ...) in CMakeLists.txt"
    return match.group(1)


def test_package_version_is_cmakes(source_dir):
    assert shadelab.__version__ == cmake_version(source_dir)
    assert shadelab.build_info["version"] == shadelab.__version__


def test_binary_version_is_the_packages(binary):
    out = subprocess.run([str(binary), "--version"], check=True, capture_output=True, text=True).stdout
    assert out == f"shadelab {shadelab.__version__}\n"


def test_setup_py_reads_cmakes_version(source_dir):
    # Only setup.py's reader, taken out of the file: importing setup.py would run setup().
    tree = ast.parse((source_dir / "setup.py").read_text())
    reader = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "cmake_project_version")
    scope = {"re": re, "ROOT": source_dir}
    exec(compile(ast.Module(body=[reader], type_ignores=[]), "setup.py", "exec"), scope)
    assert scope["cmake_project_version"]() == cmake_version(source_dir)
