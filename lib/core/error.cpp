// SPDX-License-Identifier: Apache-2.0
#include "core/error.h"
#include "core/io_error.h"

#include <cerrno>
#include <cstring>

namespace strielad {

std::string_view error_code_name(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::kInvalidArgument: return "invalid argument";
    case ErrorCode::kNotFound: return "not found";
    case ErrorCode::kInvalidInput: return "invalid input";
    case ErrorCode::kUnsupported: return "unsupported";
    case ErrorCode::kCorrupt: return "corrupt";
    case ErrorCode::kTruncated: return "truncated";
    case ErrorCode::kVersionTooNew: return "version too new";
    case ErrorCode::kIo: return "I/O error";
    case ErrorCode::kAlreadyExists: return "already exists";
    case ErrorCode::kCancelled: return "cancelled";
    case ErrorCode::kInternal: return "internal error";
  }
  return "unknown error";
}

int exit_status_for(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::kInvalidArgument: return 2;
    case ErrorCode::kNotFound: return 3;
    case ErrorCode::kInvalidInput: return 4;
    case ErrorCode::kUnsupported: return 5;
    case ErrorCode::kCorrupt:
    case ErrorCode::kTruncated:
    case ErrorCode::kVersionTooNew: return 6;
    case ErrorCode::kIo: return 7;
    case ErrorCode::kAlreadyExists: return 8;
    case ErrorCode::kCancelled: return 9;
    case ErrorCode::kInternal: return 70;
  }
  return 70;  // not an ErrorCode: a bug, as kInternal
}

Error::Error(ErrorCode code, std::string message)
    : std::runtime_error(std::move(message)), code_(code) {}

Error Error::with_context(std::string_view context) const {
  return Error(code_, fmt::format("{}: {}", context, what()));
}

Error io_error(std::string_view action, const std::filesystem::path& path, int err) {
  return make_error(err == ENOENT ? ErrorCode::kNotFound : ErrorCode::kIo, "{}: cannot {}: {}",
                    path.string(), action, std::strerror(err));
}

}  // namespace strielad
