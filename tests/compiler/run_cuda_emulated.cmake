# The CUDA target's passes run without a GPU (SPH_CUDA_EMULATE, runtime/cuda/emulate.h):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DEND= [-DHOSTSTEP=ON]
# The model is built for both targets: the CPU program, and model.cu compiled by the host
# C++ compiler with the device passes run serially on host memory (full pair lists, device
# views, reductions, sync to the host).  Both run to END; every value of the measurement
# files must agree to 1e-7 relative, and every energy to 1e-7 of the row's largest energy
# (the two targets sum the pairs in a different order, and a plane's force is a sum that
# cancels to a few digits, as does the strain energy of a body 1e4 times stiffer than the
# one it presses on; a wrong pass differs by far more: a stale initial time step alone made
# 1e-4).  A value below 1e-4 of its column's largest (on the CPU; of its vector's, for a
# component) is compared as if it were that large: a plane that a wave has not reached yet
# measures round-off (1e-15 m where the displacement comes to 1e-4 m), and so does a force
# component that stays 0, which no two orders of summation share.
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
  # each column's largest magnitude on the CPU, comma-separated (the floor of its scale); the
  # components of a vector (ux uy uz, fx fy fz: two-letter names with the same first letter)
  # take their largest, as same_csv.c does: a force component that stays at 0 is round-off
  execute_process(COMMAND awk -F, "NR == 1 { for (c = 1; c <= NF; c++)
                                                 g[c] = length($c) == 2 ? substr($c, 1, 1) : c }
                                   NR > 1 { for (c = 1; c <= NF; c++) { v = $c < 0 ? -$c : $c;
                                               if (v > m[g[c]]) m[g[c]] = v } }
                                   END { for (c = 1; c <= NF; c++) printf \"%s%.17g\",
                                         (c > 1 ? \",\" : \"\"), m[g[c]] + 0 }"
                          ${WORKDIR}/cpu_out/${csv}
                  OUTPUT_VARIABLE colmax OUTPUT_STRIP_TRAILING_WHITESPACE)
  string(REPLACE "," ";" colmax "${colmax}")
  foreach(r RANGE 1 ${last})
    list(GET a ${r} ra)
    list(GET b ${r} rb)
    set(row "")
    if(csv STREQUAL "energies.csv") # all in J: the row's largest energy sets the scale
      set(row "${ra}")
    endif()
    string(REPLACE "," ";" ra "${ra}")
    string(REPLACE "," ";" rb "${rb}")
    foreach(x y cm IN ZIP_LISTS ra rb colmax)
      if(NOT x STREQUAL y) # then |x - y| <= 1e-7 max(|x|, |y|, 1e-4 colmax), checked by awk
        execute_process(COMMAND awk "BEGIN { x = ${x}; y = ${y}; d = x - y; if (d < 0) d = -d;
                                    m = x < 0 ? -x : x; n = y < 0 ? -y : y; if (n > m) m = n;
                                    if (1e-4 * ${cm} > m) m = 1e-4 * ${cm};
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

# What bounded the time steps: the device's clock counts them as the CPU's host does, step
# for step (summary.json's time_step_bounds, the same object).
file(READ ${WORKDIR}/cpu_out/summary.json cpu_summary)
string(JSON cpu_bounds GET "${cpu_summary}" time_step_bounds)
string(JSON device_bounds GET "${summary}" time_step_bounds)
if(NOT cpu_bounds STREQUAL device_bounds)
  message(FATAL_ERROR "the time step's bounds: ${cpu_bounds} on the CPU, ${device_bounds} "
                      "counted by the device's clock")
endif()

# HOSTSTEP: the device's clock chooses the host's time steps to the bit.  The same model.cu
# without its `advance` hook (the host chooses every time step from the sums it reads back
# after each step, and waits for them) must write byte for byte the same files.
if(HOSTSTEP)
  file(READ ${WORKDIR}/${stem}.cu source)
  string(REPLACE "    .advance = model_advance,\n" "" hoststep "${source}")
  if(hoststep STREQUAL source)
    message(FATAL_ERROR "model.cu has no `.advance = model_advance,`")
  endif()
  file(WRITE ${WORKDIR}/hoststep.cu "${hoststep}")
  sph_emulated_compile(${WORKDIR}/hoststep ${WORKDIR}/hoststep.cu -Wno-unused-function)
  execute_process(COMMAND ${WORKDIR}/hoststep --quiet --threads 1 --end ${END}
                          --out ${WORKDIR}/hoststep_out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1)
    message(FATAL_ERROR "the emulated program without the device's clock failed (exit ${rc})")
  endif()
  file(GLOB files RELATIVE ${WORKDIR}/emulated_out ${WORKDIR}/emulated_out/*.csv)
  foreach(f ${files})
    file(SHA256 ${WORKDIR}/emulated_out/${f} a)
    file(SHA256 ${WORKDIR}/hoststep_out/${f} b)
    if(NOT a STREQUAL b)
      message(FATAL_ERROR "${f} differs between the device's clock and the host's time steps")
    endif()
  endforeach()
  message(STATUS "${stem}: the device's clock and the host's time steps write the same ${files}")
endif()
