#!/usr/bin/env bash
# pbr benchmark: the 2CylinderEngine.glb headless render at 1920x1080 under `--model pbr` against the same
# render under `--model phong`, whole process, back to back: PAIRS interleaved pairs (default 15, the order
# alternating) after one warm-up each, so both models see the same machine load. Prints the medians of wall
# time and of CPU time (user + system, all threads: steadier than wall on a shared machine) and the ratios.
# Target: pbr <= 1.2x phong.
set -euo pipefail
cd "$(dirname "$0")/.."
model=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
[[ -f "$model" ]] || { echo "render_engine_pbr: $model missing (apt-get install assimp-testmodels)" >&2; exit 1; }
[[ -x build/shadelab ]] || scripts/build.sh
[[ -x /usr/bin/time ]] || { echo "render_engine_pbr: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
pairs=${PAIRS:-15}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
build/shadelab render "$model" -o "$out/engine.png" --size 1920x1080 --verbose 2>&1 | grep -E 'GL_RENDERER' || true
run() {  # model -> appends "wall cpu" (seconds) to $out/$1.txt
  /usr/bin/time -f "%e %U %S" -o "$out/t" build/shadelab render "$model" -o "$out/engine-$1.png" --size 1920x1080 \
    --model "$1"
  awk '{printf "%s %.3f\n", $1, $2 + $3}' "$out/t" >> "$out/$1.txt"
}
run phong; run pbr; rm -f "$out/phong.txt" "$out/pbr.txt"  # warm-up: Mesa's shader cache
for ((i = 0; i < pairs; ++i)); do
  if ((i % 2 == 0)); then run phong; run pbr; else run pbr; run phong; fi
done
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
for col in 1 2; do
  name=$([[ $col == 1 ]] && echo "wall" || echo "cpu ")
  p=$(cut -d' ' -f$col "$out/phong.txt" | median)
  b=$(cut -d' ' -f$col "$out/pbr.txt" | median)
  awk -v n="$name" -v p="$p" -v b="$b" -v k="$pairs" \
    'BEGIN {printf "%s median of %d: phong %.0f ms, pbr %.0f ms, pbr/phong %.3f\n", n, k, 1000 * p, 1000 * b, b / p}'
done
