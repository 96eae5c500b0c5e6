#!/usr/bin/env bash
# Builds the libFuzzer targets with clang + ASan/UBSan in build-fuzz/ and runs each for SECONDS (default 600),
# seeded with the repository's scenes and Debian's glTF test models. Crashes land in build-fuzz/artifacts/;
# turn each into a regression test under tests/fuzz/regressions/.
# The whole-process structural fuzzer is separate and needs no clang:
#   /usr/bin/python3 tests/fuzz/gltf_mutate.py build/shadelab --cases 3000
# (mutated glTF/GLB structure through `shadelab render`: exit 0 or 1, one capped line, 10 s, 1 GiB).
# usage: tests/fuzz/run.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-600}
scripts/install-deps.sh --with-fuzz
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSHADELAB_FUZZ=ON \
  -DSHADELAB_SANITIZE=address,undefined -DSHADELAB_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target scene_json_fuzz gltf_fuzz
mkdir -p build-fuzz/corpus/json build-fuzz/corpus/gltf build-fuzz/artifacts
cp assets/scenes/*.json tests/fuzz/regressions/*.json build-fuzz/corpus/json/ 2>/dev/null || true
find /usr/share/assimp/models/glTF2 -name '*.gltf' -size -200k -exec cp {} build-fuzz/corpus/gltf/ \; 2>/dev/null || true
find /usr/share/assimp/models/glTF2 -name '*.glb' -size -200k -exec cp {} build-fuzz/corpus/gltf/ \; 2>/dev/null || true
cp assets/models/*.gltf tests/fuzz/regressions/*.gl* build-fuzz/corpus/gltf/ 2>/dev/null || true
# Both targets at once, one core each.
for t in scene_json_fuzz:json gltf_fuzz:gltf; do
  name=${t%%:*}; dir=${t##*:}
  UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  build-fuzz/tests/fuzz/$name -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=262144 \
    -artifact_prefix=build-fuzz/artifacts/$name- -print_final_stats=1 build-fuzz/corpus/$dir \
    >build-fuzz/$name.log 2>&1 &
done
wait
for name in scene_json_fuzz gltf_fuzz; do
  echo "== $name (${seconds}s)"
  grep -E '^#[0-9]+ +DONE|^stat::|ERROR|SUMMARY' build-fuzz/$name.log | tail -n 8
done
if ls build-fuzz/artifacts/* >/dev/null 2>&1; then echo "crashes found:"; ls build-fuzz/artifacts; exit 1; fi
