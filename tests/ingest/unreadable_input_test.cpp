// SPDX-License-Identifier: Apache-2.0
// Missing, non-netCDF and truncated inputs fail with an error naming the file, never a
// crash and never silently zero-filled data.
#include <gtest/gtest.h>

#include <fstream>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

TEST(UnreadableInputTest, MissingFileIsNotFound) {
  TempDir dir;
  expect_error([&] { scan_inputs({dir / "nope.nc"}, {}); }, ErrorCode::kNotFound,
               {(dir / "nope.nc").string(), "no such file"});
}

TEST(UnreadableInputTest, TextFileIsNotNetcdf) {
  TempDir dir;
  std::ofstream(dir / "notes.nc") << "this is not a netCDF file, just some text\n";
  expect_error([&] { scan_inputs({dir / "notes.nc"}, {}); }, ErrorCode::kInvalidInput,
               {(dir / "notes.nc").string(), "not a readable netCDF file", "NetCDF:"});
}

TEST(UnreadableInputTest, DirectoryIsRefused) {
  TempDir dir;
  expect_error([&] { scan_inputs({dir.path()}, {}); }, ErrorCode::kInvalidInput,
               {dir.path().string(), "directory"});
}

TEST(UnreadableInputTest, ClassicFileTruncatedToHalf) {
  TempDir dir;
  const auto src = ncarg_file("nug/rectilinear_grid_3D.nc");
  copy_truncated(src, dir / "half.nc", std::filesystem::file_size(src) / 2);
  expect_error([&] { scan_inputs({dir / "half.nc"}, {}); }, ErrorCode::kInvalidInput,
               {(dir / "half.nc").string(), "truncated"});
}

TEST(UnreadableInputTest, ClassicFileTruncatedInsideHeader) {
  TempDir dir;
  copy_truncated(ncarg_file("cdf/contour.cdf"), dir / "head.nc", 300);
  expect_error([&] { scan_inputs({dir / "head.nc"}, {}); }, ErrorCode::kInvalidInput,
               {(dir / "head.nc").string(), "truncated"});
}

TEST(UnreadableInputTest, ClassicMagicAloneIsInvalidInput) {
  // Only the 4 bytes of a classic, 64-bit offset or CDF-5 magic (and a few more): an
  // unusable input naming the file (exit 4), not an I/O error.
  TempDir dir;
  for (const std::string& bytes : {std::string("CDF\x01", 4), std::string("CDF\x02", 4),
                                  std::string("CDF\x05", 4), std::string("CDF\x01\0\0", 6)}) {
    const auto path = dir / "magic.nc";
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    expect_error([&] { scan_inputs({path}, {}); }, ErrorCode::kInvalidInput,
                 {path.string(), "truncated"});
  }
}

TEST(UnreadableInputTest, ClassicHeaderNetcdfAnswersWithAnErrnoIsInvalidInput) {
  // The classic magic followed by 0xff bytes: netCDF-C answered EINVAL, a system errno,
  // which was taken for an I/O error (kIo, exit 7). The file reads fine; its content is
  // bad (the classic-header grammar check now refuses it before netCDF-C reads it).
  TempDir dir;
  for (const std::size_t n : {12, 32}) {
    const auto path = dir / "damaged.nc";
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        << std::string("CDF\x01", 4) + std::string(n, '\xff');
    expect_error([&] { scan_inputs({path}, {}); }, ErrorCode::kInvalidInput,
                 {path.string(), "not a readable netCDF file"});
  }
}

TEST(UnreadableInputTest, Netcdf4FileTruncatedToHalf) {
  TempDir dir;
  const auto src = ncarg_file("cdf/nc4uvt.nc");
  copy_truncated(src, dir / "half4.nc", std::filesystem::file_size(src) / 2);
  expect_error([&] { scan_inputs({dir / "half4.nc"}, {}); }, ErrorCode::kInvalidInput,
               {(dir / "half4.nc").string()});
}

TEST(UnreadableInputTest, FileTruncatedAfterScanFailsToRead) {
  TempDir dir;
  const auto src = ncarg_file("cdf/contour.cdf");
  std::filesystem::copy_file(src, dir / "c.nc");
  const InputCatalog c = scan_inputs({dir / "c.nc"}, {});
  std::filesystem::resize_file(dir / "c.nc", std::filesystem::file_size(src) / 2);
  SlabReader reader(c, {});
  std::vector<float> out(c.dims().count());
  expect_error([&] { reader.read(0, 6, 0, c.dims().z, out); }, ErrorCode::kInvalidInput,
               {(dir / "c.nc").string(), "changed since it was scanned"});
}

}  // namespace
}  // namespace strielad::ingest
