// SPDX-License-Identifier: Apache-2.0
#include "core/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>

#include "core/error.h"
#include "core/io_error.h"

namespace strielad {
namespace {

void write_all(int fd, std::span<const std::byte> bytes, const std::filesystem::path& path) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw io_error("write", path, errno);
    }
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  // Host, pid and a random part: processes on different nodes of a shared file system,
  // or in different pid namespaces, can have the same pid.
  char host[256] = "host";
  ::gethostname(host, sizeof host - 1);
  host[sizeof host - 1] = '\0';
  for (char* c = host; *c; ++c) {
    if (*c == '/' || *c == '.') *c = '_';
  }
  static thread_local std::mt19937_64 rng{std::random_device{}() ^
                                          (std::uint64_t(::getpid()) << 32)};
  auto tmp = path;
  tmp += fmt::format(".tmp.{}.{}.{:08x}", host, ::getpid(), static_cast<std::uint32_t>(rng()));
  return tmp;
}

void fsync_directory(const std::filesystem::path& dir) {
  int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) throw io_error("open directory", dir, errno);
  ::fsync(fd);  // best effort: some file systems refuse fsync on directories
  ::close(fd);
}

std::vector<std::byte> read_file_bytes(const std::filesystem::path& path) {
  ReadOnlyFile file(path);
  std::vector<std::byte> bytes(file.size());
  file.read_at(0, bytes);
  return bytes;
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::byte> bytes) {
  AtomicOutputFile out(path);
  out.append(bytes);
  out.commit();
}

ReadOnlyFile::ReadOnlyFile(const std::filesystem::path& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw io_error("open", path, errno);
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    int err = errno;
    ::close(fd_);
    fd_ = -1;
    throw io_error("stat", path, err);
  }
  size_ = static_cast<std::uint64_t>(st.st_size);
}

ReadOnlyFile::ReadOnlyFile(ReadOnlyFile&& other) noexcept
    : path_(std::move(other.path_)), fd_(other.fd_), size_(other.size_) {
  other.fd_ = -1;
}

ReadOnlyFile& ReadOnlyFile::operator=(ReadOnlyFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(other.path_);
    fd_ = other.fd_;
    size_ = other.size_;
    other.fd_ = -1;
  }
  return *this;
}

ReadOnlyFile::~ReadOnlyFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ReadOnlyFile::read_at(std::uint64_t offset, std::span<std::byte> out) const {
  if (offset > size_ || out.size() > size_ - offset) {
    throw make_error(ErrorCode::kTruncated,
                     "{}: need {} bytes at offset {} but the file has only {} bytes",
                     path_.string(), out.size(), offset, size_);
  }
  std::size_t done = 0;
  while (done < out.size()) {
    ssize_t n = ::pread(fd_, out.data() + done, out.size() - done,
                        static_cast<off_t>(offset + done));
    if (n < 0) {
      if (errno == EINTR) continue;
      throw io_error("read", path_, errno);
    }
    if (n == 0) {
      throw make_error(ErrorCode::kTruncated, "{}: file ended at offset {} while reading {} bytes",
                       path_.string(), offset + done, out.size());
    }
    done += static_cast<std::size_t>(n);
  }
}

AtomicOutputFile::AtomicOutputFile(std::filesystem::path final_path)
    : final_path_(std::move(final_path)), temp_path_(temporary_sibling(final_path_)) {
  fd_ = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd_ < 0) throw io_error("create", temp_path_, errno);
}

AtomicOutputFile::~AtomicOutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temp_path_, ignored);
  }
}

void AtomicOutputFile::append(std::span<const std::byte> bytes) {
  write_all(fd_, bytes, temp_path_);
  size_ += bytes.size();
}

void AtomicOutputFile::commit() {
  if (::fsync(fd_) != 0) throw io_error("fsync", temp_path_, errno);
  if (::close(fd_) != 0) {
    fd_ = -1;
    throw io_error("close", temp_path_, errno);
  }
  fd_ = -1;
  if (::rename(temp_path_.c_str(), final_path_.c_str()) != 0) {
    throw io_error("rename onto " + final_path_.string(), temp_path_, errno);
  }
  committed_ = true;
  fsync_directory(final_path_.parent_path());
}

}  // namespace strielad
