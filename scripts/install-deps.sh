#!/usr/bin/env bash
# Installs the Debian 12 packages shadelab needs, skipping those already present (design.md §6).
# Usage: scripts/install-deps.sh [--with-embree] [--with-fuzz] [--with-web]   (needs root or sudo when something is missing)
set -euo pipefail

packages=(
  build-essential cmake pkg-config libgtest-dev        # build and test
  ccache                                                # keeps compiled objects between builds (CMakeLists.txt)
  clang-format                                          # scripts/check-format.sh (Debian 12: clang-format 14)
  libglfw3-dev                                          # window
  libglm-dev                                            # math
  libegl-dev libopengl-dev libgl-dev libosmesa6-dev     # OpenGL headers and loaders
  libegl-mesa0 libgl1-mesa-dri                          # Mesa drivers (llvmpipe) at run time
  libimgui-dev                                          # UI
  libtinygltf-dev libstb-dev                            # glTF and images
  zlib1g-dev                                            # PNG compression
  libopenexr-dev                                        # OpenEXR images (render -o x.exr, compare)
  nlohmann-json3-dev                                    # JSON
  xvfb xauth assimp-testmodels valgrind                 # test tools and real glTF test data
  pybind11-dev python3-dev python3-numpy python3-pytest # the Python package (build/python) and its tests
  python3-setuptools python3-wheel python3-pip python3-venv # `pip install .` / `pip wheel .` offline, with Debian's tools
  patchelf                                              # the wheel carries OpenEXR and zlib (tools/wheel_libs.py)
  jupyter-nbconvert python3-ipykernel python3-ipywidgets # the notebook, executed by the tests
  python3-distributed                                   # Dask: the batch-sweep example and its test
  python3-mypy                                          # the package's type checks (mypy --strict, stubtest)
  chromium python3-websocket                            # the web tests: headless Chromium over DevTools (tests/web)
)
for arg in "$@"; do
  case "$arg" in
    --with-embree) packages+=(libembree-dev) ;;            # benchmark baseline only
    --with-fuzz) packages+=(clang libclang-rt-14-dev) ;;   # libFuzzer and sanitizers (tests/fuzz/run.sh)
    --with-web) packages+=(emscripten) ;;                  # the web page's build (web/, docs/web.md)
    *) echo "install-deps: unknown option $arg" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install-deps: all ${#packages[@]} packages present" >&2
  exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo=""
[[ $(id -u) -eq 0 ]] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done" >&2
