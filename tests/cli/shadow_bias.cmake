# diptych shadow-bias end to end on a small study, then report.html in headless Chromium (as
# compare.cmake does): no console messages, every plot and class map loaded, every curve a row.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
expect_success(shadow-bias ARGS shadow-bias --modes none,constant,slope --resolutions 256
               --elevations 20,60 --points 4 --size 96x72 --out sb
               FILES sb/report.html sb/summary.json sb/summary.csv sb/plots/constant.svg
                     sb/plots/constant.png sb/plots/slope.svg sb/plots/time.svg
                     sb/constant/results.json sb/constant/results.csv)
foreach(expected "constant" "slope" "predicted" "wrote")
  string(FIND "${LAST_STDOUT}" "${expected}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "shadow-bias summary lacks '${expected}':\n${LAST_STDOUT}")
  endif()
endforeach()
# The study resumes: a second run renders nothing.
expect_success(shadow-bias-resume ARGS shadow-bias --modes none,constant,slope --resolutions 256
               --elevations 20,60 --points 4 --size 96x72 --out sb FILES sb/report.html)
string(FIND "${LAST_STDERR}" "exact reference" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "the resumed study rendered again:\n${LAST_STDERR}")
endif()
expect_failure(shadow-bias-unknown-mode EXPECT "--modes" "sharp" ARGS shadow-bias --modes sharp)

chromium_dump_dom(sb/report.html dom)
# 2 curves (one per elevation, one resolution) for each of none, constant and slope.
string(FIND "${dom}" "data-plots-loaded=\"true\"" loaded)
string(FIND "${dom}" "data-rows=\"6\"" rows)
if(loaded EQUAL -1 OR rows EQUAL -1)
  message(FATAL_ERROR "report.html: plots not loaded or best-table rows missing:\n${dom}")
endif()
