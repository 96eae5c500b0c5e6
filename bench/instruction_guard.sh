#!/usr/bin/env bash
# Instruction-count regression guard: timings drift by tens of percent on a shared machine, instruction counts
# do not. Each kernel runs once under valgrind's callgrind, counting only inside the functions that do its work
# (--toggle-collect, per thread; the patterns name one function each, since a match nested in another turns
# counting off again), and its count is compared with bench/instruction_baseline.txt; a count more
# than TOLERANCE percent (default 3) above its baseline fails the run, one well below it is reported so the
# baseline can follow the improvement. The kernels, each small enough to take seconds under callgrind:
#   whitted      bench/spheres40.json traced at 160x90, 1 thread           (trace::renderTile)
#   path         assets/scenes/default.json path traced, 64x36, 1 spp       (PathRender::renderPixel)
#   coherent     2CylinderEngine: a primary ray per pixel + a shadow ray per hit at 160x90 (trace_bench)
#   packets      the same rays as coherent, as packets of eight (TraceScene::intersect8 / occluded8)
#   incoherent   2CylinderEngine: one cosine-distributed bounce per hit at 160x90 (trace_bench)
#   bvh_build    loading 2CylinderEngine and building its BVH, every thread: the whole `shadelab render
#                --renderer trace` process at 8x8 (not trace_bench's, which links Embree where it is installed)
#   png_encode   320x180 frames to PNG, clean and noisy, one band           (encodePngBands)
# Counts depend on the compiler and its flags: the baseline is for the Release build of scripts/build.sh on
# Debian 12's g++, and this runs only against such a build (ctest registers it in Release builds only).
#
# Usage: bench/instruction_guard.sh [--update] [kernel...]
#   --update  rewrite the baseline with this build's counts (do it in the commit that moves them, and say
#             why in its message)
# Environment: BUILD_DIR (default build), TOLERANCE (percent, default 3), BASELINE (default
# bench/instruction_baseline.txt), GUARD_EXTRA (extra arguments for every kernel's command: the test's negative
# control passes one that doubles the work).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
tolerance=${TOLERANCE:-3}
baseline=${BASELINE:-bench/instruction_baseline.txt}
engine=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
update=0
if [[ ${1:-} == --update ]]; then
    update=1
    shift
fi
if [[ ${1:-} == -h || ${1:-} == --help ]]; then
    sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'
    exit 0
fi
all=(whitted path coherent packets incoherent bvh_build png_encode)
kernels=("$@")
[[ ${#kernels[@]} -gt 0 ]] || kernels=("${all[@]}")
[[ $tolerance =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "instruction_guard: TOLERANCE must be a number" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "instruction_guard: valgrind is missing (scripts/install-deps.sh)" >&2; exit 1; }
command -v callgrind_annotate >/dev/null || { echo "instruction_guard: callgrind_annotate is missing" >&2; exit 1; }
for tool in shadelab bench/trace_bench bench/image_encode_bench; do
    [[ -x $build/$tool ]] || { echo "instruction_guard: $build/$tool is missing (build it first)" >&2; exit 1; }
done
[[ -f $engine ]] || { echo "instruction_guard: $engine: no such file (apt-get install assimp-testmodels)" >&2; exit 1; }
[[ $update == 1 || -f $baseline ]] || { echo "instruction_guard: $baseline: no such file (run with --update)" >&2; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# The command and the functions counted for one kernel.
kernel() {
    local extra=${GUARD_EXTRA:-}
    case $1 in
        whitted)
            toggles=("shadelab::trace::renderTile(*")
            cmd=("$build/shadelab" render bench/spheres40.json --renderer trace --size 160x90 --threads 1 -o "$out/w.png")
            ;;
        path)
            toggles=("shadelab::trace::PathRender::renderPixel(*")
            cmd=("$build/shadelab" render assets/scenes/default.json --renderer path --size 64x36 --spp 1 --threads 1
                -o "$out/p.png")
            ;;
        coherent)
            toggles=("*traceOurs*")
            cmd=("$build/bench/trace_bench" --only engine --runs 1 --threads 1 --size 160x90 --engine "$engine" --no-embree)
            ;;
        packets)
            toggles=("shadelab::trace::TraceScene::intersect8(*" "shadelab::trace::TraceScene::occluded8(*")
            cmd=("$build/bench/trace_bench" --only engine --runs 1 --threads 1 --size 160x90 --engine "$engine" --no-embree)
            ;;
        incoherent)
            toggles=("*nearestHitsOurs*")
            cmd=("$build/bench/trace_bench" --only incoherent --runs 1 --threads 1 --size 160x90 --engine "$engine"
                --no-embree)
            ;;
        bvh_build)
            toggles=()  # the whole process, every builder thread: loading the model and building its BVH
            cmd=("$build/shadelab" render "$engine" --renderer trace --threads 1 --size 8x8 -o "$out/b.png")
            ;;
        png_encode)
            toggles=("shadelab::detail::encodePngBands(shadelab::Image8 const&, int)")
            cmd=("$build/bench/image_encode_bench" 1 320 180)
            ;;
        *)
            echo "instruction_guard: unknown kernel '$1'; expected one of: ${all[*]}" >&2
            exit 2
            ;;
    esac
    # shellcheck disable=SC2206
    [[ -z $extra ]] || cmd+=($extra)
}

# Instructions counted for one kernel: callgrind's total over the toggled functions.
count() {
    local name=$1 args=()
    kernel "$name"
    for t in "${toggles[@]+"${toggles[@]}"}"; do args+=(--toggle-collect="$t"); done
    valgrind --tool=callgrind "${args[@]}" --callgrind-out-file="$out/$name.cg" "${cmd[@]}" >"$out/$name.log" 2>&1 || {
        tail -5 "$out/$name.log" >&2
        echo "instruction_guard: $name: the kernel's run failed: ${cmd[*]}" >&2
        exit 1
    }
    local n
    n=$(callgrind_annotate "$out/$name.cg" 2>/dev/null | awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1; exit }')
    [[ -n $n && $n -gt 0 ]] || { echo "instruction_guard: $name: callgrind counted nothing" >&2; exit 1; }
    echo "$n"
}

declare -A base
if [[ -f $baseline ]]; then
    while read -r name n _; do
        [[ -z $name || $name == \#* ]] || base[$name]=$n
    done <"$baseline"
fi

failed=0
declare -A now
for k in "${kernels[@]}"; do
    now[$k]=$(count "$k")
    if [[ $update == 1 ]]; then
        printf '%-11s %14d\n' "$k" "${now[$k]}"
        continue
    fi
    b=${base[$k]:-}
    if [[ -z $b ]]; then
        printf '%-11s %14d  (no baseline: run with --update)\n' "$k" "${now[$k]}"
        failed=1
        continue
    fi
    verdict=$(awk -v n="${now[$k]}" -v b="$b" -v tol="$tolerance" 'BEGIN {
        d = 100 * (n - b) / b
        if (d > tol) printf "%+.2f%% FAIL (over +%s%%)", d, tol
        else if (d < -tol) printf "%+.2f%% faster: update the baseline (--update)", d
        else printf "%+.2f%% ok", d }')
    printf '%-11s %14d  baseline %14d  %s\n' "$k" "${now[$k]}" "$b" "$verdict"
    [[ $verdict != *FAIL* ]] || failed=1
done

if [[ $update == 1 ]]; then
    tmp=$(mktemp "$baseline.XXXXXX")
    {
        echo "# Instructions per kernel (bench/instruction_guard.sh), Release build, Debian 12 g++."
        echo "# Update with bench/instruction_guard.sh --update, in the commit that moves them, saying why."
        for k in "${all[@]}"; do
            n=${now[$k]:-${base[$k]:-}}
            [[ -z $n ]] || printf '%-11s %d\n' "$k" "$n"
        done
    } >"$tmp"
    mv "$tmp" "$baseline"
    echo "instruction_guard: wrote $baseline"
    exit 0
fi
if [[ $failed == 1 ]]; then
    echo "instruction_guard: FAIL: a kernel's instruction count grew by more than $tolerance % (or has no baseline)" >&2
    exit 1
fi
echo "instruction_guard: every kernel within $tolerance % of its baseline"
