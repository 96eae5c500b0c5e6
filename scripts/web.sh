#!/usr/bin/env bash
# The web page (docs/web.md): installs what is missing (Debian's emscripten and chromium), builds the page into
# build-web/page/ with emscripten, and serves it on localhost, printing the URL.
# Usage: scripts/web.sh [--build-only] [--port N] [-DNAME=VALUE ...]  (-D options go to cmake's configure)
set -euo pipefail
cd "$(dirname "$0")/.."
build_only=0
port=8000
cmake_args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build-only) build_only=1 ;;
    --port) shift; port="${1:?--port needs a number}" ;;
    -D*) cmake_args+=("$1") ;;
    -h|--help) sed -n '2,4p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "web.sh: unknown option $1 (try --help)" >&2; exit 2 ;;
  esac
  shift
done
scripts/install-deps.sh --with-web
# emscripten's tools are Node programs that need Debian's Node modules.
export NODE_PATH=/usr/share/nodejs
emcmake cmake -S . -B build-web -DCMAKE_BUILD_TYPE=Release -DSHADELAB_WERROR=OFF "${cmake_args[@]}" >/dev/null
cmake --build build-web -j "$(nproc 2>/dev/null || echo 2)"
echo "web.sh: the page is in build-web/page/ ($(du -sh build-web/page | cut -f1))" >&2
[[ $build_only == 1 ]] && exit 0
echo "web.sh: serving http://127.0.0.1:$port/ (Ctrl-C stops)" >&2
exec /usr/bin/python3 -m http.server "$port" --bind 127.0.0.1 --directory build-web/page
