// SPDX-License-Identifier: Apache-2.0
// Displacement maps (view/displacement_map.h) computed on a background thread, so the
// frame loop never waits for wind to be read or trajectories to run: the viewer says
// which steps it wants (the current one and the next), takes a step's map once it is
// ready, and draws that step's meshes unmoved until then.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "store/store.h"
#include "view/displacement_map.h"
#include "view/wind_source.h"

namespace strielad::view {

struct AdvectionSettings {
  WindNames names;
  std::optional<std::uint32_t> level;  // default: choose_wind_level
  DisplacementOptions displacement;
  // The shape the meshes are drawn on (the viewer's frame decides; kAuto is not taken).
  lod::FrameShape shape = lod::FrameShape::kPlane;
};

class AdvectionWorker {
 public:
  // Checks what it can up front: \error kNotFound naming the store and component when a
  // wind variable is missing, kUnsupported for time units advection cannot convert,
  // kInvalidArgument for a level outside the octree, and the frame's errors.
  AdvectionWorker(std::shared_ptr<const Store> store, AdvectionSettings settings);
  ~AdvectionWorker();
  AdvectionWorker(const AdvectionWorker&) = delete;
  AdvectionWorker& operator=(const AdvectionWorker&) = delete;

  // The steps whose maps are wanted, most urgent first; maps of other steps are
  // dropped. The last step of the store has no map (nothing to advect towards) and is
  // ignored.
  void want(std::vector<std::uint32_t> steps);
  // The map of `step`, or null while it is being computed (or failed: see error()).
  std::shared_ptr<const DisplacementMap> map(std::uint32_t step) const;
  // No map will come for `step`: it is the last step, or computing it failed.
  bool failed(std::uint32_t step) const;
  // The last failure, e.g. a damaged wind brick ("" when none).
  std::string error() const;
  std::uint32_t level() const { return level_; }
  // Blocks until the maps of every wanted step are ready or failed (tests, headless).
  void wait_idle() const;

 private:
  void run();

  std::shared_ptr<const Store> store_;
  AdvectionSettings settings_;
  std::uint32_t level_ = 0;
  lod::WorldFrame frame_;

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::vector<std::uint32_t> wanted_;
  std::map<std::uint32_t, std::shared_ptr<const DisplacementMap>> maps_;
  std::map<std::uint32_t, std::string> failed_;
  std::optional<std::uint32_t> busy_;  // the step being computed
  std::string error_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace strielad::view
