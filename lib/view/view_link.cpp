// SPDX-License-Identifier: Apache-2.0
#include "view/view_link.h"

#include <algorithm>
#include <chrono>

#include "core/error.h"

namespace strielad::view {
namespace {

using namespace std::chrono_literals;

// How long the link thread waits for a message before looking at its commands again:
// the most a queued command waits, and a wake-up cost of 500 per second when idle.
constexpr auto kPollInterval = 2ms;

LinkEvent message_event(LinkEvent::Kind kind, std::uint64_t epoch, NodeId node,
                        std::string message, bool fatal = false) {
  LinkEvent event;
  event.kind = kind;
  event.epoch = epoch;
  event.node = node;
  event.message = std::move(message);
  event.fatal = fatal;
  return event;
}

}  // namespace

ViewLink::ViewLink(std::unique_ptr<client::ServerClient> client, HeightPlacement heights,
                   std::shared_ptr<const format::HorizontalCoordinates> horizontal_coordinates,
                   PlacerShape shape)
    : client_(std::move(client)),
      manifest_(client_->manifest()),
      octree_(std::make_unique<OctreeLayout>(client_->octree())),
      placer_(manifest_, std::move(heights), std::move(horizontal_coordinates), shape) {
  thread_ = std::thread([this] { run(); });
}

ViewLink::~ViewLink() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

std::uint64_t ViewLink::change_scene(const Scene& scene) {
  std::lock_guard lock(mutex_);
  const std::uint64_t epoch = ++next_epoch_;
  commands_.emplace_back(SceneCommand{scene, epoch});
  wake_.notify_all();
  return epoch;
}

std::uint64_t ViewLink::change_time(std::uint32_t step) {
  std::lock_guard lock(mutex_);
  const std::uint64_t epoch = ++next_epoch_;
  commands_.emplace_back(TimeCommand{step, epoch});
  wake_.notify_all();
  return epoch;
}

void ViewLink::send_cut_diff(const lod::CutDiff& diff) {
  if (diff.empty()) return;
  std::lock_guard lock(mutex_);
  commands_.emplace_back(diff);
  wake_.notify_all();
}

void ViewLink::request_stats() {
  std::lock_guard lock(mutex_);
  commands_.emplace_back(StatsCommand{});
  wake_.notify_all();
}

std::vector<LinkEvent> ViewLink::take_events(std::size_t max) {
  std::lock_guard lock(mutex_);
  std::vector<LinkEvent> out;
  const std::size_t n = std::min(max, events_.size());
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.push_back(std::move(events_.front()));
    events_.pop_front();
  }
  return out;
}

LinkCounters ViewLink::counters() const {
  std::lock_guard lock(mutex_);
  LinkCounters c = counters_;
  c.bytes_received = client_->bytes_received();
  c.stale_results = client_->stale_results();
  return c;
}

void ViewLink::push_event(LinkEvent event) {
  std::lock_guard lock(mutex_);
  events_.push_back(std::move(event));
}

void ViewLink::run() {
  std::deque<Command> batch;
  bool reported_loss = false;
  while (true) {
    {
      std::unique_lock lock(mutex_);
      if (!generation_active_ || !connected_.load()) {
        wake_.wait_for(lock, 50ms, [&] { return stopping_ || !commands_.empty(); });
      }
      if (stopping_) return;
      batch.swap(commands_);
    }
    for (auto& command : batch) {
      if (!connected_.load()) break;
      try {
        execute(command);
      } catch (const Error& e) {
        push_event(message_event(LinkEvent::Kind::kError, epoch_, 0, e.what(),
                                 !client_->connected()));
      }
    }
    batch.clear();
    if (connected_.load() && !client_->connected()) {
      connected_.store(false);
      if (!reported_loss) {
        reported_loss = true;
        push_event(message_event(LinkEvent::Kind::kError, epoch_, 0,
                                 "connection to the server lost: " + client_->close_reason(),
                                 true));
      }
    }
    if (!generation_active_ || !connected_.load()) continue;
    auto message = client_->wait(kPollInterval);
    while (message) {
      receive(*message);
      message = client_->poll();
    }
  }
}

void ViewLink::execute(Command& command) {
  if (auto* scene = std::get_if<SceneCommand>(&command)) {
    start_generation(&scene->scene, scene->scene.time, scene->epoch);
  } else if (auto* time = std::get_if<TimeCommand>(&command)) {
    start_generation(nullptr, time->step, time->epoch);
  } else if (auto* diff = std::get_if<lod::CutDiff>(&command)) {
    for (const NodeId node : diff->removed) cut_.erase(node);
    for (const auto& a : diff->added) cut_[a.node] = a.priority;
    for (const auto& r : diff->reprioritized) cut_[r.node] = r.priority;
    if (!generation_active_) return;
    std::vector<protocol::NodePriority> added, reprioritized;
    added.reserve(diff->added.size());
    for (const auto& a : diff->added) added.push_back({a.node, a.priority});
    for (const auto& r : diff->reprioritized) reprioritized.push_back({r.node, r.priority});
    client_->update_cut(std::move(added), diff->removed, std::move(reprioritized));
  } else if (std::holds_alternative<StatsCommand>(command)) {
    if (generation_active_) client_->request_stats();
  }
}

void ViewLink::start_generation(const Scene* scene, std::uint32_t step, std::uint64_t epoch) {
  protocol::GenerationStarted started;
  if (scene != nullptr) {
    const HeightPlacement& heights = placer_.heights();
    if (heights.kind == HeightPlacement::Kind::kVariable) {
      // The heights travel as one more attribute of the scene.
      Scene sent = *scene;
      const auto it = std::find(sent.attributes.begin(), sent.attributes.end(), heights.variable);
      height_attribute_ = static_cast<int>(it - sent.attributes.begin());
      if (it == sent.attributes.end()) sent.attributes.push_back(heights.variable);
      started = client_->set_scene(sent);
    } else {
      started = client_->set_scene(*scene);
    }
    slot_ids_.clear();
    for (const auto& sub : scene->subvolumes) slot_ids_.push_back(sub.id);
  } else {
    if (!generation_active_) {
      throw make_error(ErrorCode::kInvalidArgument, "time step {}: no scene set yet", step);
    }
    started = client_->set_time(step);
  }
  epoch_ = epoch;
  step_ = started.step;
  generation_active_ = true;
  push_event(message_event(LinkEvent::Kind::kGeneration, epoch, 0,
                           std::to_string(started.step)));
  if (cut_.empty()) return;
  std::vector<protocol::NodePriority> added;
  added.reserve(cut_.size());
  for (const auto& [node, priority] : cut_) added.push_back({node, priority});
  std::sort(added.begin(), added.end(), [](const auto& a, const auto& b) {
    return a.priority < b.priority || (a.priority == b.priority && a.node < b.node);
  });
  client_->update_cut(std::move(added), {}, {});
}

void ViewLink::receive(protocol::Message& message) {
  if (auto* result = std::get_if<protocol::NodeResult>(&message)) {
    LinkEvent event = message_event(LinkEvent::Kind::kResult, epoch_, result->node, {});
    try {
      event.geometry = placer_.place(
          *result, step_,
          [&](std::uint32_t id) {
            const auto it = std::find(slot_ids_.begin(), slot_ids_.end(), id);
            return it == slot_ids_.end() ? -1 : static_cast<int>(it - slot_ids_.begin());
          },
          height_attribute_);
    } catch (const Error& e) {
      event.kind = LinkEvent::Kind::kFailed;
      event.message = e.what();
    }
    {
      std::lock_guard lock(mutex_);
      if (event.kind == LinkEvent::Kind::kResult) {
        ++counters_.results;
        counters_.triangles += event.geometry->triangle_count();
        counters_.slice_triangles += event.geometry->slice_triangle_count();
      } else {
        ++counters_.failed;
      }
      events_.push_back(std::move(event));
    }
  } else if (auto* failed = std::get_if<protocol::NodeFailed>(&message)) {
    std::lock_guard lock(mutex_);
    ++counters_.failed;
    events_.push_back(
        message_event(LinkEvent::Kind::kFailed, epoch_, failed->node, failed->message));
  } else if (auto* error = std::get_if<protocol::ErrorMessage>(&message)) {
    push_event(message_event(LinkEvent::Kind::kError, epoch_, 0, error->message, error->fatal));
  } else if (auto* stats = std::get_if<protocol::Stats>(&message)) {
    push_event(message_event(LinkEvent::Kind::kStats, epoch_, 0, stats->json));
  }
}

}  // namespace strielad::view
