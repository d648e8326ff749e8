// SPDX-License-Identifier: Apache-2.0
// Page-cache control for cold-read measurements without root: evicting a file with
// posix_fadvise(POSIX_FADV_DONTNEED) and checking how much of it is still resident
// (mincore on a read-only mapping). Only clean, unmapped pages can be evicted, so
// callers sync() first when the file was just written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace strielad::bench {

// Drops the file's pages from the page cache. Throws kIo naming the file.
void evict_file(const std::filesystem::path& path);
// The same through an open descriptor (cheaper in a measurement loop).
void evict_fd(int fd, const std::filesystem::path& what);

struct Residency {
  std::uint64_t file_bytes = 0;
  std::uint64_t resident_bytes = 0;  // bytes of pages in the page cache (page-rounded)
  double fraction() const {
    return file_bytes ? static_cast<double>(resident_bytes) / static_cast<double>(file_bytes) : 0.0;
  }
};

// How much of the file is in the page cache now. Throws kIo naming the file.
Residency page_cache_residency(const std::filesystem::path& path);

// An open read-only descriptor kept for repeated evictions. Movable, not copyable.
class EvictableFile {
 public:
  explicit EvictableFile(const std::filesystem::path& path);
  EvictableFile(EvictableFile&& other) noexcept;
  EvictableFile& operator=(EvictableFile&& other) noexcept;
  EvictableFile(const EvictableFile&) = delete;
  EvictableFile& operator=(const EvictableFile&) = delete;
  ~EvictableFile();

  void evict() const { evict_fd(fd_, path_); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

// Every regular file under a folder (a store), kept open for repeated evictions before
// cold starts. Throws kIo naming a file that cannot be opened.
class EvictableFolder {
 public:
  explicit EvictableFolder(const std::filesystem::path& folder);
  void evict() const;

 private:
  std::vector<EvictableFile> files_;
};

}  // namespace strielad::bench
