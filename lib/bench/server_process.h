// SPDX-License-Identifier: Apache-2.0
// A strielad-serve for the latency benchmark: either a real child process on loopback
// (its memory measured alone, from /proc) or, when no binary is given, a Server inside
// the benchmark process (quick mode and tests).
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "serve/server_config.h"

namespace strielad::serve {
class Server;
}

namespace strielad::bench {

struct ServerMemory {
  std::uint64_t rss_bytes = 0;       // now
  std::uint64_t peak_rss_bytes = 0;  // high-water mark since start
};

class BenchServer {
 public:
  // Starts the server on 127.0.0.1 with an ephemeral port. `binary` empty: in-process.
  // `launcher`, when given, is put before the child's command line (mpirun and its
  // flags: the server then runs on several ranks). Child output goes to `log`.
  // \error kIo when the child cannot start or does not report its port within 30 s;
  // kInvalidArgument for a launcher without a binary; the Server's errors in-process.
  BenchServer(const std::filesystem::path& binary, const serve::ServerConfig& config,
              const std::filesystem::path& log, const std::vector<std::string>& launcher = {});
  ~BenchServer();  // stop()
  BenchServer(const BenchServer&) = delete;
  BenchServer& operator=(const BenchServer&) = delete;

  std::uint16_t port() const { return port_; }
  bool in_process() const { return pid_ <= 0; }
  // The child's memory; for an in-process server, the whole benchmark process's.
  ServerMemory memory() const;
  // SIGTERM and wait (SIGKILL after 10 s). Returns the exit status (0 for in-process).
  int stop();

 private:
  pid_t pid_ = -1;
  std::uint16_t port_ = 0;
  std::unique_ptr<serve::Server> server_;
  bool stopped_ = false;
  int status_ = 0;
};

// The strielad-serve next to the running strielad-bench (build tree or install), or
// empty when there is none.
std::filesystem::path find_serve_binary();

}  // namespace strielad::bench
