# OpenImageIO is loaded as a module on the first image read or written (engine/core/image_codec.h):
# a command that touches no image never loads its ~260 libraries, one that writes an image does,
# and a missing module is one error naming it, with no image left behind.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

# The dynamic loader's own account of the libraries it opens (glibc's LD_DEBUG=libs, on stderr).
set(ENV{LD_DEBUG} libs)
expect_success(no-image ARGS passes)
string(FIND "${LAST_STDERR}" "libOpenImageIO" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "[no-image] `diptych passes` loaded OpenImageIO")
endif()
string(FIND "${LAST_STDERR}" "diptych_image_codec" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "[no-image] `diptych passes` loaded the image codec module")
endif()

expect_success(writes-image FILES out.png
               ARGS render ${SOURCE_DIR}/samples/scenes/whitted.json --size 64x48 --out out.png)
foreach(expected "diptych_image_codec" "libOpenImageIO")
  string(FIND "${LAST_STDERR}" "${expected}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "[writes-image] writing a PNG did not load ${expected}")
  endif()
endforeach()
unset(ENV{LD_DEBUG})

set(ENV{DIPTYCH_IMAGE_CODEC} "${WORK_DIR}/no-such-codec.so")
expect_failure(missing-module
               EXPECT "cannot load the image codec module" "no-such-codec.so"
               ARGS render ${SOURCE_DIR}/samples/scenes/whitted.json --size 64x48 --out out.png)
unset(ENV{DIPTYCH_IMAGE_CODEC})
