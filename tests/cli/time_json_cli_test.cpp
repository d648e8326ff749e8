// SPDX-License-Identifier: Apache-2.0
// The --json outputs that report a time step give its date beside the raw value:
// `strielad-convert info --json` (a date per value), `export-vdb --json` and
// `strielad-serve extract --json` (.vtp and .vdb): {"step", "value", "units", "calendar",
// "date"}, or "date": null and "date_error" when the store's time has no dates.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "convert/converter.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::testing {
namespace {

struct RunResult {
  int status = -1;
  std::string out;
};

RunResult run(const std::string& exe, const std::string& args) {
  const std::string command = exe + " " + args + " 2>/dev/null";
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

// A store of "t" on a small grid with the given time axis.
std::filesystem::path make_store(const TempDir& dir, std::vector<double> time,
                                 const std::string& units, const std::string& calendar) {
  SimpleGrid g;
  g.time = std::move(time);
  g.time_units = units;
  g.calendar = calendar;
  NetcdfFixture()
      .grid(g)
      .variable("t", NC_FLOAT, g.dims(), ramp(g.samples(), 250.0, 1.0))
      .write(dir / "in.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "in.nc"};
  o.store = dir / "store";
  o.brick = 2;
  o.threads = 1;
  build::convert(o);
  return o.store;
}

TEST(TimeJsonCliTest, InfoJsonListsADatePerTimeValue) {
  TempDir dir;
  // Python: datetime(1949, 12, 1) + timedelta(days=20500.5) = 2006-01-16 12:00.
  const auto store = make_store(dir, {20500, 20500.5}, "days since 1949-12-01 00:00:00",
                                "proleptic_gregorian");
  const RunResult r = run(STRIELAD_CONVERT_EXE, "info --json " + store.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto time = nlohmann::json::parse(r.out).at("time");
  EXPECT_EQ(time.at("values"), nlohmann::json({20500.0, 20500.5}));
  EXPECT_EQ(time.at("dates"), nlohmann::json({"2006-01-16T00:00:00Z", "2006-01-16T12:00:00Z"}));
}

TEST(TimeJsonCliTest, ExportVdbJsonHasTheStepsDateOrWhyNot) {
  TempDir dir;
  const auto store = make_store(dir, {0, 973356}, "hours since 1900-01-01", "noleap");
  const RunResult r = run(STRIELAD_CONVERT_EXE, "export-vdb " + store.string() +
                                                    " --var t --time 1 -o " +
                                                    (dir / "t.vdb").string() + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  // noleap: 973356 h = 40556.5 days = 111 years of 365 days + 41.5 days: February 11.
  EXPECT_EQ(nlohmann::json::parse(r.out).at("time"),
            nlohmann::json({{"step", 1},
                            {"value", 973356.0},
                            {"units", "hours since 1900-01-01"},
                            {"calendar", "noleap"},
                            {"date", "2011-02-11T12:00:00Z"}}));

  TempDir plain;
  const auto hours = make_store(plain, {0, 6}, "hours", "");
  const RunResult p = run(STRIELAD_CONVERT_EXE, "export-vdb " + hours.string() +
                                                    " --var t --time 1 -o " +
                                                    (plain / "t.vdb").string() + " --json");
  ASSERT_EQ(p.status, 0) << p.out;
  const auto time = nlohmann::json::parse(p.out).at("time");
  EXPECT_EQ(time.at("value"), 6.0);
  EXPECT_TRUE(time.at("date").is_null());
  EXPECT_NE(time.at("date_error").get<std::string>().find("no reference date"), std::string::npos);
}

TEST(TimeJsonCliTest, ServeExtractJsonHasTheStepsDate) {
  TempDir dir;
  const auto store = make_store(dir, {0, 59}, "days since 2000-01-01", "360_day");
  std::ofstream(dir / "scene.json")
      << R"({"subvolumes": [{"id": 1, "limits": [{"var": "t", "min": 260}]}]})";
  for (const char* output : {"out.vtp", "out.vdb"}) {
    const RunResult r =
        run(STRIELAD_SERVE_EXE, "extract --store " + store.string() + " --scene " +
                                    (dir / "scene.json").string() + " --time 1 -o " +
                                    (dir / output).string() + " --json");
    ASSERT_EQ(r.status, 0) << output << ": " << r.out;
    const auto time = nlohmann::json::parse(r.out).at("time");
    EXPECT_EQ(time.at("step"), 1) << output;
    // 360_day: 59 days after January 1st is February 30.
    EXPECT_EQ(time.at("date"), "2000-02-30T00:00:00Z") << output;
  }
}

}  // namespace
}  // namespace strielad::testing
