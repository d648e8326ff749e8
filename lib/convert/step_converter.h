// SPDX-License-Identifier: Apache-2.0
// Converts one time step (every variable, and a time-varying grid geometry field as the
// last section) into its step file. Memory stays bounded: the
// full-resolution level is streamed in slabs of one brick layer (B+3 planes), while the
// coarser levels (at most 1/4 of the data) are held densely.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>

#include "format/manifest.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "octree/octree_layout.h"

namespace strielad::build {

struct StepCounts {
  std::uint64_t input_bytes = 0;   // source bytes read (samples x source type size)
  std::uint64_t chunk_bytes = 0;
  std::uint64_t file_bytes = 0;
  std::uint64_t empty = 0, constant = 0, data = 0;  // bricks by kind, all variables
  // Data bricks of lossy variables: coded by zfp, and kept lossless because zfp missed
  // the bound (build/brick_encoder.h).
  std::uint64_t lossy = 0, lossy_fallback = 0;
};

// Called with the number of source bytes just read.
using ProgressFn = std::function<void(std::uint64_t bytes)>;

StepCounts convert_step(const format::Manifest& manifest, const OctreeLayout& layout,
                        ingest::SlabReader& reader, std::uint32_t step,
                        const std::filesystem::path& out_path, const ProgressFn& progress);

// The time-invariant grid geometry field (manifest.geometry, vertical kind field, not
// varying in time) as the file geometry.bricks (formats/store.md, "Geometry bricks"),
// evaluated at time step 0. \error kInvalidInput naming the source variables, the sample
// and the step for a column whose height or pressure is not strictly monotonic in the
// direction of column (0, 0), or missing.
StepCounts convert_geometry_bricks(const format::Manifest& manifest, const OctreeLayout& layout,
                                   ingest::SlabReader& reader,
                                   const std::filesystem::path& out_path);

// Bytes per sample of a netCDF source type name ("float" -> 4, "short" -> 2 ...).
std::size_t source_type_size(std::string_view type);

}  // namespace strielad::build
