#!/usr/bin/env bash
# Idle viewer benchmark: the CPU an idle viewer uses. The viewer opens the scene in a 1720x760 Xvfb window,
# settles for SETTLE seconds (the first frames, shaders), then its CPU time (all threads: utime + stime from
# /proc/PID/stat) is read over WINDOW seconds with no input. Target: under 2 % of one core.
# Each case runs RUNS times; prints every run and the median.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
[[ -x $build/shadelab ]] || scripts/build.sh
command -v Xvfb >/dev/null || { echo "viewer_idle: Xvfb is missing (apt-get install xvfb)" >&2; exit 1; }
runs=${RUNS:-3}
settle=${SETTLE:-5}
window=${WINDOW:-10}
hz=$(getconf CLK_TCK)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
median() { tr ' ' '\n' | grep . | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 1720x760x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1
ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
bench() {  # label, then shadelab view arguments
    local label=$1; shift
    local all=""
    for _ in $(seq "$runs"); do
        DISPLAY=$display "$build/shadelab" view "$@" >/dev/null 2>&1 &
        local pid=$!
        sleep "$settle"
        local t1; t1=$(ticks $pid)
        sleep "$window"
        local t2; t2=$(ticks $pid)
        kill $pid; wait $pid 2>/dev/null || true
        all+=" $(awk -v d=$((t2 - t1)) -v hz="$hz" -v w="$window" 'BEGIN {printf "%.2f", 100 * d / hz / w}')"
    done
    echo "$label: % of one core over ${window} s idle:$all -> median $(median <<<"$all") %"
}
bench "default scene, Raster" assets/scenes/default.json
split=$(mktemp --suffix=.json)
trap 'kill $xvfb 2>/dev/null || true; rm -f "$split"' EXIT
echo '[{"action": "setMode", "mode": "split"}]' >"$split"
bench "default scene, Split (the reference completes during the settle time)" assets/scenes/default.json \
  --script "$split"
