// SPDX-License-Identifier: Apache-2.0
#include "client/server_client.h"

#include <algorithm>

#include "core/error.h"
#include "net/message_stream.h"
#include "protocol/message_codec.h"

namespace strielad::client {

namespace {

Error server_error(const protocol::ErrorMessage& e) {
  return Error(protocol::error_code(e.code),
               fmt::format("server: {}: {}", protocol::wire_error_name(e.code), e.message));
}

std::optional<std::uint32_t> result_generation(const protocol::Message& m) {
  if (const auto* r = std::get_if<protocol::NodeResult>(&m)) return r->generation;
  if (const auto* f = std::get_if<protocol::NodeFailed>(&m)) return f->generation;
  return std::nullopt;
}

}  // namespace

ServerClient::ServerClient(net::Socket socket, ClientOptions options)
    : socket_(std::move(socket)), options_(std::move(options)) {}

std::unique_ptr<ServerClient> ServerClient::connect(const net::Endpoint& endpoint,
                                                    ClientOptions options) {
  net::Socket socket = net::connect_tcp(endpoint);
  std::unique_ptr<ServerClient> client(new ServerClient(std::move(socket), std::move(options)));
  net::write_message(client->socket_,
                     protocol::Hello{client->options_.protocol_version,
                                     client->options_.client_name, client->options_.token});
  client->socket_.set_receive_timeout(client->options_.timeout);
  const net::ReceivedMessage reply =
      net::read_message(client->socket_, protocol::kMaxServerPayloadBytes);
  client->socket_.set_receive_timeout(std::chrono::milliseconds(0));
  if (reply.status == net::ReceivedMessage::Status::kEndOfStream) {
    throw make_error(ErrorCode::kIo, "{}: server closed the connection during the handshake",
                     endpoint.to_string());
  }
  if (reply.status == net::ReceivedMessage::Status::kRejected) {
    throw make_error(ErrorCode::kCorrupt, "{}: bad handshake reply: {}", endpoint.to_string(),
                     reply.reason);
  }
  if (const auto* e = std::get_if<protocol::ErrorMessage>(&reply.message)) throw server_error(*e);
  const auto* welcome = std::get_if<protocol::Welcome>(&reply.message);
  if (!welcome) {
    throw make_error(ErrorCode::kCorrupt, "{}: expected Welcome, got {}", endpoint.to_string(),
                     protocol::message_type_name(protocol::message_type(reply.message)));
  }
  if (welcome->version > client->options_.protocol_version) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: Welcome: version {} is above the {} this client offered",
                     endpoint.to_string(), welcome->version, client->options_.protocol_version);
  }
  client->welcome_ = *welcome;
  client->reader_ = std::thread([c = client.get()] { c->reader_loop(); });
  return client;
}

ServerClient::~ServerClient() {
  try {
    if (connected()) send(protocol::Goodbye{});
  } catch (const Error&) {
  }
  socket_.shutdown();
  if (reader_.joinable()) reader_.join();
}

void ServerClient::send(const protocol::Message& message) {
  std::lock_guard lock(send_mutex_);
  net::write_message(socket_, message);
}

void ServerClient::reader_loop() {
  std::string reason;
  try {
    for (;;) {
      net::ReceivedMessage in = net::read_message(socket_, protocol::kMaxServerPayloadBytes);
      if (in.status == net::ReceivedMessage::Status::kEndOfStream) {
        reason = "server closed the connection";
        break;
      }
      if (in.status == net::ReceivedMessage::Status::kRejected) {
        reason = "malformed message from the server: " + in.reason;
        break;
      }
      std::lock_guard lock(mutex_);
      bytes_received_ += in.frame_bytes;
      if (const auto* g = std::get_if<protocol::GenerationStarted>(&in.message)) {
        accepted_generation_ = g->generation;
        Scene scene = parse_scene(g->scene_json, "GenerationStarted");
        attribute_names_ = std::move(scene.attributes);
        slice_variables_.clear();
        for (const Slice& s : scene.slices) slice_variables_.emplace_back(s.id, s.var);
      } else if (const auto gen = result_generation(in.message)) {
        if (*gen < accepted_generation_) {
          ++stale_results_;
          continue;
        }
        if (auto* r = std::get_if<protocol::NodeResult>(&in.message)) {
          if (!r->slices.empty() && welcome_.version < protocol::kProtocolVersionSlices) {
            reason = fmt::format("malformed message from the server: NodeResult with slices on a "
                                 "protocol version {} connection",
                                 welcome_.version);
            break;
          }
          for (auto& sv : r->subvolumes) sv.mesh.attribute_names = attribute_names_;
          for (auto& slice : r->slices) {
            for (const auto& [id, var] : slice_variables_) {
              if (id == slice.slice_id) slice.mesh.attribute_names = {var};
            }
          }
        }
      } else if (const auto* e = std::get_if<protocol::ErrorMessage>(&in.message); e && e->fatal) {
        reason = fmt::format("server closed the connection: {}: {}",
                             protocol::wire_error_name(e->code), e->message);
      }
      inbox_.push_back(std::move(in.message));
      arrived_.notify_all();
    }
  } catch (const std::exception& e) {
    reason = e.what();
  }
  std::lock_guard lock(mutex_);
  open_ = false;
  if (close_reason_.empty()) close_reason_ = reason;
  arrived_.notify_all();
}

template <typename Match>
protocol::Message ServerClient::wait_for(Match match, std::string_view what,
                                         std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    for (auto it = inbox_.begin(); it != inbox_.end(); ++it) {
      if (const auto* e = std::get_if<protocol::ErrorMessage>(&*it)) {
        const Error error = server_error(*e);
        inbox_.erase(it);
        throw error;
      }
      if (match(*it)) {
        protocol::Message m = std::move(*it);
        inbox_.erase(it);
        return m;
      }
    }
    if (!open_) {
      throw make_error(ErrorCode::kIo, "waiting for {}: {}", what, close_reason_);
    }
    if (arrived_.wait_until(lock, deadline) == std::cv_status::timeout) {
      throw make_error(ErrorCode::kIo, "no {} from the server within {} ms", what,
                       timeout.count());
    }
  }
}

const format::Manifest& ServerClient::open_dataset(const std::string& name) {
  send(protocol::OpenDataset{name});
  protocol::Message m = wait_for(
      [](const protocol::Message& m) { return std::holds_alternative<protocol::DatasetOpened>(m); },
      "DatasetOpened", options_.timeout);
  const auto& opened = std::get<protocol::DatasetOpened>(m);
  manifest_ = format::decode_manifest(opened.manifest, "DatasetOpened manifest");
  octree_ = std::make_unique<OctreeLayout>(manifest_.dims(), manifest_.brick);
  return manifest_;
}

protocol::GenerationStarted ServerClient::start_generation(const protocol::Message& request,
                                                           std::uint32_t generation) {
  send(request);
  protocol::Message m = wait_for(
      [&](const protocol::Message& m) {
        const auto* g = std::get_if<protocol::GenerationStarted>(&m);
        return g && g->generation == generation;
      },
      "GenerationStarted", options_.timeout);
  {
    // Results the server sent before it switched are of no use any more.
    std::lock_guard lock(mutex_);
    std::erase_if(inbox_, [&](const protocol::Message& msg) {
      const auto gen = result_generation(msg);
      return gen && *gen < generation;
    });
  }
  return std::get<protocol::GenerationStarted>(m);
}

protocol::GenerationStarted ServerClient::set_scene(const Scene& scene) {
  const std::uint32_t generation = [&] {
    std::lock_guard lock(mutex_);
    return ++generation_;
  }();
  return start_generation(protocol::SetScene{generation, scene_to_json(scene)}, generation);
}

protocol::GenerationStarted ServerClient::set_time(std::uint32_t step) {
  const std::uint32_t generation = [&] {
    std::lock_guard lock(mutex_);
    return ++generation_;
  }();
  return start_generation(protocol::SetTime{generation, step}, generation);
}

std::uint32_t ServerClient::generation() const {
  std::lock_guard lock(mutex_);
  return generation_;
}

void ServerClient::update_cut(std::vector<protocol::NodePriority> added, std::vector<NodeId> removed,
                              std::vector<protocol::NodePriority> reprioritized) {
  send(protocol::CutUpdate{generation(), std::move(added), std::move(removed),
                           std::move(reprioritized)});
}

void ServerClient::request_stats() { send(protocol::StatsRequest{}); }

std::optional<protocol::Message> ServerClient::poll() {
  std::lock_guard lock(mutex_);
  if (inbox_.empty()) return std::nullopt;
  protocol::Message m = std::move(inbox_.front());
  inbox_.pop_front();
  return m;
}

std::optional<protocol::Message> ServerClient::wait(std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  arrived_.wait_for(lock, timeout, [&] { return !inbox_.empty() || !open_; });
  if (inbox_.empty()) return std::nullopt;
  protocol::Message m = std::move(inbox_.front());
  inbox_.pop_front();
  return m;
}

std::string ServerClient::stats(std::chrono::milliseconds timeout) {
  request_stats();
  protocol::Message m = wait_for(
      [](const protocol::Message& m) { return std::holds_alternative<protocol::Stats>(m); }, "Stats",
      timeout);
  return std::get<protocol::Stats>(m).json;
}

bool ServerClient::connected() const {
  std::lock_guard lock(mutex_);
  return open_;
}

std::string ServerClient::close_reason() const {
  std::lock_guard lock(mutex_);
  return close_reason_;
}

std::uint64_t ServerClient::stale_results() const {
  std::lock_guard lock(mutex_);
  return stale_results_;
}

std::uint64_t ServerClient::bytes_received() const {
  std::lock_guard lock(mutex_);
  return bytes_received_;
}

}  // namespace strielad::client
