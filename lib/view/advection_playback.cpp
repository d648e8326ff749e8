// SPDX-License-Identifier: Apache-2.0
#include "view/advection_playback.h"

#include <algorithm>

namespace strielad::view {

void AdvectionPlayback::set_step(std::uint32_t step) {
  if (started_ && step == step_) return;
  previous_ = started_ && step == step_ + 1 ? std::optional<std::uint32_t>(step_) : std::nullopt;
  started_ = true;
  step_ = step;
  seconds_ = 0;
  // Most urgent first: this step, the next (for playback), the previous (kept, not
  // computed again: it was the current step).
  std::vector<std::uint32_t> wanted{step, step + 1};
  if (previous_) wanted.push_back(*previous_);
  worker_.want(std::move(wanted));
}

void AdvectionPlayback::set_seconds(double seconds) {
  const double length = step_seconds();
  seconds_ = std::max(0.0, length > 0 ? std::min(seconds, length) : seconds);
}

double AdvectionPlayback::step_seconds() const {
  const auto map = worker_.map(step_);
  return map ? map->seconds : 0.0;
}

AdvectionPlayback::Tick AdvectionPlayback::tick(double wall_seconds, bool playing,
                                                double steps_per_second, bool complete) {
  const auto map = worker_.map(step_);
  if (!map) return worker_.failed(step_) ? Tick::kNoMap : Tick::kHold;
  if (playing && wall_seconds > 0 && steps_per_second > 0) {
    seconds_ = std::min(seconds_ + wall_seconds * steps_per_second * map->seconds, map->seconds);
  }
  return playing && seconds_ >= map->seconds && complete ? Tick::kNextStep : Tick::kHold;
}

std::vector<MeshMotion> AdvectionPlayback::motions() const {
  std::vector<MeshMotion> out;
  if (auto map = worker_.map(step_)) out.push_back({std::move(map), seconds_});
  if (previous_) {
    if (auto map = worker_.map(*previous_)) {
      const double end = map->seconds;
      out.push_back({std::move(map), end});
    }
  }
  return out;
}

}  // namespace strielad::view
