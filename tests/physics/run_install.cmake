# Installation: `cmake --install BUILD --prefix PREFIX`, then the installed sphc compiles a
# model from another working directory and the program runs.
#   -DBUILD= -DPREFIX= -DMODEL=
# A module `install_marker` is added to the installed standard library only (the model
# imports it), so the model compiles only when sphc finds its files in the installation.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${WORK})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (exit ${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

get_filename_component(PREFIX ${PREFIX} ABSOLUTE)
set(WORK ${PREFIX}-work)
file(REMOVE_RECURSE ${PREFIX} ${WORK})
file(MAKE_DIRECTORY ${WORK})
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX})

foreach(f bin/sphc share/sphc/templates/body_forces.c share/sphc/templates/body_update.c
          share/sphc/stdlib/svk.sph share/sphc/stdlib/neohookean.sph share/sphc/include/sphrt.h)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "not installed: ${PREFIX}/${f}")
  endif()
endforeach()
file(GLOB_RECURSE libs ${PREFIX}/*/libsphrt.a)
if(NOT libs)
  message(FATAL_ERROR "not installed: libsphrt.a")
endif()

file(WRITE ${PREFIX}/share/sphc/stdlib/install_marker.sph
     "import svk\nmaterial marked_svk(lambda, mu) {\n"
     "  let E = 0.5 * (transpose(F) * F - I)\n"
     "  stress S = lambda * tr(E) * I + 2 * mu * E\n"
     "  energy psi = 0.5 * lambda * tr(E)^2 + mu * tr(E * E)\n}\n")
file(COPY ${MODEL} DESTINATION ${WORK})
get_filename_component(name ${MODEL} NAME_WE)
run("installed sphc" ${PREFIX}/bin/sphc -o ${name} ${name}.sph)
run("the program" ${WORK}/${name} --quiet --threads 1)
if(NOT EXISTS ${WORK}/${name}_out/summary.json)
  message(FATAL_ERROR "the program wrote no ${WORK}/${name}_out/summary.json")
endif()
file(READ ${WORK}/${name}_out/summary.json summary)
if(NOT summary MATCHES "\"verdict\": \"stable\"" OR NOT summary MATCHES "\"time\": 0.0001,")
  message(FATAL_ERROR "unexpected summary.json:\n${summary}")
endif()
message(STATUS "summary.json: stable run to t = 1e-4 s")
