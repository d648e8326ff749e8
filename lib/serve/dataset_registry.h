// SPDX-License-Identifier: Apache-2.0
// The stores a server may open: only directories under its root, named by a relative
// path without "." or ".." components, and still under the root once symbolic links
// are resolved. Opened stores are shared by every client.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

namespace strielad {
class Store;
}

namespace strielad::serve {

class DatasetRegistry {
 public:
  // \error kNotFound when the root is not a directory. `direct_reads`: stores read
  // their chunks with O_DIRECT (StoreOpenOptions::direct_reads).
  explicit DatasetRegistry(const std::filesystem::path& root, bool direct_reads = false);

  const std::filesystem::path& root() const { return root_; }

  // \error kInvalidArgument for a name that could leave the root (absolute, "..",
  // empty components, a symbolic link pointing outside); kNotFound when there is no
  // store by that name; the store's own errors (kCorrupt, ...) otherwise, naming the
  // dataset instead of its directory (they go to clients; the log keeps the path).
  std::shared_ptr<const Store> open(std::string_view name);

 private:
  std::filesystem::path root_;  // canonical
  bool direct_reads_ = false;
  std::mutex mutex_;
  std::map<std::filesystem::path, std::shared_ptr<const Store>> open_;
};

}  // namespace strielad::serve
