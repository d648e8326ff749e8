// SPDX-License-Identifier: Apache-2.0
// The one error model of the library: every failure is a strielad::Error carrying an
// ErrorCode and a message that names the file, variable, node or field at fault.
// Library code never terminates the process; tools turn errors into exit codes.
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace strielad {

enum class ErrorCode {
  kInvalidArgument,  // the caller asked for something that cannot be (bad flag, bad name)
  kNotFound,         // a file, variable, node or time step does not exist
  kInvalidInput,     // an input file is readable but its content is unusable (NaN, axes)
  kUnsupported,      // a valid input this version cannot handle (unstructured grid)
  kCorrupt,          // stored bytes fail a checksum or a structural check
  kTruncated,        // stored bytes end before a field they must contain
  kVersionTooNew,    // a format version newer than this reader
  kIo,               // the operating system refused a read or write
  kAlreadyExists,    // a store exists but was made from other inputs or options
  kCancelled,        // work was abandoned on request
  kInternal,         // a broken invariant inside the library (a bug)
};

std::string_view error_code_name(ErrorCode code) noexcept;

// Process exit status a tool uses for an error of this code (documented in README).
int exit_status_for(ErrorCode code) noexcept;

// The one exit status that is no ErrorCode's: the work ran to the end, and the checks it
// runs found deviations (strielad-bench robustness, strielad-bench report).
inline constexpr int kExitStatusChecksFailed = 1;

class Error : public std::runtime_error {
 public:
  Error(ErrorCode code, std::string message);

  ErrorCode code() const noexcept { return code_; }

  // A copy whose message is "context: original message".
  [[nodiscard]] Error with_context(std::string_view context) const;

 private:
  ErrorCode code_;
};

template <typename... Args>
[[nodiscard]] Error make_error(ErrorCode code, fmt::format_string<Args...> format,
                               Args&&... args) {
  return Error(code, fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace strielad
