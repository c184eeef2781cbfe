# Shows that check_layers.cmake can fail: runs it on synthetic trees in WORK_DIR and expects
# a clean tree to pass, and a forbidden include, an include of an unlisted folder and a file
# in an unlisted folder each to fail with a message naming the file and the edge. One tree
# uses the real docs/architecture.md, so the real table must forbid engine/gl -> engine/graph.
#
#   cmake -DSOURCE_DIR=<repo> -DWORK_DIR=<scratch> -P check_layers_selftest.cmake
cmake_minimum_required(VERSION 3.25)
set(check "${CMAKE_CURRENT_LIST_DIR}/check_layers.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")

set(synthetic_table [=[
# test
<!-- layer-table:begin -->
| layer | what | may include |
|---|---|---|
| `engine/core` | base | - |
| `engine/gl` | gl | `engine/core` |
| `engine/graph` | graph | `engine/core`, `engine/gl` |
| `passes` | passes | `engine` |
<!-- layer-table:end -->
]=])

# run_case(NAME TABLE_TEXT|REAL EXPECT pass|fail [MESSAGE text] FILES path content ...)
function(run_case name table expect)
  cmake_parse_arguments(arg "" "MESSAGE" "FILES" ${ARGN})
  set(tree "${WORK_DIR}/${name}")
  file(MAKE_DIRECTORY "${tree}/docs")
  if(table STREQUAL "REAL")
    file(COPY "${SOURCE_DIR}/docs/architecture.md" DESTINATION "${tree}/docs")
  else()
    file(WRITE "${tree}/docs/architecture.md" "${table}")
  endif()
  list(LENGTH arg_FILES n)
  math(EXPR last "${n} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET arg_FILES ${i} path)
    list(GET arg_FILES ${j} content)
    file(WRITE "${tree}/${path}" "${content}\n")
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${tree} -P ${check}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect STREQUAL "pass" AND NOT rc EQUAL 0)
    message(FATAL_ERROR "${name}: expected the check to pass, it failed:\n${out}${err}")
  endif()
  if(expect STREQUAL "fail")
    if(rc EQUAL 0)
      message(FATAL_ERROR "${name}: expected the check to fail, it passed:\n${out}${err}")
    endif()
    string(FIND "${out}${err}" "${arg_MESSAGE}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${name}: the failure does not say '${arg_MESSAGE}':\n${out}${err}")
    endif()
  endif()
  message(STATUS "${name}: ${expect}ed as expected")
endfunction()

run_case(clean "${synthetic_table}" pass FILES
  engine/core/a.h "#pragma once"
  engine/gl/b.cpp "#include \"engine/core/a.h\"\n#include \"b_local.h\"\n#include <vector>"
  engine/graph/c.cpp "#include \"engine/gl/b.h\"\n#include \"engine/graph/c.h\""
  passes/p.cpp "#include \"engine/graph/c.h\"\n#include \"passes/q.h\"")
run_case(upward "${synthetic_table}" fail
  MESSAGE "engine/gl/b.cpp: includes \"engine/graph/c.h\": layer engine/gl may not include layer engine/graph"
  FILES
  engine/core/a.h "#pragma once"
  engine/gl/b.cpp "#include \"engine/core/a.h\"\n  #  include \"engine/graph/c.h\"")
run_case(engine_into_passes "${synthetic_table}" fail
  MESSAGE "engine/core/a.h: includes \"passes/p.h\": layer engine/core may not include layer passes (it may include: nothing"
  FILES engine/core/a.h "#include \"passes/p.h\"")
run_case(unlisted_target "${synthetic_table}" fail
  MESSAGE "includes \"engine/rt/x.h\", whose folder is in no row of the layer table"
  FILES engine/graph/c.cpp "#include \"engine/rt/x.h\"")
run_case(unlisted_file "${synthetic_table}" fail
  MESSAGE "engine/rt/x.cpp: its folder is in no row of the layer table"
  FILES engine/rt/x.cpp "#include \"engine/core/a.h\"")
run_case(real_table_forbids_gl_to_graph REAL fail
  MESSAGE "layer engine/gl may not include layer engine/graph"
  FILES engine/gl/forward.cpp "#include \"engine/graph/render_world.h\"")
run_case(real_table_forbids_gl_to_rt REAL fail
  MESSAGE "layer engine/gl may not include layer engine/rt"
  FILES engine/gl/shading.cpp "#include \"engine/rt/shading.h\"")
run_case(real_table_allows_gl_to_shading REAL pass
  FILES engine/gl/shading.cpp "#include \"engine/shading/shading.h\"")
