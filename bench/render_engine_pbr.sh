#!/usr/bin/env bash
# Model benchmark: the 2CylinderEngine.glb headless render at 1920x1080 under `--model $B` (default pbr) against
# the same render under `--model $A` (default phong), whole process, back to back: PAIRS interleaved pairs
# (default 15, the order alternating) after one warm-up each, so both models see the same machine load. Prints
# the medians of wall time and of CPU time (user + system, all threads: steadier than wall on a shared machine)
# and the ratios. Targets: pbr <= 1.2x phong; `A=pbr B=disney`: disney <= 1.3x pbr.
set -euo pipefail
cd "$(dirname "$0")/.."
model=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
[[ -f "$model" ]] || { echo "render_engine_pbr.sh: $model missing (apt-get install assimp-testmodels)" >&2; exit 1; }
[[ -x build/shadelab ]] || scripts/build.sh
[[ -x /usr/bin/time ]] || { echo "render_engine_pbr.sh: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
pairs=${PAIRS:-15}
a=${A:-phong}
b=${B:-pbr}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
build/shadelab render "$model" -o "$out/engine.png" --size 1920x1080 --verbose 2>&1 | grep -E 'GL_RENDERER' || true
run() {  # model -> appends "wall cpu" (seconds) to $out/$1.txt
  /usr/bin/time -f "%e %U %S" -o "$out/t" build/shadelab render "$model" -o "$out/engine-$1.png" --size 1920x1080 \
    --model "$1"
  awk '{printf "%s %.3f\n", $1, $2 + $3}' "$out/t" >> "$out/$1.txt"
}
run "$a"; run "$b"; rm -f "$out/$a.txt" "$out/$b.txt"  # warm-up: Mesa's shader cache
for ((i = 0; i < pairs; ++i)); do
  if ((i % 2 == 0)); then run "$a"; run "$b"; else run "$b"; run "$a"; fi
done
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
for col in 1 2; do
  name=$([[ $col == 1 ]] && echo "wall" || echo "cpu ")
  ta=$(cut -d' ' -f$col "$out/$a.txt" | median)
  tb=$(cut -d' ' -f$col "$out/$b.txt" | median)
  awk -v n="$name" -v p="$ta" -v q="$tb" -v k="$pairs" -v a="$a" -v b="$b" \
    'BEGIN {printf "%s median of %d: %s %.0f ms, %s %.0f ms, %s/%s %.3f\n", n, k, a, 1000 * p, b, 1000 * q, b, a, q / p}'
done
