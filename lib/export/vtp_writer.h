// SPDX-License-Identifier: Apache-2.0
// Batch export of extraction meshes as one VTK XML PolyData file (.vtp) that ParaView
// opens, for batch use without the viewer. VTK types stay inside vtp_writer.cpp.
//
// File content (VTK XML, appended raw binary, zlib-compressed blocks, UInt64 headers):
//   Points      Float64 x 3 (Float32 on request), the meshes' positions in dataset axis
//               coordinates
//   Polys       triangles, counter-clockwise seen from outside
//   CellData    subvolume_id (UInt32), node_id (UInt32), face_kind (UInt8: 0 limit,
//               1 node boundary, 2 domain box, 3 grid edge; see extract/mesh.h)
//   FieldData   one string array per VtpOptions::field_data entry (strielad-serve extract
//               writes `frame`, `vertical_placement` and, on mapped grids, `grid_mapping`)
//   PointData   Normals (Float32 x 3, the active normals), then one Float32 array per
//               attribute name, in order of first appearance over the meshes; a mesh
//               without that attribute writes NaN for its vertices
// Meshes are written one after another in the order given; vertices are not merged
// across meshes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "extract/mesh.h"

namespace strielad {

struct NodeMeshRef {
  std::uint32_t node_id = 0;
  const Mesh* mesh = nullptr;
};

struct VtpOptions {
  // Leave out triangles whose face kind is kNodeBoundary (faces shared with the
  // neighbouring node) and the vertices only they used: a seamless export of a level.
  bool drop_node_boundary_faces = false;
  // Write the face_kind cell array.
  bool face_kind_array = true;
  // Points as Float32 (half the bytes): loses the exactness of Mesh's double positions
  // (a lon of 170 degrees resolves ~1e-5 degrees), fine for viewing.
  bool float32_points = false;
  // zlib level, 1 (fast) to 9 (small).
  int compression_level = 5;
  // Text metadata as FieldData string arrays (name, value): the frame, the vertical
  // placement, the grid mapping.
  std::vector<std::pair<std::string, std::string>> field_data{};
};

struct VtpSummary {
  std::uint64_t points = 0;
  std::uint64_t triangles = 0;
  std::uint64_t dropped_triangles = 0;  // node-boundary faces left out
  std::uint64_t bytes = 0;              // file size
};

// Writes `meshes` to `path` atomically (a temporary sibling, fsync'ed and renamed: a
// reader never sees a partial file). Overwrites an existing file.
// \error kInvalidArgument (naming the file and node) if a mesh is null or inconsistent:
//        a triangle index out of range, normals or face_kinds or an attribute not of the
//        right length, more than 2^32 points, or compression_level outside 1..9.
// \error kIo / kNotFound (naming the file) if the file cannot be written.
// \error kInternal if VTK's writer fails.
VtpSummary write_vtp(const std::filesystem::path& path, std::span<const NodeMeshRef> meshes,
                     const VtpOptions& options = {});

}  // namespace strielad
