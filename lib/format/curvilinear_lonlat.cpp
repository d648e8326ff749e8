// SPDX-License-Identifier: Apache-2.0
#include "format/curvilinear_lonlat.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace strielad {

CurvilinearLonLat::CurvilinearLonLat(
    std::shared_ptr<const format::HorizontalCoordinates> coordinates)
    : c_(std::move(coordinates)) {
  if (c_ == nullptr || c_->nx < 2 || c_->ny < 2 || c_->lon.size() != std::size_t(c_->nx) * c_->ny ||
      c_->lat.size() != std::size_t(c_->nx) * c_->ny) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "curvilinear placement needs at least 2 x 2 longitudes and latitudes, one "
                     "per column");
  }
}

GridCell grid_cell(double i, double j, std::size_t nx, std::size_t ny) {
  const auto pick = [](double x, std::size_t n) {
    const double last = double(n) - 2;  // the last cell's first index
    const double f = std::clamp(std::floor(x), 0.0, last);
    return std::pair{static_cast<std::size_t>(f), x - f};
  };
  const auto [i0, s] = pick(i, nx);
  const auto [j0, t] = pick(j, ny);
  return {i0, j0, s, t};
}

std::array<double, 2> bilinear(const CellCorners& p, double s, double t) {
  const auto& [p00, p10, p01, p11] = p;
  std::array<double, 2> out{};
  for (int k = 0; k < 2; ++k) {
    const double bottom = p00[k] + s * (p10[k] - p00[k]);
    const double top = p01[k] + s * (p11[k] - p01[k]);
    out[k] = bottom + t * (top - bottom);
  }
  return out;
}

std::array<double, 4> bilinear_jacobian(const CellCorners& p, double s, double t) {
  const auto& [p00, p10, p01, p11] = p;
  std::array<double, 4> d{};
  for (int k = 0; k < 2; ++k) {
    d[2 * k] = (1 - t) * (p10[k] - p00[k]) + t * (p11[k] - p01[k]);
    d[2 * k + 1] = (1 - s) * (p01[k] - p00[k]) + s * (p11[k] - p10[k]);
  }
  return d;
}

CellCorners CurvilinearLonLat::corners(const GridCell& c) const {
  const auto at = [&](std::size_t i, std::size_t j) {
    const std::size_t k = j * c_->nx + i;
    return std::array<double, 2>{c_->lon[k], c_->lat[k]};
  };
  return {at(c.i0, c.j0), at(c.i0 + 1, c.j0), at(c.i0, c.j0 + 1), at(c.i0 + 1, c.j0 + 1)};
}

std::array<double, 2> CurvilinearLonLat::at(double i, double j) const {
  const GridCell c = grid_cell(i, j, c_->nx, c_->ny);
  return bilinear(corners(c), c.s, c.t);
}

std::array<double, 4> CurvilinearLonLat::jacobian(double i, double j) const {
  const GridCell c = grid_cell(i, j, c_->nx, c_->ny);
  return bilinear_jacobian(corners(c), c.s, c.t);
}

std::array<double, 2> CurvilinearLonLat::centre() const {
  return at(0.5 * (double(c_->nx) - 1), 0.5 * (double(c_->ny) - 1));
}

int CurvilinearLonLat::orientation() const {
  const double i = 0.5 * (double(c_->nx) - 1), j = 0.5 * (double(c_->ny) - 1);
  const auto d = jacobian(i, j);
  // East per degree of longitude shrinks by cos(lat); the sign is what matters.
  const double coslat = std::cos(at(i, j)[1] * std::numbers::pi / 180);
  const double det = (d[0] * coslat) * d[3] - (d[1] * coslat) * d[2];
  return det < 0 ? -1 : 1;
}

}  // namespace strielad
