// SPDX-License-Identifier: Apache-2.0
// Thin POSIX file helpers that turn errno into strielad::Error naming the path.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace strielad {

// Reads a whole (small) file.
std::vector<std::byte> read_file_bytes(const std::filesystem::path& path);

// Writes bytes to `path` atomically: a temporary sibling is written, fsync'ed and
// renamed over `path`, then the directory is fsync'ed. A crash leaves either the old
// file or the new one, never a mix; the temporary is removed on failure.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::byte> bytes);

// Name of a fresh temporary sibling for writing `path`: "NAME.tmp.HOST.PID.RANDOM", unique
// across processes, hosts and pid namespaces (it is created with O_EXCL).
std::filesystem::path temporary_sibling(const std::filesystem::path& path);

void fsync_directory(const std::filesystem::path& dir);

// An open read-only file descriptor with positioned reads. Movable, not copyable.
class ReadOnlyFile {
 public:
  ReadOnlyFile() = default;
  explicit ReadOnlyFile(const std::filesystem::path& path);
  ReadOnlyFile(ReadOnlyFile&& other) noexcept;
  ReadOnlyFile& operator=(ReadOnlyFile&& other) noexcept;
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;
  ~ReadOnlyFile();

  std::uint64_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }
  int fd() const { return fd_; }

  // Reads exactly out.size() bytes at `offset` with pread; a short read is kTruncated.
  void read_at(std::uint64_t offset, std::span<std::byte> out) const;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// An append-only output file written through a temporary sibling and published with
// commit(). Destroying it without commit() removes the temporary.
class AtomicOutputFile {
 public:
  explicit AtomicOutputFile(std::filesystem::path final_path);
  AtomicOutputFile(const AtomicOutputFile&) = delete;
  AtomicOutputFile& operator=(const AtomicOutputFile&) = delete;
  ~AtomicOutputFile();

  void append(std::span<const std::byte> bytes);
  std::uint64_t size() const { return size_; }
  // fsync, rename onto the final path, fsync the directory.
  void commit();

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temp_path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  bool committed_ = false;
};

}  // namespace strielad
