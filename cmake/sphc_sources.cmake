# sphc_sources.cmake — the compiler's sources, for sphc and for the fuzz targets (fuzz/):
# the bison parser and the flex scanner generated into the current binary folder, the files
# of the stage folders, and the runtime's surface reader that the checker uses.
#
#   sphc_sources(NAME)   sets SPHC_SOURCES (compiler/**/*.c, main.c included),
#                        SPHC_GENERATED (parser.c, lexer.c) and SPHC_MESH_SOURCES
macro(sphc_sources name)
  BISON_TARGET(${name}_parser ${PROJECT_SOURCE_DIR}/compiler/front/parser.y
               ${CMAKE_CURRENT_BINARY_DIR}/parser.c
               DEFINES_FILE ${CMAKE_CURRENT_BINARY_DIR}/parser.h
               COMPILE_FLAGS "-Wall -Wno-other")
  FLEX_TARGET(${name}_lexer ${PROJECT_SOURCE_DIR}/compiler/front/lexer.l
              ${CMAKE_CURRENT_BINARY_DIR}/lexer.c
              DEFINES_FILE ${CMAKE_CURRENT_BINARY_DIR}/lexer.h)
  ADD_FLEX_BISON_DEPENDENCY(${name}_lexer ${name}_parser)
  set(SPHC_GENERATED ${BISON_${name}_parser_OUTPUTS} ${FLEX_${name}_lexer_OUTPUTS})
  # Generated scanner code is not ours to keep warning-free in every detail.
  set_source_files_properties(${FLEX_${name}_lexer_OUTPUTS} PROPERTIES
                              COMPILE_OPTIONS "-Wno-unused-function;-Wno-sign-compare")
  # One folder per stage (docs/architecture.md); files include each other as "stage/file.h".
  file(GLOB_RECURSE SPHC_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/compiler/*.c)
  # The compiler checks surface files and solids with the runtime's code (runtime/geom/mesh.h).
  set(SPHC_MESH_SOURCES ${PROJECT_SOURCE_DIR}/runtime/geom/mesh_read.c
      ${PROJECT_SOURCE_DIR}/runtime/geom/mesh_check.c ${PROJECT_SOURCE_DIR}/runtime/geom/mesh_ray.c
      ${PROJECT_SOURCE_DIR}/runtime/geom/mesh_solid.c)
endmacro()
