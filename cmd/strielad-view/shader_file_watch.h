// SPDX-License-Identifier: Apache-2.0
// Notices when the user's shader file changed on disk (polled: a modification time or
// size different from the last one seen), so the viewer recompiles it live.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>

namespace strielad::view_cmd {

class ShaderFileWatch {
 public:
  explicit ShaderFileWatch(std::filesystem::path path);
  // The file's new text when it changed since the last call (checked at most every
  // 250 ms); nothing otherwise, and nothing while it cannot be read (an editor's save
  // in progress), which is retried.
  std::optional<std::string> poll();
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::filesystem::file_time_type mtime_{};
  std::uintmax_t size_ = 0;
  std::chrono::steady_clock::time_point next_check_{};
};

}  // namespace strielad::view_cmd
