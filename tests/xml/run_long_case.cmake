# run_long_case.cmake — a case of many lines, written when the test runs, and what sphc --check
# reports of it:
#
#   cmake -DSPHC=sphc -DWORKDIR=dir -DKIND=warnings|lines [-DCOUNT=n] -P run_long_case.cmake
#
# warnings: COUNT (default 20000) <parameter>s of keys sphc does not know, one warning each:
#           the first 50 are shown, then one line says how many were not, and the run passes.
# lines:    70000 known <parameter>s, then a wrong TimeOut past line 70000: the error names
#           its own line (libxml2 keeps a node's line in 16 bits: 65535 at most).

foreach(var SPHC WORKDIR KIND)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_long_case.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED COUNT)
  set(COUNT 20000)
endif()

if(KIND STREQUAL "warnings")
  # Unknown1, Unknown2, ...: each card's own key (the loop is slow in CMake: 10 keys a line).
  set(filler "")
  math(EXPR rows "${COUNT} / 10")
  foreach(k RANGE 1 ${rows})
    string(APPEND filler "      <parameter key=\"Unknown${k}a\" value=\"1\" /><parameter key=\"Unknown${k}b\" value=\"1\" /><parameter key=\"Unknown${k}c\" value=\"1\" /><parameter key=\"Unknown${k}d\" value=\"1\" /><parameter key=\"Unknown${k}e\" value=\"1\" /><parameter key=\"Unknown${k}f\" value=\"1\" /><parameter key=\"Unknown${k}g\" value=\"1\" /><parameter key=\"Unknown${k}h\" value=\"1\" /><parameter key=\"Unknown${k}i\" value=\"1\" /><parameter key=\"Unknown${k}j\" value=\"1\" />\n")
  endforeach()
  math(EXPR COUNT "${rows} * 10")
  set(timeout "1.0e-3")
elseif(KIND STREQUAL "lines")
  string(REPEAT "      <parameter key=\"Visco\" value=\"0.1\" />\n" 70000 filler)
  set(timeout "-1.0e-3")
else()
  message(FATAL_ERROR "run_long_case.cmake: KIND is warnings or lines")
endif()

# 28 lines before the filler.
file(MAKE_DIRECTORY "${WORKDIR}")
set(case "${WORKDIR}/long_${KIND}.xml")
file(WRITE "${case}" "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>
<case>
  <casedef>
    <constantsdef>
      <coefh value=\"1.0\" />
    </constantsdef>
    <geometry>
      <definition dp=\"1.0e-3\">
        <pointmin x=\"-5e-3\" y=\"0\" z=\"-5e-3\" />
        <pointmax x=\"10e-3\" y=\"0\" z=\"10e-3\" />
      </definition>
      <commands>
        <mainlist>
          <setmkbound mk=\"1\" />
          <drawbox><point x=\"0\" y=\"-1\" z=\"0\" /><size x=\"4e-3\" y=\"2\" z=\"3e-3\" /></drawbox>
        </mainlist>
      </commands>
    </geometry>
  </casedef>
  <execution>
    <special>
      <deformstrucs>
        <deformstrucbody mkbound=\"1\">
          <density value=\"1000\" /><youngmod value=\"1.0e6\" /><poissratio value=\"0.3\" />
        </deformstrucbody>
      </deformstrucs>
    </special>
    <parameters>
${filler}      <parameter key=\"TimeMax\" value=\"1.0e-2\" />
      <parameter key=\"TimeOut\" value=\"${timeout}\" />
    </parameters>
  </execution>
</case>
")

execute_process(COMMAND "${SPHC}" --check long_${KIND}.xml WORKING_DIRECTORY "${WORKDIR}"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
string(LENGTH "${err}" bytes)

if(KIND STREQUAL "warnings")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc --check exited with ${rc}, expected 0:\n${err}")
  endif()
  string(REGEX MATCHALL "warning: <parameter key=\"Unknown[0-9]+[a-j]\"> is not known to sphc"
         shown "${err}")
  list(LENGTH shown nshown)
  math(EXPR hidden "${COUNT} - 50")
  set(last "sphc: note: ${hidden} more warnings not shown (only the first 50 are)\n")
  string(FIND "${err}" "${last}" at)
  string(LENGTH "${last}" lastlen)
  math(EXPR end "${bytes} - ${lastlen}")
  if(NOT nshown EQUAL 50 OR NOT at EQUAL end OR bytes GREATER 65536)
    string(SUBSTRING "${err}" 0 4000 head)
    message(FATAL_ERROR "${COUNT} warnings: ${nshown} shown (expected 50), ${bytes} bytes on "
                        "stderr, and its last line should read\n${last}--- stderr begins:\n${head}")
  endif()
  message(STATUS "${COUNT} warnings: 50 shown, the rest counted (${bytes} bytes)")
else()
  math(EXPR line "28 + 70000 + 2")
  set(expected "long_lines.xml:${line}: error: <parameter key=\"TimeOut\">: value must be positive (got -0.001)")
  string(FIND "${err}" "${expected}" at)
  if(rc EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "expected (exit not 0)\n${expected}\n--- exit ${rc}, stderr:\n${err}")
  endif()
  string(FIND "${err}" "${line} |       <parameter key=\"TimeOut\"" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the error does not show line ${line}:\n${err}")
  endif()
  message(STATUS "the error names line ${line}")
endif()
