# run_mpi_emit.cmake — sphc --mpi: the program's main() enters the runtime for many processes
# (sph_mpi_main), and the same model without --mpi holds nothing of MPI; with the CUDA target
# its passes exchange the halo (sph_cuda_halo).  Only the source is written, so neither MPI
# nor its runtime is needed.
#
#   cmake -DSPHC=sphc -DMODEL=model.sph -DWORKDIR=dir [-DCC=cc -DINCLUDE=runtime]
#         -P run_mpi_emit.cmake
# With CC, the code for many processes must also compile with -Wall -Wextra -Werror.

get_filename_component(stem ${MODEL} NAME_WE)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})

# The model's source with the options given, read into `var`.
function(emit var dir)
  execute_process(COMMAND ${SPHC} ${ARGN} --emit-c ${WORKDIR}/${dir} --emit-only ${MODEL}
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc ${ARGN} --emit-only ${MODEL} failed (${rc}):\n${err}")
  endif()
  file(READ ${WORKDIR}/${dir}/${stem}.c code)
  set(${var} "${code}" PARENT_SCOPE)
endfunction()

emit(mpi mpi --mpi)
string(FIND "${mpi}" "sph_mpi_main(" at)
if(at EQUAL -1)
  message(FATAL_ERROR "sphc --mpi: main() does not call sph_mpi_main in ${WORKDIR}/mpi/${stem}.c")
endif()

emit(one one)
foreach(word sph_mpi_main MPI sph_halo)
  string(FIND "${one}" "${word}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "'${word}' appears in ${WORKDIR}/one/${stem}.c, built without --mpi")
  endif()
endforeach()

# the CUDA target for many processes: its passes stage the halo through the host
execute_process(COMMAND ${SPHC} --mpi --target cuda --emit-c ${WORKDIR}/cuda --emit-only ${MODEL}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --mpi --target cuda --emit-only failed (${rc}):\n${err}")
endif()
file(READ ${WORKDIR}/cuda/${stem}.cu cuda)
foreach(word "sph_mpi_main(" "sph_cuda_halo(")
  string(FIND "${cuda}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "sphc --mpi --target cuda: no '${word}' in ${WORKDIR}/cuda/${stem}.cu")
  endif()
endforeach()

if(CC)
  execute_process(COMMAND ${CC} -std=c11 -O1 -fopenmp -Wall -Wextra -Werror -I${INCLUDE}
                          -c ${WORKDIR}/mpi/${stem}.c -o ${WORKDIR}/mpi/${stem}.o
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the code of ${stem} for many processes does not compile warning-free:\n"
                        "${err}")
  endif()
endif()
