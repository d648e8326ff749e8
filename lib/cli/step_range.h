// SPDX-License-Identifier: Apache-2.0
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace strielad::cli {

// An inclusive range of time-step indices written "A:B", "A:" (to the end), ":B" or "A".
struct StepRange {
  std::optional<std::uint32_t> first, last;
};

// Throws kInvalidArgument naming `flag` for anything else (or first > last).
StepRange parse_step_range(std::string_view text, std::string_view flag);

}  // namespace strielad::cli
