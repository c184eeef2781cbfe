# diptych compare end to end on a small scene, then report.html in headless Chromium.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(WRITE "${WORK_DIR}/variants.json" "{\"variants\": [
  {\"name\": \"reference-self\", \"recipe\": \"${SOURCE_DIR}/samples/graphs/whitted.json\"},
  {\"name\": \"hybrid-exact\"},
  {\"name\": \"sm-256\", \"slots\": [\"visibility=shadow_map:resolution=256,bias=slope\"]},
  {\"name\": \"sm-4096\", \"slots\": [\"visibility=shadow_map:resolution=4096,bias=slope\"]},
  {\"name\": \"geometry-16\", \"tessellation\": 16}]}")
expect_success(compare ARGS compare "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --variants variants.json
               --size 192x144 --frames 1 --warmup 1 --out cmp
               FILES cmp/results.json cmp/results.csv cmp/report.html cmp/plot.svg)
foreach(expected "reference-self" "sm-4096" "reference whitted" "vs exact")
  string(FIND "${LAST_STDOUT}" "${expected}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "compare summary lacks '${expected}':\n${LAST_STDOUT}")
  endif()
endforeach()
execute_process(COMMAND /usr/bin/python3 "${SOURCE_DIR}/tests/tools/check_compare.py" "${WORK_DIR}/cmp"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "results check failed:\n${out}${err}")
endif()
message(STATUS "${out}")

# A second run reuses the cached reference.
expect_success(compare-cached ARGS compare "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --variants hybrid-exact
               --size 192x144 --frames 1 --warmup 0 --out cmp FILES cmp/report.html)
string(FIND "${LAST_STDOUT}" "(cached)" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "the second run did not reuse the cached reference:\n${LAST_STDOUT}")
endif()
# Without warm-up, one frame: the method line says its times hold the first frame's first-use work.
string(FIND "${LAST_STDOUT}" "NO WARM-UP" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "compare --warmup 0 --frames 1 does not say its medians are unsteady:\n${LAST_STDOUT}")
endif()

# Bad compare input: one error line, non-zero exit.
expect_failure(compare-unknown-variant EXPECT "--variants" "nonsense" ARGS compare --variants nonsense)
expect_failure(compare-bad-reference EXPECT "--reference" ARGS compare --reference photon:3)

# The report in a real browser: no console messages, the plot loaded, every table row there,
# and a screenshot that is not blank. Debian chromium, installed by .ci/install-deps.
chromium_dump_dom(cmp/report.html dom)
string(FIND "${dom}" "data-plot-loaded=\"true\"" plot_loaded)
string(FIND "${dom}" "data-rows=\"1\"" one_row)
if(plot_loaded EQUAL -1 OR one_row EQUAL -1)
  message(FATAL_ERROR "report.html: plot not loaded or table rows missing:\n${dom}")
endif()
execute_process(COMMAND ${CHROMIUM} ${CHROMIUM_FLAGS} --window-size=1200,1600 --screenshot=${WORK_DIR}/report.png
                        "file://${WORK_DIR}/cmp/report.html"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
execute_process(COMMAND /usr/bin/python3 -c
  "import sys; from PIL import Image; im = Image.open(sys.argv[1]).convert('RGB'); n = len(set(im.getdata())); print(n); sys.exit(0 if n > 200 else 1)"
  "${WORK_DIR}/report.png" RESULT_VARIABLE rc OUTPUT_VARIABLE colours)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "report screenshot looks blank (${colours} colours)")
endif()

# A scene with SDF objects: the reference's sphere-tracing steps as a heat map and in
# results.json, and the report's section for them (passes/rt/sdf_steps.h).
expect_success(compare-sdf-steps ARGS compare "${SOURCE_DIR}/samples/scenes/sdf.json" --variants hybrid-exact
               --size 64x48 --frames 1 --warmup 0 --out cmp-sdf
               FILES cmp-sdf/heatmaps/reference-sdf-steps.png cmp-sdf/images/reference-sdf-steps.exr)
execute_process(COMMAND /usr/bin/python3 -c
  "import json, sys; s = json.load(open(sys.argv[1]))['sdf_steps']; print(s['rays'], s['mean_steps_per_ray'], s['max_steps_per_ray']); sys.exit(0 if s['rays'] > 0 and s['mean_steps_per_ray'] >= 1 and s['max_steps_per_ray'] >= s['mean_steps_per_ray'] and s['max_steps_per_ray'] <= 256 else 1)"
  "${WORK_DIR}/cmp-sdf/results.json" RESULT_VARIABLE rc OUTPUT_VARIABLE sdf_figures)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "results.json: sdf_steps missing or implausible: ${sdf_figures}")
endif()
file(READ "${WORK_DIR}/cmp-sdf/report.html" sdf_page)
string(FIND "${sdf_page}" "id=\"sdf-steps\"" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "report.html lacks the sphere-tracing steps section")
endif()

# A scene with moving objects: the stderr line and results.json say whether the reference
# integrates them over the shutter (distributed, path) or shows the frame's instant (whitted).
foreach(case "distributed:4;shutter" "whitted;instant")
  list(GET case 0 spec)
  list(GET case 1 expected)
  expect_success(compare-motion-${expected} ARGS compare "${SOURCE_DIR}/samples/scenes/motion.json"
                 --variants hybrid-exact --reference ${spec} --size 48x32 --frames 1 --warmup 0
                 --out cmp-motion-${expected} FILES cmp-motion-${expected}/results.json)
  file(READ "${WORK_DIR}/cmp-motion-${expected}/results.json" motion_results)
  string(JSON time GET "${motion_results}" reference time)
  if(NOT time STREQUAL expected)
    message(FATAL_ERROR "reference ${spec}: results.json reference.time is '${time}', not '${expected}'")
  endif()
  if(NOT LAST_STDERR MATCHES "2 moving instance")
    message(FATAL_ERROR "compare must say the scene has 2 moving instances: ${LAST_STDERR}")
  endif()
endforeach()

# The raster side's motion blur, the accumulation buffer (Variant::shutterSamples): 8 snapshots
# averaged come closer to the blurred reference than the frame's instant does, and say so.
expect_success(compare-accumulation ARGS compare "${SOURCE_DIR}/samples/scenes/motion.json"
               --variants raster,raster-accumulation-8 --reference distributed:16 --size 96x64
               --frames 1 --warmup 0 --out cmp-accumulation FILES cmp-accumulation/results.json
               cmp-accumulation/images/raster-accumulation-8.exr)
execute_process(COMMAND /usr/bin/python3 -c
  "import json, sys; v = {x['name']: x for x in json.load(open(sys.argv[1]))['variants']}; a, r = v['raster-accumulation-8'], v['raster']; print(a['metrics']['flip_mean'], r['metrics']['flip_mean']); sys.exit(0 if a['shutter_samples'] == 8 and r['shutter_samples'] == 0 and a['metrics']['flip_mean'] < 0.75 * r['metrics']['flip_mean'] and a['signals'] == {} else 1)"
  "${WORK_DIR}/cmp-accumulation/results.json" RESULT_VARIABLE rc OUTPUT_VARIABLE accumulation_flip)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "raster-accumulation-8 must have shutter_samples 8, no per-slot signals and "
          "a FLIP below 3/4 of raster's against the blurred reference: ${accumulation_flip}")
endif()
message(STATUS "FLIP against distributed:16, accumulation buffer / frame instant: ${accumulation_flip}")
