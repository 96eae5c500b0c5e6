"""The portable wheel (docs/python.md "Installing"): `pip wheel` packs the build tree's module with the libraries it
needs beyond the manylinux set, tagged manylinux_2_<glibc>; installed into a clean venv and used from a folder
outside the repository, it imports, loads a packaged scene and renders the binary's bytes while Debian's libstb,
libtinygltf and OpenEXR libraries are hidden (replaced by empty files in a private mount namespace), and the
notebook runs on a kernel of that venv.

The wheel packs the module this build tree made (SHADELAB_PREBUILT_MODULE), so the test takes seconds, not the
minutes of a from-scratch `pip wheel` (whose time bench/README.md quotes). Everything is written under the test's
output folder and the system's temporary folder; setup.py's own build folder (build-pip/, ignored by git) is the
one thing written in the source tree, as by any `pip install .`."""

import os
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile
from pathlib import Path

import pytest

import shadelab
from conftest import SOURCE_DIR, sanitized
from test_notebook import NOTEBOOKS

sys.path.insert(0, str(SOURCE_DIR / "tools"))
import wheel_libs  # noqa: E402

pytestmark = pytest.mark.skipif(sanitized(), reason="a wheel packs a Release module, not a sanitizer build's")

# Debian's libraries a wheel must not need where it is installed (the system's copies are hidden from the render).
HIDDEN = ["libstb.so.0", "libtinygltf.so.2d", "libOpenEXR-3_1.so.30", "libIex-3_1.so.30", "libIlmThread-3_1.so.30",
          "libImath-3_1.so.29"]


def build_module():
    return Path(shadelab._shadelab.__file__)


@pytest.fixture(scope="module")
def work():
    """A folder outside the repository for the wheel, the venv and the scripts; copied to the test output at the
    end (evidence), then removed."""
    folder = Path(tempfile.mkdtemp(prefix="shadelab-wheel-"))
    assert not any((p / "assets" / "scenes" / "default.json").exists() for p in [folder, *folder.parents])
    yield folder
    out = Path(os.environ.get("SHADELAB_TEST_OUTPUT", SOURCE_DIR / "build" / "test-output" / "python_wheel"))
    out.mkdir(parents=True, exist_ok=True)
    for name in ("wheelhouse", "elsewhere"):
        if (folder / name).exists():
            shutil.copytree(folder / name, out / name, dirs_exist_ok=True)
    shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture(scope="module")
def wheel(work):
    if not shutil.which("patchelf"):
        pytest.fail("patchelf is missing (scripts/install-deps.sh installs it)")
    env = dict(os.environ, SHADELAB_PREBUILT_MODULE=str(build_module()))
    env.pop("PYTHONPATH", None)
    p = subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-build-isolation", "--no-deps", "--no-index",
                        "-w", str(work / "wheelhouse"), str(SOURCE_DIR)], capture_output=True, text=True, env=env)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    (found,) = (work / "wheelhouse").glob("shadelab-*.whl")
    return found


@pytest.fixture(scope="module")
def venv(work, wheel):
    """A clean venv (Debian's numpy through the system site-packages, nothing of the build tree) with the wheel."""
    path = work / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(path)], check=True)
    p = subprocess.run([str(path / "bin" / "python"), "-m", "pip", "install", "--no-deps", "--no-index", str(wheel)],
                       capture_output=True, text=True, env=clean_env(work))
    assert p.returncode == 0, p.stderr[-3000:]
    return path


def clean_env(home):
    """No PYTHONPATH, no LD_LIBRARY_PATH, no build tree: what a user's shell would have."""
    return {"PATH": "/usr/bin:/bin", "HOME": str(home), "LANG": "C.UTF-8", "LD_LIBRARY_PATH": ""}


def installed_module(venv):
    (module,) = venv.glob("lib/python3*/site-packages/shadelab/_shadelab*.so")
    return module


def foreign_libraries(module):
    """The libraries `module` loads that are neither the manylinux system's nor inside its own package."""
    package = module.parent.resolve()
    return {name: path for name, path in wheel_libs.resolved(module).items()
            if not wheel_libs.SYSTEM_LIBRARIES.match(name) and package not in Path(path).resolve().parents}


def hiding_prefix(hidden=HIDDEN):
    """A command prefix that runs its command in a private mount namespace with Debian's copies of `hidden`
    replaced by empty files, or None where user namespaces are not allowed."""
    binds = []
    for name in hidden:
        real = os.path.realpath(f"/usr/lib/{os.uname().machine}-linux-gnu/{name}")
        if os.path.exists(real):
            binds.append(f"mount --bind /dev/null {real}")
    if not binds or not shutil.which("unshare"):
        return None
    script = " && ".join(binds) + ' && exec "$@"'
    if subprocess.run(["unshare", "-rm", "sh", "-c", script, "sh", "true"], capture_output=True).returncode != 0:
        return None
    return ["unshare", "-rm", "sh", "-c", script, "sh"]


def test_the_wheel_is_manylinux_and_carries_its_libraries_and_licences(wheel):
    assert re.search(r"-manylinux_2_\d+_x86_64\.whl$", wheel.name), wheel.name
    names = zipfile.ZipFile(wheel).namelist()
    libs = {Path(n).name for n in names if n.startswith("shadelab/_libs/") and ".so" in n and "/licences/" not in n}
    assert {"libOpenEXR-3_1.so.30", "libz.so.1"} <= libs, libs
    assert not libs & {"libstb.so.0", "libtinygltf.so.2d", "libEGL.so.1"}, libs  # compiled in, or loaded at run time
    assert {f"shadelab/_libs/licences/{lib}.txt" for lib in libs} <= set(names)
    assert "shadelab/assets/scenes/default.json" in names
    metadata = zipfile.ZipFile(wheel).read(next(n for n in names if n.endswith("/METADATA"))).decode()
    assert "License :: OSI Approved :: MIT License" in metadata


def test_the_installed_module_loads_nothing_from_debian_but_the_system(venv):
    assert foreign_libraries(installed_module(venv)) == {}
    # The negative control: the build tree's module, linked against Debian's OpenEXR, is caught by the same check.
    assert "libOpenEXR-3_1.so.30" in foreign_libraries(build_module())


RENDER = r"""
import sys
import shadelab
out = sys.argv[1]
scene = shadelab.data.scene("default")
shadelab.render(scene, (64, 36)).save(out + "/default-raster.png")
shadelab.render(scene, (64, 36), renderer="trace").save(out + "/default-trace.png")
shadelab.render(shadelab.data.scene("gltf-layers"), (64, 36), renderer="trace").save(out + "/layers.exr")
maps = [line.split()[-1] for line in open("/proc/self/maps") if ".so" in line]
print("\n".join(sorted(set(maps))))
print("shadelab from", shadelab.__file__)
"""


def run_outside(python, work, prefix=()):
    folder = work / "elsewhere"
    folder.mkdir(exist_ok=True)
    return subprocess.run([*prefix, str(python), "-c", RENDER, str(folder)], cwd=folder, capture_output=True,
                          text=True, env=clean_env(work)), folder


def test_renders_the_binarys_bytes_from_another_folder_with_debians_libraries_hidden(venv, work, binary):
    prefix = hiding_prefix()  # None where user namespaces are not allowed: the checks then run unhidden
    p, folder = run_outside(venv / "bin" / "python", work, prefix or ())
    assert p.returncode == 0, p.stderr[-3000:]
    assert f"shadelab from {venv}" in p.stdout
    mapped = p.stdout.splitlines()
    assert not [m for m in mapped if re.search(r"/lib(stb|tinygltf)\.so", m)], mapped
    assert [m for m in mapped if "libOpenEXR" in m] == [str(installed_module(venv).parent / "_libs" /
                                                           "libOpenEXR-3_1.so.30")]
    for renderer in ("raster", "trace"):
        ref = work / f"default-{renderer}-binary.png"
        subprocess.run([str(binary), "render", str(SOURCE_DIR / "assets" / "scenes" / "default.json"), "-o", str(ref),
                        "--size", "64x36", "--renderer", renderer], check=True, capture_output=True)
        assert (folder / f"default-{renderer}.png").read_bytes() == ref.read_bytes(), renderer
    assert (folder / "layers.exr").read_bytes()[:4] == b"\x76\x2f\x31\x01"  # OpenEXR's magic number
    if prefix is None:
        pytest.skip("rendered from the wheel, but user namespaces are not allowed here: Debian's libraries could "
                    "not be hidden, so the import without them is unchecked")
    # The negative control: the build tree's module, which links Debian's OpenEXR, does not even import there.
    control = subprocess.run([*prefix, sys.executable, "-c", "import shadelab"], capture_output=True, text=True,
                             env=dict(clean_env(work), PYTHONPATH=str(build_module().parent.parent)))
    assert control.returncode != 0 and "libOpenEXR-3_1.so.30" in control.stderr, control.stderr[-2000:]


NO_GL = r"""
import shadelab
scene = shadelab.data.scene("default")
print("trace", shadelab.render(scene, (32, 18), renderer="trace").to_uint8().shape)
try:
    shadelab.render(scene, (32, 18))
except Exception as e:
    print("raster:", e)
"""


def test_without_libegl_or_libosmesa_the_tracers_work_and_raster_says_why_not(venv, work):
    # libEGL and libOSMesa are loaded at run time (not linked): with both hidden the package still imports and
    # traces, and the rasterizer's error names what is missing.
    prefix = hiding_prefix(["libEGL.so.1", "libOSMesa.so.8"])
    if prefix is None:
        pytest.skip("user namespaces are not allowed here: the GL libraries cannot be hidden")
    p = subprocess.run([*prefix, str(venv / "bin" / "python"), "-c", NO_GL], capture_output=True, text=True,
                       cwd=work, env=clean_env(work))
    assert p.returncode == 0, p.stderr[-3000:]
    assert "trace (18, 32, 3)" in p.stdout or "trace (18, 32, 4)" in p.stdout, p.stdout
    (raster,) = [line for line in p.stdout.splitlines() if line.startswith("raster:")]
    assert "libEGL.so.1 not found" in raster and "libOSMesa" in raster, raster
    # The negative control: with the libraries there, the same script rasterizes.
    p = subprocess.run([str(venv / "bin" / "python"), "-c", NO_GL], capture_output=True, text=True, cwd=work,
                       env=clean_env(work))
    assert p.returncode == 0 and "raster:" not in p.stdout, p.stdout + p.stderr[-2000:]


def test_the_notebook_runs_on_a_kernel_of_the_venv(venv, work):
    jupyter = shutil.which("jupyter")
    if not jupyter:
        pytest.fail("jupyter is missing (scripts/install-deps.sh installs jupyter-nbconvert)")
    # The documented step (docs/python.md "Notebooks"): register the venv's Python as a kernel.
    kernels = work / "jupyter"
    subprocess.run([str(venv / "bin" / "python"), "-m", "ipykernel", "install", "--prefix", str(kernels), "--name",
                    "shadelab-venv"], check=True, capture_output=True, env=clean_env(work))
    folder = work / "elsewhere"
    folder.mkdir(exist_ok=True)
    shutil.copyfile(NOTEBOOKS / "phong-lab.ipynb", folder / "phong-lab.ipynb")
    env = dict(clean_env(work), JUPYTER_PATH=str(kernels / "share" / "jupyter"), PYDEVD_DISABLE_FILE_VALIDATION="1")

    def execute(kernel):
        return subprocess.run([jupyter, "nbconvert", "--to", "notebook", "--execute", "--config",
                               str(NOTEBOOKS / "nbconvert_config.py"), "--ExecutePreprocessor.timeout=300",
                               f"--ExecutePreprocessor.kernel_name={kernel}", "--output-dir", str(folder / kernel),
                               str(folder / "phong-lab.ipynb")], capture_output=True, text=True, env=env, cwd=folder)

    p = execute("shadelab-venv")
    assert p.returncode == 0, p.stderr[-3000:]
    executed = (folder / "shadelab-venv" / "phong-lab.ipynb").read_text()
    assert '"output_type": "error"' not in executed
    assert "the shininess slider changes the picture under phong" in executed
    # The negative control: Debian's own kernel (/usr/bin/python3, which the package is not installed into) fails.
    control = execute("python3")
    assert control.returncode != 0 and "No module named 'shadelab'" in control.stderr, control.stderr[-2000:]


def test_an_editable_install_is_refused_and_writes_nothing_into_the_package(venv, work):
    package = SOURCE_DIR / "python" / "shadelab"
    before = sorted(p.name for p in package.iterdir())
    env = dict(clean_env(work), SHADELAB_PREBUILT_MODULE=str(build_module()))
    p = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "--no-build-isolation", "--no-deps",
                        "--no-index", "-e", str(SOURCE_DIR)], capture_output=True, text=True, env=env)
    assert p.returncode != 0 and "editable installs (pip install -e) are not supported" in p.stdout + p.stderr
    assert sorted(p.name for p in package.iterdir()) == before
    assert not list(package.glob("_shadelab*.so"))
