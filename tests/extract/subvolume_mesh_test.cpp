// SPDX-License-Identifier: Apache-2.0
// extract_node_mesh: closed, outward-oriented meshes of sub-volumes with the right
// volume, on uniform, non-uniform and descending axes, with fill, extreme values and
// thresholds that hit sample values exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/error.h"
#include "extract/mesh_metrics.h"
#include "extract/node_extractor.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

std::vector<double> axis(std::size_t n, double lo, double hi, double stretch = 1.0) {
  std::vector<double> c(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n - 1);
    c[i] = lo + (hi - lo) * std::pow(t, stretch);
  }
  return c;
}

NodeSamples sampled(std::array<std::vector<double>, 3> coords,
                    const std::vector<std::function<double(double, double, double)>>& fields) {
  NodeSamples s;
  s.coords = std::move(coords);
  const auto d = s.dims();
  for (const auto& f : fields) {
    std::vector<float> values(s.sample_count());
    for (std::size_t z = 0; z < d[2]; ++z)
      for (std::size_t y = 0; y < d[1]; ++y)
        for (std::size_t x = 0; x < d[0]; ++x)
          values[(z * d[1] + y) * d[0] + x] =
              static_cast<float>(f(s.coords[0][x], s.coords[1][y], s.coords[2][z]));
    s.fields.push_back(std::move(values));
  }
  return s;
}

double radius(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); }

void expect_clean(const Mesh& mesh) {
  const MeshCheck c = check_mesh(mesh);
  EXPECT_EQ(c.open_edges, 0u);
  EXPECT_EQ(c.nonmanifold_edges, 0u);
  EXPECT_EQ(c.misoriented_edges, 0u);
  EXPECT_EQ(c.degenerate_triangles, 0u);
  EXPECT_EQ(c.bad_normals, 0u);
  EXPECT_EQ(c.bad_positions, 0u);
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
  EXPECT_EQ(mesh.face_kinds.size(), mesh.triangles.size());
}

// Appends node mesh m to joined, leaving out its faces on the node boundary (as a
// seamless export does): nodes that meet without cracks then join into a closed mesh.
void append_without_node_faces(Mesh& joined, const Mesh& m) {
  const auto offset = static_cast<std::uint32_t>(joined.positions.size());
  joined.positions.insert(joined.positions.end(), m.positions.begin(), m.positions.end());
  joined.normals.insert(joined.normals.end(), m.normals.begin(), m.normals.end());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (m.face_kinds[t] == FaceKind::kNodeBoundary) continue;
    joined.triangles.push_back(
        {m.triangles[t][0] + offset, m.triangles[t][1] + offset, m.triangles[t][2] + offset});
    joined.face_kinds.push_back(m.face_kinds[t]);
  }
}

TEST(SubvolumeMesh, SphereIsClosedWithTheRightVolume) {
  const NodeSamples s = sampled({axis(33, -1, 1), axis(33, -1, 1), axis(33, -1, 1)}, {radius});
  ExtractRequest r;
  r.subvolume_id = 7;
  r.limits = {{0, -kUnbounded, 0.7}};
  ExtractStats stats;
  const Mesh mesh = extract_node_mesh(s, r, &stats);
  expect_clean(mesh);
  EXPECT_EQ(mesh.subvolume_id, 7u);
  const double exact = 4.0 / 3.0 * std::numbers::pi * 0.7 * 0.7 * 0.7;
  EXPECT_NEAR(enclosed_volume(mesh) / exact, 1.0, 0.01);
  EXPECT_GT(stats.cut_cells, 0u);
  EXPECT_GT(stats.inside_cells, 0u);
  for (auto k : mesh.face_kinds) EXPECT_EQ(k, FaceKind::kLimit);
  // Normals point away from the centre.
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const auto& p = mesh.positions[v];
    const auto& n = mesh.normals[v];
    EXPECT_GT(p[0] * n[0] + p[1] * n[1] + p[2] * n[2], 0.0f);
  }
}

TEST(SubvolumeMesh, RegionCutByTheNodeBoundaryIsCappedThere) {
  // Half the sphere lies outside the node (x from 0 to 1).
  const NodeSamples s = sampled({axis(17, 0, 1), axis(33, -1, 1), axis(33, -1, 1)}, {radius});
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.7}};
  const Mesh mesh = extract_node_mesh(s, r);
  expect_clean(mesh);
  const double exact = 2.0 / 3.0 * std::numbers::pi * 0.343;
  EXPECT_NEAR(enclosed_volume(mesh) / exact, 1.0, 0.01);
  bool any_boundary = false;
  for (auto k : mesh.face_kinds) any_boundary = any_boundary || k == FaceKind::kNodeBoundary;
  EXPECT_TRUE(any_boundary);
}

TEST(SubvolumeMesh, ShellOfTwoLimitsOnStretchedDescendingAxes) {
  // x non-uniform (stretched), y descending, z strongly stretched.
  auto y = axis(29, -1, 1);
  std::reverse(y.begin(), y.end());
  const NodeSamples s = sampled({axis(31, -1, 1, 1.0), y, axis(41, -1, 1)}, {radius});
  ExtractRequest r;
  r.limits = {{0, 0.4, 0.8}};
  const Mesh mesh = extract_node_mesh(s, r);
  expect_clean(mesh);
  const double exact = 4.0 / 3.0 * std::numbers::pi * (0.512 - 0.064);
  EXPECT_NEAR(enclosed_volume(mesh) / exact, 1.0, 0.02);
}

TEST(SubvolumeMesh, DomainBoxAloneGivesTheBoxOnUnevenAxes) {
  // Spacing ratio 1:1000 along z.
  std::vector<double> z{0, 1, 2, 1002, 2002};
  const NodeSamples s =
      sampled({axis(9, 0, 8), axis(5, 10, 0), z}, {[](double, double, double) { return 1.0; }});
  ExtractRequest r;
  r.limits = {{0, 0.5, kUnbounded}};
  r.box = {{{1.5, 6.25}, {2.5, 7.5}, {0.5, 1500}}};
  const Mesh mesh = extract_node_mesh(s, r);
  expect_clean(mesh);
  EXPECT_NEAR(enclosed_volume(mesh), 4.75 * 5.0 * 1499.5, 1e-6 * 4.75 * 5 * 1499.5 * 10);
  bool any_box = false;
  for (auto k : mesh.face_kinds) any_box = any_box || k == FaceKind::kDomainBox;
  EXPECT_TRUE(any_box);
}

TEST(SubvolumeMesh, DomainRangeWithoutWidthGivesNothing) {
  const NodeSamples s = sampled({axis(5, 0, 4), axis(5, 0, 4), axis(3, 0, 2)},
                                {[](double, double, double) { return 2.0; }});
  ExtractRequest r;
  r.limits = {{0, 1.0, kUnbounded}};
  r.box = {{{1.5, 1.5}, {-kUnbounded, kUnbounded}, {-kUnbounded, kUnbounded}}};
  ExtractStats stats;
  EXPECT_TRUE(extract_node_mesh(s, r, &stats).empty());
  EXPECT_TRUE(stats.empty_by_condition);
}

TEST(SubvolumeMesh, ConstantInsideGivesTheNodeBoxAndOutsideGivesNothing) {
  const NodeSamples s = sampled({axis(5, 0, 4), axis(5, 0, 4), axis(3, 0, 2)},
                                {[](double, double, double) { return 2.0; }});
  ExtractRequest inside;
  inside.limits = {{0, 2.0, 2.0}};  // bounds equal to the value: inside (inclusive)
  const Mesh box = extract_node_mesh(s, inside);
  expect_clean(box);
  EXPECT_DOUBLE_EQ(enclosed_volume(box), 4.0 * 4.0 * 2.0);
  ExtractRequest outside;
  outside.limits = {{0, 2.5, kUnbounded}};
  ExtractStats stats;
  EXPECT_TRUE(extract_node_mesh(s, outside, &stats).empty());
  EXPECT_TRUE(stats.empty_by_condition);
}

std::size_t node_face_triangles(const Mesh& mesh) {
  std::size_t n = 0;
  for (auto k : mesh.face_kinds) n += k == FaceKind::kNodeBoundary || k == FaceKind::kGridBoundary ? 1 : 0;
  return n;
}

TEST(SubvolumeMesh, WhollyInsideNodeFacesBecomeRectanglesThroughTheirPerimeter) {
  // A node wholly inside on uneven axes: each side is one rectangle of w x h cells,
  // triangulated through its 2 (w + h) lattice points on the perimeter and none
  // inside: 2 (w + h) - 2 triangles instead of 2 w h.
  const NodeSamples s = sampled({axis(9, 0, 8, 1.7), axis(6, -1, 4), axis(4, 0, 3, 0.5)},
                                {[](double, double, double) { return 1.0; }});
  ExtractRequest r;
  r.limits = {{0, 0.5, kUnbounded}};
  const Mesh box = extract_node_mesh(s, r);
  expect_clean(box);
  EXPECT_NEAR(enclosed_volume(box), 8.0 * 5.0 * 3.0, 1e-9);
  const std::size_t w = 8, h = 5, d = 3;
  EXPECT_EQ(box.triangles.size(), 2 * ((2 * (w + h) - 2) + (2 * (h + d) - 2) + (2 * (w + d) - 2)));
  EXPECT_EQ(box.positions.size(), 8 * (w + h + d));  // each side's perimeter points (a group per side)
  // Points strictly inside a side are left out: every vertex lies on a node edge.
  for (const auto& p : box.positions) {
    int on_bounds = 0;
    on_bounds += p[0] == 0.0f || p[0] == 8.0f ? 1 : 0;
    on_bounds += p[1] == -1.0f || p[1] == 4.0f ? 1 : 0;
    on_bounds += p[2] == 0.0f || p[2] == 3.0f ? 1 : 0;
    EXPECT_GE(on_bounds, 2) << p[0] << " " << p[1] << " " << p[2];
  }

  // A half-filled node: the inside squares of each side become a few rectangles that
  // meet the cut cells' faces on unit lattice segments, so the mesh stays closed and
  // has far fewer node-face triangles than two per inside square.
  const NodeSamples half = sampled({axis(25, 0, 1), axis(25, 0, 1), axis(25, 0, 1, 1.4)},
                                   {[](double x, double y, double z) { return z - 0.3 * x - 0.2 * y; }});
  ExtractRequest below;
  below.limits = {{0, -kUnbounded, 0.4}};
  const Mesh m = extract_node_mesh(half, below);
  expect_clean(m);
  // z <= 0.4 + 0.3 x + 0.2 y over the unit square (below 1 everywhere); the field is
  // linear, so its trilinear interpolant and the mesh are exact.
  EXPECT_NEAR(enclosed_volume(m), 0.4 + 0.15 + 0.1, 1e-6);
  // Squares of the node's sides whose four corners are inside: two triangles each
  // before.
  const auto& f = half.fields[0];
  auto inside = [&](std::size_t x, std::size_t y, std::size_t z) {
    return f[(z * 25 + y) * 25 + x] <= 0.4f;
  };
  std::size_t squares = 0;
  for (std::size_t i = 0; i + 1 < 25; ++i) {
    for (std::size_t j = 0; j + 1 < 25; ++j) {
      for (std::size_t e : {std::size_t{0}, std::size_t{24}}) {
        squares += inside(e, i, j) && inside(e, i + 1, j) && inside(e, i, j + 1) && inside(e, i + 1, j + 1);
        squares += inside(i, e, j) && inside(i + 1, e, j) && inside(i, e, j + 1) && inside(i + 1, e, j + 1);
        squares += inside(i, j, e) && inside(i + 1, j, e) && inside(i, j + 1, e) && inside(i + 1, j + 1, e);
      }
    }
  }
  const std::size_t faces = node_face_triangles(m);
  EXPECT_LT(faces, squares) << squares << " inside squares";  // under half of two per square
}

TEST(SubvolumeMesh, ThresholdsExactlyOnSampleValuesGiveNoDegenerateTriangles) {
  // Integer-valued fields, thresholds at integers: crossings fall on samples.
  const NodeSamples s = sampled({axis(9, 0, 8), axis(9, 0, 8), axis(9, 0, 8)},
                                {[](double x, double y, double z) { return std::floor(x + y) + z; },
                                 [](double x, double, double z) { return x - z; }});
  for (double t : {3.0, 6.0, 10.0}) {
    ExtractRequest r;
    r.limits = {{0, t, kUnbounded}, {1, -2.0, 2.0}};
    const Mesh mesh = extract_node_mesh(s, r);
    SCOPED_TRACE(t);
    expect_clean(mesh);
    EXPECT_GT(enclosed_volume(mesh), 0.0);
  }
}

TEST(SubvolumeMesh, FillAndNonFiniteSamplesAreOutside) {
  NodeSamples s = sampled({axis(11, 0, 10), axis(11, 0, 10), axis(11, 0, 10)},
                          {[](double, double, double) { return 1.0; }});
  const float nan = std::nanf("");
  s.fields[0][(5 * 11 + 5) * 11 + 5] = nan;   // a hole in the middle
  s.fields[0][(2 * 11 + 7) * 11 + 3] = INFINITY;
  s.fields[0][0] = -INFINITY;
  ExtractRequest r;
  r.limits = {{0, 0.5, kUnbounded}};
  r.attribute_fields = {0};
  r.attribute_names = {"f"};
  const Mesh mesh = extract_node_mesh(s, r);
  expect_clean(mesh);
  const double v = enclosed_volume(mesh);
  EXPECT_LT(v, 1000.0);
  EXPECT_GT(v, 990.0);
}

// An attribute at a vertex depends only on the samples with weight there: a vertex on a
// valid sample, or on an edge between two, carries their value even where its cell has
// a missing corner (as slices and the grid's own samples do); only a vertex that a
// missing sample weighs on is NaN. (Beside land, ocean surfaces had turned grey.)
TEST(SubvolumeMesh, AttributesBesideMissingSamplesComeFromTheSamplesThatWeigh) {
  NodeSamples s = sampled({axis(9, 0, 8), axis(9, 0, 8), axis(3, 0, 2)},
                          {[](double x, double y, double z) { return 10.0 + x + 2 * y + 4 * z; }});
  const float nan = std::nanf("");
  for (std::size_t z = 0; z < 3; ++z) {
    for (std::size_t y = 3; y < 6; ++y) {
      for (std::size_t x = 3; x < 6; ++x) s.fields[0][(z * 9 + y) * 9 + x] = nan;  // "land"
    }
  }
  ExtractRequest r;
  r.limits = {{0, 0.0, kUnbounded}};
  r.attribute_fields = {0};
  r.attribute_names = {"f"};
  const Mesh mesh = extract_node_mesh(s, r);
  expect_clean(mesh);
  std::size_t on_samples = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const auto& p = mesh.positions[v];
    const double expected = 10.0 + p[0] + 2 * p[1] + 4 * p[2];
    const bool lattice_point = p[0] == std::round(p[0]) && p[1] == std::round(p[1]) &&
                               p[2] == std::round(p[2]);
    if (!lattice_point) continue;  // crossings of the validity surface lie in cells with "land"
    ++on_samples;
    EXPECT_FLOAT_EQ(mesh.attributes[0][v], float(expected))
        << "vertex at " << p[0] << ", " << p[1] << ", " << p[2];
  }
  EXPECT_GT(on_samples, 50u);
}

TEST(SubvolumeMesh, ExtremeMagnitudesAndDenormals) {
  for (double scale : {1.0, 1e-30, 1e-40, 1e30}) {
    const NodeSamples s = sampled({axis(17, -1, 1), axis(17, -1, 1), axis(17, -1, 1)},
                                  {[scale](double x, double y, double z) {
                                    return scale * (1.0 - radius(x, y, z));
                                  }});
    ExtractRequest r;
    r.limits = {{0, 0.3 * scale, kUnbounded}};
    const Mesh mesh = extract_node_mesh(s, r);
    SCOPED_TRACE(scale);
    expect_clean(mesh);
    const double exact = 4.0 / 3.0 * std::numbers::pi * 0.343;
    EXPECT_NEAR(enclosed_volume(mesh) / exact, 1.0, 0.05);
  }
}

TEST(SubvolumeMesh, OneCellThickNode) {
  const NodeSamples s = sampled({axis(2, 0, 1), axis(9, -1, 1), axis(9, -1, 1)},
                                {[](double, double y, double z) { return y * y + z * z; }});
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.5}};
  const Mesh mesh = extract_node_mesh(s, r);
  expect_clean(mesh);
  EXPECT_GT(enclosed_volume(mesh), 0.0);
}

TEST(SubvolumeMesh, NeighbouringNodesMeetWithoutCracks) {
  // One domain split at x = 0 into two nodes sharing the boundary samples; without
  // the node-boundary faces the two meshes together are closed.
  auto f = [](double x, double y, double z) { return radius(x - 0.05, y * 1.3, z) + 0.1 * x * y; };
  const auto y = axis(21, -1, 1), z = axis(21, -1, 1, 1.3);
  const NodeSamples left = sampled({axis(11, -1, 0), y, z}, {f});
  const NodeSamples right = sampled({axis(11, 0, 1), y, z}, {f});
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.75}};
  Mesh joined;
  for (const NodeSamples* s : {&left, &right}) {
    const Mesh m = extract_node_mesh(*s, r);
    expect_clean(m);
    append_without_node_faces(joined, m);
  }
  expect_clean(joined);
}

// Whether a point of the uniform lattice axis(n, -1, 1) is a lattice sample.
bool on_sample(double c, std::size_t n) {
  const double i = (c + 1) / 2 * static_cast<double>(n - 1);
  return std::fabs(i - std::round(i)) < 1e-9;
}

TEST(SubvolumeMesh, OneConditionCellsMeetOnCellEdgesInsideTheNode) {
  // Inside the node a surface crossed by one condition runs straight across cell sides
  // from one cell-edge crossing to the next (as marching cubes and the paper's clip
  // do): no vertex lies inside a cell side, so no vertex has two coordinates off the
  // lattice, and the surface has about two triangles per cut cell.
  const NodeSamples s = sampled({axis(33, -1, 1), axis(33, -1, 1), axis(33, -1, 1)}, {radius});
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.7}};
  ExtractStats stats;
  const Mesh mesh = extract_node_mesh(s, r, &stats);
  expect_clean(mesh);
  EXPECT_EQ(stats.table_cells, stats.cut_cells);
  EXPECT_EQ(stats.simple_tets + stats.clipped_tets, 0u);
  for (const auto& p : mesh.positions) {
    int off = 0;
    for (int a = 0; a < 3; ++a) off += on_sample(p[a], 33) ? 0 : 1;
    EXPECT_LE(off, 1) << p[0] << " " << p[1] << " " << p[2];
  }
  EXPECT_LE(mesh.triangles.size(), 2 * stats.cut_cells + stats.cut_cells / 4);
}

TEST(SubvolumeMesh, CellsBesideSeveralConditionsMeetTheirTetrahedra) {
  // Two limits whose surfaces cross in many cells, split into two nodes: the cells
  // crossed by both are cut into tetrahedra, their neighbours crossed by one condition
  // meet them along the shared sides' diagonals, and the node boundary is split the
  // same way on both sides whatever crosses the cells there.
  auto sphere = [](double x, double y, double z) { return radius(x - 0.05, y * 1.2, z); };
  auto slab = [](double x, double y, double z) { return z - 0.35 * x + 0.2 * y; };
  const auto y = axis(21, -1, 1), z = axis(21, -1, 1, 1.3);
  const NodeSamples left = sampled({axis(11, -1, 0), y, z}, {sphere, slab});
  const NodeSamples right = sampled({axis(11, 0, 1), y, z}, {sphere, slab});
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.8}, {1, 0.05, kUnbounded}};
  Mesh joined;
  for (const NodeSamples* s : {&left, &right}) {
    ExtractStats stats;
    const Mesh m = extract_node_mesh(*s, r, &stats);
    expect_clean(m);
    EXPECT_GT(stats.table_cells, 0u);
    EXPECT_GT(stats.simple_tets + stats.clipped_tets, 0u);
    append_without_node_faces(joined, m);
  }
  expect_clean(joined);
}

TEST(SubvolumeMesh, OutputIsDeterministic) {
  const NodeSamples s = sampled({axis(17, -1, 1), axis(17, -1, 1), axis(17, -1, 1)},
                                {radius, [](double x, double, double) { return x; }});
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.8}, {1, -0.2, kUnbounded}};
  r.attribute_fields = {1};
  r.attribute_names = {"x"};
  const Mesh a = extract_node_mesh(s, r), b = extract_node_mesh(s, r);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.attributes, b.attributes);
  expect_clean(a);
  // The attribute carries x at each vertex.
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    EXPECT_NEAR(a.attributes[0][v], a.positions[v][0], 1e-5);
  }
}

TEST(SubvolumeMesh, BadRequestsAreRejectedByName) {
  const NodeSamples s = sampled({axis(3, 0, 1), axis(3, 0, 1), axis(3, 0, 1)}, {radius});
  ExtractRequest r;
  r.limits = {{3, 0, 1}};
  testing::expect_error([&] { extract_node_mesh(s, r); }, ErrorCode::kInvalidArgument,
                        {"field 3"});
  r.limits = {{0, 2, 1}};
  testing::expect_error([&] { extract_node_mesh(s, r); }, ErrorCode::kInvalidArgument,
                        {"bad range"});
}

}  // namespace
}  // namespace strielad
