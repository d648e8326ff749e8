// SPDX-License-Identifier: Apache-2.0
// Evaluating a GRIB catalog's vertical geometry and surface (found by
// ingest/grib_vertical_detection.h) from the messages InputCatalog::grib_fields names:
// decoded whole under eccodes_mutex(), the arithmetic in double.
#pragma once

#include <cstddef>
#include <span>

#include "grid/axis.h"
#include "ingest/input_catalog.h"

namespace strielad::ingest {

// Levels [z0, z1) at time step `step` of a grid of `dims` (as in the files), x fastest:
// hybrid levels: full-level pressure in Pa, the mean of the half-level pressures
// a + b ps above and below (level number k between half levels k - 1 and k of pv);
// HHL: height in m, the mean of the two half levels around a layer.
// \error kInvalidInput naming the file and message for a message that does not decode,
// has the wrong size or units, a level number outside pv; kInvalidArgument for ranges and
// sizes that do not fit, or a catalog without GRIB vertical geometry.
void evaluate_grib_vertical_geometry(const InputCatalog& c, std::size_t step, std::size_t z0,
                                     std::size_t z1, const Dims3& dims, std::span<double> out);

// The surface height in m, dims.y * dims.x values (the surface geopotential divided by
// the standard gravity).
void evaluate_grib_surface(const InputCatalog& c, const Dims3& dims, std::span<double> out);

}  // namespace strielad::ingest
