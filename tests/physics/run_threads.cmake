# A run's outputs do not depend on its number of threads (the program takes fewer while the
# machine is busy, runtime/par/team.h): -DPROGRAM= -DOUT= -DEND= [-DARGS=...].  The program runs
# to END on 1, 2 and 3 threads (3 on a machine with fewer cores: threads that lose their
# core) and must write the same energies.csv, measurement files, particle files and .pvd
# lists, byte for byte: every sum of the passes (the viscous power, the contact's energies,
# the energies of the output) is taken in an order fixed by the particles.
include(${CMAKE_CURRENT_LIST_DIR}/same_outputs.cmake)
file(REMOVE_RECURSE ${OUT})
foreach(threads 1 2 3)
  execute_process(COMMAND ${PROGRAM} --quiet --threads ${threads} --end ${END} ${ARGS}
                          --out ${OUT}/threads${threads}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # (1: an expectation failed, the same in all)
    message(FATAL_ERROR "${PROGRAM} --threads ${threads}: exit code ${rc}\n${out}\n${err}")
  endif()
endforeach()
same_outputs(${OUT}/threads1 ${OUT}/threads2)
same_outputs(${OUT}/threads1 ${OUT}/threads3)
message(STATUS "${compared} files the same on 1, 2 and 3 threads")
