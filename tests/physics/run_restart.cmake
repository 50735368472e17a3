# A run resumed from its checkpoint is the run itself: -DPROGRAM= -DOUT= -DEND= -DMID=
# [-DARGS=...] [-DSCENE=ON].  The program runs to END in OUT/whole, and again to MID (an
# output time) with --checkpoint MID (SCENE: the model's own `checkpoint MID`) in OUT/part,
# from whose checkpoint.bin it then resumes to END.  The resumed run must write exactly the
# whole run's energies.csv, measurement files, particle files and .pvd lists (on one thread,
# so that every sum has one order) and report the same steps and expectations in
# summary.json.  A checkpoint cut short or with a byte changed, and one read by a program of
# another model (-DOTHER=), are refused.
include(${CMAKE_CURRENT_LIST_DIR}/same_outputs.cmake)
file(REMOVE_RECURSE ${OUT})
function(run)
  execute_process(COMMAND ${PROGRAM} --quiet --threads 1 ${ARGS} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # (1: an expectation failed, the same in both)
    message(FATAL_ERROR "${PROGRAM} ${ARGN}: exit code ${rc}\n${out}\n${err}")
  endif()
endfunction()
run(--end ${END} --out ${OUT}/whole)
if(SCENE) # the model's scene asks for a checkpoint at MID (`checkpoint`)
  run(--end ${MID} --out ${OUT}/part)
else()
  run(--end ${MID} --checkpoint ${MID} --out ${OUT}/part)
endif()
run(--end ${END} --restart ${OUT}/part/checkpoint.bin)

same_outputs(${OUT}/whole ${OUT}/part)
# summary.json: the same steps, time and expectation results (not the timings)
foreach(run whole part)
  file(STRINGS ${OUT}/${run}/summary.json lines
       REGEX "^  \"(steps|time)\"|\"(error|passed|value|verdict|checks)\"")
  set(summary_${run} "${lines}")
endforeach()
if(NOT summary_whole STREQUAL summary_part)
  message(FATAL_ERROR "summary.json differs:\nwhole: ${summary_whole}\nresumed: ${summary_part}")
endif()

# Refused, with the reason and exit code 4: a checkpoint cut short, one with a byte changed
# (its hash), and one of another model.
file(SIZE ${OUT}/part/checkpoint.bin size)
math(EXPR half "${size} / 2")
execute_process(COMMAND head -c ${half} ${OUT}/part/checkpoint.bin OUTPUT_FILE ${OUT}/cut.bin)
function(refused program expect)
  execute_process(COMMAND ${program} --quiet ${ARGN} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 4 OR NOT err MATCHES "${expect}")
    message(FATAL_ERROR "${program} ${ARGN}: exit code ${rc} (expected 4), stderr:\n${err}"
                        "expected: ${expect}")
  endif()
endfunction()
refused(${PROGRAM} "error: cannot restart from .*cut.bin: it is cut short or damaged"
        --restart ${OUT}/cut.bin --out ${OUT}/cut_out)
execute_process(COMMAND ${CMAKE_COMMAND} -E copy ${OUT}/part/checkpoint.bin ${OUT}/flipped.bin)
execute_process(COMMAND sh -c "printf 'x' | dd of=${OUT}/flipped.bin bs=1 seek=${half} conv=notrunc"
                OUTPUT_QUIET ERROR_QUIET)
refused(${PROGRAM} "error: cannot restart from .*flipped.bin: it is cut short or damaged"
        --restart ${OUT}/flipped.bin --out ${OUT}/flipped_out)
if(DEFINED OTHER)
  refused(${OTHER} "error: cannot restart from .*checkpoint.bin: it is a checkpoint of the model '[a-z0-9_]+', not of '[a-z0-9_]+'"
          --restart ${OUT}/part/checkpoint.bin --out ${OUT}/other_out)
endif()
message(STATUS "${compared} files the same after the restart at ${MID} s")
