// SPDX-License-Identifier: Apache-2.0
#include "view/height_placement.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "extract/output_frame.h"
#include "format/geometry_field.h"
#include "geo/standard_atmosphere.h"
#include "grid/units.h"
#include "store/store.h"
#include "view/level_heights.h"

namespace strielad::view {

void HeightPlacement::widen_boxes(std::vector<lod::WorldBox>& boxes, double exaggeration,
                                  std::optional<double> globe_frame_height_km) const {
  if (kind != Kind::kVariable) return;
  const double scale = 1e-3 * exaggeration;
  for (std::size_t n = 0; n < boxes.size() && n < node_heights_m.size(); ++n) {
    if (globe_frame_height_km) {
      const double pad =
          std::max(std::fabs(node_heights_m[n][0]), std::fabs(node_heights_m[n][1])) * scale +
          *globe_frame_height_km;
      for (int c = 0; c < 3; ++c) {
        boxes[n].lo[c] -= pad;
        boxes[n].hi[c] += pad;
      }
      continue;
    }
    boxes[n].lo[2] = std::min(boxes[n].lo[2], node_heights_m[n][0] * scale);
    boxes[n].hi[2] = std::max(boxes[n].hi[2], node_heights_m[n][1] * scale);
  }
}

double HeightPlacement::metres(double value) const {
  return pascals_per_unit > 0 ? geo::standard_height_m(value * pascals_per_unit)
                              : value * metres_per_unit;
}

namespace {

// The field's range per node in metres over every step, from the store's index.
std::vector<std::array<double, 2>> node_ranges_m(const Store& store, std::uint32_t variable,
                                                 const HeightPlacement& placement) {
  const auto& layout = store.octree();
  std::vector<std::array<double, 2>> heights(layout.node_count(), {INFINITY, -INFINITY});
  for (std::uint32_t step = 0; step < store.step_count(); ++step) {
    const auto index = store.index(step, variable);
    for (NodeId n = 0; n < layout.node_count() && n < index.size(); ++n) {
      if (!index[n].has_valid_data()) continue;
      // A pressure's lowest value is its highest height.
      const double a = placement.metres(index[n].min), b = placement.metres(index[n].max);
      heights[n][0] = std::min({heights[n][0], a, b});
      heights[n][1] = std::max({heights[n][1], a, b});
    }
  }
  return heights;
}

// A store with a grid geometry: the level table is the frame's own map; a field places
// vertices exactly and gives the frame its centre column.
HeightPlacement geometry_placement(const format::Manifest& m, const Store* store) {
  HeightPlacement out;
  const format::GridGeometry& g = *m.geometry;
  const auto quantity = format::vertical_quantity_name(g.vertical.quantity);
  if (!format::has_geometry_field(m)) {
    out.description =
        g.vertical.kind == format::VerticalGeometry::Kind::kLevels
            ? fmt::format("the grid geometry's table of {} {} levels on axis '{}'",
                          g.vertical.levels.size(), quantity, m.z.name)
            : fmt::format("vertical axis '{}'", m.z.name);
    return out;
  }
  const std::string name = format::geometry_field_name(m);
  if (store == nullptr) {
    throw make_error(ErrorCode::kUnsupported,
                     "the store is terrain-following (geometry field '{}' on model-level axis "
                     "'{}'): its vertices are placed by the field and its node boxes bounded by "
                     "the store's index, which needs the store on this machine; view a "
                     "terrain-following store on its own machine (strielad-view STORE) for now",
                     name, m.z.name);
  }
  out.kind = HeightPlacement::Kind::kVariable;
  out.variable = name;
  if (g.vertical.quantity == format::VerticalGeometry::Quantity::kPressure) {
    out.pascals_per_unit = pascals_per_pressure_unit(g.vertical.units).value_or(1.0);
  } else {
    out.metres_per_unit = metres_per_length_unit(g.vertical.units).value_or(1.0);
  }
  out.node_heights_m = node_ranges_m(*store, *format::geometry_field_variable(m), out);
  out.level_heights_m = representative_level_heights_m(*store);
  out.description = fmt::format(
      "terrain-following: vertices at geometry field '{}'{} on model-level axis '{}' (node "
      "boxes from the store's index); camera, slices and advection by its column at the "
      "domain's centre ({:.0f} to {:.0f} m)",
      name, out.pascals_per_unit > 0 ? " through the ICAO standard atmosphere" : "", m.z.name,
      out.level_heights_m.front(), out.level_heights_m.back());
  return out;
}

}  // namespace

HeightPlacement choose_height_placement(const format::Manifest& m, const Store* store) {
  if (m.geometry) return geometry_placement(m, store);
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
