// SPDX-License-Identifier: Apache-2.0
#include "view/level_heights.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "format/geometry_field.h"
#include "geo/standard_atmosphere.h"
#include "store/store.h"

namespace strielad::view {

std::vector<double> representative_level_heights_m(const Store& store) {
  const format::Manifest& m = store.manifest();
  const auto variable = format::geometry_field_variable(m);
  if (!variable) return {};
  const bool pressure =
      m.geometry->vertical.quantity == format::VerticalGeometry::Quantity::kPressure;
  const OctreeLayout& layout = store.octree();
  const LevelShape& level0 = layout.level(0);
  const std::size_t i = m.x.size() / 2, j = m.y.size() / 2;
  const auto node_along = [&](std::size_t sample, int axis) {
    return static_cast<std::uint32_t>(std::min(sample / layout.brick(), level0.nodes[axis] - 1));
  };
  std::vector<double> heights(m.z.size(), NAN);
  for (std::uint32_t nz = 0; nz < level0.nodes[2]; ++nz) {
    const NodeKey key{0, {node_along(i, 0), node_along(j, 1), nz}};
    const NodeId node = layout.id(key);
    const IndexBox box = layout.fine_box(key);
    const Brick brick = store.read_brick(0, *variable, node);
    for (std::size_t k = box.lo[2]; k <= box.hi[2]; ++k) {
      const std::size_t s = ((k - box.lo[2]) * brick.dims[1] + (j - box.lo[1])) * brick.dims[0] +
                            (i - box.lo[0]);
      const double v = brick.sample(s);
      heights[k] = pressure ? geo::standard_height_m(v) : v;
    }
  }
  for (std::size_t k = 0; k < heights.size(); ++k) {
    const bool monotonic =
        k == 0 || (heights[1] > heights[0] ? heights[k] > heights[k - 1]
                                           : heights[k] < heights[k - 1]);
    if (!std::isfinite(heights[k]) || !monotonic) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: geometry field '{}' at the domain's centre sample ({}, {}) gives "
                       "level {} the height {} m: not finite or not strictly monotonic, so "
                       "the viewer has no vertical map",
                       store.path().string(), format::geometry_field_name(m), i, j, k,
                       heights[k]);
    }
  }
  return heights;
}

}  // namespace strielad::view
