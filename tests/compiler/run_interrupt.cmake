# run_interrupt.cmake — sphc stopped by a signal while the C compiler runs leaves no temporary
# folder behind, and the compiler does not run on:
#
#   cmake -DSPHC=sphc -DMODEL=model.sph -DWORKDIR=dir -DSIGNAL=TERM|INT -P run_interrupt.cmake
#
# The compiler ($CC) is a script that records that it started, sends SIGNAL to sphc (its
# parent) alone, sleeps 4 s and then records that it finished.  sphc's temporary folder is
# made under WORKDIR/tmp (TMPDIR).  Expected: sphc ends by the signal, WORKDIR/tmp is empty,
# and the compiler never finishes (sphc passed the signal on to it).

foreach(var SPHC MODEL WORKDIR SIGNAL)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_interrupt.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}/tmp")
file(WRITE "${WORKDIR}/slowcc" "#!/bin/sh
echo \"$@\" > '${WORKDIR}/started'
kill -${SIGNAL} $PPID
sleep 4
echo finished > '${WORKDIR}/finished'
")
file(CHMOD "${WORKDIR}/slowcc" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)

set(ENV{TMPDIR} "${WORKDIR}/tmp")
set(ENV{CC} "${WORKDIR}/slowcc")
# The signal's own action in sphc (a shell may start a background job with SIGINT ignored).
execute_process(COMMAND env --default-signal=${SIGNAL} "${SPHC}" "${MODEL}"
                        -o "${WORKDIR}/program"
                WORKING_DIRECTORY "${WORKDIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)

if(NOT EXISTS "${WORKDIR}/started")
  message(FATAL_ERROR "the compiler did not start (exit ${rc}):\n${out}${err}")
endif()
file(READ "${WORKDIR}/started" args)
if(rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "sphc exited with ${rc}; it should have ended by SIG${SIGNAL}:\n${out}${err}")
endif()
file(GLOB left "${WORKDIR}/tmp/*")
if(left)
  message(FATAL_ERROR "sphc (${rc}) left its temporary files behind: ${left}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 5)
if(EXISTS "${WORKDIR}/finished")
  message(FATAL_ERROR "the compiler ran on after sphc was stopped by SIG${SIGNAL}")
endif()
message(STATUS "sphc: '${rc}', its temporary folder removed, the compiler stopped "
               "(it had been given: ${args})")
