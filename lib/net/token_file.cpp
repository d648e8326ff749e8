// SPDX-License-Identifier: Apache-2.0
#include "net/token_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"
#include "protocol/messages.h"

namespace strielad::net {
namespace {

// Closes the descriptor on every path out.
struct Fd {
  int fd;
  ~Fd() { ::close(fd); }
};

}  // namespace

std::string read_token_file(const std::string& path) {
  const Fd file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) {
    throw make_error(ErrorCode::kNotFound, "{}: cannot read the token file: {}", path,
                     std::strerror(errno));
  }
  // The mode of the file opened, not of whatever the path names a moment later.
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) {
    throw make_error(ErrorCode::kIo, "{}: cannot stat the token file: {}", path,
                     std::strerror(errno));
  }
  if ((st.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the token file has mode {:04o}, so other users may read it; refusing to "
                     "use it (chmod 600 it)",
                     path, static_cast<unsigned>(st.st_mode & 07777));
  }
  // Read up to EOF, but not much more than the longest token with its newline.
  const std::size_t cap = 2 * (protocol::kMaxTokenBytes + 2);
  std::string token;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(file.fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      throw make_error(ErrorCode::kIo, "{}: cannot read the token file: {}", path,
                       std::strerror(errno));
    }
    if (n == 0) break;
    token.append(buffer, static_cast<std::size_t>(n));
    if (token.size() > cap) {
      throw make_error(ErrorCode::kInvalidInput, "{}: token longer than {} bytes", path,
                       protocol::kMaxTokenBytes);
    }
  }
  while (!token.empty() && (token.back() == '\n' || token.back() == '\r')) token.pop_back();
  if (token.empty()) throw make_error(ErrorCode::kInvalidInput, "{}: the token file is empty", path);
  if (token.size() > protocol::kMaxTokenBytes) {
    throw make_error(ErrorCode::kInvalidInput, "{}: token longer than {} bytes", path,
                     protocol::kMaxTokenBytes);
  }
  return token;
}

}  // namespace strielad::net
