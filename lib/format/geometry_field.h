// SPDX-License-Identifier: Apache-2.0
// The grid geometry's vertical field (formats/store.md, "Grid geometry (version 5)": a
// height above mean sea level or a pressure for every sample of a terrain-following grid)
// seen as one more variable of the store: index variables.size(), named
// "geometry_height" (m) or "geometry_pressure" (Pa). Scenes name it like a variable (a
// limit, an attribute, a slice colour), Store reads its index and bricks under that index,
// and extraction carries it as a per-vertex attribute, interpolated at each vertex exactly
// as the data are (linearly along the lattice edge the vertex lies on), so vertices on a
// face shared by two nodes get the same height from the same samples and meshes stay
// crack-free once placed (extract/output_frame.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "format/manifest.h"

namespace strielad::format {

// Whether the store has a per-sample vertical geometry field.
inline bool has_geometry_field(const Manifest& m) {
  return m.geometry && m.geometry->vertical.kind == VerticalGeometry::Kind::kField;
}

// The field's variable index (variables.size()), or nothing.
inline std::optional<std::uint32_t> geometry_field_variable(const Manifest& m) {
  if (!has_geometry_field(m)) return std::nullopt;
  return static_cast<std::uint32_t>(m.variables.size());
}

// "geometry_height" or "geometry_pressure"; "" when the store has no field.
inline std::string geometry_field_name(const Manifest& m) {
  if (!has_geometry_field(m)) return "";
  return m.geometry->vertical.quantity == VerticalGeometry::Quantity::kHeight ? "geometry_height"
                                                                              : "geometry_pressure";
}

// The name of variable index `v`, the geometry field's included.
inline std::string variable_name(const Manifest& m, std::uint32_t v) {
  return v < m.variables.size() ? m.variables[v].name : geometry_field_name(m);
}

}  // namespace strielad::format
