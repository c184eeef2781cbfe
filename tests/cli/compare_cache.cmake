# The reference cache key covers the bytes of every file the scene reads: editing an image the
# scene includes (here its equirect environment) must recompute the reference, and an unchanged
# scene must reuse it.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
# A 2x1 equirect environment (plain-text PPM, read through OpenImageIO).
function(write_environment r g b)
  file(WRITE "${WORK_DIR}/sky.ppm" "P3\n2 1\n255\n${r} ${g} ${b} ${r} ${g} ${b}\n")
endfunction()
write_environment(40 80 120)
file(WRITE "${WORK_DIR}/scene.json" "{
  \"camera\": {\"position\": [0, 1, 4], \"target\": [0, 0.5, 0], \"fov\": 45},
  \"environment\": {\"equirect\": \"sky.ppm\"},
  \"materials\": {\"mirror\": {\"color\": [1, 1, 1], \"kd\": 0.1, \"kps\": 0.8}},
  \"lights\": [{\"type\": \"point\", \"position\": [2, 4, 3], \"intensity\": 40}],
  \"objects\": [{\"type\": \"sphere\", \"radius\": 0.5, \"material\": \"mirror\",
                 \"transform\": {\"translate\": [0, 0.5, 0]}}]}")
set(run_args compare "${WORK_DIR}/scene.json" --variants hybrid-exact --size 64x48 --frames 1
             --warmup 0 --out cmp)
expect_success(first ARGS ${run_args} FILES cmp/results.json)
expect_success(unchanged ARGS ${run_args} FILES cmp/results.json)
string(FIND "${LAST_STDOUT}" "(cached)" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "an unchanged scene did not reuse the cached reference:\n${LAST_STDOUT}")
endif()
write_environment(200 90 30)
expect_success(edited ARGS ${run_args} FILES cmp/results.json)
string(FIND "${LAST_STDOUT}" "(cached)" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "an edited environment image reused the stale reference:\n${LAST_STDOUT}")
endif()

# A different build (here the same binary with one byte appended, which still runs) must not
# reuse the reference the `edited` run above cached: the key covers the program's own bytes.
file(COPY_FILE "${DIPTYCH}" "${WORK_DIR}/diptych-rebuilt")
file(APPEND "${WORK_DIR}/diptych-rebuilt" "x")
set(DIPTYCH "${WORK_DIR}/diptych-rebuilt")
expect_success(rebuilt ARGS ${run_args} FILES cmp/results.json)
string(FIND "${LAST_STDOUT}" "(cached)" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "a different program binary reused the stale reference:\n${LAST_STDOUT}")
endif()
file(REMOVE "${WORK_DIR}/diptych-rebuilt")  # 100+ MB
