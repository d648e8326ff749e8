// SPDX-License-Identifier: Apache-2.0
// Scans CF-NetCDF input files (classic and NetCDF-4, groups included) into one catalog:
// the common rectilinear grid (lon, lat, vertical axes, kept exactly as stored), the
// merged time axis across files, and where every (variable, time step) lives.
// See README "Input data" for the CF conventions honoured.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "grid/axis.h"
#include "grid/grid_mapping.h"

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
};

struct VariableLocation {
  std::size_t file = 0;            // index into InputCatalog::files
  std::size_t time_in_file = 0;    // index along the variable's time dimension (0 if none)
};

struct InputCatalog {
  std::vector<SourceFile> files;
  Axis x, y, z;    // longitude, latitude, vertical: as stored (ascending or descending)
  std::optional<GridMapping> grid_mapping;  // x/y are projection coordinates placed by it
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

  Dims3 dims() const { return Dims3{x.size(), y.size(), z.size()}; }
  std::size_t variable_index(std::string_view name) const;  // throws kNotFound
};

// Throws strielad::Error naming the file, variable, dimension or attribute at fault:
// kNotFound (missing file or variable), kInvalidInput (missing coordinate variable,
// non-monotonic axis, mismatched grids or time units across files, duplicate times),
// kUnsupported (unstructured or curvilinear grids such as ICON's native triangles,
// dimension orders other than (time, vertical, lat, lon)).
InputCatalog scan_inputs(const std::vector<std::filesystem::path>& inputs,
                         const ScanOptions& options);

// Reads z-slabs of one variable and time step: samples [z0, z1) x all lat x all lon,
// x fastest, unpacked (scale_factor/add_offset), with _FillValue, missing_value and
// samples outside valid_min/valid_max (or valid_range) set to NaN. NaN/Inf in the data
// throws kInvalidInput naming file, variable, step and sample index unless
// ScanOptions::nan_as_fill. Safe to call from several threads (netCDF calls are
// serialized; direct reads run in parallel); keeps files open between calls.
//
// With ScanOptions::direct_input, planes of a netCDF-4 variable that HDF5 stores as raw
// little-endian samples (no filters; contiguous, or chunks of whole planes) are read
// with O_DIRECT in pieces and converted from there: an input that is read once costs
// no page-cache work (on a 2-core VM, reading 5.3 GB buffered took 15 s of system
// time against 0.4 s direct). Anything else, and file systems without O_DIRECT, read
// through netCDF. The result is the same either way.
class SlabReader {
 public:
  SlabReader(const InputCatalog& catalog, const ScanOptions& options);
  ~SlabReader();
  SlabReader(const SlabReader&) = delete;
  SlabReader& operator=(const SlabReader&) = delete;

  void read(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
            std::span<float> out);
  void read(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
            std::span<double> out);

  // Direct reads go in pieces of at most this many bytes: the per-thread aligned buffer
  // stays small, and each piece is converted while it is still in cache.
  static constexpr std::size_t kDirectPieceBytes = std::size_t{16} << 20;

  // Input bytes read so far with O_DIRECT (the rest went through netCDF).
  std::uint64_t direct_bytes() const;

 private:
  template <typename T>
  void read_any(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
                std::span<T> out);

  struct Impl;
  Impl* impl_;
  bool repeat_first_column_ = false;  // the catalog repeats the first meridian at the end
};

}  // namespace strielad::ingest
