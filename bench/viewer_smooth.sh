#!/usr/bin/env bash
# Smooth-frame benchmark: how long after the last change the viewer's smooth still frame (16 jittered samples,
# src/app/accumulation.h) is complete, at 1280x720 in a 1720x720 window under Xvfb. The script changes the
# shininess at frame 10 and then waits for the smooth frame; `--verbose` prints the time from the change.
# Each case runs RUNS times; prints every run and the median. Target: <= 1.5 s.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
[[ -x $build/shadelab ]] || scripts/build.sh
command -v xvfb-run >/dev/null || { echo "viewer_smooth: xvfb-run is missing (apt-get install xvfb)" >&2; exit 1; }
runs=${RUNS:-5}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
median() { tr ' ' '\n' | grep . | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bench() {  # label, scene, object
    local label=$1 scene=$2 object=$3 all=""
    cat >"$tmp/script.json" <<JSON
[{"frame": 10, "action": "setShininess", "object": "$object", "s": 77},
 {"action": "smoothScreenshot", "path": "$tmp/smooth.png"}]
JSON
    for _ in $(seq "$runs"); do
        out=$(xvfb-run -a -s "-screen 0 1920x1080x24" "$build/shadelab" view "$scene" --size 1280x720 --frames 11 \
              --verbose --script "$tmp/script.json" 2>&1)
        all+=" $(sed -n 's/.*smooth frame, 16 samples, \([0-9]*\) ms after the last change.*/\1/p' <<<"$out" | tail -1)"
    done
    echo "$label: smooth frame complete after:$all ms -> median $(median <<<"$all") ms"
}
bench "default scene, Raster" assets/scenes/default.json "red plastic"
