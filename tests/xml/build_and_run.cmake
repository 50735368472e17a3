# build_and_run(SRC NAME): sphc SRC into WORKDIR/NAME and run it to END, output every EVERY
# into WORKDIR/NAME_out; stops the test with sphc's or the program's output on failure.
function(build_and_run src name)
  execute_process(COMMAND "${SPHC}" -o "${WORKDIR}/${name}" "${src}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc ${src} failed (exit ${rc}):\n${out}\n${err}")
  endif()
  execute_process(COMMAND "${WORKDIR}/${name}" --quiet --threads 1 --end ${END} --every ${EVERY}
                          --out "${WORKDIR}/${name}_out"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${name} failed (exit ${rc}):\n${out}\n${err}")
  endif()
endfunction()
