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
def differ(values, a, b, bound, what):
    gap = abs(values[a] - values[b]) / max(values[a], values[b])
    if not gap > bound:
        sys.exit(f"{a} and {b} give the same value ({values[a]} vs {values[b]}): {what}")
# FLIP means: most of each map's error is the same (the floor and objects no environment map
# reflects), so cube and equirect differ only in the fourth digit (measured 1.2e-4 relative at
# 240x180). llvmpipe and the CPU metrics are deterministic, so 1e-5 is far above rounding.
for a, b in (("env-cube", "env-sphere"), ("env-cube", "env-equirect"), ("env-sphere", "env-equirect")):
    differ(flip, a, b, 1e-5, "the sky does not show the parameterisation")
differ(flip, "sorted-blend", "unsorted-blend", 1e-3, "blending order does not matter")
# The reflection signal itself (relative RMSE over reflective pixels): 0.3% to 1.5% apart.
refl = {n: variants[n]["signals"]["reflection"]["relative_rmse"] for n in ("env-cube", "env-sphere", "env-equirect")}
print(refl)
for a, b in (("env-cube", "env-sphere"), ("env-cube", "env-equirect"), ("env-sphere", "env-equirect")):
    differ(refl, a, b, 1e-3, "the reflection signal does not show the parameterisation")
# The signals themselves: the transmission slot differs between the two orders.
t = {n: variants[n]["signals"]["transmission"]["relative_rmse"] for n in ("sorted-blend", "unsorted-blend")}
if not abs(t["sorted-blend"] - t["unsorted-blend"]) > 1e-3 * max(t.values()):
    sys.exit(f"transmission signal error equal for both orders: {t}")
]=] "${WORK_DIR}/cmp/results.json" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "techniques compare check failed:\n${out}${err}")
endif()
message(STATUS "${out}")
