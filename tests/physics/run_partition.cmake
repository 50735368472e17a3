# `--partition N` reports each body's decomposition for N processes and exits without
# running (docs/mpi.md): -DPROGRAM= (the coarse beam).  Its parts hold the body's particles
# within 5 % of one another; more parts than particles is said; N = 0 is a bad option.
function(report n expect)
  execute_process(COMMAND ${PROGRAM} --partition ${n} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${expect}")
    message(FATAL_ERROR "--partition ${n}: exit ${rc}, output:\n${out}${err}\nexpected: ${expect}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
report(3 "body beam: ([0-9]+) particles in 3 parts: [0-9]+ to [0-9]+ a part \\(mean [0-9.]+, balance [0-4]\\.[0-9][0-9] %\\), halo [0-9.]+ a part \\(most [0-9]+\\), halo / own [0-9.]+ %")
report(7 "in 7 parts: .*balance [0-4]\\.[0-9][0-9] %")
report(100000 "of the 100000 parts hold no particle")
execute_process(COMMAND ${PROGRAM} --partition 0 RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "--partition 0: exit ${rc}, expected 2 (a bad option)")
endif()
message(STATUS "--partition reports")
