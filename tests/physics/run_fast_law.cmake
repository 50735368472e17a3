# A law with a rare `if` block (J2's return map) has a fast path in the CPU's stress pass
# (templates/body_forces.c, RARE): the law without that block for the particles that do not
# yield, the whole law for blocks where one does.  The results are the whole law's: a model
# run with the fast path and with --whole-law agrees within round-off.
# -DSPHC= -DMODEL= -DOUT= -DEND= [-DTOL=1e-9] [-DARGS=]
# The generated code must have the fast path (a *_material_fast function) and the run must
# yield (a *_plastic energy above zero by its end), so that both paths are exercised.
include(${CMAKE_CURRENT_LIST_DIR}/compare_runs.cmake) # (TOL's default)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
build_model(${MODEL} ${OUT}/model --emit-c ${OUT}/c)
file(GLOB source ${OUT}/c/*.c)
file(READ "${source}" code)
if(NOT code MATCHES "_material_fast\\(")
  message(FATAL_ERROR "${MODEL}: the generated code has no law fast path")
endif()
separate_arguments(args UNIX_COMMAND "${ARGS}")
run_model(${OUT}/model ${OUT}/fast_out ${args})
run_model(${OUT}/model ${OUT}/whole_out --whole-law ${args})
# the plastic energies of the last row (columns named *_plastic) must not all be zero
execute_process(
  COMMAND awk -F, "NR == 1 { for (k = 1; k <= NF; k++) if ($k ~ /_plastic$/) col[k] = 1; next }
                   { last = $0 }
                   END { n = split(last, v, \",\"); s = 0
                         for (k in col) s += v[k] < 0 ? -v[k] : v[k]
                         print s; exit !(s > 0) }" ${OUT}/fast_out/energies.csv
  RESULT_VARIABLE none OUTPUT_VARIABLE plastic)
if(none)
  message(FATAL_ERROR "${MODEL}: no plastic work by ${END}: the fast path's fallback untested")
endif()
near_energies(${OUT}/fast_out ${OUT}/whole_out ${TOL})
message(STATUS "fast path against the whole law: ${report}plastic work ${plastic}")
