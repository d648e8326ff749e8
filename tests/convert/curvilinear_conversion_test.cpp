// SPDX-License-Identifier: Apache-2.0
// The curvilinear sample (a rotated-pole grid written only as 2-D lat/lon) converted end to
// end: a version-5 store with index axes x and y, a curvilinear geometry naming lon and
// lat, and a GEOMETRY file whose arrays are the file's, read here with netCDF, value for
// value; the positions agree with PROJ's cs2cs for the rotated pole the sample used.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "convert/converter.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "extract/output_frame.h"
#include "format/geometry_file_format.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/cs2cs.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "synthetic/curvilinear_like_file.h"
#include "synthetic/model_like_files.h"

namespace strielad {
namespace {

constexpr Dims3 kDims{14, 11, 6};

struct Converted {
  testing::TempDir dir;
  std::filesystem::path input;
  std::shared_ptr<const Store> store;
};

const Converted& converted() {
  static const Converted* c = [] {
    auto* out = new Converted;
    synthetic::SampleSpec s;
    s.dims = kDims;
    s.steps = 2;
    s.file_per_step = false;
    out->input = synthetic::write_model_like_dataset(s, synthetic::SampleModel::kCurvilinear,
                                                     out->dir / "in")
                     .files[0]
                     .path;
    build::ConvertOptions o;
    o.inputs = {out->input};
    o.store = out->dir / "store";
    o.brick = 8;
    o.threads = 1;
    build::convert(o);
    out->store = Store::open(out->dir / "store");
    return out;
  }();
  return *c;
}

TEST(CurvilinearConversionTest, StoreRecordsTheCurvilinearGeometry) {
  const format::Manifest& m = converted().store->manifest();
  EXPECT_EQ(m.format_version, 5u);
  EXPECT_EQ(m.x.kind, AxisKind::kIndex);
  EXPECT_EQ(m.y.kind, AxisKind::kIndex);
  EXPECT_EQ(m.x.name, "x");
  EXPECT_EQ(m.y.name, "y");
  EXPECT_EQ(m.x.size(), kDims.x);
  EXPECT_EQ(m.y.size(), kDims.y);
  EXPECT_EQ(m.x.values.back(), static_cast<double>(kDims.x - 1));
  EXPECT_FALSE(m.grid_mapping);
  ASSERT_TRUE(m.geometry);
  EXPECT_EQ(m.geometry->horizontal.kind, format::HorizontalGeometry::Kind::kCurvilinear);
  EXPECT_EQ(m.geometry->horizontal.lon_variable, "lon");
  EXPECT_EQ(m.geometry->horizontal.lat_variable, "lat");
  EXPECT_EQ(m.geometry->vertical.kind, format::VerticalGeometry::Kind::kAxis);
  EXPECT_FALSE(m.geometry->surface);
  // i runs east and j north (+1), the heights are stored top to bottom (-1).
  EXPECT_EQ(m.geometry->orientation, -1);
  EXPECT_EQ(m.variables.size(), 5u);
  EXPECT_EQ(m.time.values.size(), 2u);
}

TEST(CurvilinearConversionTest, GeometryHoldsTheFilesCoordinatesExactly) {
  const Converted& c = converted();
  const auto coordinates = c.store->horizontal_coordinates();
  ASSERT_TRUE(coordinates);
  EXPECT_EQ(coordinates->nx, kDims.x);
  EXPECT_EQ(coordinates->ny, kDims.y);
  EXPECT_FALSE(coordinates->surface_m);
  const testing::NetcdfValues lon = testing::read_netcdf_variable(c.input, "lon");
  const testing::NetcdfValues lat = testing::read_netcdf_variable(c.input, "lat");
  EXPECT_EQ(lon.shape, (std::vector<std::size_t>{kDims.y, kDims.x}));
  EXPECT_EQ(coordinates->lon, lon.values);
  EXPECT_EQ(coordinates->lat, lat.values);
  EXPECT_EQ(c.store->manifest().geometry->horizontal.coordinates_checksum,
            format::coordinates_checksum(*coordinates));
}

TEST(CurvilinearConversionTest, PlacementAgreesWithCs2cs) {
  if (!testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) is not installed";
  const Converted& c = converted();
  const auto coordinates = c.store->horizontal_coordinates();
  ASSERT_TRUE(coordinates);
  const synthetic::CurvilinearSampleGrid grid =
      synthetic::curvilinear_sample_grid(kDims.x, kDims.y);
  // The pole at 40 N, 170 W written out by hand: lon_0 = -170 + 180.
  const std::string rotated = "+proj=ob_tran +o_proj=longlat +o_lat_p=40 +o_lon_p=0 +lon_0=10";
  const std::vector<std::array<std::size_t, 2>> samples{
      {0, 0}, {kDims.x - 1, 0}, {0, kDims.y - 1}, {kDims.x - 1, kDims.y - 1}, {5, 7}};
  std::vector<std::array<double, 2>> points;
  for (const auto& [i, j] : samples) points.push_back({grid.rlon[i], grid.rlat[j]});
  const auto got = testing::cs2cs(rotated, "+proj=longlat", points);
  ASSERT_TRUE(got);
  ASSERT_EQ(got->size(), samples.size());
  for (std::size_t p = 0; p < samples.size(); ++p) {
    const std::size_t k = samples[p][1] * kDims.x + samples[p][0];
    // cs2cs prints 12 decimals of a degree.
    EXPECT_NEAR(coordinates->lon[k], (*got)[p][0], 1e-9) << "sample " << p;
    EXPECT_NEAR(coordinates->lat[k], (*got)[p][1], 1e-9) << "sample " << p;
  }
}

// CF hybrid height over orog on a curvilinear grid whose rows run south: the GEOMETRY
// file holds the coordinates and the surface; the orientation is the grid's (-1: i east,
// j south) times the field's (+1: heights grow with k), and the field passes the
// converter's direction check with it.
TEST(CurvilinearConversionTest, ExtractedRegionsAreClosedAndOutwardOnTheEarth) {
  // The sample's rotated grid is mirrored against east/north and its height axis runs
  // from the top: the regions must still come out closed and outward once placed.
  const Store& store = *converted().store;
  const format::Manifest& m = store.manifest();
  Scene scene;
  SubVolume warm;
  warm.id = 1;
  warm.limits.push_back(Limit{"temp", 275.0, std::nullopt});
  scene.subvolumes.push_back(warm);
  LevelExtractionOptions o;
  o.merge_face_squares = false;
  const LevelExtraction level = extract_level(store, resolve_scene(scene, m, "test scene"), o);
  for (const OutputFrame frame : {OutputFrame::kLonLat, OutputFrame::kLocalMetric, OutputFrame::kEcef}) {
    Mesh mesh = seamless_union(level, 1);
    ASSERT_FALSE(mesh.triangles.empty());
    FrameTransform(m, frame, choose_vertical_placement(m), store.horizontal_coordinates()).apply(mesh);
    EXPECT_TRUE(check_mesh(mesh).closed()) << output_frame_name(frame);
    if (frame != OutputFrame::kLonLat) {  // degrees and metres mixed: no volume there
      EXPECT_GT(enclosed_volume(mesh), 0) << output_frame_name(frame);
    }
  }
}

TEST(CurvilinearConversionTest, SurfaceAndHeightFieldOnACurvilinearGrid) {
  using testing::NcAttr;
  const testing::TempDir dir;
  const std::vector<double> lat{1, 1, 1, 0, 0, 0}, lon{0, 1, 2, 0, 1, 2};
  const std::vector<double> orog{0, 100, 200, 300, 400, 500};
  testing::NetcdfFixture(NC_NETCDF4)
      .coordinate("lev", {100, 1000, 5000},
                  {NcAttr::text_value("standard_name", "atmosphere_hybrid_height_coordinate"),
                   NcAttr::text_value("units", "m"), NcAttr::text_value("positive", "up"),
                   NcAttr::text_value("formula_terms", "a: lev b: b orog: orog")})
      .variable("b", NC_DOUBLE, {"lev"}, {0.9, 0.5, 0})
      .dimension("y", 2)
      .dimension("x", 3)
      .variable("orog", NC_FLOAT, {"y", "x"}, orog,
                {NcAttr::text_value("standard_name", "surface_altitude"),
                 NcAttr::text_value("units", "m"), NcAttr::text_value("coordinates", "lon lat")})
      .variable("lat", NC_DOUBLE, {"y", "x"}, lat, {NcAttr::text_value("units", "degrees_north")})
      .variable("lon", NC_DOUBLE, {"y", "x"}, lon, {NcAttr::text_value("units", "degrees_east")})
      .variable("ta", NC_FLOAT, {"lev", "y", "x"}, testing::ramp(18),
                {NcAttr::text_value("units", "K"), NcAttr::text_value("coordinates", "lon lat")})
      .write(dir / "hh.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "hh.nc"};
  o.store = dir / "store";
  o.threads = 1;
  build::convert(o);
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  ASSERT_TRUE(m.geometry);
  EXPECT_EQ(m.geometry->horizontal.kind, format::HorizontalGeometry::Kind::kCurvilinear);
  EXPECT_EQ(m.geometry->vertical.kind, format::VerticalGeometry::Kind::kField);
  ASSERT_TRUE(m.geometry->surface);
  EXPECT_EQ(m.geometry->surface->variable, "orog");
  EXPECT_EQ(m.geometry->orientation, -1);
  const auto c = store->horizontal_coordinates();
  ASSERT_TRUE(c && c->surface_m);
  EXPECT_EQ(c->lon, lon);
  EXPECT_EQ(c->lat, lat);
  EXPECT_EQ(*c->surface_m, orog);
}

}  // namespace
}  // namespace strielad
