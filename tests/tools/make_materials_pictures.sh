#!/bin/bash
# The pictures of docs/materials.md's "Two shading models" section, from the shared Khronos
# models (../shared/scenes) and a bump-mapped plane written here. Hybrid frames (the default
# recipe), default lighting, exposure 0, clamp.
#   tests/tools/make_materials_pictures.sh build/release/diptych ../shared/scenes docs/images
set -eu
BIN=$1 SCENES=$2 OUT=$3
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
render() { "$BIN" render "$@" --frames 1 --warmup 0 >/dev/null 2>&1; }
spheres="$SCENES/metal-rough-spheres-no-textures/MetalRoughSpheresNoTextures.glb"
helmet="$SCENES/damaged-helmet/DamagedHelmet.glb"
for model in lecture gltf; do
  render "$spheres" --size 320x320 --shading "$model" --out "$TMP/spheres-$model.png"
  render "$helmet" --size 320x320 --shading "$model" --out "$TMP/helmet-$model.png"
done
oiiotool "$TMP/spheres-lecture.png" "$TMP/spheres-gltf.png" "$TMP/helmet-lecture.png" \
  "$TMP/helmet-gltf.png" --mosaic 4x1 -o "$OUT/materials-models.png"
# The lecture's bump mapping: a plane with the procedural sinusoid, flat beside it.
cat >"$TMP/bump.json" <<'JSON'
{"camera": {"position": [0, 2.2, 2.6], "target": [0, 0, 0], "fov": 45},
 "lights": [{"type": "directional", "direction": [-1, -0.6, -0.3], "intensity": 1.2}],
 "materials": {
   "flat": {"color": [0.6, 0.6, 0.6]},
   "bumpy": {"color": [0.6, 0.6, 0.6], "ks": 0.3, "exponent": 40,
             "bump": {"amplitude": 0.02, "frequency": [6, 6], "k": 1, "delta": 0.001}}},
 "objects": [
   {"type": "plane", "size": [1.6, 1.6], "material": "flat", "transform": {"translate": [-0.85, 0, 0]}},
   {"type": "plane", "size": [1.6, 1.6], "material": "bumpy", "transform": {"translate": [0.85, 0, 0]}}]}
JSON
render "$TMP/bump.json" --size 480x240 --out "$OUT/materials-bump.png"
