# run_regression.cmake — one input that once crashed or hung a fuzz target, through the
# ordinary sphc.
#
#   cmake -DSPHC=path/to/sphc -DINPUT=file -DSOURCE=repo -DWORK=dir -P run_regression.cmake
#
# In WORK, beside links to the surface and CSV files the cases and tests name (as the fuzz
# targets have them, fuzz/fuzz_run.c), the input is read as input.sph and as input.xml (with
# the default readings, then --xml-elastic2d=sdsph --xml-fill=gencase) by `sphc --check`:
# each run must end with status 0 or 1 within 60 s.

foreach(var SPHC INPUT SOURCE WORK)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_regression.cmake: -D${var}=... is required")
  endif()
endforeach()

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
foreach(folder cases cases/xml tests/xml/good tests/xml/bad tests/physics)
  file(GLOB data "${SOURCE}/${folder}/*.vtk" "${SOURCE}/${folder}/*.stl"
                 "${SOURCE}/${folder}/*.csv")
  foreach(f ${data})
    get_filename_component(n "${f}" NAME)
    if(NOT EXISTS "${WORK}/${n}")
      file(CREATE_LINK "${f}" "${WORK}/${n}" SYMBOLIC)
    endif()
  endforeach()
endforeach()

set(failures "")
foreach(run "sph" "xml" "xml;--xml-elastic2d=sdsph;--xml-fill=gencase")
  list(GET run 0 ext)
  set(options ${run})
  list(REMOVE_AT options 0)
  configure_file("${INPUT}" "${WORK}/input.${ext}" COPYONLY)
  execute_process(
    COMMAND "${SPHC}" --check ${options} "input.${ext}"
    WORKING_DIRECTORY "${WORK}"
    TIMEOUT 60
    RESULT_VARIABLE status
    OUTPUT_QUIET
    ERROR_VARIABLE err)
  if(NOT status MATCHES "^[01]$")
    string(LENGTH "${err}" n)
    if(n GREATER 4000)
      math(EXPR from "${n} - 4000")
      string(SUBSTRING "${err}" ${from} 4000 err)
    endif()
    string(APPEND failures "sphc --check ${options} input.${ext}: ${status}\n${err}\n")
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "${INPUT} (in ${WORK}):\n${failures}")
endif()
