#!/usr/bin/env bash
# The Whitted tracer against POV-Ray 3.7 (Debian's povray) on bench/spheres40.json at 1920x1080 on 2 threads:
# the scene written as POV-Ray text by bench/scene_to_pov.py (same camera, objects, point lights with hard
# shadows, Phong finish, reflection, max_trace_level = maxDepth + 1, no antialiasing), both whole processes,
# alternated RUNS times (default 7) after one warm-up each, median wall times and their ratio (target: shadelab
# <= 0.20x POV-Ray's time). POV-Ray is a benchmark anchor only: `apt-get install povray`; without it the
# script says so and stops.
#
#   RUNS=7 SIZE=1920x1080 THREADS=2 bench/trace_vs_povray.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SHADELAB_BUILD_DIR:-build}
runs=${RUNS:-7}
size=${SIZE:-1920x1080}
threads=${THREADS:-2}
command -v povray >/dev/null || { echo "trace_vs_povray: povray not found (apt-get install povray)" >&2; exit 1; }
[[ -x $build/shadelab ]] || scripts/build.sh
w=${size%x*}
h=${size#*x}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
/usr/bin/python3 bench/scene_to_pov.py bench/spheres40.json "$out/spheres40.pov" "$w" "$h"
pov=(povray "+I$out/spheres40.pov" "+O$out/pov.png" "+W$w" "+H$h" "+WT$threads" -D -A +FN -GA)
ours=("$build/shadelab" render bench/spheres40.json --renderer trace --threads "$threads" --size "$size" -o "$out/ours.png")
seconds() {
    local t0 t1
    t0=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f\n", b - a }'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "$(povray --version 2>&1 | head -1)"
seconds "${pov[@]}" >/dev/null
seconds "${ours[@]}" >/dev/null
: >"$out/pov.times"
: >"$out/ours.times"
for ((i = 1; i <= runs; ++i)); do
    seconds "${pov[@]}" >>"$out/pov.times"
    seconds "${ours[@]}" >>"$out/ours.times"
done
p=$(median <"$out/pov.times")
o=$(median <"$out/ours.times")
printf 'spheres40.json %s, %s threads, medians of %d alternated runs:\n' "$size" "$threads" "$runs"
printf '  POV-Ray 3.7   %.3f s  (%s)\n' "$p" "$(tr '\n' ' ' <"$out/pov.times")"
printf '  shadelab      %.3f s  (%s)\n' "$o" "$(tr '\n' ' ' <"$out/ours.times")"
printf '  ratio         %.3fx POV-Ray'"'"'s time (target <= 0.20)\n' "$(awk -v o="$o" -v p="$p" 'BEGIN { print o / p }')"
