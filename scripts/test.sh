#!/usr/bin/env bash
# Quick start "test": install what is missing, build, run the whole test suite through ctest:
#   1. under AddressSanitizer + UndefinedBehaviorSanitizer (Debug build in build-asan/), every test but the
#      valgrind leak checks; Mesa's driver allocations are reported as leaks once its module is unloaded,
#      so LeakSanitizer is off there and leaks are checked by tests/leaks/ under valgrind instead;
#   2. the Release build in build/, last, so the run ends in ctest's summary line.
# SHADELAB_SKIP_SANITIZERS=1 skips step 1 for a quicker local run; CI always runs both.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
scripts/install-deps.sh
scripts/build.sh
if [[ "${SHADELAB_SKIP_SANITIZERS:-0}" != 1 ]]; then
  echo "== test suite under ASan + UBSan (build-asan/)"
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DSHADELAB_SANITIZE=address,undefined >/dev/null
  cmake --build build-asan -j "$jobs"
  (cd build-asan && ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
     ctest --output-on-failure -j "$jobs" -E '^leak_check_')
fi
echo "== test suite (build/)"
cd build
ctest --output-on-failure -j "$jobs"
