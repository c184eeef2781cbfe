# Default lighting, --env/--light, --exposure auto and --tonemap through the real binary
# (docs/materials.md).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(blender "${SOURCE_DIR}/samples/scenes/blender-point-light.gltf")
set(whitted "${SOURCE_DIR}/samples/scenes/whitted.json")
set(fast --size 32x24 --frames 1 --warmup 0)

# A glTF with its own light gets no default, and says nothing about it.
expect_success(own-light ARGS render ${blender} ${fast} --out own.png FILES own.png)
string(FIND "${LAST_STDERR}" "default lighting" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "[own-light] default lighting added to a lit scene\n${LAST_STDERR}")
endif()

# The same scene with its lights removed through a JSON include is unlit: one line says so.
file(WRITE "${WORK_DIR}/unlit.json"
     "{\"objects\": [{\"type\": \"gltf\", \"file\": \"${blender}\", \"use_lights\": false}]}")
expect_success(default-lighting ARGS render unlit.json ${fast} --out unlit.png FILES unlit.png)
string(REGEX MATCHALL "default lighting added" lines "${LAST_STDERR}")
list(LENGTH lines count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "[default-lighting] expected one log line, got ${count}\n${LAST_STDERR}")
endif()

expect_success(light-option ARGS render unlit.json ${fast} --out lit.png
               --light "{\"type\":\"directional\",\"direction\":[0,-1,0],\"intensity\":2}"
               FILES lit.png)
string(FIND "${LAST_STDERR}" "default lighting added" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "[light-option] --light must replace the default\n${LAST_STDERR}")
endif()

expect_success(exposure-auto ARGS render ${whitted} ${fast} --exposure auto --tonemap aces
               --out auto.png FILES auto.png)
string(REGEX MATCH "--exposure auto: [-+][0-9.]+ EV" said "${LAST_STDOUT}")
if(NOT said)
  message(FATAL_ERROR "[exposure-auto] chosen EV not printed\n${LAST_STDOUT}")
endif()

expect_failure(bad-tonemap EXPECT "--tonemap" "filmic" ARGS render ${whitted} ${fast} --tonemap filmic)
expect_failure(bad-exposure EXPECT "--exposure" "bright" ARGS render ${whitted} ${fast} --exposure bright)
expect_failure(bad-light EXPECT "--light" "laser" ARGS render ${whitted} ${fast} --light "{\"type\":\"laser\"}")
expect_failure(bad-light-json EXPECT "--light" "malformed JSON" ARGS render ${whitted} ${fast} --light "{nope")
expect_failure(missing-env EXPECT "--env" "no-such.hdr" ARGS render ${whitted} ${fast} --env no-such.hdr)
