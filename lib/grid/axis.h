// SPDX-License-Identifier: Apache-2.0
// Rectilinear axes as read from CF metadata: exact coordinate values (non-uniform and
// descending axes are kept, never resampled) plus the attributes a reader needs.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace strielad {

enum class AxisKind {
  kLongitude,  // degrees_east
  kLatitude,   // degrees_north
  kHeight,     // metres above ground or sea level (positive up)
  kPressure,   // Pa, hPa, mbar (positive down)
  kModelLevel, // hybrid or dimensionless vertical coordinate
  kOther,      // a vertical coordinate of unknown meaning, kept as given
  // Horizontal coordinates of a map projection (store format version 4): the grid's
  // grid mapping (grid/grid_mapping.h) places them. Rotated-pole grids have them in
  // degrees (CF grid_longitude, grid_latitude), projected grids in metres or kilometres
  // (projection_x_coordinate, projection_y_coordinate). Without a grid mapping they are
  // plain Cartesian coordinates in metres with no place on the Earth.
  kProjectionX,
  kProjectionY,
  // The x or y index of a curvilinear grid (store format version 5): values 0 .. n-1; the
  // store's 2-D longitudes and latitudes place each column.
  kIndex,
};

std::string_view axis_kind_name(AxisKind kind) noexcept;
// Parses a name written by axis_kind_name; throws kCorrupt on anything else.
AxisKind axis_kind_from_name(std::string_view name);

struct Axis {
  std::string name;           // the coordinate variable's name in the source
  AxisKind kind = AxisKind::kOther;
  std::string units;
  std::string standard_name;
  std::string long_name;
  std::string positive;       // "up", "down" or empty
  std::vector<double> values; // strictly monotonic (ascending or descending)
  // A longitude axis that goes once round the Earth (store format version 4): its last
  // value is its first plus 360 (minus 360 descending), the same meridian, so the cell
  // between the source's last and first longitude is a cell like any other
  // (formats/store.md, "Periodic longitudes").
  bool periodic = false;

  std::size_t size() const { return values.size(); }
  bool descending() const { return values.size() > 1 && values[1] < values[0]; }

  friend bool operator==(const Axis&, const Axis&) = default;
};

// Throws kInvalidInput naming `what` and the first offending index when the values are
// empty, contain NaN/Inf, or are not strictly monotonic, and when a periodic axis is not
// a longitude whose last value is its first one turned once round (exactly).
void check_axis_values(const Axis& axis, std::string_view what);

// Whether longitudes `values` (strictly monotonic, at least 3) go round the Earth with
// the cell that closes the circle missing: the gap from the last value to the first plus
// 360 (in the axis's direction) is the axis's mean spacing within 0.1 %, as on every
// regular or Gaussian global grid written without a repeated meridian.
bool longitudes_close_the_circle(const std::vector<double>& values);
// Whether they already repeat their first meridian at the end: the last value is the
// first plus 360 (minus 360 descending), computed in double as written.
bool longitudes_repeat_the_first(const std::vector<double>& values);

// A longitude axis written wrapped at the antimeridian or at 0/360 (179.5, 180, -179.5 ...;
// 359, 0, 1 ...): when the values are finite but not strictly monotonic, and become so
// once every jump of more than 180 degrees is undone by adding or subtracting 360 to
// everything after it (numpy.unwrap with period 360), replaces them and returns true.
// They are the same longitudes (exact up to the rounding of adding 360), now continuous
// (179.5, 180, 180.5 ...). Otherwise leaves them alone and returns false.
bool unwrap_longitudes(std::vector<double>& values);

struct TimeAxis {
  std::string name;
  std::string units;     // e.g. "hours since 2013-04-26 00:00:00"; may be empty
  std::string calendar;  // e.g. "standard"; may be empty
  std::vector<double> values;

  std::size_t size() const { return values.size(); }
  friend bool operator==(const TimeAxis&, const TimeAxis&) = default;
};

enum class DType { kFloat32, kFloat64 };

// The DType of a sample type (float or double).
template <typename T>
inline constexpr DType kDTypeOf = sizeof(T) == 4 ? DType::kFloat32 : DType::kFloat64;

std::string_view dtype_name(DType type) noexcept;
DType dtype_from_name(std::string_view name);  // throws kCorrupt
inline std::size_t dtype_size(DType type) noexcept { return type == DType::kFloat32 ? 4 : 8; }

// Grid dimensions in samples along x (lon, fastest varying), y (lat) and z (vertical).
struct Dims3 {
  std::size_t x = 0, y = 0, z = 0;
  std::size_t count() const { return x * y * z; }
  friend bool operator==(const Dims3&, const Dims3&) = default;
};

}  // namespace strielad
