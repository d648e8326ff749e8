// SPDX-License-Identifier: Apache-2.0
// The viewer on mapped grids (issue 27): the real EURO-CORDEX EUR-11 store (rotated pole)
// and the real HSURF terrain on the same pole meet (a data sample and the DEM sample at
// the same true longitude/latitude land on the same world x/y), flight tracks and the
// sun stand at true longitudes/latitudes, node boxes hold every placed vertex of a
// rotated-pole store's meshes, and a Cartesian store refuses terrain, tracks and the
// true sun, naming its axes.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <filesystem>

#include "convert/converter.h"
#include "extract/node_extraction.h"
#include "scenery/dem_source.h"
#include "lod/lod_test_grids.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/cs2cs.h"
#include "support/expect_error.h"
#include "support/function_dem.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "view/node_geometry.h"
#include "view/sun_direction.h"
#include "view/terrain_tiles.h"
#include "view/track_window.h"

namespace strielad {
namespace {

using testing::expect_error;
using testing::NcAttr;
using testing::TempDir;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

const std::filesystem::path kTas = testing::ncarg_file("nug/tas_rotated_grid_EUR11.nc");
const std::filesystem::path kHsurf = testing::ncarg_file("nug/HSURF_regional_model_0.11deg.nc");

std::shared_ptr<const Store> convert(const std::vector<std::filesystem::path>& inputs,
                                     const std::filesystem::path& store, std::uint32_t brick) {
  build::ConvertOptions o;
  o.inputs = inputs;
  o.store = store;
  o.brick = brick;
  o.threads = 2;
  build::convert(o);
  return Store::open(store);
}

TEST(GeoreferencedSceneTest, HsurfTerrainMeetsEur11Data) {
  if (!std::filesystem::exists(kTas) || !std::filesystem::exists(kHsurf)) {
    GTEST_SKIP() << "libncarg-data missing";
  }
  TempDir dir;
  const auto store = convert({kTas}, dir / "eur11", 32);
  const format::Manifest& m = store->manifest();
  ASSERT_EQ(m.x.size(), 424u);
  ASSERT_TRUE(m.grid_mapping);
  const lod::WorldFrame frame(m, lod::WorldFrameOptions{.vertical_exaggeration = 1.0});
  ASSERT_EQ(frame.horizontal(), lod::HorizontalMap::kMapped);
  view::TerrainTiles tiles(geo::open_dem(kHsurf), frame, {.cull = false});
  // HSURF's rotated grid is EUR-11's with 13 more samples on every side: DEM sample
  // (i + 13, j + 13) is data sample (i, j). Samples across the domain, the Alps included
  // (rotated -2.5, -3.5 is about 47 N, 11 E).
  std::size_t compared = 0;
  for (const auto& [i, j] : {std::pair<std::size_t, std::size_t>{0, 0}, {423, 0}, {0, 411},
                             {423, 411}, {235, 180}, {300, 250}, {100, 350}}) {
    const std::size_t col = i + 13, row = j + 13;
    // The finest tile that holds the DEM sample, and the sample's vertex in it.
    const auto e = tiles.extent();
    ASSERT_GE(col, e[0]);
    ASSERT_GE(row, e[1]);
    const std::size_t span = view::kTerrainTileCells;
    const view::TerrainTileKey key{tiles.finest_level(), int((col - e[0]) / span),
                                   int((row - e[1]) / span)};
    const auto s = tiles.samples(key);
    const auto ci = std::find(s.cols.begin(), s.cols.end(), col);
    const auto ri = std::find(s.rows.begin(), s.rows.end(), row);
    ASSERT_NE(ci, s.cols.end());
    ASSERT_NE(ri, s.rows.end());
    const auto mesh = tiles.load_tile(key);
    const std::size_t v = std::size_t(ri - s.rows.begin()) * s.cols.size() + std::size_t(ci - s.cols.begin());
    const float* vertex = &mesh->vertices[v * view::kTerrainVertexFloats];
    const auto data = frame.sample_world_xy(i, j);
    EXPECT_NEAR(vertex[0], data[0], 2e-3) << "sample " << i << ", " << j;  // 2 m
    EXPECT_NEAR(vertex[1], data[1], 2e-3) << "sample " << i << ", " << j;
    // Clip coordinates: the store's own axes.
    EXPECT_NEAR(vertex[8], m.x.values[i], 1e-4);
    EXPECT_NEAR(vertex[9], m.y.values[j], 1e-4);
    ++compared;
  }
  EXPECT_EQ(compared, 7u);
  // The terrain is cut to the store's rotated box, not to its world box.
  const auto frame0 = tiles.update(lod::look_at({0, -5000, 5000}, {0, 0, 0}, 45, 1.5, frame.domain()),
                                   1.0, 720);
  EXPECT_NEAR(frame0->clip.lo[0], -28.375, 1e-9);
  EXPECT_NEAR(frame0->clip.hi[1], m.y.values.back(), 1e-9);
}

TEST(GeoreferencedSceneTest, TracksAndTheSunStandAtTrueLongitudeLatitude) {
  if (!testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  // A rotated-pole manifest like EUR-11's.
  format::Manifest m;
  m.x = Axis{"rlon", AxisKind::kProjectionX, "degrees", "grid_longitude", "", "",
             lod::testing::linspace(-28.375, 18.155, 44)};
  m.y = Axis{"rlat", AxisKind::kProjectionY, "degrees", "grid_latitude", "", "",
             lod::testing::linspace(-23.375, 21.835, 42)};
  m.z = Axis{"height", AxisKind::kHeight, "m", "", "", "up", {0.0, 10000.0}};
  m.time = TimeAxis{"time", "hours since 2006-01-16 12:00:00", "standard", {0.0}};
  GridMapping g{"rotated_pole", "rotated_latitude_longitude",
                {{"grid_mapping_name", "rotated_latitude_longitude"},
                 {"grid_north_pole_latitude", 39.25},
                 {"grid_north_pole_longitude", -162.0}},
                "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad +step +inv "
                "+proj=ob_tran +o_proj=longlat +o_lat_p=39.25 +o_lon_p=0 +lon_0=18 +step "
                "+proj=unitconvert +xy_in=rad +xy_out=deg"};
  m.grid_mapping = g;
  const lod::WorldFrame frame(m, lod::WorldFrameOptions{.vertical_exaggeration = 1.0});
  // An aircraft over Innsbruck (11.4 E, 47.27 N) at 10 km: where the data sample at the
  // rotated position cs2cs gives for Innsbruck is.
  geo::FlightTracks tracks;
  geo::FlightTrack t;
  t.id = "over Innsbruck";
  t.seconds = {0, 60};
  t.lon = {11.4, 11.4};
  t.lat = {47.27, 47.27};
  t.altitude_m = {10000, 10000};
  tracks.tracks.push_back(t);
  const auto lines = view::window_tracks(tracks, 30, 120, frame);
  ASSERT_EQ(lines.head_count(), 1u);
  const auto rotated = testing::cs2cs("+proj=longlat", testing::kEuroCordexRotatedPole, {{11.4, 47.27}});
  ASSERT_TRUE(rotated);
  const Vec3 data = frame.to_world({(*rotated)[0][0], (*rotated)[0][1], 10000.0});
  EXPECT_NEAR(lines.heads[0], data[0], 1e-3);
  EXPECT_NEAR(lines.heads[1], data[1], 1e-3);
  EXPECT_NEAR(lines.heads[2], 10.0, 1e-6);
  // Had the rotated axes been taken for longitude/latitude, Innsbruck would lie some
  // 3,000 km away: the tracks are placed by the mapping.
  EXPECT_LT(std::hypot(lines.heads[0] - data[0], lines.heads[1] - data[1]), 0.01);

  // The sun: the domain spans about 100 degrees of true longitude, so it is seen from
  // its sunniest point, within the domain's true latitudes.
  const auto sun = view::sun_at_step(frame, m, 0);
  ASSERT_TRUE(sun);
  const auto b = frame.geographic_bounds();
  EXPECT_NEAR(sun->domain_longitude_span_deg, b.lon_hi - b.lon_lo, 1e-9);
  EXPECT_GT(sun->domain_longitude_span_deg, 90.0);
  EXPECT_EQ(sun->viewpoint, view::SunViewpoint::kSunniestPoint);
  EXPECT_GE(sun->latitude_deg, b.lat_lo);
  EXPECT_LE(sun->latitude_deg, b.lat_hi);
  const auto centre = testing::cs2cs(testing::kEuroCordexRotatedPole, "+proj=longlat",
                                     {{0.5 * (-28.375 + 18.155), 0.5 * (-23.375 + 21.835)}});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(frame.lon0(), (*centre)[0][0], 1e-9);
  EXPECT_NEAR(frame.lat0(), (*centre)[0][1], 1e-9);
}

TEST(GeoreferencedSceneTest, CartesianStoreRefusesTerrainTracksAndTheSun) {
  format::Manifest m = lod::testing::geographic_manifest(5, 5, {0.0, 1000.0});
  m.x = Axis{"x", AxisKind::kProjectionX, "m", "projection_x_coordinate", "", "",
             lod::testing::linspace(0, 40000, 5)};
  m.y = Axis{"y", AxisKind::kProjectionY, "m", "projection_y_coordinate", "", "",
             lod::testing::linspace(0, 40000, 5)};
  const lod::WorldFrame frame(m);
  auto dem = std::make_shared<testing::FunctionDem>(11, 11, 0.0, 1.0, 0.0, 1.0,
                                                    [](double, double) { return 100.0f; });
  expect_error([&] { view::TerrainTiles tiles(dem, frame); }, ErrorCode::kUnsupported,
               {"function DEM", "'x'", "'y'", "no place on the Earth"});
  EXPECT_FALSE(view::sun_at_step(frame, m, 0));
  geo::FlightTracks tracks;
  geo::FlightTrack t;
  t.seconds = {0, 60};
  t.lon = {0.5, 0.6};
  t.lat = {0.5, 0.5};
  t.altitude_m = {1000, 1000};
  tracks.tracks.push_back(t);
  EXPECT_EQ(view::window_tracks(tracks, 30, 120, frame).head_count(), 0u);
}

// A small 3-D field on a rotated pole: a warm bubble over the Alps.
std::filesystem::path write_rotated_bubble(const std::filesystem::path& dir) {
  const auto rlon = lod::testing::linspace(-8.0, 4.0, 25);
  const auto rlat = lod::testing::linspace(-8.0, 2.0, 21);
  const std::vector<double> height{0, 1000, 2000, 3000, 4000, 5000, 6000, 7000, 8000};
  std::vector<double> t;
  for (double h : height) {
    for (double y : rlat) {
      for (double x : rlon) {
        const double r = std::hypot((x + 2.5) / 3.0, (y + 3.5) / 2.5, (h - 3000.0) / 2500.0);
        t.push_back(280.0 - 10.0 * r);
      }
    }
  }
  const auto path = dir / "bubble.nc";
  testing::NetcdfFixture()
      .coordinate("time", {0.0}, {NcAttr::text_value("units", "hours since 2006-01-16 00:00:00"),
                                  NcAttr::text_value("standard_name", "time")},
                  NC_DOUBLE, true)
      .coordinate("height", height, {NcAttr::text_value("units", "m"),
                                     NcAttr::text_value("standard_name", "height"),
                                     NcAttr::text_value("positive", "up")})
      .coordinate("rlat", rlat, {NcAttr::text_value("units", "degrees"),
                                 NcAttr::text_value("standard_name", "grid_latitude")})
      .coordinate("rlon", rlon, {NcAttr::text_value("units", "degrees"),
                                 NcAttr::text_value("standard_name", "grid_longitude")})
      .variable("rotated_pole", NC_CHAR, {}, {},
                {NcAttr::text_value("grid_mapping_name", "rotated_latitude_longitude"),
                 NcAttr::number("grid_north_pole_latitude", NC_DOUBLE, {39.25}),
                 NcAttr::number("grid_north_pole_longitude", NC_DOUBLE, {-162.0})})
      .variable("ta", NC_FLOAT, {"time", "height", "rlat", "rlon"}, t,
                {NcAttr::text_value("units", "K"), NcAttr::text_value("grid_mapping", "rotated_pole")})
      .write(path);
  return path;
}

TEST(GeoreferencedSceneTest, NodeBoxesHoldEveryPlacedVertexOfARotatedPoleStore) {
  TempDir dir;
  const auto store = convert({write_rotated_bubble(dir.path())}, dir / "store", 4);
  const format::Manifest& m = store->manifest();
  ASSERT_TRUE(m.grid_mapping);
  const view::GeometryPlacer placer(m);
  ASSERT_EQ(placer.frame().horizontal(), lod::HorizontalMap::kMapped);
  const auto boxes = lod::node_world_boxes(store->octree(), placer.frame());
  const ResolvedScene scene = resolve_scene(
      parse_scene(R"({"format_version": 2,
                      "subvolumes": [{"id": 1, "limits": [{"var": "ta", "min": 274}]}],
                      "slices": [{"id": 2, "axis": "height", "value": 2500, "var": "ta"}]})",
                  "scene"),
      m, "scene");
  std::size_t vertices = 0, slice_vertices = 0;
  for (NodeId n = 0; n < store->octree().node_count(); ++n) {
    const NodeExtraction e = extract_node(*store, nullptr, scene, 0, n);
    protocol::NodeResult result;
    result.node = n;
    for (const auto& r : e.results) result.subvolumes.push_back({r.subvolume_id, r.outcome, r.reason, r.mesh, {}});
    for (const auto& s : e.slices) result.slices.push_back({s.slice_id, s.outcome, s.reason, s.mesh});
    const auto geometry = placer.place(result, 0, [](std::uint32_t id) { return id == 1 ? 0 : -1; });
    // The box, widened by the rounding of the float vertices (1e-6 relative).
    lod::WorldBox box = boxes[n];
    for (int a = 0; a < 3; ++a) {
      box.lo[a] -= 1e-6 * (1.0 + std::fabs(box.lo[a]));
      box.hi[a] += 1e-6 * (1.0 + std::fabs(box.hi[a]));
    }
    for (std::size_t v = 0; v < geometry->vertex_count(); ++v) {
      const float* p = &geometry->vertices[v * view::kVertexFloats];
      ASSERT_TRUE(box.contains(Vec3{p[0], p[1], p[2]})) << "node " << n << " vertex " << v;
      // The normal is a unit vector.
      EXPECT_NEAR(std::hypot(p[3], p[4], p[5]), 1.0, 1e-5);
      ++vertices;
    }
    for (std::size_t v = 0; v < geometry->slice_vertex_count(); ++v) {
      const float* p = &geometry->slice_vertices[v * view::kSliceVertexFloats];
      ASSERT_TRUE(box.contains(Vec3{p[0], p[1], p[2]})) << "node " << n << " slice vertex " << v;
      ++slice_vertices;
    }
  }
  EXPECT_GT(vertices, 100u);
  EXPECT_GT(slice_vertices, 10u);
}

}  // namespace
}  // namespace strielad
