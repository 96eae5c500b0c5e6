#!/usr/bin/env bash
# Path-tracer throughput under two shading models: assets/scenes/default.json path traced at 320x180, 16 spp
# (the path tracer's own "M paths/s" figure) under `--model $B` (default disney) against `--model $A` (default
# pbr), PAIRS interleaved pairs (default 9, the order alternating) after one warm-up each. Prints the medians
# and their ratio. Target: disney >= 0.8x pbr in paths per second.
set -euo pipefail
cd "$(dirname "$0")/.."
[[ -x build/shadelab ]] || scripts/build.sh
pairs=${PAIRS:-9}
a=${A:-pbr}
b=${B:-disney}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
run() {  # model -> appends M paths/s to $out/$1.txt
  build/shadelab render assets/scenes/default.json --renderer path --size 320x180 --spp 16 --model "$1" \
    -o "$out/p-$1.png" 2>&1 | sed -n 's/.*(\([0-9.]*\) M paths\/s.*/\1/p' >> "$out/$1.txt"
}
run "$a"; run "$b"; rm -f "$out/$a.txt" "$out/$b.txt"  # warm-up
for ((i = 0; i < pairs; ++i)); do
  if ((i % 2 == 0)); then run "$a"; run "$b"; else run "$b"; run "$a"; fi
done
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
pa=$(median < "$out/$a.txt")
pb=$(median < "$out/$b.txt")
awk -v p="$pa" -v q="$pb" -v k="$pairs" -v a="$a" -v b="$b" \
  'BEGIN {printf "median of %d: %s %.2f M paths/s, %s %.2f M paths/s, %s/%s %.3f\n", k, a, p, b, q, b, a, q / p}'
