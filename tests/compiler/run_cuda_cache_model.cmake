# The order of the CUDA target's fixed slots does what it is for (runtime/cuda/full_lists.h,
# sph_slot_ranks): bench/cuda_cache_model.cpp traces the 3D momentum and stress passes' loads
# over the model's own pair lists through a model of a GPU's L1 cache (200 KB, two blocks of
# 256 threads), with the slots in the order of their offsets (the layout the target builds)
# and in the order of the table's keys (built with -DSPH_CUDA_SLOTS_BY_KEY).
#   -DSPHC= -DCXX= -DMODEL= -DINCLUDE= -DLIB= -DWORKDIR= -DPROBE= -DDP=
# The probe is compiled as the emulated builds are (-Wall -Wextra -Werror).
# MODEL's dp becomes DP.  The offsets' order must draw at most half the bytes from L2 per pair
# of the momentum pass that the keys' order draws (the 124 416 particles of cases/plate3d.sph
# at dp 2.5 mm: 22 against 166 bytes), and no more for the stress pass; the box's lists must
# be slot masks (sph_slot_masks), which must draw at most half the stress pass's bytes the
# lists draw (1.6 against 10.6) and no more of the momentum pass's; the default layout (holes
# near their slot's offset, u and v by component) must touch at most 0.8 of the L1 lines a
# pair that the keys' order with holes at i touched, in both passes (2.4 against 3.3, 0.5
# against 1.0); every hit rate must lie between 0 and 100 %.
set(src ${MODEL})
file(READ ${src} text)
string(REGEX REPLACE "\n( *dp) [0-9.e-]+" "\n\\1 ${DP}" text "${text}")
get_filename_component(stem ${src} NAME_WE)
set(MODEL ${WORKDIR}_model/${stem}.sph)
file(WRITE ${MODEL} "${text}")
set(EMIT_ONLY ON)
include(${CMAKE_CURRENT_LIST_DIR}/cuda_emulated_build.cmake)
file(RENAME ${WORKDIR}/${stem}.cu ${WORKDIR}/model.cu)
sph_emulated_compile(${WORKDIR}/probe ${PROBE} -I${WORKDIR})
execute_process(COMMAND ${WORKDIR}/probe --groups 8 RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the cache model failed (exit ${rc}):\n${err}")
endif()
# lines: layout pass hits% L2-bytes-per-pair L2-GB-per-step
foreach(layout packed key offset masks soa)
  foreach(pass momentum stress)
    if(NOT out MATCHES "\n${layout} +${pass} +([0-9.]+)% +([0-9.]+)")
      message(FATAL_ERROR "no line for ${layout} ${pass}")
    endif()
    if(CMAKE_MATCH_1 LESS_EQUAL 0 OR CMAKE_MATCH_1 GREATER 100)
      message(FATAL_ERROR "${layout} ${pass}: a hit rate of ${CMAKE_MATCH_1} %")
    endif()
  endforeach()
endforeach()
foreach(pass momentum stress)
  if(NOT out MATCHES "\n${pass}: bytes from L2, offset / key ([0-9.]+), masks / offset ([0-9.]+); L1 lines, soa / key ([0-9.]+)")
    message(FATAL_ERROR "no ratios for ${pass} (the box's lists must be slot masks)")
  endif()
  set(key_limit 1.0)
  set(mask_limit 1.0)
  if(pass STREQUAL momentum)
    set(key_limit 0.5)
  else()
    set(mask_limit 0.5)
  endif()
  if(CMAKE_MATCH_1 GREATER ${key_limit})
    message(FATAL_ERROR "${pass}: the offsets' order draws ${CMAKE_MATCH_1} of the bytes from L2 "
                        "per pair that the keys' order draws (at most ${key_limit})")
  endif()
  if(CMAKE_MATCH_3 GREATER 0.8)
    message(FATAL_ERROR "${pass}: the default layout's warps touch ${CMAKE_MATCH_3} of the L1 "
                        "lines a pair that the keys' order with holes at i touched (at most 0.8)")
  endif()
  if(CMAKE_MATCH_2 GREATER ${mask_limit})
    message(FATAL_ERROR "${pass}: the slot masks draw ${CMAKE_MATCH_2} of the bytes from L2 per "
                        "pair that the lists draw (at most ${mask_limit})")
  endif()
endforeach()
