#!/bin/bash
# Renders every sample scene with every recipe in samples/graphs, plus every producer that no
# recipe uses (and the shadow-map bias and filter modes) swapped into the default recipe with
# --slot, at 160x120 as linear EXR. With compare_exr.py, the check that a refactoring left every
# image bit-identical: render with the old and the new binary, then compare the two folders.
#   tests/tools/render_matrix.sh OLD_BUILD/diptych OLD_CHECKOUT before/
#   tests/tools/render_matrix.sh build/release/diptych . after/
#   tests/tools/compare_exr.py before/ after/
set -u
BIN=$1 SRC=$2 OUT=$3
mkdir -p "$OUT"
slots=("reflection=env_sphere" "reflection=env_equirect" "reflection=env_dynamic_cube"
  "reflection=planar_mirror" "reflection=env_cube" "transmission=unsorted_blend"
  "transmission=sorted_blend" "visibility=shadow_map:resolution=256,bias=none"
  "visibility=shadow_map:resolution=1024,bias=constant" "visibility=shadow_map:bias=normal_offset"
  "visibility=shadow_map:bias=receiver_plane,filter=pcf,kernel=3"
  "visibility=shadow_map:bias=adaptive,filter=poisson"
  "visibility=shadow_map:resolution=1024,filter=pcss")
run() {  # NAME ARGS...
  local name=$1
  shift
  "$BIN" render "$@" --size 160x120 --frames 1 --warmup 0 --out "$OUT/$name.exr" >/dev/null \
    2>"$OUT/$name.err" || echo "FAILED $name"
}
for scene in "$SRC"/samples/scenes/*.json; do
  s=$(basename "$scene" .json)
  for recipe in "$SRC"/samples/graphs/*.json; do
    run "$s.$(basename "$recipe" .json)" "$scene" --recipe "$recipe"
  done
  for i in "${!slots[@]}"; do run "$s.slot$i" "$scene" --slot "${slots[$i]}"; done
done
