# A model whose standard-library law (written as its energy, the stress derived) is replaced
# by the same law with its stress written by hand (handwritten.sph) gives the same run within
# round-off: -DSPHC= -DMODEL= -DLAW= -DOUT= -DEND= [-DTOL=1e-9].  The model is copied with
# `import LAW` and `material LAW(` turned into the hand-written law's names, both are built
# and run to END on one thread, and every value of energies.csv must agree within TOL of the
# row's largest energy (the stresses differ by round-off, up to ~1e-11 for J2, which the
# steps carry on; the CSV's 10 significant digits show none of it over these runs).
include(${CMAKE_CURRENT_LIST_DIR}/compare_runs.cmake) # (TOL's default)
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
get_filename_component(dir ${MODEL} DIRECTORY)
get_filename_component(stem ${MODEL} NAME_WE)
file(READ ${MODEL} text)
string(REPLACE "import ${LAW}\n" "import handwritten\n" hand_text "${text}")
string(REPLACE "material ${LAW}(" "material ${LAW}_written(" hand_text "${hand_text}")
if(hand_text STREQUAL text)
  message(FATAL_ERROR "${MODEL} does not use the law ${LAW}")
endif()
file(WRITE ${OUT}/${stem}_written.sph "${hand_text}")
file(COPY ${dir}/handwritten.sph DESTINATION ${OUT})
foreach(form derived written)
  set(src ${MODEL})
  if(form STREQUAL "written")
    set(src ${OUT}/${stem}_written.sph)
  endif()
  build_model(${src} ${OUT}/${form})
  run_model(${OUT}/${form} ${OUT}/${form}_out)
endforeach()
near_energies(${OUT}/derived_out ${OUT}/written_out ${TOL})
message(STATUS "${stem}, ${LAW} derived against written: ${report}")
