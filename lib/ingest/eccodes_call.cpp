// SPDX-License-Identifier: Apache-2.0
#include "ingest/eccodes_call.h"

#include <eccodes.h>

#include <string>

#include "core/error.h"

namespace strielad::ingest {
namespace {

thread_local std::string eccodes_log;

void keep_log(const codes_context*, int /*level*/, const char* message) {
  std::string_view text = message ? message : "";
  while (!text.empty() && (text.back() == ' ' || text.back() == '\n')) text.remove_suffix(1);
  if (text.empty()) return;
  if (!eccodes_log.empty()) eccodes_log += "; ";
  eccodes_log += text;
}

}  // namespace

std::mutex& eccodes_mutex() {
  static std::mutex mutex;
  static std::once_flag hooked;
  std::call_once(hooked, [] {
    std::lock_guard lock(mutex);
    codes_context_set_logging_proc(codes_context_get_default(), keep_log);
  });
  return mutex;
}

std::string take_eccodes_log() {
  std::string log;
  log.swap(eccodes_log);
  return log;
}

void eccodes_check(int status, std::string_view context) {
  if (status == 0) return;
  const std::string log = take_eccodes_log();
  throw make_error(ErrorCode::kInvalidInput, "{}: {}{}{}{}", context,
                   codes_get_error_message(status), log.empty() ? "" : " (", log,
                   log.empty() ? "" : ")");
}

GribHandle& GribHandle::operator=(GribHandle&& other) noexcept {
  if (this != &other) {
    if (handle_) codes_handle_delete(handle_);
    handle_ = other.handle_;
    other.handle_ = nullptr;
  }
  return *this;
}

GribHandle::~GribHandle() {
  if (handle_) codes_handle_delete(handle_);
}

std::string GribHandle::string_key(const char* key) const {
  char buffer[256];
  std::size_t length = sizeof buffer;
  if (codes_get_string(handle_, key, buffer, &length) != 0) return {};
  return std::string(buffer, length > 0 && buffer[length - 1] == '\0' ? length - 1 : length);
}

long GribHandle::long_key(const char* key, long fallback) const {
  long value = 0;
  return codes_get_long(handle_, key, &value) == 0 ? value : fallback;
}

std::optional<double> GribHandle::double_key(const char* key) const {
  int status = 0;
  if (codes_is_missing(handle_, key, &status) == 1 && status == 0) return std::nullopt;
  double value = 0;
  if (codes_get_double(handle_, key, &value) != 0) return std::nullopt;
  return value;
}

std::vector<double> GribHandle::double_array_key(const char* key, std::string_view what) const {
  std::size_t size = 0;
  eccodes_check(codes_get_size(handle_, key, &size), fmt::format("{}: key '{}'", what, key));
  std::vector<double> values(size);
  eccodes_check(codes_get_double_array(handle_, key, values.data(), &size),
                fmt::format("{}: key '{}'", what, key));
  values.resize(size);
  return values;
}

}  // namespace strielad::ingest
