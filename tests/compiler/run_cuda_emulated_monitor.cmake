# The stability monitor's sums on the device:
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DEND=
# The CPU program and the CUDA target's model.cu built with SPH_CUDA_EMULATE run to END with
# no output after t = 0 (the output interval is 2 END), so that every check of the monitor
# is a periodic one (every 20 steps).  The CPU looks at the host's state; the CUDA target must
# answer every check from the sums of its monitor pass alone (device_checks = checks in
# summary.json), and those sums
# must give what the host's look gives: the smallest principal stretch and the largest
# total energy seen over the checks agree to 1e-7 relative (the two targets' states differ
# by the summation order of their pair sums, amplified over the run, as in
# run_cuda_emulated.cmake; a wrong energy or stretch in the pass differs by far more).
include(${CMAKE_CURRENT_LIST_DIR}/cuda_emulated_build.cmake)
execute_process(COMMAND awk "BEGIN { printf \"%.17g\", 2 * ${END} }" OUTPUT_VARIABLE every)
foreach(prog cpu emulated)
  execute_process(COMMAND ${${prog}} --quiet --threads 1 --end ${END} --every ${every}
                          --out ${WORKDIR}/${prog}_out
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # 1: an expectation of the model failed (short run)
    message(FATAL_ERROR "${prog} failed (exit ${rc}):\n${out}\n${err}")
  endif()
  file(READ ${WORKDIR}/${prog}_out/summary.json summary)
  foreach(key checks device_checks smallest_stretch largest_energy)
    string(JSON ${prog}_${key} GET "${summary}" stability ${key})
  endforeach()
endforeach()
if(cpu_checks LESS 2 OR NOT cpu_checks EQUAL emulated_checks)
  message(FATAL_ERROR "checks: ${cpu_checks} on the CPU, ${emulated_checks} emulated")
endif()
if(NOT cpu_device_checks EQUAL 0 OR NOT emulated_device_checks EQUAL emulated_checks)
  message(FATAL_ERROR "the emulated CUDA program answered ${emulated_device_checks} of its "
                      "${emulated_checks} checks from the device's sums (expected all)")
endif()
foreach(key smallest_stretch largest_energy)
  set(x ${cpu_${key}})
  set(y ${emulated_${key}})
  execute_process(COMMAND awk "BEGIN { x = ${x}; y = ${y}; d = x - y; if (d < 0) d = -d;
                               m = x < 0 ? -x : x; print (x > 0 && d <= 1e-7 * m) ? \"ok\" : \"bad\" }"
                  OUTPUT_VARIABLE verdict OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT verdict STREQUAL "ok")
    message(FATAL_ERROR "${key}: CPU ${x}, emulated CUDA ${y}")
  endif()
  message(STATUS "${stem}: ${key} ${x} (CPU), ${y} (emulated CUDA)")
endforeach()
message(STATUS "${stem}: all ${emulated_checks} checks answered on the device")
