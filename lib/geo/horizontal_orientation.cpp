// SPDX-License-Identifier: Apache-2.0
#include "geo/horizontal_orientation.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "geo/grid_projection.h"

namespace strielad::geo {

int horizontal_orientation(const Axis& x, const Axis& y, const std::optional<GridMapping>& mapping) {
  int sign = (x.descending() ? -1 : 1) * (y.descending() ? -1 : 1);
  if (!mapping || mapping->proj.empty()) return sign;
  const GridProjection projection(mapping->proj);
  const double cx = 0.5 * (x.values.front() + x.values.back());
  const double cy = 0.5 * (y.values.front() + y.values.back());
  const double h = 1e-3 * std::max(std::fabs(x.values.back() - x.values.front()) /
                                       static_cast<double>(std::max<std::size_t>(x.size(), 2) - 1),
                                   1e-9);
  const auto j = projection.jacobian(cx, cy, h);
  const double det = j[0] * j[3] - j[1] * j[2];
  if (!std::isfinite(det) || det == 0) {
    throw make_error(ErrorCode::kUnsupported,
                     "grid mapping '{}': its map has no orientation at the grid's centre",
                     mapping->variable);
  }
  return det < 0 ? -sign : sign;
}

}  // namespace strielad::geo
