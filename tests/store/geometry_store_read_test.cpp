// SPDX-License-Identifier: Apache-2.0
// A format-5 store opens and its geometry reads back (lib/store/store.h): the vertical
// field from geometry.bricks (one brick for every step, cached once) or from each step
// file's section V, with index statistics equal to the samples' range, and the GEOMETRY
// file's coordinates and surface as written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "convert/geometry_writer.h"
#include "core/checksum.h"
#include "store/brick_codec.h"
#include "store/brick_cache.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/geometry_store.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;
using testing::GeometryField;
using testing::GeometryStoreSpec;

// Every sample of the brick equals `at` at its level-0 position.
template <typename At>
void expect_brick_samples(const OctreeLayout& layout, const Brick& b, const At& at) {
  const NodeKey key = layout.key(b.node);
  std::size_t i = 0;
  for (std::size_t z = b.box.lo[2]; z <= b.box.hi[2]; ++z) {
    for (std::size_t y = b.box.lo[1]; y <= b.box.hi[1]; ++y) {
      for (std::size_t x = b.box.lo[0]; x <= b.box.hi[0]; ++x, ++i) {
        const double want =
            at(layout.fine_index(key.level, 0, x), layout.fine_index(key.level, 1, y),
               layout.fine_index(key.level, 2, z));
        ASSERT_EQ(b.sample(i), want) << "node " << b.node << " sample " << i;
      }
    }
  }
}

// The recorded range and count of every node are those of the field over its level-0 box.
template <typename At>
void expect_index_statistics(const OctreeLayout& layout,
                             std::span<const format::IndexEntry> entries, const At& at) {
  ASSERT_EQ(entries.size(), layout.node_count());
  for (NodeId n = 0; n < entries.size(); ++n) {
    const NodeKey key = layout.key(n);
    const IndexBox fine = layout.fine_box(key);
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t z = fine.lo[2]; z <= fine.hi[2]; ++z) {
      for (std::size_t y = fine.lo[1]; y <= fine.hi[1]; ++y) {
        for (std::size_t x = fine.lo[0]; x <= fine.hi[0]; ++x) {
          lo = std::min(lo, at(x, y, z));
          hi = std::max(hi, at(x, y, z));
        }
      }
    }
    EXPECT_EQ(entries[n].min, lo) << "node " << n;
    EXPECT_EQ(entries[n].max, hi) << "node " << n;
    EXPECT_EQ(entries[n].valid_count, layout.owned_fine_box(key).count()) << "node " << n;
  }
}

TEST(GeometryStoreReadTest, TimeInvariantFieldIsOneBrickForEveryStepCachedOnce) {
  const testing::TempDir dir;
  const GeometryStoreSpec spec;  // curvilinear, surface, time-invariant field
  testing::write_geometry_store(dir / "store", spec);
  ASSERT_TRUE(std::filesystem::exists(dir / "store" / "geometry.bricks"));
  const auto store = Store::open(dir / "store");
  ASSERT_TRUE(store->has_geometry_field());
  const OctreeLayout& layout = store->octree();
  ASSERT_GT(layout.level_count(), 1u);

  const auto height = [&](std::size_t x, std::size_t y, std::size_t z) {
    return testing::geometry_store_height(spec, x, y, z, 0);
  };
  const auto index0 = store->geometry_index(0);
  EXPECT_EQ(store->geometry_index(1).data(), index0.data());  // one index for every step
  expect_index_statistics(layout, index0, height);
  for (NodeId n = 0; n < layout.node_count(); ++n) {
    const Brick b = store->read_geometry_brick(1, n);
    EXPECT_EQ(b.dtype, DType::kFloat64);
    expect_brick_samples(layout, b, height);
  }
  // The variable's bricks are untouched by the field.
  for (std::uint32_t s = 0; s < 2; ++s) {
    for (NodeId n = 0; n < layout.node_count(); ++n) {
      expect_brick_samples(layout, store->read_brick(s, 0, n),
                           [s](std::size_t x, std::size_t y, std::size_t z) {
                             return testing::geometry_store_value(x, y, z, s);
                           });
    }
  }

  BrickCache cache(1 << 20);
  const NodeId root = layout.root();
  const auto first = store->read_geometry_brick(0, root, cache);
  const auto second = store->read_geometry_brick(1, root, cache);
  EXPECT_EQ(first.get(), second.get());
  EXPECT_EQ(cache.stats().misses, 1u);
  EXPECT_EQ(cache.stats().hits, 1u);
  EXPECT_TRUE(cache.contains(BrickKey{store.get(), format::kGeometryStep, 1, root}));
  EXPECT_FALSE(cache.contains(BrickKey{store.get(), 0, 0, root}));  // not the variable's key
  expect_error([&] { store->geometry_index(2); }, ErrorCode::kNotFound, {"time step 2"});
}

TEST(GeometryStoreReadTest, TimeVaryingFieldIsSectionVOfEachStepFile) {
  const testing::TempDir dir;
  GeometryStoreSpec spec;
  spec.field = GeometryField::kVarying;
  spec.steps = 3;
  testing::write_geometry_store(dir / "store", spec);
  EXPECT_FALSE(std::filesystem::exists(dir / "store" / "geometry.bricks"));
  const auto store = Store::open(dir / "store");
  const OctreeLayout& layout = store->octree();
  BrickCache cache(1 << 20);
  for (std::uint32_t s = 0; s < 3; ++s) {
    const auto height = [&](std::size_t x, std::size_t y, std::size_t z) {
      return testing::geometry_store_height(spec, x, y, z, s);
    };
    expect_index_statistics(layout, store->geometry_index(s), height);
    for (NodeId n = 0; n < layout.node_count(); ++n) {
      expect_brick_samples(layout, store->read_geometry_brick(s, n), height);
      expect_brick_samples(layout, *store->read_geometry_brick(s, n, cache), height);
    }
    EXPECT_EQ(store->index(s, 0).size(), layout.node_count());
  }
  EXPECT_EQ(store->geometry_index(2)[layout.root()].min,
            store->geometry_index(0)[layout.root()].min + 14);
  EXPECT_EQ(cache.stats().misses, 3 * layout.node_count());
  EXPECT_NE(store->describe_node(1, 0).find("geometry field node 0"), std::string::npos)
      << store->describe_node(1, 0);
  // Section V is the field's: variable index V reads the field (format/geometry_field.h),
  // and the index after it is nothing.
  const auto by_index = store->index(0, 1);
  const auto field = store->geometry_index(0);
  ASSERT_EQ(by_index.size(), field.size());
  EXPECT_EQ(by_index.data(), field.data());
  EXPECT_EQ(store->read_brick(1, 1, 0).bytes, store->read_geometry_brick(1, 0).bytes);
  expect_error([&] { store->index(0, 2); }, ErrorCode::kNotFound, {"variable index 2"});
}

TEST(GeometryStoreReadTest, HorizontalCoordinatesRoundTripAndAreReadOnce) {
  const testing::TempDir dir;
  const GeometryStoreSpec spec;
  testing::write_geometry_store(dir / "store", spec);
  const auto store = Store::open(dir / "store");
  const auto coordinates = store->horizontal_coordinates();
  ASSERT_NE(coordinates, nullptr);
  EXPECT_TRUE(coordinates->has_coordinates());
  EXPECT_EQ(*coordinates, testing::geometry_store_coordinates(spec));
  EXPECT_EQ(store->horizontal_coordinates().get(), coordinates.get());
}

TEST(GeometryStoreReadTest, SurfaceWithoutCurvilinearCoordinates) {
  const testing::TempDir dir;
  GeometryStoreSpec spec;
  spec.curvilinear = false;
  spec.field = GeometryField::kNone;
  testing::write_geometry_store(dir / "store", spec);
  const auto store = Store::open(dir / "store");
  EXPECT_FALSE(store->has_geometry_field());
  const auto coordinates = store->horizontal_coordinates();
  ASSERT_NE(coordinates, nullptr);
  EXPECT_FALSE(coordinates->has_coordinates());
  ASSERT_TRUE(coordinates->surface_m.has_value());
  EXPECT_EQ(*coordinates->surface_m, *testing::geometry_store_coordinates(spec).surface_m);
  expect_error([&] { store->geometry_index(0); }, ErrorCode::kNotFound,
               {"no vertical geometry field"});
}

TEST(GeometryStoreReadTest, NoGeometryFileWithoutCoordinatesOrSurface) {
  const testing::TempDir dir;
  GeometryStoreSpec spec;
  spec.curvilinear = false;
  spec.surface = false;
  testing::write_geometry_store(dir / "store", spec);
  EXPECT_FALSE(std::filesystem::exists(dir / "store" / "GEOMETRY"));
  const auto store = Store::open(dir / "store");
  EXPECT_EQ(store->horizontal_coordinates(), nullptr);
  EXPECT_TRUE(store->has_geometry_field());
}

TEST(GeometryStoreReadTest, GeometryFilesTheGeometryDoesNotCallForAreRefused) {
  const testing::TempDir dir;
  GeometryStoreSpec varying;
  varying.field = GeometryField::kVarying;
  testing::write_geometry_store(dir / "store", varying);
  const testing::TempDir other;
  testing::write_geometry_store(other / "store");
  std::filesystem::copy_file(other / "store" / "geometry.bricks",
                             dir / "store" / "geometry.bricks");
  expect_error([&] { Store::open(dir / "store"); }, ErrorCode::kCorrupt,
               {"geometry.bricks", "no time-invariant vertical field"});
}

TEST(GeometryStoreReadTest, GeometryBricksOfAnotherStoreAreRefusedByName) {
  const testing::TempDir dir, other;
  testing::write_geometry_store(dir / "store");
  GeometryStoreSpec spec;
  spec.steps = 3;  // another plan, another store_id
  testing::write_geometry_store(other / "store", spec);
  std::filesystem::copy_file(other / "store" / "geometry.bricks", dir / "store" / "geometry.bricks",
                             std::filesystem::copy_options::overwrite_existing);
  const auto store = Store::open(dir / "store");
  expect_error([&] { store->geometry_index(0); }, ErrorCode::kCorrupt,
               {"geometry.bricks", "header store_id"});
  EXPECT_NO_THROW(store->read_brick(0, 0, 0));
}

TEST(GeometryStoreReadTest, GeometryBrickWithMissingSamplesFailsForThatNodeOnly) {
  const testing::TempDir dir;
  const format::Manifest m = testing::write_geometry_store(dir / "store");
  const OctreeLayout layout(m.dims(), m.brick);
  // Constant bricks of every sample, but node 0 counts one valid sample too few and node 1
  // is empty.
  std::vector<build::EncodedBrick> bricks(layout.node_count());
  for (NodeId n = 0; n < bricks.size(); ++n) {
    auto& e = bricks[n].entry;
    e.kind = format::BrickKind::kConstant;
    e.min = e.max = e.constant = 500;
    e.valid_count = layout.owned_fine_box(layout.key(n)).count() - (n == 0 ? 1 : 0);
  }
  bricks[1].entry = format::IndexEntry{};
  bricks[1].entry.kind = format::BrickKind::kEmpty;
  bricks[1].entry.min = bricks[1].entry.max = NAN;
  std::filesystem::remove(dir / "store" / "geometry.bricks");
  build::write_geometry_bricks(dir / "store", m.store_id, std::move(bricks));
  const auto store = Store::open(dir / "store");
  expect_error([&] { store->read_geometry_brick(0, 0); }, ErrorCode::kCorrupt,
               {"geometry.bricks", "geometry field node 0 ", "must have every sample"});
  expect_error([&] { store->read_geometry_brick(1, 1); }, ErrorCode::kCorrupt,
               {"geometry.bricks", "geometry field node 1 ", "empty"});
  EXPECT_EQ(store->read_geometry_brick(0, 2).sample(0), 500);
}

// A data brick claiming every sample but holding a NaN: found by sample, past the first
// block of 64 that the check takes at once, and in the last, partial block.
TEST(GeometryStoreReadTest, GeometryDataBrickWithANaNSampleNamesTheSample) {
  const testing::TempDir dir;
  testing::GeometryStoreSpec spec;
  spec.nx = 17;  // two nodes along x
  spec.ny = spec.nz = 9;
  spec.brick = 8;  // node 0: 9 x 9 x 9 samples
  const format::Manifest m = testing::write_geometry_store(dir / "store", spec);
  const OctreeLayout layout(m.dims(), m.brick);
  const auto& field = m.geometry->vertical;
  for (const std::size_t missing : {std::size_t{100}, std::size_t{0}}) {
    std::vector<build::EncodedBrick> bricks(layout.node_count());
    std::size_t at = 0;
    for (NodeId n = 0; n < bricks.size(); ++n) {
      const IndexBox box = layout.level_box(layout.key(n));
      const BrickDims dims{box.extent(0), box.extent(1), box.extent(2)};
      const std::size_t count = dims[0] * dims[1] * dims[2];
      at = missing == 0 ? count - 1 : missing;  // the last sample, or one past a block
      ASSERT_GT(count, 2 * missing);
      std::vector<double> samples(count, 500.0);
      if (n == 0) samples[at] = std::nan("");
      auto& e = bricks[n].entry;
      e.kind = format::BrickKind::kData;
      e.min = 500;
      e.max = 500;
      e.valid_count = layout.owned_fine_box(layout.key(n)).count();
      ASSERT_EQ(field.dtype, DType::kFloat64);
      bricks[n].chunk = compress_brick(std::as_bytes(std::span(samples)), field.dtype, dims, field.codec);
      e.chunk_size = static_cast<std::uint32_t>(bricks[n].chunk.size());
      e.chunk_checksum = checksum64(bricks[n].chunk);
    }
    std::filesystem::remove(dir / "store" / "geometry.bricks");
    build::write_geometry_bricks(dir / "store", m.store_id, std::move(bricks));
    const auto store = Store::open(dir / "store");
    expect_error([&] { store->read_geometry_brick(0, 0); }, ErrorCode::kCorrupt,
                 {"geometry field node 0 ", fmt::format("sample {} of a geometry brick is missing", at)});
    EXPECT_EQ(store->read_geometry_brick(0, 1).sample(0), 500);
  }
}

}  // namespace
}  // namespace strielad
