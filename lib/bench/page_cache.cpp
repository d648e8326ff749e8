// SPDX-License-Identifier: Apache-2.0
#include "bench/page_cache.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>
#include <vector>

#include "core/error.h"

namespace strielad::bench {
namespace {

Error io_error(std::string_view op, const std::filesystem::path& path, int err) {
  return make_error(ErrorCode::kIo, "{}: {} failed: {}", path.string(), op, std::strerror(err));
}

int open_read_only(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw io_error("open", path, errno);
  return fd;
}

}  // namespace

void evict_fd(int fd, const std::filesystem::path& what) {
  // fdatasync is harmless on a read-only descriptor and makes dirty pages evictable.
  ::fdatasync(fd);
  const int rc = ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
  if (rc != 0) throw io_error("posix_fadvise(DONTNEED)", what, rc);
}

void evict_file(const std::filesystem::path& path) {
  const int fd = open_read_only(path);
  try {
    evict_fd(fd, path);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}

Residency page_cache_residency(const std::filesystem::path& path) {
  const int fd = open_read_only(path);
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    throw io_error("stat", path, err);
  }
  Residency r;
  r.file_bytes = static_cast<std::uint64_t>(st.st_size);
  if (r.file_bytes == 0) {
    ::close(fd);
    return r;
  }
  void* map = ::mmap(nullptr, r.file_bytes, PROT_READ, MAP_SHARED, fd, 0);
  const int map_err = errno;
  ::close(fd);
  if (map == MAP_FAILED) throw io_error("mmap", path, map_err);
  const auto page = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  std::vector<unsigned char> vec((r.file_bytes + page - 1) / page);
  const int rc = ::mincore(map, r.file_bytes, vec.data());
  const int mc_err = errno;
  ::munmap(map, r.file_bytes);
  if (rc != 0) throw io_error("mincore", path, mc_err);
  for (unsigned char v : vec) r.resident_bytes += (v & 1u) ? page : 0;
  return r;
}

EvictableFile::EvictableFile(const std::filesystem::path& path)
    : path_(path), fd_(open_read_only(path)) {}

EvictableFile::EvictableFile(EvictableFile&& other) noexcept
    : path_(std::move(other.path_)), fd_(std::exchange(other.fd_, -1)) {}

EvictableFile& EvictableFile::operator=(EvictableFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

EvictableFile::~EvictableFile() {
  if (fd_ >= 0) ::close(fd_);
}

EvictableFolder::EvictableFolder(const std::filesystem::path& folder) {
  for (const auto& e : std::filesystem::recursive_directory_iterator(folder)) {
    if (e.is_regular_file()) files_.emplace_back(e.path());
  }
}

void EvictableFolder::evict() const {
  for (const auto& f : files_) f.evict();
}

}  // namespace strielad::bench
