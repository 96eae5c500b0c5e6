#!/usr/bin/env bash
# Renders every shipped scene (assets/scenes/*.json) and a few real glTF models with the raster and the
# trace renderer, and prints one "sha256  name" line per PNG. A refactoring that promises "no behaviour
# change" runs it before and after and diffs the two manifests: the PNGs must be byte-identical.
# Usage: scripts/render-manifest.sh [path/to/shadelab] [out-dir]   (defaults: build/shadelab, a temp dir)
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/shadelab}
out=${2:-$(mktemp -d)}
mkdir -p "$out"
models=/usr/share/assimp/models/glTF2
inputs=(assets/scenes/*.json assets/models/torus.gltf)
for m in 2CylinderEngine-glTF-Binary/2CylinderEngine.glb BoxTextured-glTF/BoxTextured.gltf; do
  [[ -f "$models/$m" ]] && inputs+=("$models/$m")
done
for input in "${inputs[@]}"; do
  name=$(basename "${input%.*}")
  for renderer in raster trace; do
    # Small images keep the trace quick; shadows and reflections on, as the scene file says.
    "$bin" render "$input" -o "$out/$name-$renderer.png" --renderer "$renderer" --size 320x240 2>/dev/null
  done
  # A model opened directly renders local terms only; render it with every term too, through both paths.
  for renderer in raster trace; do
    "$bin" render "$input" -o "$out/$name-$renderer-all.png" --renderer "$renderer" --size 320x240 \
      --terms ambient,diffuse,specular,shadows,reflections 2>/dev/null
  done
done
(cd "$out" && sha256sum -- *.png)
