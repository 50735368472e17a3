# --every and --frames: -DPROGRAM= -DOUT=
# The run writes a row of energies at every output (--every 1e-4 over 1e-3 s: t = 0 and ten
# more) and particle files only every --frames 4e-4 s (at t = 0, 4e-4 and 8e-4 s: three
# frames of each of the model's three bodies, also listed in each body's .pvd).
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${PROGRAM} --quiet --out ${OUT} --end 1e-3 --every 1e-4 --frames 4e-4
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit code ${rc} (expected 0); stderr:\n${err}")
endif()
file(STRINGS ${OUT}/energies.csv rows)
list(LENGTH rows nrows)
if(NOT nrows EQUAL 12) # header + 11 output times
  message(FATAL_ERROR "energies.csv has ${nrows} lines (expected 12: a header and 11 rows)")
endif()
file(GLOB frames ${OUT}/particles/*.vtu)
list(LENGTH frames nframes)
if(NOT nframes EQUAL 9)
  message(FATAL_ERROR "${nframes} particle files (expected 9: 3 bodies at t = 0, 4e-4, 8e-4 s)")
endif()
file(READ ${OUT}/particles/nu045.pvd pvd)
string(REGEX MATCHALL "timestep=" sets "${pvd}")
list(LENGTH sets nsets)
if(NOT nsets EQUAL 3)
  message(FATAL_ERROR "the .pvd lists ${nsets} frames (expected 3)")
endif()
message(STATUS "11 output rows, 3 frames")
