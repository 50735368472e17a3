# run_layers.cmake — the runtime's folders are layers, each on the ones below it
# (docs/architecture.md): every `#include "FOLDER/file.h"` of a file in runtime/LAYER must name
# LAYER itself or a folder LAYER may use, an include without a folder must name a file of the
# same folder, and no file of a folder includes the headers at runtime/'s top (sphrt.h,
# sph_cuda.h, ...: the umbrellas of generated code, which include every layer).  A change
# that makes a layer reach into a later one (core/ including run/, say) fails here.
#
#   cmake -DSOURCE=project/dir -P run_layers.cmake

cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
if(NOT DEFINED SOURCE)
  message(FATAL_ERROR "run_layers.cmake: -DSOURCE=... is required")
endif()
set(runtime ${SOURCE}/runtime)

# What each folder may include besides itself, from the bottom up.  cuda/ (the device's
# header-only code) and mpi/ (the library of runs on many processes) stand on all of libsphrt.
set(may_core "")
set(may_geom "core")
set(may_par "core")
set(may_scene "core;geom;par")
set(may_pairs "core;geom;par;scene")
set(may_contact "core;geom;par;scene;pairs")
set(may_io "core;geom;par;scene;pairs;contact")
set(may_run "core;geom;par;scene;pairs;contact;io")
set(may_cuda "core;geom;par;scene;pairs;contact;io;run")
set(may_mpi "core;geom;par;scene;pairs;contact;io;run")

file(GLOB entries RELATIVE ${runtime} ${runtime}/*)
set(bad "")
set(nfiles 0)
foreach(entry ${entries})
  if(NOT IS_DIRECTORY ${runtime}/${entry})
    if(entry MATCHES "\\.c$") # runtime/'s top holds the headers of generated code, no sources
      string(APPEND bad "runtime/${entry}: a source at runtime/'s top, in no layer\n")
    endif()
    continue()
  endif()
  set(folder ${entry})
  if(NOT DEFINED may_${folder})
    string(APPEND bad "runtime/${folder}/: a folder this test does not place among the layers\n")
    continue()
  endif()
  file(GLOB_RECURSE files ${runtime}/${folder}/*.c ${runtime}/${folder}/*.h)
  foreach(f ${files})
    math(EXPR nfiles "${nfiles} + 1")
    file(RELATIVE_PATH rel ${SOURCE} ${f})
    file(STRINGS ${f} includes REGEX "^#include \"")
    foreach(line ${includes})
      string(REGEX REPLACE "^#include \"([^\"]*)\".*" "\\1" name "${line}")
      if(name MATCHES "^([a-z_]+)/")
        set(used ${CMAKE_MATCH_1})
        if(NOT used STREQUAL folder AND NOT used IN_LIST may_${folder})
          set(may "${may_${folder}}")
          if(may STREQUAL "")
            set(may "no other folder")
          endif()
          string(APPEND bad "${rel}: ${line} (${folder}/ may include ${may})\n")
        endif()
      elseif(NOT EXISTS ${runtime}/${folder}/${name})
        string(APPEND bad "${rel}: ${line} (not a file of ${folder}/: name its folder)\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "includes against the order of the runtime's layers:\n${bad}")
endif()
message(STATUS "${nfiles} files follow the order of the runtime's layers")
