# The CUDA target's generated code, checked without a GPU:
#   -DSPHC= -DMODEL= -DNVCC= -DINCLUDE= -DWORKDIR= [-DDEFINE=NAME[,NAME...]] [-DMPI=ON]
# `sphc --target cuda --emit-only` writes model.cu, which nvcc must compile warning-free
# (-Werror all-warnings; host code -Wall -Wextra) for sm_90 and sm_80, with the macros DEFINE
# defined when it is given (SPH_CUDA_RECOMPUTE); with MPI, the program for many processes
# (sphc --mpi: its halo exchanges staged through the host).  A model using what the
# target does not run yet must be refused with a clear "does not support yet" error instead.
get_filename_component(stem ${MODEL} NAME_WE)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
set(mpi "")
if(MPI)
  set(mpi --mpi)
endif()
execute_process(COMMAND ${SPHC} --target cuda ${mpi} --emit-c ${WORKDIR} --emit-only -o ${stem}
                        ${MODEL}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  if(err MATCHES "not supported by the cuda target yet|which the cuda target does not support yet")
    string(REGEX MATCH "error: [^\n]*" first "${err}")
    message(STATUS "${stem}: refused as expected: ${first}")
    return()
  endif()
  message(FATAL_ERROR "sphc --target cuda failed on ${MODEL}:\n${err}")
endif()
set(defines "") # (macros given as NAME,NAME)
string(REPLACE "," ";" names "${DEFINE}")
foreach(name ${names})
  list(APPEND defines -D${name})
endforeach()
execute_process(COMMAND ${NVCC} -std=c++20 --extended-lambda -O3 ${defines}
                        -gencode arch=compute_90,code=sm_90 -gencode arch=compute_80,code=sm_80
                        -Werror all-warnings -Xcompiler -fopenmp,-Wall,-Wextra,-Werror
                        -I${INCLUDE} -c ${WORKDIR}/${stem}.cu -o ${WORKDIR}/${stem}.o
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nvcc failed on ${WORKDIR}/${stem}.cu:\n${out}\n${err}")
endif()
message(STATUS "${stem}.cu compiles for sm_90 and sm_80")
