# Every sample scene renders through every recipe in samples/graphs, writing image, graph and
# timings; the timing table and culling lines are printed.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(GLOB scenes "${SOURCE_DIR}/samples/scenes/*.json")
file(GLOB recipes "${SOURCE_DIR}/samples/graphs/*.json")
foreach(scene IN LISTS scenes)
  get_filename_component(s "${scene}" NAME_WE)
  foreach(recipe IN LISTS recipes)
    get_filename_component(r "${recipe}" NAME_WE)
    expect_success(${s}-${r} ARGS render ${scene} --recipe ${recipe} --size 64x48 --frames 1 --warmup 0
                   --out ${s}-${r}.png --graph-out ${s}-${r}.json --timings ${s}-${r}-timings.json
                   FILES ${s}-${r}.png ${s}-${r}.json ${s}-${r}-timings.json)
    string(FIND "${LAST_STDOUT}" "median of 1 frames after 0 warm-up frames" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "[${s}-${r}] no timing table in stdout: ${LAST_STDOUT}")
    endif()
  endforeach()
endforeach()
expect_success(exr-and-dot ARGS render "${SOURCE_DIR}/samples/scenes/whitted.json" --size 32x24 --frames 1 --warmup 0
               --out whitted.exr --graph-out whitted.dot FILES whitted.exr whitted.dot)
file(READ "${WORK_DIR}/whitted.dot" dot)
string(FIND "${dot}" "digraph frame" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "whitted.dot is not a DOT graph")
endif()
