// SPDX-License-Identifier: Apache-2.0
#include "bench/server_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>
#include <vector>

#include "core/error.h"
#include "serve/server.h"

extern char** environ;

namespace strielad::bench {

namespace {

std::uint64_t status_kib(pid_t pid, std::string_view key) {
  std::ifstream in(pid > 0 ? fmt::format("/proc/{}/status", pid) : std::string("/proc/self/status"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.starts_with(key)) return std::stoull(line.substr(key.size() + 1));
  }
  return 0;
}

// Reads the child's first stdout line (its {"host","port"} JSON) within `timeout`.
std::string read_first_line(int fd, std::chrono::milliseconds timeout) {
  std::string line;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (line.find('\n') == std::string::npos) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left.count())) <= 0) continue;
    char buffer[256];
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n <= 0) break;
    line.append(buffer, static_cast<std::size_t>(n));
  }
  return line.substr(0, line.find('\n'));
}

}  // namespace

std::filesystem::path find_serve_binary() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const auto dir = self.parent_path();
  for (const auto& candidate : {dir / "strielad-serve", dir / ".." / "strielad-serve" / "strielad-serve"}) {
    if (std::filesystem::is_regular_file(candidate, ec)) return std::filesystem::canonical(candidate);
  }
  return {};
}

BenchServer::BenchServer(const std::filesystem::path& binary, const serve::ServerConfig& config,
                         const std::filesystem::path& log,
                         const std::vector<std::string>& launcher) {
  if (binary.empty() && !launcher.empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "a launcher ({}) needs a server binary",
                     launcher.front());
  }
  if (binary.empty()) {
    serve::ServerConfig c = config;
    c.listen = net::Endpoint{"127.0.0.1", 0};
    server_ = std::make_unique<serve::Server>(c);
    server_->start();
    port_ = server_->port();
    return;
  }
  std::vector<std::string> argv = launcher;
  argv.insert(argv.end(), {binary.string(), "--root", config.root.string(), "--listen",
                                "127.0.0.1:0", "--json", "--threads", std::to_string(config.threads),
                                "--cache-mib", std::to_string(config.cache_bytes >> 20),
                                "--max-clients", std::to_string(config.max_clients), "-q"});
  if (!config.prefetch) argv.push_back("--no-prefetch");
  // Only limits that differ from the defaults, so that an older server binary can be run.
  const serve::ServerConfig defaults;
  if (config.max_handshakes != defaults.max_handshakes) {
    argv.insert(argv.end(), {"--max-handshakes", std::to_string(config.max_handshakes)});
  }
  if (config.handshake_timeout != defaults.handshake_timeout) {
    argv.insert(argv.end(), {"--handshake-timeout",
                             fmt::format("{}", double(config.handshake_timeout.count()) / 1000)});
  }
  if (config.max_pending_send_bytes != defaults.max_pending_send_bytes) {
    argv.insert(argv.end(), {"--max-send-queue-mib",
                             fmt::format("{}", double(config.max_pending_send_bytes) / (1 << 20))});
  }
  std::vector<char*> args;
  for (auto& a : argv) args.push_back(a.data());
  args.push_back(nullptr);
  int out[2];
  if (::pipe2(out, O_CLOEXEC) != 0) throw make_error(ErrorCode::kIo, "pipe failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  const int rc = ::posix_spawn(&pid_, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(out[1]);
  if (rc != 0) {
    ::close(out[0]);
    pid_ = -1;
    throw make_error(ErrorCode::kIo, "cannot start {}: {}", argv.front(), std::strerror(rc));
  }
  const std::string line = read_first_line(out[0], std::chrono::seconds(30));
  ::close(out[0]);
  try {
    port_ = nlohmann::json::parse(line).at("port").get<std::uint16_t>();
  } catch (const std::exception&) {
    stop();
    throw make_error(ErrorCode::kIo, "{} did not report its port (got '{}'); see {}",
                     binary.string(), line, log.string());
  }
}

BenchServer::~BenchServer() { stop(); }

ServerMemory BenchServer::memory() const {
  return ServerMemory{status_kib(pid_, "VmRSS") * 1024, status_kib(pid_, "VmHWM") * 1024};
}

int BenchServer::stop() {
  if (stopped_) return status_;
  stopped_ = true;
  if (server_) {
    server_->stop();
    server_->wait();
    server_.reset();
    return status_ = 0;
  }
  if (pid_ <= 0) return status_ = 0;
  ::kill(pid_, SIGTERM);
  int wstatus = 0;
  for (int i = 0; i < 1000; ++i) {
    if (::waitpid(pid_, &wstatus, WNOHANG) == pid_) {
      return status_ = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128 + WTERMSIG(wstatus);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, &wstatus, 0);
  return status_ = 137;
}

}  // namespace strielad::bench
