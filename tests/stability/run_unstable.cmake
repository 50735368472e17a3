# A run that goes unstable must be stopped by the stability monitor:
#   -DPROGRAM= -DOUT=        the generated program and its output folder
#   -DARGS=a,b               more options for the program (comma-separated)
#   -DBODY=                  the body the message must name
#   -DQUANTITY=              a regular expression the finding (after "...):") must match
#   -DMAX_STEP=              the step it must have been stopped at, at the latest
#   -DMIN_FRAMES=            frames (t = 0 included) that must have been written before
#   -DWARNING=ON|OFF         whether the fixed-dt warning must be printed before the run
#   -DNOT_FINITE=ON          the state at the stop is not finite: summary.json must give the
#                            body's largest speed as null (not the largest finite one)
#   -DNOTE=                  a text stderr must hold after the error (a hint)
# Checked: exit code 3; the message on stderr names step, time, body, particle and the
# quantity; summary.json says "unstable" with the same message; the .pvd and its frames
# exist; energies.csv and the measurement files have rows and no NaN or infinity.
function(fail what)
  message(FATAL_ERROR "${what}\n--- stdout:\n${out}\n--- stderr:\n${err}")
endfunction()

string(REPLACE "," ";" ARGS "${ARGS}")
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PROGRAM} --quiet --out ${OUT} ${ARGS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit code ${rc}; stderr:\n${err}")
if(NOT rc EQUAL 3)
  fail("expected exit code 3 (unstable), got ${rc}")
endif()
if(DEFINED NOTE)
  string(FIND "${err}" "${NOTE}" note_at)
  if(note_at EQUAL -1)
    fail("stderr does not hold '${NOTE}'")
  endif()
endif()

# the warning about a fixed time step above h/c0, printed before the run
string(FIND "${err}" "warning: the fixed time step" warn_at)
string(FIND "${err}" "error: the run went unstable" err_at)
if(WARNING AND (warn_at EQUAL -1 OR warn_at GREATER err_at))
  fail("the fixed-dt warning is missing (or comes after the error)")
elseif(NOT WARNING AND NOT warn_at EQUAL -1)
  fail("unexpected fixed-dt warning")
endif()

# step, time, body, particle, quantity
set(num "[-+0-9.eE]+")
if(NOT err MATCHES "error: the run went unstable at (step ([0-9]+), t = (${num}) s, body '([A-Za-z0-9_]+)', particle ([0-9]+) \\(reference position x = ${num}, [yz] = ${num}\\): ([^\n]*))\n")
  fail("the error message does not name step, time, body, particle and quantity")
endif()
set(message "${CMAKE_MATCH_1}")
set(step ${CMAKE_MATCH_2})
set(time ${CMAKE_MATCH_3})
set(body ${CMAKE_MATCH_4})
set(finding "${CMAKE_MATCH_6}")
if(NOT body STREQUAL BODY)
  fail("the message names body '${body}', expected '${BODY}'")
endif()
if(NOT finding MATCHES "${QUANTITY}")
  fail("the finding '${finding}' does not match '${QUANTITY}'")
endif()
if(step GREATER MAX_STEP)
  fail("stopped only at step ${step} (at most ${MAX_STEP})")
endif()
message(STATUS "stopped at step ${step}, t = ${time} s: ${finding}")

# summary.json
file(READ ${OUT}/summary.json summary)
if(NOT summary MATCHES "\"verdict\": \"unstable\"")
  fail("summary.json does not say \"verdict\": \"unstable\"")
endif()
string(FIND "${summary}" "\"message\": \"${message}\"" at)
if(at EQUAL -1)
  fail("summary.json does not carry the message")
endif()
if(NOT summary MATCHES "\"steps\": ${step},")
  fail("summary.json does not give the step count ${step}")
endif()
if(NOT_FINITE AND NOT summary MATCHES "\"max_velocity\": null")
  fail("summary.json gives a finite largest speed for a state that is not finite")
endif()

# the last good output: the pvd lists frames that all exist, at least MIN_FRAMES of them
file(READ ${OUT}/particles/${BODY}.pvd pvd)
string(REGEX MATCHALL "file=\"[^\"]+\"" frames "${pvd}")
list(LENGTH frames nframes)
if(nframes LESS MIN_FRAMES)
  fail("the pvd lists ${nframes} frames, expected at least ${MIN_FRAMES}")
endif()
foreach(f ${frames})
  string(REGEX REPLACE "file=\"([^\"]+)\"" "\\1" f "${f}")
  if(NOT EXISTS ${OUT}/particles/${f})
    fail("frame ${f} listed in the pvd is missing")
  endif()
endforeach()
if(NOT EXISTS ${OUT}/particles/${BODY}_0000.vtu)
  fail("the first frame ${BODY}_0000.vtu is missing")
endif()

# CSV files: a header and one row per frame, every number finite
file(GLOB csvs ${OUT}/*.csv)
foreach(csv ${csvs})
  file(STRINGS ${csv} lines)
  list(LENGTH lines n)
  math(EXPR rows "${n} - 1")
  if(NOT rows EQUAL nframes)
    fail("${csv} has ${rows} rows for ${nframes} frames")
  endif()
  list(REMOVE_AT lines 0)
  foreach(line ${lines})
    string(TOLOWER "${line}" line)
    if(line MATCHES "nan|inf")
      fail("${csv} has a value that is not finite: ${line}")
    endif()
  endforeach()
  message(STATUS "${csv}: ${rows} rows, all finite")
endforeach()
