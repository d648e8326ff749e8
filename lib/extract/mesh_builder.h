// SPDX-License-Identifier: Apache-2.0
// Collects the polygons of one node's extraction into indexed triangles. A vertex is
// one (group, exact lattice position): a group is one surface (a condition's zero
// plane or a node side) whose vertices share a normal rule. The kernel computes shared
// vertices canonically, so equal points are bit-identical, and it finds most of them by
// the lattice element they lie on (a corner or a lattice edge: at most one vertex per
// element and group, add_vertex). Points it cannot name that way (inside lattice
// triangles and tetrahedra, from the general clipper) are welded by position
// (vertex): the first such call indexes every vertex so far by position, and from
// then on add_vertex welds by position too.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace strielad {

class MeshBuilder {
 public:
  // Forgets every vertex and triangle (keeps the buffers).
  void reset();

  // The vertex of a point that no earlier add_vertex call made for this group unless
  // by the same position (then that vertex, once positional welding is on).
  std::uint32_t add_vertex(std::uint32_t group, const Vec3& p) {
    if (hashing_) return vertex(group, p);
    const auto v = static_cast<std::uint32_t>(points.size());
    // Element by element: p is often just computed, and a whole-array copy would wait
    // for its three stores.
    Vec3& q = points.emplace_back();
    q[0] = p[0];
    q[1] = p[1];
    q[2] = p[2];
    vertex_groups.push_back(group);
    return v;
  }

  // The vertex of (group, p), welded by exact position with every vertex made so far.
  std::uint32_t vertex(std::uint32_t group, const Vec3& p);

  // A convex planar polygon in lattice coordinates whose outward side faces
  // `outward`; repeated points are dropped, collinear points never make a zero-area
  // triangle. `pts` is scratch (reordered).
  // `indices` (optional, same length) are the points' vertex ids when known.
  void polygon(std::uint32_t group, Vec3* pts, std::size_t count, const Vec3& outward,
               std::uint32_t* indices = nullptr);

  // A convex planar polygon of vertex ids already in outward (counter-clockwise)
  // order: repeated vertices are dropped, no zero-area triangle is made. `ids` is
  // scratch.
  void oriented_polygon(std::uint32_t group, std::uint32_t* ids, std::size_t count) {
    std::size_t m = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (m > 0 && ids[i] == ids[m - 1]) continue;
      ids[m++] = ids[i];
    }
    while (m > 1 && ids[m - 1] == ids[0]) --m;
    if (m == 3 && has_area(ids[0], ids[1], ids[2])) {
      triangle(group, ids[0], ids[1], ids[2]);
    } else if (m == 4 && has_area(ids[0], ids[1], ids[2]) && has_area(ids[0], ids[2], ids[3])) {
      triangle(group, ids[0], ids[1], ids[2]);
      triangle(group, ids[0], ids[2], ids[3]);
    } else if (m >= 4) {
      fan(group, ids, m);
    } else if (count != 0) {
      maybe_unused_ = true;  // its vertices may be in no triangle
    }
  }

  // The same for a triangle and a quadrilateral, ids passed by value (the hot path:
  // an id array written just before would be read back in wider loads).
  void oriented_triangle(std::uint32_t group, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (a != b && b != c && a != c && has_area(a, b, c)) {
      triangle(group, a, b, c);
    } else {
      maybe_unused_ = true;
    }
  }
  void oriented_quad(std::uint32_t group, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                     std::uint32_t d) {
    if (a != b && a != c && a != d && b != c && b != d && c != d && has_area(a, b, c) &&
        has_area(a, c, d)) {
      triangle(group, a, b, c);
      triangle(group, a, c, d);
    } else {
      std::uint32_t ids[4]{a, b, c, d};
      oriented_polygon(group, ids, 4);
    }
  }

  void triangle(std::uint32_t group, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (triangle_count_ == triangles_.size()) grow_triangles();
    auto& t = triangles_[triangle_count_];
    t[0] = a;
    t[1] = b;
    t[2] = c;
    triangle_groups_[triangle_count_] = group;
    ++triangle_count_;
  }

  // The triangles so far (vertex ids, counter-clockwise seen from outside in lattice
  // coordinates) and the group of each.
  std::size_t triangle_count() const { return triangle_count_; }
  const std::array<std::uint32_t, 3>* triangles() const { return triangles_.data(); }
  const std::uint32_t* triangle_groups() const { return triangle_groups_.data(); }

  // Drops the vertices no triangle uses (a degenerate polygon may leave some behind),
  // renumbering the triangles.
  void drop_unused_vertices();

  bool has_area(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
    const Vec3 n = cross(sub(points[b], points[a]), sub(points[c], points[a]));
    return n[0] != 0 || n[1] != 0 || n[2] != 0;
  }

  std::vector<Vec3> points;
  std::vector<std::uint32_t> vertex_groups;

 private:
  void index_all(std::size_t room);
  void grow_triangles();
  void fan(std::uint32_t group, const std::uint32_t* ids, std::size_t m);

  // Triangles [0, triangle_count_) of buffers kept across extractions (sized, not
  // reserved: the hot path writes without a capacity check beyond one compare).
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<std::uint32_t> triangle_groups_;
  std::size_t triangle_count_ = 0;
  bool hashing_ = false;
  bool maybe_unused_ = false;
  std::size_t largest_ = 0;  // most vertices of an extraction so far
  std::vector<std::uint32_t> renumber_;
  struct HashSlot {
    std::uint32_t stamp = 0;  // occupied when equal to hash_stamp_
    std::uint32_t vertex = 0;
  };
  std::vector<HashSlot> slots_;  // open addressing by (group, position)
  std::uint32_t hash_stamp_ = 0;
  std::size_t mask_ = 0;
};

}  // namespace strielad
