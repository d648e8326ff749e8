// SPDX-License-Identifier: Apache-2.0
// The wind a viewer advects with (lib/view/wind_source.h): one octree level of the
// store's ua/va/wa at two steps as an advect::WindField, the level chosen by a sample
// budget, and the errors for stores that cannot be advected.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lod/lod_test_grids.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"
#include "support/wind_store.h"
#include "view/wind_source.h"

namespace strielad::view {
namespace {

using strielad::testing::expect_error;

class WindSourceTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    path_ = new std::filesystem::path(testing::write_wind_store(dir_->path()));
  }
  static void TearDownTestSuite() {
    delete path_;
    delete dir_;
  }
  static std::shared_ptr<const Store> open() { return Store::open(*path_); }
  static inline testing::TempDir* dir_ = nullptr;
  static inline std::filesystem::path* path_ = nullptr;
};

TEST_F(WindSourceTest, TheFieldHoldsTheLevelsSamplesAtBothSteps) {
  const auto store = open();
  const auto& layout = store->octree();
  ASSERT_GE(layout.level_count(), 3u);
  const std::uint32_t level = 1;
  const WindStep wind = load_wind_step(*store, 0, WindNames{}, level);
  EXPECT_EQ(wind.step, 0u);
  EXPECT_EQ(wind.level, level);
  EXPECT_DOUBLE_EQ(wind.seconds, 300.0);  // the generator's step
  EXPECT_GT(wind.bytes_read, 0u);
  const auto& shape = layout.level(level);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(wind.field.grid().axes[a].size(), shape.samples[a]);
  EXPECT_EQ(wind.field.grid().horizontal, advect::Horizontal::kDegrees);
  EXPECT_EQ(wind.field.grid().vertical, advect::Vertical::kMetres);

  // Every sample of one node's bricks at both steps against the field's rate there.
  const auto& m = store->manifest();
  const NodeId node = shape.first_node + static_cast<NodeId>(shape.node_count() / 2);
  const auto key = layout.key(node);
  const IndexBox box = layout.level_box(key);
  const std::uint32_t ua = static_cast<std::uint32_t>(m.variable_index("ua"));
  const std::uint32_t va = static_cast<std::uint32_t>(m.variable_index("va"));
  const std::uint32_t wa = static_cast<std::uint32_t>(m.variable_index("wa"));
  std::size_t checked = 0;
  for (std::uint32_t t = 0; t < 2; ++t) {
    const Brick u = store->read_brick(t, ua, node), v = store->read_brick(t, va, node),
                w = store->read_brick(t, wa, node);
    for (std::size_t i = 0; i < u.sample_count(); i += 7) {
      const std::size_t x = i % u.dims[0], y = (i / u.dims[0]) % u.dims[1],
                        z = i / (u.dims[0] * u.dims[1]);
      const Vec3 p{m.x.values[layout.fine_index(level, 0, box.lo[0] + x)],
                           m.y.values[layout.fine_index(level, 1, box.lo[1] + y)],
                           m.z.values[layout.fine_index(level, 2, box.lo[2] + z)]};
      Vec3 rate{};
      ASSERT_EQ(wind.field.rate(p, t * wind.seconds, rate), advect::Sample::kOk);
      const double deg = 180.0 / std::numbers::pi;
      const double cos_lat = std::cos(p[1] / deg);
      EXPECT_NEAR(rate[0] * advect::kEarthRadiusM * cos_lat / deg, u.sample(i), 1e-4);
      EXPECT_NEAR(rate[1] * advect::kEarthRadiusM / deg, v.sample(i), 1e-4);
      EXPECT_NEAR(rate[2], w.sample(i), 1e-6);
      ++checked;
    }
  }
  EXPECT_GT(checked, 50u);
}

TEST_F(WindSourceTest, TheLevelIsTheFinestWithinTheSampleBudget) {
  const auto paper = lod::testing::paper_manifest();
  const OctreeLayout layout(paper.dims(), 20);
  const std::uint32_t level = choose_wind_level(layout);
  const auto count = [&](std::size_t l) {
    const auto& s = layout.level(l).samples;
    return s[0] * s[1] * s[2];
  };
  EXPECT_LE(count(level), kDefaultWindSamples);
  ASSERT_GT(level, 0u);
  EXPECT_GT(count(level - 1), kDefaultWindSamples);
  EXPECT_EQ(choose_wind_level(layout, std::size_t{1} << 40), 0u);
  EXPECT_EQ(choose_wind_level(layout, 1), layout.level_count() - 1);  // the root at most
}

TEST_F(WindSourceTest, StoresThatCannotBeAdvectedSayWhy) {
  const auto store = open();
  expect_error([&] { load_wind_step(*store, 0, WindNames{"ua", "va", "omega"}, 0); },
               ErrorCode::kNotFound, {"wind component", "omega", path_->string()});
  expect_error([&] { load_wind_step(*store, 1, WindNames{}, 0); }, ErrorCode::kInvalidArgument,
               {"time step 1", "no later step"});
  expect_error([&] { load_wind_step(*store, 0, WindNames{}, 99); },
               ErrorCode::kInvalidArgument, {"wind level 99"});
}

TEST(WindNamesTest, ThreeCommaSeparatedNames) {
  const WindNames n = parse_wind_names("u, v ,omega");
  EXPECT_EQ(n.u, "u");
  EXPECT_EQ(n.v, "v");
  EXPECT_EQ(n.w, "omega");
  for (const char* bad : {"", "ua,va", "ua,va,wa,x", "ua,,wa"}) {
    expect_error([&] { parse_wind_names(bad); }, ErrorCode::kInvalidArgument, {"U,V,W"});
  }
}

TEST(WindUnitsTest, AxisUnitsBecomeDegreesMetresAndPascals) {
  auto m = lod::testing::geographic_manifest(5, 4, {1000, 850, 500}, AxisKind::kPressure, "hPa");
  const lod::WorldFrame pressure(m);
  const WindUnits units = wind_units(pressure);
  EXPECT_EQ(units.horizontal, advect::Horizontal::kDegrees);
  EXPECT_EQ(units.vertical, advect::Vertical::kPascals);
  EXPECT_DOUBLE_EQ(units.scale[2], 100.0);  // hPa -> Pa
  const auto back = units.to_axis(units.to_wind({10.0, 50.0, 850.0}));
  EXPECT_DOUBLE_EQ(back[2], 850.0);
  m = lod::testing::geographic_manifest(5, 4, {0, 5, 12}, AxisKind::kHeight, "km");
  EXPECT_DOUBLE_EQ(wind_units(lod::WorldFrame(m)).scale[2], 1000.0);  // km -> m
}

}  // namespace
}  // namespace strielad::view
