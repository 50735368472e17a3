# run_layouts.cmake — the layout of each pair pass is a decision the compiler makes and says:
# `sphc --dump=plan MODEL` must print each line of EXPECT (a list, ';'-separated).
#   cmake -DSPHC= -DMODEL= "-DEXPECT=line;line" -P run_layouts.cmake
execute_process(COMMAND ${SPHC} --dump=plan ${MODEL} OUTPUT_VARIABLE dump
                ERROR_VARIABLE err RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --dump=plan failed on ${MODEL}:\n${err}")
endif()
foreach(line IN LISTS EXPECT)
  string(FIND "${dump}" "\n  ${line}\n" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "'${line}' is not a line of the dump of ${MODEL}:\n${dump}")
  endif()
endforeach()
message(STATUS "the dump of ${MODEL} says each pass's layout")
