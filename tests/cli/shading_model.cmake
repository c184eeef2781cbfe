# --shading lecture|gltf (render, compare, sweep) through the real binary (docs/materials.md,
# "Two shading models"): both models render, give different pictures of the same scene, and a
# bad value is one clear error naming the option.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(whitted "${SOURCE_DIR}/samples/scenes/whitted.json")
set(fast --size 32x24 --frames 1 --warmup 0)

expect_success(lecture ARGS render ${whitted} ${fast} --shading lecture --out lecture.exr
               FILES lecture.exr)
expect_success(gltf ARGS render ${whitted} ${fast} --shading gltf --out gltf.exr FILES gltf.exr)
expect_success(own ARGS render ${whitted} ${fast} --out own.exr FILES own.exr)
# diff exits 1 when the MSE between the two is above 0.
function(differs a b result)
  execute_process(COMMAND ${DIPTYCH} diff ${a} ${b} --metrics mse --fail-above mse=0
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  set(${result} ${rc} PARENT_SCOPE)
endfunction()
differs(gltf.exr lecture.exr rc)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "[shading] --shading gltf rendered the same picture as lecture (${rc})")
endif()
differs(own.exr lecture.exr rc)
if(NOT rc EQUAL 0)  # whitted.json's materials are the lecture's own
  message(FATAL_ERROR "[shading] --shading lecture changed a lecture scene (${rc})")
endif()

expect_failure(bad-render EXPECT "--shading" "phong" ARGS render ${whitted} ${fast} --shading phong)
expect_failure(bad-compare EXPECT "--shading" "phong" ARGS compare ${whitted} --size 32x24
               --shading phong --out cmp)
expect_failure(bad-sweep EXPECT "--shading" "phong" ARGS sweep ${whitted} --slot
               visibility=shadow_map --vary resolution=128 --size 32x24 --shading phong --out sw)
