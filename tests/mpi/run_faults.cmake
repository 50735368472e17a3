# Faults of runs on many processes end with a message and an exit code, never a hang:
#   -DTINY= (tests/mpi/tiny.sph built with --mpi) -DPROGRAM= (the beam, --mpi) -DMPIEXEC=
#   -DNPFLAG= -DMPIFLAGS= -DOUT=
# - more processes than a body has particles: the set-up refuses (exit 4), naming the body;
# - --restart from a damaged checkpoint: every process refuses it (exit 4);
# - a process killed while the others run: mpirun ends the job (exit non-zero), no hang
#   (the test's timeout would catch one);
# - SIGTERM to mpirun: every process stops at once, with one checkpoint (resumed on 3).
file(REMOVE_RECURSE ${OUT})
function(expect_failure what code pattern)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  TIMEOUT 120)
  if(code STREQUAL "any")
    if(rc EQUAL 0)
      message(FATAL_ERROR "${what}: exit code 0\n${out}\n${err}")
    endif()
  elseif(NOT rc EQUAL code)
    message(FATAL_ERROR "${what}: exit code ${rc}, expected ${code}\n${out}\n${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: no message matching '${pattern}'\n${out}\n${err}")
  endif()
  message(STATUS "${what}: exit code ${rc}, as expected")
endfunction()
expect_failure("4 processes, 3 particles" 4 "body 'strip' has 3 particles, too few to give each of the 4 processes"
               ${MPIEXEC} ${NPFLAG} 4 ${MPIFLAGS} ${TINY} --quiet --out ${OUT}/tiny)

execute_process(COMMAND ${MPIEXEC} ${NPFLAG} 2 ${MPIFLAGS} ${PROGRAM} --quiet --end 0.002
                        --checkpoint 0.002 --out ${OUT}/damaged RESULT_VARIABLE rc)
# cut short: its last records and the hash of its bytes are missing
file(SIZE ${OUT}/damaged/checkpoint.bin size)
math(EXPR keep "${size} * 2 / 3")
execute_process(COMMAND head -c ${keep} ${OUT}/damaged/checkpoint.bin
                OUTPUT_FILE ${OUT}/damaged/cut.bin)
expect_failure("a damaged checkpoint on 3 processes" 4 "cannot restart|damaged|incomplete|hash"
               ${MPIEXEC} ${NPFLAG} 3 ${MPIFLAGS} ${PROGRAM} --quiet --end 0.004
               --restart ${OUT}/damaged/cut.bin)
# one byte in the middle changed: well formed, only its hash (which process 0 alone checks)
# tells; every process must refuse it all the same
math(EXPR at "${size} / 2")
file(READ ${OUT}/damaged/checkpoint.bin byte OFFSET ${at} LIMIT 1 HEX)
if(byte STREQUAL "5a") # (written in octal for printf: 0xa5, else 0x5a)
  set(octal 245)
else()
  set(octal 132)
endif()
execute_process(COMMAND sh -c "cp ${OUT}/damaged/checkpoint.bin ${OUT}/damaged/flipped.bin && \
printf '\\${octal}' | dd of=${OUT}/damaged/flipped.bin bs=1 seek=${at} count=1 conv=notrunc \
2> /dev/null" RESULT_VARIABLE rc)
file(READ ${OUT}/damaged/flipped.bin changed OFFSET ${at} LIMIT 1 HEX)
if(NOT rc EQUAL 0 OR changed STREQUAL byte)
  message(FATAL_ERROR "could not change byte ${at} of the checkpoint (${byte} -> ${changed})")
endif()
expect_failure("a checkpoint with one byte changed, on 3 processes" 4 "cut short or damaged"
               ${MPIEXEC} ${NPFLAG} 3 ${MPIFLAGS} ${PROGRAM} --quiet --end 0.004
               --restart ${OUT}/damaged/flipped.bin)

# A process that dies: the last process kills itself with SIGKILL a second into the run.
file(WRITE ${OUT}/die.sh "#!/bin/sh\nrank=\${OMPI_COMM_WORLD_RANK:-\${PMI_RANK:-0}}\n"
     "if [ \"$rank\" = 1 ]; then (sleep 1; kill -9 $$) & fi\nexec \"$@\"\n")
file(CHMOD ${OUT}/die.sh PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
expect_failure("a process killed" any ".*" ${MPIEXEC} ${NPFLAG} 2 ${MPIFLAGS} ${OUT}/die.sh
               ${PROGRAM} --quiet --end 1 --out ${OUT}/killed)

# SIGTERM to mpirun, which passes it to the processes: they agree to stop at the end of a
# batch of steps and write one checkpoint, which resumes on 3 processes.  The signal goes a
# second after the run's first output (energies.csv at t = 0: the processes are in their
# steps), not at a fixed time: a signal before mpirun has started them ends it with exit
# code 1 and nothing written, and on a busy machine that once took over the 4 s this
# waited.
string(REPLACE ";" " " flags "${MPIFLAGS}")
execute_process(COMMAND sh -c "${MPIEXEC} ${NPFLAG} 2 ${flags} ${PROGRAM} --quiet --end 1 \
--checkpoint 0.5 --out ${OUT}/signalled & pid=$!; i=0; \
while [ ! -s ${OUT}/signalled/energies.csv ] && [ $i -lt 900 ]; do sleep 0.1; i=$((i + 1)); done; \
sleep 1; kill -TERM $pid; wait $pid"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(rc EQUAL 0 OR NOT "${out}${err}" MATCHES "stopped by SIGTERM at t = [^ ]+ s \\(step [0-9]+\\); the checkpoint"
   OR NOT EXISTS ${OUT}/signalled/checkpoint.bin)
  message(FATAL_ERROR "SIGTERM on 2 processes: exit code ${rc}\n${out}\n${err}")
endif()
file(READ ${OUT}/signalled/summary.json summary)
if(NOT summary MATCHES "\"status\": \"stopped\"")
  message(FATAL_ERROR "SIGTERM on 2 processes: summary.json does not say stopped\n${summary}")
endif()
# (resumed to 2 ms after the time it stopped at: an end before it is refused)
string(REGEX MATCH "stopped by SIGTERM at t = ([^ ]+) s" stop "${out}${err}")
execute_process(COMMAND awk "BEGIN { print ${CMAKE_MATCH_1} + 0.002 }"
                OUTPUT_VARIABLE later OUTPUT_STRIP_TRAILING_WHITESPACE)
execute_process(COMMAND ${MPIEXEC} ${NPFLAG} 3 ${MPIFLAGS} ${PROGRAM} --quiet --end ${later}
                        --restart ${OUT}/signalled/checkpoint.bin
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0 AND NOT rc EQUAL 1)
  message(FATAL_ERROR "resumed on 3 processes after SIGTERM: exit code ${rc}\n${out}\n${err}")
endif()
message(STATUS "SIGTERM: stopped with one checkpoint, resumed on 3 processes")
