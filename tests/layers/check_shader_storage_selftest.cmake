# Self-test of check_shader_storage.cmake: it fails on a synthetic shader with an SSBO and
# passes on one whose comment only names one.
#
#   cmake -DWORK_DIR=<scratch folder> -P check_shader_storage_selftest.cmake
cmake_minimum_required(VERSION 3.25)
set(check "${CMAKE_CURRENT_LIST_DIR}/check_shader_storage.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(WRITE "${WORK_DIR}/bad/gl/scene.glsl"
     "layout(std430, binding = 4) readonly buffer SceneMaterials { vec4 m[]; };\n")
file(WRITE "${WORK_DIR}/good/gl/scene.glsl"
     "// was: readonly buffer SceneMaterials { vec4 m[]; };\n"
     "layout(binding = 21) uniform samplerBuffer uSceneMaterials;\n")
foreach(tree bad good)
  execute_process(COMMAND ${CMAKE_COMMAND} -DSHADER_DIR=${WORK_DIR}/${tree} -P ${check}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${tree}_result ${result})
  set(${tree}_err "${err}")
endforeach()
if(bad_result EQUAL 0 OR NOT bad_err MATCHES "bad/gl/scene.glsl:1:")
  message(FATAL_ERROR "the check passed a shader with an SSBO:\n${bad_err}")
endif()
if(NOT good_result EQUAL 0)
  message(FATAL_ERROR "the check failed a shader without an SSBO:\n${good_err}")
endif()
message(STATUS "check_shader_storage fails on an SSBO and passes without one")
