# run_layers.cmake — the compiler's stage folders depend only on earlier stages
# (docs/architecture.md): every `#include "FOLDER/file.h"` of a file in compiler/STAGE must
# name a folder STAGE may use.  A change that makes an earlier stage reach into a later one
# (a cycle between stages) fails here; a cycle between the files of one folder fails
# run_cycles.cmake.
#
#   cmake -DSOURCE=project/dir -P run_layers.cmake

cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
if(NOT DEFINED SOURCE)
  message(FATAL_ERROR "run_layers.cmake: -DSOURCE=... is required")
endif()

# What each folder may include besides itself (main.c, at the top, may include any).
set(may_util "")
set(may_lang "")
set(may_front "util;lang")
set(may_model "util;lang;front")
set(may_ir "util;lang;front;model")
set(may_check "util;lang;front;model;ir")
set(may_xml "util;lang;front;model")
set(may_lower "util;lang;front;model;ir")
set(may_emit "util;lang;front;model;ir;lower")
set(may_driver "util;lang;front;model;ir;check;xml;lower;emit")
# The runtime's folders whose code the compiler shares (surfaces, limits, input files; sphc is
# built with -I runtime): below every stage.
set(runtime_shared "core;geom")

file(GLOB folders RELATIVE ${SOURCE}/compiler ${SOURCE}/compiler/*)
set(bad "")
set(nfiles 0)
foreach(folder ${folders})
  if(NOT IS_DIRECTORY ${SOURCE}/compiler/${folder})
    continue()
  endif()
  if(NOT DEFINED may_${folder})
    string(APPEND bad "compiler/${folder}/: a folder this test does not place among the stages\n")
    continue()
  endif()
  file(GLOB files ${SOURCE}/compiler/${folder}/*)
  foreach(f ${files})
    math(EXPR nfiles "${nfiles} + 1")
    file(STRINGS ${f} includes REGEX "^#include \"[a-z]+/")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include \"([a-z]+)/.*" "\\1" used "${line}")
      if(NOT used STREQUAL folder AND NOT used IN_LIST may_${folder}
         AND NOT used IN_LIST runtime_shared)
        file(RELATIVE_PATH rel ${SOURCE} ${f})
        string(APPEND bad "${rel}: ${line} (${folder}/ may include ${may_${folder}})\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "includes against the order of the stages:\n${bad}")
endif()
message(STATUS "${nfiles} files follow the order of the stages")
