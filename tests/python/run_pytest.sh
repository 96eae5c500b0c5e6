#!/usr/bin/env bash
# Runs one pytest file for ctest: run_pytest.sh BUILD_DIR TEST_FILE [pytest args...]
# The package comes from BUILD_DIR/python (PYTHONPATH), with Debian's /usr/bin/python3 and the plugin loaded
# explicitly (-p), so an installed copy's entry point cannot register it twice. Nothing is written into the
# source tree (no bytecode, no .pytest_cache). Exit 77 (ctest's skip) when pytest, numpy or a module named in
# SHADELAB_PYTEST_REQUIRES is missing.
#
# Sanitizer builds (SHADELAB_ASAN_RUNTIME set by tests/python/CMakeLists.txt): the extension module is
# ASan-instrumented but /usr/bin/python3 is not, and ASan must be the first library in the process, so its
# runtime is preloaded (LD_PRELOAD; every subprocess, the binary, a Jupyter kernel, Dask workers, inherits it),
# with libstdc++ (SHADELAB_ASAN_RUNTIME holds both, colon-separated; see tests/python/CMakeLists.txt).
# LeakSanitizer stays off there: CPython frees little at exit, and Mesa's driver is checked under valgrind
# instead (tests/leaks/). The caller's ASAN_OPTIONS are kept; detect_leaks=0 comes last, so it wins.
set -euo pipefail
build_dir=$1
test_file=$2
shift 2
python=${SHADELAB_PYTHON:-/usr/bin/python3}
# SHADELAB_PYTEST_REQUIRES: more modules this file needs (e.g. distributed), space separated.
for module in pytest numpy ${SHADELAB_PYTEST_REQUIRES:-}; do
  if ! "$python" -c "import $module" 2>/dev/null; then
    echo "skipped: $python cannot import $module (scripts/install-deps.sh installs it)"
    exit 77
  fi
done
export PYTHONPATH="$build_dir/python${PYTHONPATH:+:$PYTHONPATH}"
export PYTHONDONTWRITEBYTECODE=1
if [[ -n "${SHADELAB_ASAN_RUNTIME:-}" ]]; then
  export LD_PRELOAD="$SHADELAB_ASAN_RUNTIME${LD_PRELOAD:+:$LD_PRELOAD}"
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
fi
# ctest runs the files in parallel: each gets its own pytest temporary folder, inside its test-output folder.
basetemp=()
if [[ -n "${SHADELAB_TEST_OUTPUT:-}" ]]; then
  mkdir -p "$SHADELAB_TEST_OUTPUT"
  basetemp=(--basetemp "$SHADELAB_TEST_OUTPUT/pytest-tmp")
fi
exec "$python" -m pytest -p shadelab.pytest_plugin -p pytester -p no:cacheprovider -q -rs "${basetemp[@]}" \
  "$test_file" "$@"
