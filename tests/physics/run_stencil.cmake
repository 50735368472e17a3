# The pair passes on the lattice stencil's runs (templates/body_stencil.c,
# runtime/pairs/stencil.c) and the 3D gradient's offset blocks (runtime/pairs/offset_blocks.c) give the lists' sums in
# another order: a model run with them and with --no-stencil agrees within round-off.
# -DSPHC= -DMODEL= -DOUT= -DEND= -DLEAST= [-DTOL=1e-9] [-DARGS=] [-DBLOCKS=ON [-DMLEAST=]]
# The model is built once and run to END on one thread both ways; every value of
# energies.csv must agree within TOL of the row's largest energy, and summary.json must show
# the stencil used: at least the fraction LEAST (per mille) of each body's particles in its
# runs, or with BLOCKS of its pairs in its gradient's offset blocks and, with MLEAST, that
# fraction of its half lists' pairs in its momentum pass's (and none with --no-stencil), so
# that a stencil or blocks that stopped matching the lattice fail here.
include(${CMAKE_CURRENT_LIST_DIR}/compare_runs.cmake) # (TOL's default)
if(BLOCKS)
  set(what offset_block_pairs)
  set(of pairs)
else()
  set(what stencil_particles)
  set(of particles)
endif()
# Body k's share `what` of its `of` (times `scale`: 2 for half lists' pairs out of pairs)
# in summary.json's text json: at least `least` per mille in the run with the stencil, none
# in the one with the lists.
function(check_share form json k what of scale least)
  string(JSON name GET "${json}" bodies ${k} name)
  string(JSON n GET "${json}" bodies ${k} ${of})
  string(JSON used GET "${json}" bodies ${k} ${what})
  if(form STREQUAL "lists" AND NOT used EQUAL 0)
    message(FATAL_ERROR "--no-stencil: body ${name} has ${used} ${what}")
  endif()
  if(form STREQUAL "stencil")
    math(EXPR permille "1000 * ${scale} * ${used} / ${n}")
    if(permille LESS least)
      message(FATAL_ERROR "body ${name}: ${what} ${used} of ${n} ${of} (times ${scale}), "
                          "fewer than ${least} per mille")
    endif()
    message(STATUS "body ${name}: ${what} ${used} of ${n} ${of} (times ${scale})")
  endif()
endfunction()

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
build_model(${MODEL} ${OUT}/model)
separate_arguments(args UNIX_COMMAND "${ARGS}")
foreach(form stencil lists)
  set(flag "")
  if(form STREQUAL "lists")
    set(flag --no-stencil)
  endif()
  run_model(${OUT}/model ${OUT}/${form}_out ${flag} ${args})
  file(READ ${OUT}/${form}_out/summary.json json)
  string(JSON nbodies LENGTH "${json}" bodies)
  math(EXPR last "${nbodies} - 1")
  foreach(k RANGE ${last})
    check_share(${form} "${json}" ${k} ${what} ${of} 1 ${LEAST})
    if(BLOCKS AND DEFINED MLEAST)
      check_share(${form} "${json}" ${k} momentum_block_pairs pairs 2 ${MLEAST})
    endif()
  endforeach()
endforeach()
near_energies(${OUT}/stencil_out ${OUT}/lists_out ${TOL})
message(STATUS "stencil against lists: ${report}")
