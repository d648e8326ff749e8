// SPDX-License-Identifier: Apache-2.0
// BoxReader::prefetch (the predictor trial's read-ahead) asks the kernel for exactly the
// bytes of a box's rows: per plane, from the box's first sample to its last, checked by
// reading those file bytes back; for storage whose planes are not raw (deflate, chunks
// smaller than a plane) it asks for nothing, and reads are the same either way.
#include <gtest/gtest.h>

#include <netcdf.h>

#include <cstring>
#include <fstream>

#include "ingest/box_reader.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::build {
namespace {

using namespace strielad::testing;

// 2 steps x 6 levels x 30 lat x 40 lon; sample value = its index in the whole variable.
SimpleGrid test_grid() {
  SimpleGrid g;
  g.time = {0, 6};
  g.time_unlimited = false;  // contiguous storage needs fixed dimensions
  g.lev = {1000, 850, 700, 500, 300, 200};
  g.lat.clear();
  for (int j = 0; j < 30; ++j) g.lat.push_back(40.0 + j);
  g.lon.clear();
  for (int i = 0; i < 40; ++i) g.lon.push_back(i * 0.5);
  return g;
}

float file_float_at(const std::filesystem::path& file, std::uint64_t offset) {
  std::ifstream in(file, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(offset));
  float v = 0;
  in.read(reinterpret_cast<char*>(&v), sizeof v);
  EXPECT_TRUE(in.good()) << "offset " << offset << " is past the end of " << file;
  return v;  // the fixture writes native (little-endian) floats
}

std::filesystem::path write_input(const std::filesystem::path& dir, VarStorage storage) {
  const SimpleGrid g = test_grid();
  std::vector<double> values(g.samples());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i);
  const auto file = dir / "clw.nc";
  NetcdfFixture().grid(g).variable("clw", NC_FLOAT, g.dims(), values, {}, storage).write(file);
  return file;
}

TEST(BoxPrefetch, RangesStartAtTheBoxsFirstSampleAndEndAtItsLastPerPlane) {
  struct Case {
    const char* name;
    VarStorage storage;
  };
  VarStorage contiguous, one_plane, three_planes;
  contiguous.contiguous = true;
  one_plane.chunks = {1, 1, 30, 40};
  three_planes.chunks = {1, 3, 30, 40};
  const Case cases[] = {{"contiguous", contiguous},
                        {"one plane per chunk", one_plane},
                        {"three planes per chunk", three_planes}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    TempDir dir;
    const auto file = write_input(dir.path(), c.storage);
    ingest::ScanOptions scan;
    const ingest::InputCatalog catalog = ingest::scan_inputs(std::vector<std::filesystem::path>{file}, scan);
    const std::size_t step = 1, nx = 40, ny = 30, nz = 6;
    BoxReader reader(catalog, scan, 0, step);
    const IndexBox box{{5, 7, 1}, {17, 12, 4}};
    const auto ranges = reader.prefetch_ranges(box);
    ASSERT_EQ(ranges.size(), box.extent(2));
    for (std::size_t k = 0; k < ranges.size(); ++k) {
      const std::size_t z = box.lo[2] + k;
      const auto index = [&](std::size_t x, std::size_t y) {
        return static_cast<float>(((step * nz + z) * ny + y) * nx + x);
      };
      EXPECT_EQ(ranges[k].bytes, ((box.hi[1] - box.lo[1]) * nx + box.extent(0)) * 4);
      EXPECT_EQ(file_float_at(file, ranges[k].offset), index(box.lo[0], box.lo[1])) << "plane " << z;
      EXPECT_EQ(file_float_at(file, ranges[k].offset + ranges[k].bytes - 4),
                index(box.hi[0], box.hi[1]))
          << "plane " << z;
    }
    reader.prefetch(box);
    std::vector<float> out(box.count());
    reader.read(box, out);
    EXPECT_EQ(out.front(), static_cast<float>(((step * nz + 1) * ny + 7) * nx + 5));
  }
}

TEST(BoxPrefetch, StorageThatIsNotRawPlanesGetsNoRanges) {
  VarStorage deflated, sub_plane_chunks;
  deflated.chunks = {1, 6, 30, 40};
  deflated.deflate_level = 1;
  sub_plane_chunks.chunks = {1, 6, 10, 40};
  const VarStorage cases[] = {deflated, sub_plane_chunks};
  for (const auto& storage : cases) {
    TempDir dir;
    const auto file = write_input(dir.path(), storage);
    ingest::ScanOptions scan;
    const ingest::InputCatalog catalog = ingest::scan_inputs(std::vector<std::filesystem::path>{file}, scan);
    BoxReader reader(catalog, scan, 0, 0);
    const IndexBox box{{0, 0, 0}, {39, 29, 5}};
    EXPECT_TRUE(reader.prefetch_ranges(box).empty());
    reader.prefetch(box);  // does nothing, and reading still works
    std::vector<float> out(box.count());
    reader.read(box, out);
    EXPECT_EQ(out.back(), static_cast<float>(box.count() - 1));
  }
}

}  // namespace
}  // namespace strielad::build
