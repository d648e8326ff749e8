// SPDX-License-Identifier: Apache-2.0
// The catalog of GRIB inputs (one file or several, every one GRIB): the 3-D variables of
// their scans (ingest/grib_scan.h) on the grid and levels of the first one (or of those
// asked for), the grid placed from its GRIB definition (ingest/grib_grid.h), and the
// validity times merged across files as "seconds since 1970-01-01 00:00:00" (proleptic
// Gregorian). Values are read as ecCodes decodes them; bitmap points become NaN, which
// the variable's NaN fill value makes missing.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ingest/grib_scan.h"
#include "ingest/input_catalog.h"

namespace strielad::ingest {

// \error kNotFound for a variable asked for that no input has (listing those there are);
// kInvalidInput for variables on other levels or grids than the first, a validity time
// in two files, time steps that differ between variables; what scan_grib_file and
// grib_grid throw. Every location names its levels' messages (VariableLocation::
// grib_levels), so reading needs no second scan.
InputCatalog grib_catalog(const std::vector<std::filesystem::path>& inputs,
                          const ScanOptions& options);
// The same from the inputs' scans (scan_grib_file), one per input, in input order.
InputCatalog grib_catalog(const std::vector<GribScan>& scans, const ScanOptions& options);

// The store names of the 3-D variables of `scans` (grib_variable_name), in the order
// first seen: what ScanOptions::variables may name.
std::vector<std::string> grib_variable_names(const std::vector<GribScan>& scans);

// The store name of `v`: its shortName, or "shortName_typeOfLevel" when another 3-D
// variable of the scan has the same shortName.
std::string grib_variable_name(const GribScan& scan, const GribVariable& v);

// The messages `levels` of `path` (consecutive levels of one variable and time), as
// ecCodes decodes them, into `out` (plane after plane, i fastest); bitmap points NaN.
// `plane` = samples per level; `what` names file, variable and step in messages. The
// file is read outside eccodes_mutex(), which only decoding holds.
// \error kInvalidInput naming the message when its size is not `plane`; kUnsupported when
// float output cannot hold the packed values apart (packing finer than float32).
void read_grib_levels(const std::filesystem::path& path, std::span<const GribMessageRef> levels,
                      std::size_t plane, std::string_view what, std::span<float> out);
void read_grib_levels(const std::filesystem::path& path, std::span<const GribMessageRef> levels,
                      std::size_t plane, std::string_view what, std::span<double> out);

}  // namespace strielad::ingest
