#!/usr/bin/env bash
# Builds every libFuzzer target with clang + ASan/UBSan in build-fuzz/ and runs each for SECONDS (default 600),
# as many at once as there are cores, then prints each one's executions and coverage (libFuzzer's final stats:
# `cov:` edges, `ft:` features). Each starts from a copy of its seed corpus (tests/fuzz/README.md) in
# build-fuzz/corpus/<target>/, where libFuzzer also keeps what it finds; the repository's seeds stay as they are.
# Crashes land in build-fuzz/artifacts/; minimise one (`<target> -minimize_crash=1 -runs=10000 FILE`) and add it
# to tests/fuzz/corpus/<target>/ as regression-<what>.
# The whole-process structural fuzzer is separate and needs no clang:
#   /usr/bin/python3 tests/fuzz/gltf_mutate.py build/shadelab --cases 3000
# (mutated glTF/GLB structure through `shadelab render`: exit 0 or 1, one capped line, 10 s, 1 GiB).
# usage: tests/fuzz/run.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-600}
targets=(scene_json_fuzz gltf_fuzz hdr_fuzz gltf_texture_fuzz script_fuzz exr_fuzz)
scripts/install-deps.sh --with-fuzz
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADELAB_FUZZ=ON \
  -DSHADELAB_SANITIZE=address,undefined -DSHADELAB_BUILD_TESTS=OFF -DSHADELAB_BUILD_PYTHON=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}" make_exr_seeds

# Seeds: the repository's corpora, the shipped scenes, models and sky, and Debian's glTF sample models.
seed() {  # seed TARGET FILES...
  local dir=build-fuzz/corpus/$1
  shift
  mkdir -p "$dir"
  cp "$@" "$dir/" 2>/dev/null || true
}
rm -rf build-fuzz/corpus
mkdir -p build-fuzz/artifacts
seed scene_json_fuzz assets/scenes/*.json
seed gltf_fuzz assets/models/*.gltf assets/models/textures/*.gltf
find /usr/share/assimp/models/glTF2 \( -name '*.gltf' -o -name '*.glb' \) -size -200k \
  -exec cp {} build-fuzz/corpus/gltf_fuzz/ \; 2>/dev/null || true
seed hdr_fuzz tests/fuzz/corpus/hdr_fuzz/* assets/environments/*.hdr
seed gltf_texture_fuzz tests/fuzz/corpus/gltf_texture_fuzz/* assets/models/textures/*.gltf
seed script_fuzz tests/fuzz/corpus/script_fuzz/*
mkdir -p build-fuzz/corpus/exr_fuzz && build-fuzz/tests/fuzz/make_exr_seeds build-fuzz/corpus/exr_fuzz

run_one() {
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  "build-fuzz/tests/fuzz/$1" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -max_len=262144 \
    -artifact_prefix="build-fuzz/artifacts/$1-" -print_final_stats=1 "build-fuzz/corpus/$1" \
    >"build-fuzz/$1.log" 2>&1 || true
}
cores=$(nproc)
for t in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= cores)); do wait -n || true; done
  run_one "$t" &
done
wait

printf '%-20s %12s %8s %8s  %s\n' target execs cov ft "last status"
for t in "${targets[@]}"; do
  log=build-fuzz/$t.log
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  # The last status line ("#N DONE cov: C ft: F corp: ..." or the last pulse) holds the final coverage.
  status=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$status")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$status")
  printf '%-20s %12s %8s %8s  %s\n' "$t" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$(cut -c1-60 <<<"$status")"
  grep -E 'ERROR|SUMMARY' "$log" | head -n 4 || true
done
if ls build-fuzz/artifacts/* >/dev/null 2>&1; then echo "crashes found:"; ls build-fuzz/artifacts; exit 1; fi
