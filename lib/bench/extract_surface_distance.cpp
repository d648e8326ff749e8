// SPDX-License-Identifier: Apache-2.0
#include "bench/extract_surface_distance.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "bench/latency_stats.h"

namespace strielad::bench {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double dist2(const Point3& a, const Point3& b) {
  const Point3 d = sub(a, b);
  return dot(d, d);
}

}  // namespace

PointTree::PointTree(const std::vector<Point3>& points)
    : points_(points), ids_(points.size()), axis_(points.size(), 0) {
  std::iota(ids_.begin(), ids_.end(), 0u);
  build(0, points_.size());
}

void PointTree::build(std::size_t lo, std::size_t hi) {
  if (hi - lo <= 1) return;
  // Split along the axis of largest extent: surfaces are thin sheets, so a fixed cycle
  // of axes would make lopsided cells.
  Point3 mn{kInf, kInf, kInf}, mx{-kInf, -kInf, -kInf};
  for (std::size_t i = lo; i < hi; ++i) {
    for (int a = 0; a < 3; ++a) {
      mn[a] = std::min(mn[a], points_[i][a]);
      mx[a] = std::max(mx[a], points_[i][a]);
    }
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a) {
    if (mx[a] - mn[a] > mx[axis] - mn[axis]) axis = a;
  }
  const std::size_t mid = lo + (hi - lo) / 2;
  // Sort an index permutation of the range, then apply it to points and ids together.
  std::vector<std::uint32_t> order(hi - lo);
  std::iota(order.begin(), order.end(), 0u);
  std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(mid - lo),
                   order.end(), [&](std::uint32_t a, std::uint32_t b) {
                     const double pa = points_[lo + a][axis], pb = points_[lo + b][axis];
                     return pa < pb || (pa == pb && a < b);
                   });
  std::vector<Point3> p(hi - lo);
  std::vector<std::uint32_t> id(hi - lo);
  for (std::size_t i = 0; i < order.size(); ++i) {
    p[i] = points_[lo + order[i]];
    id[i] = ids_[lo + order[i]];
  }
  std::copy(p.begin(), p.end(), points_.begin() + static_cast<std::ptrdiff_t>(lo));
  std::copy(id.begin(), id.end(), ids_.begin() + static_cast<std::ptrdiff_t>(lo));
  axis_[mid] = static_cast<std::uint8_t>(axis);
  build(lo, mid);
  build(mid + 1, hi);
}

void PointTree::nearest(std::size_t lo, std::size_t hi, const Point3& p, double& best2) const {
  if (lo >= hi) return;
  const std::size_t mid = lo + (hi - lo) / 2;
  best2 = std::min(best2, dist2(p, points_[mid]));
  if (hi - lo == 1) return;
  const int axis = axis_[mid];
  const double d = p[axis] - points_[mid][axis];
  if (d < 0) {
    nearest(lo, mid, p, best2);
    if (d * d < best2) nearest(mid + 1, hi, p, best2);
  } else {
    nearest(mid + 1, hi, p, best2);
    if (d * d < best2) nearest(lo, mid, p, best2);
  }
}

double PointTree::nearest2(const Point3& p) const {
  double best2 = kInf;
  nearest(0, points_.size(), p, best2);
  return best2;
}

double point_triangle_distance2(const Point3& p, const Point3& a, const Point3& b,
                                const Point3& c) {
  const Point3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return dot(ap, ap);
  const Point3 bp = sub(p, b);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dot(bp, bp);
  auto at = [&](const Point3& o, const Point3& dir, double t) {
    return dist2(p, Point3{o[0] + t * dir[0], o[1] + t * dir[1], o[2] + t * dir[2]});
  };
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return at(a, ab, d1 / (d1 - d3));
  const Point3 cp = sub(p, c);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dot(cp, cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return at(a, ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return at(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denom = va + vb + vc;
  if (!(denom > 0)) {  // degenerate: the nearest of its edges
    const double e1 = at(a, ab, std::clamp(dot(ap, ab) / std::max(dot(ab, ab), 1e-300), 0.0, 1.0));
    const double e2 = at(a, ac, std::clamp(dot(ap, ac) / std::max(dot(ac, ac), 1e-300), 0.0, 1.0));
    const Point3 bc = sub(c, b);
    const double e3 = at(b, bc, std::clamp(dot(bp, bc) / std::max(dot(bc, bc), 1e-300), 0.0, 1.0));
    return std::min({e1, e2, e3});
  }
  const double v = vb / denom, w = vc / denom;
  return dist2(p, Point3{a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w,
                         a[2] + ab[2] * v + ac[2] * w});
}

namespace {

std::vector<Point3> centroids(const std::vector<Point3>& v, const std::vector<Triangle3>& t) {
  std::vector<Point3> out(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    for (int a = 0; a < 3; ++a) out[i][a] = (v[t[i][0]][a] + v[t[i][1]][a] + v[t[i][2]][a]) / 3.0;
  }
  return out;
}

}  // namespace

SurfaceDistance::SurfaceDistance(std::vector<Point3> vertices, std::vector<Triangle3> triangles)
    : vertices_(std::move(vertices)),
      triangles_(std::move(triangles)),
      vertex_tree_(vertices_),
      centroid_tree_(centroids(vertices_, triangles_)) {
  const std::vector<Point3> c = centroids(vertices_, triangles_);
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    for (std::uint32_t v : triangles_[i])
      max_radius_ = std::max(max_radius_, dist2(c[i], vertices_[v]));
  }
  max_radius_ = std::sqrt(max_radius_);
}

double SurfaceDistance::distance(const Point3& p) const {
  if (triangles_.empty()) return kInf;
  // The nearest vertex bounds the distance; a nearer triangle's centroid lies within that
  // bound plus max_radius_.
  double best2 = vertex_tree_.nearest2(p);
  double bound2 = std::pow(std::sqrt(best2) + max_radius_, 2);
  centroid_tree_.visit_within(p, bound2, [&](std::uint32_t t) {
    const Triangle3& tri = triangles_[t];
    const double d2 =
        point_triangle_distance2(p, vertices_[tri[0]], vertices_[tri[1]], vertices_[tri[2]]);
    if (d2 < best2) {
      best2 = d2;
      bound2 = std::pow(std::sqrt(best2) + max_radius_, 2);
    }
  });
  return std::sqrt(best2);
}

DistanceSummary surface_distances(const std::vector<Point3>& queries,
                                  const SurfaceDistance& surface) {
  DistanceSummary s;
  s.count = queries.size();
  if (queries.empty() || surface.empty()) {
    s.mean = s.p90 = s.max = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  std::vector<double> d(queries.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, queries.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        d[i] = surface.distance(queries[i]);
                    });
  double sum = 0;
  for (double x : d) sum += x;
  s.mean = sum / static_cast<double>(d.size());
  const Summary q = summarize(std::move(d));
  s.p90 = q.p90;
  s.max = q.max;
  return s;
}

}  // namespace strielad::bench
