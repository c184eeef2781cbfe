# A 50-point 320x240 sweep killed mid-run (SIGTERM) resumes from what it wrote
# (tests/cli/sweep_interrupt.sh; issue 12's acceptance).
execute_process(COMMAND bash "${CMAKE_CURRENT_LIST_DIR}/sweep_interrupt.sh" "${DIPTYCH}"
                        "${SOURCE_DIR}/samples/scenes/shadow-sphere-sun.json" "${WORK_DIR}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "interrupted sweep: ${out}${err}")
endif()
message(STATUS "${out}")
