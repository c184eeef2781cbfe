#!/usr/bin/env bash
# run_long.sh [SECONDS] [TARGET...]: runs the fuzz harnesses long, one after the other, niced,
# from a configured and built `fuzz` preset (cmake --preset fuzz && cmake --build --preset fuzz).
# The corpus grows in build/fuzz/tests/fuzz/work/TARGET/corpus (kept between runs); crashes land
# in .../crashes/ and make the script exit non-zero. Each run's final stats (executions, exec/s)
# are printed; docs/robustness.md records them.
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
for t in "${targets[@]}"; do
  echo "== fuzz_$t for ${seconds}s"
  log=$build/tests/fuzz/work/$t.log
  mkdir -p "$(dirname "$log")"
  # shellcheck disable=SC2086
  nice -n 10 "$root/tests/fuzz/run.sh" "$build/tests/fuzz/fuzz_$t" "$seconds" \
    "$build/tests/fuzz/work/$t" ${seeds[$t]} >"$log" 2>&1
  rc=$?
  grep -E "^stat::|ERROR|SUMMARY|Done" "$log"
  [ $rc -eq 0 ] || status=1
done
exit $status
