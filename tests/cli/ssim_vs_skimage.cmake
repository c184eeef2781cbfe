# SSIM of `diptych diff` against scikit-image on generated PNG and EXR pairs and on real pairs
# (renders of the sample scenes by the raster and the hybrid recipe)
# (tests/tools/ssim_reference.py). Needs /usr/bin/python3 with Debian's python3-skimage; when it
# is missing this test FAILS (it does not skip): .ci/install-deps installs it.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(python /usr/bin/python3)
execute_process(COMMAND ${python} -c "import numpy, scipy, PIL, skimage.metrics"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "scikit-image is not available to ${python} (${rc}): ${err}\n"
                      "Install Debian's python3-skimage: 'apt-get install python3-skimage' "
                      "(.ci/install-deps does this).")
endif()
execute_process(COMMAND ${python} ${SOURCE_DIR}/tests/tools/ssim_reference.py
                        --diptych ${DIPTYCH} --work ${WORK_DIR} --tolerance 1e-4
                        --samples ${SOURCE_DIR}/samples
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 300)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "SSIM disagrees with scikit-image (exit ${rc})\n${out}\n${err}")
endif()
