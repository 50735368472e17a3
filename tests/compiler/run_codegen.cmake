# Generated-code checks for one model:
#   -DSPHC= -DMODEL= -DWORKDIR=          generate WORKDIR/<stem>.c with --emit-only
#   -DOPTIONS="a;b"                      and these options of sphc
#   -DFRAGMENT=file                      the file's text must appear verbatim in it
#   -DABSENT="a;b"  -DPRESENT="c;d"      words that must not / must appear
#   -DCC= -DINCLUDE=                     compile it with -Wall -Wextra -Werror
#   -DVECTORISED=ON (with CC, INCLUDE)   GCC, x86-64: the stress pass's loop over particles
#                                        must be vectorised (AVX2, sphc's other flags)
get_filename_component(stem ${MODEL} NAME_WE)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${SPHC} ${OPTIONS} --emit-c ${WORKDIR} --emit-only ${MODEL}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc failed on ${MODEL}:\n${err}")
endif()
file(READ ${WORKDIR}/${stem}.c code)

if(FRAGMENT)
  file(READ ${FRAGMENT} frag)
  string(FIND "${code}" "${frag}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "golden fragment ${FRAGMENT} not found in the generated code:\n${code}")
  endif()
  message(STATUS "golden fragment found")
endif()
foreach(word ${ABSENT})
  string(FIND "${code}" "${word}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "'${word}' must not appear in the code generated for ${stem}")
  endif()
endforeach()
foreach(word ${PRESENT})
  string(FIND "${code}" "${word}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "'${word}' must appear in the code generated for ${stem}")
  endif()
endforeach()
if(CC)
  execute_process(COMMAND ${CC} -std=c11 -O1 -fopenmp -Wall -Wextra -Werror -I${INCLUDE}
                          -c ${WORKDIR}/${stem}.c -o ${WORKDIR}/${stem}.o
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generated code of ${stem} does not compile warning-free:\n${err}")
  endif()
  message(STATUS "${stem}.c compiles with -Wall -Wextra -Werror")
endif()
if(VECTORISED)
  # The loop over particles: after SPH_IVDEP where the pass reads the body's
  # arrays in place, the first loop around B_stress_lane where it copies blocks (STAGED;
  # with a law's fast path, RARE, the loop on that path).
  string(FIND "${code}" "SPH_IVDEP" at)
  set(after 2) # the loop is the line after SPH_IVDEP
  if(at EQUAL -1)
    string(FIND "${code}" "_stress_lane(g, q, " at)
    set(after 0) # the loop is the line before its statement
  endif()
  set(loop 0)
  if(NOT at EQUAL -1)
    string(SUBSTRING "${code}" 0 ${at} before)
    string(REGEX MATCHALL "\n" newlines "${before}")
    list(LENGTH newlines count)
    math(EXPR loop "${count} + ${after}")
  endif()
  if(loop EQUAL 0)
    message(FATAL_ERROR "no stress loop found in the code generated for ${stem}")
  endif()
  execute_process(COMMAND ${CC} -std=c11 -O3 -march=x86-64-v3 -ffp-contract=fast
                          -fno-math-errno -fno-trapping-math -fopenmp -fopt-info-vec-optimized
                          -I${INCLUDE} -c ${WORKDIR}/${stem}.c -o ${WORKDIR}/${stem}_v.o
                  RESULT_VARIABLE rc ERROR_VARIABLE report OUTPUT_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "generated code of ${stem} does not compile:\n${report}")
  endif()
  string(FIND "${report}${out}" "${stem}.c:${loop}:" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the stress loop of ${stem} (line ${loop}) is not vectorised:\n${report}")
  endif()
  message(STATUS "${stem}.c:${loop}: the stress loop is vectorised")
endif()
