# A model the set-up must refuse with a message, before any step:
#   -DPROGRAM= -DOUT=        the generated program and its output folder
#   -DEXPECT=                a regular expression stderr must match
#   -DULIMIT_KB=             run under `ulimit -v` of this many KiB (optional)
# Checked: exit code 4 (set-up failed) and the message.
file(REMOVE_RECURSE ${OUT})
set(run ${PROGRAM} --quiet --out ${OUT})
if(DEFINED ULIMIT_KB)
  set(run sh -c "ulimit -v ${ULIMIT_KB} && exec \"$0\" \"$@\"" ${run})
endif()
execute_process(COMMAND ${run} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit code ${rc}; stderr:\n${err}")
if(NOT rc EQUAL 4)
  message(FATAL_ERROR "expected exit code 4 (set-up failed), got ${rc}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match '${EXPECT}'")
endif()
