// SPDX-License-Identifier: Apache-2.0
// GRIB files (libncarg-data) are recognised and listed through ecCodes; what a conversion
// cannot take (netCDF on another grid, a reduced grid, no 3-D field, a damaged message) is
// refused by name. ecCodes' own messages never reach stderr.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "ingest/grib_messages.h"
#include "ingest/input_catalog.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::ncarg_file;

TEST(GribInputTest, ListsEveryMessageOfARealGrib2File) {
  const auto messages = list_grib_messages(ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2"));
  ASSERT_EQ(messages.size(), 181u);  // grib_count says 181
  EXPECT_EQ(messages.front().offset, 0u);
  EXPECT_EQ(messages.front().edition, 2);
  EXPECT_EQ(messages.front().short_name, "mslet");
  EXPECT_EQ(messages.front().type_of_level, "meanSea");
  EXPECT_EQ(messages.front().grid_type, "lambert");
  for (std::size_t i = 1; i < messages.size(); ++i) {
    EXPECT_EQ(messages[i].offset, messages[i - 1].offset + messages[i - 1].size) << i;
  }
  EXPECT_EQ(messages.back().offset + messages.back().size,
            std::filesystem::file_size(ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2")));
}

TEST(GribInputTest, MixingWithNetcdfOnAnotherGridIsRefused) {
  // contour.cdf lies on longitudes and latitudes, the forecast on a Lambert projection.
  expect_error(
      [] {
        scan_inputs(
            {ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2"), ncarg_file("cdf/contour.cdf")}, {});
      },
      ErrorCode::kInvalidInput,
      {"contour.cdf", "not on the grid of GRIB input", "fh.0012_tl.press_gr.awp211.grb2"});
}

TEST(GribInputTest, ReducedGridIsRefusedWithHowToRegridIt) {
  ::testing::internal::CaptureStderr();
  expect_error([] { scan_inputs({ncarg_file("grb/wafsgfs_L_t06z_intdsk60.grib2")}, {}); },
               ErrorCode::kUnsupported,
               {"wafsgfs_L_t06z_intdsk60.grib2", "reduced_ll", "cdo setgridtype,regular"});
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(GribInputTest, SatelliteImageWithNoLevelsIsNot3D) {
  expect_error([] { scan_inputs({ncarg_file("grb/MET9_IR108_cosmode_0909210000.grb2")}, {}); },
               ErrorCode::kInvalidInput,
               {"MET9_IR108_cosmode_0909210000.grb2", "no 3-D field", "OBSMSG_BT_IR10.8"});
}

TEST(GribInputTest, AVariableNoInputHasIsNamedWithThoseThereAre) {
  ScanOptions o;
  o.variables = {"q"};
  expect_error([&] { scan_inputs({ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2")}, o); },
               ErrorCode::kNotFound, {"no GRIB variable 'q'", "gh", "absv"});
}

TEST(GribInputTest, DamagedGrib1NamesTheMessageAndWhatEcCodesSaid) {
  ::testing::internal::CaptureStderr();
  // Its messages refer to NCEP predefined grid 6 with no grid description section, and
  // ecCodes then misses each message's end.
  expect_error([] { list_grib_messages(ncarg_file("grb/ced1.lf00.t00z.eta.grb")); },
               ErrorCode::kInvalidInput,
               {"ced1.lf00.t00z.eta.grb", "GRIB message 1", "grid_6", "No final 7777"});
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(GribInputTest, TruncatedMessageIsNamed) {
  const testing::TempDir dir;
  const auto source = ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2");
  const auto messages = list_grib_messages(source);
  // The first message whole, then the second cut in half.
  const std::uint64_t keep = messages[1].offset + messages[1].size / 2;
  std::vector<char> head(keep);
  std::ifstream(source, std::ios::binary).read(head.data(), static_cast<std::streamsize>(keep));
  std::ofstream(dir / "cut.grb2", std::ios::binary)
      .write(head.data(), static_cast<std::streamsize>(keep));
  ::testing::internal::CaptureStderr();
  expect_error([&] { list_grib_messages(dir / "cut.grb2"); }, ErrorCode::kInvalidInput,
               {"cut.grb2", "GRIB message 2"});
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(GribInputTest, MissingFileIsNotFound) {
  expect_error([] { list_grib_messages("/nonexistent/x.grb2"); }, ErrorCode::kNotFound,
               {"/nonexistent/x.grb2"});
}

}  // namespace
}  // namespace strielad::ingest
