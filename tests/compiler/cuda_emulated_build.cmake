# Builds a model for both targets (included by run_cuda_emulated*.cmake):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR=
# Sets `stem`, the model's name, `cpu`, the CPU program, and `emulated`, the CUDA target's
# model.cu compiled by the host C++ compiler with SPH_CUDA_EMULATE (runtime/sph_cuda.h): the
# device passes run serially on host memory.  Both programs are named for the model.
get_filename_component(stem ${MODEL} NAME_WE)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR}/cpu_program ${WORKDIR}/emulated_program)
set(cpu ${WORKDIR}/cpu_program/${stem})
set(emulated ${WORKDIR}/emulated_program/${stem})
execute_process(COMMAND ${SPHC} -o ${cpu} ${MODEL} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc (cpu) failed:\n${err}")
endif()
execute_process(COMMAND ${SPHC} --target cuda --emit-c ${WORKDIR} --emit-only -o ${stem} ${MODEL}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --target cuda failed:\n${err}")
endif()
execute_process(COMMAND ${CXX} -std=c++20 -O2 -DSPH_CUDA_EMULATE -fopenmp -Wall -Wextra -Werror
                        -I${INCLUDE} -x c++ ${WORKDIR}/${stem}.cu -x none ${LIB} -lm
                        -o ${emulated}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the emulated CUDA build failed:\n${out}\n${err}")
endif()
