// SPDX-License-Identifier: Apache-2.0
// Bytes placed flush against an inaccessible page, so that code the sanitizers do not see
// (a system library such as libfpzip) faults on its first read past them instead of
// reading on silently. Header-only: the fuzz targets use it without the test support lib.
#pragma once

#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstring>
#include <span>
#include <stdexcept>

namespace strielad::testing {

class GuardedBytes {
 public:
  // Room for up to `capacity` bytes, followed by a PROT_NONE page.
  explicit GuardedBytes(std::size_t capacity) {
    const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    usable_ = (capacity + page - 1) / page * page;
    if (usable_ == 0) usable_ = page;
    mapped_ = usable_ + page;
    void* p = mmap(nullptr, mapped_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::runtime_error("GuardedBytes: mmap failed");
    base_ = static_cast<std::byte*>(p);
    if (mprotect(base_ + usable_, page, PROT_NONE) != 0) {
      munmap(base_, mapped_);
      throw std::runtime_error("GuardedBytes: mprotect failed");
    }
  }
  GuardedBytes(const GuardedBytes&) = delete;
  GuardedBytes& operator=(const GuardedBytes&) = delete;
  ~GuardedBytes() { munmap(base_, mapped_); }

  std::size_t capacity() const { return usable_; }

  // A copy of `bytes` (at most capacity()) whose last byte is the last readable one.
  std::span<const std::byte> place(std::span<const std::byte> bytes) {
    if (bytes.size() > usable_) throw std::length_error("GuardedBytes: too many bytes");
    std::byte* start = base_ + usable_ - bytes.size();
    if (!bytes.empty()) std::memcpy(start, bytes.data(), bytes.size());
    return {start, bytes.size()};
  }

 private:
  std::byte* base_ = nullptr;
  std::size_t usable_ = 0;
  std::size_t mapped_ = 0;
};

}  // namespace strielad::testing
