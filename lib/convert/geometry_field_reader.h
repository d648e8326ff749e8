// SPDX-License-Identifier: Apache-2.0
// The grid geometry's vertical field (a height or pressure per sample of a terrain-
// following grid) read from the inputs for conversion: evaluated in double by the
// SlabReader, rounded to the field's stored dtype, and every column checked, level by
// level, to run strictly in the store's recorded direction (formats/store.md, "Grid
// geometry (version 5)": `orientation`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "format/manifest.h"
#include "ingest/slab_reader.h"
#include "ingest/vertical_columns.h"

namespace strielad::build {

// Whether the manifest's geometry has a per-sample vertical field that changes between
// time steps (one section per step file) / that does not (geometry.bricks).
bool has_time_varying_geometry(const format::Manifest& manifest);
bool has_time_invariant_geometry(const format::Manifest& manifest);

// +1 when the field's values grow with the level index k, -1 when they shrink: from the
// manifest's orientation and the horizontal sign (geo::horizontal_orientation of the
// axes, or a curvilinear grid's own; a height grows upwards, a pressure shrinks).
int field_direction_per_level(const format::Manifest& manifest, int horizontal_sign);

// Reads planes of one step's field in increasing z, each call continuing the last (as the
// converter streams slabs).
class GeometryFieldReader {
 public:
  GeometryFieldReader(ingest::SlabReader& reader, const format::Manifest& manifest,
                      std::uint32_t step);

  // Planes [z0, z1), x fastest. \error kInvalidInput naming the field's source variables,
  // the sample (i, j, k) and the step, where a value as stored does not move strictly in
  // the direction of column (0, 0) from the level below it (ingest::ColumnOrderCheck), or
  // the columns run the other way than at time step 0.
  void read(std::size_t z0, std::size_t z1, std::span<float> out);
  void read(std::size_t z0, std::size_t z1, std::span<double> out);

 private:
  template <typename T>
  void read_any(std::size_t z0, std::size_t z1, std::span<T> out);

  ingest::SlabReader& reader_;
  const format::Manifest& manifest_;
  std::uint32_t step_;
  int direction_;
  std::size_t plane_;
  std::vector<double> values_;     // the planes just read, as stored
  ingest::ColumnOrderCheck columns_;
};

}  // namespace strielad::build
