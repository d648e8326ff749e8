// SPDX-License-Identifier: Apache-2.0
// Scans one input file: every variable of every group, classified as a usable
// (time?, vertical, lat, lon) field on a rectilinear grid (or (time?, vertical, y, x) on a
// curvilinear grid placed by the 2-D latitude/longitude its `coordinates` attribute
// names: ingest/curvilinear_grid.h), or not, with the reason kept
// as an Error so that the caller decides whether it matters (it does when the variable
// was asked for, and is only logged when the variable would merely have been picked by
// default).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "grid/axis.h"
#include "grid/grid_mapping.h"
#include "ingest/curvilinear_grid.h"
#include "ingest/input_catalog.h"
#include "ingest/variable_meta.h"

namespace strielad::ingest {

struct TimeCoordinate {
  std::string name, units, calendar;
  std::vector<double> values;  // as stored in this file (strictly monotonic)
};

enum class VariableClass {
  kGrid3D,        // (time?, vertical, y, x) on a rectilinear grid or one placed by 2-D
                  // latitude and longitude (curvilinear): usable
  kNotGridded,    // not a 3D lon/lat field: coordinates, 2D fields, zonal means, text...
  kUnstructured,  // on an unstructured grid, or a curvilinear one that cannot be placed
  kInvalid,       // a 3D field that cannot be used as stored: missing coordinate
                  // variable, non-monotonic axis, wrong dimension order...
};

struct ScannedVariable {
  std::string name;  // store name: "T" or "grp1/T"
  VariableClass klass = VariableClass::kNotGridded;
  std::optional<Error> problem;  // why it is not kGrid3D
  bool auxiliary = false;        // a coordinate, bounds or auxiliary coordinate variable
  // Why the default selection leaves this usable variable out (logged): WRF's T, offered
  // as theta. Empty: taken by default. Asked for by name, it is converted.
  std::string not_by_default;
  std::vector<std::string> dimensions;
  // kGrid3D only:
  Axis x, y, z;
  std::optional<GridMapping> grid_mapping;  // with its PROJ pipeline (ingest/horizontal_axes.h)
  // Placed by 2-D latitude and longitude: x and y are index axes (AxisKind::kIndex), no
  // grid mapping. Shared by the variables of a file that name the same coordinates.
  std::shared_ptr<const CurvilinearGrid> curvilinear;
  std::size_t source_nx = 0;  // samples per row in the file (x.size() - 1 when the first
                              // meridian of a periodic longitude axis was appended)
  std::optional<TimeCoordinate> time;  // absent: the variable has no time dimension
  VariableMeta meta;
  CfValueAttributes value_attributes;
};

struct ScannedFile {
  SourceFile source;  // source.path is the name used in messages
  int format = 0;     // NC_FORMAT_*
  std::vector<ScannedVariable> variables;

  const ScannedVariable* find(std::string_view name) const;
};

// Throws for a file that cannot be used at all: kNotFound (missing), kInvalidInput (not
// netCDF, truncated), kIo. Takes netcdf_mutex() itself.
ScannedFile scan_file(const std::filesystem::path& path);

}  // namespace strielad::ingest
