// SPDX-License-Identifier: Apache-2.0
// ecCodes (GRIB) as Debian builds it is not thread-safe: every call into it goes through
// eccodes_mutex(). Its own messages ("ECCODES ERROR : ...") never reach stderr: they are
// kept per thread and become part of the Error that eccodes_check() throws.
#pragma once

#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

struct grib_handle;

namespace strielad::ingest {

// Also installs the logging hook, once.
std::mutex& eccodes_mutex();

// What ecCodes logged on this thread since the last call, "; "-joined; then forgets it.
std::string take_eccodes_log();

// Throws Error(kInvalidInput) "<context>: <ecCodes message>[ (<its log>)]" when
// status != 0.
void eccodes_check(int status, std::string_view context);

// Owns a codes_handle (a decoded GRIB message). Every call, the destructor included, is
// made with eccodes_mutex() held by the caller.
class GribHandle {
 public:
  GribHandle() = default;
  explicit GribHandle(grib_handle* handle) : handle_(handle) {}
  GribHandle(GribHandle&& other) noexcept : handle_(other.handle_) { other.handle_ = nullptr; }
  GribHandle& operator=(GribHandle&& other) noexcept;
  GribHandle(const GribHandle&) = delete;
  GribHandle& operator=(const GribHandle&) = delete;
  ~GribHandle();

  grib_handle* get() const { return handle_; }
  explicit operator bool() const { return handle_ != nullptr; }

  // A string or integer key; nothing (empty, or `fallback`) when the message has no
  // such key.
  std::string string_key(const char* key) const;
  long long_key(const char* key, long fallback = 0) const;
  // A numeric key; nothing when the message has no such key (or it is "missing").
  std::optional<double> double_key(const char* key) const;
  // A numeric array key ("distinctLatitudes", "latitudes", "values"). \error
  // kInvalidInput naming `what` and the key when the message has none.
  std::vector<double> double_array_key(const char* key, std::string_view what) const;

 private:
  grib_handle* handle_ = nullptr;
};

}  // namespace strielad::ingest
