// SPDX-License-Identifier: Apache-2.0
// Inputs are told apart by content, never by name: the real files of libncarg-data, a
// GRIB message behind a WMO bulletin header, HDF5's superblock at 512 bytes, and files
// that are none of these.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "ingest/input_kind.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::ncarg_file;

std::vector<std::byte> bytes(std::string_view text) {
  std::vector<std::byte> out(text.size());
  std::memcpy(out.data(), text.data(), text.size());
  return out;
}

TEST(InputKindDetectionTest, RealFilesOfEachKind) {
  EXPECT_EQ(detect_input_kind(ncarg_file("cdf/contour.cdf")).kind, InputKind::kNetcdfClassic);
  EXPECT_EQ(detect_input_kind(ncarg_file("cdf/nc4uvt.nc")).kind, InputKind::kNetcdf4);
  const InputKindGuess grib1 = detect_input_kind(ncarg_file("grb/ced1.lf00.t00z.eta.grb"));
  EXPECT_EQ(grib1.kind, InputKind::kGrib);
  EXPECT_EQ(grib1.grib_edition, 1);
  const InputKindGuess grib2 = detect_input_kind(ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2"));
  EXPECT_EQ(grib2.kind, InputKind::kGrib);
  EXPECT_EQ(grib2.grib_edition, 2);
  EXPECT_EQ(grib2.grib_offset, 0u);
}

TEST(InputKindDetectionTest, GribAfterAWmoHeaderIsFoundAtItsOffset) {
  std::vector<std::byte> head = bytes("\x01\r\r\n123\r\r\nYTPB85 KWBC 311200\r\r\n");
  const std::size_t at = head.size();
  const auto message = bytes(std::string("GRIB\0\0\0\x02", 8));
  head.insert(head.end(), message.begin(), message.end());
  const InputKindGuess g = detect_input_kind(head);
  EXPECT_EQ(g.kind, InputKind::kGrib);
  EXPECT_EQ(g.grib_edition, 2);
  EXPECT_EQ(g.grib_offset, at);
}

TEST(InputKindDetectionTest, HdfSignatureAfterAUserBlock) {
  std::vector<std::byte> head(512, std::byte{0});
  const auto signature = bytes(std::string("\x89HDF\r\n\x1a\n", 8));
  head.insert(head.end(), signature.begin(), signature.end());
  EXPECT_EQ(detect_input_kind(head).kind, InputKind::kNetcdf4);
  head.erase(head.begin());  // at 511: not where HDF5 puts it
  EXPECT_EQ(detect_input_kind(head).kind, InputKind::kUnknown);
}

TEST(InputKindDetectionTest, LookalikesAreUnknown) {
  EXPECT_EQ(detect_input_kind(bytes("CDF\x03")).kind, InputKind::kUnknown);  // no such version
  EXPECT_EQ(detect_input_kind(bytes(std::string("GRIB\0\0\0\x07", 8))).kind,
            InputKind::kUnknown);                                         // no such edition
  EXPECT_EQ(detect_input_kind(bytes("GRIB")).kind, InputKind::kUnknown);  // cut before it
  EXPECT_EQ(detect_input_kind(bytes("netcdf x {\n}\n")).kind, InputKind::kUnknown);  // CDL
  EXPECT_EQ(detect_input_kind(std::vector<std::byte>{}).kind, InputKind::kUnknown);
}

TEST(InputKindDetectionTest, OnlyTheFirst64KiBAreLookedAt) {
  std::vector<std::byte> head(kInputKindHeadBytes, std::byte{' '});
  const auto message = bytes(std::string("GRIB\0\0\0\x02", 8));
  head.insert(head.end(), message.begin(), message.end());
  EXPECT_EQ(detect_input_kind(head).kind, InputKind::kUnknown);
}

TEST(InputKindDetectionTest, EmptyFileIsUnknown) {
  const testing::TempDir dir;
  std::ofstream(dir / "empty.nc").close();
  EXPECT_EQ(detect_input_kind(dir / "empty.nc").kind, InputKind::kUnknown);
}

}  // namespace
}  // namespace strielad::ingest
