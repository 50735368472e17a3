# run_dump.cmake — a golden of `sphc --dump=plan`:
#   cmake -DSPHC= -DMODEL= -DGOLDEN= [-DPRESENT="a;b"] -P run_dump.cmake
# The dump's lines that do not print the law's graph (those indented by four spaces: the
# body, its features, how its law gets its stress and the operations it takes) must equal
# the golden file; each PRESENT string must appear in the whole dump.
execute_process(COMMAND ${SPHC} --dump=plan ${MODEL} OUTPUT_VARIABLE dump
                ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --dump=plan failed on ${MODEL}:\n${err}")
endif()
string(REGEX REPLACE "\n    [^\n]*" "" summary "${dump}") # the first line is a body's
file(READ ${GOLDEN} golden)
if(NOT summary STREQUAL golden)
  message(FATAL_ERROR "the dump of ${MODEL} differs from ${GOLDEN}:\n--- got\n${summary}--- expected\n${golden}")
endif()
foreach(word IN LISTS PRESENT)
  string(FIND "${dump}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "'${word}' must appear in the dump of ${MODEL}")
  endif()
endforeach()
message(STATUS "the dump's summary equals ${GOLDEN}")
