// SPDX-License-Identifier: Apache-2.0
#include "extract/output_frame.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "extract/vec3.h"

namespace strielad {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kMeanRadius = 6371008.8;
constexpr double kWgs84A = 6378137.0;
constexpr double kWgs84F = 1.0 / 298.257223563;
constexpr double kWgs84E2 = kWgs84F * (2.0 - kWgs84F);

// Position and Jacobian columns (d/dlon, d/dlat per degree, d/dh) of the map.
struct Mapped {
  Vec3 p, d_lon, d_lat, d_h;
};

Mapped map_point(OutputFrame frame, const Vec3& q, double lon0, double lat0) {
  const double lon = q[0], lat = q[1], h = q[2];
  Mapped m;
  if (frame == OutputFrame::kLocalMetric) {
    const double sx = kMeanRadius * std::cos(lat0 * kDeg) * kDeg, sy = kMeanRadius * kDeg;
    m.p = {sx * (lon - lon0), sy * (lat - lat0), h};
    m.d_lon = {sx, 0, 0};
    m.d_lat = {0, sy, 0};
    m.d_h = {0, 0, 1};
    return m;
  }
  const double sl = std::sin(lat * kDeg), cl = std::cos(lat * kDeg);
  const double so = std::sin(lon * kDeg), co = std::cos(lon * kDeg);
  const double w = std::sqrt(1.0 - kWgs84E2 * sl * sl);
  const double n = kWgs84A / w;
  // Meridional radius of curvature: dN/dlat folded in.
  const double m_radius = kWgs84A * (1.0 - kWgs84E2) / (w * w * w);
  m.p = {(n + h) * cl * co, (n + h) * cl * so, (n * (1.0 - kWgs84E2) + h) * sl};
  m.d_lon = {-(n + h) * cl * so * kDeg, (n + h) * cl * co * kDeg, 0};
  m.d_lat = {-(m_radius + h) * sl * co * kDeg, -(m_radius + h) * sl * so * kDeg,
             (m_radius + h) * cl * kDeg};
  m.d_h = {cl * co, cl * so, sl};
  return m;
}

}  // namespace

OutputFrame parse_output_frame(std::string_view name) {
  if (name == "axis") return OutputFrame::kAxis;
  if (name == "metric") return OutputFrame::kLocalMetric;
  if (name == "ecef") return OutputFrame::kEcef;
  throw make_error(ErrorCode::kInvalidArgument,
                   "unknown output frame '{}': use axis, metric or ecef", name);
}

void check_frame_supported(const format::Manifest& m, OutputFrame frame) {
  if (frame == OutputFrame::kAxis) return;
  if (m.x.kind != AxisKind::kLongitude) {
    throw make_error(ErrorCode::kUnsupported, "output frame needs a longitude x axis; '{}' is not",
                     m.x.name);
  }
  if (m.y.kind != AxisKind::kLatitude) {
    throw make_error(ErrorCode::kUnsupported, "output frame needs a latitude y axis; '{}' is not",
                     m.y.name);
  }
  if (m.z.kind != AxisKind::kHeight) {
    throw make_error(ErrorCode::kUnsupported,
                     "output frame needs a height axis in metres; '{}' is not (pressure and "
                     "model levels have no metric position)",
                     m.z.name);
  }
}

void transform_mesh(Mesh& mesh, const format::Manifest& manifest, OutputFrame frame) {
  if (frame == OutputFrame::kAxis) return;
  check_frame_supported(manifest, frame);
  const double lon0 = 0.5 * (manifest.x.values.front() + manifest.x.values.back());
  const double lat0 = 0.5 * (manifest.y.values.front() + manifest.y.values.back());
  bool flip = false;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Mapped m = map_point(frame, mesh.positions[v], lon0, lat0);
    // Gradient transform: n' = J^-T n = (n_lon (J_lat x J_h) + n_lat (J_h x J_lon) +
    // n_h (J_lon x J_lat)) / det J.
    const double det = dot(m.d_lon, cross(m.d_lat, m.d_h));
    flip = det < 0;
    if (v < mesh.normals.size()) {
      const auto& n = mesh.normals[v];
      const Vec3 a = cross(m.d_lat, m.d_h), b = cross(m.d_h, m.d_lon), c = cross(m.d_lon, m.d_lat);
      Vec3 g{};
      for (int i = 0; i < 3; ++i) g[i] = (n[0] * a[i] + n[1] * b[i] + n[2] * c[i]) / det;
      const double len = std::sqrt(dot(g, g));
      if (len > 0 && std::isfinite(len)) {
        mesh.normals[v] = {static_cast<float>(g[0] / len), static_cast<float>(g[1] / len),
                           static_cast<float>(g[2] / len)};
      }
    }
    mesh.positions[v] = m.p;
  }
  if (flip) {  // the map reverses orientation (never for these frames; kept general)
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
}

}  // namespace strielad
