#!/usr/bin/env bash
# Path tracer benchmark: paths per second of shadelab's path tracer against Blender Cycles on the default
# scene (assets/scenes/default.json) at 1280x720, 16 spp, 5 bounces, 2 threads, in one run on one machine.
# Cycles renders the scene as bench/cycles_default.py translates it (CPU, no denoising, no adaptive
# sampling). Paths/s = 1280*720*16 / time. Runs alternate Blender and shadelab (RUNS of each, default 3) so
# that both see the same load; medians are printed, of wall time and of CPU time (user + system of the
# whole process, all threads), the steadier figure when other work shares the cores.
# Target: shadelab >= 2x Cycles.
#
# Blender is a benchmark baseline only (apt-get install blender; never a shadelab dependency): without it
# the Cycles half is skipped. The shadelab half is skipped when `shadelab render --help` has no
# `--renderer path`. Environment: BUILD_DIR (default build), RUNS (3), SPP (16), THREADS (2),
# SIZE (1280x720), BOUNCES (5), OUT_DIR (keep the PNGs and logs there; default a temporary folder,
# removed), CYCLES_ARGS (extra arguments for cycles_default.py, e.g. "--falloff constant").
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
runs=${RUNS:-3}
spp=${SPP:-16}
threads=${THREADS:-2}
size=${SIZE:-1280x720}
bounces=${BOUNCES:-5}
scene=assets/scenes/default.json
[[ $runs =~ ^[1-9][0-9]*$ && $spp =~ ^[1-9][0-9]*$ && $threads =~ ^[1-9][0-9]*$ && $bounces =~ ^[0-9]+$ &&
    $size =~ ^([1-9][0-9]*)x([1-9][0-9]*)$ ]] ||
    { echo "path_vs_cycles: RUNS, SPP, THREADS, BOUNCES must be whole numbers and SIZE WxH" >&2; exit 2; }
paths=$((BASH_REMATCH[1] * BASH_REMATCH[2] * spp))
if [[ -n ${OUT_DIR:-} ]]; then
    out=$OUT_DIR
    mkdir -p "$out"
else
    out=$(mktemp -d)
    trap 'rm -rf "$out"' EXIT
fi

have_blender=0
if command -v blender > /dev/null; then
    have_blender=1
else
    echo "path_vs_cycles: blender is not installed: skipping the Cycles baseline (apt-get install blender)"
fi

have_path=0
if [[ ! -x $build/shadelab ]]; then
    echo "path_vs_cycles: $build/shadelab not built: skipping shadelab (scripts/build.sh, or set BUILD_DIR)"
else
    help=$("$build/shadelab" render --help 2>&1 || true)
    # The --renderer option's lines (its description may wrap) must name `path`.
    renderer_help=$(awk '/^ *--renderer/ {on = 1; print; next} on && /^ *-/ {exit} on' <<< "$help")
    if grep -Eq '(^|[^-[:alnum:]])path([^-[:alnum:]]|$)' <<< "$renderer_help"; then
        have_path=1
        # The depth flag's name: --max-depth if the help has it, else the tracer's --depth.
        depth_flag=--depth
        if grep -q -- '--max-depth' <<< "$help"; then depth_flag=--max-depth; fi
    else
        echo "path_vs_cycles: '$build/shadelab render --help' has no '--renderer path': skipping shadelab"
    fi
fi
((have_blender || have_path)) || exit 0

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "scene: $scene, $size, $spp spp, $bounces bounces, $threads threads: $paths paths per image"
if ((have_blender)); then echo "blender: $(blender --version 2> /dev/null | head -1)"; fi

# shellcheck source=bench/timing.sh
source bench/timing.sh
mps() { awk -v p="$paths" -v t="$1" 'BEGIN {printf "%.3f", p / t / 1e6}'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", b / a}'; }  # paths/s ratio = inverse time ratio

blender_wall=() blender_render=() blender_cpu=() shadelab_wall=() shadelab_cpu=()
for ((i = 1; i <= runs; i++)); do
    if ((have_blender)); then
        # shellcheck disable=SC2086  # CYCLES_ARGS is a list of words
        timed "$out/time" "$out/cycles.log" blender -b --factory-startup --python-exit-code 1 \
            --python bench/cycles_default.py -- "$scene" "$out/cycles.png" "$spp" "$threads" \
            --size "$size" --bounces "$bounces" ${CYCLES_ARGS:-} ||
            { cat "$out/cycles.log" >&2; echo "path_vs_cycles: blender failed" >&2; exit 1; }
        read -r wall cpu < "$out/time"
        render=$(sed -n 's/^cycles: render time \([0-9.]*\) s.*/\1/p' "$out/cycles.log")
        [[ -n $render ]] ||
            { cat "$out/cycles.log" >&2; echo "path_vs_cycles: no render time in blender's output" >&2; exit 1; }
        blender_wall+=("$wall") blender_render+=("$render") blender_cpu+=("$cpu")
        echo "run $i: blender whole process $wall s (CPU $cpu s), Cycles render $render s"
    fi
    if ((have_path)); then
        timed "$out/time" "$out/shadelab.log" "$build/shadelab" render "$scene" --renderer path --spp "$spp" \
            --threads "$threads" "$depth_flag" "$bounces" --size "$size" -o "$out/shadelab.png" ||
            { cat "$out/shadelab.log" >&2; echo "path_vs_cycles: shadelab failed" >&2; exit 1; }
        read -r wall cpu < "$out/time"
        shadelab_wall+=("$wall") shadelab_cpu+=("$cpu")
        echo "run $i: shadelab whole process $wall s (CPU $cpu s)"
    fi
done

echo "medians of $runs:"
if ((have_blender)); then
    bw=$(printf '%s\n' "${blender_wall[@]}" | median)
    br=$(printf '%s\n' "${blender_render[@]}" | median)
    bc=$(printf '%s\n' "${blender_cpu[@]}" | median)
    echo "  Cycles, whole process:   $bw s = $(mps "$bw") Mpaths/s (CPU $bc s)"
    echo "  Cycles, its render time: $br s = $(mps "$br") Mpaths/s"
fi
if ((have_path)); then
    sw=$(printf '%s\n' "${shadelab_wall[@]}" | median)
    sc=$(printf '%s\n' "${shadelab_cpu[@]}" | median)
    echo "  shadelab, whole process: $sw s = $(mps "$sw") Mpaths/s (CPU $sc s)"
fi
if ((have_blender && have_path)); then
    # Against Cycles' render time (Blender's start-up excluded) is the stricter wall-time ratio.
    echo "  shadelab / Cycles paths/s: $(ratio "$sw" "$br")x against Cycles' render time," \
        "$(ratio "$sw" "$bw")x against its whole process, $(ratio "$sc" "$bc")x in CPU time (target >= 2x)"
fi
if [[ -n ${OUT_DIR:-} ]]; then echo "images: $out/cycles.png, $out/shadelab.png"; fi
