# run_case.cmake — an XML case (or a .sph model) imports, compiles and runs a few steps.
#
#   cmake -DSPHC=sphc -DXML=case.xml -DWORKDIR=dir [-DMAPFACS=1,2,4 -DPARTICLES=a,b,c]
#         [-DPARTICLES_RANGE=lo,hi] [-DSPHC_ARGS="--xml-fill=gencase"]
#         [-DEND=1e-5] [-DRUN=OFF] [-DDUMP_CONTAINS=text|text] [-DDUMP_STAGE=ast]
#         [-DTHREADS=1] [-DCLEAN=ON] [-DBODY_PARTICLES=n1,lo2:hi2,...] -P run_case.cmake
#
# For each mapfac in MAPFACS (default: the case as written, compiled where it is) the case
# is copied with its <mapfac> values replaced, compiled with sphc (and SPHC_ARGS), and
# (unless RUN=OFF) run with --end END; it must exit 0 and its summary.json must give the
# matching number of PARTICLES, or a number in [lo, hi] of PARTICLES_RANGE.
# DUMP_CONTAINS: texts (separated by |) that `sphc --dump=DUMP_STAGE` must print (default
# stage: model), e.g. the imported box or measurement plane.  THREADS: the run's threads;
# CLEAN=ON: remove the run's particle files afterwards (large cases).  BODY_PARTICLES: each
# body's particles in the order of summary.json, a number or a range lo:hi.

foreach(var SPHC XML WORKDIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_case.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED END)
  set(END 1e-5)
endif()
if(NOT DEFINED RUN)
  set(RUN ON)
endif()
if(NOT DEFINED THREADS)
  set(THREADS 1)
endif()
string(REPLACE "," ";" MAPFACS "${MAPFACS}")
string(REPLACE "," ";" PARTICLES "${PARTICLES}")
string(REPLACE "," ";" PARTICLES_RANGE "${PARTICLES_RANGE}")
separate_arguments(sphc_args UNIX_COMMAND "${SPHC_ARGS}")
if(NOT MAPFACS)
  set(MAPFACS "asis")
endif()

get_filename_component(stem "${XML}" NAME_WE)
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
file(READ "${XML}" text)

if(DEFINED DUMP_CONTAINS)
  if(NOT DEFINED DUMP_STAGE)
    set(DUMP_STAGE model)
  endif()
  execute_process(COMMAND "${SPHC}" ${sphc_args} --dump=${DUMP_STAGE} "${XML}" RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REPLACE "|" ";" wanted "${DUMP_CONTAINS}")
  foreach(text IN LISTS wanted)
    string(FIND "${out}" "${text}" at)
    if(NOT rc EQUAL 0 OR at EQUAL -1)
      message(FATAL_ERROR "sphc --dump=${DUMP_STAGE} ${XML} (exit ${rc}) does not print "
                          "'${text}':\n${out}\n${err}")
    endif()
  endforeach()
endif()

set(index 0)
foreach(mapfac IN LISTS MAPFACS)
  set(name "${stem}_${mapfac}")
  set(copy "${text}")
  if(NOT mapfac STREQUAL "asis")
    string(REGEX REPLACE "<mapfac value=\"[0-9]+\"" "<mapfac value=\"${mapfac}\"" copy "${copy}")
  endif()
  set(source "${XML}") # as written: files it names are found beside it
  if(NOT mapfac STREQUAL "asis")
    set(source "${WORKDIR}/${name}.xml")
    file(WRITE "${source}" "${copy}")
  endif()
  execute_process(COMMAND "${SPHC}" ${sphc_args} -o "${WORKDIR}/${name}" "${source}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc ${name}.xml failed (exit ${rc}):\n${out}\n${err}")
  endif()
  if(RUN)
    execute_process(COMMAND "${WORKDIR}/${name}" --quiet --threads ${THREADS} --end ${END}
                            --out "${WORKDIR}/${name}_out"
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${name} --end ${END} failed (exit ${rc}):\n${out}\n${err}")
    endif()
    file(READ "${WORKDIR}/${name}_out/summary.json" summary)
    if(CLEAN)
      file(REMOVE_RECURSE "${WORKDIR}/${name}_out/particles")
    endif()
    string(REGEX MATCH "\"particles\": ([0-9]+)" found "${summary}")
    set(particles "${CMAKE_MATCH_1}")
    string(REGEX MATCH "\"steps\": ([0-9]+)" found "${summary}")
    message(STATUS "${name}: ${particles} particles, ${CMAKE_MATCH_1} steps")
    list(LENGTH PARTICLES nexpected)
    if(index LESS nexpected)
      list(GET PARTICLES ${index} expected)
      if(NOT particles EQUAL expected)
        message(FATAL_ERROR "${name}: ${particles} particles, expected ${expected}")
      endif()
    endif()
    string(REGEX MATCHALL "\"particles\": [0-9]+" counts "${summary}")
    list(REMOVE_AT counts 0) # the total
    string(REPLACE "," ";" body_wanted "${BODY_PARTICLES}")
    set(body 0)
    foreach(want IN LISTS body_wanted)
      list(LENGTH counts nbodies)
      if(NOT body LESS nbodies)
        message(FATAL_ERROR "${name}: ${nbodies} bodies in summary.json, expected more")
      endif()
      list(GET counts ${body} got)
      string(REGEX REPLACE "[^0-9]" "" got "${got}")
      string(REPLACE ":" ";" bounds "${want}")
      list(GET bounds 0 lo)
      list(LENGTH bounds nb)
      set(hi ${lo})
      if(nb EQUAL 2)
        list(GET bounds 1 hi)
      endif()
      if(got LESS lo OR got GREATER hi)
        message(FATAL_ERROR "${name}: body ${body} has ${got} particles, expected ${want}")
      endif()
      math(EXPR body "${body} + 1")
    endforeach()
    if(PARTICLES_RANGE)
      list(GET PARTICLES_RANGE 0 lo)
      list(GET PARTICLES_RANGE 1 hi)
      if(particles LESS lo OR particles GREATER hi)
        message(FATAL_ERROR "${name}: ${particles} particles, expected ${lo} to ${hi}")
      endif()
    endif()
  endif()
  math(EXPR index "${index} + 1")
endforeach()
