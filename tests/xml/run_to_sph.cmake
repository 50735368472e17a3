# run_to_sph.cmake — `sphc --to-sph` of an XML case is a model that checks to the same
# model as the case itself.
#
#   cmake -DSPHC=sphc -DXML=dir/case.xml -DWORKDIR=dir [-DGOLDEN=case.sph.golden]
#         [-DSPHC_ARGS="--xml-fill=gencase"] [-DCOPY=file.stl] -P run_to_sph.cmake
#
# The printed model is written to WORKDIR/case.sph; `sphc --dump=model` of both must agree
# except for the first line (model name and file), the source lines of statements and the
# line saying that the imported case also writes SoliDualSPHysics' output files.  Their
# `sphc --dump=ast` must agree too (the printed model parses back to the imported tree,
# fracture items included, which --dump=model does not show), up to how a negative number
# is held: a literal in the importer's tree, a negated one in the parser's.
# GOLDEN: the printed model must equal this file (sphc runs in the case's folder, so the
# first line names the case without folders).  COPY: files beside the case (surface files)
# that the printed model, which names them as the case does, needs beside it too.

foreach(var SPHC XML WORKDIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_to_sph.cmake: -D${var}=... is required")
  endif()
endforeach()
get_filename_component(dir "${XML}" DIRECTORY)
get_filename_component(file "${XML}" NAME)
get_filename_component(stem "${XML}" NAME_WE)
file(MAKE_DIRECTORY "${WORKDIR}")
set(model "${WORKDIR}/${stem}.sph")
foreach(f IN LISTS COPY)
  file(COPY "${dir}/${f}" DESTINATION "${WORKDIR}")
endforeach()
separate_arguments(sphc_args UNIX_COMMAND "${SPHC_ARGS}")

execute_process(COMMAND "${SPHC}" ${sphc_args} --to-sph "${file}" WORKING_DIRECTORY "${dir}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE printed ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sphc --to-sph ${file} failed (exit ${rc}):\n${err}")
endif()
file(WRITE "${model}" "${printed}")

function(dump stage src result)
  set(args "")
  if(src STREQUAL XML)
    set(args ${sphc_args})
  endif()
  execute_process(COMMAND "${SPHC}" ${args} --dump=${stage} "${src}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sphc --dump=${stage} ${src} failed (exit ${rc}):\n${err}")
  endif()
  string(REGEX REPLACE "\\(- ([0-9][0-9.e+-]*)\\)" "-\\1" out "${out}")  # (- 2) -> -2
  string(FIND "${out}" "\n" eol)   # the first line names the model and its file
  math(EXPR eol "${eol} + 1")
  string(SUBSTRING "${out}" ${eol} -1 out)
  # An imported case also writes SoliDualSPHysics' files; the printed model does not.
  string(REGEX REPLACE "  outputs: also SoliDualSPHysics'[^\n]*\n" "" out "${out}")
  string(REGEX REPLACE " \\(line [0-9]+\\)" "" out "${out}")
  # COPY'd surface files: the same file, beside the case or beside the printed model.
  foreach(f IN LISTS COPY)
    string(REPLACE "${dir}/${f}" "${f}" out "${out}")
    string(REPLACE "${WORKDIR}/${f}" "${f}" out "${out}")
  endforeach()
  set(${result} "${out}" PARENT_SCOPE)
endfunction()

foreach(stage model ast)
  dump(${stage} "${XML}" from_xml)
  dump(${stage} "${model}" from_sph)
  if(NOT from_xml STREQUAL from_sph)
    message(FATAL_ERROR "the printed model differs from the case (--dump=${stage}):\n"
                        "--- case:\n${from_xml}\n--- printed (${model}):\n${from_sph}")
  endif()
endforeach()

if(DEFINED GOLDEN)
  file(READ "${GOLDEN}" expected)
  if(NOT printed STREQUAL expected)
    message(FATAL_ERROR "sphc --to-sph ${file} differs from ${GOLDEN}:\n${printed}")
  endif()
endif()
message(STATUS "${file}: the printed model checks to the same model")
