// SPDX-License-Identifier: Apache-2.0
// The background worker that computes displacement maps (lib/view/advection_worker.h):
// maps of the wanted steps arrive (the last step has none), unwanted ones are dropped,
// and a store without wind is refused up front, naming the store and the variable.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "support/sphere_store.h"
#include "support/temp_dir.h"
#include "support/wind_store.h"
#include "view/advection_worker.h"

namespace strielad::view {
namespace {

using strielad::testing::expect_error;

AdvectionSettings small_settings() {
  AdvectionSettings s;
  s.displacement.lattice = {10, 8, 8};
  return s;
}

TEST(AdvectionWorkerTest, MapsOfWantedStepsArriveAndUnwantedOnesAreDropped) {
  testing::TempDir dir;
  const auto store = Store::open(testing::write_wind_store(dir.path(), Dims3{40, 32, 16}, 3));
  AdvectionWorker worker(store, small_settings());
  EXPECT_EQ(worker.level(), 0u);  // a small grid fits the sample budget at full resolution
  worker.want({1, 0, 2});
  worker.wait_idle();
  EXPECT_EQ(worker.error(), "");
  const auto first = worker.map(0), second = worker.map(1);
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(first->step, 0u);
  EXPECT_EQ(second->step, 1u);
  EXPECT_DOUBLE_EQ(first->seconds, 300.0);
  EXPECT_EQ(worker.map(2), nullptr);  // the last step: nothing to advect towards
  worker.want({1});
  EXPECT_EQ(worker.map(0), nullptr);
  EXPECT_EQ(worker.map(1), second);  // kept, not computed again
}

TEST(AdvectionWorkerTest, AStoreWithoutWindIsRefused) {
  testing::TempDir dir;
  const auto path = testing::write_sphere_store(dir.path(), 8, 9);
  expect_error([&] { AdvectionWorker(Store::open(path), small_settings()); },
               ErrorCode::kNotFound, {"wind component", "ua", path.string()});
  AdvectionSettings settings = small_settings();
  settings.names = WindNames{"d1", "d2", "d1"};
  settings.level = 40;
  expect_error([&] { AdvectionWorker(Store::open(path), settings); },
               ErrorCode::kInvalidArgument, {"wind level 40"});
}

}  // namespace
}  // namespace strielad::view
