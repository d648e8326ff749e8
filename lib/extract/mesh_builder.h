// SPDX-License-Identifier: Apache-2.0
// Collects the polygons of one node's extraction into indexed triangles. Vertices are
// welded by (group, exact lattice position): the kernel computes shared vertices
// canonically, so equal points are bit-identical. A group is one surface (a
// condition's zero plane or a node side) whose vertices share a normal rule.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "extract/vec3.h"

namespace strielad {

class MeshBuilder {
 public:
  MeshBuilder();

  // A convex planar polygon in lattice coordinates whose outward side faces
  // `outward`; repeated points are dropped, collinear points never make a zero-area
  // triangle. `pts` is scratch (reordered).
  // `indices` (optional, same length) are the points' vertex ids when known.
  void polygon(std::uint32_t group, Vec3* pts, std::size_t count, const Vec3& outward,
               std::uint32_t* indices = nullptr);

  std::uint32_t vertex(std::uint32_t group, const Vec3& p);

  // Per-extraction cache of one vertex per lattice edge slot (sample * 7 + direction),
  // so a crossing shared by up to six tetrahedra is welded without hashing. Call
  // begin_edges once per extraction.
  void begin_edges(std::size_t slots);
  std::uint32_t edge_vertex(std::uint32_t group, std::size_t slot, const Vec3& p) {
    EdgeSlot& e = edges_[slot];
    if (e.stamp == stamp_ && e.group == group) return e.vertex;
    const std::uint32_t v = vertex(group, p);
    if (e.stamp != stamp_) e = EdgeSlot{stamp_, group, v};
    return v;
  }

  struct EdgeSlot {
    std::uint32_t stamp = 0, group = 0, vertex = 0;
  };

  std::vector<Vec3> points;
  std::vector<std::uint32_t> vertex_groups;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> triangle_groups;

 private:
  void grow();
  // The slots live per thread across extractions (stamped, never cleared): a fresh
  // array per node would cost ~0.8 MB of zeroed pages per 25^3 brick.
  EdgeSlot* edges_ = nullptr;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> slots_;  // vertex index + 1; 0 = empty
  std::size_t mask_ = 0;
};

}  // namespace strielad
