# `diptych passes` prints slots, producers and parameters from the registry, and the tables of
# docs/technique-slots.md are exactly its --markdown output (regenerate them with it).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

expect_success(passes ARGS passes)
foreach(expected "visibility:" "reflection:" "transmission:" "rt_shadows (exact)"
        "shadow_map [gl, slot visibility]" "resolution" "integer in [16, 16384], default 2048"
        "one of none, constant, slope, normal_offset, receiver_plane, adaptive; default slope")
  string(FIND "${LAST_STDOUT}" "${expected}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "[passes] stdout lacks '${expected}'\n${LAST_STDOUT}")
  endif()
endforeach()

expect_success(passes-markdown ARGS passes --markdown)
file(READ "${SOURCE_DIR}/docs/technique-slots.md" doc)
string(FIND "${doc}" "${LAST_STDOUT}" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "docs/technique-slots.md does not contain the output of "
          "'diptych passes --markdown'; paste it in:\n${LAST_STDOUT}")
endif()

expect_success(render-help ARGS render --help)
string(FIND "${LAST_STDOUT}" "visibility, reflection, transmission" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "[render-help] --slot help does not list the slots\n${LAST_STDOUT}")
endif()
