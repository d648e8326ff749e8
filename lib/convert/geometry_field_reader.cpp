// SPDX-License-Identifier: Apache-2.0
#include "convert/geometry_field_reader.h"

#include <fmt/ranges.h>

#include "core/error.h"
#include "geo/horizontal_orientation.h"

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

int field_direction_per_level(const format::Manifest& m) {
  const int up_per_k = m.geometry->orientation * geo::horizontal_orientation(m.x, m.y, m.grid_mapping);
  return m.geometry->vertical.quantity == format::VerticalGeometry::Quantity::kPressure ? -up_per_k
                                                                                       : up_per_k;
}

GeometryFieldReader::GeometryFieldReader(ingest::SlabReader& reader,
                                         const format::Manifest& manifest, std::uint32_t step)
    : reader_(reader),
      manifest_(manifest),
      step_(step),
      direction_(field_direction_per_level(manifest)),
      plane_(manifest.x.size() * manifest.y.size()) {}

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
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<T>(values_[i]);
  const format::VerticalGeometry& g = manifest_.geometry->vertical;
  for (std::size_t k = z0; k < z1; ++k) {
    const T* level = out.data() + (k - z0) * plane_;
    if (has_previous_ && previous_k_ + 1 == k) {
      for (std::size_t p = 0; p < plane_; ++p) {
        const double step = (static_cast<double>(level[p]) - previous_[p]) * direction_;
        if (!(step > 0)) {
          throw make_error(ErrorCode::kInvalidInput,
                           "{} ({}): {} at (i {}, j {}, k {}) of time step {} is {}, at k {} it is "
                           "{}: every column must {} strictly with k, as column (0, 0) does",
                           fmt::join(g.sources, " + "), g.formula,
                           format::vertical_quantity_name(g.quantity), p % manifest_.x.size(),
                           p / manifest_.x.size(), k, step_, static_cast<double>(level[p]),
                           previous_k_, previous_[p], direction_ > 0 ? "grow" : "shrink");
        }
      }
    }
    previous_.assign(level, level + plane_);
    previous_k_ = k;
    has_previous_ = true;
  }
}

}  // namespace strielad::build
