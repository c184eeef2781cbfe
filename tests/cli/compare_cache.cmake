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

# Timing rounds (--rounds): the reference and every variant timed R times in turn, each figure
# the median over rounds and each speed-up paired with the same round's reference. With a cached
# reference (the `edited` run's) the image is reused but the time is this run's, and the summary
# says so.
expect_success(rounds ARGS compare "${WORK_DIR}/scene.json" --variants hybrid-exact
               --size 64x48 --frames 1 --warmup 0 --rounds 2 --out cmp FILES cmp/results.json)
string(FIND "${LAST_STDOUT}" "(image cached; timed in this run)" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "--rounds with a cached reference must re-time it and say so:\n${LAST_STDOUT}")
endif()
execute_process(COMMAND /usr/bin/python3 -c [=[
import json, statistics, sys
r = json.load(open(sys.argv[1]))
ref = r["reference"]
assert r["rounds"] == 2 and len(ref["ms_rounds"]) == 2, r["reference"]
assert ref["cached"] and not ref["ms_cached"], ref
assert abs(ref["ms"] - statistics.median(ref["ms_rounds"])) < 1e-9, ref
assert isinstance(r["load_average_end"], list) and len(r["devices"]["cpu"]["load_average"]) == 3
for v in r["variants"]:
    t = v["total_ms_rounds"]
    assert len(t) == 2 and all(x > 0 for x in t), v["name"]
    assert abs(v["total_ms"] - statistics.median(t)) < 1e-9, v["name"]
    paired = statistics.median(a / b for a, b in zip(ref["ms_rounds"], t))
    assert abs(v["speedup_vs_reference"] - paired) < 1e-9, (v["name"], paired)
print("rounds ok")
]=] "${WORK_DIR}/cmp/results.json" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--rounds results.json check failed:\n${out}${err}")
endif()
expect_failure(rounds-zero EXPECT "--rounds" ARGS compare "${WORK_DIR}/scene.json" --rounds 0
               --out cmp)

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
