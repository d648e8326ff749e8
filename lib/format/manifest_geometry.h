// SPDX-License-Identifier: Apache-2.0
// The manifest's grid geometry record (formats/store.md, "Grid geometry (version 5)"):
// how x, y and z are placed when the axes alone do not say. JSON read and write only; the
// arrays it names are in files of their own.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "format/codec_spec.h"
#include "grid/axis.h"

namespace strielad::format {

// The formula name of a vertical field read from source variables, not computed by a CF
// formula.
inline constexpr std::string_view kGeometryFormulaVariable = "variable";

struct HorizontalGeometry {
  enum class Kind { kAxes, kCurvilinear };
  Kind kind = Kind::kAxes;
  // Curvilinear only: the source's 2-D coordinate variables and the XXH3 of the level-0
  // lon array's bytes followed by the lat array's (little-endian float64).
  std::string lon_variable, lat_variable;
  std::uint64_t coordinates_checksum = 0;
  friend bool operator==(const HorizontalGeometry&, const HorizontalGeometry&) = default;
};

struct VerticalGeometry {
  enum class Kind { kAxis, kLevels, kField };
  enum class Quantity { kHeight, kPressure };
  Kind kind = Kind::kAxis;
  // Levels and field: height above mean sea level in "m", or pressure in "Pa".
  Quantity quantity = Quantity::kHeight;
  std::string units;
  // A CF standard_name, or kGeometryFormulaVariable (field only).
  std::string formula;
  std::vector<double> levels;                 // levels: one per z index
  std::map<std::string, std::string> terms;   // field: CF term -> source variable
  std::vector<std::string> sources;           // field: source variables read
  bool varies_in_time = false;                // field
  DType dtype = DType::kFloat32;              // field: its stored type
  CodecSpec codec;                            // field: how its bricks are compressed
  friend bool operator==(const VerticalGeometry&, const VerticalGeometry&) = default;
};

struct SurfaceGeometry {
  std::string variable;
  std::string units = "m";
  friend bool operator==(const SurfaceGeometry&, const SurfaceGeometry&) = default;
};

struct GridGeometry {
  HorizontalGeometry horizontal;
  VerticalGeometry vertical;
  std::optional<SurfaceGeometry> surface;
  int orientation = 1;  // sign of det d(east, north, up) / d(i, j, k)
  friend bool operator==(const GridGeometry&, const GridGeometry&) = default;
};

std::string_view vertical_kind_name(VerticalGeometry::Kind kind) noexcept;
std::string_view vertical_quantity_name(VerticalGeometry::Quantity quantity) noexcept;
// "m" for height, "Pa" for pressure.
std::string_view vertical_quantity_units(VerticalGeometry::Quantity quantity) noexcept;

// The geometry object. Throws kInvalidArgument naming the field when the geometry is not
// one a reader accepts (the same rules as geometry_from_json).
nlohmann::json geometry_json(const GridGeometry& geometry, std::size_t z_size);
// Reads and validates a geometry object for a grid with `z_size` levels; throws kCorrupt
// naming `what` and the field at fault.
GridGeometry geometry_from_json(const nlohmann::json& json, std::size_t z_size,
                                std::string_view what);

}  // namespace strielad::format
