// SPDX-License-Identifier: Apache-2.0
// The terrain quadtree (view/terrain_tiles.h): the extent is clipped to the store, the
// selected tiles cover it without overlap, a closer camera selects finer tiles, parents
// are drawn until all children arrive, the cache stays within its byte bound, NaN
// samples and samples below sea level are drawn as water at height 0, the extent's own
// edges hang no skirts, and a global DEM goes round under a global store without a seam.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <span>
#include <thread>

#include "lod/lod_test_grids.h"
#include "support/expect_error.h"
#include "support/function_dem.h"
#include "view/terrain_tiles.h"

namespace strielad {
namespace {

using testing::FunctionDem;

// The test grids' store: lon 4.5..14.5, lat 47.5..54.5.
lod::WorldFrame store_frame() {
  return lod::WorldFrame(lod::testing::geographic_manifest(11, 8, {0.0, 12000.0}),
                         lod::WorldFrameOptions{.vertical_exaggeration = 10.0});
}

// A DEM larger than the store (lon 2..17, lat 46..56) at 0.005 degrees.
std::shared_ptr<FunctionDem> big_dem() {
  return std::make_shared<FunctionDem>(3001, 2001, 2.0, 17.0, 46.0, 56.0, [](double lon, double lat) {
    return float(500 + 400 * std::sin(lon * 3) * std::cos(lat * 2));
  });
}

std::shared_ptr<const view::TerrainFrame> settle(view::TerrainTiles& t, const lod::Camera& cam) {
  std::shared_ptr<const view::TerrainFrame> frame;
  for (int i = 0; i < 20000; ++i) {
    frame = t.update(cam, 10.0, 720);
    if (t.complete()) return frame;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ADD_FAILURE() << "terrain never complete";
  return frame;
}

lod::Camera camera_at(const lod::WorldFrame& f, Vec3 eye, Vec3 target) {
  return lod::look_at(eye, target, 45.0, 16.0 / 9.0, f.domain());
}

// Every tile of quadtree level `level` that exists, loaded, with its DEM samples.
struct LoadedTile {
  view::TerrainTileKey key;
  std::shared_ptr<const view::TerrainTileMesh> mesh;
  view::TerrainTileSamples samples;
};
std::vector<LoadedTile> loaded_tiles(const view::TerrainTiles& tiles, int level) {
  std::vector<LoadedTile> out;
  for (int x = 0; x < (1 << level); ++x) {
    for (int y = 0; y < (1 << level); ++y) {
      const view::TerrainTileKey key{level, x, y};
      if (tiles.exists(key)) out.push_back({key, tiles.load_tile(key), tiles.samples(key)});
    }
  }
  return out;
}

TEST(TerrainTilesTest, ExtentIsClippedToTheStore) {
  const auto frame = store_frame();
  view::TerrainTiles tiles(big_dem(), frame);
  const auto e = tiles.extent();
  // Store lon 4.5..14.5 is DEM columns 500..2500, lat 54.5..47.5 rows 300..1700, plus
  // the 512-lattice's step (6 samples) of margin.
  EXPECT_LE(e[0], 500u);
  EXPECT_GE(e[0], 490u);
  EXPECT_GE(e[2], 2500u);
  EXPECT_LE(e[2], 2510u);
  EXPECT_LE(e[1], 300u);
  EXPECT_GE(e[3], 1700u);
  EXPECT_EQ(tiles.finest_level(), 5);  // 2012 cells: 64 << 5 = 2048
}

TEST(TerrainTilesTest, SelectionCoversTheExtentWithoutOverlap) {
  const auto frame = store_frame();
  view::TerrainTiles tiles(big_dem(), frame, {.error_pixels = 2.0, .cull = false});
  const auto cam = camera_at(frame, {0, -300, 150}, {0, 0, 0});
  const auto selected = settle(tiles, cam);
  const auto e = tiles.extent();
  // Count how many selected tiles cover each DEM cell (on a lattice of cells).
  std::map<std::pair<std::size_t, std::size_t>, int> cover;
  for (const auto& t : selected->tiles) {
    const auto s = tiles.samples(t->key);
    for (std::size_t r = s.rows.front(); r < s.rows.back(); r += 4) {
      for (std::size_t c = s.cols.front(); c < s.cols.back(); c += 4) ++cover[{r - r % 4, c - c % 4}];
    }
  }
  // Every tile starts at the extent's corner plus a multiple of 64 samples, so the
  // lattice of every 4th cell from that corner lines up with each tile's own.
  std::size_t cells = 0;
  for (std::size_t r = e[1]; r < e[3]; r += 4) {
    for (std::size_t c = e[0]; c < e[2]; c += 4) {
      ++cells;
      ASSERT_EQ((cover[{r - r % 4, c - c % 4}]), 1) << "cell " << r << "," << c;
    }
  }
  EXPECT_GT(cells, 1000u);
  EXPECT_GT(selected->tiles.size(), 4u);
}

TEST(TerrainTilesTest, CloserCameraSelectsFinerTiles) {
  const auto frame = store_frame();
  const auto finest = [&](const lod::Camera& cam) {
    view::TerrainTiles tiles(big_dem(), frame);
    const auto selected = settle(tiles, cam);
    int level = 0;
    for (const auto& t : selected->tiles) level = std::max(level, t->key.level);
    return level;
  };
  const int far = finest(camera_at(frame, {0, -1500, 800}, {0, 0, 0}));
  const int near = finest(camera_at(frame, {0, -60, 30}, {0, 0, 0}));
  EXPECT_GT(near, far);
}

TEST(TerrainTilesTest, ParentShownUntilChildrenArrive) {
  const auto frame = store_frame();
  view::TerrainTiles tiles(big_dem(), frame);
  const auto cam = camera_at(frame, {0, -60, 30}, {0, 0, 0});
  // The first update has nothing loaded: nothing drawn, not complete, never blocks.
  const auto t0 = std::chrono::steady_clock::now();
  const auto first = tiles.update(cam, 10.0, 720);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::milliseconds(200));
  EXPECT_TRUE(first->tiles.empty());
  EXPECT_FALSE(tiles.complete());
  // Every later frame draws something (the root at least) and finally finer tiles.
  for (int i = 0; i < 20000 && !tiles.complete(); ++i) {
    const auto f = tiles.update(cam, 10.0, 720);
    if (tiles.status().loads > 0) {
      EXPECT_FALSE(f->tiles.empty());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_TRUE(tiles.complete());
}

TEST(TerrainTilesTest, CacheStaysWithinItsByteBound) {
  const auto frame = store_frame();
  const std::size_t bound = 2u << 20;
  view::TerrainTiles tiles(big_dem(), frame, {.error_pixels = 1.0, .cache_bytes = bound});
  // Fly along: each view needs other fine tiles.
  for (double x = -300; x <= 300; x += 100) {
    const auto drawn = settle(tiles, camera_at(frame, {x, -50, 20}, {x, 0, 0}));
    std::size_t drawn_bytes = 0;
    for (const auto& t : drawn->tiles) drawn_bytes += t->bytes();
    const auto s = tiles.status();
    // The bound holds except for what the current frame uses (never evicted): the tiles
    // drawn and their ancestors (at most a third more tiles, plus one per level).
    EXPECT_LE(s.cache_bytes, bound + 2 * drawn_bytes) << x;
  }
  EXPECT_GT(tiles.status().loads, tiles.status().cached);  // something was evicted
}

// A DEM whose reads take a while, so that a tile's children arrive one by one over many
// frames.
class SlowDem final : public geo::DemSource {
 public:
  explicit SlowDem(std::shared_ptr<FunctionDem> dem) : dem_(std::move(dem)) {}
  std::size_t width() const override { return dem_->width(); }
  std::size_t height() const override { return dem_->height(); }
  void georeference(std::span<const double> cols, std::span<const double> rows,
                    std::span<geo::LonLat> out) const override {
    dem_->georeference(cols, rows, out);
  }
  std::vector<float> read(const geo::DemWindow& w) const override {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return dem_->read(w);
  }
  std::string describe() const override { return "slow function DEM"; }
  std::string georeferencing() const override { return dem_->georeferencing(); }

 private:
  std::shared_ptr<FunctionDem> dem_;
};

// With a cache bound far below what a view needs, children that have arrived are kept
// while they wait for their siblings (evicting them would reload them forever).
TEST(TerrainTilesTest, TightCacheStillCompletesWhenChildrenArriveOneByOne) {
  const auto frame = store_frame();
  view::TerrainTiles tiles(std::make_shared<SlowDem>(big_dem()), frame,
                           {.error_pixels = 2.0, .cache_bytes = 1});
  const auto drawn = settle(tiles, camera_at(frame, {0, -80, 30}, {0, 0, 0}));
  EXPECT_TRUE(tiles.complete());
  EXPECT_GT(drawn->tiles.size(), 4u);  // the root was split
}

TEST(TerrainTilesTest, MissingSamplesAreFlaggedAtHeightZero) {
  const auto frame = store_frame();
  auto dem = std::make_shared<FunctionDem>(201, 141, 4.5, 14.5, 47.5, 54.5, [](double lon, double) {
    return lon < 9.5 ? NAN : 1000.0f;
  });
  view::TerrainTiles tiles(dem, frame);
  const auto root = tiles.load_tile({0, 0, 0});
  std::size_t missing = 0, present = 0;
  for (std::size_t i = 0; i < root->vertices.size(); i += view::kTerrainVertexFloats) {
    const float* v = &root->vertices[i];
    if (v[7] > 0.5f) {
      ++missing;
      EXPECT_LE(v[2], 0.0f);  // height 0 (skirt copies lower)
    } else {
      ++present;
    }
  }
  EXPECT_GT(missing, 100u);
  EXPECT_GT(present, 100u);
}

// An ETOPO-style DEM: the sea's depths are negative heights.
TEST(TerrainTilesTest, SeaBelowZeroIsWaterAtHeightZero) {
  const auto frame = store_frame();
  auto dem = std::make_shared<FunctionDem>(201, 141, 4.5, 14.5, 47.5, 54.5, [](double lon, double) {
    return lon < 9.5 ? -3000.0f : 1000.0f;
  });
  view::TerrainTiles tiles(dem, frame);
  const auto root = tiles.load_tile({0, 0, 0});
  const double coast_x = frame.geographic_to_world(9.5, 51.0)[0];
  std::size_t sea = 0, land = 0;
  for (std::size_t i = 0; i < root->vertices.size(); i += view::kTerrainVertexFloats) {
    const float* v = &root->vertices[i];
    if (v[0] < coast_x - 1) {
      ++sea;
      EXPECT_EQ(v[7], 1.0f);  // water
      EXPECT_EQ(v[2], 0.0f);  // at sea level, not at -3 km
      if (v[0] < coast_x - 30) {
        EXPECT_EQ(v[3], 0.0f);  // flat: the sea bed's slopes do not shade it
        EXPECT_EQ(v[4], 0.0f);
      }
    } else if (v[0] > coast_x + 1) {
      ++land;
      EXPECT_EQ(v[7], 0.0f);
      EXPECT_NEAR(v[2], 1.0f, 1e-6);
    }
  }
  EXPECT_GT(sea, 500u);
  EXPECT_GT(land, 500u);
  EXPECT_EQ(root->box.lo[2], 0.0);
}

// Skirts hide cracks between tiles of different levels; the extent's own edges meet no
// other tile, and a skirt there would hang as a curtain under the store's edge where the
// DEM ends with it (a global DEM at the poles).
TEST(TerrainTilesTest, ExtentEdgesHangNoSkirts) {
  const auto frame = store_frame();
  view::TerrainTiles tiles(big_dem(), frame);
  const auto surface_vertices = [&](const view::TerrainTileKey& key) {
    const auto s = tiles.samples(key);
    return s.cols.size() * s.rows.size();
  };
  const auto root = tiles.load_tile({0, 0, 0});
  EXPECT_EQ(root->vertices.size() / view::kTerrainVertexFloats, surface_vertices({0, 0, 0}));
  EXPECT_EQ(root->triangles(), root->surface_triangles);
  // A tile of level 1 at the extent's south-west corner: skirts on its two inner edges.
  const view::TerrainTileKey corner{1, 0, 0};
  const auto s = tiles.samples(corner);
  const auto tile = tiles.load_tile(corner);
  EXPECT_EQ(tile->vertices.size() / view::kTerrainVertexFloats,
            s.cols.size() * s.rows.size() + s.cols.size() + s.rows.size());
}

// A global store like a 2.5-degree forecast (0 to 357.5 E, 90 N to 90 S) over an
// ETOPO-style DEM from -180 to 180 (both ends, 0.25 degrees, rows from pole to pole).
TEST(TerrainTilesTest, GlobalDemGoesRoundWithoutASeam) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "",
             lod::testing::linspace(0, 357.5, 144)};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "",
             lod::testing::linspace(90, -90, 73)};
  m.z = Axis{"plev", AxisKind::kPressure, "Pa", "", "", "down", lod::testing::linspace(100000, 1000, 26)};
  m.time = TimeAxis{"time", "hours since 2024-06-21 00:00:00", "standard", {12}};
  m.brick = 16;
  const lod::WorldFrame frame(m, {.vertical_exaggeration = 200.0});
  auto dem = std::make_shared<FunctionDem>(1441, 721, -180.0, 180.0, -90.0, 90.0, [](double lon, double lat) {
    return float(3000 * std::sin(lon * 0.05) * std::cos(lat * 0.07));
  });
  view::TerrainTiles tiles(dem, frame);
  EXPECT_EQ(tiles.wrap_columns(), 1440u);
  const auto& domain = frame.domain();
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  std::size_t checked = 0;
  for (int level = 0; level <= 2; ++level) {
    for (const auto& [key, tile, s] : loaded_tiles(tiles, level)) {
      // Neighbouring vertices lie one tile stride apart, never across the map.
      const double stride_km = double(std::size_t{1} << (tiles.finest_level() - level)) * 0.25 *
                               lod::kKmPerDegree;
      const auto vertex = [&](std::uint32_t i) { return &tile->vertices[std::size_t(i) * view::kTerrainVertexFloats]; };
      for (std::size_t t = 0; t < tile->surface_triangles; ++t) {
        for (int e = 0; e < 3; ++e) {
          const float* a = vertex(tile->indices[3 * t + e]);
          const float* b = vertex(tile->indices[3 * t + (e + 1) % 3]);
          ASSERT_LT(std::fabs(a[0] - b[0]), 1.5 * stride_km)
              << "tile " << level << "/" << key.x << "/" << key.y;
        }
        ++checked;
      }
      for (std::size_t i = 0; i < s.cols.size() * s.rows.size(); ++i) {
        const float* v = vertex(std::uint32_t(i));
        x_lo = std::min(x_lo, double(v[0]));
        x_hi = std::max(x_hi, double(v[0]));
        y_lo = std::min(y_lo, double(v[1]));
        y_hi = std::max(y_hi, double(v[1]));
      }
    }
  }
  EXPECT_GT(checked, 10000u);
  // The tiles cover the whole store, from pole to pole and from 0 to 357.5 E.
  EXPECT_LE(x_lo, domain.lo[0]);
  EXPECT_GE(x_hi, domain.hi[0]);
  EXPECT_LE(y_lo, domain.lo[1] + 1e-3);
  EXPECT_GE(y_hi, domain.hi[1] - 1e-3);
}

// On the globe, under a store whose longitudes go round the Earth, the terrain goes all
// the way round too: no strip is left out at the turn opposite the centre (on the plane
// placed longitudes jump there; on the globe nothing does), and no longitude is clipped.
TEST(TerrainTilesTest, GlobeUnderAStoreRoundTheEarthHasTerrainAtEveryLongitude) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "",
             lod::testing::linspace(0, 360, 73)};
  m.x.periodic = true;  // its last column is its first turned once round
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "",
             lod::testing::linspace(-90, 90, 37)};
  m.z = Axis{"height", AxisKind::kHeight, "m", "height", "", "up", lod::testing::linspace(0, 15000, 8)};
  m.time = TimeAxis{"time", "hours since 2024-06-21 00:00:00", "standard", {12}};
  m.brick = 16;
  const lod::WorldFrame frame(m, {.vertical_exaggeration = 20.0, .shape = lod::FrameShape::kGlobe});
  ASSERT_TRUE(frame.globe());
  auto dem = std::make_shared<FunctionDem>(361, 181, -180.0, 180.0, -90.0, 90.0, [](double lon, double lat) {
    return float(2000 + 1500 * std::sin(lon * 0.1) * std::cos(lat * 0.07));
  });
  view::TerrainOptions options;
  options.round_the_earth = true;
  options.cull = false;
  view::TerrainTiles tiles(dem, frame, options);
  ASSERT_EQ(tiles.wrap_columns(), 360u);
  const auto extent = tiles.extent();
  EXPECT_EQ(extent[2] - extent[0], 360u) << "a whole turn of columns";
  const auto shown = tiles.update(camera_at(frame, {0, 0, 40000}, {0, 0, 0}), 20.0, 720);
  ASSERT_TRUE(shown);
  // Every vertex's longitude, at the finest level (one DEM column apart).
  const int level = tiles.finest_level();
  std::vector<double> lons;
  for (const auto& [key, tile, s] : loaded_tiles(tiles, level)) {
    for (std::size_t i = 0; i < s.cols.size() * s.rows.size(); ++i) {
      const float* v = &tile->vertices[i * view::kTerrainVertexFloats];
      if (std::hypot(v[0], v[1]) < 1.0) continue;  // a pole: any longitude
      lons.push_back(std::round(std::atan2(v[1], v[0]) * 180.0 / std::numbers::pi * 1e4) / 1e4);
      EXPECT_GE(v[8], shown->clip.lo[0]);
      EXPECT_LE(v[8], shown->clip.hi[0]);
    }
  }
  std::sort(lons.begin(), lons.end());
  lons.erase(std::unique(lons.begin(), lons.end()), lons.end());
  ASSERT_GE(lons.size(), 360u);
  double widest = lons.front() + 360.0 - lons.back();  // across the turn
  for (std::size_t i = 1; i < lons.size(); ++i) widest = std::max(widest, lons[i] - lons[i - 1]);
  EXPECT_LE(widest, 1.0 + 1e-3) << "a gap between the terrain's columns";
}

TEST(TerrainTilesTest, DemOutsideTheStoreIsRefused) {
  const auto frame = store_frame();
  auto dem = std::make_shared<FunctionDem>(10, 10, 100, 110, 10, 20, [](double, double) { return 1.0f; });
  testing::expect_error([&] { view::TerrainTiles tiles(dem, frame); }, ErrorCode::kInvalidInput,
                        {"does not overlap"});
}

}  // namespace
}  // namespace strielad
