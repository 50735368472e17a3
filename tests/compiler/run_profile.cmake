# --profile on both targets (runtime/core/profile.c):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DEND= -DPASSES=a,b,...
# The CPU program and the CUDA target's emulated one (the device's passes run on the host,
# timed by the events of runtime/cuda/launch.h) run the model to END with --profile.  Each must
# list every pass of PASSES in summary.json's "profile", in the steps, and print the table;
# on the CPU every one of them once per step (SPH_BODY_PASS around each call of the step), and
# the passes' times add up to at most the step timer's and to most of it (the passes are
# the step; the rest is the choice of the time step and the loop).  The emulated program
# launches each at least once per step, and its monitor's pass runs between the steps (at
# the stability checks).  Both time the set-up's neighbour search.
# Without --profile there is no "profile" in summary.json.
cmake_minimum_required(VERSION 3.19) # string(JSON)
include(${CMAKE_CURRENT_LIST_DIR}/cuda_emulated_build.cmake)
string(REPLACE "," ";" PASSES "${PASSES}")

function(check_profile prog dir out)
  file(READ ${dir}/summary.json json)
  string(JSON steps GET "${json}" steps)
  string(JSON step_time GET "${json}" step_time)
  string(JSON n LENGTH "${json}" profile)
  if(NOT out MATCHES ": ${steps} steps, [0-9.]+ s \\(per step")
    message(FATAL_ERROR "${prog}: no profile table of ${steps} steps in its output:\n${out}")
  endif()
  set(total 0)
  set(setup_total 0)
  set(seen "")
  math(EXPR last "${n} - 1")
  foreach(k RANGE ${last})
    string(JSON pass GET "${json}" profile ${k} pass)
    string(JSON seconds GET "${json}" profile ${k} seconds)
    string(JSON calls GET "${json}" profile ${k} calls)
    string(JSON phase GET "${json}" profile ${k} phase)
    if(phase STREQUAL "set-up" AND pass MATCHES "^set-up: neighbour search$")
      list(APPEND seen "(set-up)")
    endif()
    if(phase STREQUAL "set-up")
      set(setup_total "${setup_total}+${seconds}")
    endif()
    if(NOT phase STREQUAL "steps")
      if(prog STREQUAL "emulated" AND phase STREQUAL "checks" AND pass MATCHES "_monitor$")
        list(APPEND seen "${pass} (outside)")
      endif()
      continue()
    endif()
    set(total "${total}+${seconds}")
    list(FIND PASSES "${pass}" expected)
    if(expected EQUAL -1)
      continue()
    endif()
    list(APPEND seen "${pass}")
    if(prog STREQUAL "cpu" AND NOT calls EQUAL steps)
      message(FATAL_ERROR "cpu: ${pass} was timed ${calls} times in ${steps} steps")
    endif()
    if(prog STREQUAL "emulated" AND calls LESS steps)
      message(FATAL_ERROR "emulated: ${pass} launched ${calls} times in ${steps} steps")
    endif()
  endforeach()
  foreach(pass ${PASSES})
    list(FIND seen "${pass}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${prog}: the pass ${pass} is not in the profile of the steps:\n${json}")
    endif()
  endforeach()
  if(NOT "(set-up)" IN_LIST seen)
    message(FATAL_ERROR "${prog}: no neighbour search in the set-up's profile:\n${json}")
  endif()
  if(prog STREQUAL "emulated")
    list(FILTER seen INCLUDE REGEX "_monitor \\(outside\\)$")
    if(NOT seen)
      message(FATAL_ERROR "emulated: no monitor pass outside the steps:\n${json}")
    endif()
  endif()
  # (at most the steps' time: the passes do not overlap; and most of it, but a short run on
  # a busy machine spends a share of its steps descheduled between the passes: 0.25 of it
  # was seen, so only a fifth is asked)
  execute_process(COMMAND awk "BEGIN { t = ${total}; s = ${step_time};
                               print (t <= s * (1 + 1e-9) && t >= 0.2 * s) ? \"ok\" : \"bad\" }"
                  OUTPUT_VARIABLE verdict OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT verdict STREQUAL "ok")
    message(FATAL_ERROR "${prog}: the passes took ${total} s of the steps' ${step_time} s")
  endif()
  # The set-up's stages do not overlap: they add up to at most its time, and the table
  # shows the rest.
  string(JSON setup_time GET "${json}" setup_time)
  execute_process(COMMAND awk "BEGIN { t = ${setup_total}; s = ${setup_time};
                               print (t <= s * (1 + 1e-9)) ? \"ok\" : \"bad\" }"
                  OUTPUT_VARIABLE verdict OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT verdict STREQUAL "ok" OR NOT out MATCHES "\\(the rest: start, copies, other\\)")
    message(FATAL_ERROR "${prog}: the set-up's stages took ${setup_total} s of its "
                        "${setup_time} s, or no rest in its table:\n${out}")
  endif()
  message(STATUS "${prog}: ${n} passes profiled over ${steps} steps")
endfunction()

foreach(prog cpu emulated)
  execute_process(COMMAND ${${prog}} --quiet --threads 1 --end ${END} --profile
                          --out ${WORKDIR}/${prog}_out
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # 1: an expectation of the model failed (short run)
    message(FATAL_ERROR "${prog} failed (exit ${rc}):\n${out}\n${err}")
  endif()
  check_profile(${prog} ${WORKDIR}/${prog}_out "${out}")
endforeach()

execute_process(COMMAND ${cpu} --quiet --threads 1 --end ${END} --out ${WORKDIR}/plain_out
                RESULT_VARIABLE rc OUTPUT_VARIABLE out)
file(READ ${WORKDIR}/plain_out/summary.json json)
if(json MATCHES "\"profile\"" OR out MATCHES "steps, [0-9.]+ s \\(per step")
  message(FATAL_ERROR "a profile without --profile:\n${out}")
endif()
