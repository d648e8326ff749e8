// SPDX-License-Identifier: Apache-2.0
#include "ingest/vertical_columns.h"

#include <cmath>

#include "core/error.h"

namespace strielad::ingest {

ColumnOrderCheck::ColumnOrderCheck(std::size_t nx, std::size_t ny, std::string context)
    : nx_(nx), ny_(ny), context_(std::move(context)) {}

void ColumnOrderCheck::add_level(std::size_t k, std::span<const double> level) {
  if (level.size() != nx_ * ny_) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: level {} holds {} values, not {} x {}",
                     context_, k, level.size(), nx_, ny_);
  }
  if (last_k_ && k != *last_k_ + 1) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: level {} checked after level {}", context_,
                     k, *last_k_);
  }
  for (std::size_t s = 0; s < level.size(); ++s) {
    if (!std::isfinite(level[s])) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: sample (i {}, j {}, k {}) is {} (missing or not finite)", context_,
                       s % nx_, s / nx_, k, level[s]);
    }
  }
  if (last_k_) {
    if (direction_ == 0) {
      if (level[0] == previous_[0]) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: column (i 0, j 0) is not strictly monotonic: level {} and level {} "
                         "are both {}",
                         context_, k - 1, k, level[0]);
      }
      direction_ = level[0] > previous_[0] ? 1 : -1;
    }
    for (std::size_t s = 0; s < level.size(); ++s) {
      const double step = level[s] - previous_[s];
      if (step == 0.0) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: sample (i {}, j {}, k {}): the column is not strictly monotonic "
                         "(level {} is {} as well)",
                         context_, s % nx_, s / nx_, k, k - 1, level[s]);
      }
      if ((step > 0) != (direction_ > 0)) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: sample (i {}, j {}, k {}): the column runs the other way than "
                         "column (i 0, j 0) ({} at level {}, {} at level {}; column (0, 0) {})",
                         context_, s % nx_, s / nx_, k, previous_[s], k - 1, level[s], k,
                         direction_ > 0 ? "rises with k" : "falls with k");
      }
    }
  }
  previous_.assign(level.begin(), level.end());
  last_k_ = k;
}

}  // namespace strielad::ingest
