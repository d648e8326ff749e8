// SPDX-License-Identifier: Apache-2.0
// Direct input reads (SlabReader with ScanOptions::direct_input): netCDF-4 planes that
// HDF5 stores raw are read with O_DIRECT and give exactly what netCDF gives; every other
// storage (compressed, big-endian, chunks smaller than a plane, chunks never written)
// still reads through netCDF.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "core/direct_read_file.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// 3 steps x 7 levels x 90 lat x 110 lon: a slab spans several of the aligned blocks
// misaligned samples are converted through (32768 samples).
SimpleGrid test_grid(bool time_unlimited = true) {
  SimpleGrid g;
  g.time = {0, 6, 12};
  g.time_unlimited = time_unlimited;
  g.lev = {1000, 925, 850, 700, 500, 300, 200};
  g.lat.clear();
  for (int j = 0; j < 90; ++j) g.lat.push_back(-44.5 + j);
  g.lon.clear();
  for (int i = 0; i < 110; ++i) g.lon.push_back(i * 0.5);
  return g;
}

// Values with fill samples and a wide range, so that conversion has work to do.
std::vector<double> test_values(std::size_t n, double fill) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = i % 97 == 0 ? fill : std::sin(0.001 * static_cast<double>(i)) * 1e-3 * (1 + i % 13);
  }
  return v;
}

bool direct_io_possible(const std::filesystem::path& file) {
  return DirectReadFile::open(file) != nullptr;
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Every slab shape the converter asks for (whole steps, one level, ranges starting
// inside a chunk) read both ways; returns the direct reader's direct bytes.
template <typename T>
std::uint64_t expect_same_reads(const std::filesystem::path& file, const std::string& variable) {
  ScanOptions direct_options, buffered_options;
  direct_options.variables = buffered_options.variables = {variable};
  buffered_options.direct_input = false;
  const InputCatalog c = scan_inputs({file}, direct_options);
  SlabReader direct(c, direct_options), buffered(c, buffered_options);
  const Dims3 d = c.dims();
  const std::size_t plane = d.x * d.y;
  const std::pair<std::size_t, std::size_t> ranges[] = {{0, d.z}, {0, 1}, {1, 4}, {3, 7}, {6, 7}};
  for (std::size_t t = 0; t < c.time.size(); ++t) {
    for (const auto& [z0, z1] : ranges) {
      std::vector<T> a((z1 - z0) * plane), b((z1 - z0) * plane);
      direct.read(0, t, z0, z1, a);
      buffered.read(0, t, z0, z1, b);
      EXPECT_TRUE(same_bits(a, b)) << variable << " step " << t << " levels " << z0 << ".." << z1;
    }
  }
  EXPECT_EQ(buffered.direct_bytes(), 0u);
  return direct.direct_bytes();
}

VarStorage chunked(std::vector<std::size_t> chunks, int deflate_level = 0,
                   int endian = NC_ENDIAN_NATIVE) {
  VarStorage s;
  s.chunks = std::move(chunks);
  s.deflate_level = deflate_level;
  s.endian = endian;
  return s;
}

VarStorage contiguous() {
  VarStorage s;
  s.contiguous = true;
  return s;
}

struct StorageCase {
  const char* name;
  VarStorage storage;
  bool time_unlimited;
  bool direct;  // expected to read with O_DIRECT
};

TEST(DirectInputReadsTest, RawPlanesReadDirectlyOtherStorageThroughNetcdf) {
  const StorageCase cases[] = {
      {"netCDF's default chunks", VarStorage(), true, true},
      {"one plane per chunk", chunked({1, 1, 90, 110}), true, true},
      {"chunks of 2 steps x 3 levels", chunked({2, 3, 90, 110}), true, true},
      {"contiguous", contiguous(), false, true},
      {"chunks smaller than a plane", chunked({1, 2, 45, 110}), true, false},
      {"deflate", chunked({1, 1, 90, 110}, 1), true, false},
      {"big-endian", chunked({1, 1, 90, 110}, 0, NC_ENDIAN_BIG), true, false},
  };
  for (const StorageCase& sc : cases) {
    SCOPED_TRACE(sc.name);
    TempDir dir;
    const SimpleGrid g = test_grid(sc.time_unlimited);
    const auto file = dir / "clw.nc";
    NetcdfFixture()
        .grid(g)
        .variable("clw", NC_FLOAT, g.dims(), test_values(g.samples(), -9e33),
                  {NcAttr::number("_FillValue", NC_FLOAT, {-9e33})}, sc.storage)
        .write(file);
    const std::uint64_t direct_bytes = expect_same_reads<float>(file, "clw");
    if (!direct_io_possible(file)) GTEST_SKIP() << "no O_DIRECT on " << dir.path();
    // Every slab of every step: 3 x (7 + 1 + 3 + 4 + 1) planes.
    const std::uint64_t all = 3ull * 16 * 90 * 110 * 4;
    EXPECT_EQ(direct_bytes, sc.direct ? all : 0u);
  }
}

TEST(DirectInputReadsTest, PackedAndDoubleSamplesConvertAsThroughNetcdf) {
  TempDir dir;
  const SimpleGrid g = test_grid();
  const auto file = dir / "packed.nc";
  std::vector<double> packed(g.samples());
  for (std::size_t i = 0; i < packed.size(); ++i) packed[i] = static_cast<double>(i % 60000) - 30000;
  NetcdfFixture()
      .grid(g)
      .variable("ta", NC_SHORT, g.dims(), packed,
                {NcAttr::number("scale_factor", NC_FLOAT, {0.01}),
                 NcAttr::number("add_offset", NC_FLOAT, {250}),
                 NcAttr::number("_FillValue", NC_SHORT, {-30000})},
                chunked({1, 1, 90, 110}))
      .variable("pres", NC_DOUBLE, g.dims(), test_values(g.samples(), 1e20),
                {NcAttr::number("_FillValue", NC_DOUBLE, {1e20})}, chunked({1, 7, 90, 110}))
      .write(file);
  const std::uint64_t packed_bytes = expect_same_reads<float>(file, "ta");
  const std::uint64_t double_bytes = expect_same_reads<double>(file, "pres");
  if (!direct_io_possible(file)) GTEST_SKIP() << "no O_DIRECT on " << dir.path();
  EXPECT_EQ(packed_bytes, 3ull * 16 * 90 * 110 * 2);
  EXPECT_EQ(double_bytes, 3ull * 16 * 90 * 110 * 8);
}

TEST(DirectInputReadsTest, ChunksNeverWrittenReadAsFillThroughNetcdf) {
  TempDir dir;
  const SimpleGrid g = test_grid();
  const auto file = dir / "unwritten.nc";
  // "qr" is defined but never written: its chunks do not exist, netCDF supplies fill.
  NetcdfFixture()
      .grid(g)
      .variable("clw", NC_FLOAT, g.dims(), test_values(g.samples(), -9e33),
                {NcAttr::number("_FillValue", NC_FLOAT, {-9e33})}, chunked({1, 1, 90, 110}))
      .variable("qr", NC_FLOAT, g.dims(), {}, {NcAttr::number("_FillValue", NC_FLOAT, {-9e33})},
                chunked({1, 1, 90, 110}))
      .write(file);
  EXPECT_EQ(expect_same_reads<float>(file, "qr"), 0u);
  ScanOptions options;
  options.variables = {"qr"};
  const InputCatalog c = scan_inputs({file}, options);
  SlabReader reader(c, options);
  std::vector<float> out(7 * 90 * 110);
  reader.read(0, 1, 0, 7, out);
  for (float v : out) ASSERT_TRUE(std::isnan(v));  // fill is missing
}

TEST(DirectInputReadsTest, NaNIsRefusedAtTheSameSampleAsThroughNetcdf) {
  TempDir dir;
  const SimpleGrid g = test_grid();
  auto values = test_values(g.samples(), -9e33);
  // Step 2, level 5, lat 80, lon 3: past the first aligned block of its slab.
  values[((2 * 7 + 5) * 90 + 80) * 110 + 3] = kNaN;
  const auto file = dir / "nan.nc";
  NetcdfFixture()
      .grid(g)
      .variable("clw", NC_FLOAT, g.dims(), values, {NcAttr::number("_FillValue", NC_FLOAT, {-9e33})},
                chunked({1, 1, 90, 110}))
      .write(file);
  for (bool direct : {true, false}) {
    ScanOptions options;
    options.direct_input = direct;
    const InputCatalog c = scan_inputs({file}, options);
    SlabReader reader(c, options);
    std::vector<float> out(6 * 90 * 110);
    expect_error([&] { reader.read(0, 2, 1, 7, out); }, ErrorCode::kInvalidInput,
                 {file.string() + ": variable 'clw' time step 2: sample (lon 3, lat 80, level 5) "
                                  "is NaN"});
  }
}

}  // namespace
}  // namespace strielad::ingest
