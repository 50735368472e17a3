# run_diag.cmake — one golden diagnostic test.
#
#   cmake -DSPHC=path/to/sphc -DMODEL=dir/name.sph -DEXPECTED=dir/name.err -P run_diag.cmake
#
# Runs `sphc --check name.sph` inside the model's folder (so messages start with
# "name.sph:LINE:COL:"), requires a non-zero exit status, and requires every
# non-empty line of the .err file to appear verbatim in stderr (trailing blanks
# aside), so a golden states just the lines that matter: the
# "name.sph:L:C: error: message" line and, if wanted, the source and caret lines.
# A model whose first line is "# options: OPTION..." is checked with those options too
# (--strict: a golden of a warning, which --strict makes an error).

foreach(var SPHC MODEL EXPECTED)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_diag.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS "${EXPECTED}")
  message(FATAL_ERROR "run_diag.cmake: no expected diagnostics '${EXPECTED}'")
endif()

get_filename_component(model_dir "${MODEL}" DIRECTORY)
get_filename_component(model_name "${MODEL}" NAME)

file(STRINGS "${MODEL}" first_line LIMIT_COUNT 1)
set(options "")
if(first_line MATCHES "^# options: (.*)$")
  separate_arguments(options UNIX_COMMAND "${CMAKE_MATCH_1}")
endif()

execute_process(
  COMMAND "${SPHC}" --check ${options} "${model_name}"
  WORKING_DIRECTORY "${model_dir}"
  RESULT_VARIABLE status
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)

if(status EQUAL 0)
  message(FATAL_ERROR "sphc --check ${model_name} succeeded, but errors were expected.\n"
                      "--- stderr:\n${err}")
endif()
if(NOT status MATCHES "^[0-9]+$")
  message(FATAL_ERROR "sphc --check ${model_name} did not exit normally: ${status}\n"
                      "--- stderr:\n${err}")
endif()

# Trailing blanks and carriage returns are ignored on both sides.
function(normalize text result)
  string(REPLACE "\r" "" text "${text}")
  string(REGEX REPLACE "[ \t]+\n" "\n" text "${text}")
  string(REGEX REPLACE "[ \t]+$" "" text "${text}")
  set(${result} "${text}" PARENT_SCOPE)
endfunction()

normalize("${err}" actual)

# The .err file as a list of lines; ';', '[' and ']' would upset CMake's list
# splitting, so they travel encoded and are restored line by line.
file(READ "${EXPECTED}" expected_text)
string(REPLACE ";" "<SEMI>" expected_text "${expected_text}")
string(REPLACE "[" "<LSQB>" expected_text "${expected_text}")
string(REPLACE "]" "<RSQB>" expected_text "${expected_text}")
string(REPLACE "\n" ";" expected_lines "${expected_text}")

set(missing "")
set(nexpected 0)
foreach(line IN LISTS expected_lines)
  string(REPLACE "<SEMI>" ";" line "${line}")
  string(REPLACE "<LSQB>" "[" line "${line}")
  string(REPLACE "<RSQB>" "]" line "${line}")
  normalize("${line}" line)
  if(line STREQUAL "")
    continue()
  endif()
  math(EXPR nexpected "${nexpected} + 1")
  string(FIND "${actual}" "${line}" index)
  if(index EQUAL -1)
    string(APPEND missing "  ${line}\n")
  endif()
endforeach()

if(nexpected EQUAL 0)
  message(FATAL_ERROR "${EXPECTED} states no expected lines")
endif()
if(NOT missing STREQUAL "")
  message(FATAL_ERROR "sphc --check ${model_name} (exit ${status}): "
                      "expected lines missing from stderr:\n"
                      "${missing}--- actual stderr:\n${err}")
endif()
message(STATUS "${model_name}: exit ${status}, ${nexpected} expected line(s) found")
