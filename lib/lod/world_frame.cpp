// SPDX-License-Identifier: Apache-2.0
#include "lod/world_frame.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"
#include "geo/standard_atmosphere.h"
#include "grid/units.h"

namespace strielad::lod {
namespace {

// Kilometres per unit of a length, or nothing for other units.
std::optional<double> km_per_length_unit(std::string_view units) {
  const auto m = metres_per_length_unit(units);
  return m ? std::optional<double>(*m * 1e-3) : std::nullopt;
}

double midpoint(const Axis& axis) { return 0.5 * (axis.values.front() + axis.values.back()); }

constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

WorldFrame::WorldFrame(const format::Manifest& m, WorldFrameOptions options)
    : exaggeration_(options.vertical_exaggeration), dims_(m.dims()) {
  if (!std::isfinite(exaggeration_) || exaggeration_ <= 0) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "vertical exaggeration {} must be a finite number > 0", exaggeration_);
  }
  check_axis_values(m.x, "grid.x");
  check_axis_values(m.y, "grid.y");
  check_axis_values(m.z, "grid.z");

  // Horizontal: length units first (a projected grid is read with x/y kinds lon/lat).
  const auto kx = km_per_length_unit(m.x.units), ky = km_per_length_unit(m.y.units);
  origin_ = {midpoint(m.x), midpoint(m.y)};
  if (kx && ky) {
    horizontal_ = HorizontalMap::kMetric;
    km_per_unit_ = {*kx, *ky};
  } else if (m.x.kind == AxisKind::kLongitude && m.y.kind == AxisKind::kLatitude) {
    horizontal_ = HorizontalMap::kGeographic;
    const double cos_lat0 = std::cos(origin_[1] * kDegree);
    if (!(cos_lat0 > 1e-3)) {  // |lat0| above 89.94 degrees, or beyond the poles
      throw make_error(ErrorCode::kUnsupported,
                       "latitude axis '{}' is centred at {} degrees: a plane tangent at the "
                       "pole has no east-west scale",
                       m.y.name, origin_[1]);
    }
    km_per_unit_ = {kKmPerDegree * cos_lat0, kKmPerDegree};
  } else {
    throw make_error(ErrorCode::kUnsupported,
                     "axes '{}' ({}, units '{}') and '{}' ({}, units '{}') have no world "
                     "position: need longitude and latitude, or both in m or km",
                     m.x.name, axis_kind_name(m.x.kind), m.x.units, m.y.name,
                     axis_kind_name(m.y.kind), m.y.units);
  }

  if (m.z.kind == AxisKind::kHeight) {
    vertical_ = VerticalMap::kHeight;
    const auto km = m.z.units.empty() ? std::optional<double>(1e-3) : km_per_length_unit(m.z.units);
    if (!km) {
      throw make_error(ErrorCode::kUnsupported,
                       "height axis '{}' has units '{}'; need m or km", m.z.name, m.z.units);
    }
    vertical_unit_ = *km * 1000.0;
  } else if (m.z.kind == AxisKind::kPressure) {
    vertical_ = VerticalMap::kPressure;
    const auto pa = pascals_per_pressure_unit(m.z.units);
    if (!pa) {
      throw make_error(ErrorCode::kUnsupported,
                       "pressure axis '{}' has units '{}'; need Pa, hPa, mbar, kPa, bar or atm",
                       m.z.name, m.z.units);
    }
    vertical_unit_ = *pa;
    for (std::size_t i = 0; i < m.z.size(); ++i) {
      if (!(m.z.values[i] > 0)) {
        throw make_error(ErrorCode::kInvalidInput,
                         "pressure axis '{}' has value {} {} at index {}; a height needs a "
                         "pressure > 0",
                         m.z.name, m.z.values[i], m.z.units, i);
      }
    }
  } else {
    throw make_error(ErrorCode::kUnsupported,
                     "vertical axis '{}' is {} (units '{}'): only height and pressure axes "
                     "have a world position",
                     m.z.name, axis_kind_name(m.z.kind), m.z.units);
  }

  const std::array<const Axis*, 3> axes{&m.x, &m.y, &m.z};
  for (int a = 0; a < 3; ++a) {
    auto& w = samples_[a];
    w.reserve(axes[a]->size());
    for (double v : axes[a]->values) w.push_back(axis_to_world(a, v));
    const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
    domain_.lo[a] = *lo;
    domain_.hi[a] = *hi;
  }
}

double WorldFrame::axis_to_world(int axis, double value) const {
  if (axis < 2) return (value - origin_[axis]) * km_per_unit_[axis];
  const double metres =
      vertical_ == VerticalMap::kHeight ? value * vertical_unit_ : geo::standard_height_m(value * vertical_unit_);
  return metres * 1e-3 * exaggeration_;
}

double WorldFrame::world_to_axis(int axis, double world) const {
  if (axis < 2) return world / km_per_unit_[axis] + origin_[axis];
  const double metres = world / exaggeration_ * 1e3;
  return vertical_ == VerticalMap::kHeight ? metres / vertical_unit_
                                           : geo::standard_pressure_pa(metres) / vertical_unit_;
}

Vec3 WorldFrame::to_world(const Vec3& p) const {
  return {axis_to_world(0, p[0]), axis_to_world(1, p[1]), axis_to_world(2, p[2])};
}

Vec3 WorldFrame::to_axis(const Vec3& p) const {
  return {world_to_axis(0, p[0]), world_to_axis(1, p[1]), world_to_axis(2, p[2])};
}

std::vector<WorldBox> node_world_boxes(const OctreeLayout& layout, const WorldFrame& frame) {
  if (!(layout.grid() == frame.dims())) {
    const Dims3 g = layout.grid(), d = frame.dims();
    throw make_error(ErrorCode::kInvalidArgument,
                     "octree grid {}x{}x{} does not match the manifest's axes {}x{}x{}", g.x, g.y,
                     g.z, d.x, d.y, d.z);
  }
  std::vector<WorldBox> boxes(layout.node_count());
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const LevelShape& shape = layout.level(l);
    NodeId id = shape.first_node;
    NodeKey key{static_cast<std::uint32_t>(l), {}};
    for (std::uint32_t z = 0; z < shape.nodes[2]; ++z) {
      for (std::uint32_t y = 0; y < shape.nodes[1]; ++y) {
        for (std::uint32_t x = 0; x < shape.nodes[0]; ++x, ++id) {
          key.index = {x, y, z};
          const IndexBox fine = layout.fine_box(key);
          WorldBox& b = boxes[id];
          for (int a = 0; a < 3; ++a) {
            const double u = frame.sample_world(a, fine.lo[a]);
            const double v = frame.sample_world(a, fine.hi[a]);
            b.lo[a] = std::min(u, v);
            b.hi[a] = std::max(u, v);
          }
        }
      }
    }
  }
  return boxes;
}

}  // namespace strielad::lod
