// SPDX-License-Identifier: Apache-2.0
// Writes the files of a store's grid geometry (formats/store.md, "Geometry file" and
// "Geometry bricks"): GEOMETRY and geometry.bricks. Both are written before any step
// file, through a temporary sibling and a rename, and never change: a writer that finds
// one must find it byte for byte what it would write, so a re-run leaves it as it is and
// a different one (another plan's) is refused.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "convert/brick_encoder.h"
#include "format/geometry_file_format.h"

namespace strielad::build {

// Writes STORE/GEOMETRY. Returns true when it wrote the file, false when the same bytes
// were there already; throws kCorrupt naming the file when different bytes are there and
// kInvalidArgument when the arrays break a rule a reader checks.
bool write_geometry_file(const std::filesystem::path& store, const format::GeometryFile& file);

// Writes STORE/geometry.bricks through `write`, which writes the complete file at the
// path it is given (a temporary sibling), then publishes it, or compares it byte for byte
// with the one there. Returns and throws as write_geometry_file.
bool publish_geometry_bricks(const std::filesystem::path& store,
                             const std::function<void(const std::filesystem::path&)>& write);

// Writes STORE/geometry.bricks: the time-invariant vertical field, one encoded brick per
// node in node-id order (the octree's node_count), as a step file with step
// format::kGeometryStep and one section. Returns and throws as write_geometry_file.
bool write_geometry_bricks(const std::filesystem::path& store, std::uint64_t store_id,
                           std::vector<EncodedBrick> bricks);

}  // namespace strielad::build
