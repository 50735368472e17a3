# run_dump.cmake — `sphc ARGS --dump=STAGE FILE` prints the expected texts.
#
#   cmake -DSPHC=sphc -DFILE=case.xml [-DARGS="--xml-elastic2d=sdsph"] [-DSTAGE=model]
#         -DCONTAINS="text|text" [-DABSENT="text|text"] -P run_dump.cmake

foreach(var SPHC FILE CONTAINS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_dump.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED STAGE)
  set(STAGE model)
endif()
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND "${SPHC}" ${args} --dump=${STAGE} "${FILE}" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc ${ARGS} --dump=${STAGE} ${FILE} failed (exit ${rc}):\n${err}")
endif()
string(REPLACE "|" ";" wanted "${CONTAINS}")
foreach(text IN LISTS wanted)
  string(FIND "${out}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "sphc ${ARGS} --dump=${STAGE} ${FILE} does not print '${text}':\n${out}")
  endif()
endforeach()
string(REPLACE "|" ";" unwanted "${ABSENT}")
foreach(text IN LISTS unwanted)
  string(FIND "${out}" "${text}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "sphc ${ARGS} --dump=${STAGE} ${FILE} prints '${text}':\n${out}")
  endif()
endforeach()
message(STATUS "sphc ${ARGS} --dump=${STAGE}: ${CONTAINS}")
