# sph_sim_advance on the device's clock (tests/compiler/advance_emulated.cpp):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DSOURCE=
set(EMIT_ONLY ON)
include(${CMAKE_CURRENT_LIST_DIR}/cuda_emulated_build.cmake)
sph_emulated_compile(${WORKDIR}/advance ${SOURCE} "-DMODEL_CU=\"${WORKDIR}/${stem}.cu\"")
execute_process(COMMAND ${WORKDIR}/advance RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "advance_emulated failed (exit ${rc})")
endif()
