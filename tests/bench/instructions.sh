#!/usr/bin/env bash
# Instructions executed per frame, for recipes on one scene: a measure of work that does not
# move with the machine's load (docs/benchmarks.md, "Instructions per frame"). On a shared
# 2-core VM the same frame's time moves by up to 2x with what the other core runs, so a
# difference of a few percent between two recipes cannot be told from timings; instruction
# counts are exact and repeatable (to a few 0.1% from thread scheduling).
#
# Method: valgrind --tool=callgrind on `diptych render` (all threads: Diptych's, TBB's and
# llvmpipe's JIT-compiled shader code), once with 1 measured frame and once with 3 (each after 2
# warm-up frames); half the difference of the two totals is one steady-state frame without the
# process start, the scene load, the BVH build, shader compilation or the warm-up. A negative or
# odd figure means one-time work (a shader variant llvmpipe compiles late) fell into one run's
# frames: run it again. Caveats:
# valgrind emulates no AVX-512, so Embree runs its AVX2 kernels (8-wide, not 16-wide), and an
# instruction is not a cycle (a division or a cache miss costs more than an add): compare
# recipes that do similar work, and read timings beside it (tests/bench/cpu_ms.py). Valgrind
# 3.19 does not emulate rdtscp, which libhwy (an OpenImageIO dependency) runs at load on AMD
# hosts: there the runs die with SIGILL, and this script says so instead of printing a figure.
# Usage (from the repository root; needs valgrind):
#   tests/bench/instructions.sh DIPTYCH SCENE SIZE RECIPE [RECIPE...]
set -euo pipefail
[ $# -ge 4 ] || { sed -n '2,16p' "$0"; exit 2; }
command -v valgrind >/dev/null || { echo "instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
diptych=$1 scene=$2 size=$3
shift 3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "scene $scene, $size; instructions per frame (callgrind, all threads)"
for recipe in "$@"; do
  name=$(basename "$recipe" .json)
  pids=()
  for frames in 1 3; do
    valgrind --tool=callgrind --callgrind-out-file="$out/$name-$frames.out" "$diptych" render \
      "$scene" --recipe "$recipe" --size "$size" --frames "$frames" --warmup 2 \
      --out "$out/$name-$frames.exr" >"$out/$name-$frames.log" 2>&1 &
    pids+=($!)
  done
  # A run that died (valgrind stops at instructions it cannot emulate: on AMD hosts, libhwy's
  # rdtscp in a static constructor, loaded with OpenImageIO) leaves a profile of the process
  # start only; its difference would be printed as a figure. Say so and stop instead.
  for i in 0 1; do
    if ! wait "${pids[$i]}"; then
      echo "instructions.sh: the callgrind run of $name failed; its log says:" >&2
      log="$out/$name-$((2 * i + 1)).log"
      grep -m1 -A1 'Unrecognised instruction' "$log" >&2 || tail -n 15 "$log" >&2
      exit 1
    fi
  done
  total() { grep -m1 '^totals:' "$1" | awk '{print $2}'; }
  one=$(total "$out/$name-1.out") three=$(total "$out/$name-3.out")
  awk -v n="$name" -v a="$one" -v b="$three" \
    'BEGIN { printf "%-12s %8.1f M instructions per frame\n", n, (b - a) / 2e6 }'
done
