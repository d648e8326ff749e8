// SPDX-License-Identifier: Apache-2.0
// Level 0 of a store equals the input exactly, for every variable, fill positions
// included, and neighbouring bricks agree on their shared boundary samples.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "convert/converter.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/store_level0.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::TempDir;
using testing::assemble_level0;

bool same_bits(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ConvertRoundTripTest, LevelZeroEqualsTheInputExactlyIncludingFill) {
  TempDir dir;
  const auto data = testing::write_small_dataset(dir.path());
  const auto options = testing::small_convert_options(data, dir / "store");
  const build::ConvertResult r = build::convert(options);
  EXPECT_EQ(r.steps_converted, 2u);
  EXPECT_TRUE(r.finalized);

  const auto store = Store::open(dir / "store");
  const auto catalog = ingest::scan_inputs(data.files, {});
  ingest::SlabReader reader(catalog, {});
  ASSERT_EQ(store->variable_count(), 3u);
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
    const auto& var = store->manifest().variables[v];
    for (std::uint32_t t = 0; t < 2; ++t) {
      std::vector<double> expected(data.nx * data.ny * data.nz);
      reader.read(catalog.variable_index(var.name), t, 0, data.nz, expected);
      const auto actual = assemble_level0(*store, t, v);
      std::size_t mismatches = 0, fills = 0;
      for (std::size_t i = 0; i < expected.size(); ++i) {
        // The store keeps the variable's own type: compare after the same rounding.
        const double want = var.dtype == DType::kFloat32
                                ? static_cast<double>(static_cast<float>(expected[i]))
                                : expected[i];
        mismatches += !same_bits(want, actual[i]);
        fills += std::isnan(want);
      }
      EXPECT_EQ(mismatches, 0u) << var.name << " step " << t;
      if (var.name != "temp") {
        EXPECT_GT(fills, 0u) << var.name << " should have fill samples";
      }
    }
  }
}

TEST(ConvertRoundTripTest, StoreKeepsTypesAxesAndTimeExactly) {
  TempDir dir;
  const auto data = testing::write_small_dataset(dir.path());
  build::convert(testing::small_convert_options(data, dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto catalog = ingest::scan_inputs(data.files, {});
  const auto& m = store->manifest();
  EXPECT_EQ(m.x.values, catalog.x.values);
  EXPECT_EQ(m.y.values, catalog.y.values);
  EXPECT_TRUE(m.y.descending());
  EXPECT_EQ(m.z.values, catalog.z.values);
  EXPECT_EQ(m.time.values, (std::vector<double>{0.0, 300.0}));
  EXPECT_EQ(m.variables[m.variable_index("cloud")].dtype, DType::kFloat32);
  EXPECT_EQ(m.variables[m.variable_index("temp")].dtype, DType::kFloat64);
  EXPECT_EQ(m.variables[m.variable_index("packed")].dtype, DType::kFloat32);
  EXPECT_EQ(m.variables[m.variable_index("packed")].scale_factor, std::optional<double>(0.01f));
}

TEST(ConvertRoundTripTest, SparseCloudsStoreNoVoxelDataForEmptyAndConstantBricks) {
  TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 40, 30, 12, 1);
  build::convert(testing::small_convert_options(data, dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto entries = store->index(0, static_cast<std::uint32_t>(store->manifest().variable_index("cloud")));
  std::size_t constant = 0, data_bricks = 0;
  for (const auto& e : entries) {
    constant += e.kind == format::BrickKind::kConstant;
    data_bricks += e.kind == format::BrickKind::kData;
    if (e.kind != format::BrickKind::kData) {
      EXPECT_EQ(e.chunk_size, 0u);
    }
  }
  EXPECT_GT(constant, 0u);
  EXPECT_GT(data_bricks, 0u);
}

TEST(ConvertRoundTripTest, ConversionIsDeterministic) {
  TempDir dir;
  const auto data = testing::write_small_dataset(dir.path());
  auto a = testing::small_convert_options(data, dir / "a");
  auto b = testing::small_convert_options(data, dir / "b");
  a.threads = 1;
  build::convert(a);
  build::convert(b);
  for (const char* f : {"MANIFEST", "steps/step-000000.bricks", "steps/step-000001.bricks"}) {
    std::ifstream fa(dir / "a" / f, std::ios::binary), fb(dir / "b" / f, std::ios::binary);
    const std::string sa((std::istreambuf_iterator<char>(fa)), {});
    const std::string sb((std::istreambuf_iterator<char>(fb)), {});
    EXPECT_FALSE(sa.empty());
    EXPECT_TRUE(sa == sb) << f << " differs between a 1-thread and a 2-thread conversion";
  }
}

}  // namespace
}  // namespace strielad
