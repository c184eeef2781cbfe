# Every sample scene renders through every recipe in samples/graphs, writing image, graph and
# timings; the timing table and culling lines are printed.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(GLOB scenes "${SOURCE_DIR}/samples/scenes/*.json")
file(GLOB recipes "${SOURCE_DIR}/samples/graphs/*.json")
foreach(scene IN LISTS scenes)
  get_filename_component(s "${scene}" NAME_WE)
  foreach(recipe IN LISTS recipes)
    get_filename_component(r "${recipe}" NAME_WE)
    expect_success(${s}-${r} ARGS render ${scene} --recipe ${recipe} --size 64x48 --frames 1 --warmup 0
                   --out ${s}-${r}.png --graph-out ${s}-${r}.json --timings ${s}-${r}-timings.json
                   FILES ${s}-${r}.png ${s}-${r}.json ${s}-${r}-timings.json)
    string(FIND "${LAST_STDOUT}" "median of 1 frames after 0 warm-up frames" pos)
    if(pos EQUAL -1)
      message(FATAL_ERROR "[${s}-${r}] no timing table in stdout: ${LAST_STDOUT}")
    endif()
  endforeach()
endforeach()
expect_success(exr-and-dot ARGS render "${SOURCE_DIR}/samples/scenes/whitted.json" --size 32x24 --frames 1 --warmup 0
               --out whitted.exr --graph-out whitted.dot FILES whitted.exr whitted.dot)
file(READ "${WORK_DIR}/whitted.dot" dot)
string(FIND "${dot}" "digraph frame" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "whitted.dot is not a DOT graph")
endif()

# EGL (headless; Mesa's surfaceless platform here, the GPU's device platform where one exists)
# renders the same image as OSMesa: both run the same passes on the same kind of driver here.
expect_success(render-egl ARGS render "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --context egl
               --size 96x72 --frames 1 --warmup 0 --out egl.exr FILES egl.exr)
expect_success(render-osmesa ARGS render "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --context osmesa
               --size 96x72 --frames 1 --warmup 0 --out osmesa.exr --timings t.json FILES osmesa.exr t.json)
set(osmesa_stdout "${LAST_STDOUT}")
expect_success(egl-vs-osmesa ARGS diff egl.exr osmesa.exr --fail-above rmse=1e-6)
file(READ "${WORK_DIR}/t.json" timings)
string(JSON renderer GET "${timings}" devices gl renderer)
string(JSON embree GET "${timings}" devices embree version)
if(renderer STREQUAL "" OR embree STREQUAL "")
  message(FATAL_ERROR "--timings must name the GL renderer and the Embree version")
endif()
# Timings are summaries over the measured frames (one here), the frame's wall time included;
# process_cpu_ms is one of them, not a last-frame counter; a GL node carries its GL wait apart.
string(JSON frames GET "${timings}" frame_ms samples)
string(JSON first GET "${timings}" schedule 0 name)
string(JSON process GET "${timings}" schedule 0 timing process_cpu_ms samples)
string(JSON wait GET "${timings}" schedule 0 timing gl_wait_ms samples)
if(NOT frames EQUAL 1 OR NOT process EQUAL 1 OR NOT wait EQUAL 1 OR NOT first STREQUAL "gbuffer")
  message(FATAL_ERROR "--timings: expected frame_ms, and process_cpu_ms and gl_wait_ms over 1 "
          "frame on the first node (gbuffer): ${timings}")
endif()
# The world's first-use builds are one-time costs, listed apart from the frame medians (with no
# warm-up the frame that paid for them is measured again; tests/unit/test_render_world_one_time.cpp).
foreach(what "embree device and BVH build" "gl scene upload" "gl shading upload" "gl programs and targets")
  string(JSON ms ERROR_VARIABLE missing GET "${timings}" one_time_ms "${what}")
  if(missing OR NOT ms GREATER 0)
    message(FATAL_ERROR "--timings one_time_ms lacks '${what}': ${timings}")
  endif()
endforeach()
if(NOT osmesa_stdout MATCHES "one-time: embree device and BVH build [0-9.]+ ms")
  message(FATAL_ERROR "render must print the BVH build as a one-time cost:\n${osmesa_stdout}")
endif()
# The first frame against a steady one: what it paid beyond the recorded one-time work is said
# too (tests/unit/test_first_frame.cpp checks the split).
foreach(key wall_ms one_time_ms steady_ms unrecorded_ms)
  string(JSON ms ERROR_VARIABLE missing GET "${timings}" first_frame ${key})
  if(missing)
    message(FATAL_ERROR "--timings first_frame lacks '${key}': ${timings}")
  endif()
endforeach()
string(JSON first_one_time GET "${timings}" first_frame one_time_ms)
if(NOT first_one_time GREATER 0 OR NOT osmesa_stdout MATCHES
   "first frame: [0-9.]+ ms against a steady [0-9.]+ ms: [0-9.]+ ms one-time work")
  message(FATAL_ERROR "render must print its first frame against a steady one, with the one-time "
          "work it did (${first_one_time} ms):\n${osmesa_stdout}")
endif()
string(JSON again GET "${timings}" measured_again)
if(NOT again OR NOT osmesa_stdout MATCHES "a measured frame did one-time work")
  message(FATAL_ERROR "with no warm-up the first frame did one-time work and must be said to "
          "have been measured again (measured_again: ${again}):\n${osmesa_stdout}")
endif()
# --context auto picks EGL on a hardware device, else OSMesa, and the devices line says which.
expect_success(render-auto ARGS render "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --context auto
               --size 96x72 --frames 1 --warmup 0 --out auto.exr FILES auto.exr)
if(NOT LAST_STDOUT MATCHES "devices: GL: .* via (osmesa|egl)")
  message(FATAL_ERROR "--context auto must name the context it picked:\n${LAST_STDOUT}")
endif()
expect_failure(bad-context EXPECT "--context" "vulkan" ARGS render "${SOURCE_DIR}/samples/scenes/shadow-sphere.json"
               --context vulkan)
# --gl-sync: auto says what it chose and why (OSMesa here: a software rasterizer, so a wait per
# node); frame waits once per frame, at its end, and gives the same image.
string(JSON sync GET "${timings}" gl_sync)
if(NOT sync MATCHES "^node \\(auto: software rasterizer llvmpipe")
  message(FATAL_ERROR "--gl-sync auto on llvmpipe must resolve to node and say why: ${sync}")
endif()
expect_success(render-frame-sync ARGS render "${SOURCE_DIR}/samples/scenes/shadow-sphere.json" --context osmesa
               --gl-sync frame --size 96x72 --frames 2 --warmup 0 --out frame.exr --timings f.json
               FILES frame.exr f.json)
expect_success(frame-vs-node-sync ARGS diff frame.exr osmesa.exr --fail-above rmse=0)
file(READ "${WORK_DIR}/f.json" timings)
string(JSON sync GET "${timings}" gl_sync)
string(JSON frameWait GET "${timings}" frame_gl_wait_ms samples)
string(JSON nodeWait ERROR_VARIABLE noWait GET "${timings}" schedule 0 timing gl_wait_ms)
if(NOT sync STREQUAL "frame (asked)" OR NOT frameWait EQUAL 2 OR noWait STREQUAL "NOTFOUND")
  message(FATAL_ERROR "--gl-sync frame: expected one wait per frame and none per node: ${timings}")
endif()
expect_failure(bad-gl-sync EXPECT "--gl-sync" "always" ARGS render "${SOURCE_DIR}/samples/scenes/shadow-sphere.json"
               --gl-sync always)

# A scene with moving objects says which frame it is: blurred by the distributed reference, the
# frame's instant in the hybrid.
expect_success(motion-distributed ARGS render "${SOURCE_DIR}/samples/scenes/motion.json"
               --recipe "${SOURCE_DIR}/samples/graphs/distributed.json" --size 32x24 --frames 1
               --warmup 0 --out motion-distributed.png FILES motion-distributed.png)
if(NOT LAST_STDOUT MATCHES "motion: 2 moving instance\\(s\\), blurred over the shutter by distributed \\(rt_distributed\\)")
  message(FATAL_ERROR "render must say the distributed frame blurs the motion: ${LAST_STDOUT}")
endif()
expect_success(motion-hybrid ARGS render "${SOURCE_DIR}/samples/scenes/motion.json" --size 32x24
               --frames 1 --warmup 0 --out motion-hybrid.png FILES motion-hybrid.png)
if(NOT LAST_STDOUT MATCHES "motion: 2 moving instance\\(s\\), shown at the frame's instant")
  message(FATAL_ERROR "render must say the hybrid frame shows the frame's instant: ${LAST_STDOUT}")
endif()
