// SPDX-License-Identifier: Apache-2.0
#include "serve/dataset_registry.h"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/error.h"
#include "protocol/messages.h"
#include "serve/client_error_text.h"
#include "store/store.h"

namespace strielad::serve {

namespace fs = std::filesystem;

DatasetRegistry::DatasetRegistry(const fs::path& root, bool direct_reads)
    : direct_reads_(direct_reads) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) {
    throw make_error(ErrorCode::kNotFound, "{}: dataset root is not a directory", root.string());
  }
  root_ = fs::canonical(root);
}

namespace {

void check_name(std::string_view name) {
  if (name.empty()) throw make_error(ErrorCode::kInvalidArgument, "dataset name is empty");
  if (name.size() > protocol::kMaxNameBytes) {
    throw make_error(ErrorCode::kInvalidArgument, "dataset name is longer than {} bytes",
                     protocol::kMaxNameBytes);
  }
  if (name.front() == '/') {
    throw make_error(ErrorCode::kInvalidArgument,
                     "dataset '{}': absolute names are not allowed (names are relative to the "
                     "server's root)", name);
  }
  if (name.find('\0') != std::string_view::npos || name.find('\\') != std::string_view::npos) {
    throw make_error(ErrorCode::kInvalidArgument, "dataset '{}': contains NUL or backslash", name);
  }
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    const std::string_view part = name.substr(start, end - start);
    if (part.empty() || part == "." || part == "..") {
      throw make_error(ErrorCode::kInvalidArgument,
                       "dataset '{}': empty, '.' and '..' path components are not allowed", name);
    }
    start = end + 1;
  }
}

bool is_under(const fs::path& path, const fs::path& root) {
  const auto [r, p] = std::mismatch(root.begin(), root.end(), path.begin(), path.end());
  return r == root.end();
}

}  // namespace

std::shared_ptr<const Store> DatasetRegistry::open(std::string_view name) {
  check_name(name);
  const fs::path candidate = root_ / fs::path(std::string(name));
  std::error_code ec;
  const fs::path resolved = fs::canonical(candidate, ec);
  if (ec) {
    throw make_error(ErrorCode::kNotFound, "dataset '{}': no such store under the server's root",
                     name);
  }
  if (!is_under(resolved, root_)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "dataset '{}': resolves outside the server's root (symbolic link)", name);
  }
  std::lock_guard lock(mutex_);
  if (const auto it = open_.find(resolved); it != open_.end()) return it->second;
  std::shared_ptr<const Store> store;
  try {
    store = Store::open(resolved, StoreOpenOptions{.direct_reads = direct_reads_});
  } catch (const Error& e) {
    // The store's errors name its files; clients learn the dataset's name, the log the path.
    spdlog::warn("dataset '{}': {}", name, e.what());
    throw Error(e.code(), fmt::format("dataset '{}': {}", name,
                                      name_dataset_not_path(e.what(), resolved, name)));
  }
  open_.emplace(resolved, store);
  return store;
}

}  // namespace strielad::serve
