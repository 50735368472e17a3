# Generated-code checks for one model:
#   -DSPHC= -DMODEL= -DWORKDIR=          generate WORKDIR/<stem>.c with --emit-only
#   -DFRAGMENT=file                      the file's text must appear verbatim in it
#   -DABSENT="a;b"  -DPRESENT="c;d"      words that must not / must appear
#   -DCC= -DINCLUDE=                     compile it with -Wall -Wextra -Werror
get_filename_component(stem ${MODEL} NAME_WE)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${SPHC} --emit-c ${WORKDIR} --emit-only ${MODEL}
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
