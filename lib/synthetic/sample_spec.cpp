// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_spec.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace strielad::synthetic {

std::vector<SampleVariable> validate_sample_spec(const SampleSpec& spec) {
  const Dims3& d = spec.dims;
  if (d.x == 0 || d.y == 0 || d.z == 0) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sample dims {}x{}x{}: every dimension must be at least 1", d.x, d.y, d.z);
  }
  // HDF5 chunks (one level each) must stay below 4 GiB.
  constexpr std::size_t kMaxLevelSamples = (std::size_t{1} << 30) - 1;
  if (d.x > kMaxLevelSamples / d.y) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sample dims {}x{}x{}: one level of {}x{} floats is too large for a chunk",
                     d.x, d.y, d.z, d.x, d.y);
  }
  if (spec.steps == 0 || spec.steps > kMaxSampleSteps) {
    throw make_error(ErrorCode::kInvalidArgument, "sample steps {}: must be in 1..{}",
                     spec.steps, kMaxSampleSteps);
  }
  if (!std::isfinite(spec.step_seconds) || spec.step_seconds <= 0) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sample step_seconds {}: must be a positive number of seconds",
                     spec.step_seconds);
  }
  if (spec.format == SampleFormat::kGrib2 && spec.deflate != 0) {
    throw make_error(ErrorCode::kInvalidArgument, "sample deflate level {}: GRIB is not deflated",
                     spec.deflate);
  }
  if (spec.format == SampleFormat::kGrib2 && (spec.grib_bits < 0 || spec.grib_bits > 32)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sample GRIB bits {}: must be in 1..32, or 0 for IEEE float32",
                     spec.grib_bits);
  }
  if (spec.format == SampleFormat::kGrib2 && spec.steps > 1 &&
      std::abs(spec.step_seconds / 60 - std::round(spec.step_seconds / 60)) > 1e-9) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sample step seconds {}: GRIB validity times are in whole minutes",
                     spec.step_seconds);
  }
  if (spec.deflate < 0 || spec.deflate > 9) {
    throw make_error(ErrorCode::kInvalidArgument, "sample deflate level {}: must be in 0..9",
                     spec.deflate);
  }
  if (spec.variables.empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "sample variables: none given");
  }
  std::vector<SampleVariable> resolved;
  for (const auto& name : spec.variables) {
    const SampleVariable v = sample_variable_from_name(name);
    if (std::find(resolved.begin(), resolved.end(), v) != resolved.end()) {
      throw make_error(ErrorCode::kInvalidArgument, "sample variable '{}' is given twice", name);
    }
    resolved.push_back(v);
  }
  return resolved;
}

SampleFormat parse_sample_format(std::string_view text) {
  if (text == "netcdf") return SampleFormat::kNetcdf;
  if (text == "grib2") return SampleFormat::kGrib2;
  throw make_error(ErrorCode::kInvalidArgument, "sample format '{}': expected netcdf or grib2",
                   text);
}

std::vector<std::string> sample_file_names(const SampleSpec& spec) {
  std::vector<std::string> names;
  if (!spec.file_per_step) {
    names.push_back(spec.format == SampleFormat::kGrib2 ? "sample.grib2" : "sample.nc");
    return names;
  }
  for (std::size_t s = 0; s < spec.steps; ++s) names.push_back(fmt::format("sample_t{:03d}.{}", s, spec.format == SampleFormat::kGrib2 ? "grib2" : "nc"));
  return names;
}

}  // namespace strielad::synthetic
