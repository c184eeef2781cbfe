# diptych sweep: the cartesian product, one exact reference per scene state, results.json/csv,
# resume after an interruption, and bad specifications rejected before any rendering.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(scene "${SOURCE_DIR}/samples/scenes/shadow-sphere-sun.json")
set(args sweep "${scene}" --slot visibility=shadow_map:bias=constant --vary resolution=128,256
         --vary constant_bias=0.01:0.1:log3 --vary-light elevation=30,60 --size 96x72 --out sw)
expect_success(sweep ARGS ${args} FILES sw/results.json sw/results.csv sw/classes/p0011.png)
# Light axes outermost: 12 points, two scene states, so two exact references.
string(REGEX MATCHALL "exact reference" refs "${LAST_STDERR}")
list(LENGTH refs count)
if(NOT count EQUAL 2)
  message(FATAL_ERROR "expected 2 exact references (one per elevation), got ${count}:\n${LAST_STDERR}")
endif()
string(FIND "${LAST_STDERR}" "sweep: 12/12" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "no progress line 12/12:\n${LAST_STDERR}")
endif()
execute_process(COMMAND /usr/bin/python3 -c "
import csv, json, sys
r = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
assert len(r['points']) == 12 and len(rows) == 12, (len(r['points']), len(rows))
for k in ('elevation', 'resolution', 'constant_bias', 'acne_rate', 'peter_panning_rate', 'mean_abs_error', 'producer_ms'):
    assert k in rows[0], k
assert [p['index'] for p in r['points']] == list(range(12))
# Interrupt: keep the first 7 points, as a killed run leaves them.
r['points'] = r['points'][:7]
json.dump(r, open(sys.argv[1], 'w'))
" "${WORK_DIR}/sw/results.json" "${WORK_DIR}/sw/results.csv" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "results check failed: ${err}")
endif()
expect_success(sweep-resume ARGS ${args} FILES sw/results.json)
string(FIND "${LAST_STDERR}" "12 points, 7 resumed" pos)
string(REGEX MATCHALL "exact reference" refs "${LAST_STDERR}")
list(LENGTH refs count)
# Points 0..5 are elevation 30 (done), 6 is the first of 60: only 60's reference is rendered.
if(pos EQUAL -1 OR NOT count EQUAL 1)
  message(FATAL_ERROR "resume did not reuse the 7 written points:\n${LAST_STDERR}")
endif()
execute_process(COMMAND /usr/bin/python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
assert [p['index'] for p in r['points']] == list(range(12)), [p['index'] for p in r['points']]
" "${WORK_DIR}/sw/results.json" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "resumed results wrong: ${err}")
endif()
# Another sweep into the same folder is refused, not mixed in.
expect_failure(sweep-other-spec EXPECT "results.json" "different sweep"
               ARGS sweep "${scene}" --slot visibility=shadow_map --vary resolution=64 --out sw)

# Bad specifications: one named error, and nothing rendered or written.
function(expect_rejected label)
  cmake_parse_arguments(ARG "" "" "EXPECT;ARGS" ${ARGN})
  file(REMOVE_RECURSE "${WORK_DIR}/bad")
  expect_failure(${label} EXPECT ${ARG_EXPECT} ARGS ${ARG_ARGS} --out bad)
  if(EXISTS "${WORK_DIR}/bad")
    message(FATAL_ERROR "[${label}] wrote into the output folder before failing")
  endif()
endfunction()
expect_rejected(sweep-unknown-key EXPECT "--vary" "nonsense"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary nonsense=1,2)
expect_rejected(sweep-empty-range EXPECT "--vary" "empty range"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary constant_bias=1:0:0.1)
expect_rejected(sweep-bad-value EXPECT "--vary" "kernel"
                ARGS sweep "${scene}" --slot visibility=shadow_map:filter=pcf --vary kernel=3,4)
expect_rejected(sweep-not-a-parameter EXPECT "--vary" "resolution"
                ARGS sweep "${scene}" --slot visibility=rt_shadows --vary resolution=256,512)
expect_rejected(sweep-light-key EXPECT "--vary-light" "height"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary-light height=1,2)
expect_rejected(sweep-point-light EXPECT "--vary-light" "not directional"
                ARGS sweep "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --slot visibility=shadow_map
                     --vary-light elevation=10,20)
expect_rejected(sweep-nothing EXPECT "--vary" "nothing to sweep"
                ARGS sweep "${scene}" --slot visibility=shadow_map)
# Bounded work: the product of the axes, and the classification's pixel bands.
expect_rejected(sweep-too-many-points EXPECT "--vary" "points (limit 10000)"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary constant_bias=0.001:1:log200
                     --vary resolution=64:8000:1)
expect_rejected(sweep-huge-band EXPECT "--band" "width + height"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary resolution=64 --band 2147483647)
expect_rejected(sweep-negative-reach EXPECT "--reach"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary resolution=64 --reach -1)
