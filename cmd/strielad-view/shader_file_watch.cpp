// SPDX-License-Identifier: Apache-2.0
#include "shader_file_watch.h"

#include <fstream>
#include <sstream>

namespace strielad::view_cmd {

ShaderFileWatch::ShaderFileWatch(std::filesystem::path path) : path_(std::move(path)) {
  std::error_code ec;
  mtime_ = std::filesystem::last_write_time(path_, ec);
  size_ = std::filesystem::file_size(path_, ec);
}

std::optional<std::string> ShaderFileWatch::poll() {
  const auto now = std::chrono::steady_clock::now();
  if (now < next_check_) return std::nullopt;
  next_check_ = now + std::chrono::milliseconds(250);
  std::error_code ec;
  const auto mtime = std::filesystem::last_write_time(path_, ec);
  if (ec) return std::nullopt;
  const auto size = std::filesystem::file_size(path_, ec);
  if (ec || (mtime == mtime_ && size == size_)) return std::nullopt;
  std::ifstream in(path_, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  mtime_ = mtime;
  size_ = size;
  return text.str();
}

}  // namespace strielad::view_cmd
