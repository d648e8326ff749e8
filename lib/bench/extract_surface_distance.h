// SPDX-License-Identifier: Apache-2.0
// Point-to-surface distances for the level error of `strielad-bench extract`: the exact
// Euclidean distance from a point to the nearest triangle of a triangle soup (in level-0
// index space), found with two static k-d trees: the nearest vertex bounds the answer
// from above, then only triangles whose centroid lies within that bound plus the largest
// centroid-to-corner distance can be nearer.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace strielad::bench {

using Point3 = Vec3;
using Triangle3 = std::array<std::uint32_t, 3>;

// A static k-d tree over points, each carrying its index in the input.
class PointTree {
 public:
  explicit PointTree(const std::vector<Point3>& points);
  bool empty() const { return points_.empty(); }
  // Squared distance to the nearest point (+inf when empty).
  double nearest2(const Point3& p) const;
  // Calls visit(index) for points within sqrt(bound2) of p, where visit may lower
  // bound2 (pruning the rest of the search with it).
  template <typename Visit>
  void visit_within(const Point3& p, double& bound2, Visit&& visit) const {
    visit_within(0, points_.size(), p, bound2, visit);
  }

 private:
  void build(std::size_t lo, std::size_t hi);
  void nearest(std::size_t lo, std::size_t hi, const Point3& p, double& best2) const;
  template <typename Visit>
  void visit_within(std::size_t lo, std::size_t hi, const Point3& p, double& bound2,
                    Visit& visit) const;
  std::vector<Point3> points_;      // reordered into the implicit tree
  std::vector<std::uint32_t> ids_;  // input index of points_[i]
  std::vector<std::uint8_t> axis_;  // split axis of the subtree whose median is at i
};

class SurfaceDistance {
 public:
  SurfaceDistance(std::vector<Point3> vertices, std::vector<Triangle3> triangles);
  bool empty() const { return triangles_.empty(); }
  // Distance from p to the nearest point of any triangle; +inf when there is none.
  double distance(const Point3& p) const;

 private:
  std::vector<Point3> vertices_;
  std::vector<Triangle3> triangles_;
  PointTree vertex_tree_, centroid_tree_;
  double max_radius_ = 0;  // largest centroid-to-corner distance
};

// Squared distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection
// 5.1.5); degenerate triangles work.
double point_triangle_distance2(const Point3& p, const Point3& a, const Point3& b, const Point3& c);

struct DistanceSummary {
  std::uint64_t count = 0;
  double mean = 0, p90 = 0, max = 0;  // NaN when there is no query or no surface
};

// Distances from every query to the surface (in parallel; the result does not depend on
// the thread count).
DistanceSummary surface_distances(const std::vector<Point3>& queries,
                                  const SurfaceDistance& surface);

// The template's body, here so that callers can pass lambdas.
template <typename Visit>
void PointTree::visit_within(std::size_t lo, std::size_t hi, const Point3& p, double& bound2,
                             Visit& visit) const {
  if (lo >= hi) return;
  const std::size_t mid = lo + (hi - lo) / 2;
  const Point3& q = points_[mid];
  const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
  if (dx * dx + dy * dy + dz * dz <= bound2) visit(ids_[mid]);
  if (hi - lo == 1) return;
  const int axis = axis_[mid];
  const double d = p[axis] - q[axis];
  if (d < 0) {
    visit_within(lo, mid, p, bound2, visit);
    if (d * d <= bound2) visit_within(mid + 1, hi, p, bound2, visit);
  } else {
    visit_within(mid + 1, hi, p, bound2, visit);
    if (d * d <= bound2) visit_within(lo, mid, p, bound2, visit);
  }
}

}  // namespace strielad::bench
