# A model run on 1, 2, 3 and 4 processes gives the serial program's results:
#   -DSERIAL= -DPROGRAM= (the same model built with sphc --mpi) -DMPIEXEC= -DNPFLAG=
#   -DMPIFLAGS= (;-list) -DSAME_CSV= -DOUT= -DEND= [-DARGS=...] [-DTOL=...] [-DINEXACT=ON]
# On one process the MPI program is the serial one: every output file the same, byte for
# byte.  On 2 to 4 the particles are shared out and their sums taken in other orders:
# energies.csv and every measurement file agree with the serial run within TOL of each
# column's scale (same_csv.c: a column's largest value over the run, a vector's largest
# component's; default 2e-9: the files print 10 significant digits, so this is the last digit
# or two, and what round-off leaves after some thousand steps is below it: 1e-10 to 2e-10 of
# the tip force of the beam, 0 in its energies' printed digits).  INEXACT: a program of
# another target (the CUDA target's, emulated), which sums in its own order on one process
# too: compared like the others, on 1 to 3 processes.
include(${CMAKE_CURRENT_LIST_DIR}/../physics/same_outputs.cmake)
if(NOT TOL)
  set(TOL 2e-9)
endif()
file(REMOVE_RECURSE ${OUT})
function(run name)
  execute_process(COMMAND ${ARGN} --quiet --end ${END} ${ARGS} --out ${OUT}/${name}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # (1: an expectation failed, the same in all)
    message(FATAL_ERROR "${name}: exit code ${rc}\n${out}\n${err}")
  endif()
  set(rc_${name} ${rc} PARENT_SCOPE)
endfunction()
run(serial ${SERIAL})
set(nps 1 2 3 4)
set(compared_nps 2 3 4)
if(INEXACT)
  set(nps 1 2 3)
  set(compared_nps 1 2 3)
endif()
foreach(np ${nps})
  run(np${np} ${MPIEXEC} ${NPFLAG} ${np} ${MPIFLAGS} ${PROGRAM})
  if(NOT rc_np${np} EQUAL rc_serial)
    message(FATAL_ERROR "${np} processes: exit code ${rc_np${np}}, serial ${rc_serial}")
  endif()
endforeach()
if(NOT INEXACT)
  same_outputs(${OUT}/serial ${OUT}/np1)
  message(STATUS "1 process: ${compared} files the same as the serial run's")
endif()
file(GLOB csvs RELATIVE ${OUT}/serial ${OUT}/serial/*.csv)
foreach(np ${compared_nps})
  foreach(f ${csvs})
    execute_process(COMMAND ${SAME_CSV} ${OUT}/serial/${f} ${OUT}/np${np}/${f} ${TOL}
                    RESULT_VARIABLE differ OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "${np} processes: ${out}")
    if(differ)
      message(FATAL_ERROR "${np} processes: ${f} differs from the serial run's\n${out}${err}")
    endif()
  endforeach()
  if(np EQUAL 1)
    continue() # (one process writes .vtu files, no pieces)
  endif()
  file(GLOB pieces ${OUT}/np${np}/particles/*_p*.vtu)
  file(GLOB frames ${OUT}/np${np}/particles/*.pvtu)
  list(LENGTH pieces npieces)
  list(LENGTH frames nframes)
  math(EXPR expected "${nframes} * ${np}")
  if(nframes EQUAL 0 OR NOT npieces EQUAL expected)
    message(FATAL_ERROR "${np} processes: ${nframes} frames (.pvtu) with ${npieces} pieces")
  endif()
  # (the .pvtu declares the pieces' arrays with their components' names, as they do)
  list(GET frames 0 frame)
  file(READ ${frame} pvtu)
  if(NOT pvtu MATCHES "Name=\"cauchy_stress\" NumberOfComponents=\"6\" ComponentName0=\"XX\" ComponentName1=\"YY\" ComponentName2=\"ZZ\" ComponentName3=\"XY\" ComponentName4=\"YZ\" ComponentName5=\"XZ\""
     OR NOT pvtu MATCHES "Name=\"displacement\" NumberOfComponents=\"3\" ComponentName0=\"X\" ComponentName1=\"Y\" ComponentName2=\"Z\"")
    message(FATAL_ERROR "${frame} does not name the components of its arrays")
  endif()
endforeach()
