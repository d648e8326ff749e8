// SPDX-License-Identifier: Apache-2.0
// Checking terrain-following columns level by level while they stream past: every value
// finite, and every column strictly monotonic in k in the direction of column (0, 0).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace strielad::ingest {

class ColumnOrderCheck {
 public:
  // Levels of nx * ny values, x fastest. `context` starts every message (the file,
  // source variables and time step the levels come from).
  ColumnOrderCheck(std::size_t nx, std::size_t ny, std::string context);

  // Level k, after level k - 1 (the first call may start at any k).
  // \error kInvalidInput naming the sample (i, j, k): a NaN or infinite value, a column
  // whose value does not change from level k - 1 to k, or one that runs the other way
  // than column (0, 0); kInvalidArgument for a level of the wrong size or out of order.
  void add_level(std::size_t k, std::span<const double> level);

  // +1 (values grow with k), -1 (they fall), 0 (fewer than two levels seen so far).
  int direction() const { return direction_; }

 private:
  std::size_t nx_, ny_;
  std::string context_;
  std::optional<std::size_t> last_k_;
  std::vector<double> previous_;
  int direction_ = 0;
};

}  // namespace strielad::ingest
