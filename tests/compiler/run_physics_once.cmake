# run_physics_once.cmake — each pair term's arithmetic is written once in templates/
# (templates/physics/pairs.c) and called by every loop layout: the viscous pressure's
# constants (eq. 58), the gradient's and the momentum term's functions must each be
# defined in exactly one template file, and each layout's file must call them.
#   cmake -DTEMPLATES=dir -P run_physics_once.cmake
file(GLOB_RECURSE files ${TEMPLATES}/*.c ${TEMPLATES}/*.cu)
# text that defines a term, and the number of template files that may hold it
set(defining "0.125 * @BETA1@" "0.03125 * @BETA2@" "_gradient_term_@S@(" "_momentum_term_@S@("
             "_viscosity_term_@S@(" "_viscous_pressure_@S@(")
foreach(text IN LISTS defining)
  set(holders "")
  foreach(f ${files})
    file(READ ${f} src)
    string(FIND "${src}" "${text}" at)
    if(NOT at EQUAL -1)
      file(RELATIVE_PATH rel ${TEMPLATES} ${f})
      list(APPEND holders ${rel})
    endif()
  endforeach()
  if(NOT holders STREQUAL "physics/pairs.c")
    message(FATAL_ERROR "'${text}' must be written in templates/physics/pairs.c alone; "
                        "found in: ${holders}")
  endif()
endforeach()
# each layout calls the terms (file: what it must call)
set(calls "body_forces.c:_gradient_term_v8(" "body_forces.c:_momentum_term_v8("
          "body_forces.c:_viscosity_term_v8(" "body_forces.c:_viscous_pressure_@RS@("
          "body_stencil.c:_viscous_pressure_v8(" "body_cuda.cu:_gradient_term_d("
          "body_cuda.cu:_momentum_term_@RS@(" "body_cuda.cu:_viscosity_term_@RS@(")
foreach(call IN LISTS calls)
  string(REGEX REPLACE ":.*" "" file "${call}")
  string(REGEX REPLACE "^[^:]*:" "" text "${call}")
  file(READ ${TEMPLATES}/${file} src)
  string(FIND "${src}" "${text}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "templates/${file} must call '${text}'")
  endif()
endforeach()
message(STATUS "the pair terms are written once and called by every layout")
