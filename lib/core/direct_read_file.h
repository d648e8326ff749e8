// SPDX-License-Identifier: Apache-2.0
// Positioned reads that bypass the page cache (O_DIRECT). A buffered read of any byte
// range makes the kernel fetch every 4 KiB page it touches; a direct read fetches only
// the device's logical blocks (512 bytes on most disks), so a small chunk costs little
// more than its own bytes from disk. There is no kernel cache behind it: callers keep
// their own (BrickCache). Used by Store when opened with direct reads.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

namespace strielad {

class DirectReadFile {
 public:
  // Opens `path` with O_DIRECT. Returns nullptr when the file system does not support
  // direct I/O (EINVAL, e.g. some tmpfs and FUSE mounts): the caller reads buffered.
  // Other failures (missing file, permissions) throw kNotFound or kIo naming the path.
  static std::unique_ptr<DirectReadFile> open(const std::filesystem::path& path);

  DirectReadFile(const DirectReadFile&) = delete;
  DirectReadFile& operator=(const DirectReadFile&) = delete;
  ~DirectReadFile();

  // Reads exactly out.size() bytes at `offset` through one aligned pread of the blocks
  // they span (into a per-thread aligned buffer, then copied). Returns the bytes
  // requested from the device. A read that ends early is kTruncated.
  std::uint64_t read_at(std::uint64_t offset, std::span<std::byte> out) const;

  // The same read without the copy: the `bytes` bytes at `offset` as they lie in the
  // calling thread's aligned buffer, valid until this thread's next read of any
  // DirectReadFile. For callers that transform the bytes anyway (the converter's input).
  std::span<const std::byte> read_view(std::uint64_t offset, std::size_t bytes) const;

  // Current alignment of offsets and lengths: 512, raised to 4096 once the device
  // refuses a 512-byte-aligned read.
  std::size_t alignment() const { return alignment_.load(std::memory_order_relaxed); }
  std::uint64_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  DirectReadFile(std::filesystem::path path, int fd, std::uint64_t size);
  // One aligned pread of the blocks `bytes` at `offset` span; the bytes in the thread's
  // buffer. `device_bytes` (optional) gets the length requested from the device.
  std::span<const std::byte> read_blocks(std::uint64_t offset, std::size_t bytes,
                                         std::uint64_t* device_bytes) const;

  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  mutable std::atomic<std::size_t> alignment_{512};
};

}  // namespace strielad
