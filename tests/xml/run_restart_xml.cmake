# A case imported from XML resumed from its checkpoint writes exactly what its whole run
# writes, SoliDualSPHysics' own output files (DeformStruc_Energies.csv,
# MeasuringPlData_MK<mk>_PL<k>.csv) included: -DSPHC= -DXML= -DWORKDIR= -DEND= -DMID=
# [-DARGS=...] [-DMAPFAC=m] (tests/physics/run_restart.cmake on the program sphc makes of the
# case; MAPFAC: its <mapfac> values replaced by m, for a shorter run).
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
get_filename_component(stem ${XML} NAME_WE)
set(case ${XML})
if(DEFINED MAPFAC)
  file(READ ${XML} text)
  string(REGEX REPLACE "<mapfac value=\"[0-9]+\"" "<mapfac value=\"${MAPFAC}\"" text "${text}")
  set(case ${WORKDIR}/${stem}.xml)
  file(WRITE ${case} "${text}")
endif()
execute_process(COMMAND ${SPHC} -o ${WORKDIR}/${stem} ${case} RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc ${XML} failed:\n${err}")
endif()
set(PROGRAM ${WORKDIR}/${stem})
set(OUT ${WORKDIR}/restart)
include(${CMAKE_CURRENT_LIST_DIR}/../physics/run_restart.cmake)
foreach(f DeformStruc_Energies.csv MeasuringPlData_MK1_PL1.csv)
  if(NOT EXISTS ${OUT}/part/${f})
    message(FATAL_ERROR "the resumed run has no ${f}")
  endif()
endforeach()
