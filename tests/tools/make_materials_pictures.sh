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
# Rough reflections (docs/materials-secondary.md), under a studio HDR (plus the default sun):
# the raster recipe without prefiltering (mirror faded by roughness), with it, and the path
# tracer (64 spp).
studio="--env $SCENES/hdri/studio_small_03_1k.hdr"
render "$spheres" $studio --size 256x256 --recipe samples/graphs/raster.json \
  --slot reflection=env_cube:prefilter=false --out "$TMP/raster-mirror.png"
render "$spheres" $studio --size 256x256 --recipe samples/graphs/raster.json --out "$TMP/raster-pre.png"
sed 's/"spp": 4/"spp": 64/' samples/graphs/path.json >"$TMP/path64.json"
render "$spheres" $studio --size 256x256 --recipe "$TMP/path64.json" --out "$TMP/path.png"
oiiotool "$TMP/raster-mirror.png" "$TMP/raster-pre.png" "$TMP/path.png" --mosaic 3x1 \
  -o "$OUT/materials-prefilter.png"
