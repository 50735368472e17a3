# The CUDA target on many processes, checked without a GPU: the model's model.cu for many
# processes (sphc --mpi --target cuda) compiled by MPI's C++ wrapper with SPH_CUDA_EMULATE
# (runtime/cuda/emulate.h: the device passes run serially on host memory, cudaMemcpy a copy), so
# that the device's halo exchange (packed on the device, staged through the host) and its
# host-chosen time steps run as on GPUs; then run_ranks.cmake against the serial CPU program
# on 1 to 3 processes.
#   -DSPHC= -DMPICXX= -DMODEL= -DINCLUDE= -DLIBS= (;-list: libsphrt_mpi.a;libsphrt.a) and
#   run_ranks.cmake's variables but PROGRAM; -DDEVICE_BUFFERS=ON: the MPI library given the
#   device's buffers (SPH_MPI_DEVICE_BUFFERS=1, as a CUDA-aware one would be)
get_filename_component(stem ${MODEL} NAME_WE)
set(work ${OUT}_build)
file(REMOVE_RECURSE ${work})
file(MAKE_DIRECTORY ${work})
execute_process(COMMAND ${SPHC} --mpi --target cuda --emit-c ${work} --emit-only ${MODEL}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --mpi --target cuda failed:\n${err}")
endif()
set(PROGRAM ${work}/${stem}_emulated)
execute_process(COMMAND ${MPICXX} -std=c++20 -O2 -DSPH_CUDA_EMULATE -fopenmp -Wall -Wextra
                        -Werror -I${INCLUDE} -x c++ ${work}/${stem}.cu -x none ${LIBS} -lm
                        -o ${PROGRAM}
                RESULT_VARIABLE rc OUTPUT_VARIABLE log ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the emulated build of ${stem}.cu for many processes failed:\n${log}\n${err}")
endif()
set(INEXACT ON)
if(DEVICE_BUFFERS)
  set(ENV{SPH_MPI_DEVICE_BUFFERS} 1) # (the emulated device's buffers are host memory)
endif()
include(${CMAKE_CURRENT_LIST_DIR}/run_ranks.cmake)
if(DEVICE_BUFFERS) # the halo went from "device" buffer to "device" buffer
  file(READ ${OUT}/np2/summary.json summary)
  if(NOT summary MATCHES "\"device_buffers\": 1")
    message(FATAL_ERROR "2 processes with SPH_MPI_DEVICE_BUFFERS=1: the summary does not say "
                        "device_buffers 1")
  endif()
  message(STATUS "2 processes: the halo exchanged from the device's buffers")
endif()
