#!/usr/bin/env bash
# Configures and builds shadelab into build/ (Release by default). Extra arguments go to cmake.
# Warnings are not errors here unless SHADELAB_WERROR=ON (or -DSHADELAB_WERROR=ON) says so: a user's build
# should not fail on a warning a newer compiler adds. scripts/test.sh builds with it on, so CI holds the line.
# The option is passed on every configure, so build/ does not keep -Werror from an earlier test run.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE="${SHADELAB_BUILD_TYPE:-Release}" -DSHADELAB_WERROR="${SHADELAB_WERROR:-OFF}" \
  "$@" >/dev/null
cmake --build build -j "$jobs"
