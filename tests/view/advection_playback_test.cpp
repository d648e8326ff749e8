// SPDX-License-Identifier: Apache-2.0
// Smooth playback with wind advection (lib/view/advection_playback.h): seconds advance
// with the play speed once the step's map is ready, the step ends only when its meshes
// have all arrived, the previous step's meshes stay moved to their step's end while the
// next step streams in, and the last step plays as without advection.
#include <gtest/gtest.h>

#include "support/temp_dir.h"
#include "support/wind_store.h"
#include "view/advection_playback.h"

namespace strielad::view {
namespace {

using Tick = AdvectionPlayback::Tick;

class AdvectionPlaybackTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    store_ = new std::shared_ptr<const Store>(
        Store::open(testing::write_wind_store(dir_->path(), Dims3{32, 24, 12}, 3)));
  }
  static void TearDownTestSuite() {
    delete store_;
    delete dir_;
  }
  static AdvectionSettings settings() {
    AdvectionSettings s;
    s.displacement.lattice = {8, 8, 8};
    return s;
  }
  static inline testing::TempDir* dir_ = nullptr;
  static inline std::shared_ptr<const Store>* store_ = nullptr;
};

TEST_F(AdvectionPlaybackTest, SecondsAdvanceAndTheStepEndsWhenComplete) {
  AdvectionWorker worker(*store_, settings());
  AdvectionPlayback playback(worker);
  playback.set_step(0);
  EXPECT_EQ(playback.step_seconds(), 0.0);  // not yet known (or just computed)
  worker.wait_idle();
  ASSERT_NE(worker.map(0), nullptr);
  ASSERT_NE(worker.map(1), nullptr);  // the next step is prepared meanwhile
  EXPECT_DOUBLE_EQ(playback.step_seconds(), 300.0);

  // 2 steps per second of wall time: 0.1 s moves 60 s of model time.
  EXPECT_EQ(playback.tick(0.1, true, 2.0, true), Tick::kHold);
  EXPECT_NEAR(playback.seconds(), 60.0, 1e-9);
  EXPECT_EQ(playback.tick(0.1, false, 2.0, true), Tick::kHold);  // paused
  EXPECT_NEAR(playback.seconds(), 60.0, 1e-9);
  auto motions = playback.motions();
  ASSERT_EQ(motions.size(), 1u);
  EXPECT_EQ(motions[0].map->step, 0u);
  EXPECT_NEAR(motions[0].seconds, 60.0, 1e-9);

  // At the step's end it waits for the step's meshes to be complete.
  EXPECT_EQ(playback.tick(5.0, true, 2.0, false), Tick::kHold);
  EXPECT_DOUBLE_EQ(playback.seconds(), 300.0);
  EXPECT_EQ(playback.tick(0.01, true, 2.0, true), Tick::kNextStep);

  // The next step: its meshes start at 0 s, the previous step's stay at its end.
  playback.set_step(1);
  EXPECT_EQ(playback.seconds(), 0.0);
  motions = playback.motions();
  ASSERT_EQ(motions.size(), 2u);
  EXPECT_EQ(motions[0].map->step, 1u);
  EXPECT_EQ(motions[0].seconds, 0.0);
  EXPECT_EQ(motions[1].map->step, 0u);
  EXPECT_DOUBLE_EQ(motions[1].seconds, 300.0);

  // Scrubbing is clamped to the step.
  playback.set_seconds(1e6);
  EXPECT_DOUBLE_EQ(playback.seconds(), 300.0);
  playback.set_seconds(-5);
  EXPECT_EQ(playback.seconds(), 0.0);
}

TEST_F(AdvectionPlaybackTest, AJumpForgetsThePreviousStepAndTheLastStepHasNoMap) {
  AdvectionWorker worker(*store_, settings());
  AdvectionPlayback playback(worker);
  playback.set_step(0);
  playback.set_step(2);  // a jump, and the last step
  worker.wait_idle();
  EXPECT_TRUE(playback.motions().empty());
  EXPECT_EQ(playback.tick(1.0, true, 2.0, true), Tick::kNoMap);
  EXPECT_EQ(worker.map(0), nullptr);  // no longer wanted
}

}  // namespace
}  // namespace strielad::view
