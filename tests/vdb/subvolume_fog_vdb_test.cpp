// SPDX-License-Identifier: Apache-2.0
// A sub-volume exported as a fog volume: density 1 exactly at the samples where every
// limit holds inside the domain box, one grid per sub-volume, nodes excluded by their
// value range skipped without reading.
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>

#include "convert/converter.h"
#include "geo/grid_projection.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"
#include "vdb/level_grid.h"

namespace strielad {
namespace {

TEST(SubvolumeFogVdbTest, ActiveVoxelsAreTheSamplesInsideTheSubvolume) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 30, 20, 10, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 4));
  const auto store = Store::open(dir / "store");
  const auto scene = resolve_scene(parse_scene(R"({"subvolumes": [
      {"id": 3, "name": "warm", "limits": [{"var": "temp", "min": 270}]},
      {"id": 5, "limits": [{"var": "cloud", "min": 1e30}]}]})", "scene"),
                                   store->manifest(), "scene");
  const auto out = dir / "sub.vdb";
  const auto summaries = vdb::write_subvolume_vdb(*store, scene, 0, out);
  ASSERT_EQ(summaries.size(), 2u);
  EXPECT_EQ(summaries[1].bricks_read, 0u);  // no cloud reaches 1e30: all skipped
  EXPECT_EQ(summaries[1].active_voxels, 0u);

  openvdb::initialize();
  openvdb::io::File file(out.string());
  file.open();
  auto warm = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("warm"));
  auto none = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("subvolume-5"));
  file.close();
  ASSERT_TRUE(warm);
  ASSERT_TRUE(none);
  EXPECT_EQ(warm->getGridClass(), openvdb::GRID_FOG_VOLUME);
  // Count the samples with temp >= 270 from the level-0 bricks (shared samples once).
  const auto var = static_cast<std::uint32_t>(store->manifest().variable_index("temp"));
  std::uint64_t expected = 0;
  const auto& shape = store->octree().level(0);
  std::vector<char> seen(data.nx * data.ny * data.nz, 0);
  for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); ++n) {
    const Brick b = store->read_brick(0, var, n);
    for (std::size_t z = 0; z < b.dims[2]; ++z)
      for (std::size_t y = 0; y < b.dims[1]; ++y)
        for (std::size_t x = 0; x < b.dims[0]; ++x) {
          const std::size_t g = ((b.box.lo[2] + z) * data.ny + b.box.lo[1] + y) * data.nx +
                                b.box.lo[0] + x;
          if (seen[g]) continue;
          seen[g] = 1;
          expected += b.sample((z * b.dims[1] + y) * b.dims[0] + x) >= 270;
        }
  }
  EXPECT_GT(expected, 0u);
  EXPECT_EQ(warm->activeVoxelCount(), expected);
  EXPECT_EQ(summaries[0].active_voxels, expected);
  EXPECT_EQ(none->activeVoxelCount(), 0u);
}

// Longitude ranges in any convention and geographic boxes hold the same samples in the
// fog volume as in the meshes: on a global grid stored 0 .. 337.5 (periodic, 360 repeated)
// [-45, 45] is the three meridians on either side of the seam, the repeated one included.
TEST(SubvolumeFogVdbTest, LongitudeRangesAndGeographicBoxesSelectTheirSamples) {
  testing::TempDir dir;
  testing::SimpleGrid g;
  g.lon = testing::ramp(16, 0, 22.5);
  g.lat = {-10, 0, 10};
  testing::NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), testing::ramp(g.samples()))
      .write(dir / "g.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "g.nc"};
  o.store = dir / "store";
  o.brick = 4;
  build::convert(o);
  const auto store = Store::open(dir / "store");
  ASSERT_TRUE(store->manifest().x.periodic);
  const auto scene = resolve_scene(parse_scene(R"({"format_version": 3, "subvolumes": [
      {"id": 1, "domain": {"lon": [-45, 45]}},
      {"id": 2, "geographic": {"lon": [315, 405], "lat": [-5, 20]}}]})", "scene"),
                                   store->manifest(), "scene");
  const auto summaries = vdb::write_subvolume_vdb(*store, scene, 0, dir / "lon.vdb");
  ASSERT_EQ(summaries.size(), 2u);
  // Columns 0, 1, 2 (0, 22.5, 45) and 14, 15, 16 (315, 337.5, 360) of 3 x 2 samples each.
  EXPECT_EQ(summaries[0].active_voxels, 6u * 3u * 2u);
  // The same columns, latitudes 0 and 10.
  EXPECT_EQ(summaries[1].active_voxels, 6u * 2u * 2u);
}

// On a rotated-pole grid a geographic box activates exactly the samples whose true position
// (by PROJ) lies in it.
TEST(SubvolumeFogVdbTest, GeographicBoxOnARotatedGridSelectsSamplesByTheirTruePosition) {
  testing::TempDir dir;
  const auto rlon = testing::ramp(21, -10, 1), rlat = testing::ramp(17, -8, 1);
  testing::NetcdfFixture()
      .coordinate("height", {0, 1000}, {testing::NcAttr::text_value("units", "m"),
                                        testing::NcAttr::text_value("positive", "up")})
      .coordinate("rlat", rlat, {testing::NcAttr::text_value("standard_name", "grid_latitude"),
                                 testing::NcAttr::text_value("units", "degrees")})
      .coordinate("rlon", rlon, {testing::NcAttr::text_value("standard_name", "grid_longitude"),
                                 testing::NcAttr::text_value("units", "degrees")})
      .variable("rotated_pole", NC_CHAR, {}, {},
                {testing::NcAttr::text_value("grid_mapping_name", "rotated_latitude_longitude"),
                 testing::NcAttr::number("grid_north_pole_latitude", NC_DOUBLE, {39.25}),
                 testing::NcAttr::number("grid_north_pole_longitude", NC_DOUBLE, {-162.0})})
      .variable("v", NC_FLOAT, {"height", "rlat", "rlon"}, testing::ramp(2 * 17 * 21),
                {testing::NcAttr::text_value("grid_mapping", "rotated_pole")})
      .write(dir / "r.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "r.nc"};
  o.store = dir / "store";
  o.brick = 8;
  build::convert(o);
  const auto store = Store::open(dir / "store");
  const auto scene = resolve_scene(parse_scene(R"({"format_version": 3, "subvolumes": [
      {"id": 1, "geographic": {"lon": [12, 24], "lat": [46, 52]}}]})", "scene"),
                                   store->manifest(), "scene");
  const auto summaries = vdb::write_subvolume_vdb(*store, scene, 0, dir / "geo.vdb");
  const geo::GridProjection p(
      "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad +step +inv +proj=ob_tran "
      "+o_proj=longlat +o_lat_p=39.25 +lon_0=18 +step +proj=unitconvert +xy_in=rad +xy_out=deg");
  std::uint64_t inside = 0;
  for (double y : rlat) {
    for (double x : rlon) {
      const auto ll = p.to_geographic(x, y);
      inside += ll[0] >= 12 && ll[0] <= 24 && ll[1] >= 46 && ll[1] <= 52 ? 2 : 0;  // both levels
    }
  }
  ASSERT_GT(inside, 0u);
  EXPECT_EQ(summaries.at(0).active_voxels, inside);
}

}  // namespace
}  // namespace strielad
