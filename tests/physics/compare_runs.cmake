# Two runs of a model compared (the scripts that include this: run_stencil.cmake,
# run_fast_law.cmake, run_same_law.cmake):
#   build_model(MODEL EXE [sphc options...])  sphc builds EXE from MODEL, or the test fails
#   run_model(EXE DIR [program options...])   EXE runs to END on one thread, its outputs in
#                                             DIR (exit 0, or 1: an expectation failed,
#                                             which the runs compared share), or it fails
#   near_energies(A B TOL)                    energies.csv of run folders A and B agree,
#                                             every value within TOL of its row's largest
#                                             energy (at least 3 rows); fails naming the
#                                             values that do not, and sets `report` to the
#                                             rows compared and the largest difference
# TOL of the scripts that include it: 1e-9 unless given (-DTOL=).
if(NOT DEFINED TOL)
  set(TOL 1e-9)
endif()

function(build_model model exe)
  execute_process(COMMAND ${SPHC} ${ARGN} -o ${exe} ${model} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc ${model}: exit ${rc}\n${out}\n${err}")
  endif()
endfunction()

function(run_model exe dir)
  execute_process(COMMAND ${exe} --quiet --threads 1 --end ${END} ${ARGN} --out ${dir}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 AND NOT rc EQUAL 1)
    message(FATAL_ERROR "${exe} ${ARGN}: exit ${rc}\n${out}\n${err}")
  endif()
endfunction()

function(near_energies a b tol)
  execute_process(
    COMMAND awk -F, -v tol=${tol} "
      FNR == 1 { next }
      NR == FNR { row[FNR] = $0; next }
      { n = split(row[FNR], a, \",\"); m = 0
        for (k = 2; k <= n; k++) { v = a[k] < 0 ? -a[k] : a[k]; if (v > m) m = v }
        for (k = 1; k <= n; k++) { d = a[k] - $k; d = d < 0 ? -d : d
          if (d > worst * m) worst = m > 0 ? d / m : worst
          if (d > tol * m + 1e-300) { print \"row \" FNR \" column \" k \": \" a[k] \" against \" $k; bad = 1 } }
        rows++ }
      END { printf \"%d rows, largest difference %.3g of the row's largest energy\\n\", rows, worst
            exit bad || rows < 3 }"
            ${a}/energies.csv ${b}/energies.csv
    RESULT_VARIABLE differ OUTPUT_VARIABLE out)
  if(differ)
    message(FATAL_ERROR "energies.csv differs beyond ${tol}:\n${out}")
  endif()
  set(report "${out}" PARENT_SCOPE)
endfunction()
