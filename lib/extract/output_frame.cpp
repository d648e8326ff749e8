// SPDX-License-Identifier: Apache-2.0
#include "extract/output_frame.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>

#include <fmt/ranges.h>

#include "core/error.h"
#include "core/vec3.h"
#include "format/geometry_field.h"
#include "geo/horizontal_orientation.h"
#include "geo/standard_atmosphere.h"
#include "geo/wgs84.h"
#include "grid/units.h"
#include "store/store.h"

namespace strielad {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMeanRadius = 6371008.8;
constexpr double kStandardGravity = 9.80665;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Metres per unit of a height or geopotential variable, or nothing.
std::optional<double> height_variable_scale(std::string_view units) {
  std::string u;
  for (char c : lower(units)) {
    if (c != ' ' && c != '*' && c != '^') u += c;
  }
  if (u == "m" || u == "gpm" || u == "metre" || u == "metres" || u == "meter" || u == "meters") {
    return 1.0;
  }
  if (u == "km") return 1000.0;
  if (u == "dam" || u == "gpdam") return 10.0;
  if (u == "m2s-2" || u == "m2/s2" || u == "m2.s-2") return 1.0 / kStandardGravity;
  return std::nullopt;
}

bool geographic_axes(const format::Manifest& m) {
  return m.x.kind == AxisKind::kLongitude && m.y.kind == AxisKind::kLatitude;
}

bool mapped_axes(const format::Manifest& m) {
  return m.grid_mapping && !m.grid_mapping->proj.empty() && m.x.kind == AxisKind::kProjectionX;
}

double midpoint(const Axis& a) { return 0.5 * (a.values.front() + a.values.back()); }

// std::remainder(x, 360.0), the same bits: x itself within [-180, 180] (the remainder
// rounds the quotient 0.5 to the even 0), which longitudes about a centre nearly always
// are, without the library call.
double remainder_360(double x) { return std::fabs(x) <= 180.0 ? x : std::remainder(x, 360.0); }

// Jacobian columns of the frame map at (lon, lat, h): d/dlon, d/dlat (per degree), d/dh.
struct FramePoint {
  Vec3 p, d_lon, d_lat, d_h;
};

using geo::ecef_position;
using geo::ecef_terms;
using geo::EcefTerms;

// Metres per degree of longitude and of latitude on the local metric plane.
std::array<double, 2> metric_scales(double lat0) {
  return {kMeanRadius * std::cos(lat0 * kDeg) * kDeg, kMeanRadius * kDeg};
}

// The frame position of (lon, lat, h) alone: the same bits as frame_point's p.
Vec3 frame_position(OutputFrame frame, double lon, double lat, double h, double lon0, double lat0) {
  if (frame == OutputFrame::kLonLat) return {lon, lat, h};
  if (frame == OutputFrame::kLocalMetric) {
    const auto [sx, sy] = metric_scales(lat0);
    return {sx * (lon - lon0), sy * (lat - lat0), h};
  }
  return ecef_position(ecef_terms(lon, lat), h);
}

FramePoint frame_point(OutputFrame frame, double lon, double lat, double h, double lon0,
                       double lat0) {
  FramePoint f;
  if (frame == OutputFrame::kLonLat) {
    f.p = {lon, lat, h};
    f.d_lon = {1, 0, 0};
    f.d_lat = {0, 1, 0};
    f.d_h = {0, 0, 1};
    return f;
  }
  if (frame == OutputFrame::kLocalMetric) {
    const auto [sx, sy] = metric_scales(lat0);
    f.p = {sx * (lon - lon0), sy * (lat - lat0), h};
    f.d_lon = {sx, 0, 0};
    f.d_lat = {0, sy, 0};
    f.d_h = {0, 0, 1};
    return f;
  }
  const EcefTerms e = ecef_terms(lon, lat);
  const double sl = e.sl, cl = e.cl, so = e.so, co = e.co, n = e.n;
  // Meridional radius of curvature: dN/dlat folded in.
  const double m_radius = e.meridional_radius();
  f.p = ecef_position(e, h);
  f.d_lon = {-(n + h) * cl * so * kDeg, (n + h) * cl * co * kDeg, 0};
  f.d_lat = {-(m_radius + h) * sl * co * kDeg, -(m_radius + h) * sl * so * kDeg,
             (m_radius + h) * cl * kDeg};
  f.d_h = {cl * co, cl * so, sl};
  return f;
}

// Columns of a 3x3 matrix times a vector: a * v[0] + b * v[1] + c * v[2].
Vec3 combine(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& v) {
  return {a[0] * v[0] + b[0] * v[1] + c[0] * v[2], a[1] * v[0] + b[1] * v[1] + c[1] * v[2],
          a[2] * v[0] + b[2] * v[1] + c[2] * v[2]};
}

// The cross products transform_normal needs (they depend on the map alone): J_y x J_z,
// J_z x J_x and J_x x J_y of the Jacobian columns cx, cy, cz.
std::array<Vec3, 3> normal_terms(const Vec3& cx, const Vec3& cy, const Vec3& cz) {
  return {cross(cy, cz), cross(cz, cx), cross(cx, cy)};
}

// Normal n (unit, axis frame) through the map with Jacobian columns cx, cy, cz
// (determinant det, cross products `terms`): n' = J^-T n = (n_x (J_y x J_z) + n_y (J_z x
// J_x) + n_z (J_x x J_y)) / det J, unit length; n is kept where that has none.
void transform_normal(const std::array<Vec3, 3>& terms, double det, std::array<float, 3>& n) {
  const auto& [a, b, c] = terms;
  Vec3 g{};
  for (int i = 0; i < 3; ++i) g[i] = (n[0] * a[i] + n[1] * b[i] + n[2] * c[i]) / det;
  const double len = std::sqrt(dot(g, g));
  if (len > 0 && std::isfinite(len)) {
    n = {static_cast<float>(g[0] / len), static_cast<float>(g[1] / len), static_cast<float>(g[2] / len)};
  }
}

void transform_normal(const Vec3& cx, const Vec3& cy, const Vec3& cz, double det, std::array<float, 3>& n) {
  transform_normal(normal_terms(cx, cy, cz), det, n);
}

// The mesh's normals as its own area-weighted face normals (where those have a length),
// every triangle's winding first reversed when `reverse` (in the same pass); `sum` is
// scratch, one entry per vertex.
template <bool kReverse>
void sum_face_normals(Mesh& mesh, Vec3* __restrict sum) {
  const Vec3* __restrict p = mesh.positions.data();
  for (auto& t : mesh.triangles) {
    if constexpr (kReverse) std::swap(t[1], t[2]);
    const std::uint32_t i0 = t[0], i1 = t[1], i2 = t[2];
    const Vec3 n = cross(sub(p[i1], p[i0]), sub(p[i2], p[i0]));  // area_normal (mesh_metrics.h)
    for (const std::uint32_t i : {i0, i1, i2}) {
      Vec3& s = sum[i];
      s[0] += n[0];
      s[1] += n[1];
      s[2] += n[2];
    }
  }
}

void placed_surface_normals(Mesh& mesh, bool reverse, std::vector<Vec3>& sum) {
  sum.assign(mesh.positions.size(), Vec3{0, 0, 0});
  if (reverse) {
    sum_face_normals<true>(mesh, sum.data());
  } else {
    sum_face_normals<false>(mesh, sum.data());
  }
  const std::size_t count = std::min(sum.size(), mesh.normals.size());
  const Vec3* __restrict s = sum.data();
  std::array<float, 3>* __restrict out = mesh.normals.data();
  for (std::size_t v = 0; v < count; ++v) {
    const Vec3& n = s[v];
    const double len = std::sqrt(dot(n, n));
    if (len > 0 && std::isfinite(len)) {
      const double inv = 1.0 / len;
      out[v] = {static_cast<float>(n[0] * inv), static_cast<float>(n[1] * inv),
                static_cast<float>(n[2] * inv)};
    }
  }
}

}  // namespace

OutputFrame parse_output_frame(std::string_view name) {
  if (name == "axis") return OutputFrame::kAxis;
  if (name == "lonlat") return OutputFrame::kLonLat;
  if (name == "metric") return OutputFrame::kLocalMetric;
  if (name == "ecef") return OutputFrame::kEcef;
  throw make_error(ErrorCode::kInvalidArgument,
                   "unknown output frame '{}': use axis, lonlat, metric or ecef", name);
}

std::string_view output_frame_name(OutputFrame frame) {
  switch (frame) {
    case OutputFrame::kAxis: return "axis";
    case OutputFrame::kLonLat: return "lonlat";
    case OutputFrame::kLocalMetric: return "metric";
    case OutputFrame::kEcef: return "ecef";
  }
  return "axis";
}

namespace {

// The placement by a version-5 store's vertical geometry.
VerticalPlacement geometry_placement(const format::Manifest& m) {
  using format::VerticalGeometry;
  const format::GridGeometry& g = *m.geometry;
  VerticalPlacement v;
  v.kind = VerticalPlacement::Kind::kGeometry;
  v.pressure = g.vertical.quantity == VerticalGeometry::Quantity::kPressure;
  // orientation = sign d(east, north, up) / d(i, j, k) = horizontal sign x sign dh/dk.
  // (A curvilinear grid's index axes count as east and north here; FrameTransform
  // corrects the sign by its coordinates.)
  const int vertical_per_k = g.orientation * geo::horizontal_orientation(m.x, m.y, m.grid_mapping);
  v.vertical_sign = m.z.descending() ? -vertical_per_k : vertical_per_k;
  const std::string what = v.pressure ? "pressure" : "height";
  const std::string how = g.vertical.formula == format::kGeometryFormulaVariable
                              ? fmt::format("variable {}", fmt::join(g.vertical.sources, " + "))
                              : g.vertical.formula;
  const std::string atmosphere = v.pressure ? ", heights by the ICAO standard atmosphere" : "";
  if (g.vertical.kind == VerticalGeometry::Kind::kField) {
    v.attribute = format::geometry_field_name(m);
    v.description = fmt::format("grid geometry: {} of every sample from {}{}", what, how, atmosphere);
  } else if (g.vertical.kind == VerticalGeometry::Kind::kLevels) {
    v.levels = g.vertical.levels;
    v.description = fmt::format("grid geometry: {} of every level from {}{}", what, how, atmosphere);
  } else {
    throw make_error(ErrorCode::kUnsupported, "the store's geometry places no vertical");
  }
  return v;
}

}  // namespace

VerticalPlacement choose_vertical_placement(const format::Manifest& m,
                                            std::optional<std::string> height_var) {
  if (m.geometry && m.geometry->vertical.kind != format::VerticalGeometry::Kind::kAxis) {
    if (height_var) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "--height-var {}: the store's grid geometry places every sample's height; "
                       "leave the option out",
                       *height_var);
    }
    return geometry_placement(m);
  }
  VerticalPlacement v;
  if (m.z.kind == AxisKind::kHeight) {
    const auto scale = m.z.units.empty() ? std::optional<double>(1.0) : metres_per_length_unit(m.z.units);
    if (!scale) {
      throw make_error(ErrorCode::kUnsupported, "height axis '{}' has units '{}'; need m or km",
                       m.z.name, m.z.units);
    }
    v.kind = VerticalPlacement::Kind::kHeightAxis;
    v.metres_per_unit = *scale;
    v.description = fmt::format("height axis '{}' ({})", m.z.name, m.z.units.empty() ? "m" : m.z.units);
    return v;
  }
  auto use_variable = [&](std::size_t i) {
    const format::StoreVariable& var = m.variables[i];
    const auto scale = height_variable_scale(var.units);
    if (!scale) {
      throw make_error(ErrorCode::kUnsupported,
                       "height variable '{}' has units '{}'; need a height (m, gpm, km, dam) or a "
                       "geopotential (m2 s-2)",
                       var.name, var.units);
    }
    v.kind = VerticalPlacement::Kind::kHeightVariable;
    v.variable = var.name;
    v.metres_per_unit = *scale;
    v.description = *scale == 1.0 / kStandardGravity
                        ? fmt::format("geopotential height from variable '{}' ({} / 9.80665)",
                                      var.name, var.units)
                        : fmt::format("height from variable '{}' ({})", var.name, var.units);
    return v;
  };
  if (height_var) return use_variable(m.variable_index(*height_var));
  static constexpr std::array<std::string_view, 7> kNames{
      "zg", "gh", "geopotential_height", "hgt", "z", "phi", "geopotential"};
  for (std::string_view name : kNames) {
    for (std::size_t i = 0; i < m.variables.size(); ++i) {
      const auto& var = m.variables[i];
      const std::string base = var.name.substr(var.name.rfind('/') + 1);
      if (lower(base) == name && height_variable_scale(var.units)) return use_variable(i);
    }
  }
  for (std::size_t i = 0; i < m.variables.size(); ++i) {
    const std::string sn = lower(m.variables[i].standard_name);
    if ((sn == "geopotential_height" || sn == "geopotential") &&
        height_variable_scale(m.variables[i].units)) {
      return use_variable(i);
    }
  }
  if (m.z.kind == AxisKind::kPressure) {
    const auto pa = pascals_per_pressure_unit(m.z.units);
    if (!pa) {
      throw make_error(ErrorCode::kUnsupported,
                       "pressure axis '{}' has units '{}'; need Pa, hPa, mbar, kPa, bar or atm",
                       m.z.name, m.z.units);
    }
    v.kind = VerticalPlacement::Kind::kStandardAtmosphere;
    v.metres_per_unit = *pa;  // pascals per unit here
    v.description = fmt::format("ICAO standard atmosphere of pressure axis '{}' ({}): no "
                                "geopotential variable in the store",
                                m.z.name, m.z.units);
    return v;
  }
  throw make_error(ErrorCode::kUnsupported,
                   "vertical axis '{}' ({}) has no height: the store has no height or "
                   "geopotential variable (zg, gh, z, phi ...) to place it by; convert one with "
                   "the data or name it with --height-var",
                   m.z.name, axis_kind_name(m.z.kind));
}

FrameTransform::FrameTransform(const format::Manifest& manifest, OutputFrame frame,
                               VerticalPlacement vertical,
                               std::shared_ptr<const format::HorizontalCoordinates> coordinates)
    : frame_(frame),
      vertical_(std::move(vertical)),
      manifest_(&manifest),
      projection_(mapped_axes(manifest) ? manifest.grid_mapping->proj : std::string()) {
  geographic_ = geographic_axes(manifest) || mapped_axes(manifest);
  if (frame_ == OutputFrame::kAxis) return;
  if (format::is_curvilinear(manifest)) {
    const format::HorizontalGeometry& h = manifest.geometry->horizontal;
    if (coordinates == nullptr || !coordinates->has_coordinates()) {
      throw make_error(ErrorCode::kUnsupported,
                       "output frame '{}' of a curvilinear store ({} / {}) needs the "
                       "coordinates of its GEOMETRY file",
                       output_frame_name(frame_), h.lon_variable, h.lat_variable);
    }
    curvilinear_.emplace(std::move(coordinates));
    geographic_ = true;
    const auto c = curvilinear_->centre();
    lon0_ = c[0];
    lat0_ = c[1];
    if (vertical_.kind == VerticalPlacement::Kind::kGeometry) {
      vertical_.vertical_sign *= curvilinear_->orientation();
    }
  }
  if (!geographic_) {
    const auto sx = metres_per_length_unit(manifest.x.units);
    const auto sy = metres_per_length_unit(manifest.y.units);
    const bool metres = sx && sy;
    if (frame_ != OutputFrame::kLocalMetric || !metres) {
      throw make_error(ErrorCode::kUnsupported,
                       "output frame '{}' needs the grid's place on the Earth, but axes '{}' and "
                       "'{}' ({}, {}) are {} without a grid_mapping",
                       output_frame_name(frame_), manifest.x.name, manifest.y.name,
                       manifest.x.units, manifest.y.units,
                       metres ? "Cartesian coordinates" : "not longitude and latitude");
    }
    cartesian_scale_ = {*sx, *sy};
    cartesian_centre_ = {midpoint(manifest.x), midpoint(manifest.y)};
  }
  if (curvilinear_) {
    // centred above
  } else if (geographic_axes(manifest)) {
    lon0_ = midpoint(manifest.x);
    lat0_ = midpoint(manifest.y);
  } else if (mapped_axes(manifest)) {
    const auto c = projection_.to_geographic(midpoint(manifest.x), midpoint(manifest.y));
    lon0_ = c[0];
    lat0_ = c[1];
    if (!std::isfinite(lon0_) || !std::isfinite(lat0_)) {
      throw make_error(ErrorCode::kUnsupported,
                       "grid mapping '{}' gives the domain's centre no geographic position",
                       manifest.grid_mapping->variable);
    }
    double spacing = std::fabs(manifest.x.values.back() - manifest.x.values.front());
    for (const Axis* a : {&manifest.x, &manifest.y}) {
      for (std::size_t i = 1; i < a->size(); ++i) {
        spacing = std::min(spacing, std::fabs(a->values[i] - a->values[i - 1]));
      }
    }
    jacobian_step_ = spacing * 1e-3;
  }
  if (vertical_.kind == VerticalPlacement::Kind::kHeightAxis ||
      vertical_.kind == VerticalPlacement::Kind::kStandardAtmosphere) {
    z_unit_ = vertical_.metres_per_unit;
  }
}

FrameTransform::FrameTransform(const Store& store, OutputFrame frame, VerticalPlacement vertical)
    : FrameTransform(store.manifest(), frame, std::move(vertical),
                     frame != OutputFrame::kAxis && format::is_curvilinear(store.manifest())
                         ? store.horizontal_coordinates()
                         : nullptr) {}

std::array<double, 3> FrameTransform::lon_lat_height(const std::array<double, 3>& p,
                                                     double height) const {
  double lon = p[0], lat = p[1];
  if (curvilinear_ || !projection_.identity()) {
    const auto& g = column(p[0], p[1]).lonlat;
    lon = g[0];
    lat = g[1];
  }
  return {lon, lat, height_m(p[2], height)};
}

double FrameTransform::height_m(double z, double height) const {
  switch (vertical_.kind) {
    case VerticalPlacement::Kind::kHeightAxis: return z * z_unit_;
    case VerticalPlacement::Kind::kStandardAtmosphere: return geo::standard_height_m(z * z_unit_);
    case VerticalPlacement::Kind::kHeightVariable: return height * vertical_.metres_per_unit;
    case VerticalPlacement::Kind::kGeometry: {
      const double value = vertical_.levels.empty() ? height : level_value(z);
      return vertical_.pressure ? geo::standard_height_m(value) : value;
    }
  }
  return 0;
}

// kGeometry per level: the level table at axis value z, linear between the levels.
double FrameTransform::level_value(double z) const {
  const std::vector<double>& a = manifest_->z.values;
  const std::vector<double>& l = vertical_.levels;
  if (a.size() == 1) return l.front();
  const bool ascending = !manifest_->z.descending();
  // First index whose axis value is beyond z, clamped to the last cell.
  const auto beyond = ascending ? std::upper_bound(a.begin(), a.end(), z)
                                : std::upper_bound(a.begin(), a.end(), z, std::greater<>());
  std::size_t k = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(beyond - a.begin(), 1,
                                                                      static_cast<std::ptrdiff_t>(a.size()) - 1));
  const double f = (z - a[k - 1]) / (a[k] - a[k - 1]);
  return (1 - f) * l[k - 1] + f * l[k];
}

// The attribute that places vertices vertically, or null when the placement uses none.
const std::vector<float>* FrameTransform::placing_heights(const Mesh& mesh) const {
  const std::vector<float>* heights = nullptr;
  const std::string& name = vertical_.kind == VerticalPlacement::Kind::kGeometry
                                ? vertical_.attribute
                                : vertical_.variable;
  if (placed_by_attribute()) {
    for (std::size_t a = 0; a < mesh.attribute_names.size(); ++a) {
      if (mesh.attribute_names[a] == name) heights = &mesh.attributes[a];
    }
    if (heights == nullptr && !mesh.positions.empty()) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "placing by '{}' needs the meshes to carry it as an attribute", name);
    }
  }
  return heights;
}

// Direct-mapped by the bits of (x, y): the vertices of a column share them.
FrameTransform::Column& FrameTransform::column(double x, double y) const {
  const auto bx = std::bit_cast<std::uint64_t>(x), by = std::bit_cast<std::uint64_t>(y);
  if (columns_.empty()) columns_.resize(std::size_t{1} << kColumnBits);
  const std::uint64_t hash = bx * 0x9E3779B97F4A7C15ull ^ (by * 0xC2B2AE3D27D4EB4Full + (by >> 29));
  Column& c = columns_[hash >> (64 - kColumnBits)];
  if (!c.used || c.x != bx || c.y != by) {
    c.used = true;
    c.x = bx;
    c.y = by;
    const auto g = curvilinear_ ? curvilinear_->at(x, y) : projection_.to_geographic(x, y);
    c.lonlat = {lon0_ + remainder_360(g[0] - lon0_), g[1]};
    c.has_jacobian = false;
    c.has_normal_terms = false;
    c.memo_used = 0;
    c.memo_next = 0;
  }
  return c;
}

const std::array<double, 4>& FrameTransform::column_jacobian(double x, double y) const {
  Column& c = column(x, y);
  if (!c.has_jacobian) {
    c.jacobian = curvilinear_ ? curvilinear_->jacobian(x, y) : projection_.jacobian(x, y, jacobian_step_);
    c.has_jacobian = true;
  }
  return c.jacobian;
}

std::array<double, 3> FrameTransform::cartesian_position(const std::array<double, 3>& q,
                                                         double hv) const {
  return {(q[0] - cartesian_centre_[0]) * cartesian_scale_[0],
          (q[1] - cartesian_centre_[1]) * cartesian_scale_[1], lon_lat_height(q, hv)[2]};
}

std::array<double, 3> FrameTransform::position(const std::array<double, 3>& q, double hv) const {
  if (!geographic_) return cartesian_position(q, hv);
  const std::array<double, 3> llh = lon_lat_height(q, hv);
  return frame_position(frame_, llh[0], llh[1], llh[2], lon0_, lat0_);
}

FrameTransform::MappedPoint FrameTransform::map_point(const std::array<double, 3>& q, double hv) const {
  // Axis to (lon, lat, h) or, on a Cartesian grid, to metres: position and Jacobian
  // columns (d/dx, d/dy, d/dz).
  std::array<double, 3> llh;
  Vec3 jx{1, 0, 0}, jy{0, 1, 0}, jz{0, 0, 0};
  if (geographic_) {
    llh = lon_lat_height(q, hv);
    if (curvilinear_ || !projection_.identity()) {
      const auto& j = column_jacobian(q[0], q[1]);
      jx = {j[0], j[2], 0};
      jy = {j[1], j[3], 0};
    }
  } else {  // Cartesian metres about the domain's centre
    llh = cartesian_position(q, hv);
    jx = {cartesian_scale_[0], 0, 0};
    jy = {0, cartesian_scale_[1], 0};
  }
  if (vertical_.kind == VerticalPlacement::Kind::kHeightAxis) {
    jz = {0, 0, z_unit_};
  } else if (vertical_.kind == VerticalPlacement::Kind::kStandardAtmosphere) {
    const double pa = q[2] * z_unit_, dp = std::max(pa * 1e-6, 1e-9);
    jz = {0, 0, (geo::standard_height_m(pa + dp) - geo::standard_height_m(pa - dp)) / (2 * dp) * z_unit_};
  } else if (vertical_.kind == VerticalPlacement::Kind::kHeightVariable &&
             manifest_->z.kind == AxisKind::kPressure) {
    // Heights from a field on pressure levels: only the direction is known (and used, for
    // the triangles' orientation): up where the pressure falls.
    jz = {0, 0, -1};
  } else if (vertical_.kind == VerticalPlacement::Kind::kGeometry) {
    // Only its direction is used: for the triangles' orientation (normals come from the
    // placed surface).
    jz = {0, 0, static_cast<double>(vertical_.vertical_sign)};
  }
  MappedPoint m;
  if (geographic_) {
    const FramePoint f = frame_point(frame_, llh[0], llh[1], llh[2], lon0_, lat0_);
    m.p = f.p;
    m.cx = combine(f.d_lon, f.d_lat, f.d_h, jx);
    m.cy = combine(f.d_lon, f.d_lat, f.d_h, jy);
    m.cz = combine(f.d_lon, f.d_lat, f.d_h, jz);
  } else {
    m.p = {llh[0], llh[1], llh[2]};
    m.cx = jx;
    m.cy = jy;
    m.cz = jz;
  }
  return m;
}

// height_m at vertices first.. of mesh, the placement's kind decided once.
void FrameTransform::place_heights(Mesh& mesh, const std::vector<float>* heights,
                                   std::size_t first) const {
  std::array<double, 3>* __restrict p = mesh.positions.data();
  const std::size_t n = mesh.positions.size();
  if (heights != nullptr && vertical_.kind == VerticalPlacement::Kind::kGeometry &&
      vertical_.levels.empty()) {
    const float* __restrict h = heights->data();
    if (vertical_.pressure) {
      for (std::size_t v = first; v < n; ++v) p[v][2] = geo::standard_height_m(static_cast<double>(h[v]));
    } else {
      for (std::size_t v = first; v < n; ++v) p[v][2] = static_cast<double>(h[v]);
    }
    return;
  }
  for (std::size_t v = first; v < n; ++v) {
    p[v][2] = height_m(p[v][2], heights != nullptr ? static_cast<double>((*heights)[v]) : 0.0);
  }
}

bool FrameTransform::column_normals() const {
  return (curvilinear_ || !projection_.identity()) &&
         (frame_ == OutputFrame::kLonLat || frame_ == OutputFrame::kLocalMetric) &&
         vertical_.kind == VerticalPlacement::Kind::kHeightAxis;
}

// In lonlat and metric the frame's Jacobian does not depend on the height, and on a
// height axis the vertical column of the map is constant: map_point's Jacobian columns
// are the same at every vertex of a column, and so are transform_normal's terms.
void FrameTransform::apply_by_columns(Mesh& mesh) const {
  const FramePoint f = frame_point(frame_, lon0_, lat0_, 0.0, lon0_, lat0_);
  const std::array<Vec3, 3> frame{f.d_lon, f.d_lat, f.d_h};
  const Vec3 cz = combine(frame[0], frame[1], frame[2], Vec3{0, 0, z_unit_});
  int orientation = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    auto& q = mesh.positions[v];
    Column& c = column(q[0], q[1]);
    if (!c.has_normal_terms) {
      // map_point's Jacobian columns, the frame's derivatives taken once.
      const auto& j = column_jacobian(q[0], q[1]);
      const Vec3 cx = combine(frame[0], frame[1], frame[2], Vec3{j[0], j[2], 0});
      const Vec3 cy = combine(frame[0], frame[1], frame[2], Vec3{j[1], j[3], 0});
      c.normal_terms = normal_terms(cx, cy, cz);
      c.det = dot(cx, cross(cy, cz));
      c.has_normal_terms = true;
    }
    if (orientation == 0 && c.det != 0 && std::isfinite(c.det)) orientation = c.det < 0 ? -1 : 1;
    if (v < mesh.normals.size()) {
      std::array<float, 3>& n = mesh.normals[v];
      const auto bits = std::bit_cast<std::array<std::uint32_t, 3>>(n);
      int hit = -1;
      for (int k = 0; k < c.memo_used; ++k) {
        if (std::bit_cast<std::array<std::uint32_t, 3>>(c.normal_memo[k][0]) == bits) hit = k;
      }
      if (hit >= 0) {
        n = c.normal_memo[hit][1];
      } else {
        auto& slot = c.normal_memo[c.memo_next];
        slot[0] = n;
        transform_normal(c.normal_terms, c.det, n);
        slot[1] = n;
        constexpr int kSlots = static_cast<int>(std::tuple_size_v<decltype(c.normal_memo)>);
        c.memo_next = static_cast<std::uint8_t>((c.memo_next + 1) % kSlots);
        c.memo_used = static_cast<std::uint8_t>(std::min(c.memo_used + 1, kSlots));
      }
    }
    q = frame_position(frame_, c.lonlat[0], c.lonlat[1], height_m(q[2], 0.0), lon0_, lat0_);
  }
  if (orientation < 0) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
}

void FrameTransform::apply(Mesh& mesh) const {
  if (frame_ == OutputFrame::kAxis) return;
  if (column_normals()) {
    apply_by_columns(mesh);
    return;
  }
  const std::vector<float>* heights = placing_heights(mesh);
  auto height_at = [&](std::size_t v) {
    return heights != nullptr ? static_cast<double>((*heights)[v]) : 0.0;
  };
  const bool surface = placed_surface() && !mesh.normals.empty();
  int orientation = 0;  // sign of the map's Jacobian determinant
  std::size_t v = 0;
  for (; v < mesh.positions.size(); ++v) {
    const MappedPoint m = map_point(mesh.positions[v], height_at(v));
    const double det = dot(m.cx, cross(m.cy, m.cz));
    if (orientation == 0 && det != 0 && std::isfinite(det)) orientation = det < 0 ? -1 : 1;
    if (v < mesh.normals.size() && !placed_surface()) {
      transform_normal(m.cx, m.cy, m.cz, det, mesh.normals[v]);
    }
    mesh.positions[v] = m.p;
    // Normals from the placed surface: once the orientation is known the Jacobian has
    // no further use, and the rest of the vertices need only their positions.
    if (orientation != 0 && placed_surface()) {
      ++v;
      break;
    }
  }
  if (frame_ == OutputFrame::kLonLat && geographic_axes(*manifest_)) {
    // Longitude and latitude stay as they are: only the height is new.
    place_heights(mesh, heights, v);
    v = mesh.positions.size();
  }
  for (; v < mesh.positions.size(); ++v) mesh.positions[v] = position(mesh.positions[v], height_at(v));
  // A negative orientation: the map reverses the triangles' winding (a pressure axis, say).
  if (surface) {
    // Heights from a field: the map's vertical derivatives are not known per vertex, so
    // the normals are the placed surface's own.
    placed_surface_normals(mesh, orientation < 0, normal_sums_);
  } else if (orientation < 0) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
}

bool FrameTransform::affine() const {
  if (frame_ == OutputFrame::kAxis) return true;
  if (frame_ == OutputFrame::kEcef) return false;
  return !curvilinear_ && projection_.identity() &&
         vertical_.kind == VerticalPlacement::Kind::kHeightAxis;
}

bool FrameTransform::placed_by_attribute() const {
  return vertical_.kind == VerticalPlacement::Kind::kHeightVariable ||
         (vertical_.kind == VerticalPlacement::Kind::kGeometry && vertical_.levels.empty());
}

bool FrameTransform::placed_surface() const {
  return vertical_.kind == VerticalPlacement::Kind::kHeightVariable ||
         vertical_.kind == VerticalPlacement::Kind::kGeometry;
}

void transform_mesh(Mesh& mesh, const format::Manifest& manifest, OutputFrame frame) {
  if (frame == OutputFrame::kAxis) return;
  FrameTransform(manifest, frame, choose_vertical_placement(manifest)).apply(mesh);
}

}  // namespace strielad
