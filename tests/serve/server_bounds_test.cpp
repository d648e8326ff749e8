// SPDX-License-Identifier: Apache-2.0
// strielad-serve's bounds (docs/security.md): the handshake has one
// deadline however its bytes trickle in; connections in the handshake have their own
// pool and never take an authenticated client's slot; a client that does not read makes
// the server stop reading it instead of queueing its replies without bound; generation 0
// is refused. Deadlines are short and configured; nothing here times the server.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <poll.h>
#include <sys/socket.h>

#include <chrono>
#include <functional>
#include <thread>

#include "convert/converter.h"
#include "client/server_client.h"
#include "core/error.h"
#include "format/manifest.h"
#include "net/message_stream.h"
#include "protocol/message_codec.h"
#include "serve/server.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using namespace std::chrono_literals;

constexpr const char* kToken = "correct horse battery staple";
constexpr const char* kSceneJson =
    R"({"time": 0, "subvolumes": [{"id": 1, "limits": [{"var": "cloud", "min": 1e-6}]}]})";

// Polls `done` every 10 ms for up to `limit`; returns its last value.
bool eventually(const std::function<bool()>& done, std::chrono::milliseconds limit = 30s) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

// True when the peer has closed the connection (end of stream or reset), without waiting.
bool closed_by_peer(const net::Socket& s) {
  pollfd p{s.fd(), POLLIN, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  std::byte b{};
  return ::recv(s.fd(), &b, 1, MSG_DONTWAIT) <= 0;
}

class ServerBoundsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    std::filesystem::create_directories(*dir_ / "root");
    std::filesystem::create_directories(*dir_ / "src");
    const auto data = testing::write_small_dataset(*dir_ / "src", 33, 29, 17, 2);
    build::convert(testing::small_convert_options(data, *dir_ / "root" / "small", 8));
  }
  static void TearDownTestSuite() { delete dir_; }

  serve::ServerConfig config() const {
    serve::ServerConfig c;
    c.root = *dir_ / "root";
    c.listen = net::Endpoint{"127.0.0.1", 0};
    c.token = kToken;
    c.threads = 1;
    c.cache_bytes = 16 << 20;
    return c;
  }
  std::unique_ptr<serve::Server> start(const serve::ServerConfig& c) {
    auto server = std::make_unique<serve::Server>(c);
    server->start();
    return server;
  }
  std::unique_ptr<client::ServerClient> connect(const serve::Server& server) {
    client::ClientOptions options;
    options.token = kToken;
    options.timeout = 20s;
    return client::ServerClient::connect(net::Endpoint{"127.0.0.1", server.port()}, options);
  }
  // A raw connection past Welcome (the client library never sends what these tests send).
  net::Socket greeted(const serve::Server& server) {
    net::Socket raw = net::connect_tcp({"127.0.0.1", server.port()});
    net::write_message(raw, protocol::Hello{protocol::kProtocolVersion, "raw", kToken});
    const auto welcome = net::read_message(raw, protocol::kMaxServerPayloadBytes);
    EXPECT_TRUE(std::holds_alternative<protocol::Welcome>(welcome.message));
    return raw;
  }

  static testing::TempDir* dir_;
};
testing::TempDir* ServerBoundsTest::dir_ = nullptr;

TEST_F(ServerBoundsTest, AHandshakeTricklingOneByteAtATimeIsClosedAtItsDeadline) {
  serve::ServerConfig c = config();
  c.handshake_timeout = 500ms;
  auto server = start(c);
  net::Socket raw = net::connect_tcp({"127.0.0.1", server->port()});
  // A Hello of 60 bytes at one byte per 100 ms: every byte well within the timeout, the
  // whole Hello ten times over it.
  const std::vector<std::byte> hello = protocol::encode_frame(
      protocol::Hello{protocol::kProtocolVersion, std::string(30, 'x'), kToken});
  ASSERT_GE(hello.size(), 50u);
  bool closed = false;
  std::size_t sent = 0;
  for (; sent + 1 < hello.size() && !closed; ++sent) {
    try {
      raw.write_all(std::span(hello).subspan(sent, 1));
    } catch (const Error&) {
      closed = true;
      break;
    }
    std::this_thread::sleep_for(100ms);
    closed = closed_by_peer(raw);
  }
  EXPECT_TRUE(closed) << "still open after " << sent << " bytes, one per 100 ms";
  EXPECT_TRUE(eventually([&] { return server->counters().handshakes == 0; }));
  EXPECT_EQ(server->counters().handshakes_dropped.load(), 1u);
  EXPECT_EQ(server->counters().clients.load(), 0);
  EXPECT_TRUE(connect(*server)->connected());  // the server still serves
}

TEST_F(ServerBoundsTest, ConnectionsInTheHandshakeDoNotTakeClientSlots) {
  serve::ServerConfig c = config();
  c.max_clients = 2;
  c.max_handshakes = 2;
  c.handshake_timeout = 60s;  // only the pool's limit closes them here
  auto server = start(c);
  // Two connections that never say Hello fill the handshake pool.
  net::Socket silent_a = net::connect_tcp({"127.0.0.1", server->port()});
  ASSERT_TRUE(eventually([&] { return server->counters().handshakes == 1; }));
  net::Socket silent_b = net::connect_tcp({"127.0.0.1", server->port()});
  ASSERT_TRUE(eventually([&] { return server->counters().handshakes == 2; }));

  // Both client slots are still free. A client arriving at a full pool closes the
  // oldest silent connection; the next finds room beside the other one.
  auto first = connect(*server);
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  EXPECT_EQ(net::read_message(silent_a, protocol::kMaxServerPayloadBytes, deadline).status,
            net::ReceivedMessage::Status::kEndOfStream);
  auto second = connect(*server);
  EXPECT_FALSE(closed_by_peer(silent_b));
  EXPECT_EQ(server->counters().handshakes_dropped.load(), 1u);

  // silent_a's session may still be ending.
  EXPECT_TRUE(eventually([&] { return server->counters().handshakes == 1; }));
  const auto stats = nlohmann::json::parse(second->stats());
  EXPECT_EQ(stats["clients"], 2);
  EXPECT_EQ(stats["max_clients"], 2);
  EXPECT_EQ(stats["handshakes"], 1);
  EXPECT_EQ(stats["max_handshakes"], 2);
  // Authenticated clients beyond max_clients are still turned away.
  try {
    connect(*server);
    FAIL() << "a third client was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("busy"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(first->connected());
}

// 300 KB of OpenDataset requests from a client that never reads once grew the server by
// 286 MB: every kind of reply now counts against the send-queue bound.
TEST_F(ServerBoundsTest, RepliesToAClientThatDoesNotReadStayWithinTheSendQueueBound) {
  serve::ServerConfig c = config();
  c.max_pending_send_bytes = 256 << 10;
  auto server = start(c);
  const auto store = Store::open(*dir_ / "root" / "small");
  const std::size_t reply_bytes =
      protocol::encode_frame(protocol::DatasetOpened{"small", format::encode_manifest(store->manifest())})
          .size();
  // Replies far beyond what the kernel's socket buffers can take.
  const std::size_t requests = std::max<std::size_t>(2000, (48u << 20) / reply_bytes);
  const std::uint64_t allowed = c.max_pending_send_bytes + reply_bytes;

  net::Socket raw = greeted(*server);
  std::thread writer([&] {
    for (std::size_t i = 0; i < requests; ++i) net::write_message(raw, protocol::OpenDataset{"small"});
  });
  const serve::ServerCounters& counters = server->counters();
  eventually([&] { return counters.readers_paused == 1 || counters.send_queue_peak_bytes > allowed; });
  EXPECT_EQ(counters.readers_paused.load(), 1) << "the server kept reading a client that does not read";
  EXPECT_LE(counters.send_queue_peak_bytes.load(), allowed);

  // Nothing is lost: once the client reads, every request is answered, in order.
  for (std::size_t i = 0; i < requests; ++i) {
    const auto in = net::read_message(raw, protocol::kMaxServerPayloadBytes);
    ASSERT_TRUE(std::holds_alternative<protocol::DatasetOpened>(in.message)) << "reply " << i;
  }
  writer.join();
  EXPECT_TRUE(eventually([&] { return counters.readers_paused == 0 && counters.send_queue_bytes == 0; }));
  EXPECT_LE(counters.send_queue_peak_bytes.load(), allowed);
}

TEST_F(ServerBoundsTest, GenerationZeroIsRefused) {
  auto server = start(config());
  net::Socket raw = greeted(*server);
  auto next = [&] { return net::read_message(raw, protocol::kMaxServerPayloadBytes).message; };
  net::write_message(raw, protocol::OpenDataset{"small"});
  ASSERT_TRUE(std::holds_alternative<protocol::DatasetOpened>(next()));
  net::write_message(raw, protocol::SetScene{0, kSceneJson});
  const auto refused = next();
  const auto* error = std::get_if<protocol::ErrorMessage>(&refused);
  ASSERT_TRUE(error) << "SetScene with generation 0 was accepted";
  EXPECT_EQ(error->code, protocol::WireError::kOutOfOrder);
  EXPECT_FALSE(error->fatal);
  EXPECT_NE(error->message.find("at least 1"), std::string::npos) << error->message;
  net::write_message(raw, protocol::SetScene{1, kSceneJson});
  const auto started = next();
  ASSERT_TRUE(std::holds_alternative<protocol::GenerationStarted>(started));
  EXPECT_EQ(std::get<protocol::GenerationStarted>(started).generation, 1u);
}

}  // namespace
}  // namespace strielad
