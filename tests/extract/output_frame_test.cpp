// SPDX-License-Identifier: Apache-2.0
// Meshes moved from lon/lat/height axis coordinates into metric frames: WGS84 reference
// points, closed outward meshes stay closed and outward, unsupported axes are named.
#include <gtest/gtest.h>

#include <cmath>

#include "extract/mesh_metrics.h"
#include "extract/node_extractor.h"
#include "extract/output_frame.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

format::Manifest lon_lat_height(double lon0, double lon1, double lat0, double lat1, double h1,
                                std::size_t n) {
  format::Manifest m;
  auto fill = [n](Axis& a, std::string name, AxisKind kind, double lo, double hi) {
    a.name = std::move(name);
    a.kind = kind;
    for (std::size_t i = 0; i < n; ++i) a.values.push_back(lo + (hi - lo) * double(i) / double(n - 1));
  };
  fill(m.x, "lon", AxisKind::kLongitude, lon0, lon1);
  fill(m.y, "lat", AxisKind::kLatitude, lat0, lat1);
  fill(m.z, "height", AxisKind::kHeight, 0, h1);
  return m;
}

TEST(OutputFrameTest, EcefMatchesWgs84ReferencePoints) {
  const format::Manifest m = lon_lat_height(-1, 1, -1, 1, 1000, 3);
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {90, 0, 0}, {0, 90, 0}, {0, 0, 1000}};
  transform_mesh(mesh, m, OutputFrame::kEcef);
  EXPECT_NEAR(mesh.positions[0][0], 6378137.0, 1e-6);
  EXPECT_NEAR(mesh.positions[1][1], 6378137.0, 1e-6);
  EXPECT_NEAR(mesh.positions[1][0], 0.0, 1e-6);
  EXPECT_NEAR(mesh.positions[2][2], 6356752.314245, 1e-5);  // polar semi-axis b
  EXPECT_NEAR(mesh.positions[3][0], 6379137.0, 1e-6);
}

TEST(OutputFrameTest, ClosedMeshesStayClosedAndOutward) {
  // A blob 20 km across near 48N, 11E, 10 km high.
  const format::Manifest m = lon_lat_height(10.8, 11.2, 47.9, 48.1, 10000, 17);
  NodeSamples s;
  s.coords = {m.x.values, m.y.values, m.z.values};
  std::vector<float> f;
  for (double z : s.coords[2])
    for (double y : s.coords[1])
      for (double x : s.coords[0]) {
        const double dx = (x - 11.0) / 0.2, dy = (y - 48.0) / 0.1, dz = (z - 5000.0) / 5000.0;
        f.push_back(static_cast<float>(dx * dx + dy * dy + dz * dz));
      }
  s.fields.push_back(f);
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.6}};
  for (OutputFrame frame : {OutputFrame::kLocalMetric, OutputFrame::kEcef}) {
    Mesh mesh = extract_node_mesh(s, r);
    transform_mesh(mesh, m, frame);
    const MeshCheck c = check_mesh(mesh);
    EXPECT_TRUE(c.clean());
    // About an ellipsoid of semi-axes 0.775 * (14.9 km, 11.1 km, 5 km).
    const double v = enclosed_volume(mesh);
    const double expected = 4.0 / 3.0 * M_PI * std::pow(std::sqrt(0.6), 3) * 14.88e3 * 11.12e3 * 5e3;
    EXPECT_NEAR(v / expected, 1.0, 0.03) << static_cast<int>(frame);
    // Normals point away from the blob's centre.
    std::array<double, 3> centre{0, 0, 0};
    for (const auto& p : mesh.positions)
      for (int a = 0; a < 3; ++a) centre[a] += p[a] / double(mesh.positions.size());
    std::size_t outward = 0;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      double d = 0;
      for (int a = 0; a < 3; ++a) d += (mesh.positions[i][a] - centre[a]) * mesh.normals[i][a];
      outward += d > 0;
    }
    EXPECT_EQ(outward, mesh.positions.size());
  }
}

TEST(OutputFrameTest, PressureAxisHasNoMetricFrame) {
  format::Manifest m = lon_lat_height(0, 1, 0, 1, 1, 2);
  m.z.kind = AxisKind::kPressure;
  m.z.name = "plev";
  Mesh mesh;
  testing::expect_error([&] { transform_mesh(mesh, m, OutputFrame::kEcef); },
                        ErrorCode::kUnsupported, {"plev"});
  testing::expect_error([&] { parse_output_frame("utm"); }, ErrorCode::kInvalidArgument,
                        {"utm", "ecef"});
}

}  // namespace
}  // namespace strielad
