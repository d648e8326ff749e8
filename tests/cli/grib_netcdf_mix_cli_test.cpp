// SPDX-License-Identifier: Apache-2.0
// `strielad-convert` with GRIB and netCDF inputs together (NCEP's AWIPS 211 forecast from
// libncarg-data and its temperature as CF-NetCDF): converts when they agree (exit 0, the
// store's variables from both), exits 4 naming both files when a variable is in both.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <string>

#include "store/store.h"
#include "support/grib_as_netcdf.h"
#include "support/temp_dir.h"

namespace strielad::testing {
namespace {

struct RunResult {
  int status = -1;
  std::string out;  // stdout and stderr
};

RunResult run(const std::string& args) {
  const std::string command = std::string(STRIELAD_CONVERT_EXE) + " " + args + " 2>&1";
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

TEST(GribNetcdfMixCliTest, ConvertsGribAndNetcdfVariablesIntoOneStore) {
  const TempDir dir;
  const auto grib = ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2");
  GribAsNetcdf spec;
  spec.name = "tmp";
  write_grib_variable_as_netcdf(grib, spec, dir / "tmp.nc");
  const auto store = dir / "store";
  const RunResult r = run(grib.string() + " " + (dir / "tmp.nc").string() + " -o " +
                          store.string() + " --vars gh,tmp --brick 16");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto s = Store::open(store);
  ASSERT_EQ(s->manifest().variables.size(), 2u);
  EXPECT_EQ(s->manifest().variables[0].name, "gh");
  EXPECT_EQ(s->manifest().variables[1].name, "tmp");
}

TEST(GribNetcdfMixCliTest, AVariableInBothFormatsExitsWithInvalidInput) {
  const TempDir dir;
  const auto grib = ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2");
  write_grib_variable_as_netcdf(grib, {}, dir / "t.nc");
  const RunResult r =
      run(grib.string() + " " + (dir / "t.nc").string() + " -o " + (dir / "store").string());
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("variable 't'"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fh.0012_tl.press_gr.awp211.grb2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("t.nc"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace strielad::testing
