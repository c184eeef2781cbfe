# `diptych check`: the numerics suite on a sample, its report files, its exit status, bad input.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(scene "${SOURCE_DIR}/samples/scenes/shadow-sphere.json")
set(small --size 48x36 --recipes whitted,raster --scales 1e-6,1e6 --offsets 1e5)

expect_success(passes ARGS check ${scene} ${small} --out ok FILES ok/check.json ok/check.md)
file(READ "${WORK_DIR}/ok/check.json" json)
string(JSON pass GET "${json}" pass)
string(JSON cases LENGTH "${json}" cases)
# as given, grazing, 2 scales, 1 offset, grazing at both scales and at the offset
if(NOT pass OR NOT cases EQUAL 8)
  message(FATAL_ERROR "expected a passing check with 8 cases, got pass=${pass} cases=${cases}")
endif()
string(JSON rebased GET "${json}" cases 4 rebased)
string(JSON nan GET "${json}" cases 2 recipes whitted nan)
if(NOT rebased OR NOT nan EQUAL 0)
  message(FATAL_ERROR "offset case not rebased (${rebased}) or NaN count ${nan}")
endif()

# A bound no transformed render can meet: exit status 3, report still written.
execute_process(COMMAND ${DIPTYCH} check ${scene} ${small} --fail-above 0 --out strict
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 300)
if(NOT rc EQUAL 3 OR NOT EXISTS "${WORK_DIR}/strict/check.md")
  message(FATAL_ERROR "--fail-above 0: expected exit 3 and a report, got ${rc}\n${err}")
endif()

expect_failure(bad_scale EXPECT "--scales" "got '0'" ARGS check ${scene} --scales 1,0)
expect_failure(bad_offset EXPECT "--offsets" ARGS check ${scene} --offsets 1e5,x)
expect_failure(bad_recipe EXPECT "nosuch" ARGS check ${scene} --recipes nosuch)
expect_failure(bad_size EXPECT "--size" ARGS check ${scene} --size 0x5)
expect_failure(missing_scene EXPECT "nope.json" ARGS check nope.json)
