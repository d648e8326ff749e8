// SPDX-License-Identifier: Apache-2.0
// Grids too large for a chunk or for the machine's memory are refused from their size
// alone, before anything is read, allocated or written (docs/robustness.md, "Very large
// grids").
#include <gtest/gtest.h>

#include <chrono>

#include "convert/conversion_limits.h"
#include "convert/converter.h"
#include "robust/case_netcdf.h"
#include "robust/extreme_cases.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad::build {
namespace {

using testing::expect_error;

TEST(ConversionLimitsTest, BrickLargerThanAChunkIsRefusedNamingTheLargestThatFits) {
  const OctreeLayout layout(Dims3{1025, 1025, 1025}, 1024);
  expect_error([&] { check_brick_fits_chunk(layout, DType::kFloat32, "f"); },
               ErrorCode::kInvalidArgument,
               {"brick 1024", "variable 'f'", "1025x1025x1025 float32", "use --brick 811 or smaller"});
  expect_error([&] { check_brick_fits_chunk(layout, DType::kFloat64, "d"); },
               ErrorCode::kInvalidArgument, {"use --brick 644 or smaller"});
  // 811 cells (812 samples) per edge is the largest float32 brick that fits.
  EXPECT_NO_THROW(check_brick_fits_chunk(OctreeLayout(Dims3{1025, 1025, 1025}, 811),
                                         DType::kFloat32, "f"));
}

TEST(ConversionLimitsTest, LargeBricksOnSmallOrFlatGridsFit) {
  EXPECT_NO_THROW(check_brick_fits_chunk(OctreeLayout(Dims3{30, 30, 30}, 1024), DType::kFloat64, "f"));
  EXPECT_NO_THROW(
      check_brick_fits_chunk(OctreeLayout(Dims3{4096, 4096, 2}, 1024), DType::kFloat64, "f"));
}

TEST(ConversionLimitsTest, MemoryEstimateOf2To31Cells) {
  const OctreeLayout layout(Dims3{2048, 2048, 512}, 24);
  const ConversionMemory m = estimate_conversion_memory(layout, DType::kFloat32, 4, 2);
  EXPECT_EQ(m.slabs, 2);
  EXPECT_EQ(m.slab_bytes, 2048.0 * 2048 * 27 * 4);  // B + 3 planes
  EXPECT_EQ(m.coarse_bytes, 2.0 * 1025 * 1025 * 257 * 4 + 513.0 * 513 * 129 * 4);
  EXPECT_GT(m.total_bytes, 4e9);
  EXPECT_LT(m.total_bytes, 6e9);
  // More threads, more slabs in flight; a single level of 2^32 samples is 17 GB a slab.
  EXPECT_EQ(estimate_conversion_memory(layout, DType::kFloat32, 4, 16).slabs, 16);
  const OctreeLayout flat(Dims3{65536, 65536, 1}, 24);
  EXPECT_EQ(estimate_conversion_memory(flat, DType::kFloat32, 4, 1).slab_bytes,
            65536.0 * 65536 * 4);
}

TEST(ConversionLimitsTest, MemoryLimitRefusalSaysWhatToDo) {
  const OctreeLayout layout(Dims3{2048, 2048, 512}, 24);
  expect_error([&] { check_conversion_memory(layout, DType::kFloat32, 4, 2, 1ull << 30, "clw"); },
               ErrorCode::kUnsupported,
               {"grid 2048x2048x512", "variable 'clw' (float32)", "GB of memory to convert",
                "2 slabs in flight", "27 planes of 2048x2048 samples", "more than the 1.1 GB allowed",
                "fewer --threads"});
  EXPECT_NO_THROW(check_conversion_memory(layout, DType::kFloat32, 4, 2, 64ull << 30, "clw"));
}

TEST(ConversionLimitsTest, ConvertRefusesAHugeDeclaredGridBeforeWritingAnything) {
  testing::TempDir dir;
  const robust::ExtremeCase c = robust::extreme_case("2^31-cells");
  robust::write_case_netcdf(c, dir / "huge.nc");
  EXPECT_LT(std::filesystem::file_size(dir / "huge.nc"), 1u << 20);  // declared, not written
  ConvertOptions o;
  o.inputs = {dir / "huge.nc"};
  o.store = dir / "store";
  o.brick = 24;
  o.threads = 2;
  o.memory_limit = 1ull << 30;
  const auto started = std::chrono::steady_clock::now();
  expect_error([&] { convert(o); }, ErrorCode::kUnsupported,
               {"grid 2048x2048x512", "variable 'f'", "GB of memory to convert"});
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
  EXPECT_FALSE(std::filesystem::exists(dir / "store" / "MANIFEST"));
}

}  // namespace
}  // namespace strielad::build
