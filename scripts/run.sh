#!/usr/bin/env bash
# Quick start "run": install what is missing, build, then show the default scene.
# With a display this opens the viewer (once it exists); without one it renders headlessly and prints the PNG path.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
scene=assets/scenes/default.json
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]] && build/shadelab view --help >/dev/null 2>&1; then
  exec build/shadelab view "$scene"
fi
mkdir -p out
build/shadelab render "$scene" -o out/default.png
build/shadelab render "$scene" -o out/default-blinn.png --model blinn-phong
echo "Rendered the default scene headlessly:"
echo "  $(pwd)/out/default.png        (Phong)"
echo "  $(pwd)/out/default-blinn.png  (Blinn-Phong)"
