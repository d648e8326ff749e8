// SPDX-License-Identifier: Apache-2.0
// Scans CF-NetCDF input files (classic and NetCDF-4, groups included) and GRIB files
// (ingest/grib_catalog.h), alone or together (ingest/mixed_catalog.h), into one catalog:
// the common grid (lon, lat, vertical axes kept exactly as stored, or index axes and the
// 2-D coordinates of a curvilinear grid), the merged time axis across files, and where
// every (variable, time step) lives.
// See docs/input-data.md for the CF conventions honoured.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grid/axis.h"
#include "grid/grid_mapping.h"
#include "ingest/curvilinear_grid.h"

namespace strielad::ingest {

struct ScanOptions {
  // Variables to convert ("T" or "group/sub/T"); empty = every 3D variable on the grid
  // of the first one found (others are skipped with a log line).
  std::vector<std::string> variables;
  // Inclusive range of merged time-step indices to keep; empty = all.
  std::optional<std::size_t> first_step, last_step;
  // Treat NaN/Inf samples as missing instead of rejecting the input.
  bool nan_as_fill = false;
  // SlabReader reads netCDF-4 planes that HDF5 keeps as raw bytes (Hdf5PlaneLayout)
  // with O_DIRECT, bypassing the page cache; false: every read through netCDF.
  bool direct_input = true;
  // The source variable holding every sample's height or geopotential (3-D, on the
  // variables' levels or on half levels), instead of the automatic choice (z_mc, z_ifc,
  // HHL, PH+PHB, a CF formula). Empty: automatic.
  std::optional<std::string> height_var;
  // Values of CF formula terms the files lack, e.g. {"P0", 100000} for the CCM
  // attribute P0_var or a formula_terms `p0:` variable that is absent (in the term
  // variable's units as the formula expects them).
  std::map<std::string, double> formula_constants;
};

// Where every sample lies vertically when the z axis alone does not say (terrain-
// following levels): a height above mean sea level (m) or a pressure (Pa) per sample,
// computed by a CF formula or read from source variables. SlabReader evaluates it.
struct VerticalGeometrySource {
  enum class Quantity { kHeight, kPressure };
  Quantity quantity = Quantity::kHeight;
  // The CF standard_name of the formula (atmosphere_hybrid_height_coordinate,
  // atmosphere_hybrid_sigma_pressure_coordinate, atmosphere_sigma_coordinate), or
  // "variable" when read from source variables.
  std::string formula;
  std::map<std::string, std::string> terms;  // formula term -> source variable
  // Formula terms no input file holds, given by ScanOptions::formula_constants: term ->
  // value in the SI unit of the term (Pa for p0 and ptop, m for lengths).
  std::map<std::string, double> constants;
  // Source variables read, in order. For formula "variable": one height or geopotential
  // (z_mc, z_ifc, HHL, --height-var) or the two geopotentials summed (WRF's PH + PHB).
  std::vector<std::string> sources;
  bool varies_in_time = false;               // differs between time steps
  // The g (m s-2) that turns geopotential sources into heights: WRF's 9.81 for PH + PHB
  // (WRF computes them with it); 0: the WMO's standard gravity.
  double geopotential_gravity = 0;
  friend bool operator==(const VerticalGeometrySource&, const VerticalGeometrySource&) = default;
};

// The model's own surface height (HSURF, HGT, topography_c, orog): 2-D, metres above
// mean sea level, time-invariant.
struct SurfaceSource {
  std::string variable;
  friend bool operator==(const SurfaceSource&, const SurfaceSource&) = default;
};

struct SourceFile {
  std::string path;                  // absolute path
  std::uint64_t size = 0;            // bytes
  std::uint64_t header_checksum = 0; // checksum64 of the first min(size, 64 KiB) bytes
  friend bool operator==(const SourceFile&, const SourceFile&) = default;
};

struct VariableMeta {
  std::string name;  // store name: the variable's name, prefixed "group/" when in a group
  std::string units, long_name, standard_name;
  DType store_type = DType::kFloat32;  // type the store keeps (exact for the source)
  std::string source_type;             // netCDF type name in the source: "float", "short"...
  // CF attributes as found (in the source's packed units); absent when not set.
  std::optional<double> fill_value, missing_value, valid_min, valid_max;
  std::optional<double> scale_factor, add_offset;
  // Every value of missing_value (CF allows a vector); missing_value is the first one.
  std::vector<double> missing_values;
  // A variable derived from another one of the same file (WRF's theta from T): the
  // file's variable that is read, its attributes above; empty: `name` itself.
  std::string source_variable;
  // Added to every value once unpacked (WRF's theta: T + 300 K); 0: none.
  double value_offset = 0;
};

// Where a GRIB message lies in its file.
struct GribMessageRef {
  std::uint64_t offset = 0;  // of "GRIB"
  std::uint64_t size = 0;    // bytes, "GRIB" to "7777"
};

struct VariableLocation {
  std::size_t file = 0;            // index into InputCatalog::files
  std::size_t time_in_file = 0;    // index along the variable's time dimension (0 if none)
  // GRIB inputs: the message of each level, in the order of z (empty for netCDF).
  std::vector<GribMessageRef> grib_levels;
};

struct InputCatalog {
  std::vector<SourceFile> files;
  Axis x, y, z;    // longitude, latitude (or indices), vertical: as stored
  std::optional<GridMapping> grid_mapping;  // x/y are projection coordinates placed by it
  // x/y are index axes placed by 2-D longitude and latitude (then no grid_mapping).
  std::shared_ptr<const CurvilinearGrid> curvilinear;
  // Samples per row in the files: x.size() (or 0, meaning the same), or x.size() - 1
  // when x is a periodic longitude axis whose first meridian the catalog repeats at the
  // end (SlabReader and BoxReader copy the first column there).
  std::size_t source_nx = 0;
  bool repeats_first_column() const { return source_nx != 0 && source_nx + 1 == x.size(); }
  // The catalog as the files hold it: without the repeated meridian.
  InputCatalog as_in_files() const;
  TimeAxis time;   // merged, ascending, selected steps only
  std::vector<VariableMeta> variables;
  // locations[v][t]: where variable v at time step t lives.
  std::vector<std::vector<VariableLocation>> locations;
  // Terrain-following levels: how each sample's height or pressure is found (none: the z
  // axis places every sample).
  std::optional<VerticalGeometrySource> vertical_geometry;
  std::optional<SurfaceSource> surface;
  // GRIB inputs: where the fields that vertical_geometry and surface name lie (lnsp or
  // sp, HHL, orog ...), by shortName: one location per time step, or a single one when
  // the field does not vary in time. HHL lists, per level of z, the half levels to
  // average (two for generalVerticalLayer, one for generalVertical); a plane lists one.
  std::map<std::string, std::vector<VariableLocation>> grib_fields;

  Dims3 dims() const { return Dims3{x.size(), y.size(), z.size()}; }
  std::size_t variable_index(std::string_view name) const;  // throws kNotFound
};

// Throws strielad::Error naming the file, variable, dimension or attribute at fault:
// kNotFound (missing file or variable), kInvalidInput (missing coordinate variable,
// non-monotonic axis, mismatched grids or time units across files, duplicate times),
// kUnsupported (unstructured grids such as ICON's native triangles, 2-D coordinates a
// variable does not name or the file lacks, dimension orders other than (time, vertical,
// lat, lon)); kInvalidInput also for 2-D coordinates that cannot place a curvilinear grid
// (ingest/curvilinear_grid.h) or differ between files. Inputs are told apart by content
// (ingest/input_kind.h); GRIB and netCDF inputs together are joined as
// merge_grib_and_netcdf says (kNotFound for a variable asked for that neither format
// has, kInvalidInput for one both have, kInvalidArgument for a --vars list that takes
// nothing from one format).
InputCatalog scan_inputs(const std::vector<std::filesystem::path>& inputs,
                         const ScanOptions& options);

}  // namespace strielad::ingest
