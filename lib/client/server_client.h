// SPDX-License-Identifier: Apache-2.0
// The client side of formats/protocol.md, used by strielad-view and strielad-bench: a
// connection with a reader thread that queues incoming messages, so a render loop can
// poll() without ever blocking on the network. Generations are numbered by the client.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "format/manifest.h"
#include "net/socket.h"
#include "protocol/messages.h"
#include "scene/scene.h"

namespace strielad::client {

struct ClientOptions {
  std::string client_name = "strielad-client";
  std::string token;  // empty: none
  // The highest protocol version to offer in Hello (formats/protocol.md): 2 receives
  // slice results; 1 behaves as a version-1 client (a scene with slices is refused).
  std::uint16_t protocol_version = protocol::kProtocolVersion;
  // How long the synchronous calls (connect, open_dataset, set_scene, set_time) wait.
  std::chrono::milliseconds timeout{30000};
};

class ServerClient {
 public:
  // Connects and performs the handshake.
  // \error kIo when the server cannot be reached or closes; an ErrorMessage from the
  // server becomes the Error of its code (kInvalidArgument for kUnauthorized, ...) with
  // the server's message.
  static std::unique_ptr<ServerClient> connect(const net::Endpoint& endpoint,
                                               ClientOptions options = {});
  ~ServerClient();  // says Goodbye and closes

  const protocol::Welcome& welcome() const { return welcome_; }
  // The version both speak (Welcome's).
  std::uint16_t protocol_version() const { return welcome_.version; }

  // Opens a dataset by name under the server's root and waits for its manifest.
  // \error the server's error (kNotFound, kInvalidArgument for a name outside the root).
  const format::Manifest& open_dataset(const std::string& name);
  const format::Manifest& manifest() const { return manifest_; }
  const OctreeLayout& octree() const { return *octree_; }

  // Start a new generation and wait until the server confirms it; every message after
  // the returned GenerationStarted belongs to it. The cut starts empty: send the whole
  // cut as `added` again. \error the server's error for an invalid scene or step.
  protocol::GenerationStarted set_scene(const Scene& scene);
  protocol::GenerationStarted set_time(std::uint32_t step);
  std::uint32_t generation() const;

  void update_cut(std::vector<protocol::NodePriority> added, std::vector<NodeId> removed,
                  std::vector<protocol::NodePriority> reprioritized);
  void request_stats();

  // The next message (NodeResult, NodeFailed, ErrorMessage, Stats), or nothing yet.
  // Results of older generations never surface: they are counted in stale_results()
  // (the server must never send them, so that count stays 0).
  std::optional<protocol::Message> poll();
  std::optional<protocol::Message> wait(std::chrono::milliseconds timeout);
  // Waits for the next Stats reply, keeping other messages queued.
  std::string stats(std::chrono::milliseconds timeout = std::chrono::milliseconds(10000));

  bool connected() const;
  std::string close_reason() const;
  std::uint64_t stale_results() const;
  std::uint64_t bytes_received() const;

 private:
  ServerClient(net::Socket socket, ClientOptions options);
  void reader_loop();
  void send(const protocol::Message& message);
  // Waits for the first queued message satisfying `match`, which is removed and
  // returned; an ErrorMessage received meanwhile throws it.
  template <typename Match>
  protocol::Message wait_for(Match match, std::string_view what, std::chrono::milliseconds timeout);
  protocol::GenerationStarted start_generation(const protocol::Message& request,
                                               std::uint32_t generation);

  net::Socket socket_;
  ClientOptions options_;
  protocol::Welcome welcome_;
  format::Manifest manifest_;
  std::unique_ptr<OctreeLayout> octree_;
  std::mutex send_mutex_;

  mutable std::mutex mutex_;  // guards everything below
  std::condition_variable arrived_;
  std::deque<protocol::Message> inbox_;
  std::uint32_t generation_ = 0;
  std::uint32_t accepted_generation_ = 0;  // last GenerationStarted received
  std::vector<std::string> attribute_names_;
  std::vector<std::pair<std::uint32_t, std::string>> slice_variables_;  // id, colouring variable
  bool open_ = true;
  std::string close_reason_;
  std::uint64_t stale_results_ = 0;
  std::uint64_t bytes_received_ = 0;
  std::thread reader_;
};

}  // namespace strielad::client
