// SPDX-License-Identifier: Apache-2.0
#include "serve/session.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <thread>

#include "core/error.h"
#include "format/manifest.h"
#include "net/message_stream.h"
#include "protocol/message_codec.h"
#include "serve/client_error_text.h"
#include "serve/dataset_registry.h"
#include "store/store.h"

namespace strielad::serve {

namespace {

// Compares without an early exit, so the time taken does not tell how much matched.
bool same_secret(std::string_view a, std::string_view b) {
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff |= static_cast<unsigned char>(a[i] ^ (i < b.size() ? b[i] : 0));
  }
  return diff == 0;
}

}  // namespace

// The largest valid Hello: magic, version, client name and token at their limits.
constexpr std::uint32_t kMaxHelloPayloadBytes =
    8 + 2 + (2 + protocol::kMaxNameBytes) + (2 + protocol::kMaxTokenBytes);

Session::Session(std::uint64_t id, net::Socket socket, SessionContext context)
    : id_(id),
      socket_(std::move(socket)),
      context_(std::move(context)),
      outbound_(&context_.counters.send_queue_bytes, &context_.counters.send_queue_peak_bytes) {}

Session::~Session() = default;

void Session::shutdown() { socket_.shutdown(); }

void Session::send(const protocol::Message& message) {
  outbound_.push(protocol::encode_frame(message));
}

void Session::send_error(protocol::WireError code, std::string message, bool fatal) {
  spdlog::log(fatal ? spdlog::level::warn : spdlog::level::info, "client {} ({}): {}: {}", id_,
              peer(), protocol::wire_error_name(code), message);
  // Errors name datasets already (DatasetRegistry); no path under the root leaves the server.
  message = hide_root(message, context_.datasets.root());
  if (message.size() > protocol::kMaxMessageTextBytes) message.resize(protocol::kMaxMessageTextBytes);
  send(protocol::ErrorMessage{code, fatal, std::move(message)});
}

void Session::leave_handshake() {
  if (in_handshake_.exchange(false)) --context_.counters.handshakes;
}

bool Session::handshake() {
  // One deadline for the whole Hello: a client trickling a byte at a time does not
  // extend it.
  const auto timeout = context_.config.handshake_timeout;
  const net::Deadline deadline = std::chrono::steady_clock::now() + timeout;
  net::ReceivedMessage first;
  try {
    first = net::read_message(
        socket_, std::min(context_.config.limits.max_payload_bytes, kMaxHelloPayloadBytes),
        deadline);
  } catch (const Error&) {
    if (std::chrono::steady_clock::now() < deadline) throw;
    ++context_.counters.handshakes_dropped;
    spdlog::info("client {} ({}): no Hello within {} ms; closed", id_, peer(), timeout.count());
    return false;
  }
  auto refuse = [&](protocol::WireError code, std::string message) {
    ++context_.counters.connections_rejected;
    spdlog::warn("client {} ({}): refused: {}", id_, peer(), message);
    try {
      net::write_message(socket_, protocol::ErrorMessage{code, true, std::move(message)});
    } catch (const Error&) {
    }
    return false;
  };
  if (first.status == net::ReceivedMessage::Status::kEndOfStream) return false;
  if (first.status == net::ReceivedMessage::Status::kRejected) {
    return refuse(first.error, first.reason);
  }
  const auto* hello = std::get_if<protocol::Hello>(&first.message);
  if (!hello) {
    return refuse(protocol::WireError::kOutOfOrder,
                  fmt::format("the first message must be Hello, not {}",
                              protocol::message_type_name(protocol::message_type(first.message))));
  }
  if (hello->version < 1) {
    return refuse(protocol::WireError::kVersionMismatch,
                  fmt::format("client speaks protocol version {}, this server {}", hello->version,
                              protocol::kProtocolVersion));
  }
  if (context_.config.token && !same_secret(hello->token, *context_.config.token)) {
    return refuse(protocol::WireError::kUnauthorized, "wrong or missing token");
  }
  if (!context_.admit_client()) {
    return refuse(protocol::WireError::kServerBusy,
                  fmt::format("server busy: {} clients connected (limit {})",
                              context_.counters.clients.load(), context_.config.max_clients));
  }
  admitted_ = true;
  leave_handshake();  // before Welcome: a client that has it is counted as a client only
  spdlog::info("client {} ({}) connected: '{}'", id_, peer(), hello->client_name);
  version_ = std::min(hello->version, protocol::kProtocolVersion);
  net::write_message(socket_, protocol::Welcome{version_, context_.config.server_name,
                                                context_.config.limits});
  return true;
}

void Session::run() {
  bool greeted = false;
  try {
    greeted = handshake();
  } catch (const Error& e) {
    spdlog::info("client {} ({}): handshake failed: {}", id_, peer(), e.what());
  }
  leave_handshake();
  if (!greeted) {
    socket_.close();
    return;
  }
  std::thread writer([this] { writer_loop(); });
  try {
    for (;;) {
      wait_for_send_room();
      const net::ReceivedMessage in =
          net::read_message(socket_, context_.config.limits.max_payload_bytes);
      if (in.status == net::ReceivedMessage::Status::kEndOfStream) break;
      if (in.status == net::ReceivedMessage::Status::kRejected) {
        outbound_.discard_pending();
        send_error(in.error, in.reason, true);
        break;
      }
      if (!handle(in.message)) break;
    }
  } catch (const Error& e) {
    spdlog::info("client {} ({}): {}", id_, peer(), e.what());
  }
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
    cancel_all_locked();
  }
  outbound_.close();
  writer.join();
  socket_.close();
  spdlog::info("client {} ({}) disconnected", id_, peer());
}

void Session::wait_for_send_room() {
  const std::uint64_t limit = context_.config.max_pending_send_bytes;
  if (outbound_.pending_bytes() <= limit) return;
  ++context_.counters.readers_paused;
  spdlog::debug("client {} ({}): {} bytes unsent; not reading its requests until it reads",
                id_, peer(), outbound_.pending_bytes());
  outbound_.wait_until_at_most(limit);
  --context_.counters.readers_paused;
}

void Session::writer_loop() {
  const std::uint64_t resume_below = context_.config.max_pending_send_bytes;
  while (auto frame = outbound_.pop()) {
    const bool was_full = outbound_.pending_bytes() + frame->size() > resume_below;
    try {
      socket_.write_all(*frame);
    } catch (const Error& e) {
      spdlog::info("client {} ({}): {}", id_, peer(), e.what());
      outbound_.close();  // nothing more is queued, and a reader waiting for room returns
      outbound_.discard_pending();
      socket_.shutdown();  // ends the reader too
      return;
    }
    context_.counters.bytes_sent += frame->size();
    if (was_full && outbound_.pending_bytes() <= resume_below) context_.work_available();
  }
}

bool Session::handle(const protocol::Message& message) {
  using namespace protocol;
  try {
    if (const auto* m = std::get_if<OpenDataset>(&message)) {
      open_dataset(*m);
    } else if (const auto* m = std::get_if<SetScene>(&message)) {
      set_scene(*m);
    } else if (const auto* m = std::get_if<SetTime>(&message)) {
      set_time(*m);
    } else if (const auto* m = std::get_if<CutUpdate>(&message)) {
      update_cut(*m);
    } else if (std::holds_alternative<StatsRequest>(message)) {
      std::uint32_t generation;
      {
        std::lock_guard lock(mutex_);
        generation = generation_;
      }
      send(Stats{context_.stats_json(generation)});
    } else if (std::holds_alternative<Goodbye>(message)) {
      outbound_.discard_pending();
      return false;
    } else {
      const MessageType type = message_type(message);
      send_error(WireError::kOutOfOrder,
                 is_client_message(type)
                     ? fmt::format("{} may only be the first message", message_type_name(type))
                     : fmt::format("{} is a server message; a client may not send it",
                                   message_type_name(type)),
                 true);
      return false;
    }
  } catch (const Error& e) {
    send_error(wire_error(e.code()), e.what());
  }
  return true;
}

void Session::open_dataset(const protocol::OpenDataset& m) {
  std::shared_ptr<const Store> store = context_.datasets.open(m.name);
  std::vector<std::byte> manifest = format::encode_manifest(store->manifest());
  {
    std::lock_guard lock(mutex_);
    cancel_all_locked();
    store_ = std::move(store);
    dataset_ = m.name;
    scene_.reset();
    resolved_.reset();
    resolved_next_.reset();
    generation_started_ = false;
    send(protocol::DatasetOpened{m.name, std::move(manifest)});
  }
  spdlog::info("client {} ({}): opened dataset '{}'", id_, peer(), m.name);
}

bool Session::check_new_generation(std::uint32_t generation) {
  std::lock_guard lock(mutex_);
  if (!store_) {
    send_error(protocol::WireError::kOutOfOrder, "open a dataset before setting a scene or time");
    return false;
  }
  // generation_ is 0 before the first accepted one, so the first must be at least 1.
  if (generation <= generation_) {
    send_error(protocol::WireError::kOutOfOrder,
               generation_ == 0
                   ? std::string("generation 0: the first generation of a connection is at least 1")
                   : fmt::format("generation {} is not greater than the last accepted generation {}",
                                 generation, generation_));
    return false;
  }
  return true;
}

void Session::set_scene(const protocol::SetScene& m) {
  if (!check_new_generation(m.generation)) return;
  Scene scene = parse_scene(m.scene_json, "scene");
  const protocol::ServerLimits& limits = context_.config.limits;
  if (scene.subvolumes.size() > limits.max_subvolumes) {
    send_error(protocol::WireError::kTooLarge,
               fmt::format("scene: {} sub-volumes, this server allows {}",
                           scene.subvolumes.size(), limits.max_subvolumes));
    return;
  }
  for (std::size_t i = 0; i < scene.subvolumes.size(); ++i) {
    if (scene.subvolumes[i].limits.size() > limits.max_limits_per_subvolume) {
      send_error(protocol::WireError::kTooLarge,
                 fmt::format("scene: subvolumes[{}]: {} limits, this server allows {}", i,
                             scene.subvolumes[i].limits.size(), limits.max_limits_per_subvolume));
      return;
    }
  }
  if (!scene.slices.empty() && version_ < protocol::kProtocolVersionSlices) {
    send_error(protocol::WireError::kUnsupported,
               fmt::format("scene: {} slices, but slice results need protocol version {} and this "
                           "connection speaks version {} (the client's Hello); remove 'slices' "
                           "or use a newer client",
                           scene.slices.size(), protocol::kProtocolVersionSlices, version_));
    return;
  }
  std::shared_ptr<const Store> store;
  {
    std::lock_guard lock(mutex_);
    store = store_;
  }
  ResolvedScene resolved = resolve_scene(scene, store->manifest(), "scene");
  start_generation(m.generation, std::move(scene), std::move(resolved));
}

void Session::set_time(const protocol::SetTime& m) {
  if (!check_new_generation(m.generation)) return;
  Scene scene;
  std::shared_ptr<const Store> store;
  {
    std::lock_guard lock(mutex_);
    if (!scene_) {
      send_error(protocol::WireError::kOutOfOrder, "set a scene before changing its time step");
      return;
    }
    scene = *scene_;
    store = store_;
  }
  scene.time = m.step;
  ResolvedScene resolved = resolve_scene(scene, store->manifest(), "SetTime");
  start_generation(m.generation, std::move(scene), std::move(resolved));
}

void Session::start_generation(std::uint32_t generation, Scene scene, ResolvedScene resolved) {
  std::lock_guard lock(mutex_);
  cancel_all_locked();
  generation_ = generation;
  generation_started_ = true;
  queue_.start_generation(generation);
  source_ = std::make_shared<const SceneSource>(
      SceneSource{next_scene_source_id(), scene_to_json(scene)});
  resolved_ = std::make_shared<const ResolvedScene>(resolved);
  resolved_next_.reset();
  source_next_.reset();
  if (resolved.time + 1 < store_->step_count()) {
    Scene next = scene;
    next.time = resolved.time + 1;
    ResolvedScene r = resolved;
    r.time = next.time;
    resolved_next_ = std::make_shared<const ResolvedScene>(std::move(r));
    source_next_ = std::make_shared<const SceneSource>(
        SceneSource{next_scene_source_id(), scene_to_json(next)});
  }
  const std::uint32_t step = scene.time;
  scene_ = std::move(scene);
  send(protocol::GenerationStarted{generation, step, source_->json});
}

void Session::cancel_all_locked() {
  const std::size_t dropped = queue_.start_generation(queue_.generation());
  context_.counters.queued -= static_cast<std::int64_t>(dropped);
  context_.counters.nodes_cancelled += dropped;
  for (auto& [node, running] : running_) running.stop.request_stop();
  cut_.clear();
  generation_stop_.request_stop();
  generation_stop_ = std::stop_source();
  prefetch_order_.clear();
  prefetch_cursor_ = 0;
  prefetch_order_stale_ = true;
  prefetched_.clear();
}

void Session::update_cut(const protocol::CutUpdate& m) {
  const protocol::ServerLimits& limits = context_.config.limits;
  for (const std::size_t n : {m.added.size(), m.removed.size(), m.reprioritized.size()}) {
    if (n > limits.max_nodes_per_update) {
      send_error(protocol::WireError::kTooLarge,
                 fmt::format("CutUpdate lists {} nodes, this server allows {} per list", n,
                             limits.max_nodes_per_update));
      return;
    }
  }
  std::vector<NodeId> unknown;
  {
    std::lock_guard lock(mutex_);
    if (!generation_started_ || m.generation != generation_) {
      send_error(protocol::WireError::kOutOfOrder,
                 generation_started_
                     ? fmt::format("CutUpdate for generation {}, the current one is {}",
                                   m.generation, generation_)
                     : std::string("CutUpdate before any SetScene"));
      return;
    }
    const OctreeLayout& octree = store_->octree();
    for (NodeId node : m.removed) {
      if (cut_.erase(node) == 0) continue;
      if (queue_.remove(node)) {
        --context_.counters.queued;
        ++context_.counters.nodes_cancelled;
      }
      if (const auto it = running_.find(node); it != running_.end()) it->second.stop.request_stop();
    }
    for (const protocol::NodePriority& p : m.added) {
      if (!octree.contains(p.node)) {
        unknown.push_back(p.node);
        continue;
      }
      const auto [it, inserted] = cut_.try_emplace(p.node, p.priority);
      if (!inserted) {
        it->second = p.priority;
        queue_.reprioritize(p.node, p.priority);
        continue;
      }
      queue_.add(p.node, p.priority);
      ++context_.counters.queued;
    }
    for (const protocol::NodePriority& p : m.reprioritized) {
      const auto it = cut_.find(p.node);
      if (it == cut_.end()) continue;
      it->second = p.priority;
      queue_.reprioritize(p.node, p.priority);
    }
    prefetch_order_stale_ = true;
    for (NodeId node : unknown) {
      send(protocol::NodeFailed{m.generation, node, protocol::WireError::kNotFound,
                                fmt::format("node {} is not in the octree of '{}' ({} nodes)", node,
                                            dataset_, octree.node_count())});
    }
  }
  context_.work_available();
}

bool Session::can_take_work_locked() const {
  return !closed_ && !queue_.empty() &&
         outbound_.pending_bytes() <= context_.config.max_pending_send_bytes;
}

bool Session::has_queued_work() const {
  std::lock_guard lock(mutex_);
  return can_take_work_locked();
}

std::optional<NodeTask> Session::take_task() {
  std::lock_guard lock(mutex_);
  if (!can_take_work_locked()) return std::nullopt;
  const WorkItem item = *queue_.pop();
  --context_.counters.queued;
  const std::uint64_t serial = next_serial_++;
  std::stop_source stop;
  NodeTask task{store_, dataset_, resolved_, source_, item.generation, item.node, serial,
                stop.get_token()};
  running_[item.node] = Running{serial, std::move(stop)};
  ++context_.counters.running;
  return task;
}

void Session::complete(const NodeTask& task, NodeOutput output) {
  std::lock_guard lock(mutex_);
  --context_.counters.running;
  const auto it = running_.find(task.node);
  if (it != running_.end() && it->second.serial == task.serial) running_.erase(it);
  const bool deliver = !closed_ && output.kind != NodeOutputKind::kCancelled &&
                       !task.stop.stop_requested() && task.generation == generation_ &&
                       cut_.contains(task.node);
  if (!deliver) {
    ++context_.counters.nodes_cancelled;
    return;
  }
  switch (output.kind) {
    case NodeOutputKind::kSkipped: ++context_.counters.nodes_skipped; break;
    case NodeOutputKind::kFailed: ++context_.counters.nodes_failed; break;
    default: ++context_.counters.nodes_done; break;
  }
  context_.counters.slice_meshes += output.slice_meshes;
  context_.counters.slice_triangles += output.slice_triangles;
  outbound_.push(std::move(output.frame));
}

std::optional<NodeTask> Session::take_prefetch() {
  std::lock_guard lock(mutex_);
  if (closed_ || !resolved_next_ || !queue_.empty() || !running_.empty()) return std::nullopt;
  if (prefetch_order_stale_) {
    std::vector<std::pair<float, NodeId>> order;
    for (const auto& [node, priority] : cut_) {
      if (!prefetched_.contains(node)) order.emplace_back(priority, node);
    }
    std::sort(order.begin(), order.end());
    prefetch_order_.clear();
    for (const auto& [priority, node] : order) prefetch_order_.push_back(node);
    prefetch_cursor_ = 0;
    prefetch_order_stale_ = false;
  }
  while (prefetch_cursor_ < prefetch_order_.size()) {
    const NodeId node = prefetch_order_[prefetch_cursor_++];
    if (!cut_.contains(node) || !prefetched_.insert(node).second) continue;
    return NodeTask{store_, dataset_, resolved_next_, source_next_, generation_, node, 0,
                    generation_stop_.get_token()};
  }
  return std::nullopt;
}

}  // namespace strielad::serve
