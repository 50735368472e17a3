# References from CSV files (reference2d.sph): -DPROGRAM= -DOUT=
# The run must pass its two references within 1 % (exit code 0), and report for the table
# that is 10 % too large a relative error of 1 - 1/1.1 = 9.09 % (within 0.5 %: the
# integrator's own error is about 0.3 %).
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PROGRAM} --quiet --out ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit code ${rc} (expected 0):\n${out}\n${err}")
endif()
file(READ ${OUT}/summary.json summary)
string(REGEX MATCHALL "\"relative_error\": [0-9.e+-]+" errors "${summary}")
list(LENGTH errors n)
if(NOT n EQUAL 3)
  message(FATAL_ERROR "expected 3 reference errors in summary.json, found ${n}:\n${summary}")
endif()
list(GET errors 2 last)
string(REGEX REPLACE ".*: " "" last "${last}")
if(last LESS 0.0859 OR last GREATER 0.0959)
  message(FATAL_ERROR "the 10 % table's relative error is ${last}, expected 0.0909 +- 0.005")
endif()
message(STATUS "references: ${errors}")
# Without --quiet the final line gives them too, with the run time.
execute_process(COMMAND ${PROGRAM} --overwrite --out ${OUT} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT out MATCHES "steps to t = [^\n]* s in [0-9.]+ s \\([0-9.]+ ns per particle-step\\); errors: reference [0-9.e+-]+ %, reference [0-9.e+-]+ %, reference [0-9.e+-]+ %\n")
  message(FATAL_ERROR "the final line does not give the run time and the three errors:\n${out}")
endif()
message(STATUS "final line gives the errors")
