// SPDX-License-Identifier: Apache-2.0
#include "convert/geometry_field_reader.h"

#include <fmt/ranges.h>

#include "core/error.h"
#include "convert/geometry_plan.h"

namespace strielad::build {

namespace {

bool has_field(const format::Manifest& m) {
  return m.geometry && m.geometry->vertical.kind == format::VerticalGeometry::Kind::kField;
}

}  // namespace

bool has_time_varying_geometry(const format::Manifest& m) {
  return has_field(m) && m.geometry->vertical.varies_in_time;
}

bool has_time_invariant_geometry(const format::Manifest& m) {
  return has_field(m) && !m.geometry->vertical.varies_in_time;
}

int field_direction_per_level(const format::Manifest& m, int horizontal_sign) {
  const int up_per_k = m.geometry->orientation * horizontal_sign;
  return m.geometry->vertical.quantity == format::VerticalGeometry::Quantity::kPressure ? -up_per_k
                                                                                       : up_per_k;
}

GeometryFieldReader::GeometryFieldReader(ingest::SlabReader& reader,
                                         const format::Manifest& manifest, std::uint32_t step)
    : reader_(reader),
      manifest_(manifest),
      step_(step),
      direction_(field_direction_per_level(manifest, horizontal_sign(reader.catalog()))),
      plane_(manifest.x.size() * manifest.y.size()),
      columns_(manifest.x.size(), manifest.y.size(),
               fmt::format("{} ({}), stored as {}, time step {}",
                           fmt::join(manifest.geometry->vertical.sources, " + "),
                           manifest.geometry->vertical.formula,
                           dtype_name(manifest.geometry->vertical.dtype), step)) {}

void GeometryFieldReader::read(std::size_t z0, std::size_t z1, std::span<float> out) {
  read_any(z0, z1, out);
}
void GeometryFieldReader::read(std::size_t z0, std::size_t z1, std::span<double> out) {
  read_any(z0, z1, out);
}

template <typename T>
void GeometryFieldReader::read_any(std::size_t z0, std::size_t z1, std::span<T> out) {
  values_.resize(out.size());
  reader_.read_vertical_geometry(step_, z0, z1, values_);
  // The values as stored: rounded to the field's dtype, then checked again, since two
  // close levels may round to one value.
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = static_cast<T>(values_[i]);
    values_[i] = static_cast<double>(out[i]);
  }
  for (std::size_t k = z0; k < z1; ++k) {
    columns_.add_level(k, std::span<const double>(values_).subspan((k - z0) * plane_, plane_));
  }
  if (columns_.direction() != 0 && columns_.direction() != direction_) {
    const format::VerticalGeometry& g = manifest_.geometry->vertical;
    throw make_error(ErrorCode::kInvalidInput,
                     "{} ({}): at time step {} the columns {} with k, at time step 0 they {}: the "
                     "store records one orientation",
                     fmt::join(g.sources, " + "), g.formula, step_,
                     columns_.direction() > 0 ? "grow" : "shrink",
                     direction_ > 0 ? "grow" : "shrink");
  }
}

}  // namespace strielad::build
