// SPDX-License-Identifier: Apache-2.0
// strielad-serve under mpirun (rank 0 serves, ranks 1..N-1 extract) gives the same
// results as the threaded server: for a whole cut at two time steps every node's
// NodeResult is the same bytes. Rapid generation changes across ranks leave no stale
// result, -np 1 runs threaded, and a SIGTERM to rank 0 ends every rank with status 0.
// Skipped when mpirun is not installed.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "convert/converter.h"
#include "client/server_client.h"
#include "core/error.h"
#include "protocol/message_codec.h"
#include "serve/server.h"
#include "support/small_dataset.h"
#include "support/server_results.h"
#include "support/temp_dir.h"

extern char** environ;

namespace strielad {
namespace {

using namespace std::chrono_literals;
using protocol::NodePriority;

constexpr const char* kSceneJson = R"({"time": 0, "subvolumes": [
    {"id": 4, "name": "cloud", "limits": [{"var": "cloud", "min": 1e-6}]},
    {"id": 9, "name": "warm box", "limits": [{"var": "temp", "min": 250}],
     "domain": {"lon": [2, 20]}}],
    "attributes": ["temp"]})";

std::filesystem::path find_in_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// `mpirun -np N strielad-serve --root ROOT --listen 127.0.0.1:0 --json ...` as a child
// process: its first stdout line is the endpoint, stderr goes to a log file.
class MpiServer {
 public:
  MpiServer(const std::filesystem::path& mpirun, int ranks, const std::filesystem::path& root,
            const std::filesystem::path& log, std::vector<std::string> extra)
      : log_(log) {
    std::vector<std::string> args = {mpirun.string(), "--allow-run-as-root", "--oversubscribe",
                                      "--bind-to", "none", "-np", std::to_string(ranks),
                                      STRIELAD_SERVE_EXE, "--root", root.string(),
                                      "--listen", "127.0.0.1:0", "--json"};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    int out[2];
    if (::pipe(out) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    posix_spawn_file_actions_addclose(&actions, out[1]);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int rc = ::posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    stdout_ = out[0];
    if (rc != 0) {
      pid_ = -1;
      throw std::runtime_error("cannot start mpirun");
    }
  }

  ~MpiServer() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      if (!wait_exit(20s)) {
        ::kill(pid_, SIGKILL);
        wait_exit(20s);
      }
    }
    if (stdout_ >= 0) ::close(stdout_);
  }

  // Reads the endpoint line; false (with the log in `error`) when none comes in time.
  bool read_endpoint(std::chrono::seconds timeout, std::string& error) {
    std::string line;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (line.find('\n') == std::string::npos) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      pollfd p{stdout_, POLLIN, 0};
      if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) {
        error = "no endpoint line in time; log:\n" + read_file(log_);
        return false;
      }
      char buffer[512];
      const ssize_t n = ::read(stdout_, buffer, sizeof buffer);
      if (n <= 0) {
        error = "mpirun closed its output; log:\n" + read_file(log_);
        return false;
      }
      line.append(buffer, static_cast<std::size_t>(n));
    }
    endpoint_ = nlohmann::json::parse(line.substr(0, line.find('\n')));
    return true;
  }

  const nlohmann::json& endpoint() const { return endpoint_; }
  net::Endpoint address() const {
    return {endpoint_["host"].get<std::string>(), endpoint_["port"].get<std::uint16_t>()};
  }
  pid_t rank0_pid() const { return endpoint_.value("pid", -1); }
  pid_t mpirun_pid() const { return pid_; }
  std::string log() const { return read_file(log_); }

  // Waits for mpirun to end; true with its wait status in `status` when it did in time.
  bool wait_exit(std::chrono::seconds timeout, int* status = nullptr) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      int s = 0;
      const pid_t r = ::waitpid(pid_, &s, WNOHANG);
      if (r == pid_) {
        pid_ = -1;
        if (status) *status = s;
        return true;
      }
      std::this_thread::sleep_for(20ms);
    }
    return false;
  }

 private:
  std::filesystem::path log_;
  pid_t pid_ = -1;
  int stdout_ = -1;
  nlohmann::json endpoint_;
};

class MpiServerTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mpirun_ = new std::filesystem::path(find_in_path("mpirun"));
    if (mpirun_->empty()) return;
    dir_ = new testing::TempDir();
    std::filesystem::create_directories(*dir_ / "root");
    std::filesystem::create_directories(*dir_ / "src");
    const auto data = testing::write_small_dataset(*dir_ / "src", 33, 29, 17, 2);
    build::convert(testing::small_convert_options(data, *dir_ / "root" / "small", 8));
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete mpirun_;
    dir_ = nullptr;
  }
  void SetUp() override {
    if (mpirun_->empty()) GTEST_SKIP() << "mpirun is not installed (package openmpi-bin)";
  }

  std::unique_ptr<MpiServer> start_mpi(int ranks, std::vector<std::string> extra = {}) {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    auto server = std::make_unique<MpiServer>(
        *mpirun_, ranks, *dir_ / "root", *dir_ / (name + "-" + std::to_string(ranks) + ".log"),
        std::move(extra));
    std::string error;
    if (!server->read_endpoint(120s, error)) {
      ADD_FAILURE() << error;
      return nullptr;
    }
    return server;
  }

  static std::unique_ptr<client::ServerClient> connect(const net::Endpoint& endpoint) {
    client::ClientOptions options;
    options.timeout = 60s;
    return client::ServerClient::connect(endpoint, options);
  }

  static testing::TempDir* dir_;
  static std::filesystem::path* mpirun_;
};
testing::TempDir* MpiServerTest::dir_ = nullptr;
std::filesystem::path* MpiServerTest::mpirun_ = nullptr;

using testing::whole_octree;

// One NodeResult per node, re-encoded: the bytes are equal exactly when the frames the
// servers sent decode to the same values.
std::map<NodeId, std::vector<std::byte>> collect_frames(client::ServerClient& c, std::size_t wanted,
                                                        std::uint32_t generation) {
  std::map<NodeId, std::vector<std::byte>> frames;
  for (const auto& [node, result] : testing::collect_results(c, wanted, generation)) {
    frames[node] = protocol::encode_frame(result);
  }
  return frames;
}

struct CutRun {
  std::map<NodeId, std::vector<std::byte>> step0, step1;
  double seconds0 = 0;  // first cut, cold caches
};

// The whole octree at step 0 (scene), then at step 1 (SetTime).
CutRun run_cuts(client::ServerClient& c) {
  CutRun run;
  c.open_dataset("small");
  const auto start = std::chrono::steady_clock::now();
  const auto started = c.set_scene(parse_scene(kSceneJson, "test"));
  const auto nodes = whole_octree(c.octree());
  c.update_cut(nodes, {}, {});
  run.step0 = collect_frames(c, nodes.size(), started.generation);
  run.seconds0 = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto next = c.set_time(1);
  c.update_cut(nodes, {}, {});
  run.step1 = collect_frames(c, nodes.size(), next.generation);
  EXPECT_EQ(c.stale_results(), 0u);
  return run;
}

void expect_same_frames(const std::map<NodeId, std::vector<std::byte>>& mpi,
                        const std::map<NodeId, std::vector<std::byte>>& threaded,
                        std::string_view what) {
  ASSERT_EQ(mpi.size(), threaded.size()) << what;
  std::size_t differing = 0;
  for (const auto& [node, frame] : threaded) {
    const auto it = mpi.find(node);
    ASSERT_NE(it, mpi.end()) << what << ": node " << node << " missing";
    if (it->second != frame && ++differing <= 5) {
      ADD_FAILURE() << what << ": node " << node << " differs (" << it->second.size() << " vs "
                    << frame.size() << " bytes)";
    }
  }
  EXPECT_EQ(differing, 0u) << what;
}

void expect_clean_stop(MpiServer& server) {
  const pid_t rank0 = server.rank0_pid();
  ASSERT_GT(rank0, 0) << "no pid in the endpoint line " << server.endpoint().dump();
  ASSERT_EQ(::kill(rank0, SIGTERM), 0);
  int status = 0;
  ASSERT_TRUE(server.wait_exit(60s, &status)) << "mpirun still running; log:\n" << server.log();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << "mpirun wait status " << status << "; log:\n" << server.log();
  EXPECT_NE(server.log().find("worker ranks stopped"), std::string::npos) << server.log();
}

TEST_F(MpiServerTest, MpiRunEqualsThreadedRun) {
  serve::ServerConfig config;
  config.root = *dir_ / "root";
  config.listen = net::Endpoint{"127.0.0.1", 0};
  config.threads = 2;
  config.cache_bytes = 64 << 20;
  CutRun threaded;
  {
    serve::Server server(config);
    server.start();
    auto c = connect(net::Endpoint{"127.0.0.1", server.port()});
    threaded = run_cuts(*c);
  }
  ASSERT_FALSE(threaded.step0.empty());

  auto mpi = start_mpi(3, {"--threads", "2", "--cache-mib", "64"});
  ASSERT_TRUE(mpi);
  EXPECT_EQ(mpi->endpoint()["ranks"], 3);
  CutRun distributed;
  {
    auto c = connect(mpi->address());
    distributed = run_cuts(*c);
    const auto stats = nlohmann::json::parse(c->stats());
    EXPECT_EQ(stats["ranks"], 3) << stats.dump();
    EXPECT_EQ(stats["workers"], 4) << stats.dump();  // 2 worker ranks x 2 threads
    EXPECT_EQ(stats["cache"]["budget"], 2 * (64 << 20)) << stats.dump();
    EXPECT_GT(stats["cache"]["misses"].get<std::uint64_t>(), 0u) << stats.dump();
    EXPECT_EQ(stats["nodes_failed"], 0) << stats.dump();
  }
  expect_same_frames(distributed.step0, threaded.step0, "step 0");
  expect_same_frames(distributed.step1, threaded.step1, "step 1");
  std::cout << "whole cut, cold caches: threaded (2 threads) " << threaded.seconds0
            << " s, MPI 2 worker ranks x 2 threads " << distributed.seconds0 << " s ("
            << threaded.step0.size() << " nodes)\n";
  expect_clean_stop(*mpi);
}

TEST_F(MpiServerTest, OneWorkerRankEqualsThreadedRun) {
  auto mpi = start_mpi(2, {"--threads", "2"});
  ASSERT_TRUE(mpi);
  auto c = connect(mpi->address());
  CutRun run;
  try {
    run = run_cuts(*c);
  } catch (const std::exception& e) {
    // Seen once in CI under load ("server closed the connection"): keep what mpirun said.
    FAIL() << e.what() << "; mpirun log:\n" << mpi->log();
  }
  const auto stats = nlohmann::json::parse(c->stats());
  EXPECT_EQ(stats["ranks"], 2) << stats.dump();
  EXPECT_EQ(stats["workers"], 2) << stats.dump();
  c.reset();

  serve::ServerConfig config;
  config.root = *dir_ / "root";
  config.listen = net::Endpoint{"127.0.0.1", 0};
  config.threads = 2;
  serve::Server server(config);
  server.start();
  auto t = connect(net::Endpoint{"127.0.0.1", server.port()});
  const CutRun threaded = run_cuts(*t);
  expect_same_frames(run.step0, threaded.step0, "step 0");
  expect_same_frames(run.step1, threaded.step1, "step 1");
  std::cout << "whole cut, cold caches: MPI 1 worker rank x 2 threads " << run.seconds0 << " s\n";
  expect_clean_stop(*mpi);
}

TEST_F(MpiServerTest, NoStaleResultAcrossRanksWhenGenerationsChangeRapidly) {
  auto mpi = start_mpi(3, {"--threads", "2"});
  ASSERT_TRUE(mpi);
  auto c = connect(mpi->address());
  c->open_dataset("small");
  const Scene scene = parse_scene(kSceneJson, "test");
  const auto nodes = whole_octree(c->octree());
  const std::uint32_t generation = testing::change_generations_rapidly(*c, scene, nodes, 40);
  const auto frames = collect_frames(*c, nodes.size(), generation);
  EXPECT_EQ(frames.size(), nodes.size());
  EXPECT_EQ(c->stale_results(), 0u);
  const auto stats = nlohmann::json::parse(c->stats());
  EXPECT_GT(stats["nodes_cancelled"].get<std::uint64_t>(), 0u) << stats.dump();
  EXPECT_EQ(stats["queued"].get<std::int64_t>(), 0) << stats.dump();
  EXPECT_EQ(stats["ranks"], 3) << stats.dump();
  c.reset();
  expect_clean_stop(*mpi);
}

TEST_F(MpiServerTest, OneRankRunsThreaded) {
  auto mpi = start_mpi(1, {"--threads", "2"});
  ASSERT_TRUE(mpi);
  EXPECT_FALSE(mpi->endpoint().contains("ranks")) << mpi->endpoint().dump();
  auto c = connect(mpi->address());
  const auto stats = nlohmann::json::parse(c->stats());
  EXPECT_EQ(stats["ranks"], 1) << stats.dump();
  EXPECT_EQ(stats["workers"], 2) << stats.dump();
  c.reset();
  // No pid in the threaded endpoint line: mpirun passes the SIGTERM to its one rank.
  ::kill(mpi->mpirun_pid(), SIGTERM);
  EXPECT_TRUE(mpi->wait_exit(60s)) << mpi->log();
}

TEST_F(MpiServerTest, SigtermToMpirunEndsEveryRank) {
  auto mpi = start_mpi(3, {"--threads", "1"});
  ASSERT_TRUE(mpi);
  {
    auto c = connect(mpi->address());
    c->open_dataset("small");
    const auto started = c->set_scene(parse_scene(kSceneJson, "test"));
    c->update_cut(whole_octree(c->octree()), {}, {});
    (void)started;
  }
  // mpirun passes SIGTERM to every rank and ends the job (its own status is 1 then);
  // rank 0 still stops the workers in order.
  ASSERT_EQ(::kill(mpi->mpirun_pid(), SIGTERM), 0);
  EXPECT_TRUE(mpi->wait_exit(60s)) << mpi->log();
  EXPECT_NE(mpi->log().find("SIGTERM received"), std::string::npos) << mpi->log();
}

}  // namespace
}  // namespace strielad
