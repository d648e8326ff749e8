// SPDX-License-Identifier: Apache-2.0
// strielad-serve end to end over loopback with a generated store: results equal batch
// extraction, nearest nodes first, no stale result across rapid scene and time changes,
// token and root confinement, a malformed client closed alone, disconnects cancelling.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <map>
#include <set>
#include <thread>

#include "convert/converter.h"
#include "client/server_client.h"
#include "core/error.h"
#include "extract/node_extraction.h"
#include "net/message_stream.h"
#include "protocol/message_codec.h"
#include "serve/server.h"
#include "store/store.h"
#include "support/server_results.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using namespace std::chrono_literals;
using protocol::NodePriority;

constexpr const char* kToken = "correct horse battery staple";
constexpr const char* kSceneJson = R"({"time": 0, "subvolumes": [
    {"id": 4, "name": "cloud", "limits": [{"var": "cloud", "min": 1e-6}]},
    {"id": 9, "name": "warm box", "limits": [{"var": "temp", "min": 250}],
     "domain": {"lon": [2, 20]}}],
    "attributes": ["temp"]})";

class ServerLoopbackTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    std::filesystem::create_directories(*dir_ / "root");
    std::filesystem::create_directories(*dir_ / "src");
    const auto data = testing::write_small_dataset(*dir_ / "src", 33, 29, 17, 2);
    build::convert(testing::small_convert_options(data, *dir_ / "root" / "small", 8));
  }
  static void TearDownTestSuite() { delete dir_; }

  std::unique_ptr<serve::Server> start_server(unsigned threads = 2, std::size_t max_clients = 8,
                                              bool direct_reads = false) {
    serve::ServerConfig config;
    config.direct_reads = direct_reads;
    config.root = *dir_ / "root";
    config.listen = net::Endpoint{"127.0.0.1", 0};
    config.token = kToken;
    config.threads = threads;
    config.cache_bytes = 64 << 20;
    config.max_clients = max_clients;
    auto server = std::make_unique<serve::Server>(config);
    server->start();
    return server;
  }
  std::unique_ptr<client::ServerClient> connect(const serve::Server& server,
                                                std::string token = kToken) {
    client::ClientOptions options;
    options.token = std::move(token);
    options.timeout = 20s;
    return client::ServerClient::connect(net::Endpoint{"127.0.0.1", server.port()}, options);
  }

  // Every node of the whole octree over the wire equals batch extraction.
  void expect_results_equal_batch_extraction(bool direct_reads);

  static testing::TempDir* dir_;
};
testing::TempDir* ServerLoopbackTest::dir_ = nullptr;

using testing::whole_octree;

std::map<NodeId, protocol::NodeResult> collect(client::ServerClient& c, std::size_t wanted,
                                               std::uint32_t generation,
                                               std::vector<NodeId>* order = nullptr) {
  return testing::collect_results(c, wanted, generation, order, 20s);
}

void ServerLoopbackTest::expect_results_equal_batch_extraction(bool direct_reads) {
  auto server = start_server(2, 8, direct_reads);
  auto c = connect(*server);
  c->open_dataset("small");
  const Scene scene = parse_scene(kSceneJson, "test");
  const auto started = c->set_scene(scene);
  EXPECT_EQ(started.step, 0u);
  const OctreeLayout& octree = c->octree();
  c->update_cut(whole_octree(octree), {}, {});
  const auto results = collect(*c, octree.node_count(), started.generation);

  const auto store = Store::open(*dir_ / "root" / "small");
  const ResolvedScene resolved = resolve_scene(scene, store->manifest(), "test");
  std::size_t meshes = 0;
  for (const auto& [node, wire] : results) {
    const NodeExtraction batch = extract_node(*store, nullptr, resolved, 0, node);
    ASSERT_EQ(wire.subvolumes.size(), batch.results.size());
    for (std::size_t s = 0; s < batch.results.size(); ++s) {
      const SubVolumeResult& want = batch.results[s];
      const SubVolumeResult& got = wire.subvolumes[s];
      EXPECT_EQ(got.subvolume_id, want.subvolume_id);
      ASSERT_EQ(got.outcome, want.outcome) << "node " << node;
      EXPECT_EQ(got.reason, want.reason);
      ASSERT_EQ(got.mesh.triangles, want.mesh.triangles);
      EXPECT_EQ(got.mesh.face_kinds, want.mesh.face_kinds);
      ASSERT_EQ(got.mesh.positions.size(), want.mesh.positions.size());
      if (want.outcome != NodeOutcome::kMesh) continue;
      ++meshes;
      EXPECT_EQ(got.mesh.attribute_names, std::vector<std::string>{"temp"});
      for (int a = 0; a < 3; ++a) {
        double lo = INFINITY, hi = -INFINITY;
        for (const auto& p : want.mesh.positions) lo = std::min(lo, p[a]), hi = std::max(hi, p[a]);
        const double quantum = (hi - lo) / 65535.0;
        for (std::size_t v = 0; v < want.mesh.positions.size(); ++v) {
          EXPECT_NEAR(got.mesh.positions[v][a], want.mesh.positions[v][a], quantum * 0.51 + 1e-12);
        }
      }
      for (std::size_t v = 0; v < want.mesh.normals.size(); ++v) {
        const auto& g = got.mesh.normals[v];
        const auto& w = want.mesh.normals[v];
        EXPECT_GT(g[0] * w[0] + g[1] * w[1] + g[2] * w[2], 0.9999f);
      }
      ASSERT_EQ(got.mesh.attributes.size(), 1u);
      const auto& want_values = want.mesh.attributes[0];
      float lo = INFINITY, hi = -INFINITY;
      for (float x : want_values) if (!std::isnan(x)) lo = std::min(lo, x), hi = std::max(hi, x);
      for (std::size_t v = 0; v < want_values.size(); ++v) {
        if (std::isnan(want_values[v])) {
          EXPECT_TRUE(std::isnan(got.mesh.attributes[0][v]));
        } else {
          EXPECT_NEAR(got.mesh.attributes[0][v], want_values[v], (hi - lo) / 65534.0 * 0.51 + 1e-4);
        }
      }
    }
  }
  EXPECT_GT(meshes, 5u);
  EXPECT_EQ(c->stale_results(), 0u);
}

TEST_F(ServerLoopbackTest, ResultsEqualBatchExtraction) { expect_results_equal_batch_extraction(false); }

// --direct-io: bricks read with O_DIRECT (or buffered where the file system has none).
TEST_F(ServerLoopbackTest, DirectReadsGiveTheSameResults) {
  expect_results_equal_batch_extraction(true);
}

// Counts how many nodes run at once; the first two wait (up to 10 s) for each other.
class ConcurrencyProbe final : public serve::NodeExecutor {
 public:
  serve::NodeOutput execute(const serve::NodeTask& task) override {
    {
      std::unique_lock lock(mutex_);
      max_running_ = std::max(max_running_, ++running_);
      both_.notify_all();
      both_.wait_for(lock, 10s, [&] { return max_running_ >= 2; });
    }
    serve::NodeOutput out = local_.execute(task);
    std::lock_guard lock(mutex_);
    --running_;
    return out;
  }
  std::size_t prefetch(const serve::NodeTask&, const serve::YieldCheck&) override { return 0; }
  BrickCacheStats cache_stats() const override { return local_.cache_stats(); }
  int max_running() {
    std::lock_guard lock(mutex_);
    return max_running_;
  }

 private:
  serve::LocalNodeExecutor local_{16 << 20};
  std::mutex mutex_;
  std::condition_variable both_;
  int running_ = 0, max_running_ = 0;
};

TEST_F(ServerLoopbackTest, TwoWorkersExtractTwoNodesAtOnce) {
  serve::ServerConfig config;
  config.root = *dir_ / "root";
  config.listen = net::Endpoint{"127.0.0.1", 0};
  config.threads = 2;
  auto probe = std::make_unique<ConcurrencyProbe>();
  ConcurrencyProbe* seen = probe.get();
  serve::Server server(config, std::move(probe));
  server.start();
  auto c = client::ServerClient::connect({"127.0.0.1", server.port()});
  c->open_dataset("small");
  const auto started = c->set_scene(parse_scene(kSceneJson, "test"));
  c->update_cut(whole_octree(c->octree()), {}, {});  // one update, one wake-up
  collect(*c, c->octree().node_count(), started.generation);
  EXPECT_EQ(seen->max_running(), 2);
}

TEST_F(ServerLoopbackTest, OneWorkerSendsNearestNodesFirst) {
  auto server = start_server(1);
  auto c = connect(*server);
  c->open_dataset("small");
  const auto started = c->set_scene(parse_scene(kSceneJson, "test"));
  const std::size_t n = c->octree().node_count();
  std::vector<NodePriority> nodes;
  for (NodeId node = 0; node < n; ++node) nodes.push_back({node, float((node * 7919) % 101)});
  c->update_cut(nodes, {}, {});
  std::vector<NodeId> order;
  collect(*c, n, started.generation, &order);
  ASSERT_EQ(order.size(), n);
  std::map<NodeId, float> priority;
  for (const auto& p : nodes) priority[p.node] = p.priority;
  // The first node may have started before the rest of the list was queued; after it
  // the order must follow the priorities.
  for (std::size_t i = 2; i < order.size(); ++i) {
    EXPECT_LE(priority[order[i - 1]], priority[order[i]]) << "at " << i;
  }
}

TEST_F(ServerLoopbackTest, NoStaleResultAcrossRapidSceneAndTimeChanges) {
  auto server = start_server();
  auto c = connect(*server);
  c->open_dataset("small");
  const Scene scene = parse_scene(kSceneJson, "test");
  const auto nodes = whole_octree(c->octree());
  const std::uint32_t generation = testing::change_generations_rapidly(*c, scene, nodes, 40);
  const auto results = collect(*c, nodes.size(), generation);
  EXPECT_EQ(results.size(), nodes.size());
  EXPECT_EQ(c->stale_results(), 0u);
  const auto stats = nlohmann::json::parse(c->stats());
  EXPECT_GT(stats["nodes_cancelled"].get<std::uint64_t>(), 0u);
  EXPECT_EQ(stats["queued"].get<std::int64_t>(), 0);
}

TEST_F(ServerLoopbackTest, RemovedAndReprioritizedNodesFollowTheCut) {
  auto server = start_server(1);
  auto c = connect(*server);
  c->open_dataset("small");
  const auto started = c->set_scene(parse_scene(kSceneJson, "test"));
  const std::size_t n = c->octree().node_count();
  // Add all, then remove the odd ones and reverse the even ones' order in one update.
  std::vector<NodePriority> all;
  for (NodeId node = 0; node < n; ++node) all.push_back({node, float(node)});
  std::vector<NodeId> removed;
  std::vector<NodePriority> changed;
  for (NodeId node = 0; node < n; ++node) {
    if (node % 2) removed.push_back(node);
    else changed.push_back({node, float(n - node)});
  }
  c->update_cut(all, {}, {});
  c->update_cut({}, removed, changed);
  // Removed nodes may only have been sent before the removal arrived, i.e. early.
  std::map<NodeId, protocol::NodeResult> results;
  const std::size_t evens = (n + 1) / 2;
  std::size_t evens_seen = 0;
  while (evens_seen < evens) {
    auto m = c->wait(20s);
    ASSERT_TRUE(m) << c->close_reason();
    auto* r = std::get_if<protocol::NodeResult>(&*m);
    ASSERT_TRUE(r);
    EXPECT_TRUE(results.emplace(r->node, *r).second);
    if (r->node % 2 == 0) ++evens_seen;
  }
  std::this_thread::sleep_for(100ms);
  EXPECT_FALSE(c->poll().has_value()) << "a removed node arrived after all kept ones";
  EXPECT_EQ(started.generation, c->generation());
}

TEST_F(ServerLoopbackTest, WrongTokenIsRefused) {
  auto server = start_server();
  try {
    connect(*server, "wrong");
    FAIL() << "connected with a wrong token";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("token"), std::string::npos) << e.what();
  }
  EXPECT_THROW(connect(*server, ""), Error);
  auto ok = connect(*server);
  EXPECT_TRUE(ok->connected());
}

TEST_F(ServerLoopbackTest, DatasetsOnlyFromUnderTheRoot) {
  auto server = start_server();
  auto c = connect(*server);
  std::filesystem::create_directory_symlink(*dir_ / "src", *dir_ / "root" / "escape");
  for (const char* name : {"../src", "/etc", "small/../../src", "escape", "", "./small", "nope"}) {
    try {
      c->open_dataset(name);
      ADD_FAILURE() << "opened '" << name << "'";
    } catch (const Error& e) {
      EXPECT_TRUE(e.code() == ErrorCode::kInvalidArgument || e.code() == ErrorCode::kNotFound)
          << name << ": " << e.what();
    }
  }
  std::filesystem::remove(*dir_ / "root" / "escape");
  EXPECT_EQ(c->open_dataset("small").variables.size(), 3u);  // the connection still works
}

TEST_F(ServerLoopbackTest, ErrorsNameTheDatasetNotTheServersPath) {
  // A damaged manifest (open fails) and damaged chunks (nodes fail): the client learns
  // the dataset's name, never where the server keeps it.
  namespace fs = std::filesystem;
  const fs::path root = fs::canonical(*dir_ / "root");
  fs::copy(root / "small", root / "bad-manifest", fs::copy_options::recursive);
  {
    std::fstream f(root / "bad-manifest" / "MANIFEST", std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(100);
    f.put('#');
  }
  fs::copy(root / "small", root / "bad-chunks", fs::copy_options::recursive);
  {
    const auto store = Store::open(root / "bad-chunks");
    std::fstream f(root / "bad-chunks" / format::step_file_name(0),
                   std::ios::in | std::ios::out | std::ios::binary);
    for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
      for (const format::IndexEntry& e : store->index(0, v)) {
        if (e.kind != format::BrickKind::kData) continue;
        f.seekp(static_cast<std::streamoff>(e.chunk_offset + e.chunk_size / 2));
        f.put('\xa5');
        f.put('\x5a');
      }
    }
  }
  auto server = start_server();
  auto c = connect(*server);
  const std::string private_path = dir_->path().string();
  try {
    c->open_dataset("bad-manifest");
    ADD_FAILURE() << "opened a damaged manifest";
  } catch (const Error& e) {
    const std::string text = e.what();
    EXPECT_EQ(e.code(), ErrorCode::kCorrupt) << text;
    EXPECT_NE(text.find("dataset 'bad-manifest': bad-manifest/MANIFEST: checksum mismatch"),
              std::string::npos) << text;
    EXPECT_EQ(text.find(private_path), std::string::npos) << text;
  }
  c->open_dataset("bad-chunks");
  const auto started = c->set_scene(parse_scene(kSceneJson, "test"));
  c->update_cut(whole_octree(c->octree()), {}, {});
  std::size_t failed = 0, answers = 0;
  while (answers < c->octree().node_count()) {
    auto m = c->wait(20s);
    ASSERT_TRUE(m) << c->close_reason();
    if (const auto* f = std::get_if<protocol::NodeFailed>(&*m)) {
      ++failed;
      EXPECT_EQ(f->generation, started.generation);
      EXPECT_NE(f->message.find("bad-chunks/steps/step-000000.bricks"), std::string::npos)
          << f->message;
      EXPECT_EQ(f->message.find(private_path), std::string::npos) << f->message;
    }
    answers += std::holds_alternative<protocol::NodeFailed>(*m) ||
               std::holds_alternative<protocol::NodeResult>(*m);
  }
  EXPECT_GT(failed, 0u);
  fs::remove_all(root / "bad-manifest");
  fs::remove_all(root / "bad-chunks");
}

TEST_F(ServerLoopbackTest, MalformedMessageClosesOnlyThatConnection) {
  auto server = start_server();
  auto good = connect(*server);
  good->open_dataset("small");

  net::Socket raw = net::connect_tcp({"127.0.0.1", server->port()});
  net::write_message(raw, protocol::Hello{protocol::kProtocolVersion, "raw", kToken});
  ASSERT_EQ(net::read_message(raw, protocol::kMaxServerPayloadBytes).status,
            net::ReceivedMessage::Status::kMessage);
  // A frame announcing a 1 GiB payload: refused from its header.
  const std::array<std::byte, 8> header{std::byte{0}, std::byte{0}, std::byte{0}, std::byte{0x40},
                                        std::byte{5}, std::byte{0}, std::byte{0}, std::byte{0}};
  raw.write_all(header);
  const auto reply = net::read_message(raw, protocol::kMaxServerPayloadBytes);
  ASSERT_EQ(reply.status, net::ReceivedMessage::Status::kMessage);
  const auto* error = std::get_if<protocol::ErrorMessage>(&reply.message);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->code, protocol::WireError::kTooLarge);
  EXPECT_TRUE(error->fatal);
  EXPECT_EQ(net::read_message(raw, protocol::kMaxServerPayloadBytes).status,
            net::ReceivedMessage::Status::kEndOfStream);

  const auto started = good->set_scene(parse_scene(kSceneJson, "test"));
  good->update_cut({{0, 1.0f}}, {}, {});
  EXPECT_EQ(collect(*good, 1, started.generation).size(), 1u);
}

// Raw messages: the client library never sends these.
TEST_F(ServerLoopbackTest, OldGenerationsAreRejected) {
  auto server = start_server();
  net::Socket raw = net::connect_tcp({"127.0.0.1", server->port()});
  auto next = [&] {
    auto in = net::read_message(raw, protocol::kMaxServerPayloadBytes);
    EXPECT_EQ(in.status, net::ReceivedMessage::Status::kMessage);
    return in.message;
  };
  auto expect_out_of_order = [&] {
    const auto m = next();
    const auto* e = std::get_if<protocol::ErrorMessage>(&m);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, protocol::WireError::kOutOfOrder);
    EXPECT_FALSE(e->fatal);
  };
  net::write_message(raw, protocol::Hello{protocol::kProtocolVersion, "raw", kToken});
  ASSERT_TRUE(std::holds_alternative<protocol::Welcome>(next()));
  net::write_message(raw, protocol::SetScene{1, kSceneJson});  // no dataset yet
  expect_out_of_order();
  net::write_message(raw, protocol::OpenDataset{"small"});
  ASSERT_TRUE(std::holds_alternative<protocol::DatasetOpened>(next()));
  net::write_message(raw, protocol::CutUpdate{0, {{0, 1.0f}}, {}, {}});  // no scene yet
  expect_out_of_order();
  net::write_message(raw, protocol::SetScene{5, kSceneJson});
  ASSERT_TRUE(std::holds_alternative<protocol::GenerationStarted>(next()));
  net::write_message(raw, protocol::CutUpdate{4, {{0, 1.0f}}, {}, {}});
  expect_out_of_order();
  net::write_message(raw, protocol::SetTime{5, 1});  // not greater than 5
  expect_out_of_order();
  net::write_message(raw, protocol::SetTime{6, 1});
  const auto started = next();
  ASSERT_TRUE(std::holds_alternative<protocol::GenerationStarted>(started));
  EXPECT_EQ(std::get<protocol::GenerationStarted>(started).step, 1u);
  net::write_message(raw, protocol::CutUpdate{6, {{0, 1.0f}}, {}, {}});
  const auto result = next();
  ASSERT_TRUE(std::holds_alternative<protocol::NodeResult>(result));
  EXPECT_EQ(std::get<protocol::NodeResult>(result).generation, 6u);
}

TEST_F(ServerLoopbackTest, SceneAboveTheServersLimitsIsTooLargeAndASecondHelloIsFatal) {
  serve::ServerConfig config;
  config.root = *dir_ / "root";
  config.listen = net::Endpoint{"127.0.0.1", 0};
  config.limits.max_subvolumes = 1;
  serve::Server server(config);
  server.start();
  net::Socket raw = net::connect_tcp({"127.0.0.1", server.port()});
  auto next = [&] {
    auto in = net::read_message(raw, protocol::kMaxServerPayloadBytes);
    EXPECT_EQ(in.status, net::ReceivedMessage::Status::kMessage);
    return in.message;
  };
  net::write_message(raw, protocol::Hello{protocol::kProtocolVersion, "raw", ""});
  const auto welcome = next();
  ASSERT_TRUE(std::holds_alternative<protocol::Welcome>(welcome));
  EXPECT_EQ(std::get<protocol::Welcome>(welcome).limits.max_subvolumes, 1u);
  net::write_message(raw, protocol::OpenDataset{"small"});
  ASSERT_TRUE(std::holds_alternative<protocol::DatasetOpened>(next()));
  net::write_message(raw, protocol::SetScene{1, kSceneJson});  // two sub-volumes
  auto m = next();
  auto* e = std::get_if<protocol::ErrorMessage>(&m);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, protocol::WireError::kTooLarge);
  EXPECT_FALSE(e->fatal);
  net::write_message(raw, protocol::Hello{protocol::kProtocolVersion, "again", ""});
  m = next();
  e = std::get_if<protocol::ErrorMessage>(&m);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, protocol::WireError::kOutOfOrder);
  EXPECT_TRUE(e->fatal);
  EXPECT_NE(e->message.find("Hello"), std::string::npos) << e->message;
  EXPECT_EQ(net::read_message(raw, protocol::kMaxServerPayloadBytes).status,
            net::ReceivedMessage::Status::kEndOfStream);
}

TEST_F(ServerLoopbackTest, DisconnectMidStreamCancelsItsWork) {
  auto server = start_server(1);
  {
    auto c = connect(*server);
    c->open_dataset("small");
    c->set_scene(parse_scene(kSceneJson, "test"));
    c->update_cut(whole_octree(c->octree()), {}, {});
  }  // gone without reading
  for (int i = 0; i < 200 && (server->counters().queued || server->counters().running ||
                              server->counters().clients); ++i) {
    std::this_thread::sleep_for(10ms);
  }
  EXPECT_EQ(server->counters().queued.load(), 0);
  EXPECT_EQ(server->counters().running.load(), 0);
  EXPECT_EQ(server->counters().clients.load(), 0);
}

TEST_F(ServerLoopbackTest, ClientsBeyondTheLimitAreTurnedAway) {
  auto server = start_server(1, 2);
  auto a = connect(*server);
  auto b = connect(*server);
  try {
    connect(*server);
    FAIL() << "third client accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("busy"), std::string::npos) << e.what();
  }
}

TEST_F(ServerLoopbackTest, InvalidSceneIsAnErrorNotADisconnect) {
  auto server = start_server();
  auto c = connect(*server);
  EXPECT_THROW(c->set_scene(parse_scene(kSceneJson, "test")), Error);  // no dataset yet
  c->open_dataset("small");
  Scene bad = parse_scene(kSceneJson, "test");
  bad.subvolumes[0].limits[0].var = "no_such_variable";
  try {
    c->set_scene(bad);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_variable"), std::string::npos) << e.what();
  }
  EXPECT_THROW(c->set_time(99), Error);
  const auto started = c->set_scene(parse_scene(kSceneJson, "test"));
  c->update_cut({{0, 0.0f}, {1u << 30, 1.0f}}, {}, {});
  bool failed = false, result = false;
  for (int i = 0; i < 2; ++i) {
    auto m = c->wait(20s);
    ASSERT_TRUE(m);
    if (auto* f = std::get_if<protocol::NodeFailed>(&*m)) {
      failed = true;
      EXPECT_EQ(f->code, protocol::WireError::kNotFound);
      EXPECT_EQ(f->generation, started.generation);
    }
    result |= std::holds_alternative<protocol::NodeResult>(*m);
  }
  EXPECT_TRUE(failed);
  EXPECT_TRUE(result);
}

}  // namespace
}  // namespace strielad
