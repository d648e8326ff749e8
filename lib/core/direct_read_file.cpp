// SPDX-License-Identifier: Apache-2.0
#include "core/direct_read_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "core/io_error.h"

namespace strielad {
namespace {

// Buffer alignment that every device's direct I/O accepts.
constexpr std::size_t kMemoryAlignment = 4096;

struct AlignedFree {
  void operator()(std::byte* p) const { std::free(p); }
};

// A per-thread buffer of at least `bytes`, aligned for direct I/O; grows, never shrinks.
std::byte* aligned_buffer(std::size_t bytes) {
  static thread_local std::unique_ptr<std::byte, AlignedFree> buffer;
  static thread_local std::size_t capacity = 0;
  if (capacity < bytes) {
    void* p = nullptr;
    if (::posix_memalign(&p, kMemoryAlignment, bytes) != 0) throw std::bad_alloc();
    buffer.reset(static_cast<std::byte*>(p));
    capacity = bytes;
  }
  return buffer.get();
}

}  // namespace

std::unique_ptr<DirectReadFile> DirectReadFile::open(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_DIRECT);
  if (fd < 0) {
    if (errno == EINVAL) return nullptr;
    throw io_error("open for direct reads", path, errno);
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    throw io_error("stat", path, err);
  }
  return std::unique_ptr<DirectReadFile>(
      new DirectReadFile(path, fd, static_cast<std::uint64_t>(st.st_size)));
}

DirectReadFile::DirectReadFile(std::filesystem::path path, int fd, std::uint64_t size)
    : path_(std::move(path)), fd_(fd), size_(size) {}

DirectReadFile::~DirectReadFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::uint64_t DirectReadFile::read_at(std::uint64_t offset, std::span<std::byte> out) const {
  std::uint64_t device_bytes = 0;
  const std::span<const std::byte> view = read_blocks(offset, out.size(), &device_bytes);
  if (!view.empty()) std::memcpy(out.data(), view.data(), view.size());
  return device_bytes;
}

std::span<const std::byte> DirectReadFile::read_view(std::uint64_t offset, std::size_t bytes) const {
  return read_blocks(offset, bytes, nullptr);
}

std::span<const std::byte> DirectReadFile::read_blocks(std::uint64_t offset, std::size_t bytes,
                                                       std::uint64_t* device_bytes) const {
  if (offset > size_ || bytes > size_ - offset) {
    throw make_error(ErrorCode::kTruncated,
                     "{}: need {} bytes at offset {} but the file has only {} bytes",
                     path_.string(), bytes, offset, size_);
  }
  if (device_bytes) *device_bytes = 0;
  if (bytes == 0) return {};
  for (;;) {
    const std::uint64_t align = alignment();
    const std::uint64_t begin = offset / align * align;
    const std::uint64_t end = (offset + bytes + align - 1) / align * align;
    const std::size_t length = static_cast<std::size_t>(end - begin);
    std::byte* buffer = aligned_buffer(length);
    std::size_t done = 0;
    bool retry_aligned = false;
    // The last block may lie past the end of the file: the read then stops short at the
    // end, which is fine once it covers the requested bytes.
    while (begin + done < offset + bytes) {
      const ssize_t n = ::pread(fd_, buffer + done, length - done, static_cast<off_t>(begin + done));
      if (n < 0) {
        if (errno == EINTR) continue;
        if (errno == EINVAL && align < kMemoryAlignment) {
          retry_aligned = true;
          break;
        }
        throw io_error("read (direct)", path_, errno);
      }
      if (n == 0) {
        throw make_error(ErrorCode::kTruncated,
                         "{}: file ended at offset {} while reading {} bytes at offset {}",
                         path_.string(), begin + done, bytes, offset);
      }
      done += static_cast<std::size_t>(n);
    }
    if (retry_aligned) {
      alignment_.store(kMemoryAlignment, std::memory_order_relaxed);
      continue;
    }
    if (device_bytes) *device_bytes = length;
    return {buffer + (offset - begin), bytes};
  }
}

}  // namespace strielad
