# SPDX-License-Identifier: Apache-2.0
# All third-party dependencies come from Debian 12 packages (see scripts/install-deps.sh).
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)

# oneTBB must be found before OpenVDB's FindOpenVDB (toolchain.md pitfall 2).
find_package(TBB REQUIRED CONFIG)

list(APPEND CMAKE_MODULE_PATH /usr/lib/x86_64-linux-gnu/cmake/OpenVDB)
find_package(OpenVDB REQUIRED)

find_package(netCDF REQUIRED CONFIG)
# HDF5 directly only to silence its per-thread error printing (lib/ingest/netcdf_call.cpp);
# the serial build, which netCDF links (toolchain.md pitfall 3: VTK pulls in the MPI one).
pkg_check_modules(HDF5_SERIAL REQUIRED IMPORTED_TARGET hdf5-serial)
pkg_check_modules(BLOSC REQUIRED IMPORTED_TARGET blosc)
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)
pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)
# GRIB input (ingest). Debian 12 builds ecCodes without thread support: one mutex
# guards every call (ingest/eccodes_call.h).
# Not through eccodes.pc (Debian 12's points at a missing include folder) nor its CMake
# config (which requires the command-line tools to be installed).
find_path(ECCODES_INCLUDE_DIR eccodes.h REQUIRED)
find_library(ECCODES_LIBRARY eccodes REQUIRED)
if(NOT TARGET strielad_deps::eccodes)
  add_library(strielad_deps::eccodes INTERFACE IMPORTED)
  set_target_properties(strielad_deps::eccodes PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES ${ECCODES_INCLUDE_DIR}
    INTERFACE_LINK_LIBRARIES ${ECCODES_LIBRARY})
endif()
# fpzip: the lossless floating-point coder of store version 3 (formats/store.md).
find_package(fpzip REQUIRED CONFIG)
# zfp 1.0 (libzfp-dev): the error-bounded lossy coder of store version 6 (formats/store.md,
# "zfp chunks"), through Debian's CMake config (target zfp::zfp).
find_package(zfp 1.0 REQUIRED CONFIG)
find_package(spdlog REQUIRED CONFIG)
find_package(fmt REQUIRED CONFIG)
find_package(CLI11 REQUIRED CONFIG)
find_package(nlohmann_json REQUIRED CONFIG)
# PROJ 9.1 (libproj-dev): grid mappings (rotated poles, Lambert, polar stereographic ...)
# placed by pipelines built from their CF attributes (lib/geo/grid_projection.cpp).
find_package(PROJ CONFIG REQUIRED)
# GDAL 3.6 (libgdal-dev): terrain from GeoTIFF and any other raster format, drape images
# (lib/scenery/gdal_raster.cpp). Only its C API is used.
find_package(GDAL CONFIG REQUIRED)

# Open MPI 4.1 (libopenmpi-dev): strielad-serve's MPI mode only (lib/serve/mpi_*.cpp, in
# the strielad_serve_mpi library; docs/cluster.md). Only
# the C API is used, so the deprecated C++ bindings are skipped.
set(MPI_CXX_SKIP_MPICXX ON CACHE BOOL "Skip the MPI C++ bindings" FORCE)
find_package(MPI REQUIRED COMPONENTS CXX)

# VTK 9.1 for the paper's extraction pipeline (lib/peers) and .vtp export (lib/export).
# Only the modules used: every extra module adds imported targets and transitive
# find_package calls. Found after TBB and OpenVDB (toolchain.md pitfall 2). None of these
# modules depends on VTK's HDF5, so hdf5-mpi is not pulled into the build (pitfall 3).
find_package(VTK 9.1 REQUIRED COMPONENTS
  CommonCore            # vtkFloatArray, vtkSMPTools
  CommonDataModel       # vtkRectilinearGrid, vtkImageData, vtkPolyData, vtkPlane
  CommonExecutionModel  # vtkAlgorithm (pipelines)
  FiltersCore           # vtkFlyingEdges3D, vtkTriangleFilter, vtkPolyDataNormals,
                        # vtkMassProperties, vtkFeatureEdges, vtkThreshold
  FiltersGeneral        # vtkTableBasedClipDataSet
  FiltersGeometry       # vtkDataSetSurfaceFilter
  FiltersParallel       # vtkIntegrateAttributes (its only factory override is
                        # vtkConvertToMultiBlockDataSet, unused here)
  IOXML)                # vtkXMLPolyDataWriter/Reader

# The viewer (lib/render, cmd/strielad-view): OpenGL through libepoxy, contexts through
# EGL (headless) and GLFW (windows), PNG through stb, the panel through Dear ImGui 1.86
# (a static library with its GLFW and OpenGL 3 backends).
pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
pkg_check_modules(GLFW REQUIRED IMPORTED_TARGET glfw3)
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
