// SPDX-License-Identifier: Apache-2.0
// A closed, outward-oriented triangle mesh of one sub-volume inside one octree node
// (formats/scene.md, "Extraction output").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace strielad {

// Where a triangle lies: on a limit's iso-surface (or the edge of missing data), on a
// node face shared with a neighbouring node (a seamless export drops these), on the
// scene's domain box, or on a node face that is the edge of the dataset's grid.
enum class FaceKind : std::uint8_t {
  kLimit = 0,
  kNodeBoundary = 1,
  kDomainBox = 2,
  kGridBoundary = 3,
  // A slice's triangle (formats/scene.md, "Slices"): slice meshes carry only this kind
  // and are not closed.
  kSlice = 4,
};

struct Mesh {
  std::uint32_t subvolume_id = 0;
  // Vertex positions in the dataset's axis coordinates (x, y, z as in the manifest:
  // e.g. lon degrees, lat degrees, height metres). Double: in float, a lon of 170
  // degrees resolves only 1/1000 of a full-resolution cell, which would collapse
  // distinct vertices into zero-area triangles (the wire format quantizes per node).
  std::vector<std::array<double, 3>> positions;
  // Unit outward normals in the same frame (never NaN, never zero-length).
  std::vector<std::array<float, 3>> normals;
  // Counter-clockwise seen from outside.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<FaceKind> face_kinds;  // one per triangle
  // Per-vertex attribute values, attributes[a][vertex]; NaN where the attribute is
  // missing at that point.
  std::vector<std::string> attribute_names;
  std::vector<std::vector<float>> attributes;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }
  friend bool operator==(const Mesh&, const Mesh&) = default;
};

}  // namespace strielad
