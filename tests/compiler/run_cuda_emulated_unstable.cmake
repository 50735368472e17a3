# A run that goes unstable is stopped alike by both targets:
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= [-DARGS=a,b] [-DSYMMETRIC=ON]
# The CPU program and the CUDA target's model.cu built with SPH_CUDA_EMULATE (device passes
# run serially on host memory) both run the model with ARGS.  Both must exit with 3 (the
# stability monitor stopped the run) and print the same error, with the same step, time,
# body, particle and finding, and the same notes: the CUDA target's periodic checks read the
# sums of its monitor pass (templates/body_cuda.cu) and copy the state only when those show
# something wrong, so a pass that missed the instability lets the run go on to a later
# check and names another step.  SYMMETRIC: a model symmetric about a plane, whose mirror
# particles reach the finding alike up to the round-off of sums taken in another order (a
# block crushed to a stretch of 6e-4 amplifies it past any tie rule): the particle named may
# be either of a mirror pair, all else the same.
include(${CMAKE_CURRENT_LIST_DIR}/cuda_emulated_build.cmake)
string(REPLACE "," ";" ARGS "${ARGS}")
foreach(prog cpu emulated)
  file(MAKE_DIRECTORY ${WORKDIR}/${prog}_run)
  execute_process(COMMAND ${${prog}} --quiet --threads 1 --out out ${ARGS}
                  WORKING_DIRECTORY ${WORKDIR}/${prog}_run
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err_${prog})
  if(NOT rc EQUAL 3)
    message(FATAL_ERROR "${prog}: expected exit code 3 (unstable), got ${rc}:\n${err_${prog}}")
  endif()
endforeach()
if(SYMMETRIC)
  foreach(prog cpu emulated)
    string(REGEX REPLACE "particle [0-9]+ \\(reference position [^)]*\\)" "particle (one of a mirror pair)"
           err_${prog} "${err_${prog}}")
  endforeach()
endif()
if(NOT err_cpu STREQUAL err_emulated)
  message(FATAL_ERROR "the targets stop differently:\n--- CPU:\n${err_cpu}\n"
                      "--- emulated CUDA:\n${err_emulated}")
endif()
message(STATUS "${stem}: both targets stop with\n${err_cpu}")
