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
  "beta2=Gc * Gc"
  "gravity=@B@_gravity"
  "velocity_bcs=@B@_velocity_bcs(sph_body"
  "force_bcs=@B@_force_bcs(sph_body"
  "hourglass=htab"
  "fracture=ltab"
  "restrict=@B@_restrict(sph_body"
  "state=st_new"
  "crush=sph_stretch2_min(F")

string(REGEX MATCHALL "body [A-Za-z0-9_]+: dim [23][^\n]*\n[^\n]*features:[^\n]*" bodies "${plan}")
foreach(entry ${bodies})
  string(REGEX MATCH "^body ([A-Za-z0-9_]+)" _ "${entry}")
  set(body ${CMAKE_MATCH_1})
  # the code of this body: from its header to the next body's header (or the scene)
  string(FIND "${code}" "/* ==== body ${body} ==== */" from)
  string(SUBSTRING "${code}" ${from} -1 rest)
  string(SUBSTRING "${rest}" 10 -1 after)
  string(FIND "${after}" "/* ==== body " next)
  if(next EQUAL -1)
    string(FIND "${after}" "static void model_velocity_bcs" next)
  endif()
  math(EXPR len "${next} + 10")
  string(SUBSTRING "${rest}" 0 ${len} rest)
  foreach(mark ${marks})
    string(REGEX MATCH "^([a-z_0-9]+)=(.*)$" _ "${mark}")
    set(feature ${CMAKE_MATCH_1})
    string(REPLACE "@B@" "${body}" word "${CMAKE_MATCH_2}")
    string(REGEX MATCH "${feature}=([01])" _ "${entry}")
    set(on ${CMAKE_MATCH_1})
    string(FIND "${rest}" "${word}" at)
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
foreach(word "sph_contact_forces(s, dt)" "sph_contact_desc" ".restitution =")
  string(FIND "${code}" "${word}" at)
  if(NOT contact_on EQUAL -1 AND at EQUAL -1)
    message(FATAL_ERROR "${stem}: contact is on but '${word}' is not in its code")
  endif()
  if(contact_on EQUAL -1 AND NOT at EQUAL -1)
    message(FATAL_ERROR "${stem}: '${word}' in the code of a scene without contact")
  endif()
endforeach()
