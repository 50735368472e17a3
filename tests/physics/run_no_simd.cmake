# A model built as sphc builds it (vector code: the stress pass and the update vectorised
# across particles, the pair passes on the lattice stencil or the offset blocks where they
# apply) and with --no-simd (scalar code, the pair passes on the half lists) gives the same
# run within round-off: the vector loops sum in another order, and glibc's vector exp, log
# and pow differ from the scalar ones in the last bits.
# -DSPHC= -DMODEL= -DOUT= -DEND= [-DTOL=1e-9] [-DARGS=] [-DCOARSEN="dp A|dp B"]
# With COARSEN, the model's text with its first A replaced by B (a coarser spacing), in OUT
# (a model that imports the standard library only).  Both programs run to END on one thread; every value of energies.csv must
# agree within TOL of the row's largest energy, and the scalar program's summary.json must
# show no particle in a stencil's runs and no pair in offset blocks.
include(${CMAKE_CURRENT_LIST_DIR}/compare_runs.cmake) # (TOL's default)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(model ${MODEL})
if(COARSEN)
  string(REPLACE "|" ";" swap "${COARSEN}")
  list(GET swap 0 from)
  list(GET swap 1 to)
  file(READ ${MODEL} text)
  string(FIND "${text}" "${from}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "'${from}' is not in ${MODEL}")
  endif()
  string(SUBSTRING "${text}" 0 ${at} head)
  string(LENGTH "${from}" n)
  math(EXPR rest "${at} + ${n}")
  string(SUBSTRING "${text}" ${rest} -1 tail)
  get_filename_component(name ${MODEL} NAME)
  set(model ${OUT}/${name})
  file(WRITE ${model} "${head}${to}${tail}")
endif()
build_model(${model} ${OUT}/vector)
build_model(${model} ${OUT}/scalar --no-simd)
separate_arguments(args UNIX_COMMAND "${ARGS}")
run_model(${OUT}/vector ${OUT}/vector_out ${args})
run_model(${OUT}/scalar ${OUT}/scalar_out ${args})
file(READ ${OUT}/scalar_out/summary.json json)
string(JSON nbodies LENGTH "${json}" bodies)
math(EXPR last "${nbodies} - 1")
foreach(k RANGE ${last})
  foreach(what stencil_particles offset_block_pairs momentum_block_pairs)
    string(JSON used ERROR_VARIABLE none GET "${json}" bodies ${k} ${what})
    if(NOT none AND NOT used EQUAL 0)
      message(FATAL_ERROR "--no-simd: body ${k} has ${used} ${what}")
    endif()
  endforeach()
endforeach()
near_energies(${OUT}/vector_out ${OUT}/scalar_out ${TOL})
message(STATUS "vector against scalar code: ${report}")
