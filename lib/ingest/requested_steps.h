// SPDX-License-Identifier: Apache-2.0
// The merged time steps a conversion keeps (ScanOptions::first_step, last_step), checked
// against the steps the inputs have: the same rule for netCDF and GRIB inputs.
#pragma once

#include <cstddef>
#include <string_view>

#include "core/error.h"
#include "ingest/input_catalog.h"

namespace strielad::ingest {

struct StepRange {
  std::size_t first = 0;
  std::size_t last = 0;
};

// \error kInvalidArgument naming the step asked for and the steps there are.
inline StepRange requested_steps(const ScanOptions& options, std::size_t n) {
  const std::size_t first = options.first_step.value_or(0);
  const std::size_t last = options.last_step.value_or(n - 1);
  auto out_of_range = [&](std::string_view which, std::size_t step) {
    return make_error(ErrorCode::kInvalidArgument,
                      "{} time step {} requested but the inputs have {} time step{} (0..{})",
                      which, step, n, n == 1 ? "" : "s", n - 1);
  };
  if (first >= n) throw out_of_range("first", first);
  if (last >= n) throw out_of_range("last", last);
  if (first > last) {
    throw make_error(ErrorCode::kInvalidArgument, "first time step {} is after last time step {}",
                     first, last);
  }
  return {first, last};
}

}  // namespace strielad::ingest
