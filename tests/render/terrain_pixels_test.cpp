// SPDX-License-Identifier: Apache-2.0
// Terrain in the renderer's opaque pass, checked by pixels: a mountain lit from the east
// is brighter on its east slope; a solid-colour drape image colours the terrain (unless
// the frame turns drapes off, as the viewer's panel does); terrain
// in front of a sub-volume hides it; the sea of a DEM with bathymetry is water, not
// lowland; where the DEM ends with the store, nothing hangs below its edge.
#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "scenery/drape_image.h"
#include "render/headless_context.h"
#include "render/offscreen_target.h"
#include "render/render_fixture.h"
#include "render/volume_renderer.h"
#include "support/function_dem.h"
#include "view/terrain_tiles.h"

namespace strielad {
namespace {

using testing::FunctionDem;

std::shared_ptr<const view::TerrainFrame> settle(view::TerrainTiles& t, const lod::Camera& cam,
                                                 double exaggeration, int height) {
  std::shared_ptr<const view::TerrainFrame> frame;
  for (int i = 0; i < 20000; ++i) {
    frame = t.update(cam, exaggeration, height);
    if (t.complete()) return frame;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ADD_FAILURE() << "terrain never complete";
  return frame;
}

struct Pixel {
  int r, g, b;
  int brightness() const { return r + g + b; }
};
Pixel at(const std::vector<std::uint8_t>& rgba, int size, int x, int y) {
  const std::size_t i = (std::size_t(y) * size + x) * 4;
  return {rgba[i], rgba[i + 1], rgba[i + 2]};
}

class TerrainPixelsTest : public testing::RenderTest {};

// The sphere store's frame: lon 0..1, lat -0.5..0.5, a 111 km cube at exaggeration 10.
TEST_F(TerrainPixelsTest, EastSlopeLitFromTheEastIsBrighter) {
  Scene scene;  // a sphere too small to show: nothing but the terrain
  scene.subvolumes.push_back(testing::sphere(1, "d1", 0.001));
  controller_ = std::make_unique<view::ViewController>(*link_, scene);
  auto dem = std::make_shared<FunctionDem>(129, 129, 0.0, 1.0, -0.5, 0.5, [](double lon, double lat) {
    const double dx = (lon - 0.5) * 111.0, dy = lat * 111.0;  // km from the centre
    return float(4000.0 * std::exp(-(dx * dx + dy * dy) / (2 * 15.0 * 15.0)));
  });
  view::TerrainTiles tiles(dem, controller_->frame());
  const auto cam = lod::look_at({0, 0, 400}, {0, 0, 0}, 45.0, 1.0, controller_->frame().domain());
  auto inputs = render::frame_inputs(*controller_, cam);
  inputs.sun_direction = {1.0, 0.0, 0.4};  // low in the east
  inputs.terrain = settle(tiles, cam, inputs.vertical_exaggeration, kSize);
  const auto stats = renderer_->render(inputs, target_->framebuffer(), kSize, kSize);
  EXPECT_GT(stats.terrain_tiles, 0u);
  EXPECT_GT(stats.terrain_triangles, 8000u);
  const auto rgba = render::VolumeRenderer::read_pixels(target_->framebuffer(), kSize, kSize);
  const auto east = project(cam, {8, 0, 0}), west = project(cam, {-8, 0, 0});
  const Pixel e = at(rgba, kSize, east.first, east.second), w = at(rgba, kSize, west.first, west.second);
  EXPECT_GT(e.brightness(), w.brightness() + 60) << "east " << e.brightness() << ", west " << w.brightness();
}

std::filesystem::path write_solid_image(const std::filesystem::path& path) {
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 16, 16, 3, GDT_Byte, nullptr);
  double t[6] = {-0.2, 1.4 / 16, 0, 0.7, 0, -1.4 / 16};  // covers the domain with a margin
  GDALSetGeoTransform(ds, t);
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 4326);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  GDALSetProjection(ds, wkt);
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  const std::uint8_t rgb[3] = {200, 40, 220};
  for (int b = 0; b < 3; ++b) {
    std::vector<std::uint8_t> v(256, rgb[b]);
    EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, b + 1), GF_Write, 0, 0, 16, 16, v.data(), 16, 16,
                           GDT_Byte, 0, 0),
              CE_None);
  }
  GDALClose(ds);
  return path;
}

TEST_F(TerrainPixelsTest, SolidDrapeColoursTheTerrain) {
  Scene scene;
  scene.subvolumes.push_back(testing::sphere(1, "d1", 0.001));
  controller_ = std::make_unique<view::ViewController>(*link_, scene);
  auto dem = std::make_shared<FunctionDem>(65, 65, 0.0, 1.0, -0.5, 0.5, [](double, double) { return 100.0f; });
  auto drape = std::make_shared<const geo::DrapeImage>(write_solid_image(dir_->path() / "solid.tif"));
  view::TerrainTiles tiles(dem, controller_->frame(), {}, drape);
  const auto cam = lod::look_at({0, 0.01, 300}, {0, 0, 0}, 45.0, 1.0, controller_->frame().domain());
  auto inputs = render::frame_inputs(*controller_, cam);
  inputs.sun_direction = {0, 0, 1};  // overhead: flat ground fully lit
  inputs.terrain = settle(tiles, cam, inputs.vertical_exaggeration, kSize);
  renderer_->render(inputs, target_->framebuffer(), kSize, kSize);
  const auto rgba = render::VolumeRenderer::read_pixels(target_->framebuffer(), kSize, kSize);
  const Pixel p = at(rgba, kSize, kSize / 2, kSize / 2);
  EXPECT_NEAR(p.r, 200, 4);
  EXPECT_NEAR(p.g, 40, 4);
  EXPECT_NEAR(p.b, 220, 4);
  // Drapes off: the ground's own colours.
  inputs.terrain_drape = false;
  renderer_->render(inputs, target_->framebuffer(), kSize, kSize);
  const Pixel off = at(render::VolumeRenderer::read_pixels(target_->framebuffer(), kSize, kSize),
                       kSize, kSize / 2, kSize / 2);
  EXPECT_GT(std::abs(off.r - 200) + std::abs(off.g - 40) + std::abs(off.b - 220), 100)
      << off.r << " " << off.g << " " << off.b;
}

TEST_F(TerrainPixelsTest, TerrainInFrontHidesASubVolume) {
  Scene scene;
  scene.subvolumes.push_back(testing::sphere(1, "d1", 15.0));
  const Vec3 eye{-20, -140, 55}, target{-20, 0, 55};
  // Without terrain the sphere shows red at the centre of the image.
  const auto plain = render(scene, eye, target, testing::flat_shader("return 1.0;"));
  const Pixel before = at(plain.image.pixels, kSize, kSize / 2, kSize / 2);
  EXPECT_GT(before.r, 200);
  // A ridge 8 km high (80 km at exaggeration 10) across the view at y = -40 km.
  auto dem = std::make_shared<FunctionDem>(129, 129, 0.0, 1.0, -0.5, 0.5, [](double, double lat) {
    return std::fabs(lat * 111.0 + 40.0) < 8.0 ? 8000.0f : 0.0f;
  });
  view::TerrainTiles tiles(dem, controller_->frame());
  const auto cam = camera(eye, target);
  auto inputs = render::frame_inputs(*controller_, cam);
  inputs.terrain = settle(tiles, cam, inputs.vertical_exaggeration, kSize);
  const auto frame = render::render_complete_frame(*controller_, *renderer_, *target_, inputs);
  const Pixel after = at(frame.image.pixels, kSize, kSize / 2, kSize / 2);
  EXPECT_GT(frame.stats.terrain_tiles, 0u);
  EXPECT_FALSE(after.r > 200 && after.g < 50 && after.b < 50)
      << "still red: " << after.r << "," << after.g << "," << after.b;
}

// An ETOPO-style DEM: 4 km deep sea west of 0.5 E, land 500 m high east of it.
TEST_F(TerrainPixelsTest, SeaIsDrawnAsWaterNotLowland) {
  Scene scene;
  scene.subvolumes.push_back(testing::sphere(1, "d1", 0.001));
  controller_ = std::make_unique<view::ViewController>(*link_, scene);
  auto dem = std::make_shared<FunctionDem>(129, 129, 0.0, 1.0, -0.5, 0.5, [](double lon, double) {
    return lon < 0.5 ? -4000.0f : 500.0f;
  });
  view::TerrainTiles tiles(dem, controller_->frame());
  const auto cam = lod::look_at({0, 0.01, 300}, {0, 0, 0}, 45.0, 1.0, controller_->frame().domain());
  auto inputs = render::frame_inputs(*controller_, cam);
  inputs.sun_direction = {0, 0, 1};
  inputs.terrain = settle(tiles, cam, inputs.vertical_exaggeration, kSize);
  renderer_->render(inputs, target_->framebuffer(), kSize, kSize);
  const auto rgba = render::VolumeRenderer::read_pixels(target_->framebuffer(), kSize, kSize);
  const auto sea_px = project(cam, {-30, 0, 0}), land_px = project(cam, {30, 0, 5});
  const Pixel sea = at(rgba, kSize, sea_px.first, sea_px.second);
  const Pixel land = at(rgba, kSize, land_px.first, land_px.second);
  EXPECT_GT(sea.b, sea.g + 30) << "sea " << sea.r << "," << sea.g << "," << sea.b;
  EXPECT_GT(sea.b, sea.r + 60);
  EXPECT_GT(land.g, land.b + 30) << "land " << land.r << "," << land.g << "," << land.b;
}

// The DEM ends where the store does (as a global DEM at the poles under a global store):
// seen from above the edge, what lies just below it is the background, not a curtain
// hanging from the edge.
TEST_F(TerrainPixelsTest, NothingHangsBelowTheEdgeWhereTheDemEnds) {
  Scene scene;
  scene.subvolumes.push_back(testing::sphere(1, "d1", 0.001));
  controller_ = std::make_unique<view::ViewController>(*link_, scene);
  // 8 km high at the store's southern edge, 1 km at its northern one; one tile, whose
  // edges are all the extent's.
  auto dem = std::make_shared<FunctionDem>(65, 65, 0.0, 1.0, -0.5, 0.5, [](double, double lat) {
    return float(1000.0 + 7000.0 * (0.5 - lat));
  });
  view::TerrainTiles tiles(dem, controller_->frame());
  const double edge_y = controller_->frame().domain().lo[1];
  // From the south, looking down more steeply than the ground falls away northwards.
  const auto cam = lod::look_at({0, -160, 200}, {0, -40, 60}, 45.0, 1.0,
                                controller_->frame().domain());
  auto inputs = render::frame_inputs(*controller_, cam);
  inputs.terrain = settle(tiles, cam, inputs.vertical_exaggeration, kSize);
  renderer_->render(inputs, target_->framebuffer(), kSize, kSize);
  const auto rgba = render::VolumeRenderer::read_pixels(target_->framebuffer(), kSize, kSize);
  const auto inside = project(cam, {0, edge_y + 20, 67});  // on the ground
  EXPECT_GT(at(rgba, kSize, inside.first, inside.second).brightness(), 60);
  // Under the edge (80 km up at exaggeration 10) down to 20 km, across the middle half.
  const int edge_row = project(cam, {0, edge_y, 80}).second, low_row = project(cam, {0, edge_y, 20}).second;
  ASSERT_GT(low_row, edge_row + 10);
  int lit = 0, pixels = 0;
  for (int y = edge_row + 2; y < low_row; ++y) {
    for (int x = kSize / 4; x < 3 * kSize / 4; ++x, ++pixels) lit += at(rgba, kSize, x, y).brightness() > 0;
  }
  EXPECT_EQ(lit, 0) << "of " << pixels << " pixels under the edge";
}

}  // namespace
}  // namespace strielad
