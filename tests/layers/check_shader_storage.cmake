# Scene data reaches the shaders as buffer textures, never as SSBOs (docs/gl.md, "Scene data"):
# llvmpipe runs each SSBO load as a loop over its SIMD lanes with a bounds test per lane, which
# made the all-raster frame three times slower than its buffer-texture reads. Fails on any shader
# under SHADER_DIR that declares a shader storage block (`buffer` interface block).
#
#   cmake -DSHADER_DIR=<shaders folder> -P check_shader_storage.cmake
cmake_minimum_required(VERSION 3.25)
if(NOT SHADER_DIR)
  message(FATAL_ERROR "check_shader_storage: SHADER_DIR is not set")
endif()
file(GLOB_RECURSE files "${SHADER_DIR}/*.glsl" "${SHADER_DIR}/*.vert" "${SHADER_DIR}/*.frag"
     "${SHADER_DIR}/*.comp" "${SHADER_DIR}/*.geom")
if(NOT files)
  message(FATAL_ERROR "check_shader_storage: no shader under ${SHADER_DIR}")
endif()
set(problems)
foreach(file IN LISTS files)
  file(STRINGS "${file}" lines)
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    string(REGEX REPLACE "//.*" "" code "${line}")  # comments may name SSBOs
    if(code MATCHES "(^|[ \t)])buffer[ \t]+[A-Za-z_][A-Za-z_0-9]*[ \t]*({|$)")
      list(APPEND problems
           "${file}:${number}: a shader storage block (read scene data through a BufferTexture)")
    endif()
  endforeach()
endforeach()
list(LENGTH files count)
if(problems)
  list(JOIN problems "\n" text)
  message(FATAL_ERROR "${text}")
endif()
message(STATUS "check_shader_storage: ${count} shaders, no storage block")
