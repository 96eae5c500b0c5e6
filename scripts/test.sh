#!/usr/bin/env bash
# Quick start "test": install what is missing, check the C++ formatting (scripts/check-format.sh), build, run the
# whole test suite through ctest:
#   1. under AddressSanitizer + UndefinedBehaviorSanitizer (Debug build in build-asan/), every test but the
#      valgrind leak checks; Mesa's driver allocations are reported as leaks once its module is unloaded,
#      so LeakSanitizer is off there and leaks are checked by tests/leaks/ under valgrind instead;
#   2. a headless build of the shadelab binary alone with SHADELAB_BUILD_VIEWER=OFF (build-headless/): it must
#      render, must say it has no viewer, and must link neither GLFW nor Dear ImGui (ldd, and nm for the static
#      libimgui.a), checked against build/shadelab, which must show both, so that the check cannot go blind;
#   3. the web page (scripts/web.sh --build-only: emscripten into build-web/page/), which the Release suite's
#      web_page test drives in headless Chromium;
#   4. the Release build in build/, last, so the run ends in ctest's summary line.
# SHADELAB_SKIP_SANITIZERS=1 skips step 1 for a quicker local run; CI always runs all four.
# Every build here is configured with SHADELAB_WERROR=ON: a warning in shadelab's own code fails the run (third-party
# headers are SYSTEM includes and do not count). scripts/build.sh alone leaves it off for users' builds.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
scripts/install-deps.sh --with-web
scripts/check-format.sh  # before any build, so that a formatting slip fails in seconds
scripts/build.sh -DSHADELAB_WERROR=ON -DSHADELAB_WEB_TESTS=ON

# What of GLFW and Dear ImGui binary $1 carries: shared libraries (ldd) and linked-in symbols (nm).
viewer_libs() {
  { ldd "$1" | grep -Eio 'lib(glfw|imgui)[^ ]*' || true
    nm -C "$1" | grep -Eo 'ImGui::[A-Za-z]+|glfwInit' | sort -u | head -n 3 || true; } | tr '\n' ' '
}
if [[ "${SHADELAB_SKIP_SANITIZERS:-0}" != 1 ]]; then
  echo "== test suite under ASan + UBSan (build-asan/)"
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DSHADELAB_SANITIZE=address,undefined \
    -DSHADELAB_WERROR=ON >/dev/null
  cmake --build build-asan -j "$jobs"
  (cd build-asan && ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j "$jobs" -E '^leak_check_')
fi
echo "== headless build without the viewer (build-headless/)"
cmake -S . -B build-headless -DCMAKE_BUILD_TYPE=Release -DSHADELAB_BUILD_VIEWER=OFF -DSHADELAB_BUILD_TESTS=OFF \
  -DSHADELAB_WERROR=ON >/dev/null
cmake --build build-headless -j "$jobs" --target shadelab
if [[ -z "$(viewer_libs build/shadelab)" ]]; then
  echo "FAIL: the headless check is blind: build/shadelab (with the viewer) shows no GLFW or ImGui" >&2
  exit 1
fi
linked=$(viewer_libs build-headless/shadelab)
if [[ -n "$linked" ]]; then
  echo "FAIL: build-headless/shadelab, built with SHADELAB_BUILD_VIEWER=OFF, links the viewer's libraries: $linked" >&2
  ldd build-headless/shadelab >&2
  exit 1
fi
headless_tmp=$(mktemp -d)
trap 'rm -rf "$headless_tmp"' EXIT
build-headless/shadelab render assets/scenes/default.json -o "$headless_tmp/default.png"
if [[ ! -s "$headless_tmp/default.png" ]]; then
  echo "FAIL: build-headless/shadelab render wrote no PNG" >&2
  exit 1
fi
view_code=0
build-headless/shadelab view 2>"$headless_tmp/view.txt" || view_code=$?
if [[ $view_code != 1 ]] || ! grep -q "this build has no viewer" "$headless_tmp/view.txt"; then
  echo "FAIL: build-headless/shadelab view should exit 1 saying it has no viewer; got $view_code:" >&2
  cat "$headless_tmp/view.txt" >&2
  exit 1
fi
echo "headless build: renders, 'view' says it has none, links neither GLFW nor ImGui:"
ldd build-headless/shadelab | sed 's/^/  /'

echo "== the web page (build-web/page/)"
scripts/web.sh --build-only -DSHADELAB_WERROR=ON

echo "== test suite (build/)"
cd build
ctest --output-on-failure -j "$jobs"
