// SPDX-License-Identifier: Apache-2.0
// What one stage of a robustness case found: the problems (each one line naming the
// node, sample or trajectory), a refusal (a clear error the stage reported instead of a
// result), and a one-line summary of what was checked.
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace strielad::robust {

struct StageFindings {
  static constexpr std::size_t kKeptProblems = 8;

  std::vector<std::string> problems;  // the first kKeptProblems
  std::size_t problem_count = 0;
  std::optional<std::string> refusal;  // a clear error instead of a result
  std::string summary;

  template <typename... Args>
  void problem(fmt::format_string<Args...> format, Args&&... args) {
    if (problems.size() < kKeptProblems) {
      problems.push_back(fmt::format(format, std::forward<Args>(args)...));
    }
    ++problem_count;
  }
  bool ok() const { return problem_count == 0; }
};

}  // namespace strielad::robust
