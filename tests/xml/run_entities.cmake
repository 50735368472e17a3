# run_entities.cmake — a hostile case file is refused at once, with a short message.
#
#   cmake -DSPHC=sphc -DXML=case.xml | -DBIG=attr|text -DWORKDIR=dir  -DEXPECTED="text"
#         [-DARGS=--to-sph] [-DABSENT="text"] -P run_entities.cmake
#
# With -DBIG, writes WORKDIR/entity_big_BIG.xml first: an entity of 100 000 bytes used 20 000
# times (2 GB of text) in an attribute value or in an element's text.  Runs `sphc ARGS
# file` (default --check) in the file's folder and requires a non-zero exit status within
# 10 s, EXPECTED in stderr, at most 2000 bytes of output, and ABSENT nowhere in it.

foreach(var SPHC EXPECTED)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_entities.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED ARGS)
  set(ARGS --check)
endif()

if(DEFINED BIG)
  file(READ "${CMAKE_CURRENT_LIST_DIR}/bad/bad_number.xml" text)
  string(REPLACE "2.1e11x" "2.1e11" text "${text}")
  string(REPEAT "x" 100000 big)
  string(REPLACE "<case>" "<!DOCTYPE case [\n<!ENTITY big \"${big}\">\n]>\n<case>" text
         "${text}")
  string(REPEAT "&big;" 20000 uses)
  if(BIG STREQUAL "attr")
    string(REPLACE "<youngmod value=\"2.1e11\" />" "<youngmod value=\"${uses}\" />" text
           "${text}")
  else()
    string(REPLACE "<boxfill>solid</boxfill>" "<boxfill>${uses}</boxfill>" text "${text}")
  endif()
  file(MAKE_DIRECTORY "${WORKDIR}")
  set(XML "${WORKDIR}/entity_big_${BIG}.xml")
  file(WRITE "${XML}" "${text}")
endif()

get_filename_component(dir "${XML}" DIRECTORY)
get_filename_component(name "${XML}" NAME)
execute_process(COMMAND "${SPHC}" ${ARGS} "${name}" WORKING_DIRECTORY "${dir}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 10)
string(LENGTH "${out}${err}" size)
if(size GREATER 2000)
  string(SUBSTRING "${err}" 0 2000 err)
  message(FATAL_ERROR "sphc ${ARGS} ${name} (exit ${rc}) wrote ${size} bytes:\n${err}")
endif()
if(rc EQUAL 0 OR NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "sphc ${ARGS} ${name}: exit '${rc}', a refusal was expected:\n${err}")
endif()
string(FIND "${err}" "${EXPECTED}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "sphc ${ARGS} ${name} does not say '${EXPECTED}':\n${err}")
endif()
if(DEFINED ABSENT)
  string(FIND "${out}${err}" "${ABSENT}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "sphc ${ARGS} ${name} prints '${ABSENT}':\n${out}${err}")
  endif()
endif()
message(STATUS "${name}: exit ${rc}, ${size} bytes of output")
