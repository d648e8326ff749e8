// SPDX-License-Identifier: Apache-2.0
// Sub-volumes of a terrain-following store (the ICON-like sample, converted), extracted
// over every node of level 0 and placed in the metric and ecef frames by the store's grid
// geometry, against an independent reference: VTK clipping a vtkStructuredGrid whose points
// are the samples' true positions, built from the input file alone (its lon and lat, the
// half levels z_ifc, temp) and the frame's formula, and integrating the clipped cells'
// volume and their surface's area (peers/vtk_structured_clip.h). The extraction must be
// closed where welded by position (no cracks between nodes), outward, and enclose VTK's
// volume and area; placed by flat levels it must miss them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "convert/converter.h"
#include "core/vec3.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "extract/output_frame.h"
#include "format/geometry_field.h"
#include "peers/vtk_structured_clip.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "synthetic/model_like_files.h"

namespace strielad {
namespace {

constexpr Dims3 kDims{24, 20, 12};

// Tolerances, relative, from measurements on this sample (24 x 20 x 12 samples, cells of
// about 30 km x 41 km x 0.1 to 2 km; 3 x 3 x 2 nodes of 8^3 samples). Metric frame: the
// extraction's volume is within 3.5e-5 of VTK's for the cold region aloft, 2.4e-3 for warm
// air down to the terrain, 1.6e-3 for the same cut by a longitude range; areas within
// 3.0e-4. Both are linear readings of the same samples at the same places, with vertices at
// the same fractions of the same edges, but the kernel splits a cell into tetrahedra its
// own way and VTK cuts the hexahedron by its case tables and integrates it over its own
// tetrahedra. Cells over the terrain are twisted (the corners of a side at different
// heights), so the readings differ by the twist: VTK alone, the volume of its clipped cells
// and that enclosed by their outer surface differ by up to 1.7e-3; with the levels flat (no
// twist) kernel and VTK agree to 1.1e-3.
constexpr double kVolumeTolerance = 4e-3;
constexpr double kAreaTolerance = 1e-3;
// Ecef frame: the extraction places a vertex on a lattice edge at the true position of its
// interpolated longitude, latitude and height, on the Earth's curve; VTK interpolates the
// placed end points, on the chord. A horizontal edge of 30 to 41 km bows 18 to 33 m off its
// chord, and where the warm layer's top (about 1 km above the ground) crosses the sloping
// levels its vertices lie on such edges: the volumes differ by 3.1e-4, 3.4e-3 and 7.9e-3.
// Against VTK's metric-frame surface with its vertices moved into the ecef frame (on the
// curve, as the extraction places them) they are back within 5.9e-5, 2.8e-3 and 7.7e-4.
constexpr double kEcefChordTolerance = 1e-2;
// Levels placed flat at their mean heights instead of the geometry's (what the level axis
// alone would give) move the warm regions' volume by 2.4e-2 to 2.9e-2 (the extraction so
// placed: 2.8e-2 and 2.4e-2; VTK's flat lattice: 2.9e-2 and 2.5e-2), and the cold region's
// by 1.0e-3 only: it does not reach down to the terrain.
constexpr double kFlatMiss = 5 * kVolumeTolerance;

// WGS84, as the ecef frame (formats/scene.md); the metric frame's mean Earth radius.
constexpr double kWgs84A = 6378137.0, kWgs84F = 1 / 298.257223563;
constexpr double kMeanRadius = 6371008.8;
constexpr double kDeg = std::numbers::pi / 180;

struct Region {
  std::uint32_t id = 0;
  std::optional<double> t_min = std::nullopt, t_max = std::nullopt;  // K
  std::optional<std::array<double, 2>> lon = std::nullopt;           // a domain range, degrees
  bool near_ground = false;  // a flat placement of the levels must miss it
};

const std::vector<Region>& regions() {
  static const std::vector<Region> r{
      {.id = 1, .t_max = 265.0},                       // cold air aloft, up to the model top
      {.id = 2, .t_min = 278.0, .near_ground = true},  // warm air, down to the terrain
      {.id = 3, .t_min = 278.0, .lon = std::array<double, 2>{8.0, 11.0}, .near_ground = true},
  };
  return r;
}

// The frame's formula at (lon, lat, h) (formats/scene.md, "Output frames"), written out
// here rather than taken from the extraction: metric is the plane tangent at (lon0, lat0)
// (equirectangular in the mean Earth radius), ecef geocentric WGS84.
std::array<double, 3> frame_position(OutputFrame frame, double lon, double lat, double h,
                                     double lon0, double lat0) {
  if (frame == OutputFrame::kLocalMetric) {
    return {kMeanRadius * std::cos(lat0 * kDeg) * kDeg * (lon - lon0),
            kMeanRadius * kDeg * (lat - lat0), h};
  }
  const double e2 = kWgs84F * (2 - kWgs84F), sl = std::sin(lat * kDeg), cl = std::cos(lat * kDeg);
  const double n = kWgs84A / std::sqrt(1 - e2 * sl * sl);
  return {(n + h) * cl * std::cos(lon * kDeg), (n + h) * cl * std::sin(lon * kDeg),
          (n * (1 - e2) + h) * sl};
}

// The input, read with netCDF directly.
struct Input {
  std::vector<double> lon, lat, z_ifc, temp;
  std::size_t nx = 0, ny = 0, nz = 0;
  explicit Input(const std::filesystem::path& file)
      : lon(testing::read_netcdf_variable(file, "lon").values),
        lat(testing::read_netcdf_variable(file, "lat").values),
        z_ifc(testing::read_netcdf_variable(file, "z_ifc").values),
        temp(testing::read_netcdf_variable(file, "temp").values),
        nx(lon.size()),
        ny(lat.size()),
        nz(temp.size() / (nx * ny)) {}
  std::size_t plane() const { return nx * ny; }
  // Full level k's height in column c: the mean of the half levels around it (level 0 the
  // top, as ICON counts).
  double height(std::size_t k, std::size_t c) const {
    return 0.5 * (z_ifc[k * plane() + c] + z_ifc[(k + 1) * plane() + c]);
  }
  double level_mean(std::size_t k) const {
    double sum = 0;
    for (std::size_t c = 0; c < plane(); ++c) sum += height(k, c);
    return sum / double(plane());
  }
};

// The lattice in the order VTK wants it (east, north, up), every point at its true place in
// `frame`: the centre (lon0, lat0) of the axes' extent as the metric frame takes it, the
// height of its own column; fields temp and lon. `flat`: every level at its mean height.
peers::StructuredPoints reference_lattice(const Input& in, OutputFrame frame, bool flat) {
  const double lon0 = 0.5 * (in.lon.front() + in.lon.back());
  const double lat0 = 0.5 * (in.lat.front() + in.lat.back());
  const bool south_first = in.lat.front() < in.lat.back(),
             west_first = in.lon.front() < in.lon.back();
  peers::StructuredPoints g;
  g.dims = {in.nx, in.ny, in.nz};
  g.fields.resize(2);
  for (std::size_t up = 0; up < in.nz; ++up) {
    const std::size_t k = in.nz - 1 - up;
    const double mean = in.level_mean(k);
    for (std::size_t north = 0; north < in.ny; ++north) {
      const std::size_t j = south_first ? north : in.ny - 1 - north;
      for (std::size_t east = 0; east < in.nx; ++east) {
        const std::size_t i = west_first ? east : in.nx - 1 - east, c = j * in.nx + i;
        g.positions.push_back(
            frame_position(frame, in.lon[i], in.lat[j], flat ? mean : in.height(k, c), lon0, lat0));
        g.fields[0].push_back(in.temp[k * in.plane() + c]);
        g.fields[1].push_back(in.lon[i]);
      }
    }
  }
  return g;
}

peers::StructuredClipMeasures reference(const Input& in, OutputFrame frame, const Region& region,
                                        bool flat = false) {
  std::vector<peers::ScalarLimit> limits{{.field = 0, .min = region.t_min, .max = region.t_max}};
  if (region.lon) limits.push_back({.field = 1, .min = (*region.lon)[0], .max = (*region.lon)[1]});
  return peers::clip_structured_grid(reference_lattice(in, frame, flat), limits);
}

class TerrainFollowingVtkReferenceTest : public ::testing::Test {
 protected:
  // One ICON-like sample and its store for every test: 3 x 3 x 2 nodes at level 0, the
  // regions extracted once in axis coordinates with the geometry's heights attached.
  static void SetUpTestSuite() {
    dir_ = std::make_unique<testing::TempDir>();
    synthetic::SampleSpec spec;
    spec.dims = kDims;
    spec.steps = 1;
    spec.file_per_step = false;
    const auto file =
        synthetic::write_model_like_dataset(spec, synthetic::SampleModel::kIcon, *dir_ / "in")
            .files.front()
            .path;
    build::ConvertOptions convert;
    convert.inputs = {file};
    convert.store = *dir_ / "store";
    convert.brick = 8;
    convert.threads = 1;
    build::convert(convert);
    store_ = Store::open(*dir_ / "store");
    input_ = std::make_unique<Input>(file);
    const format::Manifest& m = store_->manifest();
    Scene scene;
    for (const Region& region : regions()) {
      SubVolume sv;
      sv.id = region.id;
      sv.limits.push_back(Limit{"temp", region.t_min, region.t_max});
      if (region.lon) sv.domain[m.x.name] = AxisRange{(*region.lon)[0], (*region.lon)[1]};
      scene.subvolumes.push_back(sv);
    }
    scene.attributes.push_back(format::geometry_field_name(m));
    LevelExtractionOptions o;
    o.merge_face_squares = false;  // the geometry bends the lattice's faces
    o.threads = 1;
    level_ = std::make_unique<LevelExtraction>(
        extract_level(*store_, resolve_scene(scene, m, "scene"), o));
  }
  static void TearDownTestSuite() {
    level_.reset();
    input_.reset();
    store_.reset();
    dir_.reset();
  }

  // Region `id` at level 0, every node's mesh moved into the frame by `transform`, joined
  // without the faces the nodes share.
  static Mesh placed(const FrameTransform& transform, std::uint32_t id) {
    LevelExtraction level = *level_;
    for (NodeExtraction& n : level.nodes) {
      for (SubVolumeResult& r : n.results) {
        if (r.outcome == NodeOutcome::kMesh) transform.apply(r.mesh);
      }
    }
    return seamless_union(level, id);
  }

  // Checks every region placed in `frame` by the store's geometry against VTK's.
  static void expect_matches_reference(OutputFrame frame);

  static inline std::unique_ptr<testing::TempDir> dir_;
  static inline std::shared_ptr<const Store> store_;
  static inline std::unique_ptr<Input> input_;
  static inline std::unique_ptr<LevelExtraction> level_;
};

// Vertices whose normal leans away from the area-weighted normal of their triangles (the
// outward side of a counter-clockwise surface).
std::size_t inward_normals(const Mesh& mesh) {
  std::vector<Vec3> sum(mesh.positions.size(), Vec3{0, 0, 0});
  for (const auto& t : mesh.triangles) {
    const Vec3 n = area_normal(mesh, t);
    for (auto v : t) sum[v] = add(sum[v], n);
  }
  std::size_t inward = 0;
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const auto& n = mesh.normals[v];
    inward += sum[v][0] * n[0] + sum[v][1] * n[1] + sum[v][2] * n[2] < 0;
  }
  return inward;
}

// VTK's region cut from the metric lattice (a linear image of the lon/lat/height lattice,
// so its vertices sit at the same fractions of the same edges), every vertex moved to
// `frame` by the frame's formula: the vertices where the extraction places them, on the
// curved image of each lattice edge rather than on its chord.
Mesh mapped_reference_surface(const Input& in, OutputFrame frame, const Region& region) {
  Mesh s = reference(in, OutputFrame::kLocalMetric, region).surface;
  const double lon0 = 0.5 * (in.lon.front() + in.lon.back());
  const double lat0 = 0.5 * (in.lat.front() + in.lat.back());
  for (auto& p : s.positions) {
    const double lat = lat0 + p[1] / (kMeanRadius * kDeg);
    const double lon = lon0 + p[0] / (kMeanRadius * std::cos(lat0 * kDeg) * kDeg);
    p = frame_position(frame, lon, lat, p[2], lon0, lat0);
  }
  return s;
}

void TerrainFollowingVtkReferenceTest::expect_matches_reference(OutputFrame frame) {
  // reference_lattice reads the levels top down, as ICON counts them.
  ASSERT_GT(input_->level_mean(0), input_->level_mean(input_->nz - 1));
  const format::Manifest& m = store_->manifest();
  const FrameTransform transform(m, frame, choose_vertical_placement(m));
  for (const Region& region : regions()) {
    SCOPED_TRACE(fmt::format("{} frame, sub-volume {}", output_frame_name(frame), region.id));
    const Mesh mesh = placed(transform, region.id);
    ASSERT_FALSE(mesh.triangles.empty());
    // Closed where vertices are welded by exact position: nodes meet without cracks.
    const MeshCheck c = check_mesh(mesh);
    EXPECT_TRUE(c.clean()) << c.open_edges << " open, " << c.nonmanifold_edges << " non-manifold, "
                           << c.misoriented_edges << " misoriented edges, "
                           << c.degenerate_triangles << " degenerate triangles";
    const double volume = enclosed_volume(mesh), area = surface_area(mesh);
    EXPECT_GT(volume, 0) << "triangles counter-clockwise from outside";
    EXPECT_EQ(inward_normals(mesh), 0u);

    const peers::StructuredClipMeasures ref = reference(*input_, frame, region);
    // VTK's region is closed too: its area is whole.
    EXPECT_EQ(ref.boundary_edges, 0u);
    EXPECT_EQ(ref.non_manifold_edges, 0u);
    const double tolerance = frame == OutputFrame::kEcef ? kEcefChordTolerance : kVolumeTolerance;
    EXPECT_NEAR(volume / ref.volume, 1.0, tolerance) << volume << " m3, VTK " << ref.volume;
    EXPECT_NEAR(area / ref.surface_area, 1.0, kAreaTolerance)
        << area << " m2, VTK " << ref.surface_area;
    if (frame == OutputFrame::kLocalMetric) continue;
    const double mapped = enclosed_volume(mapped_reference_surface(*input_, frame, region));
    EXPECT_NEAR(volume / mapped, 1.0, kVolumeTolerance) << volume << " m3, VTK mapped " << mapped;
  }
}

TEST_F(TerrainFollowingVtkReferenceTest, MetricFramePlacementMatchesVtk) {
  expect_matches_reference(OutputFrame::kLocalMetric);
}

TEST_F(TerrainFollowingVtkReferenceTest, EcefPlacementMatchesVtk) {
  expect_matches_reference(OutputFrame::kEcef);
}

// The test tells a wrong placement: the same meshes placed by a table of the levels' mean
// heights (flat levels, as a placement by the level axis alone would put them), and VTK's
// flat lattice, both miss the terrain-following reference of the regions that reach down to
// the terrain by more than five times the tolerance.
TEST_F(TerrainFollowingVtkReferenceTest, FlatLevelsMissTheReference) {
  format::Manifest flat = store_->manifest();
  ASSERT_TRUE(flat.geometry);
  flat.geometry->vertical.kind = format::VerticalGeometry::Kind::kLevels;
  for (std::size_t k = 0; k < input_->nz; ++k) {
    flat.geometry->vertical.levels.push_back(input_->level_mean(k));
  }
  const FrameTransform transform(flat, OutputFrame::kLocalMetric, choose_vertical_placement(flat));
  for (const Region& region : regions()) {
    if (!region.near_ground) continue;
    SCOPED_TRACE(fmt::format("sub-volume {}", region.id));
    const double truth = reference(*input_, OutputFrame::kLocalMetric, region).volume;
    const double mesh = enclosed_volume(placed(transform, region.id));
    const double vtk_flat = reference(*input_, OutputFrame::kLocalMetric, region, true).volume;
    EXPECT_GT(std::fabs(mesh / truth - 1), kFlatMiss) << mesh << " m3, reference " << truth;
    EXPECT_GT(std::fabs(vtk_flat / truth - 1), kFlatMiss) << vtk_flat << " m3, reference " << truth;
    // The flat placement agrees with VTK's flat lattice: what moved is the placement.
    EXPECT_NEAR(mesh / vtk_flat, 1.0, kVolumeTolerance);
  }
}

}  // namespace
}  // namespace strielad
