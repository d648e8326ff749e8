// SPDX-License-Identifier: Apache-2.0
#include "view/local_server.h"

#include <fmt/format.h>

#include <random>

#include "core/error.h"

namespace strielad::view {
namespace {

std::string random_token() {
  std::random_device device;
  std::string token;
  for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", device());
  return token;
}

}  // namespace

LocalConnection open_local_store(const std::filesystem::path& store,
                                 const LocalServerOptions& options) {
  std::error_code ec;
  auto path = std::filesystem::weakly_canonical(store, ec);
  if (ec || !std::filesystem::is_directory(path)) {
    throw make_error(ErrorCode::kNotFound, "{}: no such store directory", store.string());
  }
  if (!std::filesystem::exists(path / "MANIFEST")) {
    throw make_error(ErrorCode::kNotFound, "{}: not a STRIELAD store (no MANIFEST)",
                     store.string());
  }
  serve::ServerConfig config;
  config.root = path.parent_path();
  config.listen = net::Endpoint{"127.0.0.1", 0};
  config.token = random_token();
  config.threads = options.threads;
  config.cache_bytes = options.cache_bytes;
  config.prefetch = options.prefetch;
  config.max_clients = 4;
  config.server_name = "strielad-view (in-process)";
  LocalConnection connection;
  connection.server = std::make_unique<serve::Server>(config);
  connection.server->start();
  client::ClientOptions client_options;
  client_options.client_name = "strielad-view";
  client_options.token = *config.token;
  connection.client = client::ServerClient::connect(
      net::Endpoint{"127.0.0.1", connection.server->port()}, client_options);
  try {
    connection.client->open_dataset(path.filename().string());
  } catch (const Error& e) {
    throw e.with_context(store.string());
  }
  return connection;
}

}  // namespace strielad::view
