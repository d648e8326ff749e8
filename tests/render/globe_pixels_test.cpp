// SPDX-License-Identifier: Apache-2.0
// A global store seen on the globe (lod/world_frame.h FrameShape, view/globe_view.h): a
// round Earth on the background, lit by the true sun at the simulation time, the day side
// bright and the night side dim but readable (the built-in clouds shader's ambient light);
// a user shader's height_m() gives the height above the ellipsoid, and alpha() gets true
// (unexaggerated) kilometres; flight tracks drawn over the globe; clouds moved with the
// wind turn round the Earth at their height (a map of D degrees east everywhere draws
// them as the unmoved clouds seen from D degrees further west).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <vector>
#include <thread>

#include "render/complete_frame.h"
#include "render/headless_context.h"
#include "render/offscreen_target.h"
#include "render/png_file.h"
#include "render/volume_renderer.h"
#include "render/volume_shaders.h"
#include "support/function_dem.h"
#include "support/globe_store.h"
#include "support/temp_dir.h"
#include "view/displacement_map.h"
#include "view/globe_view.h"
#include "view/local_server.h"
#include "view/simulation_time.h"
#include "view/sun_direction.h"
#include "view/terrain_tiles.h"
#include "view/track_window.h"
#include "view/view_controller.h"
#include "view/view_link.h"

namespace strielad::testing {
namespace {

constexpr int kSize = 160;
constexpr double kExaggeration = 20.0;

// A sub-volume "height_km <= 2": a shell round the whole Earth, its top 2 km up.
Scene ground_scene() {
  Scene scene;
  SubVolume shell;
  shell.id = 1;
  shell.name = "ground";
  shell.limits.push_back(Limit{.var = "height_km", .min = std::nullopt, .max = 2.0});
  scene.subvolumes.push_back(shell);
  return scene;
}

class GlobePixelsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    // At 00 UTC on the June solstice the sun stands over 180 E, 23.4 N.
    store_ = new std::filesystem::path(
        write_globe_store(dir_->path(), "seconds since 2024-06-21 00:00:00"));
    context_ = render::HeadlessContext::create().release();
  }
  static void TearDownTestSuite() {
    delete context_;
    delete store_;
    delete dir_;
  }

  void SetUp() override {
    connection_ = view::open_local_store(*store_, view::LocalServerOptions{.threads = 2});
    link_ = std::make_unique<view::ViewLink>(
        std::move(connection_.client), view::HeightPlacement{}, nullptr,
        view::PlacerShape{.shape = lod::FrameShape::kAuto, .globe_exaggeration = kExaggeration});
    render::RenderSettings settings;
    settings.background_top = settings.background_bottom = {0, 0, 0};
    renderer_ = std::make_unique<render::VolumeRenderer>(settings);
    target_ = std::make_unique<render::OffscreenTarget>(kSize, kSize);
    const Scene scene = ground_scene();
    controller_ = std::make_unique<view::ViewController>(*link_, scene);
    EXPECT_TRUE(renderer_->set_scene_layout({1}, scene.attributes).ok);
    EXPECT_TRUE(renderer_->set_user_shader(render::default_user_shader(), "clouds.glsl").ok);
  }
  void TearDown() override {
    controller_.reset();
    link_.reset();
    connection_.server.reset();
  }

  render::CompleteFrame render(const lod::Camera& camera, const Vec3& sun,
                               std::vector<view::MeshMotion> motions = {}) {
    auto inputs = render::frame_inputs(*controller_, camera);
    inputs.sun_direction = sun;
    inputs.motions = std::move(motions);
    return render::render_complete_frame(*controller_, *renderer_, *target_, inputs);
  }

  static std::pair<int, int> project(const lod::Camera& cam, const Vec3& p) {
    const auto clip =
        lod::to_clip(lod::multiply(lod::projection_matrix(cam), lod::view_matrix(cam)), p);
    return {static_cast<int>((clip[0] / clip[3] + 1) / 2 * kSize),
            static_cast<int>((1 - clip[1] / clip[3]) / 2 * kSize)};
  }

  static int brightness(const render::RgbaImage& image, std::pair<int, int> px) {
    const auto p = image.at(px.first, px.second);
    return p[0] + p[1] + p[2];
  }

  static void save(const render::RgbaImage& image, const char* name) {
    if (const char* out = std::getenv("STRIELAD_TEST_IMAGES")) {
      render::write_png(std::filesystem::path(out) / name, image);
    }
  }

  static inline TempDir* dir_ = nullptr;
  static inline std::filesystem::path* store_ = nullptr;
  static inline render::HeadlessContext* context_ = nullptr;
  view::LocalConnection connection_;
  std::unique_ptr<view::ViewLink> link_;
  std::unique_ptr<view::ViewController> controller_;
  std::unique_ptr<render::VolumeRenderer> renderer_;
  std::unique_ptr<render::OffscreenTarget> target_;
};

TEST_F(GlobePixelsTest, AGlobalStoreOpensAsAGlobeWithItsExaggerationPlaced) {
  const lod::WorldFrame& frame = controller_->frame();
  ASSERT_TRUE(frame.globe());
  EXPECT_DOUBLE_EQ(frame.vertical_exaggeration(), kExaggeration);
  EXPECT_DOUBLE_EQ(controller_->renderer_vertical_scale(), 1.0);
  // The domain is the Earth and its 15 km x 20 atmosphere.
  EXPECT_NEAR(frame.domain().hi[0], 6378.137 + 300.0, 1.0);
  EXPECT_NEAR(frame.domain().lo[2], -(6356.752 + 300.0), 25.0);
  // Another exaggeration is drawn (the meshes keep theirs): the frame and its boxes go
  // with it, the renderer still scales nothing.
  controller_->set_vertical_exaggeration(50.0);
  EXPECT_DOUBLE_EQ(controller_->frame().vertical_exaggeration(), 50.0);
  EXPECT_NEAR(controller_->frame().domain().hi[0], 6378.137 + 750.0, 1.0);
  EXPECT_DOUBLE_EQ(controller_->renderer_vertical_scale(), 1.0);
  EXPECT_DOUBLE_EQ(link_->placer().placed_exaggeration(), kExaggeration);
  const auto inputs = render::frame_inputs(*controller_, lod::Camera{});
  EXPECT_DOUBLE_EQ(inputs.globe_exaggeration, 50.0);
  EXPECT_DOUBLE_EQ(inputs.globe_placed_exaggeration, kExaggeration);
}

TEST_F(GlobePixelsTest, TheSunLightsTheDaySideAndTheNightSideStaysReadable) {
  const lod::WorldFrame& frame = controller_->frame();
  const auto sun = view::sun_at_step(frame, link_->manifest(), 0);
  ASSERT_TRUE(sun);
  const auto jd = view::step_sun_julian_day(link_->manifest(), 0);
  ASSERT_TRUE(jd);
  const auto [lon_s, lat_s] = view::subsolar_point(*jd);
  EXPECT_NEAR(std::fabs(lon_s), 180.0, 2.0);
  EXPECT_NEAR(lat_s, 23.44, 0.1);
  // Seen over the evening terminator, 90 degrees west of the sub-solar point.
  view::OrbitCamera orbit(frame.domain());
  orbit.set_globe(lon_s - 90.0, 0.0);
  const lod::Camera cam = orbit.camera(1.0);
  const auto image = render(cam, sun->direction).image;
  save(image, "globe_terminator.png");
  for (const auto& corner : {std::pair{1, 1}, std::pair{kSize - 2, 1}, std::pair{1, kSize - 2},
                            std::pair{kSize - 2, kSize - 2}}) {
    EXPECT_LT(brightness(image, corner), 10) << "corner " << corner.first << "," << corner.second;
  }
  const double top = 2.0 * kExaggeration;  // the shell's top, km
  const auto day = project(cam, frame.place_geographic(lon_s - 45.0, 0.0, top));
  const auto night = project(cam, frame.place_geographic(lon_s - 135.0, 0.0, top));
  const int lit = brightness(image, day), dark = brightness(image, night);
  // The built-in shader's light is 0.35 + 0.55 cos(sun) + 0.10 cos(view): at 45 degrees
  // from the sub-solar point about 0.8, on the night side at most 0.45.
  EXPECT_GT(lit, 1.5 * dark) << "day " << lit << ", night " << dark;
  EXPECT_GT(dark, 60) << "the night side is black";
  // The disk's centre, on the terminator, is drawn.
  EXPECT_GT(brightness(image, project(cam, frame.place_geographic(lon_s - 90.0, 0.0, top))), 10);
}

TEST_F(GlobePixelsTest, HomeLooksDownOnTheDaySide) {
  const lod::WorldFrame& frame = controller_->frame();
  const auto sun = view::sun_at_step(frame, link_->manifest(), 0);
  ASSERT_TRUE(sun);
  const lod::Camera cam = view::home_orbit_camera(frame, link_->manifest(), 0).camera(1.0);
  const auto image = render(cam, sun->direction).image;
  save(image, "globe_home.png");
  const int centre = brightness(image, {kSize / 2, kSize / 2});
  EXPECT_GT(centre, 400) << "the sub-solar point is not lit";
  EXPECT_LT(brightness(image, {1, 1}), 10);
}

// A global DEM (0.5 degrees, -180..180 E: it goes round) drapes the globe: the terrain
// is drawn round the Earth, lit on the day side, dim on the night side.
TEST_F(GlobePixelsTest, TerrainDrapesTheGlobeLitByTheSun) {
  Scene empty;  // cloud water nowhere this dense: nothing but the terrain
  SubVolume none;
  none.id = 1;
  none.name = "none";
  none.limits.push_back(Limit{.var = "clw", .min = 1.0, .max = std::nullopt});
  empty.subvolumes.push_back(none);
  controller_->set_scene(empty);
  const lod::WorldFrame& frame = controller_->frame();
  auto dem = std::make_shared<FunctionDem>(721, 361, -180.0, 180.0, -90.0, 90.0,
                                           [](double lon, double lat) {
    return float(1200.0 + 900.0 * std::sin(lon * 0.1) * std::cos(lat * 0.07));
  });
  view::TerrainTiles tiles(dem, frame);
  EXPECT_GT(tiles.wrap_columns(), 0u);
  const auto sun = view::sun_at_step(frame, link_->manifest(), 0);
  ASSERT_TRUE(sun);
  const auto [lon_s, lat_s] = view::subsolar_point(*view::step_sun_julian_day(link_->manifest(), 0));
  view::OrbitCamera orbit(frame.domain());
  orbit.set_globe(lon_s - 90.0, 0.0);
  const lod::Camera cam = orbit.camera(1.0);
  auto inputs = render::frame_inputs(*controller_, cam);
  inputs.sun_direction = sun->direction;
  std::shared_ptr<const view::TerrainFrame> terrain;
  for (int i = 0; i < 20000; ++i) {
    terrain = tiles.update(cam, controller_->options().vertical_exaggeration, kSize);
    if (tiles.complete()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(tiles.complete());
  EXPECT_TRUE(terrain->globe);
  inputs.terrain = terrain;
  const auto image = render::render_complete_frame(*controller_, *renderer_, *target_, inputs).image;
  save(image, "globe_terrain.png");
  EXPECT_LT(brightness(image, {1, 1}), 10);
  const double top = 1.2 * kExaggeration;
  const int lit = brightness(image, project(cam, frame.place_geographic(lon_s - 45.0, 0.0, top)));
  const int dark = brightness(image, project(cam, frame.place_geographic(lon_s - 135.0, 0.0, top)));
  EXPECT_GT(lit, 2 * dark) << "day " << lit << ", night " << dark;
  EXPECT_GT(dark, 40) << "the night side is black";
}

// A sub-volume "4 km <= height_km <= 6 km": a shell round the Earth.
Scene band_scene() {
  Scene scene;
  SubVolume band;
  band.id = 1;
  band.name = "band";
  band.limits.push_back(Limit{.var = "height_km", .min = 4.0, .max = 6.0});
  scene.subvolumes.push_back(band);
  return scene;
}

// Colours by height_m(): red between 1.8 and 2.2 km, green between 5.8 and 6.2 km, blue
// elsewhere; opaque or with an opacity from the true distance.
std::string height_band_shader(const std::string& alpha_body) {
  return R"(vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,
                       vec3 position, vec3 view, float time) {
  float h = height_m(position);
  if (h > 1800.0 && h < 2200.0) return vec4(1.0, 0.0, 0.0, 1.0);
  if (h > 5800.0 && h < 6200.0) return vec4(0.0, 1.0, 0.0, 1.0);
  return vec4(0.0, 0.0, 1.0, 1.0);
}
float alpha(int id, float distance) { )" + alpha_body + " }\n";
}

TEST_F(GlobePixelsTest, HeightMGivesTheHeightAboveTheEllipsoid) {
  ASSERT_TRUE(renderer_->set_user_shader(height_band_shader("return 1.0;"), "bands.glsl").ok);
  const lod::WorldFrame& frame = controller_->frame();
  const Vec3 sun{1, 0, 0};
  // Over the equator, mid-latitudes and near the pole, the ground shell (top 2 km) is red
  // and the band (top 6 km) green where the camera looks straight down on a grid column
  // of every fourth row and column (a vertex of the coarser levels' meshes too). Between
  // columns the meshes' flat triangles lie under the sphere (on the 7.5-degree grid up to
  // 14 km drawn, 0.7 km true; twice and four times that on the coarser levels), and
  // height_m() says so.
  for (const auto& [lon, lat] : {std::pair{120.0, 0.0}, std::pair{-60.0, 30.0}, std::pair{0.0, 60.0}}) {
    view::OrbitCamera orbit(frame.domain());
    orbit.set_globe(lon, lat);
    const lod::Camera cam = orbit.camera(1.0);
    controller_->set_scene(ground_scene());
    const auto column = project(cam, frame.place_geographic(lon, lat, 2.0 * kExaggeration));
    auto image = render(cam, sun).image;
    auto p = image.at(column.first, column.second);
    EXPECT_GT(p[0], 200) << lon << " E " << lat << " N: the 2 km top is not red";
    EXPECT_LT(p[1] + p[2], 40) << lon << " E " << lat << " N";
    controller_->set_scene(band_scene());
    image = render(cam, sun).image;
    if (lat == 30.0) save(image, "globe_height_band.png");
    p = image.at(column.first, column.second);
    EXPECT_GT(p[1], 200) << lon << " E " << lat << " N: the 6 km top is not green";
    EXPECT_LT(p[0] + p[2], 40) << lon << " E " << lat << " N";
  }
}

TEST_F(GlobePixelsTest, AlphaCountsTrueKilometres) {
  // Straight down through the band: 2 true km (40 drawn) on the near side, entered at
  // 6 km (green), and again on the far side of the Earth (nothing opaque between),
  // entered at 4 km (blue). At distance / 8 each segment is a quarter opaque: green 0.25,
  // blue 0.75 * 0.25 over black; drawn kilometres would make the near side opaque.
  ASSERT_TRUE(renderer_->set_user_shader(height_band_shader("return distance / 8.0;"),
                                         "bands.glsl").ok);
  controller_->set_scene(band_scene());
  const lod::WorldFrame& frame = controller_->frame();
  view::OrbitCamera orbit(frame.domain());
  orbit.set_globe(-30.0, 30.0);
  const auto image = render(orbit.camera(1.0), {1, 0, 0}).image;
  const auto p = image.at(kSize / 2, kSize / 2);
  EXPECT_NEAR(p[1], 0.25 * 255, 10) << "green " << int(p[1]);
  EXPECT_NEAR(p[2], 0.1875 * 255, 10) << "blue " << int(p[2]);
}

// A flight along the equator from 30 W to 30 E, 11 km up, seen from over 0 E: its line
// runs through the picture's centre row where the track window places it, and the
// aircraft's point is at its position at the time shown.
TEST_F(GlobePixelsTest, FlightTracksLieWhereTheyArePlaced) {
  Scene none;
  SubVolume nothing;
  nothing.id = 1;
  nothing.name = "none";
  nothing.limits.push_back(Limit{.var = "clw", .min = 1.0, .max = std::nullopt});
  none.subvolumes.push_back(nothing);
  controller_->set_scene(none);
  const lod::WorldFrame& frame = controller_->frame();
  geo::FlightTracks tracks;
  geo::FlightTrack t;
  t.id = "EQ";
  t.seconds = {0, 7200};
  t.lon = {-30, 30};
  t.lat = {0, 0};
  t.altitude_m = {11000, 11000};
  tracks.tracks.push_back(t);
  // At 5400 s the aircraft is at 15 E; the last 90 minutes from 30 W are drawn.
  auto lines = std::make_shared<view::TrackLines>(view::window_tracks(tracks, 5400, 5400, frame));
  ASSERT_EQ(lines->head_count(), 1u);
  view::OrbitCamera orbit(frame.domain());
  orbit.set_globe(0.0, 0.0);
  const lod::Camera cam = orbit.camera(1.0);
  auto inputs = render::frame_inputs(*controller_, cam);
  inputs.tracks = lines;
  const auto image = render::render_complete_frame(*controller_, *renderer_, *target_, inputs).image;
  save(image, "globe_track.png");
  const auto is_track = [&](std::pair<int, int> px) {
    const auto p = image.at(px.first, px.second);
    return p[0] > 150 && p[1] > 80 && p[1] < 170 && p[2] < 60;
  };
  const double up = 11.0 * kExaggeration;
  EXPECT_TRUE(is_track(project(cam, frame.place_geographic(15.0, 0.0, up)))) << "the aircraft";
  for (const double lon : {-25.0, -10.0, 0.0, 10.0}) {
    EXPECT_TRUE(is_track(project(cam, frame.place_geographic(lon, 0.0, up)))) << lon << " E";
    EXPECT_FALSE(is_track(project(cam, frame.place_geographic(lon, 6.0, up)))) << lon << " E 6 N";
  }
  // Not drawn yet: east of the aircraft.
  EXPECT_FALSE(is_track(project(cam, frame.place_geographic(25.0, 0.0, up))));
}

}  // namespace
}  // namespace strielad::testing

namespace strielad::testing {
namespace {

// A globe displacement map (view/displacement_map.h) that turns everything `east_deg`
// degrees east about the polar axis by the end of its 600 s: east part D cos(lat) at
// every latitude (the map stores dlon cos(lat0)), nothing north or up.
std::shared_ptr<const view::DisplacementMap> turning_map(double east_deg) {
  auto map = std::make_shared<view::DisplacementMap>();
  map->step = 0;
  map->seconds = 600;
  map->globe = true;
  map->periodic = true;
  map->box.lo = {-180.0, -90.0, 0.0};
  map->box.hi = {180.0, 90.0, 15.0};
  map->lattice = {2, 181, 2};
  map->keyframes = 2;
  map->displacement.assign(map->points() * 3 * map->keyframes, 0.0f);
  for (std::size_t z = 0; z < 2; ++z) {
    for (std::size_t y = 0; y < 181; ++y) {
      for (std::size_t x = 0; x < 2; ++x) {
        const std::size_t point = (z * 181 + y) * 2 + x;
        const double lat = -90.0 + static_cast<double>(y);
        map->displacement[(map->points() + point) * 3] =
            static_cast<float>(east_deg * std::cos(lat * std::numbers::pi / 180.0));
      }
    }
  }
  return map;
}

Vec3 turned_east(const Vec3& v, double deg) {
  const double a = deg * std::numbers::pi / 180.0;
  return {v[0] * std::cos(a) - v[1] * std::sin(a), v[0] * std::sin(a) + v[1] * std::cos(a), v[2]};
}

// Pixels whose colour differs by more than a little.
int differing_pixels(const render::RgbaImage& a, const render::RgbaImage& b) {
  int n = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const auto p = a.at(x, y), q = b.at(x, y);
      n += std::abs(int(p[0]) - int(q[0])) + std::abs(int(p[1]) - int(q[1])) +
                       std::abs(int(p[2]) - int(q[2])) > 24 ? 1 : 0;
    }
  }
  return n;
}

// The mean column of the pixels where `clouds` differs from `bare` (the same view without
// clouds).
double cloud_column(const render::RgbaImage& clouds, const render::RgbaImage& bare, int* count) {
  double sum = 0;
  *count = 0;
  for (int y = 0; y < clouds.height; ++y) {
    for (int x = 0; x < clouds.width; ++x) {
      const auto p = clouds.at(x, y), q = bare.at(x, y);
      if (std::abs(int(p[0]) - int(q[0])) + std::abs(int(p[1]) - int(q[1])) +
              std::abs(int(p[2]) - int(q[2])) > 24) {
        sum += x;
        ++*count;
      }
    }
  }
  return *count > 0 ? sum / *count : 0;
}

TEST_F(GlobePixelsTest, CloudsMovedEastTurnRoundTheEarthAtTheirHeight) {
  // The ground shell (turning it changes nothing) hides the clouds on the far side.
  Scene clouds = ground_scene();
  SubVolume clw;
  clw.id = 2;
  clw.name = "cloud water";
  clw.limits.push_back(Limit{.var = "clw", .min = 2e-5, .max = std::nullopt});
  clouds.subvolumes.push_back(clw);
  ASSERT_TRUE(renderer_->set_scene_layout({1, 2}, clouds.attributes).ok);
  controller_->set_scene(clouds);
  const lod::WorldFrame& frame = controller_->frame();
  const auto sun = view::sun_at_step(frame, link_->manifest(), 0);
  ASSERT_TRUE(sun);
  constexpr double kEastDeg = 12.0;
  constexpr double kLon = -40.0;
  const auto map = turning_map(kEastDeg);
  const auto camera_over = [&](double lon) {
    view::OrbitCamera orbit(frame.domain());
    orbit.set_globe(lon, 10.0);
    return orbit.camera(1.0);
  };
  const lod::Camera cam = camera_over(kLon);
  const auto still = render(cam, sun->direction);
  const auto at_zero = render(cam, sun->direction, {{map, 0.0}});
  const auto moved = render(cam, sun->direction, {{map, 600.0}});
  EXPECT_EQ(moved.stats.nodes_moved, moved.stats.nodes_drawn);
  EXPECT_GT(moved.stats.nodes_moved, 0u);
  // The unmoved clouds seen from kEastDeg further west, the sun turned with the view.
  const auto reference =
      render(camera_over(kLon - kEastDeg), turned_east(sun->direction, -kEastDeg));
  save(still.image, "globe_advect_still.png");
  save(moved.image, "globe_advect_moved.png");
  save(reference.image, "globe_advect_reference.png");
  // Clouds alone: the same views with a scene of no clouds.
  Scene none = clouds;
  none.subvolumes[1].limits[0].min = 1.0;
  controller_->set_scene(none);
  const auto bare = render(cam, sun->direction);
  const auto bare_reference =
      render(camera_over(kLon - kEastDeg), turned_east(sun->direction, -kEastDeg));
  int still_count = 0, moved_count = 0, reference_count = 0;
  const double still_column = cloud_column(still.image, bare.image, &still_count);
  const double moved_column = cloud_column(moved.image, bare.image, &moved_count);
  const double reference_column =
      cloud_column(reference.image, bare_reference.image, &reference_count);
  ASSERT_GT(still_count, 300);
  // Not moved at time 0.
  EXPECT_LT(differing_pixels(still.image, at_zero.image), 0.002 * kSize * kSize);
  // Moved east (the right of a north-up view; less than the centre's shift as clouds
  // near the limb foreshorten) by what turning the view shows.
  const double centre_shift = project(cam, frame.place_geographic(kLon + kEastDeg, 10.0, 100.0)).first -
                              project(cam, frame.place_geographic(kLon, 10.0, 100.0)).first;
  EXPECT_GT(centre_shift, 5);
  EXPECT_GT(moved_column - still_column, 1.0);
  EXPECT_NEAR(moved_column, reference_column, 0.75);
  EXPECT_NEAR(moved_count, reference_count, 0.03 * reference_count);
  const int moved_vs_reference = differing_pixels(moved.image, reference.image);
  const int moved_vs_still = differing_pixels(moved.image, still.image);
  EXPECT_LT(moved_vs_reference, 0.1 * moved_vs_still)
      << moved_vs_reference << " pixels differ from the turned view, " << moved_vs_still
      << " from the unmoved one";
}

// The panel's exaggeration on the globe: a store opened at 20 and drawn at 100 gives
// the picture of the store opened at 100: the ground shell (top 2 km), a slice along
// 12 E and terrain, seen obliquely from 2000 km over the equator towards the limb, where
// heights show. Drawn at 20 the picture differs.
TEST_F(GlobePixelsTest, ExaggerationChangedOnTheGlobeDrawsWhatAStoreOpenedAtItDraws) {
  constexpr double kDrawn = 100.0;
  Scene scene = ground_scene();
  Slice slice;
  slice.id = 1;
  slice.name = "12 E";
  slice.axis = "lon";
  slice.value = 12.0;
  slice.var = "clw";
  slice.range = AxisRange{0.0, 1e-4};
  scene.slices.push_back(slice);
  auto dem = std::make_shared<FunctionDem>(721, 361, -180.0, 180.0, -90.0, 90.0,
                                           [](double lon, double lat) {
    return float(1200.0 + 900.0 * std::sin(lon * 0.3) * std::cos(lat * 0.2));
  });
  const Vec3 sun{1, 0.3, 0.2};
  // One picture of `controller` (its link placed at its own exaggeration) drawn at
  // `drawn`, with terrain placed as the link's meshes are.
  const auto picture = [&](view::ViewController& controller, double drawn) {
    controller.set_scene(scene);
    controller.set_vertical_exaggeration(drawn);
    const lod::WorldFrame& frame = controller.frame();
    const Vec3 eye = frame.place_geographic(0.0, 0.0, 2000.0);
    const Vec3 target = frame.place_geographic(25.0, 0.0, 0.0);
    const lod::Camera cam = lod::look_at(eye, target, 45.0, 1.0, frame.domain());
    // The finest tiles everywhere: the same terrain whatever boxes choose the levels.
    view::TerrainTiles tiles(dem, controller.link().placer().frame(),
                             view::TerrainOptions{.error_pixels = 1e-3});
    auto inputs = render::frame_inputs(controller, cam);
    inputs.sun_direction = sun;
    for (int i = 0; i < 20000; ++i) {
      inputs.terrain = tiles.update(cam, drawn, kSize);
      if (tiles.complete()) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_TRUE(tiles.complete());
    EXPECT_NEAR(inputs.terrain->globe_ratio, drawn / controller.link().placer().placed_exaggeration(), 1e-12);
    return render::render_complete_frame(controller, *renderer_, *target_, inputs).image;
  };
  const auto redrawn = picture(*controller_, kDrawn);
  const auto as_placed = picture(*controller_, kExaggeration);
  // The store opened at kDrawn.
  auto connection = view::open_local_store(*store_, view::LocalServerOptions{.threads = 2});
  view::ViewLink link(std::move(connection.client), view::HeightPlacement{}, nullptr,
                      view::PlacerShape{.shape = lod::FrameShape::kAuto, .globe_exaggeration = kDrawn});
  view::ViewController opened(link, scene);
  const auto reference = picture(opened, kDrawn);
  save(redrawn, "globe_exaggeration_redrawn.png");
  save(reference, "globe_exaggeration_opened.png");
  save(as_placed, "globe_exaggeration_placed.png");
  const int off = differing_pixels(redrawn, reference);
  const int changed = differing_pixels(as_placed, reference);
  EXPECT_GT(changed, 0.05 * kSize * kSize) << "the exaggeration changes too little to test";
  EXPECT_LT(off, 0.05 * changed) << off << " pixels differ from the store opened at " << kDrawn
                                 << ", " << changed << " between the two exaggerations";
}

// height_m() takes out the exaggeration drawn: after the panel's change from 20 to 60 the
// ground shell's top is still 2 km (red; 6 km, green, had the placed one been taken out,
// and under 1 km, blue, had the vertices not moved).
TEST_F(GlobePixelsTest, HeightMTakesOutTheExaggerationDrawn) {
  ASSERT_TRUE(renderer_->set_user_shader(height_band_shader("return 1.0;"), "bands.glsl").ok);
  controller_->set_vertical_exaggeration(60.0);
  const lod::WorldFrame& frame = controller_->frame();
  view::OrbitCamera orbit(frame.domain());
  orbit.set_globe(120.0, 0.0);
  const lod::Camera cam = orbit.camera(1.0);
  const auto column = project(cam, frame.place_geographic(120.0, 0.0, 2.0 * 60.0));
  const auto image = render(cam, {1, 0, 0}).image;
  const auto p = image.at(column.first, column.second);
  EXPECT_GT(p[0], 200) << "the 2 km top is not red: " << int(p[0]) << " " << int(p[1]) << " "
                       << int(p[2]);
  EXPECT_LT(p[1] + p[2], 40);
}

}  // namespace
}  // namespace strielad::testing
