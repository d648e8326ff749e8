// SPDX-License-Identifier: Apache-2.0
// `strielad-serve --root DIR`: the extraction server (formats/protocol.md).
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "commands.h"
#include "core/error.h"
#include "net/token_file.h"
#include "serve/mpi_executor.h"
#include "serve/mpi_runtime.h"
#include "serve/mpi_worker.h"
#include "serve/server.h"

namespace strielad::serve_cmd {

namespace {

struct ServeArgs {
  std::string root;
  std::string listen = "127.0.0.1:7420";
  std::string token_file;
  unsigned threads = 0;
  double cache_mib = 1024;
  std::size_t max_clients = 64;
  std::size_t max_handshakes = 64;
  double handshake_timeout_s = 10;
  double max_send_queue_mib = 64;
  bool no_prefetch = false;
  bool direct_io = false;
  std::uint32_t max_nodes_per_update = protocol::kMaxNodesPerUpdate;
  bool json = false;
};

// SIGINT and SIGTERM stop the server cleanly: they are blocked in every thread and
// taken by one watcher thread.
class SignalWatcher {
 public:
  explicit SignalWatcher(serve::Server& server) {
    watcher_ = std::thread([this, &server] {
      sigset_t set;
      sigemptyset(&set);
      sigaddset(&set, SIGINT);
      sigaddset(&set, SIGTERM);
      const timespec tick{0, 200'000'000};
      while (!done_) {
        const int sig = sigtimedwait(&set, nullptr, &tick);
        if (sig == SIGINT || sig == SIGTERM) {
          spdlog::info("{} received", sig == SIGINT ? "SIGINT" : "SIGTERM");
          server.stop();
          return;
        }
      }
    });
  }
  ~SignalWatcher() {
    done_ = true;
    watcher_.join();
  }
  static void block_in_this_and_new_threads() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
  }

 private:
  std::atomic<bool> done_{false};
  std::thread watcher_;
};

void print_endpoint(const serve::ServerConfig& config, const serve::Server& server, bool json,
                    const serve::MpiRuntime* mpi) {
  if (json) {
    nlohmann::json j{{"host", config.listen.host}, {"port", server.port()}};
    if (mpi) {  // rank 0's process (signal it to stop every rank cleanly) and node
      j["pid"] = ::getpid();
      j["node"] = mpi->host();
      j["ranks"] = mpi->size();
    }
    std::cout << j.dump() << std::endl;
  } else {
    std::cout << "listening on " << net::Endpoint{config.listen.host, server.port()}.to_string();
    if (mpi) std::cout << " (MPI: " << mpi->size() << " ranks, rank 0 on " << mpi->host() << ")";
    std::cout << std::endl;
  }
}

int run_threaded(const serve::ServerConfig& config, bool json) {
  serve::Server server(config);
  print_endpoint(config, server, json, nullptr);
  SignalWatcher watcher(server);
  server.run();
  return 0;
}

// Under mpirun or srun with several ranks (docs/cluster.md): rank 0
// runs the server, ranks 1..N-1 extract its nodes. The thread that
// starts MPI makes every MPI call.
int run_serve_mpi(serve::ServerConfig config, bool json) {
  serve::MpiRuntime mpi;
  if (mpi.size() == 1) return run_threaded(config, json);
  if (mpi.rank() != 0) {
    return serve::run_mpi_worker(mpi, {config.root, config.threads, config.cache_bytes,
                                       config.direct_reads});
  }
  serve::MpiMaster master(mpi);
  // --threads counts per worker rank; the dispatcher keeps every rank's threads busy.
  config.threads = master.worker_threads();
  serve::Server server(config, master.executor());
  print_endpoint(config, server, json, &mpi);
  SignalWatcher watcher(server);
  master.communicate_while([&] { server.run(); });
  return 0;
}

int run_serve(const ServeArgs& args) {
  serve::ServerConfig config;
  config.root = args.root;
  config.listen = net::parse_endpoint(args.listen, "--listen");
  if (!args.token_file.empty()) config.token = net::read_token_file(args.token_file);
  config.threads = args.threads;
  if (!(args.cache_mib >= 0)) {
    throw make_error(ErrorCode::kInvalidArgument, "--cache-mib must be >= 0, not {}", args.cache_mib);
  }
  config.cache_bytes = static_cast<std::uint64_t>(args.cache_mib * 1024 * 1024);
  config.direct_reads = args.direct_io;
  config.max_clients = args.max_clients;
  config.max_handshakes = args.max_handshakes;
  config.handshake_timeout = std::chrono::milliseconds(
      static_cast<std::int64_t>(std::llround(args.handshake_timeout_s * 1000)));
  config.max_pending_send_bytes = static_cast<std::uint64_t>(args.max_send_queue_mib * 1024 * 1024);
  config.prefetch = !args.no_prefetch;
  config.limits.max_nodes_per_update = args.max_nodes_per_update;
  // Before MPI starts its threads too, so that only the watcher takes the signals.
  SignalWatcher::block_in_this_and_new_threads();
  if (const std::optional<int> ranks = serve::mpi_launch_size(); ranks && *ranks > 1) {
    return run_serve_mpi(std::move(config), args.json);
  }
  return run_threaded(config, args.json);
}

}  // namespace

void register_serve(CLI::App& app, cli::Action& action) {
  auto args = std::make_shared<ServeArgs>();
  app.add_option("--root", args->root,
                 "Serve the stores under this folder (clients open them by relative name); "
                 "without --root and without a subcommand, print help");
  app.add_option("--listen", args->listen,
                 "HOST:PORT to listen on (default 127.0.0.1:7420 — loopback only; port 0 picks "
                 "a free one)");
  app.add_option("--token-file", args->token_file,
                 "File holding a shared secret every client must send (never pass secrets on "
                 "the command line)");
  app.add_option("--threads", args->threads,
                 "Extraction workers (default: one per core); under MPI, per worker rank");
  app.add_option("--cache-mib", args->cache_mib,
                 "Brick cache budget in MiB shared by all clients (default 1024); under MPI, "
                 "per worker rank");
  app.add_option("--max-clients", args->max_clients,
                 "Clients served at once (past the handshake); one more is refused with "
                 "ServerBusy (default 64)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  app.add_option("--max-handshakes", args->max_handshakes,
                 "Connections still in their handshake (before Welcome), counted apart from "
                 "--max-clients; when this many wait, a new connection closes the oldest "
                 "(default 64)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20));
  app.add_option("--handshake-timeout", args->handshake_timeout_s,
                 "Seconds a connection has for its whole handshake, however its bytes "
                 "trickle in (default 10)")
      ->check(CLI::Range(0.001, 3600.0));
  app.add_option("--max-send-queue-mib", args->max_send_queue_mib,
                 "Replies waiting for one client, in MiB; above this its extraction pauses "
                 "and its requests are not read until it reads (default 64)")
      ->check(CLI::Range(0.0625, 65536.0));
  app.add_option("--max-nodes-per-update", args->max_nodes_per_update,
                 "Largest node list one CutUpdate may carry");
  app.add_flag("--direct-io", args->direct_io,
               "Read bricks with O_DIRECT: only the 512-byte disk blocks a brick spans, not "
               "whole 4 KiB pages, and no page cache (the brick cache is the only cache); "
               "stays buffered where the file system has no direct I/O");
  app.add_flag("--no-prefetch", args->no_prefetch,
               "Do not warm the cache with the next time step when idle");
  app.add_flag("--json", args->json, "Print the listening endpoint as one JSON line");
  app.callback([&app, &action, args] {
    if (app.get_subcommands().empty() && !args->root.empty()) {
      action = [args] { return run_serve(*args); };
    }
  });
}

}  // namespace strielad::serve_cmd
