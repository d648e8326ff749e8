// SPDX-License-Identifier: Apache-2.0
// `strielad-sample` end to end: flags, --json summary, exit statuses.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

struct RunResult {
  int status = -1;
  std::string out;
};

RunResult run_sample(const std::string& args) {
  const std::string command = std::string(STRIELAD_SAMPLE_EXE) + " " + args + " 2>/dev/null";
  RunResult r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int raw = ::pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

TEST(SampleCliTest, WritesFilesAndPrintsJsonSummary) {
  TempDir dir;
  const auto out = dir.path() / "new" / "dir";
  const RunResult r = run_sample("-q -o " + out.string() +
                                  " --dims 9x7x5 --steps 2 --seed 3 --vars clw,ta"
                                  " --step-seconds 120 --deflate 1 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json.at("files").size(), 2u);
  EXPECT_EQ(json.at("dims"), nlohmann::json({9, 7, 5}));
  EXPECT_EQ(json.at("steps"), 2);
  EXPECT_GE(json.at("seconds").get<double>(), 0.0);
  std::uint64_t bytes = 0;
  for (const auto& f : json.at("files")) {
    ASSERT_TRUE(std::filesystem::is_regular_file(f.get<std::string>()));
    bytes += std::filesystem::file_size(f.get<std::string>());
  }
  EXPECT_EQ(json.at("bytes").get<std::uint64_t>(), bytes);

  const NcFile f(out / "sample_t001.nc");
  EXPECT_TRUE(f.has_var("clw"));
  EXPECT_TRUE(f.has_var("ta"));
  EXPECT_FALSE(f.has_var("ua"));
  EXPECT_EQ(f.doubles("time"), std::vector<double>{120.0});
  unsigned long long seed = 0;
  ASSERT_EQ(nc_get_att_ulonglong(f.id(), NC_GLOBAL, "seed", &seed), NC_NOERR);
  EXPECT_EQ(seed, 3u);
}

TEST(SampleCliTest, SingleFileFlag) {
  TempDir dir;
  const RunResult r =
      run_sample("-q -o " + dir.path().string() + " --dims 4x4x3 --steps 3 --single-file");
  ASSERT_EQ(r.status, 0);
  EXPECT_TRUE(r.out.empty()) << "stdout stays empty without --json";
  const NcFile f(dir.path() / "sample.nc");
  EXPECT_EQ(f.dim_length("time"), 3u);
  EXPECT_EQ(f.doubles("time"), (std::vector<double>{0.0, 300.0, 600.0}));
  EXPECT_TRUE(f.has_var("wa")) << "all variables by default";
}

TEST(SampleCliTest, BadArgumentsExitWithTheirStatus) {
  TempDir dir;
  const std::string o = " -o " + (dir.path() / "x").string();
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x0x3").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims banana").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --vars clw,nope").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --steps 0").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --deflate 12").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --steps -1").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --seed -5").status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x"));
  std::ofstream(dir.path() / "file") << "x";
  EXPECT_EQ(run_sample("-o " + (dir.path() / "file" / "sub").string() + " --dims 4x4x3")
                .status,
            7);
  EXPECT_NE(run_sample("--dims 4x4x3").status, 0) << "-o is required";
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --model mm5").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --model icon --vars ta").status, 2);
  EXPECT_EQ(run_sample(o.substr(1) + " --dims 4x4x3 --model icon-cf --z-mc").status, 2);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x"));
}

TEST(SampleCliTest, ModelFlagWritesModelLikeFiles) {
  TempDir dir;
  RunResult r = run_sample("-q -o " + dir.path().string() +
                           " --dims 6x5x4 --steps 2 --model icon --z-mc --json");
  ASSERT_EQ(r.status, 0) << r.out;
  auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json.at("model"), "icon");
  ASSERT_EQ(json.at("files").size(), 2u);
  const NcFile icon(dir.path() / "icon_t001.nc");
  EXPECT_EQ(icon.dim_length("height_2"), 5u);
  EXPECT_TRUE(icon.has_var("z_ifc"));
  EXPECT_TRUE(icon.has_var("z_mc"));

  r = run_sample("-q -o " + dir.path().string() +
                 " --dims 6x5x4 --steps 2 --single-file --model sigma-pressure");
  ASSERT_EQ(r.status, 0);
  const NcFile sigma(dir.path() / "sigma_pressure.nc");
  EXPECT_EQ(sigma.dim_length("time"), 2u);
  EXPECT_TRUE(sigma.has_var("ps"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "sample.nc"));

  r = run_sample("-q -o " + dir.path().string() +
                 " --dims 6x5x4 --steps 2 --step-seconds 3600 --model wrf --json");
  ASSERT_EQ(r.status, 0) << r.out;
  json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json.at("model"), "wrf");
  ASSERT_EQ(json.at("files").size(), 2u);
  const NcFile wrf(dir.path() / "wrfout_d01_2013-04-26_13:00:00");
  EXPECT_EQ(wrf.dim_length("Time"), 1u);
  EXPECT_EQ(wrf.dim_length("west_east_stag"), 7u);
  EXPECT_TRUE(wrf.has_var("PHB"));
}

}  // namespace
}  // namespace strielad::testing
