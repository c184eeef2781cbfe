# Shows that check_unity_tests.cmake can fail: a test file with an anonymous namespace, one with
# a using-directive before its DIPTYCH_UNITY_ID namespace and one without that namespace each
# fail with the file's name; a file written as the convention says passes.
#
#   cmake -DWORK_DIR=<scratch> -P check_unity_tests_selftest.cmake
cmake_minimum_required(VERSION 3.25)
set(check "${CMAKE_CURRENT_LIST_DIR}/check_unity_tests.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")

# run_case(NAME CONTENT EXPECT pass|fail [MESSAGE text])
function(run_case name content expect)
  cmake_parse_arguments(arg "" "MESSAGE" "" ${ARGN})
  set(tree "${WORK_DIR}/${name}")
  file(WRITE "${tree}/tests/unit/test_${name}.cpp" "${content}")
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${tree} -DDIRS=tests/unit -P ${check}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect STREQUAL "pass" AND NOT rc EQUAL 0)
    message(FATAL_ERROR "[${name}] expected the check to pass:\n${out}${err}")
  elseif(expect STREQUAL "fail")
    if(rc EQUAL 0)
      message(FATAL_ERROR "[${name}] expected the check to fail:\n${out}${err}")
    endif()
    # CMake wraps the message's lines: compare with the whitespace folded.
    string(REGEX REPLACE "[ \n]+" " " flat "${err}")
    string(FIND "${flat}" "test_${name}.cpp" at_file)
    string(FIND "${flat}" "${arg_MESSAGE}" at_message)
    if(at_file EQUAL -1 OR at_message EQUAL -1)
      message(FATAL_ERROR "[${name}] the error must name test_${name}.cpp and say "
              "'${arg_MESSAGE}':\n${err}")
    endif()
  endif()
endfunction()

run_case(kept [=[
#include <gtest/gtest.h>
namespace diptych {
namespace DIPTYCH_UNITY_ID {
using namespace shading;
constexpr int kW = 4;
TEST(Kept, Width) { EXPECT_EQ(kW, 4); }
}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
]=] pass)
run_case(anonymous [=[
namespace diptych {
namespace {
constexpr int kW = 4;
}  // namespace
}  // namespace diptych
]=] fail MESSAGE "anonymous namespace")
run_case(leaking [=[
using namespace diptych;
namespace DIPTYCH_UNITY_ID {
}  // namespace DIPTYCH_UNITY_ID
]=] fail MESSAGE "using-directive before")
run_case(missing [=[
static int helper() { return 1; }
]=] fail MESSAGE "no namespace DIPTYCH_UNITY_ID")
message(STATUS "check_unity_tests_selftest: 4 cases as expected")
