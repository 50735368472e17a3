# run_compat.cmake — an imported case also writes SoliDualSPHysics' output files, with the
# values of the run's own files.
#
#   cmake -DSPHC=sphc -DXML=case.xml -DWORKDIR=dir -DEND=T -DEVERY=T
#         -DENERGY_HEADER="Time|mkbound_1_STRAIN_ENERGY|..."
#         -DPLANES="MeasuringPlData_MK1_PL1.csv=measure_plane1.csv|..."
#         -DPLANE_HEADER="Time|Av.Disp.x|..." [-DSPH=model.sph] -P run_compat.cmake
#
# DeformStruc_Energies.csv must have the header ENERGY_HEADER (tab-separated) and, row by
# row, the fields of energies.csv without its total; each plane file of PLANES the header
# PLANE_HEADER and the fields of the measurement file named beside it (without the y
# columns when the header has none).  A .sph model (SPH) must not write these files.

foreach(var SPHC XML WORKDIR END EVERY ENERGY_HEADER PLANES PLANE_HEADER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_compat.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")

include(${CMAKE_CURRENT_LIST_DIR}/build_and_run.cmake)

# The lines of a CSV file as lists of fields (rows joined with '|').
function(read_rows file sep out_header out_rows)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${file} was not written")
  endif()
  file(STRINGS "${file}" lines)
  list(GET lines 0 header)
  list(REMOVE_AT lines 0)
  string(REPLACE "${sep}" "|" header "${header}")
  set(${out_header} "${header}" PARENT_SCOPE)
  set(${out_rows} "${lines}" PARENT_SCOPE)
endfunction()

# Compares the rows of a compat file with the chosen columns of one of ours.
function(same_values compat ours columns)
  read_rows("${compat}" "\t" h rows_c)
  read_rows("${ours}" "," h rows_o)
  list(LENGTH rows_c nc)
  list(LENGTH rows_o no)
  if(nc LESS 3 OR NOT nc EQUAL no)
    message(FATAL_ERROR "${compat}: ${nc} rows, ${ours}: ${no} rows (expected the same, >= 3)")
  endif()
  math(EXPR last "${nc} - 1")
  foreach(i RANGE ${last})
    list(GET rows_c ${i} rc)
    list(GET rows_o ${i} ro)
    string(REPLACE "\t" ";" fc "${rc}")
    string(REPLACE "," ";" fo "${ro}")
    set(picked "")
    foreach(k IN LISTS columns)
      list(GET fo ${k} v)
      list(APPEND picked "${v}")
    endforeach()
    if(NOT fc STREQUAL picked)
      message(FATAL_ERROR "${compat} row ${i}: '${fc}' differs from ${ours}: '${picked}'")
    endif()
  endforeach()
  get_filename_component(name "${compat}" NAME)
  message(STATUS "${name}: ${nc} rows, the values of ${ours}")
endfunction()

build_and_run("${XML}" case)
set(out "${WORKDIR}/case_out")

read_rows("${out}/DeformStruc_Energies.csv" "\t" header rows)
if(NOT header STREQUAL ENERGY_HEADER)
  message(FATAL_ERROR "DeformStruc_Energies.csv header '${header}', expected '${ENERGY_HEADER}'")
endif()
string(REPLACE "|" ";" names "${ENERGY_HEADER}")
list(LENGTH names ncol)
math(EXPR last "${ncol} - 1")
set(columns "")
foreach(k RANGE ${last})
  list(APPEND columns ${k})
endforeach()
same_values("${out}/DeformStruc_Energies.csv" "${out}/energies.csv" "${columns}")

string(FIND "${PLANE_HEADER}" "Av.Disp.y" has_y)
if(has_y EQUAL -1)
  set(columns 0 1 3 4 6)
else()
  set(columns 0 1 2 3 4 5 6)
endif()
string(REPLACE "|" ";" planes "${PLANES}")
foreach(pair IN LISTS planes)
  string(REPLACE "=" ";" pair "${pair}")
  list(GET pair 0 compat)
  list(GET pair 1 ours)
  read_rows("${out}/${compat}" "\t" header rows)
  if(NOT header STREQUAL PLANE_HEADER)
    message(FATAL_ERROR "${compat} header '${header}', expected '${PLANE_HEADER}'")
  endif()
  same_values("${out}/${compat}" "${out}/${ours}" "${columns}")
endforeach()

if(DEFINED SPH)
  build_and_run("${SPH}" model)
  file(GLOB extra "${WORKDIR}/model_out/DeformStruc_*" "${WORKDIR}/model_out/MeasuringPl*")
  if(extra)
    message(FATAL_ERROR "the .sph model wrote SoliDualSPHysics' files: ${extra}")
  endif()
  message(STATUS "the .sph model writes only its own files")
endif()
