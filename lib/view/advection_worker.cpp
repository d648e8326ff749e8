// SPDX-License-Identifier: Apache-2.0
#include "view/advection_worker.h"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/error.h"
#include "view/level_heights.h"

namespace strielad::view {

AdvectionWorker::AdvectionWorker(std::shared_ptr<const Store> store, AdvectionSettings settings)
    : store_(std::move(store)),
      settings_(std::move(settings)),
      level_(settings_.level.value_or(choose_wind_level(store_->octree()))),
      frame_(store_->manifest(),
             lod::WorldFrameOptions{.vertical_exaggeration = 1.0, .shape = settings_.shape},
             representative_level_heights_m(*store_), store_->horizontal_coordinates()) {
  wind_variables(*store_, settings_.names, level_);  // refuse a store without wind up front
  thread_ = std::thread([this] { run(); });
}

AdvectionWorker::~AdvectionWorker() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void AdvectionWorker::want(std::vector<std::uint32_t> steps) {
  std::erase_if(steps, [&](std::uint32_t s) { return s + 1 >= store_->step_count(); });
  {
    std::lock_guard lock(mutex_);
    if (steps == wanted_) return;
    wanted_ = std::move(steps);
    std::erase_if(maps_, [&](const auto& entry) {
      return std::find(wanted_.begin(), wanted_.end(), entry.first) == wanted_.end();
    });
  }
  changed_.notify_all();
}

std::shared_ptr<const DisplacementMap> AdvectionWorker::map(std::uint32_t step) const {
  std::lock_guard lock(mutex_);
  const auto it = maps_.find(step);
  return it == maps_.end() ? nullptr : it->second;
}

bool AdvectionWorker::failed(std::uint32_t step) const {
  if (step + 1 >= store_->step_count()) return true;
  std::lock_guard lock(mutex_);
  return failed_.contains(step);
}

std::string AdvectionWorker::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void AdvectionWorker::wait_idle() const {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] {
    if (busy_) return false;
    return std::all_of(wanted_.begin(), wanted_.end(), [&](std::uint32_t s) {
      return maps_.contains(s) || failed_.contains(s);
    });
  });
}

void AdvectionWorker::run() {
  while (true) {
    std::uint32_t step = 0;
    {
      std::unique_lock lock(mutex_);
      const auto next = [&]() -> std::optional<std::uint32_t> {
        for (const auto s : wanted_) {
          if (!maps_.contains(s) && !failed_.contains(s)) return s;
        }
        return std::nullopt;
      };
      changed_.wait(lock, [&] { return stopping_ || next().has_value(); });
      if (stopping_) return;
      step = *next();
      busy_ = step;
    }
    std::shared_ptr<const DisplacementMap> map;
    std::string failure;
    try {
      const WindStep wind = load_wind_step(*store_, step, settings_.names, level_);
      map = std::make_shared<const DisplacementMap>(
          compute_displacement_map(wind, frame_, settings_.displacement));
      spdlog::info("advection: step {} moved by {} trajectories ({}x{}x{}, wind level {}) in "
                   "{:.2f} s, {} stopped early",
                   step, map->points(), map->lattice[0], map->lattice[1], map->lattice[2],
                   level_, map->compute_seconds, map->stopped);
    } catch (const Error& e) {
      failure = e.what();
      spdlog::warn("advection: step {}: {}", step, failure);
    }
    {
      std::lock_guard lock(mutex_);
      busy_.reset();
      const bool still_wanted = std::find(wanted_.begin(), wanted_.end(), step) != wanted_.end();
      if (map && still_wanted) maps_[step] = std::move(map);
      if (!failure.empty()) {
        failed_[step] = failure;
        error_ = failure;
      }
    }
    changed_.notify_all();
  }
}

}  // namespace strielad::view
