// SPDX-License-Identifier: Apache-2.0
// SlabReader argument checks, concurrent use, and many files kept open at once.
#include <gtest/gtest.h>

#include <thread>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

TEST(SlabReaderArgumentsTest, BadArgumentsAreInvalidArguments) {
  TempDir dir;
  SimpleGrid g;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "a.nc");
  const InputCatalog c = scan_inputs({dir / "a.nc"}, {});
  SlabReader reader(c, {});
  std::vector<float> out(12);
  expect_error([&] { reader.read(0, 0, 0, 2, out); }, ErrorCode::kInvalidArgument,
               {"output holds 12 samples", "need 24"});
  expect_error([&] { reader.read(0, 0, 1, 3, out); }, ErrorCode::kInvalidArgument,
               {"level range [1, 3)"});
  expect_error([&] { reader.read(0, 1, 0, 1, out); }, ErrorCode::kInvalidArgument,
               {"time step 1 out of range"});
  expect_error([&] { reader.read(1, 0, 0, 1, out); }, ErrorCode::kInvalidArgument,
               {"variable index 1 out of range"});
  reader.read(0, 0, 1, 2, out);
  EXPECT_EQ(out[0], 12.0f);
  std::vector<float> none;
  reader.read(0, 0, 1, 1, none);  // empty slab: nothing to do
}

TEST(SlabReaderArgumentsTest, ConcurrentReadsMatchSerialReads) {
  const auto file = ncarg_file("cdf/contour.cdf");
  const InputCatalog c = scan_inputs({file}, {});
  SlabReader reader(c, {});
  const Dims3 d = c.dims();
  std::vector<std::vector<float>> serial(c.time.size(), std::vector<float>(d.count()));
  for (std::size_t t = 0; t < c.time.size(); ++t) reader.read(0, t, 0, d.z, serial[t]);
  std::vector<std::vector<float>> parallel(c.time.size(), std::vector<float>(d.count()));
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < c.time.size(); ++t) {
    threads.emplace_back([&, t] { reader.read(0, t, 0, d.z, parallel[t]); });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(serial, parallel);
}

TEST(SlabReaderArgumentsTest, MoreFilesThanKeptOpen) {
  TempDir dir;
  std::vector<std::filesystem::path> files;
  for (int i = 0; i < 70; ++i) {
    SimpleGrid g;
    g.time = {static_cast<double>(i)};
    files.push_back(dir / ("step" + std::to_string(i) + ".nc"));
    NetcdfFixture(NC_CLOBBER)
        .grid(g)
        .variable("T", NC_FLOAT, g.dims(), ramp(g.samples(), 100.0 * i))
        .write(files.back());
  }
  const InputCatalog c = scan_inputs(files, {});
  ASSERT_EQ(c.time.size(), 70u);
  SlabReader reader(c, {});
  std::vector<float> out(24);
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t t = 0; t < 70; ++t) {
      reader.read(0, t, 0, 2, out);
      ASSERT_EQ(out[1], static_cast<float>(100.0 * static_cast<double>(t) + 1)) << t;
    }
  }
}

}  // namespace
}  // namespace strielad::ingest
