// SPDX-License-Identifier: Apache-2.0
// Model output on terrain-following levels converted end to end: the ICON-like sample
// (z_ifc half levels over the sample terrain) becomes a version-5 store whose geometry
// field holds, at every level-0 sample, the mean of the two half levels around it as the
// file has them (read here with netCDF directly); the hybrid sigma-pressure sample keeps
// a pressure per sample and step; extracted meshes placed by the geometry sit at those
// heights, and a height band cut from the field is exact.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "convert/converter.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "extract/output_frame.h"
#include "format/geometry_field.h"
#include "scene/scene.h"
#include "store/brick_cache.h"
#include "store/level_samples.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/model_levels_fixture.h"
#include "support/temp_dir.h"
#include "synthetic/model_like_files.h"

namespace strielad {
namespace {

constexpr Dims3 kDims{24, 20, 12};

synthetic::SampleSpec spec(std::size_t steps) {
  synthetic::SampleSpec s;
  s.dims = kDims;
  s.steps = steps;
  s.file_per_step = false;
  return s;
}

std::filesystem::path write_model(const std::filesystem::path& dir, synthetic::SampleModel model,
                                  std::size_t steps) {
  const auto result = synthetic::write_model_like_dataset(spec(steps), model, dir / "in");
  return result.files.front().path;
}

build::ConvertOptions options(const std::filesystem::path& input,
                              const std::filesystem::path& store) {
  build::ConvertOptions o;
  o.inputs = {input};
  o.store = store;
  o.brick = 8;
  o.threads = 1;
  return o;
}

TEST(TerrainFollowingConversionTest, IconHalfLevelsBecomeTheStoresHeightField) {
  const testing::TempDir dir;
  const auto input = write_model(dir.path(), synthetic::SampleModel::kIcon, 2);
  build::convert(options(input, dir / "store"));
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  EXPECT_EQ(m.format_version, 5u);
  ASSERT_TRUE(m.geometry);
  EXPECT_EQ(m.geometry->vertical.kind, format::VerticalGeometry::Kind::kField);
  EXPECT_EQ(m.geometry->vertical.sources, std::vector<std::string>{"z_ifc"});
  EXPECT_FALSE(m.geometry->vertical.varies_in_time);
  EXPECT_EQ(m.geometry->orientation, -1);  // ICON counts levels from the top
  ASSERT_TRUE(m.geometry->surface);
  EXPECT_EQ(m.geometry->surface->variable, "topography_c");
  EXPECT_TRUE(std::filesystem::exists(dir / "store" / "geometry.bricks"));

  // Every level-0 sample: the mean of the half levels above and below it, as float32.
  const std::vector<double> z_ifc = testing::read_netcdf_variable(input, "z_ifc").values;
  const std::size_t plane = kDims.x * kDims.y;
  ASSERT_EQ(z_ifc.size(), (kDims.z + 1) * plane);
  const auto v = *format::geometry_field_variable(m);
  for (std::uint32_t step = 0; step < 2; ++step) {
    const auto heights = read_level_samples<float>(*store, step, v, 0);
    ASSERT_EQ(heights.values.size(), kDims.z * plane);
    for (std::size_t k = 0; k < kDims.z; ++k) {
      for (std::size_t s = 0; s < plane; ++s) {
        const double want = 0.5 * (z_ifc[k * plane + s] + z_ifc[(k + 1) * plane + s]);
        ASSERT_EQ(heights.values[k * plane + s], static_cast<float>(want)) << k << " " << s;
      }
    }
  }
  // The surface, from topography_c, exactly.
  const auto coordinates = store->horizontal_coordinates();
  ASSERT_TRUE(coordinates && coordinates->surface_m);
  EXPECT_EQ(*coordinates->surface_m, testing::read_netcdf_variable(input, "topography_c").values);
}

TEST(TerrainFollowingConversionTest, APlacedHeightBandIsExact) {
  const testing::TempDir dir;
  const auto input = write_model(dir.path(), synthetic::SampleModel::kIcon, 1);
  build::convert(options(input, dir / "store"));
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  // Everything up to 3000 m above sea level: a limit on the geometry's own field.
  Scene scene;
  SubVolume below;
  below.id = 1;
  below.limits.push_back(Limit{format::geometry_field_name(m), std::nullopt, 3000.0});
  scene.subvolumes.push_back(below);
  scene.attributes.push_back(format::geometry_field_name(m));
  const ResolvedScene resolved = resolve_scene(scene, m, "test scene");
  LevelExtractionOptions o;
  o.merge_face_squares = false;
  LevelExtraction result = extract_level(*store, resolved, o);
  const FrameTransform lonlat(m, OutputFrame::kLonLat, choose_vertical_placement(m));
  const auto on_axis = [](const Axis& a, double v) {
    return std::find(a.values.begin(), a.values.end(), v) != a.values.end();
  };
  std::size_t meshes = 0, on_top = 0, on_edges = 0;
  for (NodeExtraction& n : result.nodes) {
    for (SubVolumeResult& r : n.results) {
      if (r.outcome != NodeOutcome::kMesh) continue;
      ++meshes;
      const std::vector<std::array<double, 3>> axis_positions = r.mesh.positions;
      lonlat.apply(r.mesh);
      EXPECT_TRUE(check_mesh(r.mesh).closed());
      EXPECT_GT(enclosed_volume(r.mesh), 0);
      for (std::size_t i = 0; i < axis_positions.size(); ++i) {
        const auto& q = axis_positions[i];
        const int sampled = on_axis(m.x, q[0]) + on_axis(m.y, q[1]) + on_axis(m.z, q[2]);
        // On a lattice edge the kernel's crossing and the trilinear placement agree: the
        // band's top is at 3000 m. (On a node face's split diagonal the crossing is linear
        // along the diagonal, the placement bilinear: they differ by the field's twist.)
        if (sampled < 2) continue;
        ++on_edges;
        const double h = r.mesh.positions[i][2];
        ASSERT_LE(h, 3000.0 + 1e-2);
        on_top += std::fabs(h - 3000.0) < 1e-2;
      }
    }
  }
  EXPECT_GT(on_edges, 0u);
  EXPECT_GT(meshes, 0u);
  EXPECT_GT(on_top, 0u);  // the band's top face lies at 3000 m
}

// Every mesh of a level-0 extraction of `scene`, placed in longitude/latitude/height.
// Counts the nodes and those skipped for the domain into `nodes` and `skipped_domain`.
std::vector<Mesh> placed_meshes(const Store& store, const Scene& scene,
                                std::size_t* skipped_domain = nullptr,
                                std::size_t* nodes = nullptr) {
  const format::Manifest& m = store.manifest();
  LevelExtractionOptions o;
  o.merge_face_squares = false;
  LevelExtraction result = extract_level(store, resolve_scene(scene, m, "test scene"), o);
  const FrameTransform lonlat(m, OutputFrame::kLonLat, choose_vertical_placement(m));
  std::vector<Mesh> meshes;
  if (nodes != nullptr) *nodes = result.nodes.size();
  for (NodeExtraction& n : result.nodes) {
    for (SubVolumeResult& r : n.results) {
      if (skipped_domain != nullptr) *skipped_domain += r.outcome == NodeOutcome::kSkippedDomain;
      if (r.outcome != NodeOutcome::kMesh) continue;
      lonlat.apply(r.mesh);
      meshes.push_back(std::move(r.mesh));
    }
  }
  return meshes;
}

TEST(TerrainFollowingConversionTest, AKeptBrickCacheReadsATimeInvariantGeometryOncePerNode) {
  const testing::TempDir dir;
  const auto input = write_model(dir.path(), synthetic::SampleModel::kIcon, 2);
  build::convert(options(input, dir / "store"));
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  ASSERT_FALSE(m.geometry->vertical.varies_in_time);
  Scene scene;
  SubVolume cold;
  cold.id = 1;
  cold.limits.push_back(Limit{"temp", std::nullopt, 270.0});
  scene.subvolumes.push_back(cold);
  scene.attributes.push_back(format::geometry_field_name(m));
  const ResolvedScene resolved = resolve_scene(scene, m, "test scene");
  const auto chunks = [&](std::uint32_t step, BrickCache* cache, LevelExtraction* out) {
    const std::uint64_t before = store->counters().chunks_read;
    LevelExtractionOptions o;
    o.step = step;
    o.cache = cache;
    o.merge_face_squares = false;
    *out = extract_level(*store, resolved, o);
    return store->counters().chunks_read - before;
  };
  LevelExtraction fresh, first, kept;
  const std::uint64_t cold_reads = chunks(0, nullptr, &fresh);
  BrickCache cache(64ull << 20);
  const std::uint64_t step1_reads = chunks(1, &cache, &first);
  const std::uint64_t kept_reads = chunks(0, &cache, &kept);
  // Step 0 with the cache kept from step 1 reads its data bricks, not the geometry's.
  const std::uint64_t geometry_bricks = fresh.totals.bricks_used / 2;
  ASSERT_GT(geometry_bricks, 0u);
  EXPECT_EQ(step1_reads, cold_reads);
  EXPECT_EQ(kept_reads + geometry_bricks, cold_reads);
  ASSERT_EQ(kept.nodes.size(), fresh.nodes.size());
  for (std::size_t n = 0; n < fresh.nodes.size(); ++n) {
    ASSERT_EQ(kept.nodes[n].results.size(), fresh.nodes[n].results.size());
    for (std::size_t r = 0; r < fresh.nodes[n].results.size(); ++r) {
      EXPECT_EQ(kept.nodes[n].results[r].mesh.positions, fresh.nodes[n].results[r].mesh.positions);
      EXPECT_EQ(kept.nodes[n].results[r].mesh.attributes, fresh.nodes[n].results[r].mesh.attributes);
    }
  }
}

TEST(TerrainFollowingConversionTest, AGeographicHeightRangeCutsTheBandWithDomainBoxFaces) {
  const testing::TempDir dir;
  const auto input = write_model(dir.path(), synthetic::SampleModel::kIcon, 1);
  build::convert(options(input, dir / "store"));
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  // 1000 to 3000 m above sea level, once as a geographic height range and once as a
  // limit on the geometry's field: the same samples bound both, so the same surfaces;
  // the range's faces are domain-box faces, the limit's limit faces.
  Scene box_scene;
  SubVolume box;
  box.id = 1;
  box.geographic.emplace().height = AxisRange{1000.0, 3000.0};
  box_scene.subvolumes.push_back(box);
  box_scene.attributes.push_back(format::geometry_field_name(m));
  EXPECT_EQ(box_scene.required_format_version(), kSceneVersionGeographicHeight);
  Scene limit_scene;
  SubVolume limit;
  limit.id = 1;
  limit.limits.push_back(Limit{format::geometry_field_name(m), 1000.0, 3000.0});
  limit_scene.subvolumes.push_back(limit);
  limit_scene.attributes.push_back(format::geometry_field_name(m));

  const std::vector<Mesh> by_box = placed_meshes(*store, box_scene);
  const std::vector<Mesh> by_limit = placed_meshes(*store, limit_scene);
  ASSERT_FALSE(by_box.empty());
  ASSERT_EQ(by_box.size(), by_limit.size());
  std::size_t box_faces = 0;
  for (std::size_t i = 0; i < by_box.size(); ++i) {
    const Mesh& a = by_box[i];
    const Mesh& b = by_limit[i];
    EXPECT_TRUE(check_mesh(a).closed());
    EXPECT_GT(enclosed_volume(a), 0);
    EXPECT_NEAR(enclosed_volume(a), enclosed_volume(b), 1e-9 * std::fabs(enclosed_volume(b)));
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (std::size_t t = 0; t < a.triangles.size(); ++t) {
      EXPECT_NE(a.face_kinds[t], FaceKind::kLimit);
      if (b.face_kinds[t] == FaceKind::kLimit) {
        EXPECT_EQ(a.face_kinds[t], FaceKind::kDomainBox);
        ++box_faces;
      }
    }
    // The same vertices (the band's bounds lie where the limit's do).
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (std::size_t v = 0; v < a.positions.size(); ++v) {
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(a.positions[v][k], b.positions[v][k], 1e-6);
    }
  }
  EXPECT_GT(box_faces, 0u);

  // A range above the model top skips every node from the index alone.
  Scene above_scene;
  box.geographic->height = AxisRange{90000.0, 95000.0};
  above_scene.subvolumes.push_back(box);
  above_scene.attributes.push_back(format::geometry_field_name(m));
  std::size_t skipped = 0, nodes = 0;
  EXPECT_TRUE(placed_meshes(*store, above_scene, &skipped, &nodes).empty());
  EXPECT_GT(nodes, 0u);
  EXPECT_EQ(skipped, nodes);
}

TEST(TerrainFollowingConversionTest, SigmaPressureKeepsAPressurePerSampleAndStep) {
  const testing::TempDir dir;
  const auto input = write_model(dir.path(), synthetic::SampleModel::kSigmaPressure, 2);
  build::convert(options(input, dir / "store"));
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  ASSERT_TRUE(m.geometry);
  EXPECT_EQ(m.geometry->vertical.quantity, format::VerticalGeometry::Quantity::kPressure);
  EXPECT_EQ(m.geometry->vertical.formula, "atmosphere_hybrid_sigma_pressure_coordinate");
  EXPECT_TRUE(m.geometry->vertical.varies_in_time);
  EXPECT_FALSE(std::filesystem::exists(dir / "store" / "geometry.bricks"));
  // p = hyam + hybm * ps(t), per sample and step, as float32.
  const std::vector<double> hyam = testing::read_netcdf_variable(input, "hyam").values,
                            hybm = testing::read_netcdf_variable(input, "hybm").values;
  const std::vector<double> ps = testing::read_netcdf_variable(input, "ps").values;
  const std::size_t plane = kDims.x * kDims.y;
  const auto v = *format::geometry_field_variable(m);
  for (std::uint32_t step = 0; step < 2; ++step) {
    const auto p = read_level_samples<float>(*store, step, v, 0);
    for (std::size_t k = 0; k < kDims.z; ++k) {
      for (std::size_t s = 0; s < plane; ++s) {
        const double want = hyam[k] + hybm[k] * ps[step * plane + s];
        ASSERT_EQ(p.values[k * plane + s], static_cast<float>(want))
            << step << " " << k << " " << s;
      }
    }
  }
}

TEST(TerrainFollowingConversionTest, LevelsThatFloat32CannotTellApartAreRefused) {
  // 5000 m and 5000.0001 m differ in double (the reader accepts the column) but are one
  // float32 value: the stored column would not be strictly monotonic.
  const testing::TempDir dir;
  const testing::ModelLevels g;
  const auto z = [](std::size_t, std::size_t k, std::size_t) {
    return k == 0 ? 4000.0 : k == 1 ? 5000.0 : 5000.0001;
  };
  g.fixture()
      .variable("z_mc", NC_DOUBLE, {"lev", "lat", "lon"}, testing::field(1, g.nz, g.plane(), z),
                {testing::NcAttr::text_value("units", "m")})
      .write(dir / "close.nc");
  testing::expect_error([&] { build::convert(options(dir / "close.nc", dir / "store")); },
                        ErrorCode::kInvalidInput,
                        {"z_mc", "stored as float32", "not strictly monotonic"});
}

}  // namespace
}  // namespace strielad
