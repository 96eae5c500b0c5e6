#!/usr/bin/env bash
# The tracer's ray-tree bound: `shadelab render bench/glass-tree.json --renderer trace --threads 2` (45 spheres,
# kr = kt = 1, depth 64) at 64x48, whole process, median of 5 after one warm-up; then the same scene at
# depth 5, 9 and 12 for how the time grows with the depth now that the budget bounds it.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SHADELAB_BUILD_DIR:-build}
[[ -x $build/shadelab && -x $build/bench/process_bench ]] || scripts/build.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
for depth in 64 5 9 12; do
  echo "shadelab render bench/glass-tree.json --renderer trace --threads 2 --size 64x48 --depth $depth:"
  "$build"/bench/process_bench --runs 5 --warmup 1 -- \
    "$build"/shadelab render bench/glass-tree.json --renderer trace --threads 2 --size 64x48 --depth "$depth" \
    -o "$out/glass-tree.png"
done
