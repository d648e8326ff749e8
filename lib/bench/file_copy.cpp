// SPDX-License-Identifier: Apache-2.0
#include "bench/file_copy.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "bench/stopwatch.h"
#include "core/direct_read_file.h"
#include "core/error.h"

namespace strielad::bench {
namespace {

Error io_error(std::string_view op, const std::filesystem::path& path, int err) {
  return make_error(ErrorCode::kIo, "{}: {} failed: {}", path.string(), op, std::strerror(err));
}

class Fd {
 public:
  Fd(const std::filesystem::path& path, int flags, mode_t mode = 0)
      : fd_(::open(path.c_str(), flags | O_CLOEXEC, mode)) {
    if (fd_ < 0) throw io_error("open", path, errno);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }

 private:
  int fd_;
};

// Reads up to buf.size() bytes, retrying on EINTR; 0 at the end of the file.
std::size_t read_some(int fd, std::vector<char>& buf, const std::filesystem::path& path) {
  for (;;) {
    const ssize_t n = ::read(fd, buf.data(), buf.size());
    if (n >= 0) return static_cast<std::size_t>(n);
    if (errno != EINTR) throw io_error("read", path, errno);
  }
}

}  // namespace

CopyResult read_files(std::span<const std::filesystem::path> files, std::size_t buffer_bytes) {
  std::vector<char> buf(buffer_bytes);
  CopyResult r;
  const Stopwatch clock;
  for (const auto& path : files) {
    const Fd in(path, O_RDONLY);
    while (const std::size_t n = read_some(in.get(), buf, path)) r.bytes += n;
  }
  r.seconds = clock.seconds();
  return r;
}

std::optional<CopyResult> read_files_direct(std::span<const std::filesystem::path> files,
                                            std::size_t piece_bytes) {
  CopyResult r;
  const Stopwatch clock;
  for (const auto& path : files) {
    const auto file = DirectReadFile::open(path);
    if (!file) return std::nullopt;
    for (std::uint64_t offset = 0; offset < file->size(); offset += piece_bytes) {
      const std::size_t n =
          static_cast<std::size_t>(std::min<std::uint64_t>(piece_bytes, file->size() - offset));
      r.bytes += file->read_view(offset, n).size();
    }
  }
  r.seconds = clock.seconds();
  return r;
}

CopyResult copy_files(std::span<const std::filesystem::path> files,
                      const std::filesystem::path& out_dir, std::size_t buffer_bytes) {
  std::vector<char> buf(buffer_bytes);
  CopyResult r;
  const Stopwatch clock;
  for (const auto& path : files) {
    const auto target = out_dir / path.filename();
    const Fd in(path, O_RDONLY);
    const Fd out(target, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    while (const std::size_t n = read_some(in.get(), buf, path)) {
      std::size_t done = 0;
      while (done < n) {
        const ssize_t w = ::write(out.get(), buf.data() + done, n - done);
        if (w < 0) {
          if (errno == EINTR) continue;
          throw io_error("write", target, errno);
        }
        done += static_cast<std::size_t>(w);
      }
      r.bytes += n;
    }
    if (::fsync(out.get()) != 0) throw io_error("fsync", target, errno);
  }
  r.seconds = clock.seconds();
  return r;
}

void fsync_file(const std::filesystem::path& path) {
  const Fd fd(path, O_RDONLY);
  if (::fsync(fd.get()) != 0) throw io_error("fsync", path, errno);
}

}  // namespace strielad::bench
