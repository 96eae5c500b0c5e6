#!/usr/bin/env bash
# The README's "Your first five minutes" commands, run as written, in order, in a fresh copy of the repository
# (its tracked files only: no out/, no build/), with build/ pointing at the build under test. A line may say
# the exit status it expects in a trailing comment ("# FAIL (exit 1): ..."); every other line must exit 0.
# Run twice by ctest: without a display, every line, where each `view` line must exit 1 saying it needs one;
# and with one (a fresh Xvfb, tests/with_xvfb.sh), the `view` lines alone, the only ones a display changes,
# each with `--frames 5` added, the only change to a line, since the viewer otherwise runs until it is closed.
# On failure the copy, with every command's output, stays in OUTPUT_DIR.
#
# The Quick start's first command, scripts/run.sh, is install-deps, build and then scripts/show.sh: its install
# and build are the second command's too (CI runs that one on a fresh clone), so here the Quick start must hold
# exactly those two commands, run.sh must end in show.sh, and show.sh runs first, in the copy: without a
# display it must write out/default.png and out/default-blinn.png, with one open the viewer (--frames 5).
#
# Usage: tests/readme_test.sh SOURCE_DIR BUILD_DIR OUTPUT_DIR [--display]
set -euo pipefail
[[ $# -ge 3 ]] || { echo "usage: readme_test.sh SOURCE_DIR BUILD_DIR OUTPUT_DIR [--display]" >&2; exit 2; }
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
output=$3
display=${4:-}

# The sh blocks of the section, with backslash continuations joined: one command per line.
commands=$(awk '
    /^## / { in_section = ($0 ~ /^## Your first five minutes/) }
    in_section && /^```sh/ { in_block = 1; next }
    in_block && /^```/ { in_block = 0; next }
    in_block { print }' "$src/README.md" |
    sed -e ':a' -e '/\\$/N; s/\\\n[[:space:]]*/ /; ta' | grep -v '^[[:space:]]*\(#\|$\)' || true)
count=$(printf '%s\n' "$commands" | grep -c . || true)
[[ $count -ge 10 ]] || { echo "readme_test: only $count commands found in README.md's first five minutes" >&2; exit 1; }

rm -rf "$output"
mkdir -p "$output/clone"
(cd "$src" && git ls-files -z | xargs -0 cp --parents -t "$output/clone")
ln -s "$build" "$output/clone/build"
cd "$output/clone"
[[ ! -e out ]] || { echo "readme_test: the copy already has out/" >&2; exit 1; }

if [[ $display == --display ]]; then
    wrap=("$src/tests/with_xvfb.sh")
else
    wrap=(env -u DISPLAY -u WAYLAND_DISPLAY)
fi
n=0
ran=0
failed=0

# The Quick start: exactly its two commands, the first ending in the main job that runs here.
quick=$(awk '
    /^## / { in_section = ($0 ~ /^## Quick start/) }
    in_section && /^```sh/ { in_block = 1; next }
    in_block && /^```/ { in_block = 0; next }
    in_block { sub(/[[:space:]]*#.*/, ""); if (length($0)) print }' "$src/README.md")
if [[ $quick != $'scripts/run.sh\nscripts/test.sh' ]]; then
    echo "readme_test: the Quick start should be exactly scripts/run.sh and scripts/test.sh, got:" >&2
    printf '%s\n' "$quick" >&2
    failed=1
fi
if [[ $(grep -v '^[[:space:]]*\(#\|$\)' scripts/run.sh | tail -1) != 'exec scripts/show.sh "$@"' ]]; then
    echo "readme_test: scripts/run.sh no longer ends in scripts/show.sh, the part run here" >&2
    failed=1
fi
show=(scripts/show.sh)
[[ $display != --display ]] || show+=(--frames 5)
status=0
"${wrap[@]}" "${show[@]}" >"$output/quick-start.log" 2>&1 || status=$?
printf '  0  exit %d        %s (the Quick start'"'"'s main job)\n' "$status" "${show[*]}"
if [[ $status != 0 ]]; then
    echo "readme_test: ${show[*]} exited $status" >&2
    tail -5 "$output/quick-start.log" >&2
    failed=1
elif [[ $display != --display ]]; then
    for f in out/default.png out/default-blinn.png; do
        [[ -s $f ]] || { echo "readme_test: scripts/show.sh did not write $f" >&2; failed=1; }
    done
    grep -q "Rendered the default scene headlessly" "$output/quick-start.log" ||
        { echo "readme_test: scripts/show.sh did not say where the PNGs are" >&2; failed=1; }
    rm -rf out  # the first five minutes start without out/, as on a fresh clone
fi
while IFS= read -r line; do
    n=$((n + 1))
    expected=0
    if [[ $line =~ \#.*exit\ ([0-9]+) ]]; then expected=${BASH_REMATCH[1]}; fi
    command=${line%%#*}
    viewer=0
    [[ $command != *" view "* ]] || viewer=1
    if [[ $viewer == 0 && $display == --display ]]; then
        continue
    elif [[ $viewer == 1 && $display == --display ]]; then
        command="$command --frames 5"
    elif [[ $viewer == 1 ]]; then
        expected=1
    fi
    ran=$((ran + 1))
    log="$output/command-$n.log"
    start=$(date +%s)
    status=0
    # shellcheck disable=SC2086
    "${wrap[@]}" bash -c "$command" >"$log" 2>&1 || status=$?
    printf '%3d  exit %d  %4ds  %s\n' "$n" "$status" "$(($(date +%s) - start))" "$command"
    if [[ $status != "$expected" ]]; then
        echo "readme_test: command $n exited $status, expected $expected: $command" >&2
        tail -5 "$log" >&2
        failed=1
    elif [[ $viewer == 1 && $display != --display ]] && ! grep -q "needs a display" "$log"; then
        echo "readme_test: command $n without a display did not say it needs one: $command" >&2
        failed=1
    fi
done <<<"$commands"

# What the section promises to leave behind exists.
promised=(out/phong.png out/both.png out/heat.png out/global.png out/cornell.exr out/row.png)
[[ $display != --display ]] || promised=()
for f in "${promised[@]+"${promised[@]}"}"; do
    [[ -s $f ]] || { echo "readme_test: $f was not written" >&2; failed=1; }
done
if [[ $failed == 1 ]]; then
    echo "readme_test: FAIL; the copy and each command's output are in $output" >&2
    exit 1
fi
cd /
rm -rf "$output"
echo "readme_test: $ran of the $n commands ran as written${display:+ (the viewer lines, with a display)}"
