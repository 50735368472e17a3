# Builds a model for both targets (included by run_cuda_emulated*.cmake):
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= [-DDEFINE=NAME[,NAME...]]
# Sets `stem`, the model's name, `cpu`, the CPU program, and `emulated`, the CUDA target's
# model.cu (WORKDIR/STEM.cu) compiled by the host C++ compiler with SPH_CUDA_EMULATE
# (runtime/cuda/emulate.h): the device passes run serially on host memory.  Both programs are
# named for the model.  With EMIT_ONLY set, only model.cu is written.  DEFINE: a macro the
# emulated build defines too (SPH_CUDA_RECOMPUTE: the pair gradients from the positions).

# sph_emulated_compile(OUT SOURCE [FLAGS...]): SOURCE (C++ including a model.cu) into the
# program OUT, as the emulated build compiles it, warning-free.
function(sph_emulated_compile out source)
  execute_process(COMMAND ${CXX} -std=c++20 -O2 -DSPH_CUDA_EMULATE -fopenmp -Wall -Wextra -Werror
                          ${ARGN} -I${INCLUDE} -x c++ ${source} -x none ${LIB} -lm -o ${out}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the emulated build of ${source} failed:\n${log}\n${err}")
  endif()
endfunction()

get_filename_component(stem ${MODEL} NAME_WE)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR}/cpu_program ${WORKDIR}/emulated_program)
execute_process(COMMAND ${SPHC} --target cuda --emit-c ${WORKDIR} --emit-only -o ${stem} ${MODEL}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --target cuda failed:\n${err}")
endif()
if(NOT EMIT_ONLY)
  set(cpu ${WORKDIR}/cpu_program/${stem})
  set(emulated ${WORKDIR}/emulated_program/${stem})
  execute_process(COMMAND ${SPHC} -o ${cpu} ${MODEL} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc (cpu) failed:\n${err}")
  endif()
  set(defines "") # (macros given as NAME,NAME)
  string(REPLACE "," ";" names "${DEFINE}")
  foreach(name ${names})
    list(APPEND defines -D${name})
  endforeach()
  sph_emulated_compile(${emulated} ${WORKDIR}/${stem}.cu ${defines})
endif()
