# same_outputs(WHOLE PART): the output files (CSV, particle files, .pvd lists) in folder PART
# are those in WHOLE, byte for byte and no more; sets `compared` to how many there are.
function(same_outputs whole part)
  foreach(dir whole part)
    file(GLOB_RECURSE files_${dir} RELATIVE ${${dir}} ${${dir}}/*.csv ${${dir}}/*.vtu
         ${${dir}}/*.pvd)
  endforeach()
  list(LENGTH files_whole n)
  list(LENGTH files_part n_part)
  if(n LESS 3 OR NOT n EQUAL n_part)
    message(FATAL_ERROR "${part} holds ${n_part} output files, ${whole} ${n}")
  endif()
  foreach(f ${files_whole})
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${whole}/${f} ${part}/${f}
                    RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "${part}/${f} differs from ${whole}/${f}")
    endif()
  endforeach()
  set(compared ${n} PARENT_SCOPE)
endfunction()
