#!/usr/bin/env bash
# Issue-12 benchmark: the 2CylinderEngine.glb headless render at 1920x1080 under `--model pbr` against the same
# render under `--model phong`, whole process, back to back: ROUNDS rounds (default 3), each a median of 5 runs
# (after one warm-up) of phong then of pbr, so both see the same machine load. Target: pbr <= 1.2x phong.
set -euo pipefail
cd "$(dirname "$0")/.."
model=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
[[ -f "$model" ]] || { echo "render_engine_pbr: $model missing (apt-get install assimp-testmodels)" >&2; exit 1; }
[[ -x build/shadelab && -x build/bench/process_bench ]] || scripts/build.sh
rounds=${ROUNDS:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
build/shadelab render "$model" -o "$out/engine.png" --size 1920x1080 --verbose 2>&1 | grep -E 'GL_RENDERER' || true
for ((r = 1; r <= rounds; ++r)); do
  for m in phong pbr; do
    echo "round $r, --model $m:"
    build/bench/process_bench --runs 5 --warmup 1 -- \
      build/shadelab render "$model" -o "$out/engine-$m.png" --size 1920x1080 --model "$m"
  done
done
echo "stage breakdown (one run each):"
for m in phong pbr; do
  echo "--model $m:"
  build/shadelab render "$model" -o "$out/engine-$m.png" --size 1920x1080 --model "$m" --timings
done
