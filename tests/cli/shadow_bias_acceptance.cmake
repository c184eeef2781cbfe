# Issue 12's acceptance: shadow-sphere under a 40 degree sun, a 1024 map, constant bias. The acne
# fraction falls from above 40% to below 1% as the bias passes (w/2) tan(theta), the crossing
# within a factor of 2 of it, and peter-panning grows past it (tests/tools/check_bias_acceptance.py).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
expect_success(acceptance ARGS sweep "${SOURCE_DIR}/samples/scenes/shadow-sphere-sun.json"
               --slot visibility=shadow_map:bias=constant,resolution=1024
               --vary constant_bias=0.002:0.5:log12 --vary-light elevation=40 --size 320x240 --out acc
               FILES acc/results.json)
expect_check(acceptance check_bias_acceptance.py "${WORK_DIR}/acc/results.json")
