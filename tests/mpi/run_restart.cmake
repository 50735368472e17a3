# A run checkpointed on 2 processes and resumed on 3, and on 1, gives the whole run's results:
#   -DSERIAL= -DPROGRAM= (built with sphc --mpi) -DMPIEXEC= -DNPFLAG= -DMPIFLAGS= -DSAME_CSV=
#   -DOUT= -DEND= -DAT= (the checkpoint's time) [-DARGS=...]
# Checkpoints hold each body's particles by global id (runtime/io/checkpoint.c), so a run
# resumes on any number of processes.  The resumed runs' energies.csv and measurement files
# agree with those of the whole serial run within 2e-9 of each column's scale (same_csv.c,
# run_ranks.cmake), their .pvd lists every frame, and each frame after the checkpoint has one
# piece per process of the resumed run.
file(REMOVE_RECURSE ${OUT})
function(run name)
  execute_process(COMMAND ${ARGN} --quiet ${ARGS} --out ${OUT}/${name}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # (1: an expectation failed, the same in all)
    message(FATAL_ERROR "${name}: exit code ${rc}\n${out}\n${err}")
  endif()
endfunction()
run(whole ${SERIAL} --end ${END})
run(np2 ${MPIEXEC} ${NPFLAG} 2 ${MPIFLAGS} ${PROGRAM} --end ${AT} --checkpoint ${AT})
if(NOT EXISTS ${OUT}/np2/checkpoint.bin)
  message(FATAL_ERROR "the run on 2 processes wrote no checkpoint")
endif()
foreach(np 3 1)
  file(COPY ${OUT}/np2/ DESTINATION ${OUT}/resumed${np})
  run(resumed${np} ${MPIEXEC} ${NPFLAG} ${np} ${MPIFLAGS} ${PROGRAM} --end ${END}
      --restart ${OUT}/resumed${np}/checkpoint.bin)
  file(GLOB csvs RELATIVE ${OUT}/whole ${OUT}/whole/*.csv)
  foreach(f ${csvs})
    execute_process(COMMAND ${SAME_CSV} ${OUT}/whole/${f} ${OUT}/resumed${np}/${f} 2e-9
                    RESULT_VARIABLE differ OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "resumed on ${np}: ${out}")
    if(differ)
      message(FATAL_ERROR "resumed on ${np}: ${f} differs from the whole run's\n${out}${err}")
    endif()
  endforeach()
  file(GLOB pvds ${OUT}/whole/particles/*.pvd)
  foreach(pvd ${pvds})
    get_filename_component(name ${pvd} NAME)
    file(STRINGS ${pvd} whole_frames REGEX "<DataSet")
    file(STRINGS ${OUT}/resumed${np}/particles/${name} frames REGEX "<DataSet")
    list(LENGTH whole_frames n_whole)
    list(LENGTH frames n)
    list(GET frames -1 last)
    string(REGEX MATCH "file=\"([^\"]*)\"" m "${last}")
    set(last_file ${CMAKE_MATCH_1})
    if(NOT n EQUAL n_whole OR NOT EXISTS ${OUT}/resumed${np}/particles/${last_file})
      message(FATAL_ERROR "resumed on ${np}: ${name} lists ${n} frames (the whole run "
                          "${n_whole}), the last ${last_file}")
    endif()
    if(np GREATER 1)
      string(REPLACE ".pvtu" "_p2.vtu" piece ${last_file})
      if(NOT EXISTS ${OUT}/resumed${np}/particles/${piece})
        message(FATAL_ERROR "resumed on ${np}: the last frame has no piece ${piece}")
      endif()
    endif()
  endforeach()
endforeach()
