// SPDX-License-Identifier: Apache-2.0
// write_vtp writes one VTK XML PolyData file (appended raw binary, zlib) that VTK's own
// reader reads back with the points, triangles, cell ids, normals and attributes given;
// it drops node-boundary faces on request, and reports unwritable paths by name.
#include "export/vtp_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "readback/vtp_reader.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

// The unit cube [0,1]^3 as 12 triangles, counter-clockwise from outside; the two faces
// x = 0 and x = 1 marked as node boundary.
Mesh cube(std::uint32_t subvolume, float offset) {
  Mesh m;
  m.subvolume_id = subvolume;
  for (int i = 0; i < 8; ++i) {
    const float x = float(i & 1), y = float((i >> 1) & 1), z = float((i >> 2) & 1);
    m.positions.push_back({x + offset + 0.1 * i / 3.0, y, z});  // not float-exact
    const float len = std::sqrt(3.0f);
    m.normals.push_back({(2 * x - 1) / len, (2 * y - 1) / len, (2 * z - 1) / len});
  }
  // Quads (a, b, c, d) counter-clockwise from outside; first two are the x faces.
  const std::array<std::array<std::uint32_t, 4>, 6> quads{{{0, 4, 6, 2},
                                                           {1, 3, 7, 5},
                                                           {0, 1, 5, 4},
                                                           {2, 6, 7, 3},
                                                           {0, 2, 3, 1},
                                                           {4, 5, 7, 6}}};
  for (std::size_t q = 0; q < quads.size(); ++q) {
    const auto& f = quads[q];
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
    const FaceKind kind = q < 2 ? FaceKind::kNodeBoundary : (q == 5 ? FaceKind::kDomainBox : FaceKind::kLimit);
    m.face_kinds.push_back(kind);
    m.face_kinds.push_back(kind);
  }
  return m;
}

std::vector<float> ramp(std::size_t n, float start) {
  std::vector<float> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = start + float(i);
  return v;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(VtpWriterTest, ReadsBackWithVtkWithIdsNormalsAndAttributes) {
  testing::TempDir dir;
  Mesh a = cube(1, 0.0f);
  a.attribute_names = {"ta"};
  a.attributes = {ramp(8, 100.0f)};
  Mesh b = cube(2, 5.0f);
  b.attribute_names = {"ua", "ta"};
  b.attributes = {ramp(8, -10.0f), ramp(8, 200.0f)};
  const std::vector<NodeMeshRef> meshes{{.node_id = 7, .mesh = &a}, {.node_id = 9, .mesh = &b}};
  const auto path = dir / "out.vtp";
  const VtpSummary summary = write_vtp(path, meshes);
  EXPECT_EQ(summary.points, 16u);
  EXPECT_EQ(summary.triangles, 24u);
  EXPECT_EQ(summary.dropped_triangles, 0u);
  EXPECT_EQ(summary.bytes, std::filesystem::file_size(path));
  // Only the file: no temporary left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()),
                          std::filesystem::directory_iterator()),
            1);

  const std::string text = read_text(path);
  EXPECT_NE(text.find("type=\"PolyData\""), std::string::npos);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);

  const VtpContents c = read_vtp(path);
  EXPECT_EQ(c.points_type, "double");
  ASSERT_EQ(c.points.size(), 16u);
  ASSERT_EQ(c.triangles.size(), 24u);
  EXPECT_EQ(c.other_cells, 0u);
  for (std::size_t v = 0; v < 8; ++v) {
    EXPECT_EQ(c.points[v], a.positions[v]);
    EXPECT_EQ(c.points[8 + v], b.positions[v]);
  }
  for (std::size_t t = 0; t < 12; ++t) {
    EXPECT_EQ(c.triangles[t], a.triangles[t]);
    const auto& tb = b.triangles[t];
    EXPECT_EQ(c.triangles[12 + t], (std::array<std::uint32_t, 3>{tb[0] + 8, tb[1] + 8, tb[2] + 8}));
  }
  const VtpArray* subvolume = c.cell_array("subvolume_id");
  const VtpArray* node = c.cell_array("node_id");
  const VtpArray* kind = c.cell_array("face_kind");
  ASSERT_TRUE(subvolume && node && kind);
  EXPECT_EQ(subvolume->type, "unsigned int");
  EXPECT_EQ(kind->type, "unsigned char");
  for (std::size_t t = 0; t < 24; ++t) {
    EXPECT_EQ(subvolume->values[t], t < 12 ? 1.0 : 2.0);
    EXPECT_EQ(node->values[t], t < 12 ? 7.0 : 9.0);
    EXPECT_EQ(kind->values[t], double(std::uint8_t((t < 12 ? a : b).face_kinds[t % 12])));
  }
  EXPECT_EQ(c.normals_name, "Normals");
  const VtpArray* normals = c.point_array("Normals");
  ASSERT_TRUE(normals);
  EXPECT_EQ(normals->components, 3);
  for (std::size_t v = 0; v < 8; ++v)
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(float(normals->values[3 * v + k]), a.normals[v][k]);
  const VtpArray* ta = c.point_array("ta");
  const VtpArray* ua = c.point_array("ua");
  ASSERT_TRUE(ta && ua);
  for (std::size_t v = 0; v < 8; ++v) {
    EXPECT_EQ(ta->values[v], 100.0 + double(v));
    EXPECT_EQ(ta->values[8 + v], 200.0 + double(v));
    EXPECT_TRUE(std::isnan(ua->values[v])) << "mesh a has no ua";
    EXPECT_EQ(ua->values[8 + v], -10.0 + double(v));
  }
}

TEST(VtpWriterTest, FieldDataStringsReadBackWholeEvenAcrossVtksReadBlocks) {
  // VTK reads string arrays 1024 characters at a time: a value longer than one block and
  // values that straddle a block boundary must come back whole.
  testing::TempDir dir;
  const Mesh m = cube(1, 0.0f);
  const std::vector<NodeMeshRef> meshes{{.node_id = 3, .mesh = &m}};
  VtpOptions options;
  const std::string long_text(2500, 'x');
  options.field_data = {{"frame", "lonlat"}, {"history", long_text + "end"}, {"empty", ""},
                        {"units", "m"}};
  const auto path = dir / "out.vtp";
  write_vtp(path, meshes, options);
  const VtpContents c = read_vtp(path);
  ASSERT_EQ(c.field_strings.size(), 4u);
  EXPECT_EQ(c.field_strings[0], (std::pair<std::string, std::string>{"frame", "lonlat"}));
  EXPECT_EQ(c.field_strings[1].second, long_text + "end");
  EXPECT_EQ(c.field_strings[2].second, "");
  EXPECT_EQ(c.field_strings[3].second, "m");
}

TEST(VtpWriterTest, DropNodeBoundaryFacesLeavesOutThoseTrianglesAndTheirOnlyVertices) {
  testing::TempDir dir;
  Mesh m = cube(3, 0.0f);
  // A ninth vertex used only by an extra node-boundary triangle.
  m.positions.push_back({0.0f, 0.5f, 0.5f});
  m.normals.push_back({-1.0f, 0.0f, 0.0f});
  m.triangles.push_back({0, 8, 2});
  m.face_kinds.push_back(FaceKind::kNodeBoundary);
  m.attribute_names = {"ta"};
  m.attributes = {ramp(9, 0.0f)};
  const std::vector<NodeMeshRef> meshes{{.node_id = 1, .mesh = &m}};
  const VtpSummary summary = write_vtp(dir / "seamless.vtp", meshes,
                                       {.drop_node_boundary_faces = true});
  EXPECT_EQ(summary.triangles, 8u);
  EXPECT_EQ(summary.dropped_triangles, 5u);
  EXPECT_EQ(summary.points, 8u);  // vertex 8 is gone; the cube's 8 stay (side faces)
  const VtpContents c = read_vtp(dir / "seamless.vtp");
  ASSERT_EQ(c.triangles.size(), 8u);
  ASSERT_EQ(c.points.size(), 8u);
  const VtpArray* kind = c.cell_array("face_kind");
  ASSERT_TRUE(kind);
  for (double k : kind->values) EXPECT_NE(k, double(std::uint8_t(FaceKind::kNodeBoundary)));
  // Vertex attributes follow their vertices through the renumbering.
  const VtpArray* ta = c.point_array("ta");
  ASSERT_TRUE(ta);
  for (std::size_t v = 0; v < c.points.size(); ++v) {
    bool found = false;
    for (std::size_t w = 0; w < m.positions.size(); ++w) {
      if (m.positions[w] == c.points[v]) {
        EXPECT_EQ(ta->values[v], m.attributes[0][w]);
        found = true;
      }
    }
    EXPECT_TRUE(found);
  }
  // Without the option everything is written.
  EXPECT_EQ(write_vtp(dir / "all.vtp", meshes).triangles, 13u);
}

TEST(VtpWriterTest, Float32PointsOnRequest) {
  testing::TempDir dir;
  const Mesh m = cube(1, 170.0f);
  const std::vector<NodeMeshRef> meshes{{.node_id = 1, .mesh = &m}};
  write_vtp(dir / "f32.vtp", meshes, {.float32_points = true});
  const VtpContents c = read_vtp(dir / "f32.vtp");
  EXPECT_EQ(c.points_type, "float");
  ASSERT_EQ(c.points.size(), 8u);
  for (std::size_t v = 0; v < 8; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(c.points[v][a], double(float(m.positions[v][a])));
}

TEST(VtpWriterTest, EmptyExportIsAValidFile) {
  testing::TempDir dir;
  const VtpSummary summary = write_vtp(dir / "empty.vtp", {});
  EXPECT_EQ(summary.triangles, 0u);
  const VtpContents c = read_vtp(dir / "empty.vtp");
  EXPECT_TRUE(c.points.empty());
  EXPECT_TRUE(c.triangles.empty());
}

TEST(VtpWriterTest, UnwritablePathIsAnErrorNamingTheFile) {
  testing::TempDir dir;
  const Mesh m = cube(1, 0.0f);
  const std::vector<NodeMeshRef> meshes{{.node_id = 1, .mesh = &m}};
  const auto path = dir / "no-such-dir" / "out.vtp";
  testing::expect_error([&] { write_vtp(path, meshes); }, ErrorCode::kNotFound,
                        {path.string() + ": writing VTK PolyData", "cannot create"});
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(VtpWriterTest, InconsistentMeshIsInvalidArgumentNamingFileAndNode) {
  testing::TempDir dir;
  Mesh m = cube(1, 0.0f);
  m.triangles.push_back({0, 1, 99});
  m.face_kinds.push_back(FaceKind::kLimit);
  const std::vector<NodeMeshRef> meshes{{.node_id = 42, .mesh = &m}};
  const auto path = dir / "bad.vtp";
  testing::expect_error([&] { write_vtp(path, meshes); }, ErrorCode::kInvalidArgument,
                        {path.string(), "node 42", "vertex 99"});
  Mesh n = cube(1, 0.0f);
  n.normals.pop_back();
  const std::vector<NodeMeshRef> meshes2{{.node_id = 5, .mesh = &n}};
  testing::expect_error([&] { write_vtp(path, meshes2); }, ErrorCode::kInvalidArgument,
                        {"node 5", "normals has 7 entries, expected 8"});
  const std::vector<NodeMeshRef> null_mesh{{.node_id = 6, .mesh = nullptr}};
  testing::expect_error([&] { write_vtp(path, null_mesh); }, ErrorCode::kInvalidArgument,
                        {"node 6: mesh is null"});
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(VtpReaderTest, MissingAndCorruptFilesAreErrorsNamingTheFile) {
  testing::TempDir dir;
  testing::expect_error([&] { read_vtp(dir / "missing.vtp"); }, ErrorCode::kNotFound,
                        {"missing.vtp"});
  {
    std::ofstream out(dir / "junk.vtp");
    out << "not xml at all";
  }
  testing::expect_error([&] { read_vtp(dir / "junk.vtp"); }, ErrorCode::kInvalidInput,
                        {"junk.vtp"});
}

}  // namespace
}  // namespace strielad
