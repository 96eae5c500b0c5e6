#!/usr/bin/env bash
# Layer benchmark: a glTF asset with material layers rendered headless at 1920x1080 under pbr, its layers shaded,
# against the same asset with every material extension stripped (a copy of the asset with the .gltf edited): whole
# process, PAIRS interleaved pairs (default 15, the order alternating) after one warm-up each. Prints the medians of
# wall and CPU time (user + system) and the ratios. Usage: bench/render_layers.sh [ASSET.gltf]; the default is
# Khronos's ClearCoatTest.gltf (Debian's assimp-testmodels); shadelab's grids are in assets/models/layers/.
# Target: layered <= 1.3x stripped.
set -euo pipefail
cd "$(dirname "$0")/.."
asset=$(realpath "${1:-/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf}")
dir=$(dirname "$asset")
name=$(basename "$asset")
[[ -f "$asset" ]] || { echo "render_layers.sh: $asset missing (apt-get install assimp-testmodels)" >&2; exit 1; }
[[ -x build/shadelab ]] || scripts/build.sh
[[ -x /usr/bin/time ]] || { echo "render_layers.sh: /usr/bin/time missing (apt-get install time)" >&2; exit 1; }
pairs=${PAIRS:-15}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mkdir "$out/stripped"
cp "$dir"/* "$out/stripped/"
rm "$out/stripped/$name"
/usr/bin/python3 - "$asset" "$out/stripped/$name" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
for m in d.get("materials", []):
    m.pop("extensions", None)
d["extensionsUsed"] = [e for e in d.get("extensionsUsed", []) if not e.startswith("KHR_materials_")]
json.dump(d, open(sys.argv[2], "w"))
PY
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "asset: $asset"
run() {  # coated|stripped -> appends "wall cpu" (seconds) to $out/$1.txt
  local model="$asset"
  [[ $1 == stripped ]] && model="$out/stripped/$name"
  /usr/bin/time -f "%e %U %S" -o "$out/t" build/shadelab render "$model" -o "$out/$1.png" --size 1920x1080 \
    --model pbr
  awk '{printf "%s %.3f\n", $1, $2 + $3}' "$out/t" >> "$out/$1.txt"
}
run stripped; run coated; rm -f "$out/stripped.txt" "$out/coated.txt"  # warm-up: Mesa's shader cache
for ((i = 0; i < pairs; ++i)); do
  if ((i % 2 == 0)); then run stripped; run coated; else run coated; run stripped; fi
done
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
for col in 1 2; do
  name=$([[ $col == 1 ]] && echo "wall" || echo "cpu ")
  ta=$(cut -d' ' -f$col "$out/stripped.txt" | median)
  tb=$(cut -d' ' -f$col "$out/coated.txt" | median)
  awk -v n="$name" -v p="$ta" -v q="$tb" -v k="$pairs" \
    'BEGIN {printf "%s median of %d: stripped %.0f ms, coated %.0f ms, coated/stripped %.3f\n", n, k, 1000 * p, 1000 * q, q / p}'
done
