#!/usr/bin/env bash
# Leak check: one headless raster render and one traced render under valgrind memcheck with
# tests/leaks/system.supp. Passes when valgrind reports no error and no definite or indirect leak.
# usage: leak_check.sh SHADELAB_BINARY SOURCE_DIR raster|trace OUTPUT_DIR     (exit 77: skipped)
set -u
bin=$1 src=$2 renderer=$3 out=$4
command -v valgrind >/dev/null || { echo "SKIPPED: valgrind is not installed"; exit 77; }
mkdir -p "$out"
log="$out/valgrind-$renderer.log"
# Mesa's shader disk cache makes the first run after a shader change take another path (and a client check
# inside it); with the cache off every run is the same.
MESA_SHADER_CACHE_DISABLE=true valgrind --leak-check=full --show-leak-kinds=definite,indirect --errors-for-leak-kinds=definite,indirect \
  --error-exitcode=3 --keep-debuginfo=yes --num-callers=40 --suppressions="$src/tests/leaks/system.supp" \
  "$bin" render "$src/assets/scenes/torus.json" --renderer "$renderer" --size 48x27 -o "$out/leak-$renderer.png" \
  >"$log" 2>&1
rc=$?
grep -E "ERROR SUMMARY|definitely lost|indirectly lost" "$log"
if [[ $rc -ne 0 ]]; then
  echo "valgrind found problems (exit $rc); full log: $log"
  exit 1
fi
echo "no leaks or memory errors in shadelab's code ($renderer render); log: $log"
