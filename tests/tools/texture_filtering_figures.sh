#!/usr/bin/env bash
# The figures of docs/textures.md ("Measurements"): every texture_filtering producer, and ray
# cones against level 0 at reflected hits, on samples/scenes/textures.json at 640x480, each
# final image against a supersampled reference: the hybrid at 4x the size (2560x1920) with
# texture_supersample N = 2 (8 x 8 texture samples per final pixel) and level-0 reflections,
# box-averaged to 640x480 by oiiotool. FLIP (diptych diff, 67 ppd) and the per-pass medians of
# `diptych render` (3 frames after 1 warm-up frame).
# Usage: tests/tools/texture_filtering_figures.sh BUILD_DIR OUT_DIR
set -euo pipefail
build=$1 out=$2
scene=$(dirname "$0")/../../samples/scenes/textures.json
mkdir -p "$out"
d="$build/diptych"
if [ ! -f "$out/reference.exr" ]; then  # minutes on llvmpipe: kept between runs
  "$d" render "$scene" --size 2560x1920 --frames 1 --warmup 0 \
    --slot texture_filtering=texture_supersample:samples=2 --out "$out/reference4x.exr" > "$out/reference4x.log"
  oiiotool "$out/reference4x.exr" --resize:filter=box 640x480 -o "$out/reference.exr"
fi
run() {  # name, slot options...
  local name=$1; shift
  "$d" render "$scene" --size 640x480 --frames 3 --warmup 1 "$@" --out "$out/$name.exr" > "$out/$name.log"
  oiiotool "$out/$name.exr" -o "$out/$name.png"
  local flip
  flip=$("$d" diff "$out/$name.exr" "$out/reference.exr" --metrics flip --json | python3 -c 'import json,sys; print("%.4f" % json.load(sys.stdin)["metrics"]["flip_mean"])')
  local tf
  tf=$(awk '$1 == "texture_filtering" {print $4}' "$out/$name.log")
  local refl
  refl=$(awk '$1 == "reflection" {print $4}' "$out/$name.log")
  echo "$name flip=$flip texture_filtering_ms=${tf:--} reflection_ms=${refl:--}" | tee -a "$out/figures.txt"
}
: > "$out/figures.txt"
for p in texture_nearest texture_bilinear texture_distance texture_trilinear texture_anisotropic texture_sampler "texture_supersample:samples=4"; do
  run "${p%%:*}" --slot "texture_filtering=$p"
done
run trilinear-cone --slot texture_filtering=texture_trilinear --slot reflection=rt_reflection:texture_lod=cone
run anisotropic-cone --slot texture_filtering=texture_anisotropic --slot reflection=rt_reflection:texture_lod=cone
