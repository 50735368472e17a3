# "Leave out what a scene does not need", read from the generated source:
#   -DSPHC= -DMODEL= -DWORKDIR=
# For every body of the model, each feature of its kernel plan (sphc --dump=plan) must appear
# in the generated C exactly when the plan switches it on.  Prints one summary line per body.
get_filename_component(stem ${MODEL} NAME_WE)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
execute_process(COMMAND ${SPHC} --dump=plan ${MODEL} OUTPUT_VARIABLE plan RESULT_VARIABLE rc)
execute_process(COMMAND ${SPHC} --emit-c ${WORKDIR} --emit-only ${MODEL} RESULT_VARIABLE rc2)
if(NOT rc EQUAL 0 OR NOT rc2 EQUAL 0)
  message(FATAL_ERROR "sphc failed on ${MODEL}")
endif()
file(READ ${WORKDIR}/${stem}.c code)

# feature name -> a spelling that only the code of that feature contains (@B@ = body name);
# no square brackets: CMake lists treat them specially
set(marks
  "viscosity=Cv + (size_t)j"
  "beta2=d * (sph_real)(0.03125"
  "gravity=@B@_gravity"
  "velocity_bcs=@B@_velocity_bcs(sph_body"
  "force_bcs=@B@_force_bcs(sph_body"
  "hourglass=htab"
  "fracture=ltab"
  "restrict=@B@_restrict(sph_body"
  "state=st_new"
  "crush=sph_stretch2_min(F")

# the features of a body's own code (its boundary conditions, the bound of its phase field):
# a body that runs another body's code (sphc writes it once for bodies of the same text:
# compiler/emit/emit_share.c) has these in its own part, the rest in that body's
set(own_features velocity_bcs force_bcs restrict)

# The part of the code from body NAME's header to the next body's header (or the scene),
# into OUT; the name of the body whose code it runs into CODE_OF (NAME itself, or the body
# its header names).
function(body_part name out code_of)
  string(REGEX MATCH "/\\* ==== body ${name}(: the code of body ([A-Za-z0-9_]+)[^*]*)? ==== \\*/" head
         "${code}")
  if(NOT head)
    message(FATAL_ERROR "${stem}: no part of the code for body ${name}")
  endif()
  set(of ${name})
  if(CMAKE_MATCH_2)
    set(of ${CMAKE_MATCH_2})
  endif()
  string(FIND "${code}" "${head}" from)
  string(SUBSTRING "${code}" ${from} -1 rest)
  string(SUBSTRING "${rest}" 10 -1 after)
  string(FIND "${after}" "/* ==== body " next)
  if(next EQUAL -1)
    string(FIND "${after}" "static void model_velocity_bcs" next)
  endif()
  math(EXPR len "${next} + 10")
  string(SUBSTRING "${rest}" 0 ${len} rest)
  set(${out} "${rest}" PARENT_SCOPE)
  set(${code_of} ${of} PARENT_SCOPE)
endfunction()

# The features of a plan's entry for a body, those of its own code (boundary conditions,
# measurement planes) left out: what two bodies that run one code must have alike.
function(code_features entry out)
  string(REGEX MATCH "features: ([^\n]*)" _ "${entry}")
  string(REGEX REPLACE "(velocity_bcs|force_bcs|restrict|measure|bc_fns)=[0-9]+ ?" "" f
         "${CMAKE_MATCH_1}")
  set(${out} "${f}" PARENT_SCOPE)
endfunction()

string(REGEX MATCHALL "body [A-Za-z0-9_]+: dim [23][^\n]*\n[^\n]*features:[^\n]*" bodies "${plan}")
foreach(entry ${bodies})
  string(REGEX MATCH "^body ([A-Za-z0-9_]+)" _ "${entry}")
  set(body ${CMAKE_MATCH_1})
  body_part(${body} own code_body)
  set(rest "${own}")
  if(NOT code_body STREQUAL body)
    # runs another body's code: the code that body's part has, of the same plan (its
    # features, those of the boundary conditions and measurement planes apart)
    body_part(${code_body} rest of_that)
    if(NOT of_that STREQUAL code_body)
      message(FATAL_ERROR "${stem}/${body}: runs the code of ${code_body}, which runs ${of_that}'s")
    endif()
    foreach(e ${bodies})
      if(e MATCHES "^body ${code_body}:")
        code_features("${e}" features_that)
      endif()
    endforeach()
    code_features("${entry}" features_mine)
    if(NOT features_mine STREQUAL features_that)
      message(FATAL_ERROR "${stem}/${body}: runs the code of ${code_body}, whose features differ:\n"
                          "${features_mine}\n${features_that}")
    endif()
    message(STATUS "${stem}/${body}: runs the code of ${code_body}")
  endif()
  foreach(mark ${marks})
    string(REGEX MATCH "^([a-z_0-9]+)=(.*)$" _ "${mark}")
    set(feature ${CMAKE_MATCH_1})
    set(word "${CMAKE_MATCH_2}")
    list(FIND own_features ${feature} own_feature)
    if(NOT own_feature EQUAL -1)
      string(REPLACE "@B@" "${body}" word "${word}")
      set(part "${own}")
    else()
      string(REPLACE "@B@" "${code_body}" word "${word}")
      set(part "${rest}")
    endif()
    string(REGEX MATCH "${feature}=([01])" _ "${entry}")
    set(on ${CMAKE_MATCH_1})
    string(FIND "${part}" "${word}" at)
    if(on EQUAL 1 AND at EQUAL -1)
      message(FATAL_ERROR "${stem}/${body}: ${feature} is on but '${word}' is not in its code")
    endif()
    if(on EQUAL 0 AND NOT at EQUAL -1)
      message(FATAL_ERROR "${stem}/${body}: ${feature} is off but '${word}' is in its code")
    endif()
  endforeach()
  string(REGEX MATCH "fracture=([01])" _ "${entry}")
  set(frac ${CMAKE_MATCH_1})
  string(REGEX MATCH "state=([01])" _ "${entry}")
  set(state ${CMAKE_MATCH_1})
  set(words contact)
  if(state EQUAL 0)
    list(APPEND words plastic b->state st_new)
  endif()
  if(frac EQUAL 0)
    list(APPEND words phase fracture notch sph_sym_pos)
  endif()
  foreach(word ${words})
    string(FIND "${rest}" "${word}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${stem}/${body}: '${word}' in the code of a body without it")
    endif()
  endforeach()
  if(frac EQUAL 1)
    set(any_fracture 1)
  endif()
  # measurement planes: the body's table of them, in the scene's descriptions
  string(REGEX MATCH "measure=([01])" _ "${entry}")
  string(FIND "${code}" "sph_measure_desc ${body}_measures" at)
  if(CMAKE_MATCH_1 EQUAL 1 AND at EQUAL -1)
    message(FATAL_ERROR "${stem}/${body}: measure is on but its planes are not in the code")
  elseif(CMAKE_MATCH_1 EQUAL 0 AND NOT at EQUAL -1)
    message(FATAL_ERROR "${stem}/${body}: measurement planes in the code of a body without")
  endif()
  # one value function per boundary condition (its expression), none for another body's
  string(REGEX MATCH "bc_fns=([0-9]+)" _ "${entry}")
  set(want_fns ${CMAKE_MATCH_1})
  string(REGEX MATCHALL "SPH_FN int ${body}_bc[0-9]+\\(" fns "${own}")
  list(LENGTH fns nfns)
  if(NOT nfns EQUAL want_fns)
    message(FATAL_ERROR "${stem}/${body}: ${nfns} BC value functions for ${want_fns} BCs")
  endif()
  # the other dimension's code is not there (2D scenes: no 3D terms)
  string(REGEX MATCH "dim ([23])" _ "${entry}")
  if(CMAKE_MATCH_1 EQUAL 2)
    set(other "enum { D = 3 }")
  else()
    set(other "enum { D = 2 }")
  endif()
  string(FIND "${rest}" "${other}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${stem}/${body}: '${other}' in the code of a ${CMAKE_MATCH_1}D scene")
  endif()
  string(REGEX MATCH "features: ([^\n]*)" _ "${entry}")
  message(STATUS "${stem}/${body}: ${CMAKE_MATCH_1}")
endforeach()
# the tensor routines of the tension/compression split are included only when used
string(FIND "${code}" "sph_tensor.h" at)
if(NOT any_fracture AND NOT at EQUAL -1)
  message(FATAL_ERROR "${stem}: sph_tensor.h included without a body with fracture")
endif()
# contact (a scene feature): the contact pass and its description only in scenes with it
string(FIND "${plan}" "contact=1" contact_on)
foreach(word "sph_contact_forces, (s, dt)" "sph_contact_desc" ".restitution =")
  string(FIND "${code}" "${word}" at)
  if(NOT contact_on EQUAL -1 AND at EQUAL -1)
    message(FATAL_ERROR "${stem}: contact is on but '${word}' is not in its code")
  endif()
  if(contact_on EQUAL -1 AND NOT at EQUAL -1)
    message(FATAL_ERROR "${stem}: '${word}' in the code of a scene without contact")
  endif()
endforeach()
