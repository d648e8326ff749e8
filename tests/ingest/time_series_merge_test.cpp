// SPDX-License-Identifier: Apache-2.0
// A time series split over files merges into one ascending axis, whatever the order of
// the files on the command line; first_step/last_step select a range of it.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

// Sample value encodes the time: every sample of time t is 1000 * t + index.
class TimeSeriesMergeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    write("late.nc", {24});
    write("early.nc", {0, 6});
    write("middle.nc", {12, 18});
    inputs_ = {dir_ / "middle.nc", dir_ / "late.nc", dir_ / "early.nc"};
  }
  void write(const std::string& name, std::vector<double> times) {
    SimpleGrid g;
    g.time = times;
    std::vector<double> data;
    for (double t : times) {
      for (double v : ramp(g.samples_per_step(), 1000.0 * t)) data.push_back(v);
    }
    NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), data).write(dir_ / name);
  }
  TempDir dir_;
  std::vector<std::filesystem::path> inputs_;
};

TEST_F(TimeSeriesMergeTest, MergedAxisIsSortedAndLocationsPointIntoFiles) {
  const InputCatalog c = scan_inputs(inputs_, {});
  EXPECT_EQ(c.time.values, (std::vector<double>{0, 6, 12, 18, 24}));
  ASSERT_EQ(c.files.size(), 3u);  // command-line order
  EXPECT_EQ(c.files[0].path, (dir_ / "middle.nc").string());
  ASSERT_EQ(c.locations[0].size(), 5u);
  const std::vector<std::pair<std::size_t, std::size_t>> expected{
      {2, 0}, {2, 1}, {0, 0}, {0, 1}, {1, 0}};
  for (std::size_t t = 0; t < 5; ++t) {
    EXPECT_EQ(c.locations[0][t].file, expected[t].first) << t;
    EXPECT_EQ(c.locations[0][t].time_in_file, expected[t].second) << t;
  }
  SlabReader reader(c, {});
  std::vector<float> out(2 * 3 * 4);
  for (std::size_t t = 0; t < 5; ++t) {
    reader.read(0, t, 0, 2, out);
    EXPECT_EQ(out[0], static_cast<float>(1000.0 * c.time.values[t])) << t;
    EXPECT_EQ(out[23], static_cast<float>(1000.0 * c.time.values[t] + 23)) << t;
  }
}

TEST_F(TimeSeriesMergeTest, FirstAndLastStepSelectARange) {
  ScanOptions o;
  o.first_step = 1;
  o.last_step = 3;
  const InputCatalog c = scan_inputs(inputs_, o);
  EXPECT_EQ(c.time.values, (std::vector<double>{6, 12, 18}));
  ASSERT_EQ(c.locations[0].size(), 3u);
  EXPECT_EQ(c.locations[0][0].file, 2u);
  EXPECT_EQ(c.locations[0][0].time_in_file, 1u);
  SlabReader reader(c, o);
  std::vector<float> out(2 * 3 * 4);
  reader.read(0, 2, 0, 2, out);
  EXPECT_EQ(out[0], 18000.0f);
}

TEST_F(TimeSeriesMergeTest, OnlyFirstStep) {
  ScanOptions o;
  o.first_step = 4;
  const InputCatalog c = scan_inputs(inputs_, o);
  EXPECT_EQ(c.time.values, (std::vector<double>{24}));
}

TEST_F(TimeSeriesMergeTest, OutOfRangeStepsAreInvalidArguments) {
  ScanOptions o;
  o.last_step = 5;
  expect_error([&] { scan_inputs(inputs_, o); }, ErrorCode::kInvalidArgument,
               {"last time step 5 requested", "5 time steps (0..4)"});
  o.last_step = 1;
  o.first_step = 2;
  expect_error([&] { scan_inputs(inputs_, o); }, ErrorCode::kInvalidArgument,
               {"first time step 2 is after last time step 1"});
  o.last_step.reset();
  o.first_step = 7;
  expect_error([&] { scan_inputs(inputs_, o); }, ErrorCode::kInvalidArgument, {"first time step 7 requested"});
}

}  // namespace
}  // namespace strielad::ingest
