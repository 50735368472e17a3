# run_compare.cmake — an XML case and its hand-written .sph model give the same run.
#
#   cmake -DSPHC=sphc -DXML=case.xml -DSPH=case.sph -DWORKDIR=dir -DEND=T -DEVERY=T
#         [-DMAPFAC=1] -P run_compare.cmake
#   cmake ... -DSPH=TO_SPH ...: the model is the case converted by `sphc --to-sph`, and the
#         two runs' particle files must be identical too (the --to-sph round trip).
#   cmake ... -DMEASURE=OFF ...: the model measures a plane the case does not; the
#         measurement files are not compared (a plane does not change the run).
#
# Both are compiled at the same refinement (<mapfac> of the XML and `refine` of the model
# set to MAPFAC), run on one thread to END with an output every EVERY, and must agree:
# particles and steps in summary.json, and energies.csv and the one measurement file
# line for line (the header lines name the bodies and differ).

foreach(var SPHC XML SPH WORKDIR END EVERY)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_compare.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED MAPFAC)
  set(MAPFAC 1)
endif()
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")

file(READ "${XML}" text)
string(REGEX REPLACE "<mapfac value=\"[0-9]+\"" "<mapfac value=\"${MAPFAC}\"" text "${text}")
file(WRITE "${WORKDIR}/from_xml.xml" "${text}")
if(SPH STREQUAL "TO_SPH")
  execute_process(COMMAND "${SPHC}" --to-sph from_xml.xml WORKING_DIRECTORY "${WORKDIR}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc --to-sph ${XML} failed (exit ${rc}):\n${err}")
  endif()
else()
  file(READ "${SPH}" text)
endif()
string(REGEX REPLACE "refine [0-9]+" "refine ${MAPFAC}" text "${text}")
file(WRITE "${WORKDIR}/from_sph.sph" "${text}")

include(${CMAKE_CURRENT_LIST_DIR}/build_and_run.cmake)
foreach(name from_xml from_sph)
  if(name STREQUAL "from_xml")
    set(src "${WORKDIR}/from_xml.xml")
  else()
    set(src "${WORKDIR}/from_sph.sph")
  endif()
  build_and_run(${src} ${name})
endforeach()

# summary.json: particles and steps
foreach(key particles steps)
  set(values "")
  foreach(name from_xml from_sph)
    file(READ "${WORKDIR}/${name}_out/summary.json" summary)
    string(REGEX MATCH "\"${key}\": ([0-9]+)" found "${summary}")
    list(APPEND values "${CMAKE_MATCH_1}")
  endforeach()
  list(GET values 0 a)
  list(GET values 1 b)
  if(NOT a STREQUAL b OR a STREQUAL "")
    message(FATAL_ERROR "${key}: ${a} from the XML case, ${b} from the .sph model")
  endif()
  message(STATUS "${key}: ${a} from both")
endforeach()

# Two CSV files agree row for row, header lines aside.
function(same_rows a b)
  file(STRINGS "${a}" rows_a)
  file(STRINGS "${b}" rows_b)
  list(REMOVE_AT rows_a 0)
  list(REMOVE_AT rows_b 0)
  list(LENGTH rows_a n)
  if(n LESS 3 OR NOT rows_a STREQUAL rows_b)
    message(FATAL_ERROR "${a} and ${b} differ (or have fewer than 3 rows)")
  endif()
  get_filename_component(name "${a}" NAME)
  message(STATUS "${name}: ${n} rows, the same")
endfunction()

same_rows("${WORKDIR}/from_xml_out/energies.csv" "${WORKDIR}/from_sph_out/energies.csv")
file(GLOB xml_measure "${WORKDIR}/from_xml_out/measure_*.csv")
file(GLOB sph_measure "${WORKDIR}/from_sph_out/measure_*.csv")
list(LENGTH xml_measure nx)
list(LENGTH sph_measure ns)
if(DEFINED MEASURE AND NOT MEASURE)
  message(STATUS "measurement files not compared (${nx} from the case, ${ns} from the model)")
elseif(nx EQUAL 0 AND ns EQUAL 0 AND SPH STREQUAL "TO_SPH")
  message(STATUS "no measurement files (the case has no plane)")
elseif(NOT nx EQUAL 1 OR NOT ns EQUAL 1)
  message(FATAL_ERROR "expected one measurement file from each run: ${xml_measure} ${sph_measure}")
else()
  same_rows("${xml_measure}" "${sph_measure}")
endif()

# The --to-sph round trip: the same particles, frame by frame.
if(SPH STREQUAL "TO_SPH")
  file(GLOB frames RELATIVE "${WORKDIR}/from_xml_out/particles" "${WORKDIR}/from_xml_out/particles/*.vtu")
  list(LENGTH frames n)
  if(n LESS 2)
    message(FATAL_ERROR "expected particle files from the XML case's run")
  endif()
  foreach(f IN LISTS frames)
    file(SHA256 "${WORKDIR}/from_xml_out/particles/${f}" ha)
    file(SHA256 "${WORKDIR}/from_sph_out/particles/${f}" hb)
    if(NOT ha STREQUAL hb)
      message(FATAL_ERROR "particles/${f} differs between the case and its --to-sph model")
    endif()
  endforeach()
  message(STATUS "${n} particle files, identical")
endif()
