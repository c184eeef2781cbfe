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
expect_python("sweep results" [=[
import csv, json, sys
r = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
assert len(r['points']) == 12 and len(rows) == 12, (len(r['points']), len(rows))
for k in ('elevation', 'resolution', 'constant_bias', 'acne_rate', 'peter_panning_rate', 'mean_abs_error', 'producer_ms'):
    assert k in rows[0], k
assert [p['index'] for p in r['points']] == list(range(12))
# Static shadow maps: built once per (scene state, resolution), a one-time cost of the first
# point that needs them (constant bias does not change the maps), never in its frame medians.
seen = set()
for p in r['points']:
    key = (p['params']['elevation'], p['params']['resolution'])
    built = p['one_time_ms'].get('shadow_map build', 0) > 0
    assert built == (key not in seen), (p['index'], key, p['one_time_ms'])
    seen.add(key)
assert 'one_time_ms' in rows[0]
# Interrupt: keep the first 7 points, as a killed run leaves them.
r['points'] = r['points'][:7]
json.dump(r, open(sys.argv[1], 'w'))
]=] "${WORK_DIR}/sw/results.json" "${WORK_DIR}/sw/results.csv")
expect_success(sweep-resume ARGS ${args} FILES sw/results.json)
string(FIND "${LAST_STDERR}" "12 points, 7 resumed" pos)
string(REGEX MATCHALL "exact reference" refs "${LAST_STDERR}")
list(LENGTH refs count)
# Points 0..5 are elevation 30 (done), 6 is the first of 60: only 60's reference is rendered.
if(pos EQUAL -1 OR NOT count EQUAL 1)
  message(FATAL_ERROR "resume did not reuse the 7 written points:\n${LAST_STDERR}")
endif()
expect_python("resumed sweep results" [=[
import json, sys
r = json.load(open(sys.argv[1]))
assert [p['index'] for p in r['points']] == list(range(12)), [p['index'] for p in r['points']]
]=] "${WORK_DIR}/sw/results.json")
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
expect_rejected(sweep-view-key EXPECT "--vary-view" "unknown view key 'fov'"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary-view fov=30,60)
expect_rejected(sweep-view-size EXPECT "--vary-view" "WIDTHxHEIGHT"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary-view size=0x10)
expect_rejected(sweep-view-distance EXPECT "--vary-view" "camera_distance is a factor > 0"
                ARGS sweep "${scene}" --slot visibility=shadow_map --vary-view camera_distance=0,1)

# View axes: frame size and camera are scene states too (one exact reference each), and each
# point is rendered at its own size from its own camera.
expect_success(sweep-view
               ARGS sweep "${scene}" --slot visibility=shadow_map:bias=constant --vary resolution=256
                    --vary-view size=64x48,96x72 --vary-view camera_azimuth=0,40 --out view
               FILES view/results.json view/results.csv view/classes/p0003.png)
string(REGEX MATCHALL "exact reference" refs "${LAST_STDERR}")
list(LENGTH refs count)
if(NOT count EQUAL 4)
  message(FATAL_ERROR "expected 4 exact references (2 sizes x 2 cameras), got ${count}:\n${LAST_STDERR}")
endif()
expect_python("view sweep results" [=[
import csv, json, struct, sys
r = json.load(open(sys.argv[1] + '/results.json'))
rows = list(csv.DictReader(open(sys.argv[1] + '/results.csv')))
assert [row['size'] for row in rows] == ['64x48', '64x48', '96x72', '96x72'], rows
assert [row['camera_azimuth'] for row in rows] == ['0', '40', '0', '40'], rows
def png_size(path):
    with open(path, 'rb') as f:
        head = f.read(24)
    return struct.unpack('>II', head[16:24])
sizes = [png_size(sys.argv[1] + '/' + p['files']['classes']) for p in r['points']]
assert sizes == [(64, 48), (64, 48), (96, 72), (96, 72)], sizes
# The orbit shows the receivers from elsewhere: the measured pixel sets differ.
def seen(p):
    s = p['signal']
    return (s['lit_outside'], s['shadow_outside'], s['misclassified'])
assert seen(r['points'][2]) != seen(r['points'][3]), (seen(r['points'][2]), seen(r['points'][3]))
]=] "${WORK_DIR}/view")

# The output folder is locked while a sweep writes into it: a second run (here flock(1) holds
# the lock, as a running sweep would) stops with one error instead of interleaving rows.
file(MAKE_DIRECTORY "${WORK_DIR}/locked")
execute_process(COMMAND flock "${WORK_DIR}/locked/.diptych.lock" ${DIPTYCH} sweep "${scene}"
                        --slot visibility=shadow_map --vary resolution=64 --size 32x24 --out locked
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 120)
string(FIND "${err}" "another diptych run is writing to this folder" pos)
if(rc EQUAL 0 OR pos EQUAL -1 OR EXISTS "${WORK_DIR}/locked/results.json")
  message(FATAL_ERROR "a locked output folder was not refused (exit ${rc}):\n${err}")
endif()
# An analytic sphere (the hybrid G-buffer's impostor texels name no triangle) and no --receiver:
# every covered pixel, the sphere's included, gets its exact point (samples/diptych/sweep/geometry.cpp).
expect_success(sweep_analytic ARGS sweep "${SOURCE_DIR}/samples/scenes/shadow-sphere.json"
               --slot visibility=shadow_map:bias=constant --vary constant_bias=0.01 --size 96x72
               --out swa FILES swa/results.json)
