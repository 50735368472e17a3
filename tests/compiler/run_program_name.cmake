# run_program_name.cmake — the program is named after the model file as given ("my-beam.sph"
# builds ./my-beam), and sphc says what it produced.
#
#   cmake -DSPHC=sphc -DMODEL=model.sph -DWORKDIR=dir -P run_program_name.cmake

file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
configure_file(${MODEL} ${WORKDIR}/my-beam.sph COPYONLY)
execute_process(COMMAND ${SPHC} my-beam.sph WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc my-beam.sph failed (${rc}):\n${err}")
endif()
if(NOT EXISTS ${WORKDIR}/my-beam OR EXISTS ${WORKDIR}/my_beam)
  message(FATAL_ERROR "sphc my-beam.sph did not build ./my-beam")
endif()
if(NOT out STREQUAL "sphc: built ./my-beam (cpu)\n")
  message(FATAL_ERROR "sphc my-beam.sph printed '${out}', expected 'sphc: built ./my-beam (cpu)'")
endif()
# A name with characters the generated code would have to quote: changed, with a note.
configure_file(${MODEL} "${WORKDIR}/my beam.sph" COPYONLY)
execute_process(COMMAND ${SPHC} --emit-c src --emit-only "my beam.sph" WORKING_DIRECTORY ${WORKDIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT EXISTS ${WORKDIR}/src/my_beam.c OR NOT out MATCHES "wrote src/my_beam.c"
   OR NOT err MATCHES "the program is named 'my_beam'")
  message(FATAL_ERROR "sphc --emit-only 'my beam.sph': exit ${rc}, stdout '${out}', stderr '${err}'")
endif()
