// SPDX-License-Identifier: Apache-2.0
// Evaluating a catalog's vertical geometry (VerticalGeometrySource): each sample's height
// above mean sea level (m) or pressure (Pa), from source variables read through a
// TermSource (ingest/term_reader.h reads them from netCDF). The arithmetic is in double;
// no netCDF calls here.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "ingest/input_catalog.h"

namespace strielad::ingest {

// Values of one source variable: unpacked (scale_factor, add_offset), in its own units.
struct TermValues {
  std::vector<double> values;
  std::string units;
};

class TermSource {
 public:
  virtual ~TermSource() = default;
  // Levels along the variable's vertical dimension: its first dimension after time when
  // it has one or three of them; 0 for a scalar or a (y, x) plane.
  virtual std::size_t levels(const std::string& variable) = 0;
  // The variable at catalog time step `step` (when it has a time dimension; nullopt: its
  // first time index, wherever it is): levels [k0, k1) when it has a vertical dimension,
  // else all of it; x fastest, then y, then k.
  // \error kInvalidInput naming the file, variable, sample and step for a missing or
  // non-finite value, or a time step the variable lacks.
  virtual TermValues read(const std::string& variable, std::optional<std::size_t> step,
                          std::size_t k0, std::size_t k1) = 0;
};

// Metres per unit of a height or geopotential: m, km (length units), gpm (geopotential
// metres), m2 s-2 (geopotential: 1 / 9.80665). nullopt for anything else.
std::optional<double> metres_per_height_unit(std::string_view units);

inline constexpr double kStandardGravity = 9.80665;  // m s-2, the WMO's g0

// `geometry` at time step `step`, levels [z0, z1) of a grid of `dims` (as in the files),
// into `out` ((z1 - z0) * dims.y * dims.x values, x fastest): heights in m or pressures
// in Pa. Source variables with dims.z + 1 levels are half levels: level k is the mean of
// half levels k and k + 1.
// \error kInvalidInput for a source of the wrong size or with units the formula cannot
// use; kInvalidArgument for a level range or output size that does not fit `dims`.
void evaluate_vertical_geometry(const VerticalGeometrySource& geometry, TermSource& terms,
                                std::size_t step, std::size_t z0, std::size_t z1, const Dims3& dims,
                                std::span<double> out);

// The surface height in m: `surface` at time index 0, dims.y * dims.x values.
void evaluate_surface(const SurfaceSource& surface, TermSource& terms, const Dims3& dims,
                      std::span<double> out);

}  // namespace strielad::ingest
