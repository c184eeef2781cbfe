# Issue 12's predictions for point and spot lights (docs/shadow-bias.md §4): the per-pixel texel
# model from the map's own projection, drawn beside the measured acne curve, against the sweep
# (tests/tools/check_bias_lights.py); the spot report opened in headless Chromium.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(study shadow-bias --modes constant --resolutions 256,1024 --points 10 --receiver ground
          --size 160x120)
expect_success(spot ARGS ${study} "${SOURCE_DIR}/samples/scenes/shadow-sphere-spot.json"
               --out spot FILES spot/summary.json spot/plots/constant.svg spot/report.html)
expect_success(point ARGS ${study} "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --out point
               FILES point/summary.json)
foreach(case spot point)
  expect_check(${case} check_bias_lights.py ${case} "${WORK_DIR}/${case}/summary.json")
endforeach()
# The predicted acne rate is drawn: matplotlib names each legend entry in an SVG comment.
file(READ "${WORK_DIR}/spot/plots/constant.svg" svg)
string(FIND "${svg}" "1024 map predicted" drawn)
if(drawn EQUAL -1)
  message(FATAL_ERROR "spot/plots/constant.svg lacks the predicted acne curve")
endif()
chromium_dump_dom(spot/report.html dom)
string(FIND "${dom}" "data-plots-loaded=\"true\"" loaded)
string(FIND "${dom}" "data-rows=\"2\"" rows)
if(loaded EQUAL -1 OR rows EQUAL -1)
  message(FATAL_ERROR "spot/report.html: plots not loaded or rows missing:\n${dom}")
endif()
