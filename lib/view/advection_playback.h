// SPDX-License-Identifier: Apache-2.0
// The clock of smooth playback with wind advection: the current
// step's meshes are drawn `seconds` after their step, moved by the step's displacement
// map; playing advances the seconds at the chosen steps per second of model time; at
// the step's end the meshes wait there until the current step has fully arrived, and
// then the next step is requested. Its meshes stream in while the previous step's
// meshes, still shown until replaced, stay moved to their step's end, where the new
// ones belong: clouds drift instead of jumping.
//
// No graphics here: strielad-view's window drives it once per frame and hands
// motions() to the renderer; tests drive it directly.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "view/advection_worker.h"
#include "view/displacement_map.h"

namespace strielad::view {

class AdvectionPlayback {
 public:
  enum class Tick {
    kHold,      // keep showing the current step
    kNextStep,  // the step is over and complete: request the next one
    kNoMap,     // this step has no map (the last step, or its wind failed): play as without
                // advection
  };

  explicit AdvectionPlayback(AdvectionWorker& worker) : worker_(worker) {}

  // A change of time step, by the user or by playback; seconds restart at 0. When `step`
  // follows the current one, the current step's meshes keep moving with their map.
  void set_step(std::uint32_t step);
  // Scrubbing: seconds after the step, clamped to the step's length once it is known.
  void set_seconds(double seconds);

  // Once per frame. `complete`: every node of the cut shows the current step.
  Tick tick(double wall_seconds, bool playing, double steps_per_second, bool complete);

  std::vector<MeshMotion> motions() const;
  double seconds() const { return seconds_; }
  // The current step's length once its map is ready, else 0.
  double step_seconds() const;
  std::uint32_t step() const { return step_; }

 private:
  AdvectionWorker& worker_;
  std::uint32_t step_ = 0;
  std::optional<std::uint32_t> previous_;
  double seconds_ = 0;
  bool started_ = false;
};

}  // namespace strielad::view
