# A run's outputs do not depend on its number of threads (the program takes fewer while the
# machine is busy, runtime/par/team.h): -DPROGRAM= -DOUT= -DEND= [-DARGS=...].  The program runs
# to END on 1, 2 and 3 threads (3 on a machine with fewer cores: threads that lose their
# core) and must write the same energies.csv, measurement files, particle files and .pvd
# lists, byte for byte: every sum of the passes (the viscous power, the contact's energies,
# the energies of the output) is taken in an order fixed by the particles.  With
# -DCOLOURS=N the first body's stripes must come in N colours (summary.json), and with
# -DLANES=L its momentum blocks' lanes must be at least the share L full.
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
file(READ ${OUT}/threads1/summary.json json)
string(JSON colours GET "${json}" bodies 0 colours)
string(JSON lanes GET "${json}" bodies 0 momentum_block_lanes)
if(DEFINED COLOURS AND NOT colours EQUAL COLOURS)
  message(FATAL_ERROR "the stripes come in ${colours} colours, not ${COLOURS}")
endif()
if(DEFINED LANES AND lanes LESS LANES)
  message(FATAL_ERROR "the momentum blocks' lanes are ${lanes} full, less than ${LANES}")
endif()
message(STATUS "${colours} colours of stripes, the momentum blocks' lanes ${lanes} full")
same_outputs(${OUT}/threads1 ${OUT}/threads2)
same_outputs(${OUT}/threads1 ${OUT}/threads3)
message(STATUS "${compared} files the same on 1, 2 and 3 threads")
