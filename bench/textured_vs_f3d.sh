#!/usr/bin/env bash
# Textured-model benchmark: a textured glTF model rendered headlessly at 1920x1080 by shadelab (`render`, EGL)
# and by F3D (`f3d --output`, the baseline; never a shadelab dependency: apt-get install f3d), whole
# process, RUNS alternating runs each, medians. Target: shadelab <= 0.40x F3D's time. F3D 1.3 needs an X
# display even for --output, so it runs on the DISPLAY given (an Xvfb is started when none is set).
# shadelab frames the model with --camera fit (its default for a model), F3D with its own framing; neither
# model below has a glTF camera. Also prints shadelab's --timings stage breakdown of one run.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
runs=${RUNS:-5}
[[ -x $build/shadelab ]] || scripts/build.sh
command -v f3d >/dev/null || { echo "textured_vs_f3d: f3d is not installed (apt-get install f3d); nothing to compare" >&2; exit 1; }
if [[ -z "${DISPLAY:-}" ]]; then
  command -v Xvfb >/dev/null || { echo "textured_vs_f3d: F3D needs an X display; install xvfb" >&2; exit 1; }
  Xvfb :93 -screen 0 1920x1080x24 >/dev/null 2>&1 &
  xvfb=$!
  trap 'kill $xvfb' EXIT
  export DISPLAY=:93
  sleep 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"; [[ -n "${xvfb:-}" ]] && kill "$xvfb" 2>/dev/null || true' EXIT
models=${MODELS:-"/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb
/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf"}
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "f3d: $(f3d --version 2>&1 | head -1)"
median() { tr ' ' '\n' | grep . | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
seconds() { local t0 t1; t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N); echo "$t1 - $t0" | bc; }
while read -r model; do
  [[ -f $model ]] || { echo "skip: $model is missing (apt-get install assimp-testmodels)"; continue; }
  ours="" theirs=""
  for _ in $(seq "$runs"); do
    ours+=" $(seconds "$build/shadelab" render "$model" --size 1920x1080 -o "$tmp/shadelab.png")"
    theirs+=" $(seconds f3d "$model" --resolution=1920,1080 --output="$tmp/f3d.png")"
  done
  a=$(median <<<"$ours") b=$(median <<<"$theirs")
  echo "$(basename "$model"): shadelab$ours -> $a s; f3d$theirs -> $b s; ratio $(echo "scale=2; $a / $b" | bc) (target <= 0.40)"
  "$build/shadelab" render "$model" --size 1920x1080 -o "$tmp/shadelab.png" --timings 2>&1 | sed 's/^/    /'
done <<<"$models"
