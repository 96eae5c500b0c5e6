#!/usr/bin/env bash
# Viewer benchmark: frame times under Xvfb at 1280x720 (`shadelab view --frames N --stats`), each
# case run RUNS times (default 5); prints every run's medians and the median of them. Targets: a frame while
# a shininess slider is dragged <= 33 ms; orbiting < 40 ms; <= 50 ms while the reference restarts every frame
# (Split, a shininess change per frame). Orbiting is measured twice: as the viewer runs by default, with the
# half-size preview while the camera moves (raster.movingPreview), and with the preview off (every orbit frame
# at full size). ENGINE=0 leaves out the 2CylinderEngine case.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
[[ -x $build/shadelab ]] || scripts/build.sh
command -v xvfb-run >/dev/null || { echo "viewer_frames: xvfb-run is missing (apt-get install xvfb)" >&2; exit 1; }
runs=${RUNS:-5}
frames=${FRAMES:-200}
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
median() { tr ' ' '\n' | grep . | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
bench() {  # label, then shadelab view arguments
    local label=$1; shift
    local frame="" p95="" draw="" idle=""
    for _ in $(seq "$runs"); do
        out=$(xvfb-run -a -s "-screen 0 1920x1080x24" "$build/shadelab" view "$@" --size 1280x720 \
              --frames "$frames" --stats 2>&1)
        frame+=" $(awk '/frame, raster redrawn/ {print $6}' <<<"$out")"
        p95+=" $(awk '/frame, raster redrawn/ {print $9}' <<<"$out")"
        draw+=" $(awk '/raster draw alone/ {print $6}' <<<"$out")"
        idle+=" $(awk '/nothing changed/ {print $6}' <<<"$out")"
    done
    echo "$label:"
    echo "  frame with redraw, medians of $runs runs:$frame -> $(median <<<"$frame") ms (p95 median $(median <<<"$p95") ms)"
    echo "  raster draw: $(median <<<"$draw") ms; frame without redraw: $(median <<<"$idle") ms"
}
bench "default scene, Raster, shininess dragged every frame (a partial redraw)" assets/scenes/default.json \
    --script bench/viewer_drag.json
bench "default scene, Raster, full redraw of an unchanged image" assets/scenes/default.json
bench "default scene, Raster, orbiting 1.5 degrees every frame (half-size preview while moving, the default)" \
    assets/scenes/default.json --script bench/viewer_orbit.json
bench "default scene, Raster, orbiting 1.5 degrees every frame, preview off (full size every frame)" \
    assets/scenes/default.json --script bench/viewer_orbit_full.json
bench "default scene, Split, reference restarting every frame" assets/scenes/default.json \
    --script bench/viewer_split_restart.json
if [[ -f $engine && ${ENGINE:-1} != 0 ]]; then
    bench "2CylinderEngine.glb, 4 lights, Blinn-Phong, Raster" "$engine" --script bench/viewer_engine_4lights.json
fi
