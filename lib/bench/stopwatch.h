// SPDX-License-Identifier: Apache-2.0
// A monotonic stopwatch for benchmarks.
#pragma once

#include <chrono>

namespace strielad::bench {

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  void restart() { start_ = std::chrono::steady_clock::now(); }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  double microseconds() const { return seconds() * 1e6; }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace strielad::bench
