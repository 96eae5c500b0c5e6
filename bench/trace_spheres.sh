#!/usr/bin/env bash
# Tracer benchmarks. (1) `shadelab render bench/spheres40.json --renderer trace --threads 2` at
# 1920x1080, whole process, median of 5 after one warm-up (target <= 0.55 s). (2) trace_bench: the same
# scene timed in-process, and 2CylinderEngine.glb primary + shadow rays in Mrays/s against Embree 3 when
# libembree-dev was found at configure time (target >= 0.5x Embree).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SHADELAB_BUILD_DIR:-build}
[[ -x $build/shadelab && -x $build/bench/process_bench && -x $build/bench/trace_bench ]] || scripts/build.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "shadelab render bench/spheres40.json --renderer trace --threads 2 --size 1920x1080:"
"$build"/bench/process_bench --runs 5 --warmup 1 -- \
  "$build"/shadelab render bench/spheres40.json --renderer trace --threads 2 --size 1920x1080 -o "$out/spheres40.png"
"$build"/bench/trace_bench --runs 5 --threads 2 --size 1920x1080
