// SPDX-License-Identifier: Apache-2.0
// A thread-safe progress bar on stderr, drawn only when stderr is a terminal and at most
// ten times a second; otherwise silent (logs carry the progress instead).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace strielad::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, std::uint64_t total, std::string unit = "");
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  void advance(std::uint64_t n = 1);
  void finish();

 private:
  void draw(bool final);

  std::string label_;
  std::uint64_t total_;
  std::string unit_;
  std::atomic<std::uint64_t> done_{0};
  bool enabled_;
  bool finished_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace strielad::cli
