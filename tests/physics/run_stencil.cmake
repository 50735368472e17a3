# The pair passes on the lattice stencil's runs (templates/body_stencil.c, runtime/stencil.c)
# give the lists' sums in another order: a model run with the stencil and with --no-stencil
# agrees within round-off.  -DSPHC= -DMODEL= -DOUT= -DEND= -DLEAST= [-DTOL=1e-9] [-DARGS=]
# The model is built once and run to END on one thread both ways; every value of
# energies.csv must agree within TOL of the row's largest energy, and summary.json must show
# the stencil used: at least the fraction LEAST of each body's particles in its runs (and
# none with --no-stencil), so that a stencil that stopped matching the lattice fails here.
include(${CMAKE_CURRENT_LIST_DIR}/near_energies.cmake) # (TOL's default)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${SPHC} -o ${OUT}/model ${MODEL} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc ${MODEL}: exit ${rc}\n${out}\n${err}")
endif()
separate_arguments(args UNIX_COMMAND "${ARGS}")
foreach(form stencil lists)
  set(flag "")
  if(form STREQUAL "lists")
    set(flag --no-stencil)
  endif()
  execute_process(COMMAND ${OUT}/model --quiet --threads 1 --end ${END} ${flag} ${args}
                          --out ${OUT}/${form}_out
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1) # (1: an expectation failed, the same in both)
    message(FATAL_ERROR "${form}: exit ${rc}\n${out}\n${err}")
  endif()
  file(READ ${OUT}/${form}_out/summary.json json)
  string(JSON nbodies LENGTH "${json}" bodies)
  math(EXPR last "${nbodies} - 1")
  foreach(k RANGE ${last})
    string(JSON name GET "${json}" bodies ${k} name)
    string(JSON n GET "${json}" bodies ${k} particles)
    string(JSON runs GET "${json}" bodies ${k} stencil_particles)
    if(form STREQUAL "lists" AND NOT runs EQUAL 0)
      message(FATAL_ERROR "--no-stencil: body ${name} has ${runs} particles in stencil runs")
    endif()
    if(form STREQUAL "stencil")
      math(EXPR permille "1000 * ${runs} / ${n}")
      if(permille LESS LEAST)
        message(FATAL_ERROR "body ${name}: ${runs} of ${n} particles in stencil runs, "
                            "fewer than ${LEAST} per mille")
      endif()
      message(STATUS "body ${name}: ${runs} of ${n} particles in stencil runs")
    endif()
  endforeach()
endforeach()
near_energies(${OUT}/stencil_out ${OUT}/lists_out ${TOL})
message(STATUS "stencil against lists: ${report}")
