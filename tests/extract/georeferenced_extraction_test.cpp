// SPDX-License-Identifier: Apache-2.0
// Extraction on georeferenced grids: longitude ranges in any convention on a periodic
// global grid (continuous across the seam, closed, the right volume), geographic boxes on
// a rotated-pole grid (closed, where PROJ says the box is, the area a quadrature of the
// box gives), and output frames through the grid mapping (ECEF where PROJ's cartesian
// conversion puts the true positions).
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "extract/node_extractor.h"
#include "extract/output_frame.h"
#include "geo/grid_projection.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::NcAttr;
using testing::NetcdfFixture;
using testing::ramp;

// A smooth field: warm blobs on the globe.
double field(double lon, double lat, double level) {
  const double r = std::cos(lat * M_PI / 180) * std::cos((lon - 10) * M_PI / 90);
  return 280 + 20 * r - 0.02 * (1000 - level);
}

class GeoreferencedExtractionTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    // A global grid 0 .. 357.5 E (periodic), 20 S .. 20 N, 5 pressure levels.
    const std::vector<double> lon = ramp(144, 0, 2.5), lat = ramp(17, -20, 2.5),
                              lev = {1000, 900, 800, 700, 600};
    std::vector<double> t;
    for (double p : lev)
      for (double y : lat)
        for (double x : lon) t.push_back(field(x, y, p));
    NetcdfFixture()
        .coordinate("lev", lev, {NcAttr::text_value("units", "hPa")})
        .coordinate("lat", lat, {NcAttr::text_value("units", "degrees_north")})
        .coordinate("lon", lon, {NcAttr::text_value("units", "degrees_east")})
        .variable("t", NC_FLOAT, {"lev", "lat", "lon"}, t, {NcAttr::text_value("units", "K")})
        .write(*dir_ / "global.nc");
    convert(*dir_ / "global.nc", *dir_ / "global.store");

    // A rotated-pole grid (the EURO-CORDEX pole) with 4 height levels.
    const std::vector<double> rlon = ramp(41, -20, 1), rlat = ramp(31, -15, 1),
                              height = {0, 1000, 2000, 3000};
    std::vector<double> v;
    for (double h : height)
      for (double y : rlat)
        for (double x : rlon) v.push_back(std::sin(0.2 * x) * std::cos(0.15 * y) + 1e-4 * h);
    NetcdfFixture()
        .coordinate("height", height, {NcAttr::text_value("units", "m"), NcAttr::text_value("positive", "up")})
        .coordinate("rlat", rlat, {NcAttr::text_value("standard_name", "grid_latitude"),
                                   NcAttr::text_value("units", "degrees")})
        .coordinate("rlon", rlon, {NcAttr::text_value("standard_name", "grid_longitude"),
                                   NcAttr::text_value("units", "degrees")})
        .variable("rotated_pole", NC_CHAR, {}, {},
                  {NcAttr::text_value("grid_mapping_name", "rotated_latitude_longitude"),
                   NcAttr::number("grid_north_pole_latitude", NC_DOUBLE, {39.25}),
                   NcAttr::number("grid_north_pole_longitude", NC_DOUBLE, {-162.0})})
        .variable("v", NC_FLOAT, {"height", "rlat", "rlon"}, v,
                  {NcAttr::text_value("grid_mapping", "rotated_pole")})
        .write(*dir_ / "rotated.nc");
    convert(*dir_ / "rotated.nc", *dir_ / "rotated.store");
  }
  static void TearDownTestSuite() { delete dir_; }

  static void convert(const std::filesystem::path& in, const std::filesystem::path& out) {
    build::ConvertOptions o;
    o.inputs = {in};
    o.store = out;
    o.brick = 8;
    o.threads = 2;
    build::convert(o);
  }

  static LevelExtraction extract(const Store& store, const std::string& json, std::uint32_t level = 0,
                                 bool merge_face_squares = true) {
    const ResolvedScene scene = resolve_scene(parse_scene(json, "scene"), store.manifest(), "scene");
    LevelExtractionOptions o;
    o.level = level;
    o.merge_face_squares = merge_face_squares;
    o.threads = 2;
    return extract_level(store, scene, o);
  }

  static testing::TempDir* dir_;
};
testing::TempDir* GeoreferencedExtractionTest::dir_ = nullptr;

std::array<double, 2> x_range(const Mesh& m) {
  std::array<double, 2> r{INFINITY, -INFINITY};
  for (const auto& p : m.positions) {
    r[0] = std::min(r[0], p[0]);
    r[1] = std::max(r[1], p[0]);
  }
  return r;
}

TEST_F(GeoreferencedExtractionTest, LongitudeRangeAcrossTheSeamIsOneClosedRegion) {
  const auto store = Store::open(*dir_ / "global.store");
  ASSERT_TRUE(store->manifest().x.periodic);
  const double lat_extent = 40, lev_extent = 400;
  // The same 60 degrees in three conventions.
  for (const auto& [lo, hi] : {std::pair{-30.0, 30.0}, std::pair{330.0, 390.0}, std::pair{-390.0, -330.0}}) {
    for (std::uint32_t level = 0; level < store->octree().level_count(); ++level) {
      const LevelExtraction e = extract(*store, fmt::format(R"({{"format_version": 3, "subvolumes": [
          {{"id": 1, "domain": {{"lon": [{}, {}]}}}},
          {{"id": 2, "limits": [{{"var": "t", "min": 290}}], "domain": {{"lon": [{}, {}]}}}}]}})",
                                                            lo, hi, lo, hi), level);
      const std::string where = fmt::format("lon [{}, {}], level {}", lo, hi, level);
      const Mesh box = seamless_union(e, 1);
      const MeshCheck c = check_mesh(box);
      EXPECT_TRUE(c.clean()) << where << ": " << c.open_edges << " open edges";
      // All 60 degrees: before periodic longitudes only the part on one side of the seam
      // came out (0 .. 30 of a -30 .. 30 range).
      EXPECT_NEAR(enclosed_volume(box), 60 * lat_extent * lev_extent, 1e-6 * 60 * lat_extent * lev_extent)
          << where;
      const auto xr = x_range(box);
      EXPECT_EQ(xr[0], lo) << where;  // in the range's own convention
      EXPECT_EQ(xr[1], hi) << where;
      const Mesh warm = seamless_union(e, 2);
      EXPECT_TRUE(check_mesh(warm).clean()) << where;
      EXPECT_GT(enclosed_volume(warm), 0) << where;
    }
  }
}

TEST_F(GeoreferencedExtractionTest, TheSeamCellIsKept) {
  // 357.5 .. 360 (= 0): the cell between the source's last and first longitude.
  const auto store = Store::open(*dir_ / "global.store");
  const Mesh box = seamless_union(extract(*store, R"({"subvolumes": [{"id": 1, "domain": {"lon": [357, 361]}}]})"), 1);
  EXPECT_TRUE(check_mesh(box).clean());
  EXPECT_NEAR(enclosed_volume(box), 4 * 40 * 400, 1e-6 * 4 * 40 * 400);
}

TEST_F(GeoreferencedExtractionTest, RegionsAgreeWhateverTheConvention) {
  // The warm region between 300 and 420 (= 60) E, in three conventions: the same volume.
  const auto store = Store::open(*dir_ / "global.store");
  std::vector<double> volumes;
  for (const auto& [lo, hi] : {std::pair{300.0, 420.0}, std::pair{-60.0, 60.0}, std::pair{660.0, 780.0}}) {
    volumes.push_back(enclosed_volume(seamless_union(
        extract(*store, fmt::format(R"({{"subvolumes": [{{"id": 1, "limits": [{{"var": "t", "min": 285}}],
            "domain": {{"lon": [{}, {}]}}}}]}})", lo, hi)), 1)));
  }
  EXPECT_GT(volumes[0], 0);
  EXPECT_NEAR(volumes[1], volumes[0], 1e-9 * volumes[0]);
  EXPECT_NEAR(volumes[2], volumes[0], 1e-9 * volumes[0]);
}

// Area (rotated degrees squared) of the part of the grid's rlon/rlat extent whose true
// position lies in the box, by a midpoint quadrature on a grid 8 times finer than the
// data's, positions from PROJ: a reference the kernel takes no part in.
double box_area(const format::Manifest& m, double lon0, double lon1, double lat0, double lat1) {
  const geo::GridProjection p(m.grid_mapping->proj);
  const double x0 = m.x.values.front(), x1 = m.x.values.back();
  const double y0 = m.y.values.front(), y1 = m.y.values.back();
  const std::size_t nx = (m.x.size() - 1) * 8, ny = (m.y.size() - 1) * 8;
  const double dx = (x1 - x0) / double(nx), dy = (y1 - y0) / double(ny);
  double area = 0;
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const auto ll = p.to_geographic(x0 + (double(i) + 0.5) * dx, y0 + (double(j) + 0.5) * dy);
      if (ll[0] >= lon0 && ll[0] <= lon1 && ll[1] >= lat0 && ll[1] <= lat1) area += dx * dy;
    }
  }
  return area;
}

TEST_F(GeoreferencedExtractionTest, GeographicBoxOnARotatedGridIsClosedAndWherePROJSays) {
  const auto store = Store::open(*dir_ / "rotated.store");
  const format::Manifest& m = store->manifest();
  ASSERT_TRUE(m.grid_mapping.has_value());
  const double lon0 = 0, lon1 = 20, lat0 = 45, lat1 = 55;
  const LevelExtraction e = extract(*store, R"({"format_version": 3, "subvolumes": [
      {"id": 1, "geographic": {"lon": [0, 20], "lat": [45, 55]}},
      {"id": 2, "limits": [{"var": "v", "min": 0.2}], "geographic": {"lon": [0, 20], "lat": [45, 55]}}]})");
  const Mesh box = seamless_union(e, 1);
  const MeshCheck c = check_mesh(box);
  EXPECT_TRUE(c.clean()) << c.open_edges << " open edges";
  // Every vertex lies in the box, up to the interpolation between samples (the grid's
  // cells are about 1 degree: a tenth of that).
  const geo::GridProjection p(m.grid_mapping->proj);
  for (const auto& q : box.positions) {
    const auto ll = p.to_geographic(q[0], q[1]);
    EXPECT_GE(ll[0], lon0 - 0.1);
    EXPECT_LE(ll[0], lon1 + 0.1);
    EXPECT_GE(ll[1], lat0 - 0.1);
    EXPECT_LE(ll[1], lat1 + 0.1);
  }
  // Its volume (rotated degrees squared times metres) matches the box's area by quadrature
  // times the 3000 m the grid spans, within the interpolation's error.
  const double reference = box_area(m, lon0, lon1, lat0, lat1) * 3000;
  EXPECT_NEAR(enclosed_volume(box) / reference, 1.0, 0.01);
  const Mesh limited = seamless_union(e, 2);
  EXPECT_TRUE(check_mesh(limited).clean());
  EXPECT_LT(enclosed_volume(limited), enclosed_volume(box));
  // Nodes wholly outside the box are skipped from the geometry alone.
  std::uint64_t skipped = e.totals.outcomes[static_cast<int>(NodeOutcome::kSkippedDomain)];
  EXPECT_GT(skipped, 0u);
}

TEST_F(GeoreferencedExtractionTest, GeographicBoxOnALonLatGridIsTheAxisBox) {
  const auto store = Store::open(*dir_ / "global.store");
  const Mesh a = seamless_union(extract(*store, R"({"format_version": 3, "subvolumes": [
      {"id": 1, "geographic": {"lon": [-30, 30], "lat": [-10, 10]}}]})"), 1);
  const Mesh b = seamless_union(extract(*store, R"({"subvolumes": [
      {"id": 1, "domain": {"lon": [-30, 30], "lat": [-10, 10]}}]})"), 1);
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.triangles, b.triangles);
}

TEST_F(GeoreferencedExtractionTest, EcefFrameOfARotatedGridIsWherePROJPutsTheTruePositions) {
  const auto store = Store::open(*dir_ / "rotated.store");
  const format::Manifest& m = store->manifest();
  const FrameTransform ecef(m, OutputFrame::kEcef, choose_vertical_placement(m));
  ASSERT_FALSE(ecef.affine());
  // Face squares kept per cell: a rectangle of 8 cells is 8 degrees, whose chord would
  // sag 15 km below this 3 km layer on the curved Earth.
  const LevelExtraction e = extract(*store, R"({"subvolumes": [{"id": 1, "limits": [{"var": "v", "min": 0.3}]}]})",
                                    0, ecef.affine());
  Mesh mesh = seamless_union(e, 1);
  ASSERT_FALSE(mesh.empty());
  const Mesh axis = mesh;
  Mesh metric = mesh;
  FrameTransform(m, OutputFrame::kLocalMetric, choose_vertical_placement(m)).apply(metric);
  ecef.apply(mesh);
  // PROJ: rotated degrees -> geographic -> geocentric (cart), in one pipeline.
  const geo::GridProjection reference(
      "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad +step +inv +proj=ob_tran "
      "+o_proj=longlat +o_lat_p=39.25 +lon_0=18 +step +proj=cart +ellps=WGS84");
  for (std::size_t v = 0; v < mesh.positions.size(); v += 37) {
    const auto& q = axis.positions[v];
    // cart gives geocentric x, y at height 0 (its z is not returned): the vertex at
    // height h lies at most h metres from there.
    const auto xy = reference.to_geographic(q[0], q[1]);
    EXPECT_NEAR(mesh.positions[v][0], xy[0], 1e-3 + 1e-9 * std::fabs(xy[0]) + q[2]) << v;
    EXPECT_NEAR(mesh.positions[v][1], xy[1], 1e-3 + 1e-9 * std::fabs(xy[1]) + q[2]) << v;
  }
  // Outward, and the volume in cubic metres: within a few per cent of the tangent plane's
  // (whose east-west scale is off by cos(lat)/cos(lat0) - 1 away from the centre).
  EXPECT_NEAR(enclosed_volume(mesh) / enclosed_volume(metric), 1.0, 0.05);
}

// A mapped grid's geographic positions and Jacobians are kept per column of vertices:
// every vertex still gets the bits that a transform made for it alone gives, whatever
// the transform placed before.
TEST_F(GeoreferencedExtractionTest, MappedVerticesArePlacedAsByAFreshTransform) {
  const auto store = Store::open(*dir_ / "rotated.store");
  const format::Manifest& m = store->manifest();
  for (OutputFrame frame : {OutputFrame::kLonLat, OutputFrame::kEcef}) {
    const FrameTransform transform(m, frame, choose_vertical_placement(m));
    const LevelExtraction e = extract(
        *store, R"({"subvolumes": [{"id": 1, "limits": [{"var": "v", "min": 0.3}]}]})", 0, false);
    const Mesh axis = seamless_union(e, 1);
    ASSERT_FALSE(axis.empty());
    Mesh once = axis, twice = axis;
    transform.apply(once);
    transform.apply(twice);  // every column now cached
    EXPECT_TRUE(once == twice) << output_frame_name(frame);
    for (std::size_t v = 0; v < axis.positions.size(); v += 53) {
      Mesh single = axis;
      FrameTransform(m, frame, choose_vertical_placement(m)).apply(single);
      EXPECT_EQ(single.positions[v], once.positions[v]) << v;
      EXPECT_EQ(single.normals[v], once.normals[v]) << v;
      if (frame == OutputFrame::kLonLat) {
        const FrameTransform fresh(m, frame, choose_vertical_placement(m));
        EXPECT_EQ(fresh.lon_lat_height(axis.positions[v]), once.positions[v]) << v;
      }
    }
  }
}

}  // namespace
}  // namespace strielad
