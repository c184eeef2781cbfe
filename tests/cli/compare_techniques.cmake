# The techniques sample gives each raster technique something to get wrong (issue 9, "Samples
# that make the comparison say something"): with its procedural sky the three environment-map
# parameterisations must give different errors against the Whitted reference, and with two
# overlapping tinted glass objects sorted and unsorted blending must too. (With a constant
# environment and one transparent object, as whitted has, each group measured the same FLIP.)
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
expect_success(compare-techniques ARGS compare "${SOURCE_DIR}/samples/scenes/techniques.json"
               --variants env-cube,env-sphere,env-equirect,sorted-blend,unsorted-blend
               --size 240x180 --frames 1 --warmup 0 --out cmp FILES cmp/results.json)
execute_process(COMMAND /usr/bin/python3 -c [=[
import json, sys
variants = {v["name"]: v for v in json.load(open(sys.argv[1]))["variants"]}
flip = {n: v["metrics"]["flip_mean"] for n, v in variants.items()}
print(flip)
def differ(a, b, what):
    # Relative gap: FLIP means of a few 1e-2 differ in the third or fourth digit here.
    gap = abs(flip[a] - flip[b]) / max(flip[a], flip[b])
    if not gap > 1e-4:
        sys.exit(f"{a} and {b} give the same FLIP ({flip[a]} vs {flip[b]}): {what}")
differ("env-cube", "env-sphere", "the sky does not show the parameterisation")
differ("env-cube", "env-equirect", "the sky does not show the parameterisation")
differ("env-sphere", "env-equirect", "the sky does not show the parameterisation")
differ("sorted-blend", "unsorted-blend", "blending order does not matter")
# The signals themselves: the transmission slot differs between the two orders.
t = {n: variants[n]["signals"]["transmission"]["relative_rmse"] for n in ("sorted-blend", "unsorted-blend")}
if not abs(t["sorted-blend"] - t["unsorted-blend"]) > 1e-3 * max(t.values()):
    sys.exit(f"transmission signal error equal for both orders: {t}")
]=] "${WORK_DIR}/cmp/results.json" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "techniques compare check failed:\n${out}${err}")
endif()
message(STATUS "${out}")
