#!/bin/bash
# The pictures of docs/materials.md's "Bump vs normal maps" section: diptych compare's
# surface-detail variants on samples/scenes/surface-detail.json. Top row: flat, bump, normal map
# (baked from the same height), the displaced reference (Whitted); bottom row: their FLIP maps
# against it (the reference's own place shows the detail-displaced hybrid's, ~0).
#   tests/tools/make_surface_detail_pictures.sh build/release/diptych docs/images [SIZE] [OUT_DIR]
# SIZE defaults to 320x240; OUT_DIR (default a temporary folder) keeps results.json.
set -eu
BIN=$1 IMAGES=$2 SIZE=${3:-320x240}
OUT=${4:-$(mktemp -d)}
HERE=$(cd "$(dirname "$0")/../.." && pwd)
"$BIN" compare "$HERE/samples/scenes/surface-detail.json" \
  --variants detail-flat,detail-bump,detail-normal-map,detail-displaced \
  --size "$SIZE" --frames 3 --warmup 1 --out "$OUT"
i="$OUT/images" h="$OUT/heatmaps"
rgb=()  # the images carry alpha, the heat maps not: RGB only, for one mosaic
for f in "$i/detail-flat.png" "$i/detail-bump.png" "$i/detail-normal-map.png" "$i/reference.png" \
  "$h/detail-flat.png" "$h/detail-bump.png" "$h/detail-normal-map.png" "$h/detail-displaced.png"; do
  rgb+=("$f" --ch R,G,B)
done
oiiotool "${rgb[@]}" --mosaic 4x2 -o "$IMAGES/materials-surface-detail.png"
