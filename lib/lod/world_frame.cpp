// SPDX-License-Identifier: Apache-2.0
#include "lod/world_frame.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"
#include "format/curvilinear_lonlat.h"
#include "geo/grid_projection.h"
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
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Index i of the cell [v[i], v[i + 1]] that holds `value` (clamped to the axis's cells),
// for strictly monotonic v with at least two values.
std::size_t cell_of(const std::vector<double>& v, double value) {
  const bool ascending = v.back() > v.front();
  const auto it = ascending ? std::upper_bound(v.begin(), v.end(), value)
                            : std::upper_bound(v.begin(), v.end(), value, std::greater<>());
  const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - v.begin() - 1, 0));
  return std::min(i, v.size() - 2);
}

// Piecewise-linear from `from` to `to` (both strictly monotonic, the same size >= 2),
// linearly continued beyond the ends.
double interpolate_levels(const std::vector<double>& from, const std::vector<double>& to,
                          double value) {
  const std::size_t i = cell_of(from, value);
  const double t = (value - from[i]) / (from[i + 1] - from[i]);
  return to[i] + t * (to[i + 1] - to[i]);
}

double largest_spacing(const std::vector<double>& v) {
  double h = 0;
  for (std::size_t i = 1; i < v.size(); ++i) h = std::max(h, std::fabs(v[i] - v[i - 1]));
  return h;
}

// The largest |f''| along each of `lines` grid lines, f the world x and y of the samples
// at positions `along`: second divided differences (an axis of two samples: the
// midpoint's offset from the chord, through PROJ). sample(k, l) is the world position of
// sample k of line l, midpoint_world(l) that of line l's first midpoint.
template <typename Sample, typename MidpointWorld>
std::vector<std::array<double, 2>> grid_line_bends(const std::vector<double>& along,
                                                   std::size_t lines, Sample sample,
                                                   MidpointWorld midpoint_world) {
  std::vector<std::array<double, 2>> out(lines, {0.0, 0.0});
  const std::size_t n = along.size();
  for (std::size_t l = 0; l < lines; ++l) {
    if (n == 2) {
      const double h = along[1] - along[0];
      const auto mid = midpoint_world(l);
      for (int c = 0; c < 2; ++c) {
        const double chord = 0.5 * (sample(0, l)[c] + sample(1, l)[c]);
        out[l][c] = std::isfinite(mid[c]) ? 8.0 * std::fabs(mid[c] - chord) / (h * h) : 0.0;
      }
    }
    for (std::size_t k = 1; k + 1 < n; ++k) {
      const double h0 = along[k] - along[k - 1], h1 = along[k + 1] - along[k];
      for (int c = 0; c < 2; ++c) {
        const double d1 = (sample(k + 1, l)[c] - sample(k, l)[c]) / h1;
        const double d0 = (sample(k, l)[c] - sample(k - 1, l)[c]) / h0;
        out[l][c] = std::max(out[l][c], std::fabs(2.0 * (d1 - d0) / (h0 + h1)));
      }
    }
  }
  return out;
}

}  // namespace

struct WorldFrame::Mapped {
  std::string proj;           // the PROJ pipeline: axis x/y to longitude/latitude
  std::string variable, name;  // the grid mapping, for messages
  std::vector<double> x, y;    // axis values
  bool degrees = false;        // x/y in degrees (a rotated pole)
  double x_mid = 0;
  std::size_t nx = 0, ny = 0;
  std::vector<std::array<double, 2>> xy;  // world km of sample (i, j) at j * nx + i
  // Estimated largest |f''| (world km per axis unit squared) of world x and y along each
  // row j (f of x) and each column i (f of y).
  std::vector<std::array<double, 2>> row_bend, col_bend;
  double hx = 0, hy = 0;  // largest sample spacing along x and y (axis units)
  const geo::GridProjection& projection() const {
    return geo::GridProjection::for_this_thread(proj);
  }
  const std::array<double, 2>& at(std::size_t i, std::size_t j) const { return xy[j * nx + i]; }

  // Every sample's world position on the plane tangent at (lon0, lat0); x_name and
  // y_name name the axes in errors.
  void place_samples(double lon0, double lat0, double km_per_lon, const std::string& x_name,
                     const std::string& y_name) {
    const geo::GridProjection& p = projection();
    xy.resize(nx * ny);
    for (std::size_t j = 0; j < ny; ++j) {
      for (std::size_t i = 0; i < nx; ++i) {
        const auto g = p.to_geographic(x[i], y[j]);
        if (!std::isfinite(g[0]) || !std::isfinite(g[1])) {
          throw make_error(ErrorCode::kUnsupported,
                           "grid mapping '{}' ({}) gives sample ({}, {}) ({} {}, {} {}) no "
                           "geographic position",
                           variable, name, i, j, x_name, x[i], y_name, y[j]);
        }
        xy[j * nx + i] = {std::remainder(g[0] - lon0, 360.0) * km_per_lon,
                          (g[1] - lat0) * kKmPerDegree};
      }
    }
  }

  // Tears: neighbours more than half a turn of longitude apart lie on both sides of the
  // meridian opposite the centre, where the plane is cut.
  void check_tears(double lon0, double lat0, double km_per_lon) const {
    const double half_turn_km = 180.0 * km_per_lon;
    const auto tear = [&](std::size_t i0, std::size_t j0, std::size_t i1, std::size_t j1) {
      if (std::fabs(at(i1, j1)[0] - at(i0, j0)[0]) > half_turn_km) {
        throw make_error(ErrorCode::kUnsupported,
                         "grid mapping '{}' ({}): samples ({}, {}) and ({}, {}) lie on both "
                         "sides of longitude {:.2f}, opposite the domain's centre (the grid goes "
                         "round a pole or across the whole Earth): the viewer's plane, tangent at "
                         "the centre ({:.2f} N, {:.2f} E), cannot show it",
                         variable, name, i0, j0, i1, j1, std::remainder(lon0 + 180.0, 360.0),
                         lat0, lon0);
      }
    };
    for (std::size_t j = 0; j < ny; ++j) {
      for (std::size_t i = 0; i < nx; ++i) {
        if (i + 1 < nx) tear(i, j, i + 1, j);
        if (j + 1 < ny) tear(i, j, i, j + 1);
      }
    }
  }

  // Folds: every cell must keep the orientation of the others. Returns that orientation
  // (1 or -1), or 0 for a grid of one row or column.
  int cell_orientation() const {
    int orientation = 0;
    for (std::size_t j = 0; j + 1 < ny; ++j) {
      for (std::size_t i = 0; i + 1 < nx; ++i) {
        const auto& p = at(i, j);
        const auto& px = at(i + 1, j);
        const auto& py = at(i, j + 1);
        const double det = (px[0] - p[0]) * (py[1] - p[1]) - (px[1] - p[1]) * (py[0] - p[0]);
        const int s = det > 0 ? 1 : det < 0 ? -1 : 0;
        if (s != 0 && orientation != 0 && s != orientation) {
          throw make_error(ErrorCode::kUnsupported,
                           "grid mapping '{}' ({}) folds the grid over itself at cell ({}, {}): "
                           "the viewer cannot place it",
                           variable, name, i, j);
        }
        if (orientation == 0) orientation = s;
      }
    }
    return orientation;
  }
};

// Horizontal: a grid mapping first, then length units (a Cartesian grid; a projected
// grid was once read with x/y kinds lon/lat), then longitude/latitude.
void WorldFrame::place_horizontal(const format::Manifest& m) {
  const auto kx = km_per_length_unit(m.x.units), ky = km_per_length_unit(m.y.units);
  const bool mapped = m.grid_mapping && !m.grid_mapping->proj.empty() &&
                      m.x.kind == AxisKind::kProjectionX && m.y.kind == AxisKind::kProjectionY;
  origin_ = {midpoint(m.x), midpoint(m.y)};
  axis_ranges_ = {std::min(m.x.values.front(), m.x.values.back()),
                  std::max(m.x.values.front(), m.x.values.back()),
                  std::min(m.y.values.front(), m.y.values.back()),
                  std::max(m.y.values.front(), m.y.values.back())};
  axis_names_ = fmt::format("'{}' and '{}'", m.x.name, m.y.name);
  if (format::is_curvilinear(m)) {
    horizontal_ = HorizontalMap::kCurvilinear;
    axis_km_ = {0.0, 0.0};
  } else if (mapped) {
    horizontal_ = HorizontalMap::kMapped;
    axis_km_ = {kx.value_or(0.0), ky.value_or(0.0)};
  } else if (kx && ky) {
    horizontal_ = HorizontalMap::kMetric;
    km_per_unit_ = {*kx, *ky};
    axis_km_ = km_per_unit_;
    no_earth_reason_ = fmt::format(
        "axes '{}' ({}) and '{}' ({}) are Cartesian coordinates without a grid_mapping: the "
        "grid has no place on the Earth",
        m.x.name, m.x.units, m.y.name, m.y.units);
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
    lon0_ = origin_[0];
    lat0_ = origin_[1];
    km_per_lon_ = km_per_unit_[0];
  } else {
    throw make_error(ErrorCode::kUnsupported,
                     "axes '{}' ({}, units '{}') and '{}' ({}, units '{}') have no world "
                     "position: need longitude and latitude, map coordinates with a "
                     "grid_mapping, or both in m or km",
                     m.x.name, axis_kind_name(m.x.kind), m.x.units, m.y.name,
                     axis_kind_name(m.y.kind), m.y.units);
  }
}

void WorldFrame::place_level_heights(const Axis& z, std::vector<double> heights) {
  if (heights.size() != z.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "vertical axis '{}': {} level heights for its {} samples", z.name,
                     heights.size(), z.size());
  }
  for (std::size_t k = 0; k < heights.size(); ++k) {
    const bool monotonic = k == 0 || (heights.size() > 1 && (heights[1] > heights[0]
                                                                 ? heights[k] > heights[k - 1]
                                                                 : heights[k] < heights[k - 1]));
    if (!std::isfinite(heights[k]) || !monotonic) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "vertical axis '{}': level height {} m at index {} is not finite or not "
                       "strictly monotonic",
                       z.name, heights[k], k);
    }
  }
  vertical_ = VerticalMap::kLevelHeights;
  level_heights_m_ = std::move(heights);
  const double span = z.values.back() - z.values.front();
  vertical_unit_ =
      z.size() > 1 ? (level_heights_m_.back() - level_heights_m_.front()) / span : 1.0;
}

void WorldFrame::place_vertical(const format::Manifest& m, std::vector<double> level_heights) {
  const Axis& z = m.z;
  const format::VerticalGeometry* geometry = m.geometry ? &m.geometry->vertical : nullptr;
  if (!level_heights.empty()) {
    place_level_heights(z, std::move(level_heights));
  } else if (geometry && geometry->kind == format::VerticalGeometry::Kind::kLevels) {
    std::vector<double> heights;
    for (double v : geometry->levels) {
      heights.push_back(geometry->quantity == format::VerticalGeometry::Quantity::kPressure
                            ? geo::standard_height_m(v)
                            : v);
    }
    place_level_heights(z, std::move(heights));
  } else if (geometry && geometry->kind == format::VerticalGeometry::Kind::kField) {
    throw make_error(ErrorCode::kUnsupported,
                     "vertical axis '{}' ({}) of a terrain-following store is placed by its "
                     "geometry field ({}, per sample): the world frame needs one representative "
                     "height per level (level_heights_m)",
                     z.name, axis_kind_name(z.kind),
                     format::vertical_quantity_name(geometry->quantity));
  } else if (z.kind == AxisKind::kHeight) {
    vertical_ = VerticalMap::kHeight;
    const auto km = z.units.empty() ? std::optional<double>(1e-3) : km_per_length_unit(z.units);
    if (!km) {
      throw make_error(ErrorCode::kUnsupported,
                       "height axis '{}' has units '{}'; need m or km", z.name, z.units);
    }
    vertical_unit_ = *km * 1000.0;
  } else if (z.kind == AxisKind::kPressure) {
    vertical_ = VerticalMap::kPressure;
    const auto pa = pascals_per_pressure_unit(z.units);
    if (!pa) {
      throw make_error(ErrorCode::kUnsupported,
                       "pressure axis '{}' has units '{}'; need Pa, hPa, mbar, kPa, bar or atm",
                       z.name, z.units);
    }
    vertical_unit_ = *pa;
    for (std::size_t i = 0; i < z.size(); ++i) {
      if (!(z.values[i] > 0)) {
        throw make_error(ErrorCode::kInvalidInput,
                         "pressure axis '{}' has value {} {} at index {}; a height needs a "
                         "pressure > 0",
                         z.name, z.values[i], z.units, i);
      }
    }
  } else {
    throw make_error(ErrorCode::kUnsupported,
                     "vertical axis '{}' is {} (units '{}'): only height and pressure axes "
                     "have a world position",
                     z.name, axis_kind_name(z.kind), z.units);
  }
  z_axis_ = z.values;
  z_samples_.reserve(z.size());
  for (double v : z.values) z_samples_.push_back(vertical_to_world(v));
  const auto [lo, hi] = std::minmax_element(z_samples_.begin(), z_samples_.end());
  domain_.lo[2] = *lo;
  domain_.hi[2] = *hi;
}

// A mapped grid: the centre's true position, then every sample's world position.
void WorldFrame::place_mapped(const format::Manifest& m, bool z_negative) {
  auto t = std::make_shared<Mapped>();
  const GridMapping& gm = *m.grid_mapping;
  t->proj = gm.proj;
  t->variable = gm.variable;
  t->name = gm.name;
  t->x = m.x.values;
  t->y = m.y.values;
  t->nx = m.x.size();
  t->ny = m.y.size();
  t->degrees = !km_per_length_unit(m.x.units);
  t->x_mid = origin_[0];
  const geo::GridProjection& projection = t->projection();  // kUnsupported if PROJ rejects it
  const auto centre = projection.to_geographic(origin_[0], origin_[1]);
  if (!std::isfinite(centre[0]) || !std::isfinite(centre[1])) {
    throw make_error(ErrorCode::kUnsupported,
                     "grid mapping '{}' ({}) gives the domain's centre ({} {}, {} {}) no "
                     "geographic position",
                     gm.variable, gm.name, m.x.name, origin_[0], m.y.name, origin_[1]);
  }
  lon0_ = std::remainder(centre[0], 360.0);
  lat0_ = centre[1];
  const double cos_lat0 = std::cos(lat0_ * kDegree);
  if (!(cos_lat0 > 1e-3)) {
    throw make_error(ErrorCode::kUnsupported,
                     "grid mapping '{}' ({}) centres the domain at latitude {}: a plane tangent "
                     "at the pole has no east-west scale",
                     gm.variable, gm.name, lat0_);
  }
  km_per_lon_ = kKmPerDegree * cos_lat0;
  t->place_samples(lon0_, lat0_, km_per_lon_, m.x.name, m.y.name);
  t->check_tears(lon0_, lat0_, km_per_lon_);
  int orientation = t->cell_orientation();
  mapped_ = t;  // mapped_xy below needs it
  t->row_bend = grid_line_bends(
      t->x, t->ny, [&](std::size_t k, std::size_t l) { return t->at(k, l); },
      [&](std::size_t l) { return mapped_xy(0.5 * (t->x[0] + t->x[1]), t->y[l]); });
  t->col_bend = grid_line_bends(
      t->y, t->nx, [&](std::size_t k, std::size_t l) { return t->at(l, k); },
      [&](std::size_t l) { return mapped_xy(t->x[l], 0.5 * (t->y[0] + t->y[1])); });
  t->hx = largest_spacing(t->x);
  t->hy = largest_spacing(t->y);
  if (orientation == 0) {  // one row or column: the mapping's own Jacobian at the centre
    const auto j = projection.jacobian(origin_[0], origin_[1],
                                       1e-6 * std::max({t->hx, t->hy, 1e-3}));
    const double det = j[0] * j[3] - j[1] * j[2];
    orientation = det < 0 ? -1 : 1;
  }
  mirrored_ = (orientation < 0) != z_negative;
  const WorldBox all =
      mapped_index_box(IndexBox{{0, 0, 0}, {t->nx - 1, t->ny - 1, m.z.size() - 1}});
  domain_.lo[0] = all.lo[0];
  domain_.lo[1] = all.lo[1];
  domain_.hi[0] = all.hi[0];
  domain_.hi[1] = all.hi[1];
}

// A curvilinear grid: the centre index's true position, then every column on the plane.
void WorldFrame::place_curvilinear(const format::Manifest& m, bool z_negative,
                                   const std::shared_ptr<const format::HorizontalCoordinates>& c) {
  const auto& h = m.geometry->horizontal;
  const std::string what =
      fmt::format("curvilinear grid ('{}' / '{}')", h.lon_variable, h.lat_variable);
  if (c == nullptr || !c->has_coordinates()) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: the world frame places its columns by the store's GEOMETRY "
                     "coordinates, and none were given (they are read from the store's files "
                     "on this machine)",
                     what);
  }
  if (c->nx != m.x.size() || c->ny != m.y.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: GEOMETRY coordinates of {} x {} columns for a grid of {} x {}", what,
                     c->nx, c->ny, m.x.size(), m.y.size());
  }
  const auto centre = CurvilinearLonLat(c).centre();
  lon0_ = std::remainder(centre[0], 360.0);
  lat0_ = centre[1];
  const double cos_lat0 = std::cos(lat0_ * kDegree);
  if (!(cos_lat0 > 1e-3)) {
    throw make_error(ErrorCode::kUnsupported,
                     "{} is centred at latitude {}: a plane tangent at the pole has no "
                     "east-west scale",
                     what, lat0_);
  }
  km_per_lon_ = kKmPerDegree * cos_lat0;
  auto plane = std::make_shared<CurvilinearPlane>(*c, lon0_, lat0_, km_per_lon_, what);
  mirrored_ = (plane->orientation() < 0) != z_negative;
  const auto all = plane->box_of(IndexBox{{0, 0, 0}, {c->nx - 1u, c->ny - 1u, 0}});
  domain_.lo[0] = all[0];
  domain_.lo[1] = all[1];
  domain_.hi[0] = all[2];
  domain_.hi[1] = all[3];
  curvilinear_ = std::move(plane);
  curvilinear_what_ = what;
}

WorldFrame::WorldFrame(const format::Manifest& m, WorldFrameOptions options,
                       std::vector<double> level_heights_m,
                       std::shared_ptr<const format::HorizontalCoordinates> coordinates)
    : exaggeration_(options.vertical_exaggeration), dims_(m.dims()) {
  place(m, std::move(level_heights_m), coordinates);
  choose_shape(options.shape);
}

void WorldFrame::place(const format::Manifest& m, std::vector<double> level_heights_m,
                       const std::shared_ptr<const format::HorizontalCoordinates>& coordinates) {
  if (!std::isfinite(exaggeration_) || exaggeration_ <= 0) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "vertical exaggeration {} must be a finite number > 0", exaggeration_);
  }
  check_axis_values(m.x, "grid.x");
  check_axis_values(m.y, "grid.y");
  check_axis_values(m.z, "grid.z");
  place_horizontal(m);
  place_vertical(m, std::move(level_heights_m));
  // Whether the vertical map decreases, at the middle of the domain's height.
  const double z_mid = world_to_vertical(0.5 * (domain_.lo[2] + domain_.hi[2]));
  const double hz = std::max(std::abs(z_mid), 1.0) * 1e-6;
  const bool z_negative = vertical_to_world(z_mid + hz) - vertical_to_world(z_mid - hz) < 0;
  if (horizontal_ == HorizontalMap::kMapped) {
    place_mapped(m, z_negative);
    return;
  }
  if (horizontal_ == HorizontalMap::kCurvilinear) {
    place_curvilinear(m, z_negative, coordinates);
    return;
  }
  const std::array<const Axis*, 2> axes{&m.x, &m.y};
  for (int a = 0; a < 2; ++a) {
    auto& w = xy_samples_[a];
    w.reserve(axes[a]->size());
    for (double v : axes[a]->values) w.push_back(separable_to_world(a, v));
    const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
    domain_.lo[a] = *lo;
    domain_.hi[a] = *hi;
  }
  mirrored_ = z_negative;  // x and y map with positive slopes
}

WorldFrame WorldFrame::with_exaggeration(double e) const {
  if (!std::isfinite(e) || e <= 0) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "vertical exaggeration {} must be a finite number > 0", e);
  }
  WorldFrame f = *this;
  f.exaggeration_ = e;
  for (std::size_t k = 0; k < z_axis_.size(); ++k) {
    f.z_samples_[k] = f.vertical_to_world(z_axis_[k]);
  }
  const auto [lo, hi] = std::minmax_element(f.z_samples_.begin(), f.z_samples_.end());
  f.plane_domain_.lo[2] = *lo;
  f.plane_domain_.hi[2] = *hi;
  f.domain_ = f.globe_ ? f.globe_index_box(IndexBox{{0, 0, 0}, {dims_.x - 1, dims_.y - 1,
                                                                 dims_.z - 1}})
                       : f.plane_domain_;
  return f;
}

double WorldFrame::separable_to_world(int axis, double value) const {
  return (value - origin_[axis]) * km_per_unit_[axis];
}

double WorldFrame::separable_to_axis(int axis, double world) const {
  return world / km_per_unit_[axis] + origin_[axis];
}

double WorldFrame::vertical_to_world(double value) const {
  double metres = 0;
  switch (vertical_) {
    case VerticalMap::kHeight:
      metres = value * vertical_unit_;
      break;
    case VerticalMap::kPressure:
      metres = geo::standard_height_m(value * vertical_unit_);
      break;
    case VerticalMap::kLevelHeights:
      metres = z_axis_.size() < 2 ? level_heights_m_[0]
                                  : interpolate_levels(z_axis_, level_heights_m_, value);
      break;
  }
  return metres * 1e-3 * exaggeration_;
}

double WorldFrame::world_to_vertical(double world) const {
  const double metres = world / exaggeration_ * 1e3;
  switch (vertical_) {
    case VerticalMap::kHeight:
      return metres / vertical_unit_;
    case VerticalMap::kPressure:
      return geo::standard_pressure_pa(metres) / vertical_unit_;
    case VerticalMap::kLevelHeights:
      return z_axis_.size() < 2 ? z_axis_[0]
                                : interpolate_levels(level_heights_m_, z_axis_, metres);
  }
  return metres;
}

std::array<double, 2> WorldFrame::mapped_xy(double x, double y) const {
  const auto g = mapped_->projection().to_geographic(x, y);
  return {std::remainder(g[0] - lon0_, 360.0) * km_per_lon_, (g[1] - lat0_) * kKmPerDegree};
}

Vec3 WorldFrame::to_world(const Vec3& p) const {
  const Vec3 plane = plane_to_world(p);
  return globe_ ? plane_to_globe(plane) : plane;
}

Vec3 WorldFrame::to_axis(const Vec3& world) const {
  return plane_to_axis(globe_ ? globe_to_plane(world) : world);
}

Vec3 WorldFrame::normal_to_world(const Vec3& p, const Vec3& n) const {
  const Vec3 plane = plane_normal(p, n);
  return globe_ ? globe_normal(plane_to_world(p), plane) : plane;
}

Vec3 WorldFrame::plane_to_world(const Vec3& p) const {
  if (curvilinear_) {
    const auto xy = curvilinear_->position(p[0], p[1]);
    return {xy[0], xy[1], vertical_to_world(p[2])};
  }
  if (mapped_) {
    const auto xy = mapped_xy(p[0], p[1]);
    return {xy[0], xy[1], vertical_to_world(p[2])};
  }
  return {separable_to_world(0, p[0]), separable_to_world(1, p[1]), vertical_to_world(p[2])};
}

Vec3 WorldFrame::plane_to_axis(const Vec3& p) const {
  if (curvilinear_) {
    const auto a = curvilinear_->index_of(p[0], p[1]);
    return {a[0], a[1], world_to_vertical(p[2])};
  }
  if (mapped_) {
    const auto g = geographic_of_plane(p[0], p[1]);
    const auto a = geographic_to_axis(g[0], g[1]);
    return {a[0], a[1], world_to_vertical(p[2])};
  }
  return {separable_to_axis(0, p[0]), separable_to_axis(1, p[1]), world_to_vertical(p[2])};
}

Vec3 WorldFrame::plane_normal(const Vec3& p, const Vec3& n) const {
  // d world / d axis along one axis at `value`, by a central difference scaled to the
  // value (the maps are smooth and monotonic; linear ones give their exact slope).
  const auto slope = [this](int axis, double value) {
    const double h = std::max(std::abs(value), 1.0) * 1e-6;
    if (axis == 2) return (vertical_to_world(value + h) - vertical_to_world(value - h)) / (2 * h);
    return (separable_to_world(axis, value + h) - separable_to_world(axis, value - h)) / (2 * h);
  };
  Vec3 g{0, 0, 0};
  if (curvilinear_) {
    // The bilinear map's Jacobian in the cell the position uses.
    const auto j = curvilinear_->jacobian(p[0], p[1]);
    const double det = j[0] * j[3] - j[1] * j[2];
    g[0] = (j[3] * n[0] - j[2] * n[1]) / det;
    g[1] = (-j[1] * n[0] + j[0] * n[1]) / det;
    g[2] = n[2] / slope(2, p[2]);
  } else if (!mapped_) {
    for (int axis = 0; axis < 3; ++axis) g[axis] = n[axis] / slope(axis, p[axis]);
  } else {
    // The horizontal Jacobian {dX/dx, dX/dy, dY/dx, dY/dy} of the bilinear interpolant of
    // the sample table (exact at the samples; shading needs no more), by PROJ when an axis
    // has a single sample. Normals transform by its inverse transpose.
    const Mapped& t = *mapped_;
    std::array<double, 4> j{};
    if (t.nx >= 2 && t.ny >= 2) {
      const std::size_t i = cell_of(t.x, p[0]), k = cell_of(t.y, p[1]);
      const double hx = t.x[i + 1] - t.x[i], hy = t.y[k + 1] - t.y[k];
      const double u = std::clamp((p[0] - t.x[i]) / hx, 0.0, 1.0);
      const double v = std::clamp((p[1] - t.y[k]) / hy, 0.0, 1.0);
      const auto& a = t.at(i, k);
      const auto& b = t.at(i + 1, k);
      const auto& c = t.at(i, k + 1);
      const auto& d = t.at(i + 1, k + 1);
      for (int w = 0; w < 2; ++w) {
        j[w * 2 + 0] = ((1 - v) * (b[w] - a[w]) + v * (d[w] - c[w])) / hx;
        j[w * 2 + 1] = ((1 - u) * (c[w] - a[w]) + u * (d[w] - b[w])) / hy;
      }
    } else {
      const auto dj = t.projection().jacobian(p[0], p[1], 1e-6 * std::max({t.hx, t.hy, 1e-3}));
      j = {dj[0] * km_per_lon_, dj[1] * km_per_lon_, dj[2] * kKmPerDegree, dj[3] * kKmPerDegree};
    }
    const double det = j[0] * j[3] - j[1] * j[2];
    g[0] = (j[3] * n[0] - j[2] * n[1]) / det;
    g[1] = (-j[1] * n[0] + j[0] * n[1]) / det;
    g[2] = n[2] / slope(2, p[2]);
  }
  const double len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  if (!(len > 0) || !std::isfinite(len)) return {0.0, 0.0, 1.0};
  return {g[0] / len, g[1] / len, g[2] / len};
}

void WorldFrame::check_on_earth() const {
  if (!on_earth()) throw make_error(ErrorCode::kUnsupported, "{}", no_earth_reason_);
}

std::array<double, 2> WorldFrame::plane_of_geographic(double lon, double lat) const {
  return {std::remainder(lon - lon0_, 360.0) * km_per_lon_, (lat - lat0_) * kKmPerDegree};
}

std::array<double, 2> WorldFrame::geographic_of_plane(double x, double y) const {
  return {x / km_per_lon_ + lon0_, y / kKmPerDegree + lat0_};
}

std::array<double, 2> WorldFrame::geographic_to_world(double lon, double lat) const {
  check_on_earth();
  check_plane("geographic_to_world");
  return plane_of_geographic(lon, lat);
}

std::array<double, 2> WorldFrame::world_to_geographic(double x, double y) const {
  check_on_earth();
  check_plane("world_to_geographic");
  return geographic_of_plane(x, y);
}

std::array<double, 2> WorldFrame::geographic_to_axis(double lon, double lat) const {
  check_on_earth();
  if (curvilinear_) {
    if (!(std::fabs(lat) <= 90.0)) return {kNaN, kNaN};
    const auto xy = plane_of_geographic(lon, lat);
    return curvilinear_->index_of(xy[0], xy[1]);
  }
  if (!mapped_) return {lon0_ + std::remainder(lon - lon0_, 360.0), lat};
  if (!(std::fabs(lat) <= 90.0)) return {kNaN, kNaN};
  auto a = mapped_->projection().to_axis(lon, lat);
  // A rotated pole's grid longitude comes back in (-180, 180]: near the axis's range.
  if (mapped_->degrees) a[0] = mapped_->x_mid + std::remainder(a[0] - mapped_->x_mid, 360.0);
  return a;
}

double WorldFrame::lon0() const {
  check_on_earth();
  return lon0_;
}

double WorldFrame::lat0() const {
  check_on_earth();
  return lat0_;
}

GeographicBounds WorldFrame::geographic_bounds() const {
  check_on_earth();
  const auto a = geographic_of_plane(plane_domain_.lo[0], plane_domain_.lo[1]);
  const auto b = geographic_of_plane(plane_domain_.hi[0], plane_domain_.hi[1]);
  return {std::min(a[0], b[0]), std::max(a[0], b[0]), std::min(a[1], b[1]), std::max(a[1], b[1])};
}

std::array<double, 2> WorldFrame::sample_world_xy(std::size_t i, std::size_t j) const {
  if (curvilinear_) return curvilinear_->at(i, j);
  if (mapped_) return mapped_->at(i, j);
  return {xy_samples_[0][i], xy_samples_[1][j]};
}

std::string WorldFrame::describe_horizontal() const {
  switch (horizontal_) {
    case HorizontalMap::kGeographic:
      return fmt::format("longitude/latitude axes {}, centred at {:.2f} N, {:.2f} E", axis_names_,
                         lat0_, lon0_);
    case HorizontalMap::kMapped:
      return fmt::format("axes {} placed by grid mapping '{}' ({}) through PROJ, centred at "
                         "{:.2f} N, {:.2f} E",
                         axis_names_, mapped_->variable, mapped_->name, lat0_, lon0_);
    case HorizontalMap::kMetric:
      return no_earth_reason_;
    case HorizontalMap::kCurvilinear:
      return fmt::format("index axes {} of a {} placed by its 2-D longitudes and latitudes, "
                         "centred at {:.2f} N, {:.2f} E",
                         axis_names_, curvilinear_what_, lat0_, lon0_);
  }
  return {};
}

WorldBox WorldFrame::mapped_index_box(const IndexBox& box) const {
  const Mapped& t = *mapped_;
  WorldBox b{{INFINITY, INFINITY, 0}, {-INFINITY, -INFINITY, 0}};
  const auto take = [&b](const std::array<double, 2>& p) {
    for (int a = 0; a < 2; ++a) {
      b.lo[a] = std::min(b.lo[a], p[a]);
      b.hi[a] = std::max(b.hi[a], p[a]);
    }
  };
  for (std::size_t i = box.lo[0]; i <= box.hi[0]; ++i) {
    take(t.at(i, box.lo[1]));
    take(t.at(i, box.hi[1]));
  }
  for (std::size_t j = box.lo[1]; j <= box.hi[1]; ++j) {
    take(t.at(box.lo[0], j));
    take(t.at(box.hi[0], j));
  }
  // The grid lines between samples bow away from their chords by up to h^2 / 8 max|f''|;
  // twice that, so that f'' may grow between the samples that estimate it.
  for (int c = 0; c < 2; ++c) {
    const double rows = std::max(t.row_bend[box.lo[1]][c], t.row_bend[box.hi[1]][c]);
    const double cols = std::max(t.col_bend[box.lo[0]][c], t.col_bend[box.hi[0]][c]);
    const double pad = 0.25 * std::max(rows * t.hx * t.hx, cols * t.hy * t.hy);
    b.lo[c] -= pad;
    b.hi[c] += pad;
  }
  return b;
}

WorldBox WorldFrame::index_box_world(const IndexBox& box) const {
  return globe_ ? globe_index_box(box) : plane_index_box(box);
}

WorldBox WorldFrame::plane_index_box(const IndexBox& box) const {
  WorldBox b;
  if (curvilinear_) {
    const auto xy = curvilinear_->box_of(box);
    b.lo[0] = xy[0];
    b.lo[1] = xy[1];
    b.hi[0] = xy[2];
    b.hi[1] = xy[3];
  } else if (mapped_) {
    b = mapped_index_box(box);
  } else {
    for (int a = 0; a < 2; ++a) {
      const double u = xy_samples_[a][box.lo[a]], v = xy_samples_[a][box.hi[a]];
      b.lo[a] = std::min(u, v);
      b.hi[a] = std::max(u, v);
    }
  }
  const double u = z_samples_[box.lo[2]], v = z_samples_[box.hi[2]];
  b.lo[2] = std::min(u, v);
  b.hi[2] = std::max(u, v);
  return b;
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
          boxes[id] = frame.index_box_world(layout.fine_box(key));
        }
      }
    }
  }
  return boxes;
}

}  // namespace strielad::lod
