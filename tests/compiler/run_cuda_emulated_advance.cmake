# sph_sim_advance on the device's clock (tests/compiler/advance_emulated.cpp):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DSOURCE=
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${SPHC} --target cuda --emit-c ${WORKDIR} --emit-only -o model ${MODEL}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --target cuda failed:\n${err}")
endif()
execute_process(COMMAND ${CXX} -std=c++20 -O2 -DSPH_CUDA_EMULATE -fopenmp -Wall -Wextra -Werror
                        "-DMODEL_CU=\"${WORKDIR}/model.cu\"" -I${INCLUDE} ${SOURCE} ${LIB} -lm
                        -o ${WORKDIR}/advance
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the build failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${WORKDIR}/advance RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "advance_emulated failed (exit ${rc})")
endif()
