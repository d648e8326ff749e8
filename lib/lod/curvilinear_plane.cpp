// SPDX-License-Identifier: Apache-2.0
#include "lod/curvilinear_plane.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "format/curvilinear_lonlat.h"
#include "lod/world_frame.h"

namespace strielad::lod {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double cross(const std::array<double, 2>& o, const std::array<double, 2>& a,
             const std::array<double, 2>& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

}  // namespace

CurvilinearPlane::CurvilinearPlane(const format::HorizontalCoordinates& c, double lon0,
                                   double lat0, double km_per_lon, const std::string& what)
    : nx_(c.nx), ny_(c.ny) {
  if (nx_ < 2 || ny_ < 2 || c.lon.size() != nx_ * ny_ || c.lat.size() != nx_ * ny_) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: a curvilinear grid needs at least 2 x 2 longitudes and latitudes, one "
                     "per column ({} x {} columns, {} longitudes, {} latitudes)",
                     what, nx_, ny_, c.lon.size(), c.lat.size());
  }
  xy_.resize(nx_ * ny_);
  for (std::size_t k = 0; k < xy_.size(); ++k) {
    xy_[k] = {std::remainder(c.lon[k] - lon0, 360.0) * km_per_lon,
              (c.lat[k] - lat0) * kKmPerDegree};
  }
  check_tears(lon0, km_per_lon, what);
  find_orientation(what);
  build_buckets();
}

void CurvilinearPlane::check_tears(double lon0, double km_per_lon, const std::string& what) const {
  const double half_turn_km = 180.0 * km_per_lon;
  for (std::size_t j = 0; j < ny_; ++j) {
    for (std::size_t i = 0; i < nx_; ++i) {
      for (const auto& [di, dj] : {std::pair<std::size_t, std::size_t>{1, 0}, {0, 1}}) {
        if (i + di >= nx_ || j + dj >= ny_) continue;
        if (std::fabs(at(i + di, j + dj)[0] - at(i, j)[0]) > half_turn_km) {
          throw make_error(ErrorCode::kUnsupported,
                           "{}: columns ({}, {}) and ({}, {}) lie on both sides of longitude "
                           "{:.2f}, opposite the domain's centre (the grid goes round a pole or "
                           "across the whole Earth): the viewer's plane cannot show it",
                           what, i, j, i + di, j + dj, std::remainder(lon0 + 180.0, 360.0));
        }
      }
    }
  }
}

// A bilinear cell maps one to one when its Jacobian's determinant keeps one sign; that
// determinant is affine in each fraction, so its signs at the four corners decide.
void CurvilinearPlane::find_orientation(const std::string& what) {
  int orientation = 0;
  for (std::size_t j = 0; j + 1 < ny_; ++j) {
    for (std::size_t i = 0; i + 1 < nx_; ++i) {
      const auto &p00 = at(i, j), &p10 = at(i + 1, j), &p01 = at(i, j + 1),
                 &p11 = at(i + 1, j + 1);
      const double d[4] = {cross(p00, p10, p01), cross(p10, p11, p00), cross(p11, p01, p10),
                           cross(p01, p00, p11)};
      for (double det : d) {
        const int s = det > 0 ? 1 : det < 0 ? -1 : 0;
        if (orientation == 0) orientation = s;
        if (s == 0 || s != orientation) {
          throw make_error(ErrorCode::kUnsupported,
                           "{}: the cell from column ({}, {}) to ({}, {}) is {} on the viewer's "
                           "plane: the viewer cannot place a grid that folds over itself",
                           what, i, j, i + 1, j + 1, s == 0 ? "degenerate" : "folded");
        }
      }
    }
  }
  orientation_ = orientation;
}

void CurvilinearPlane::build_buckets() {
  extent_ = {INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const auto& p : xy_) {
    extent_[0] = std::min(extent_[0], p[0]);
    extent_[1] = std::min(extent_[1], p[1]);
    extent_[2] = std::max(extent_[2], p[0]);
    extent_[3] = std::max(extent_[3], p[1]);
  }
  const std::size_t cells = (nx_ - 1) * (ny_ - 1);
  const double w = std::max(extent_[2] - extent_[0], 1e-9);
  const double h = std::max(extent_[3] - extent_[1], 1e-9);
  // About two cells per bucket, buckets about square.
  const double per_side = std::sqrt(double(cells) / 2.0 / (w * h));
  bx_ = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(w * per_side)), 1, 4096);
  by_ = std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(h * per_side)), 1, 4096);
  bucket_w_ = w / double(bx_);
  bucket_h_ = h / double(by_);
  const auto range = [&](std::size_t i0, std::size_t j0) {
    std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const auto& p : {at(i0, j0), at(i0 + 1, j0), at(i0, j0 + 1), at(i0 + 1, j0 + 1)}) {
      b = {std::min(b[0], p[0]), std::min(b[1], p[1]), std::max(b[2], p[0]),
           std::max(b[3], p[1])};
    }
    const auto bucket = [](double v, double lo, double size, std::size_t n) {
      return std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::max(0.0, (v - lo) / size)));
    };
    return std::array<std::size_t, 4>{bucket(b[0], extent_[0], bucket_w_, bx_),
                                      bucket(b[1], extent_[1], bucket_h_, by_),
                                      bucket(b[2], extent_[0], bucket_w_, bx_),
                                      bucket(b[3], extent_[1], bucket_h_, by_)};
  };
  // Two passes: counts, then the cells (compressed rows).
  bucket_start_.assign(bx_ * by_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t b = 1; b < bucket_start_.size(); ++b) bucket_start_[b] += bucket_start_[b - 1];
      bucket_cells_.resize(bucket_start_.back());
      fill.assign(bucket_start_.begin(), bucket_start_.end() - 1);
    }
    for (std::size_t j = 0; j + 1 < ny_; ++j) {
      for (std::size_t i = 0; i + 1 < nx_; ++i) {
        const auto r = range(i, j);
        for (std::size_t b = r[1]; b <= r[3]; ++b) {
          for (std::size_t a = r[0]; a <= r[2]; ++a) {
            if (pass == 0) {
              ++bucket_start_[b * bx_ + a + 1];
            } else {
              bucket_cells_[fill[b * bx_ + a]++] = static_cast<std::uint32_t>(j * nx_ + i);
            }
          }
        }
      }
    }
  }
  for (std::size_t i = 0; i + 1 < nx_; ++i) {
    boundary_cells_.push_back(static_cast<std::uint32_t>(i));
    if (ny_ > 2) boundary_cells_.push_back(static_cast<std::uint32_t>((ny_ - 2) * nx_ + i));
  }
  for (std::size_t j = 1; j + 2 < ny_; ++j) {
    boundary_cells_.push_back(static_cast<std::uint32_t>(j * nx_));
    if (nx_ > 2) boundary_cells_.push_back(static_cast<std::uint32_t>(j * nx_ + nx_ - 2));
  }
  for (std::uint32_t id : boundary_cells_) {
    boundary_centres_.push_back(position(double(id % nx_) + 0.5, double(id / nx_) + 0.5));
  }
}

CellCorners CurvilinearPlane::corners(std::size_t i0, std::size_t j0) const {
  return {at(i0, j0), at(i0 + 1, j0), at(i0, j0 + 1), at(i0 + 1, j0 + 1)};
}

std::array<double, 2> CurvilinearPlane::position(double i, double j) const {
  const GridCell c = grid_cell(i, j, nx_, ny_);
  return bilinear(corners(c.i0, c.j0), c.s, c.t);
}

std::array<double, 4> CurvilinearPlane::jacobian(double i, double j) const {
  const GridCell c = grid_cell(i, j, nx_, ny_);
  return bilinear_jacobian(corners(c.i0, c.j0), c.s, c.t);
}

bool CurvilinearPlane::solve(std::size_t i0, std::size_t j0, double x, double y, double& s,
                             double& t) const {
  const auto &p00 = at(i0, j0), &p10 = at(i0 + 1, j0), &p01 = at(i0, j0 + 1),
             &p11 = at(i0 + 1, j0 + 1);
  s = 0.5;
  t = 0.5;
  for (int iteration = 0; iteration < 40; ++iteration) {
    double r[2], j[4];
    for (int k = 0; k < 2; ++k) {
      const double a = p10[k] - p00[k], b = p01[k] - p00[k], c = p11[k] - p10[k] - p01[k] + p00[k];
      r[k] = p00[k] + s * a + t * b + s * t * c - (k == 0 ? x : y);
      j[2 * k] = a + t * c;
      j[2 * k + 1] = b + s * c;
    }
    const double det = j[0] * j[3] - j[1] * j[2];
    if (!(det != 0) || !std::isfinite(det)) return false;
    const double ds = (j[3] * r[0] - j[1] * r[1]) / det;
    const double dt = (-j[2] * r[0] + j[0] * r[1]) / det;
    s -= ds;
    t -= dt;
    if (!std::isfinite(s) || !std::isfinite(t)) return false;
    if (std::fabs(ds) + std::fabs(dt) <= 1e-12 * (1.0 + std::fabs(s) + std::fabs(t))) return true;
  }
  return false;
}

std::array<double, 2> CurvilinearPlane::index_of(double x, double y) const {
  constexpr double kSlack = 1e-9;  // fractions this far outside [0, 1] still count as in
  if (!std::isfinite(x) || !std::isfinite(y)) return {kNaN, kNaN};
  if (x >= extent_[0] && x <= extent_[2] && y >= extent_[1] && y <= extent_[3]) {
    const auto bucket = [](double v, double lo, double size, std::size_t n) {
      return std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::max(0.0, (v - lo) / size)));
    };
    const std::size_t b =
        bucket(y, extent_[1], bucket_h_, by_) * bx_ + bucket(x, extent_[0], bucket_w_, bx_);
    for (std::size_t k = bucket_start_[b]; k < bucket_start_[b + 1]; ++k) {
      const std::size_t i0 = bucket_cells_[k] % nx_, j0 = bucket_cells_[k] / nx_;
      double s = 0, t = 0;
      if (solve(i0, j0, x, y, s, t) && s >= -kSlack && s <= 1 + kSlack && t >= -kSlack &&
          t <= 1 + kSlack) {
        return {double(i0) + s, double(j0) + t};
      }
    }
  }
  // Beyond the grid: the continued map of a boundary cell, the one whose continuation
  // `position` uses at the solution (nearest cell centres first).
  std::vector<double> distance(boundary_cells_.size());
  for (std::size_t k = 0; k < distance.size(); ++k) {
    const auto& c = boundary_centres_[k];
    distance[k] = (c[0] - x) * (c[0] - x) + (c[1] - y) * (c[1] - y);
  }
  // The nearest few: a point whose continuation none of them reaches is left unplaced
  // rather than searched for among every boundary cell.
  constexpr std::size_t kTries = 16;
  for (std::size_t tried = 0; tried < std::min(kTries, distance.size()); ++tried) {
    const auto k = static_cast<std::size_t>(std::min_element(distance.begin(), distance.end()) -
                                            distance.begin());
    distance[k] = INFINITY;
    const std::size_t i0 = boundary_cells_[k] % nx_, j0 = boundary_cells_[k] / nx_;
    double s = 0, t = 0;
    if (!solve(i0, j0, x, y, s, t)) continue;
    const GridCell used = grid_cell(double(i0) + s, double(j0) + t, nx_, ny_);
    if (used.i0 == i0 && used.j0 == j0) return {double(i0) + s, double(j0) + t};
  }
  return {kNaN, kNaN};
}

std::array<double, 4> CurvilinearPlane::box_of(const IndexBox& box) const {
  std::array<double, 4> b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (std::size_t j = box.lo[1]; j <= box.hi[1]; ++j) {
    for (std::size_t i = box.lo[0]; i <= box.hi[0]; ++i) {
      const auto& p = at(i, j);
      b = {std::min(b[0], p[0]), std::min(b[1], p[1]), std::max(b[2], p[0]),
           std::max(b[3], p[1])};
    }
  }
  return b;
}

}  // namespace strielad::lod
