# SPDX-License-Identifier: Apache-2.0
# STRIELAD_FUZZ_ONLY: the sanitizer fuzzing build scripts/fuzz.sh runs in CI. Every
# translation unit (library and fuzz targets) gets AddressSanitizer, UndefinedBehavior-
# Sanitizer (a report aborts) and libFuzzer's coverage instrumentation; only the library
# sources the fuzz targets use are compiled (STRIELAD_FUZZ_LIB_SOURCES below), and no
# tool, test, viewer or benchmark.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "STRIELAD_FUZZ_ONLY needs clang (libFuzzer): configure with "
                      "-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
endif()
set(STRIELAD_BUILD_FUZZ ON)
add_compile_options(-fsanitize=address,undefined,fuzzer-no-link
                    -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)

# lib/ sources, relative to lib/, that the fuzz targets need (lib/scenery/gdal_raster.cpp is
# always its own library). Whole folders where the readers and decoders live, so that a
# file added there is built here too; single files from the folders that are mostly
# something else. A missing one shows as an undefined symbol when a <name>_libfuzzer
# target links (scripts/fuzz.sh, run by CI, links every one).
set(STRIELAD_FUZZ_LIB_FOLDERS core export format geo grid ingest octree protocol scene scenery store)
set(STRIELAD_FUZZ_LIB_SOURCES
  extract/collapsed_triangles.cpp extract/collinear_slivers.cpp extract/conditions.cpp
  extract/geographic_conditions.cpp extract/mesh_builder.cpp extract/mesh_metrics.cpp
  extract/node_extraction.cpp extract/node_extractor.cpp extract/slice_extraction.cpp
  extract/tet_clipper.cpp
  lod/camera.cpp lod/camera_path_json.cpp lod/camera_path_validate.cpp
  lod/camera_path_world.cpp lod/world_frame.cpp
  serve/client_error_text.cpp serve/mpi_messages.cpp serve/node_executor.cpp)
foreach(folder IN LISTS STRIELAD_FUZZ_LIB_FOLDERS)
  file(GLOB folder_sources CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/lib
       ${PROJECT_SOURCE_DIR}/lib/${folder}/*.cpp)
  list(APPEND STRIELAD_FUZZ_LIB_SOURCES ${folder_sources})
endforeach()
list(REMOVE_ITEM STRIELAD_FUZZ_LIB_SOURCES scenery/gdal_raster.cpp)
