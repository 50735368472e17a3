# run_cycles.cmake — the files of each compiler stage folder depend on each other without a
# cycle (docs/architecture.md), so that each can be read, and tested, after the files it uses.
# A file and its own header (X.c, X.h) count as one; a cycle is a loop of them
#
#   through their includes:   X.c or X.h includes Y.h while Y.c or Y.h includes X.h,
#                             directly or through other files of the folder;
#   through their functions:  X.c uses a function Y.c defines while Y.c uses one of X.c's,
#                             directly or through other files (a header several files share
#                             hides such a loop from the includes).
#
# Each cycle fails here, named with the include or the function that makes each of its steps.
# Functions are read from the code without its comments, strings and character constants: a
# definition is a line that starts with a name, not `static`, and whose parameter list ends
# before a `{`; a use is the function's name anywhere in another file's code.
#
#   cmake -DSOURCE=project/dir -P run_cycles.cmake

cmake_policy(SET CMP0057 NEW) # if(... IN_LIST ...)
if(NOT DEFINED SOURCE)
  message(FATAL_ERROR "run_cycles.cmake: -DSOURCE=... is required")
endif()

# The code of a C (or flex, bison) file with its comments, strings and character constants
# blanked, between two spaces.
function(code_of path out)
  file(READ ${path} text)
  string(REGEX REPLACE
         "'([^'\\\\\n]|\\\\.)+'|\"([^\"\\\\\n]|\\\\.)*\"|/\\*[^*]*\\*+([^/*][^*]*\\*+)*/|//[^\n]*"
         " " text "${text}")
  set(${out} " ${text} " PARENT_SCOPE)
endfunction()

# The functions that code defines (not static).
function(definitions_of code out)
  string(REGEX MATCHALL "\n[A-Za-z_][^;{}(\n]*[ *][A-Za-z_][A-Za-z_0-9]*\\([^;{}]*\\)[ \t\n]*{"
         heads "${code}")
  set(names "")
  foreach(head ${heads})
    if(NOT head MATCHES "^\nstatic[ \t]")
      string(REGEX REPLACE "^\n[^(]*[ *]([A-Za-z_][A-Za-z_0-9]*)\\(.*" "\\1" name "${head}")
      list(APPEND names ${name})
    endif()
  endforeach()
  set(${out} ${names} PARENT_SCOPE)
endfunction()

# File f of folder `folder` (in dir), of unit `unit`: its includes of the folder's headers
# (include_UNIT, why_include_UNIT_USED), and, unless a header, its code (code_UNIT) and the
# functions it defines (defs_UNIT).
macro(read_file dir folder f unit)
  get_filename_component(name ${f} NAME)
  file(STRINGS ${f} includes REGEX "^#include \"")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"(${folder}/)?([^\"/]*)\".*" "\\2" used "${line}")
    get_filename_component(used_unit ${used} NAME_WE)
    if(EXISTS ${dir}/${used} AND NOT used MATCHES "/" AND NOT used_unit STREQUAL "${unit}"
       AND NOT used_unit IN_LIST include_${unit})
      list(APPEND include_${unit} ${used_unit})
      set(why_include_${unit}_${used_unit} "${name} includes ${used}")
    endif()
  endforeach()
  if(NOT name MATCHES "\\.h$")
    code_of(${f} code)
    definitions_of("${code}" defs)
    list(APPEND defs_${unit} ${defs})
    string(APPEND code_${unit} "${code}")
    set(file_${unit} ${name})
  endif()
endmacro()

# call_UNIT: the units whose functions unit's code uses (why_call_UNIT_OTHER: the first).
macro(find_uses unit)
  foreach(other ${units})
    if(other STREQUAL "${unit}")
      continue()
    endif()
    foreach(fn ${defs_${other}})
      if(code_${unit} MATCHES "[^A-Za-z0-9_]${fn}[^A-Za-z0-9_]")
        list(APPEND call_${unit} ${other})
        set(why_call_${unit}_${other} "${file_${unit}} uses ${fn}() of ${file_${other}}")
        break()
      endif()
    endforeach()
  endforeach()
endmacro()

# The units of folder dir (file names without their suffix) and what each depends on:
# include_UNIT and call_UNIT.
macro(read_folder dir folder)
  file(GLOB files ${dir}/*)
  set(units "")
  foreach(f ${files})
    get_filename_component(unit ${f} NAME_WE)
    if(NOT unit IN_LIST units)
      list(APPEND units ${unit})
      foreach(what include call defs code)
        set(${what}_${unit} "")
      endforeach()
    endif()
  endforeach()
  foreach(f ${files})
    get_filename_component(unit ${f} NAME_WE)
    read_file(${dir} ${folder} ${f} ${unit})
  endforeach()
  foreach(unit ${units})
    find_uses(${unit})
  endforeach()
endmacro()

# reach_UNIT: the units each unit depends on through edges `kind`, directly or not.
macro(close_over kind)
  foreach(u ${units})
    set(reach_${u} ${${kind}_${u}})
  endforeach()
  set(changed 1)
  while(changed)
    set(changed 0)
    foreach(u ${units})
      foreach(v ${reach_${u}})
        foreach(w ${${kind}_${v}})
          if(NOT w IN_LIST reach_${u})
            list(APPEND reach_${u} ${w})
            set(changed 1)
          endif()
        endforeach()
      endforeach()
    endforeach()
  endwhile()
endmacro()

# The shortest way from unit u back to itself through edges `kind` (u reaches itself): its
# units into path (u first and last), the reason of each step into steps.
function(way_back kind u path steps)
  set(queue ${u})
  set(seen "")
  while(queue AND NOT u IN_LIST seen)
    list(GET queue 0 x)
    list(REMOVE_AT queue 0)
    foreach(w ${${kind}_${x}})
      if(NOT w IN_LIST seen)
        list(APPEND seen ${w})
        list(APPEND queue ${w})
        set(from_${w} ${x})
      endif()
    endforeach()
  endwhile()
  set(units_back ${u})
  set(why "")
  set(x ${u})
  while(1)
    set(prev ${from_${x}})
    list(INSERT units_back 0 ${prev})
    list(INSERT why 0 "${why_${kind}_${prev}_${x}}")
    set(x ${prev})
    if(x STREQUAL u)
      break()
    endif()
  endwhile()
  set(${path} ${units_back} PARENT_SCOPE)
  set(${steps} ${why} PARENT_SCOPE)
endfunction()

# Appends to `bad` each cycle of the units of `folder` through edges `kind` (include, call).
function(report_cycles folder kind)
  close_over(${kind})
  set(reported "")
  foreach(u ${units})
    if(u IN_LIST reach_${u} AND NOT u IN_LIST reported)
      way_back(${kind} ${u} path steps)
      list(APPEND reported ${path})
      string(REPLACE ";" " -> " path "${path}")
      string(REPLACE ";" "; " steps "${steps}")
      string(APPEND bad "compiler/${folder}/: ${kind} cycle ${path} (${steps})\n")
    endif()
  endforeach()
  set(bad "${bad}" PARENT_SCOPE)
endfunction()

file(GLOB folders RELATIVE ${SOURCE}/compiler ${SOURCE}/compiler/*)
set(bad "")
set(nunits 0)
foreach(folder ${folders})
  if(NOT IS_DIRECTORY ${SOURCE}/compiler/${folder})
    continue()
  endif()
  read_folder(${SOURCE}/compiler/${folder} ${folder})
  list(LENGTH units n)
  math(EXPR nunits "${nunits} + ${n}")
  report_cycles(${folder} include)
  report_cycles(${folder} call)
endforeach()
if(bad)
  message(FATAL_ERROR "files of a stage folder that depend on each other in a cycle:\n${bad}")
endif()
message(STATUS "${nunits} files (a .c with its .h) depend on each other without a cycle")
