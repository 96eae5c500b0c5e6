#!/usr/bin/env bash
# Global illumination at equal error: shadelab's path tracer against Blender Cycles on the Cornell box
# (assets/scenes/cornell.json, as bench/cycles_default.py translates it: the lamp an emissive mesh sphere).
# Cycles renders SPP (64) samples, raw (CPU, THREADS threads, BOUNCES bounces, no denoising, no adaptive
# sampling, and --unbiased: no clamping, no Filter Glossy, no light threshold, a 1-pixel box filter).
# Each renderer's error is its relative RMSE (bench/image_error.h, the lamp left out) against its OWN
# converged reference, since the two images are of nearly, not exactly, the same scene:
# - Cycles: two renders of REF_SPP samples each, seeds 1 and 2, whose mean is the reference and whose
#   difference removes its noise (`class_ready_bench error`, split halves);
# - shadelab: class_ready_bench's cached split-halves reference (REF_SPP x 2 samples, Sobol, seeds 1 and 2).
# Then shadelab's samples to reach Cycles' error are found (class_ready_bench --no-denoise --target E), and
# the two renders are timed in alternating runs (RUNS of each, default 3) as whole processes, `blender` and
# `shadelab render --spp N`, both writing float EXR: medians of wall and CPU time (user + system, all
# threads; the steadier figure when other work shares the cores), and Cycles' own render time.
# Target: shadelab reaches Cycles' 64-spp error in at most a third of Cycles' time.
#
# Blender is a benchmark baseline only (apt-get install blender; never a shadelab dependency): without it
# the script says so and stops (the class-ready half is build/bench/class_ready_bench alone). Cycles'
# references are cached in CACHE_DIR (default BUILD_DIR/bench-cache), keyed by Blender's version, this
# script's translation (cycles_default.py), the scene, size, samples and seed.
# Environment: BUILD_DIR (build), RUNS (3), SPP (64), REF_SPP (256), THREADS (2), SIZE (320x180),
# BOUNCES (5), OUT_DIR (keep the images and logs there; default a temporary folder, removed), CACHE_DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
runs=${RUNS:-3}
spp=${SPP:-64}
ref_spp=${REF_SPP:-256}
threads=${THREADS:-2}
size=${SIZE:-320x180}
bounces=${BOUNCES:-5}
cache=${CACHE_DIR:-$build/bench-cache}
scene=assets/scenes/cornell.json
[[ $runs =~ ^[1-9][0-9]*$ && $spp =~ ^[1-9][0-9]*$ && $ref_spp =~ ^[1-9][0-9]*$ && $threads =~ ^[1-9][0-9]*$ &&
    $bounces =~ ^[0-9]+$ && $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] ||
    { echo "cornell_vs_cycles: RUNS, SPP, REF_SPP, THREADS, BOUNCES must be whole numbers and SIZE WxH" >&2; exit 2; }
if ! command -v blender > /dev/null; then
    echo "cornell_vs_cycles: blender is not installed: skipping the Cycles comparison (apt-get install blender)"
    exit 0
fi
bench=$build/bench/class_ready_bench
for tool in "$bench" "$build/shadelab"; do
    [[ -x $tool ]] || { echo "cornell_vs_cycles: $tool not built (cmake --build $build)" >&2; exit 1; }
done
if [[ -n ${OUT_DIR:-} ]]; then
    out=$OUT_DIR
    mkdir -p "$out"
else
    out=$(mktemp -d)
    trap 'rm -rf "$out"' EXIT
fi
mkdir -p "$cache"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
blender_version=$(blender --version 2> /dev/null | head -1)
echo "blender: $blender_version"
echo "scene: $scene, $size, Cycles $spp spp, $bounces bounces, $threads threads; references 2 x $ref_spp spp"

# shellcheck source=bench/timing.sh
source bench/timing.sh
cycles() {  # output.exr spp seed log
    blender -b --factory-startup --python-exit-code 1 --python bench/cycles_default.py -- "$scene" "$1" "$2" \
        "$threads" --size "$size" --bounces "$bounces" --seed "$3" --unbiased > "$4" 2>&1 ||
        { cat "$4" >&2; echo "cornell_vs_cycles: blender failed" >&2; return 1; }
}

# Cycles' references, rendered once per version of Blender, translation and scene.
key=$(cat bench/cycles_default.py "$scene" | sha256sum | cut -c1-16)
refs=()
for seed in 1 2; do
    ref="$cache/cycles-cornell-${blender_version// /-}-$size-${ref_spp}spp-seed$seed-$key.exr"
    if [[ ! -f $ref ]]; then
        echo "Cycles reference, seed $seed: rendering $ref_spp spp"
        cycles "$ref" "$ref_spp" "$seed" "$out/ref.log"
        grep '^cycles:' "$out/ref.log"
    fi
    refs+=("$ref")
done

# Cycles' error at SPP, then the samples shadelab needs for it.
cycles "$out/cycles.exr" "$spp" 0 "$out/cycles.log"
error_line=$("$bench" error "$out/cycles.exr" "${refs[@]}")
cycles_error=$(sed -n 's/^relative RMSE \([0-9.]*\) .*/\1/p' <<< "$error_line")
echo "Cycles at $spp spp against its reference: $error_line"
"$bench" --no-denoise --target "$cycles_error" --runs 1 --raw-runs 1 --size "$size" --threads "$threads" \
    --ref-spp "$((2 * ref_spp))" --cache "$cache" > "$out/shadelab_error.log"
grep -E '^reference|^  raw ' "$out/shadelab_error.log" | grep -v median || true
shadelab_spp=$(sed -n 's/^  raw .* at *\([0-9]*\) spp.*/\1/p' "$out/shadelab_error.log" | head -1)
[[ -n $shadelab_spp ]] ||
    { cat "$out/shadelab_error.log" >&2; echo "cornell_vs_cycles: shadelab did not reach the error" >&2; exit 1; }
echo "shadelab reaches it at $shadelab_spp spp"

cw=() cc=() cr=() ct=() sw=() sc=()
for ((i = 1; i <= runs; i++)); do
    timed "$out/time" "$out/run.log" cycles "$out/cycles.exr" "$spp" 0 "$out/cycles.log"
    read -r wall cpu < "$out/time"
    render=$(sed -n 's/^cycles: render time \([0-9.]*\) s.*/\1/p' "$out/cycles.log")
    tracing=$(sed -n 's/^cycles: .*path tracing alone \([0-9.]*\) s.*/\1/p' "$out/cycles.log")
    cw+=("$wall") cc+=("$cpu") cr+=("$render") ct+=("${tracing:-$render}")
    echo "run $i: blender whole process $wall s (CPU $cpu s), Cycles render $render s (tracing ${tracing:-?} s)"
    timed "$out/time" "$out/shadelab.log" "$build/shadelab" render "$scene" --renderer path --spp "$shadelab_spp" \
        --threads "$threads" --depth "$bounces" --size "$size" -o "$out/shadelab.exr" ||
        { cat "$out/shadelab.log" >&2; echo "cornell_vs_cycles: shadelab failed" >&2; exit 1; }
    read -r wall cpu < "$out/time"
    sw+=("$wall") sc+=("$cpu")
    echo "run $i: shadelab whole process $wall s (CPU $cpu s), $shadelab_spp spp"
done

m() { printf '%s\n' "$@" | median; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }
bw=$(m "${cw[@]}") bc=$(m "${cc[@]}") br=$(m "${cr[@]}") bt=$(m "${ct[@]}") xw=$(m "${sw[@]}") xc=$(m "${sc[@]}")
echo "medians of $runs, at relative RMSE $cycles_error:"
echo "  Cycles $spp spp, whole process:    $bw s (CPU $bc s); its render time $br s, path tracing alone $bt s"
echo "  shadelab $shadelab_spp spp, whole process: $xw s (CPU $xc s)"
echo "  shadelab / Cycles time: $(ratio "$xc" "$bc") in CPU time, $(ratio "$xw" "$bw") in wall time," \
    "$(ratio "$xw" "$br") against Cycles' render time (target <= 0.33)"
if [[ -n ${OUT_DIR:-} ]]; then echo "images: $out/cycles.exr, $out/shadelab.exr"; fi
