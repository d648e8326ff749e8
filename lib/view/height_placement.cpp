// SPDX-License-Identifier: Apache-2.0
#include "view/height_placement.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "extract/output_frame.h"
#include "geo/standard_atmosphere.h"
#include "grid/units.h"
#include "store/store.h"

namespace strielad::view {

void HeightPlacement::widen_boxes(std::vector<lod::WorldBox>& boxes, double exaggeration) const {
  if (kind != Kind::kVariable) return;
  const double scale = 1e-3 * exaggeration;
  for (std::size_t n = 0; n < boxes.size() && n < node_heights_m.size(); ++n) {
    boxes[n].lo[2] = std::min(boxes[n].lo[2], node_heights_m[n][0] * scale);
    boxes[n].hi[2] = std::max(boxes[n].hi[2], node_heights_m[n][1] * scale);
  }
}

HeightPlacement choose_height_placement(const format::Manifest& m, const Store* store) {
  HeightPlacement out;
  if (m.z.kind != AxisKind::kPressure) {
    out.description = m.z.kind == AxisKind::kHeight
                          ? fmt::format("height axis '{}' ({})", m.z.name,
                                        m.z.units.empty() ? "m" : m.z.units)
                          : fmt::format("vertical axis '{}'", m.z.name);
    return out;
  }
  const auto pa = pascals_per_pressure_unit(m.z.units);
  const std::string standard = fmt::format(
      "the ICAO standard atmosphere of pressure axis '{}' ({})", m.z.name, m.z.units);
  VerticalPlacement v;
  try {
    v = choose_vertical_placement(m);
  } catch (const Error& e) {
    out.description = fmt::format("{}: {}", standard, e.what());
    return out;
  }
  if (v.kind != VerticalPlacement::Kind::kHeightVariable || !pa) {
    out.description = standard + ": the store has no geopotential or height variable";
    return out;
  }
  if (store == nullptr) {
    out.description = fmt::format(
        "{}: '{}' would place it, but bounding the node boxes by it needs the store's index "
        "on this machine (a served store through --connect)",
        standard, v.variable);
    return out;
  }
  // The field's exact range per node over every step, from the store's index.
  const auto& layout = store->octree();
  const auto variable = static_cast<std::uint32_t>(m.variable_index(v.variable));
  std::vector<std::array<double, 2>> heights(layout.node_count(), {INFINITY, -INFINITY});
  for (std::uint32_t step = 0; step < store->step_count(); ++step) {
    const auto index = store->index(step, variable);
    for (NodeId n = 0; n < layout.node_count() && n < index.size(); ++n) {
      if (!index[n].has_valid_data()) continue;
      heights[n][0] = std::min(heights[n][0], index[n].min * v.metres_per_unit);
      heights[n][1] = std::max(heights[n][1], index[n].max * v.metres_per_unit);
    }
  }
  // Joined with the standard atmosphere's heights of the node's pressures (vertices where
  // the field is missing fall back to them).
  for (NodeId n = 0; n < layout.node_count(); ++n) {
    const IndexBox fine = layout.fine_box(layout.key(n));
    for (const std::size_t k : {fine.lo[2], fine.hi[2]}) {
      const double h = geo::standard_height_m(m.z.values[k] * *pa);
      heights[n][0] = std::min(heights[n][0], h);
      heights[n][1] = std::max(heights[n][1], h);
    }
  }
  out.kind = HeightPlacement::Kind::kVariable;
  out.variable = v.variable;
  out.metres_per_unit = v.metres_per_unit;
  out.node_heights_m = std::move(heights);
  out.description = fmt::format("{} on pressure axis '{}' (node boxes from the store's index)",
                                v.description, m.z.name);
  return out;
}

}  // namespace strielad::view
