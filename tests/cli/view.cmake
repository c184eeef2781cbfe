# `diptych view` under a private Xvfb (tests/run_with_xvfb.sh): a scripted session renders,
# switches a producer, moves the camera, measures against the reference, writes screenshots,
# a recipe and a camera; `diptych render` with those must give the same frame. Resizing to tiny
# and huge sizes and quitting end cleanly; bad input is one error line before any window opens.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(XVFB ${SOURCE_DIR}/tests/run_with_xvfb.sh)
set(SCENE ${SOURCE_DIR}/samples/scenes/shadow-sphere.json)

function(run_view label)
  execute_process(COMMAND ${XVFB} ${DIPTYCH} view ${ARGN} WORKING_DIRECTORY "${WORK_DIR}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[${label}] exit ${rc}\nstdout: ${out}\nstderr: ${err}")
  endif()
  set(VIEW_OUT "${out}" PARENT_SCOPE)
endfunction()

# diff's JSON metric KEY of two images under WORK_DIR.
function(image_metric a b key out_var)
  execute_process(COMMAND ${DIPTYCH} diff ${a} ${b} --json --metrics rmse WORKING_DIRECTORY "${WORK_DIR}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "diff ${a} ${b}: ${err}")
  endif()
  string(JSON v GET "${out}" metrics ${key})
  set(${out_var} ${v} PARENT_SCOPE)
endfunction()

function(json_get file out_var)
  file(READ "${WORK_DIR}/${file}" text)
  string(JSON v GET "${text}" ${ARGN})
  set(${out_var} "${v}" PARENT_SCOPE)
endfunction()

file(WRITE "${WORK_DIR}/session.txt" "# exact hybrid, then a raster shadow map, then a moved camera
frames 1
time 2
screenshot hybrid
slot visibility=shadow_map:resolution=256,bias=none
screenshot raster
param visibility bias=constant
camera orbit 25 10
camera dolly 0.9
write-recipe saved
overlay flip
screenshot moved
motion on 4
camera orbit 5 0
screenshot moving
motion off
screenshot rested
split off
overlay none
resize 1 1
frames 2
resize 2400 1600
frames 1
screenshot huge
quit
")
run_view(session ${SCENE} --size 200x150 --script session.txt)
foreach(f hybrid raster moved huge)
  foreach(ext .png .window.png .json)
    if(NOT EXISTS "${WORK_DIR}/${f}${ext}")
      message(FATAL_ERROR "[session] did not write ${f}${ext}\n${VIEW_OUT}")
    endif()
  endforeach()
endforeach()

# Not blank: every frame differs from black.
execute_process(COMMAND oiiotool --pattern constant:color=0,0,0 200x150 3 -d uint8 -o black.png
                WORKING_DIRECTORY "${WORK_DIR}")
foreach(f hybrid raster moved)
  image_metric(${f}.png black.png rmse v)
  if(NOT v GREATER 0.05)
    message(FATAL_ERROR "[blank] ${f}.png is (nearly) black: rmse ${v} against black")
  endif()
endforeach()

# The state: the producer switched, its parameters, and the figures against the exact hybrid.
json_get(hybrid.json t slots visibility type)
json_get(raster.json t2 slots visibility type)
json_get(raster.json res slots visibility params resolution)
json_get(moved.json bias slots visibility params bias)
if(NOT t STREQUAL "rt_shadows" OR NOT t2 STREQUAL "shadow_map" OR NOT res EQUAL 256
   OR NOT bias STREQUAL "constant")
  message(FATAL_ERROR "[state] slots: ${t}, ${t2} (resolution ${res}), bias ${bias}")
endif()
json_get(hybrid.json shade_ms timings nodes shade cpu_ms)
json_get(hybrid.json shade_frames timings nodes shade frames)
if(NOT shade_ms GREATER 0 OR NOT shade_frames EQUAL 2)
  message(FATAL_ERROR "[timings] shade ${shade_ms} ms over ${shade_frames} frames")
endif()
json_get(hybrid.json r0 figures rmse)
if(NOT r0 EQUAL 0)  # the hybrid against the hybrid reference: the same frame
  message(FATAL_ERROR "[figures] hybrid against itself has rmse ${r0}")
endif()
json_get(raster.json r1 figures rmse)
json_get(raster.json acne figures visibility acne_rate)
if(NOT r1 GREATER 0 OR NOT acne GREATER 0.01)
  message(FATAL_ERROR "[figures] an unbiased 256 shadow map: rmse ${r1}, acne ${acne} (expected > 0, > 1%)")
endif()
image_metric(hybrid.png raster.png rmse d)
if(NOT d GREATER 0)
  message(FATAL_ERROR "[differ] switching the shadow producer changed nothing")
endif()
json_get(moved.json overlay view overlay)
if(NOT overlay STREQUAL "flip")
  message(FATAL_ERROR "[state] overlay ${overlay}")
endif()

# While the camera moves the frame renders at 1/4 size and no figures are computed; at rest,
# full size with figures again.
json_get(moving.json mvw size 0)
json_get(moving.json mvh size 1)
file(READ "${WORK_DIR}/moving.json" moving)
string(JSON mvf TYPE "${moving}" figures)
json_get(rested.json rw size 0)
json_get(rested.json rf figures rmse)
if(NOT mvw EQUAL 50 OR NOT mvh EQUAL 37 OR NOT mvf STREQUAL "NULL" OR NOT rw EQUAL 200
   OR NOT rf GREATER 0)
  message(FATAL_ERROR "[motion] moving ${mvw}x${mvh} figures ${mvf}; rested ${rw} rmse ${rf}")
endif()

# Huge: the window is large, the frame is capped at 2 Mpx (docs/viewer.md).
json_get(huge.json w size 0)
json_get(huge.json h size 1)
math(EXPR pixels "${w} * ${h}")
if(pixels GREATER 2097152 OR w LESS 200)
  message(FATAL_ERROR "[huge] frame ${w}x${h}")
endif()

# The same frame through `diptych render` with the saved recipe and camera (same GL driver,
# a GLFW context like the viewer's): identical.
json_get(moved.json mw size 0)
json_get(moved.json mh size 1)
execute_process(COMMAND ${XVFB} ${DIPTYCH} render ${SCENE} --recipe saved.recipe.json
                        --camera saved.camera.json --size ${mw}x${mh} --frames 1 --warmup 0
                        --context glfw --out rendered.png
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "[parity] render failed: ${err}")
endif()
image_metric(moved.png rendered.png rmse p)
if(NOT p EQUAL 0)
  message(FATAL_ERROR "[parity] viewer and render differ: rmse ${p}")
endif()

# The camera moved as asked: dolly 0.9 from (0,5,7) to the origin, orbiting kept the distance.
json_get(saved.camera.json fd camera focus_distance)
json_get(saved.camera.json tx camera target 0)
if(NOT fd GREATER 7.7420 OR NOT fd LESS 7.7422 OR NOT tx EQUAL 0)  # 0.9 * sqrt(74) = 7.74209
  message(FATAL_ERROR "[camera] distance ${fd}, target x ${tx}")
endif()

# The variants entry runs in compare (small and one frame: this checks that it is usable).
execute_process(COMMAND ${DIPTYCH} compare ${SCENE} --variants saved.variants.json --size 64x48
                        --frames 1 --warmup 0 --out compare
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET
                TIMEOUT 600)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "[variants] compare failed: ${err}")
endif()
json_get(compare/results.json name variants 0 name)
if(NOT name STREQUAL "saved")
  message(FATAL_ERROR "[variants] compare ran '${name}'")
endif()

# A camera file loaded at start, the Whitted reference, a screenshot and quit.
file(WRITE "${WORK_DIR}/whitted.txt" "screenshot whitted\nquit\n")
run_view(whitted ${SCENE} --size 64x48 --camera saved.camera.json --reference whitted
         --script whitted.txt)
json_get(whitted.json ref reference)
json_get(whitted.json wrmse figures rmse)
json_get(whitted.json wfd camera focus_distance)
if(NOT VIEW_OUT MATCHES "quit" OR NOT ref STREQUAL "whitted" OR NOT wrmse GREATER_EQUAL 0
   OR NOT wfd STREQUAL fd)
  message(FATAL_ERROR "[whitted] ${ref} rmse ${wrmse}, camera ${wfd} (saved ${fd})\n${VIEW_OUT}")
endif()
file(WRITE "${WORK_DIR}/quit.txt" "quit\n")

# --shading as in render: the viewer's frame under --shading gltf equals render's with the same
# option, recipe and camera, and differs from the frame without it (so the option took effect).
file(WRITE "${WORK_DIR}/gltf.txt" "frames 1\nscreenshot gltf\nwrite-recipe gltf\nquit\n")
run_view(shading ${SCENE} --size 64x48 --shading gltf --script gltf.txt)
json_get(gltf.json gw size 0)
json_get(gltf.json gh size 1)
foreach(model gltf none)
  set(extra)
  if(model STREQUAL "gltf")
    set(extra --shading gltf)
  endif()
  execute_process(COMMAND ${XVFB} ${DIPTYCH} render ${SCENE} --recipe gltf.recipe.json
                          --camera gltf.camera.json --size ${gw}x${gh} --frames 1 --warmup 0
                          --context glfw --out shading-${model}.png ${extra}
                  WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[shading] render ${model} failed: ${err}")
  endif()
endforeach()
image_metric(gltf.png shading-gltf.png rmse same)
image_metric(gltf.png shading-none.png rmse other)
if(NOT same EQUAL 0 OR NOT other GREATER 0)
  message(FATAL_ERROR "[shading] view --shading gltf vs render --shading gltf: rmse ${same} (expected 0); vs render without: ${other} (expected > 0)")
endif()
expect_failure(bad_shading EXPECT "--shading" "expected lecture or gltf" ARGS view ${SCENE} --shading phong)

# A script command that fails once the window is open (a value its schema rejects): one error
# line naming the script line, non-zero exit, the window closed.
file(WRITE "${WORK_DIR}/bad_param.txt" "slot visibility=shadow_map\nparam visibility bias=bogus\nquit\n")
execute_process(COMMAND ${XVFB} ${DIPTYCH} view ${SCENE} --size 64x48 --script bad_param.txt
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET
                TIMEOUT 300)
string(REGEX MATCHALL "diptych: error:" errors "${err}")
list(LENGTH errors count)
if(rc EQUAL 0 OR NOT count EQUAL 1 OR NOT err MATCHES "bad_param.txt: line 2: .*bogus")
  message(FATAL_ERROR "[bad_param] exit ${rc}, stderr: ${err}")
endif()

# On a textured scene the hybrid reference takes each pixel's texture colour over its footprint
# (as compare does): anisotropic filtering measures closer to it than bilinear; against the pixel
# centre's lookup bilinear, that lookup itself, would measure 0 (docs/viewer.md).
file(WRITE "${WORK_DIR}/textures.txt" "frames 1
slot texture_filtering=texture_bilinear
screenshot bilinear
slot texture_filtering=texture_anisotropic
screenshot anisotropic
quit
")
run_view(textures ${SOURCE_DIR}/samples/scenes/textures.json --size 160x120 --script textures.txt)
expect_python("textures against the footprint" [=[
import json, sys
rb, ra = (json.load(open(f))["figures"]["rmse"] for f in sys.argv[1:3])
print("rmse bilinear", rb, "anisotropic", ra)
if not (rb > 0.03 and ra < 0.6 * rb):  # measured 0.084 and 0.026 at 160x120
    sys.exit(f"rmse bilinear {rb}, anisotropic {ra} against the footprint")
]=] "${WORK_DIR}/bilinear.json" "${WORK_DIR}/anisotropic.json")

# Bad input: one error line, before any window (no display needed).
file(WRITE "${WORK_DIR}/bad.txt" "frames 1\nzoom 3\n")
expect_failure(bad_script EXPECT "bad.txt: line 2: unknown command 'zoom'"
               ARGS view ${SCENE} --script bad.txt)
file(WRITE "${WORK_DIR}/bad_slot.txt" "slot visibility=nope\n")
expect_failure(bad_slot EXPECT "bad_slot.txt: line 1" "unknown pass type 'nope'"
               ARGS view ${SCENE} --script bad_slot.txt)
expect_failure(missing_scene EXPECT "no-such-scene.json" ARGS view no-such-scene.json)
file(WRITE "${WORK_DIR}/broken.json" "{\"objects\": [")
expect_failure(broken_scene EXPECT "broken.json" ARGS view broken.json)
file(WRITE "${WORK_DIR}/nocam.json" "{\"objects\": []}")
expect_failure(camera_missing EXPECT "nocam.json: camera: missing" ARGS view ${SCENE} --camera nocam.json)
expect_failure(camera_not_json EXPECT "quit.txt" "malformed JSON" ARGS view ${SCENE} --camera quit.txt)
# No X display: GLFW's reason, one error line, non-zero exit.
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY
                        ${DIPTYCH} view ${SCENE} --script quit.txt
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET TIMEOUT 120)
if(rc EQUAL 0 OR NOT err MATCHES "^diptych: error: cannot initialize GLFW[^\n]*DISPLAY is not set[^\n]*\n$")
  message(FATAL_ERROR "[no_display] exit ${rc}, stderr: ${err}")
endif()
