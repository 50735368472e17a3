# run_template_errors.cmake — a template with a mark the emitter cannot fill is an error
# naming the template's file and line, never a block dropped or a key left in the output.
#
#   cmake -DSPHC=path/to/sphc -DSOURCE=project/dir -DMODEL=m.sph -DWORKDIR=dir -P run_template_errors.cmake
#
# For each broken template: an installation under WORKDIR (SPHC_HOME) whose body_forces.c
# ends with the broken mark; sphc must fail with the expected message.

foreach(var SPHC SOURCE MODEL WORKDIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_template_errors.cmake: -D${var}=... is required")
  endif()
endforeach()

# mark|message|the line it names, counted from the mark's first (- : none)
set(cases
  "//@if NO_SUCH_SWITCH\n//@endif\n|unknown switch 'NO_SUCH_SWITCH'|0"
  "static int @NO_SUCH_KEY@ = 0\n|no value for @NO_SUCH_KEY@|0"
  "//@else\n|unexpected '//@else'|0"
  "//@if VISCOSITY\n//@else\n//@else\n//@endif\n|unexpected '//@else'|2"
  "//@endif\n|unexpected '//@endif'|0"
  "//@if VISCOSITY\n|1 //@if without //@endif|-")
file(READ "${SOURCE}/templates/body_forces.c" text)
string(REGEX REPLACE "[^\n]" "" newlines "${text}")
string(LENGTH "${newlines}" nlines)
math(EXPR first "${nlines} + 1") # the first line of the broken mark
set(k 0)
foreach(c ${cases})
  string(REPLACE "|" ";" c "${c}")
  list(GET c 0 mark)
  list(GET c 1 expected)
  list(GET c 2 offset)
  string(REPLACE "\\n" "\n" mark "${mark}")
  set(home ${WORKDIR}/home${k})
  file(REMOVE_RECURSE ${home})
  file(COPY ${SOURCE}/templates/ DESTINATION ${home}/share/sphc/templates)
  file(COPY ${SOURCE}/stdlib/ DESTINATION ${home}/share/sphc/stdlib)
  file(APPEND ${home}/share/sphc/templates/body_forces.c "${mark}")
  execute_process(COMMAND ${CMAKE_COMMAND} -E env SPHC_HOME=${home}
                          ${SPHC} --emit-c ${home}/out --emit-only ${MODEL}
                  RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_VARIABLE out)
  if(status EQUAL 0 OR NOT status MATCHES "^[0-9]+$")
    message(FATAL_ERROR "a template ending with '${mark}': sphc exited with '${status}', "
                        "expected an error\n${err}")
  endif()
  if(NOT err MATCHES "template '[^']*body_forces.c'" OR NOT err MATCHES "${expected}")
    message(FATAL_ERROR "a template ending with '${mark}': expected '${expected}' naming "
                        "body_forces.c, got:\n${err}")
  endif()
  if(NOT offset STREQUAL "-")
    math(EXPR line "${first} + ${offset}")
    if(NOT err MATCHES "line ${line}:")
      message(FATAL_ERROR "a template ending with '${mark}': expected line ${line}, got:\n${err}")
    endif()
  endif()
  math(EXPR k "${k} + 1")
endforeach()
message(STATUS "${k} broken templates refused")
