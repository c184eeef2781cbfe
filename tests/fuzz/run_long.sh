#!/usr/bin/env bash
# run_long.sh [SECONDS] [TARGET...]: runs the fuzz harnesses long, one after the other, niced,
# from a configured and built `fuzz` preset (cmake --preset fuzz && cmake --build --preset fuzz).
# The corpus grows in build/fuzz/tests/fuzz/work/TARGET/corpus (kept between runs); crashes land
# in .../crashes/ and make the script exit non-zero. Each run's final stats (executions, exec/s)
# are printed; docs/robustness.md records them. FUZZ_RUNS=N stops each target after N executions
# (run.sh); FUZZ_PARALLEL=1 runs the targets at once instead of one after the other; FUZZ_NICE
# (default 10) is their niceness.
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$root/build/fuzz
seconds=${1:-3600}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene_json recipe gltf image)
shared=$root/../shared/scenes
declare -A seeds=(
  [scene_json]="$root/samples/scenes $root/tests/fuzz/regressions/scene_json"
  [recipe]="$root/samples/graphs $root/tests/fuzz/regressions/recipe"
  [gltf]="$shared/edge-cases-tinygltf $shared/edge-cases-assimp $shared/mesh-primitive-modes $shared/orientation-test $shared/cornell-box $root/tests/fuzz/regressions/gltf"
  [image]="$root/tests/fuzz/seeds/image $root/tests/fuzz/regressions/image"
)
status=0
run_one() {
  local t=$1 log=$build/tests/fuzz/work/$1.log
  mkdir -p "$(dirname "$log")"
  # shellcheck disable=SC2086
  nice -n "${FUZZ_NICE:-10}" "$root/tests/fuzz/run.sh" "$build/tests/fuzz/fuzz_$t" "$seconds" \
    "$build/tests/fuzz/work/$t" ${seeds[$t]} >"$log" 2>&1
}
report() {
  echo "== fuzz_$1"
  grep -E "^stat::|ERROR|SUMMARY|Done" "$build/tests/fuzz/work/$1.log"
}
if [ "${FUZZ_PARALLEL:-0}" = 1 ]; then
  declare -A pids=()
  for t in "${targets[@]}"; do
    echo "== fuzz_$t for ${seconds}s (in parallel)"
    run_one "$t" &
    pids[$t]=$!
  done
  for t in "${targets[@]}"; do
    wait "${pids[$t]}" || status=1
    report "$t"
  done
  exit $status
fi
for t in "${targets[@]}"; do
  echo "== fuzz_$t for ${seconds}s"
  run_one "$t" || status=1
  report "$t"
done
exit $status
