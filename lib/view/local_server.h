// SPDX-License-Identifier: Apache-2.0
// An in-process strielad-serve for one local store, and a client connected to it: what
// `strielad-view STORE` (and the view tests and benchmark) use, so that one command
// explores a store through exactly the code paths of a remote server. The server
// listens on 127.0.0.1 on a free port and requires a random token, so other local
// users cannot attach to it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

#include "client/server_client.h"
#include "serve/server.h"

namespace strielad::view {

struct LocalServerOptions {
  unsigned threads = 0;                // extraction workers; 0 = one per hardware thread
  std::uint64_t cache_bytes = 1ull << 30;
  bool prefetch = true;
};

struct LocalConnection {
  std::unique_ptr<serve::Server> server;  // destroy after the client
  std::unique_ptr<client::ServerClient> client;  // with the store opened
};

// \error kNotFound when `store` is not a directory with a MANIFEST; otherwise the
// errors of opening the store (formats/store.md) with the path in the message.
LocalConnection open_local_store(const std::filesystem::path& store,
                                 const LocalServerOptions& options = {});

}  // namespace strielad::view
