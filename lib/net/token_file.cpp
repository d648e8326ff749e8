// SPDX-License-Identifier: Apache-2.0
#include "net/token_file.h"

#include <spdlog/spdlog.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "core/error.h"
#include "protocol/messages.h"

namespace strielad::net {

std::string read_token_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw make_error(ErrorCode::kNotFound, "{}: cannot read the token file", path);
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && (st.st_mode & (S_IRWXG | S_IRWXO))) {
    spdlog::warn("{}: token file is readable by other users (chmod 600 it)", path);
  }
  std::ostringstream text;
  text << in.rdbuf();
  std::string token = text.str();
  while (!token.empty() && (token.back() == '\n' || token.back() == '\r')) token.pop_back();
  if (token.empty()) throw make_error(ErrorCode::kInvalidInput, "{}: the token file is empty", path);
  if (token.size() > protocol::kMaxTokenBytes) {
    throw make_error(ErrorCode::kInvalidInput, "{}: token longer than {} bytes", path,
                     protocol::kMaxTokenBytes);
  }
  return token;
}

}  // namespace strielad::net
