# The CUDA target's passes run without a GPU (SPH_CUDA_EMULATE, runtime/sph_cuda.h):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DEND=
# The model is built for both targets: the CPU program, and model.cu compiled by the host
# C++ compiler with the device passes run serially on host memory (full pair lists, device
# views, reductions, sync to the host).  Both run to END; every value of the measurement
# files must agree to 1e-7 relative, and every energy to 1e-7 of the row's largest energy
# (the two targets sum the pairs in a different order, and a plane's force is a sum that
# cancels to a few digits, as does the strain energy of a body 1e4 times stiffer than the
# one it presses on; a wrong pass differs by far more: a stale initial time step alone made
# 1e-4).
include(${CMAKE_CURRENT_LIST_DIR}/cuda_emulated_build.cmake)
foreach(prog cpu emulated)
  execute_process(COMMAND ${${prog}} --quiet --threads 1 --end ${END}
                          --out ${WORKDIR}/${prog}_out
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # 1: an expectation of the model failed (short run)
    message(FATAL_ERROR "${prog} failed (exit ${rc}):\n${out}\n${err}")
  endif()
endforeach()
file(GLOB csvs RELATIVE ${WORKDIR}/cpu_out ${WORKDIR}/cpu_out/*.csv)
set(compared 0)
set(worst 0)
foreach(csv ${csvs})
  file(STRINGS ${WORKDIR}/cpu_out/${csv} a)
  file(STRINGS ${WORKDIR}/emulated_out/${csv} b)
  list(LENGTH a na)
  list(LENGTH b nb)
  if(NOT na EQUAL nb)
    message(FATAL_ERROR "${csv}: ${na} rows on the CPU, ${nb} emulated")
  endif()
  math(EXPR last "${na} - 1")
  foreach(r RANGE 1 ${last})
    list(GET a ${r} ra)
    list(GET b ${r} rb)
    set(row "")
    if(csv STREQUAL "energies.csv") # all in J: the row's largest energy sets the scale
      set(row "${ra}")
    endif()
    string(REPLACE "," ";" ra "${ra}")
    string(REPLACE "," ";" rb "${rb}")
    foreach(x y IN ZIP_LISTS ra rb)
      if(NOT x STREQUAL y) # then |x - y| <= 1e-7 max(|x|, |y|), checked by awk
        execute_process(COMMAND awk "BEGIN { x = ${x}; y = ${y}; d = x - y; if (d < 0) d = -d;
                                    m = x < 0 ? -x : x; n = y < 0 ? -y : y; if (n > m) m = n;
                                    k = split(\"${row}\", e, \",\");
                                    for (q = 2; q <= k; q++) { v = e[q] < 0 ? -e[q] : e[q];
                                                               if (v > m) m = v }
                                    print (d <= 1e-7 * m + 1e-300) ? \"ok\" : \"bad\" }"
                        OUTPUT_VARIABLE verdict OUTPUT_STRIP_TRAILING_WHITESPACE)
        if(NOT verdict STREQUAL "ok")
          message(FATAL_ERROR "${csv} row ${r}: CPU ${x}, emulated CUDA ${y}")
        endif()
      endif()
      math(EXPR compared "${compared} + 1")
    endforeach()
  endforeach()
endforeach()
message(STATUS "${stem}: ${compared} values of ${csvs} agree (CPU and emulated CUDA)")

# The stability monitor's periodic checks (every 20 steps) read the device's sums alone; only
# the checks before outputs, one per row of energies.csv after the first, copy the state.
file(READ ${WORKDIR}/emulated_out/summary.json summary)
if(NOT summary MATCHES "\"checks\": ([0-9]+),[ \n]*\"device_checks\": ([0-9]+)")
  message(FATAL_ERROR "summary.json does not give the monitor's checks")
endif()
set(checks ${CMAKE_MATCH_1})
set(device_checks ${CMAKE_MATCH_2})
file(STRINGS ${WORKDIR}/emulated_out/energies.csv rows)
list(LENGTH rows nrows)
math(EXPR looks "${checks} - ${device_checks}")
math(EXPR outputs "${nrows} - 2")
if(NOT looks EQUAL outputs)
  message(FATAL_ERROR "the monitor copied the state at ${looks} of its ${checks} checks; "
                      "expected only the ${outputs} before outputs")
endif()
message(STATUS "${stem}: ${device_checks} of the monitor's ${checks} checks on the device")
