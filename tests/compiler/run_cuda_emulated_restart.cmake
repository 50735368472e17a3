# Checkpoints of the CUDA target (SPH_CUDA_EMULATE, runtime/cuda/emulate.h):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DEND= -DMID=
# The emulated program resumed from its own checkpoint writes exactly what its whole run
# writes (tests/physics/run_restart.cmake, on the device state the checkpoint copies both
# ways), and the CPU program resumes from the same checkpoint (the state arrays are laid out
# alike on both targets) and ends with the same total energy to 1e-6.
include(${CMAKE_CURRENT_LIST_DIR}/cuda_emulated_build.cmake)
set(PROGRAM ${emulated})
set(OUT ${WORKDIR}/restart)
include(${CMAKE_CURRENT_LIST_DIR}/../physics/run_restart.cmake)
file(REMOVE_RECURSE ${WORKDIR}/on_cpu) # the part run's folder, resumed there on the CPU
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_directory ${OUT}/part ${WORKDIR}/on_cpu)
execute_process(COMMAND ${cpu} --quiet --threads 1 --end ${END}
                        --restart ${WORKDIR}/on_cpu/checkpoint.bin
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 AND NOT rc EQUAL 1)
  message(FATAL_ERROR "the CPU program resumed from the device's checkpoint: exit ${rc}\n${err}")
endif()
file(STRINGS ${OUT}/whole/energies.csv a)
file(STRINGS ${WORKDIR}/on_cpu/energies.csv b)
list(LENGTH a na)
list(LENGTH b nb)
list(GET a -1 la)
list(GET b -1 lb)
string(REGEX MATCH "[^,]+$" ea "${la}")
string(REGEX MATCH "[^,]+$" eb "${lb}")
execute_process(COMMAND awk "BEGIN { d = ${ea} - ${eb}; if (d < 0) d = -d; m = ${ea} < 0 ? -${ea} : ${ea};
                             print (d <= 1e-6 * m) ? \"ok\" : \"bad\" }"
                OUTPUT_VARIABLE verdict OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT na EQUAL nb OR NOT verdict STREQUAL "ok")
  message(FATAL_ERROR "resumed on the CPU: ${nb} energy rows ending in a total of ${eb}; the "
                      "device's whole run: ${na} rows, ${ea}")
endif()
message(STATUS "resumed on the CPU from the device's checkpoint: total energy ${eb} (device ${ea})")
