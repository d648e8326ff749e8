// SPDX-License-Identifier: Apache-2.0
// read_vtp on damaged .vtp files (the fuzzer's reproducers in
// tests/fuzz/regressions/vtp_reader/): sizes the file's bytes cannot back, array types
// or formats VTK does not know and compressed arrays of zero blocks are refused with kInvalidInput
// naming the file, before VTK allocates terabytes (std::bad_alloc thrown through VTK) or
// dereferences null (SEGV); so are polygons that refer to points the file does not have.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "readback/vtp_reader.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

const std::filesystem::path kRegressions =
    std::filesystem::path(STRIELAD_SOURCE_DIR) / "tests/fuzz/regressions/vtp_reader";

TEST(VtpReaderDamagedFilesTest, CompressedBlockCountBeyondTheFileIsRefused) {
  const auto path = kRegressions / "compressed-block-count-beyond-file.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "compressed header", "more than its 3729 bytes can hold"});
}

TEST(VtpReaderDamagedFilesTest, CompressedBlockSizeBeyondTheFileIsRefused) {
  const auto path = kRegressions / "compressed-block-size-beyond-file.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput, {path.string(), "compressed header"});
}

TEST(VtpReaderDamagedFilesTest, CompressedArrayOfZeroBlocksIsRefused) {
  const auto path = kRegressions / "compressed-array-of-zero-blocks.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput, {path.string(), "0 blocks"});
}

TEST(VtpReaderDamagedFilesTest, CompressedBlockSizeOfZeroIsRefused) {
  // VTK divides by the block size: SIGFPE (found by the gcc replay's mutations).
  const auto path = kRegressions / "compressed-block-size-zero-sigfpe.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "compressed header has", "blocks of 0 bytes"});
}

TEST(VtpReaderDamagedFilesTest, ArrayOfAnUnknownFormatIsRefused) {
  // "appunded": VTK reads it as appended data, whose compressed header (block size 0)
  // the check skipped for a format it did not know: SIGFPE in VTK.
  const auto path = kRegressions / "unknown-array-format-sigfpe.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "Points", "format 'appunded'"});
}

TEST(VtpReaderDamagedFilesTest, FieldArrayOfAnUnknownTypeIsRefused) {
  const auto path = kRegressions / "unknown-field-array-type.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput, {path.string(), "'Strina'"});
}

TEST(VtpReaderDamagedFilesTest, FieldArrayTypeInsideAQuotedNameIsRefused) {
  // Name="TimeValue type='String'": a text scan saw a type, VTK's XML parser sees none
  // and VTK 9.1 dereferences the null array it makes (SEGV).
  const auto path = kRegressions / "field-array-type-inside-a-quoted-name.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "Array 'TimeValue type='String'' of type ''"});
}

TEST(VtpReaderDamagedFilesTest, FieldChildOfAnotherNameIsCheckedAsAnArray) {
  // <Arrt yaype="String" ...> in FieldData: VTK makes an array of every child whatever
  // its name, gets none without a type and dereferences it (SEGV).
  const auto path = kRegressions / "field-child-not-named-array.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "Arrt 'frame' of type ''"});
}

TEST(VtpReaderDamagedFilesTest, ArrayWithAnOffsetButNoFormatIsCheckedAsAppended) {
  // fozmat="appunded": no format attribute, but an offset, so VTK reads appended data,
  // here a compressed header with blocks of 0 bytes: SIGFPE in VTK.
  const auto path = kRegressions / "offset-without-format-sigfpe.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "compressed header has", "blocks of 0 bytes"});
}

TEST(VtpReaderDamagedFilesTest, TwoArraysOfOneNameAreRefused) {
  // CellData with node_id and face_kind twice: VTK keeps one array per name, reads the
  // elements by index into them and dereferences null past the last (SEGV).
  const auto path = kRegressions / "two-cell-arrays-of-one-name.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "CellData has two arrays named 'node_id'"});
}

TEST(VtpReaderDamagedFilesTest, ComponentCountBelowOneIsRefused) {
  // NumberOfComponents="-3": VTK makes the array, refuses the count and leaks the array.
  const auto path = kRegressions / "negative-component-count-leak.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput,
               {path.string(), "'Normals' has NumberOfComponents '-3'"});
}

TEST(VtpReaderDamagedFilesTest, MoreFieldStringsThanTuplesStayWithinTheArray) {
  // Without its compressor the compressed bytes read as many NUL-terminated strings for
  // a one-tuple array: VTK 9.1 stored them all past the array's end (heap overflow). The
  // array takes one; the file is then refused for its other, unreadable arrays.
  const auto path = kRegressions / "more-field-strings-than-tuples.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput, {path.string()});
}

TEST(VtpReaderDamagedFilesTest, PointCountBeyondTheFileIsRefused) {
  testing::TempDir dir;
  const auto path = dir / "huge.vtp";
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n"
                         "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                         "<PolyData><Piece NumberOfPoints=\"900000000000\" NumberOfPolys=\"0\">\n"
                         "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
                         "0 0 0</DataArray></Points>\n"
                         "</Piece></PolyData></VTKFile>\n";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput, {path.string(), "NumberOfPoints"});
}

TEST(VtpReaderDamagedFilesTest, PolygonReferringToAMissingPointIsRefused) {
  const auto path = kRegressions / "polygon-beyond-the-points.vtp";  // point 3 of 3
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput, {path.string(), "point 3 of 3"});
}

TEST(VtpReaderDamagedFilesTest, PointsWithoutThreeComponentsAreRefused) {
  const auto path = kRegressions / "points-without-three-components.vtp";
  expect_error([&] { read_vtp(path); }, ErrorCode::kInvalidInput, {path.string()});
}

}  // namespace
}  // namespace strielad
