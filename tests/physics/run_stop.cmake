# A run with checkpoints stopped by SIGTERM (a batch system's notice) writes a checkpoint and
# exits with 6; resumed from it, it writes exactly what the whole run writes:
#   -DPROGRAM= -DOUT= -DEND= -DAFTER=seconds [-DARGS=...]
# The whole run must take well over AFTER seconds (the signal comes while it steps).
include(${CMAKE_CURRENT_LIST_DIR}/same_outputs.cmake)
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PROGRAM} --quiet --threads 1 ${ARGS} --end ${END} --out ${OUT}/whole
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
execute_process(COMMAND timeout --preserve-status -s TERM ${AFTER}
                        ${PROGRAM} --quiet --threads 1 ${ARGS} --end ${END} --checkpoint ${END}
                        --out ${OUT}/part
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 6 OR NOT err MATCHES "error: stopped by SIGTERM at t = [0-9.e-]+ s \\(step [0-9]+\\); the checkpoint .*/part/checkpoint.bin resumes the run \\(--restart\\)")
  message(FATAL_ERROR "stopped after ${AFTER} s: exit ${rc} (expected 6), stderr:\n${err}")
endif()
file(READ ${OUT}/part/summary.json summary)
if(NOT summary MATCHES "\"stopped\": {\n +\"signal\": \"SIGTERM\"")
  message(FATAL_ERROR "summary.json does not say the run was stopped:\n${summary}")
endif()
string(REGEX MATCH "t = [0-9.e-]+ s \\(step [0-9]+\\)" when "${err}")
execute_process(COMMAND ${PROGRAM} --quiet --threads 1 ${ARGS} --end ${END}
                        --restart ${OUT}/part/checkpoint.bin
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
same_outputs(${OUT}/whole ${OUT}/part)
message(STATUS "stopped at ${when}, resumed: the same ${compared} files")
