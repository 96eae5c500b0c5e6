#!/usr/bin/env bash
# Instructions per incoherent ray: shadelab's walk and, in a build with Embree, Embree's
# rtcIntersect1 on the same rays, counted by callgrind around the timed loop alone. The count has none of the
# ±5 % that timings spread between processes on a busy or virtual machine, so a small change to the walk can be
# judged by it before it is timed (bench/README.md, "Counting instructions"). Prints the total per ray and the
# functions that hold most of it.
# Usage: bench/trace_instructions.sh [model.glb]   (default: 2CylinderEngine from assimp-testmodels)
# Environment: BUILD_DIR (default build), SIZE (the primary-ray image, default 1920x1080).
set -euo pipefail
cd "$(dirname "$0")/.."
bench=${BUILD_DIR:-build}/bench/trace_bench
model=${1:-/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb}
size=${SIZE:-1920x1080}
command -v valgrind >/dev/null || { echo "trace_instructions: valgrind is missing (scripts/install-deps.sh)" >&2; exit 1; }
[[ -x $bench ]] || { echo "trace_instructions: $bench is missing (build the trace_bench target)" >&2; exit 1; }
[[ -f $model ]] || { echo "trace_instructions: $model: no such file" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# count LABEL LOOP-FUNCTION [trace_bench options...]: callgrind collects inside LOOP-FUNCTION only.
count() {
    local label=$1 loop=$2
    shift 2
    valgrind --tool=callgrind --toggle-collect="*$loop*" --callgrind-out-file="$out/$label.cg" \
        "$bench" --only incoherent --runs 1 --threads 1 --size "$size" --engine "$model" "$@" > "$out/$label.log" 2>&1 ||
        { tail -5 "$out/$label.log" >&2; echo "trace_instructions: $label run failed" >&2; exit 1; }
    local rays
    rays=$(sed -n 's/.*threads: \([0-9]*\) cosine-distributed.*/\1/p' "$out/$label.log")
    [[ -n $rays && $rays -gt 0 ]] || { echo "trace_instructions: no rays in $label's output" >&2; exit 1; }
    callgrind_annotate "$out/$label.cg" 2>/dev/null | awk -v rays="$rays" -v label="$label" '
        /PROGRAM TOTALS/ { gsub(",", "", $1); printf "%s: %d rays, %.1f instructions per ray\n", label, rays, $1 / rays; next }
        /^ *[0-9,]+ \(/ && shown < 6 {
            n = $1; gsub(",", "", n); name = $0; sub(/^[^)]*\) */, "", name); sub(/^[^:]*:/, "", name)
            if (n / rays >= 1) { printf "  %8.1f  %s\n", n / rays, substr(name, 1, 100); shown++ }
        }'
}

count shadelab nearestHitsOurs --no-embree
if "$bench" --only incoherent --runs 1 --size 64x48 --engine "$model" 2>/dev/null | grep -q '^embree incoherent'; then
    count embree nearestHitsEmbree
else
    echo "embree: not in this build (scripts/install-deps.sh --with-embree, then reconfigure)"
fi
