#!/usr/bin/env bash
# The main job of the Quick start's first command (scripts/run.sh runs it after installing and building): the
# default scene, in the viewer when there is a display and the viewer is built (extra arguments go to
# `shadelab view`, e.g. --projector), else rendered headlessly to out/ with the PNGs' paths printed.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=assets/scenes/default.json
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]] && build/shadelab view --help >/dev/null 2>&1; then
  exec build/shadelab view "$scene" "$@"
fi
mkdir -p out
build/shadelab render "$scene" -o out/default.png
build/shadelab render "$scene" -o out/default-blinn.png --model blinn-phong
echo "Rendered the default scene headlessly:"
echo "  $(pwd)/out/default.png        (Phong)"
echo "  $(pwd)/out/default-blinn.png  (Blinn-Phong)"
