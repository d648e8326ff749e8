// SPDX-License-Identifier: Apache-2.0
// A coarse sample standing in for fill is a mean that may take in samples just outside
// its node's box. The node's range covers it: conversion used to fail ("a brick with data
// has no value range") when the node's level-0 box held no valid sample at all, and a
// range that missed such a mean would let culling drop part of a coarse surface.
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using namespace strielad::testing;

TEST(CoarseRangesCoverFillMeansTest, NodeWithoutValidLevel0DataButAMeanInItsBrick) {
  TempDir dir;
  SimpleGrid g;
  g.lon = {0, 1, 2, 3, 4, 5, 6, 7, 8};  // brick 2: 4 leaves along x, 2 nodes at level 1
  g.lat = {0, 1};
  g.lev = {1000, 900};
  std::vector<double> data;
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t j = 0; j < 2; ++j)
      for (std::size_t i = 0; i < 9; ++i) data.push_back(i <= 4 ? -999.0 : 10.0 * double(i));
  NetcdfFixture()
      .grid(g)
      .variable("f", NC_FLOAT, g.dims(), data, {NcAttr::number("_FillValue", NC_FLOAT, {-999})})
      .write(dir / "f.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "f.nc"};
  o.store = dir / "store";
  o.brick = 2;
  o.threads = 1;
  ASSERT_NO_THROW(build::convert(o));
  const auto store = Store::open(dir / "store");
  const OctreeLayout& layout = store->octree();
  // Level 1, node 0: level-0 samples x 0..4, all fill; its sample at x 4 is the mean of
  // x 3 (fill) and x 5 (50).
  const NodeId node = static_cast<NodeId>(layout.level(1).first_node);
  const auto& e = store->node_entry(0, 0, node);
  EXPECT_EQ(e.valid_count, 0u);
  EXPECT_EQ(e.min, 50.0);
  EXPECT_EQ(e.max, 50.0);
  const Brick brick = store->read_brick(0, 0, node);
  for (std::size_t i = 0; i < brick.sample_count(); ++i) {
    const double v = brick.sample(i);
    if (!std::isnan(v)) {
      EXPECT_TRUE(v >= e.min && v <= e.max) << v;
    }
  }
  // The root's range is still exactly the valid level-0 range.
  const auto& root = store->node_entry(0, 0, layout.root());
  EXPECT_EQ(root.min, 50.0);
  EXPECT_EQ(root.max, 80.0);
}

}  // namespace
}  // namespace strielad
