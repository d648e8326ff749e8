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

# lib/ sources, relative to lib/, that the fuzz targets need (with lib/geo/gdal_raster.cpp,
# always its own library). A missing one shows as an
# undefined symbol when a <name>_libfuzzer target links.
set(STRIELAD_FUZZ_LIB_SOURCES
  core/checksum.cpp core/direct_read_file.cpp core/error.cpp core/file_io.cpp
  core/io_error.cpp core/strict_json.cpp core/text_columns.cpp
  export/vtp_declared_sizes.cpp export/vtp_reader.cpp export/vtp_writer.cpp
  extract/collapsed_triangles.cpp extract/collinear_slivers.cpp extract/conditions.cpp
  extract/geographic_conditions.cpp extract/mesh_builder.cpp extract/mesh_metrics.cpp
  extract/node_extraction.cpp extract/node_extractor.cpp extract/slice_extraction.cpp
  extract/tet_clipper.cpp
  format/manifest.cpp format/step_file_format.cpp
  geo/cf_calendar.cpp geo/cf_grid_mapping.cpp geo/cf_time.cpp geo/dem_gdal.cpp
  geo/dem_netcdf.cpp geo/dem_source.cpp geo/flight_tracks.cpp geo/flight_tracks_netcdf.cpp
  geo/grid_projection.cpp geo/standard_atmosphere.cpp
  geo/time_axis_dates.cpp
  grid/axis.cpp grid/longitude_turns.cpp grid/units.cpp
  ingest/cf_attributes.cpp ingest/cf_axis_detection.cpp ingest/classic_layout.cpp
  ingest/file_scan.cpp ingest/grid_compare.cpp ingest/grid_mapping_reader.cpp
  ingest/horizontal_axes.cpp ingest/input_catalog.cpp ingest/netcdf_call.cpp
  ingest/netcdf_file.cpp ingest/source_file.cpp ingest/variable_meta.cpp
  ingest/variable_selection.cpp
  lod/camera.cpp lod/camera_path_json.cpp lod/camera_path_validate.cpp
  lod/camera_path_world.cpp lod/world_frame.cpp
  octree/octree_layout.cpp
  protocol/mesh_encoding.cpp protocol/message_codec.cpp protocol/messages.cpp
  scene/scene_json.cpp scene/scene_resolve.cpp scene/scene_validate.cpp
  serve/mpi_messages.cpp serve/node_executor.cpp
  store/brick_cache.cpp store/brick_codec.cpp store/fpzip_chunk.cpp
  store/lorenzo_predictor.cpp store/store.cpp store/store_info.cpp
  store/store_verifier.cpp)
