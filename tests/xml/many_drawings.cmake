# many_drawings.cmake — writes, when the tests are configured, two 2D cases whose body is
# drawn with thousands of <drawbox>es (an mk's drawings are joined into a balanced union, so
# they nest some log2 levels; docs/xml.md):
#   WORK/many_drawings.xml  mk 1: 2000 boxes of one column of 4 nodes each, side by side
#                           (8000 nodes); mk 2, drawn after them, takes the first 10
#                           columns over: 7960 particles;
#   WORK/many_drawings_50k.xml  mk 1: one box of three columns drawn 50000 times, mk 2 a
#                           box beside it (compiled only: the shape nested 50000 levels
#                           deep before, and the compiler's walks overflowed);
#   WORK/many_drawings_bad/alternating.xml  600 times a box of mk 1, then a box of mk 2 over
#                           it: the shape would nest 1200 levels, which is refused.

function(many_drawings_case path ncolumns alternate same)
  set(boxes "")
  math(EXPR last "${ncolumns} - 1")
  set(box "          <drawbox><point x=\"@X@\" y=\"-1\" z=\"0\" />"
          "<size x=\"0.2e-3\" y=\"2\" z=\"3e-3\" /></drawbox>\n")
  string(CONCAT box ${box})
  if(same) # one box three columns wide, repeated
    string(REPLACE "@X@" "0" box "${box}")
    string(REPLACE "x=\"0.2e-3\"" "x=\"2.2e-3\"" box "${box}")
    string(REPEAT "${box}" ${ncolumns} boxes)
  else()
    foreach(k RANGE ${last})
      string(REPLACE "@X@" "${k}e-3" one "${box}")
      string(APPEND boxes "${one}")
      if(alternate)
        string(APPEND boxes "          <setmkbound mk=\"2\" />\n${one}"
                            "          <setmkbound mk=\"1\" />\n")
      endif()
    endforeach()
  endif()
  if(NOT alternate AND NOT same)
    string(APPEND boxes "          <setmkbound mk=\"2\" />\n"
                        "          <drawbox><point x=\"0\" y=\"-1\" z=\"0\" />"
                        "<size x=\"9.2e-3\" y=\"2\" z=\"3e-3\" /></drawbox>\n")
  elseif(same) # mk 2 beside mk 1, which keeps all its nodes
    string(APPEND boxes "          <setmkbound mk=\"2\" />\n"
                        "          <drawbox><point x=\"5e-3\" y=\"-1\" z=\"0\" />"
                        "<size x=\"4.2e-3\" y=\"2\" z=\"3e-3\" /></drawbox>\n")
  endif()
  file(WRITE "${path}" "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>
<case>
  <casedef>
    <constantsdef>
      <coefh value=\"1.0\" />
    </constantsdef>
    <geometry>
      <definition dp=\"1.0e-3\">
        <pointmin x=\"-5e-3\" y=\"0\" z=\"-5e-3\" />
        <pointmax x=\"${ncolumns}.5e-3\" y=\"0\" z=\"10e-3\" />
      </definition>
      <commands>
        <mainlist>
          <setmkbound mk=\"1\" />
${boxes}        </mainlist>
      </commands>
    </geometry>
  </casedef>
  <execution>
    <special>
      <deformstrucs>
        <deformstrucbody mkbound=\"1\">
          <density value=\"1000\" />
          <youngmod value=\"1.0e6\" />
          <poissratio value=\"0.3\" />
        </deformstrucbody>
      </deformstrucs>
    </special>
    <parameters>
      <parameter key=\"StepAlgorithm\" value=\"1\" />
      <parameter key=\"TimeMax\" value=\"1.0e-2\" />
    </parameters>
  </execution>
</case>
")
endfunction()

many_drawings_case("${WORK}/many_drawings.xml" 2000 OFF OFF)
many_drawings_case("${WORK}/many_drawings_50k.xml" 50000 OFF ON)
many_drawings_case("${WORK}/many_drawings_bad/alternating.xml" 600 ON OFF)
file(WRITE "${WORK}/many_drawings_bad/alternating.err"
     "error: the drawings of mk 1 and the later drawings of other mks that take nodes over "
     "from them alternate more than 499 times\n")
