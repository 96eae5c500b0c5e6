#!/usr/bin/env bash
# Headless render benchmark: `shadelab render 2CylinderEngine.glb` (121,496 triangles) at 1920x1080 to PNG.
# Whole process, median of 5 (after one warm-up run), plus one run's per-stage breakdown.
# Target: <= 0.25 s median wall time and <= 150 MiB peak memory on the 2-core llvmpipe machine.
set -euo pipefail
cd "$(dirname "$0")/.."
model=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
[[ -f "$model" ]] || { echo "render_engine: $model missing (apt-get install assimp-testmodels)" >&2; exit 1; }
[[ -x build/shadelab && -x build/bench/process_bench ]] || scripts/build.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
build/shadelab render "$model" -o "$out/engine.png" --size 1920x1080 --verbose 2>&1 | grep -E 'GL_RENDERER|backend'
echo "shadelab render 2CylinderEngine.glb --size 1920x1080:"
build/bench/process_bench --runs 5 --warmup 1 -- build/shadelab render "$model" -o "$out/engine.png" --size 1920x1080
echo "stage breakdown (one run):"
build/shadelab render "$model" -o "$out/engine.png" --size 1920x1080 --timings
