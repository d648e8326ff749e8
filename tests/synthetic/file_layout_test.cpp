// SPDX-License-Identifier: Apache-2.0
// One file per time step (sample_t000.nc, ...) or one file with every step; both hold
// the same data, and no temporary files stay behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

std::vector<std::string> directory_names(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(SampleFileLayoutTest, FilePerStepWritesNumberedFiles) {
  auto spec = small_spec(Dims3{10, 9, 8}, 3);
  spec.variables = {"clw", "ta"};
  spec.step_seconds = 300;
  const GeneratedSample s(spec);
  EXPECT_EQ(directory_names(s.dir.path()),
            (std::vector<std::string>{"sample_t000.nc", "sample_t001.nc", "sample_t002.nc"}));
  ASSERT_EQ(s.result.files.size(), 3u);
  std::uint64_t total = 0;
  for (std::size_t t = 0; t < 3; ++t) {
    EXPECT_EQ(s.file(t).filename(), synthetic::sample_file_names(spec)[t]);
    EXPECT_EQ(s.result.files[t].bytes, std::filesystem::file_size(s.file(t)));
    total += s.result.files[t].bytes;
    const NcFile f(s.file(t));
    EXPECT_EQ(f.dim_length("time"), 1u);
    EXPECT_EQ(f.doubles("time"), std::vector<double>{300.0 * static_cast<double>(t)});
  }
  EXPECT_EQ(s.result.bytes, total);
}

TEST(SampleFileLayoutTest, SingleFileHoldsAllStepsWithTheSameData) {
  auto spec = small_spec(Dims3{10, 9, 8}, 3);
  spec.variables = {"clw", "ta", "wa"};
  const GeneratedSample per_step(spec);
  spec.file_per_step = false;
  const GeneratedSample single(spec);
  EXPECT_EQ(directory_names(single.dir.path()), std::vector<std::string>{"sample.nc"});
  ASSERT_EQ(single.result.files.size(), 1u);
  const NcFile all(single.file());
  EXPECT_EQ(all.dim_length("time"), 3u);
  EXPECT_EQ(all.doubles("time"), (std::vector<double>{0.0, 300.0, 600.0}));
  for (std::size_t t = 0; t < 3; ++t) {
    const NcFile one(per_step.file(t));
    for (const char* name : {"clw", "ta", "wa"}) {
      const auto a = all.step(name, t), b = one.step(name, 0);
      ASSERT_EQ(a.size(), b.size());
      EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0)
          << name << " step " << t;
    }
  }
}

TEST(SampleFileLayoutTest, RerunReplacesFilesAndCreatesMissingDirectories) {
  TempDir dir;
  const auto out = dir.path() / "a" / "b";
  auto spec = small_spec(Dims3{4, 4, 4}, 1);
  spec.variables = {"ta"};
  synthetic::write_sample_dataset(spec, out);
  spec.seed = 7;
  const auto result = synthetic::write_sample_dataset(spec, out);
  EXPECT_EQ(directory_names(out), std::vector<std::string>{"sample_t000.nc"});
  const NcFile f(result.files.at(0).path);
  unsigned long long seed = 0;
  ASSERT_EQ(nc_get_att_ulonglong(f.id(), NC_GLOBAL, "seed", &seed), NC_NOERR);
  EXPECT_EQ(seed, 7u);
}

TEST(SampleFileLayoutTest, ProgressCountsEveryLevelOnce) {
  TempDir dir;
  auto spec = small_spec(Dims3{5, 4, 7}, 2);
  spec.variables = {"ta", "qr", "ua"};
  std::vector<std::uint64_t> seen;
  std::uint64_t reported_total = 0;
  synthetic::write_sample_dataset(spec, dir.path(), [&](std::uint64_t done, std::uint64_t total) {
    seen.push_back(done);
    reported_total = total;
  });
  EXPECT_EQ(reported_total, 2u * 3u * 7u);
  ASSERT_EQ(seen.size(), reported_total);
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], i + 1);
}

}  // namespace
}  // namespace strielad::testing
