#!/usr/bin/env bash
# Runs one web test file for ctest: run_pytest.sh TEST_FILE [pytest args...]
# With Debian's /usr/bin/python3; nothing is written into the source tree (no bytecode, no .pytest_cache).
# Exit 77 (ctest's skip), with the reason, when pytest, numpy, websocket-client or Chromium is missing.
set -euo pipefail
test_file=$1
shift
python=${SHADELAB_PYTHON:-/usr/bin/python3}
for module in pytest numpy websocket; do
  if ! "$python" -c "import $module" 2>/dev/null; then
    echo "skipped: $python cannot import $module (Debian packages python3-pytest, python3-numpy, python3-websocket)"
    exit 77
  fi
done
chromium=${SHADELAB_CHROMIUM:-/usr/bin/chromium}
if [[ ! -x "$chromium" ]]; then
  echo "skipped: no Chromium at $chromium (Debian package chromium)"
  exit 77
fi
export PYTHONDONTWRITEBYTECODE=1
basetemp=()
if [[ -n "${SHADELAB_TEST_OUTPUT:-}" ]]; then
  mkdir -p "$SHADELAB_TEST_OUTPUT"
  basetemp=(--basetemp "$SHADELAB_TEST_OUTPUT/pytest-tmp")
fi
exec "$python" -m pytest -p no:cacheprovider -q -rs "${basetemp[@]}" "$test_file" "$@"
