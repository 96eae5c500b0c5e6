#!/usr/bin/env bash
# Raster terms benchmark: the cost of raster shadows and planar reflection. The default scene at 1920x1080,
# headless, with its 2 point lights: all terms on against --terms ambient,diffuse,specular (shadows and
# reflections off), whole process, median of 5 after one warm-up. Target: on <= 2x off.
# The default floor has kr = 0, so a copy with a kr = 0.3 floor is timed too (the planar mirror pass).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
[[ -x $build/shadelab && -x $build/bench/process_bench ]] || scripts/build.sh
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
scene=assets/scenes/default.json
mirror="$out/default-mirror-floor.json"
sed 's/"material": {"ma": 0.8, "md": 0.8, "ms": 0.1, "s": 16}/"material": {"ma": 0.8, "md": 0.8, "ms": 0.1, "s": 16, "kr": 0.3}/' \
    "$scene" > "$mirror"
grep -q '"kr": 0.3' "$mirror" || { echo "raster_terms: could not add kr to the default floor" >&2; exit 1; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "shadow maps: auto size, 2048x2048 texels per layer at 1080p (RasterSettings::shadowMapSize), one perspective layer per point light"
bench() {  # label, then shadelab render arguments
    local label=$1; shift
    echo "$label:"
    "$build/bench/process_bench" --runs 5 --warmup 1 -- "$build/shadelab" render "$@" -o "$out/x.png" --size 1920x1080 |
        tail -1
}
bench "default scene, shadows + reflections off" "$scene" --terms ambient,diffuse,specular
bench "default scene, all terms on (shadows; environment cube for its mirror sphere)" "$scene"
bench "default scene + kr 0.3 floor, shadows + reflections off" "$mirror" --terms ambient,diffuse,specular
bench "default scene + kr 0.3 floor, shadows + planar reflection on" "$mirror"
