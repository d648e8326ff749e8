// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_args.h"

#include <charconv>

#include "core/error.h"
#include "synthetic/sample_variables.h"

namespace strielad::synthetic {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

Dims3 parse_dims(std::string_view text) {
  std::size_t values[3] = {0, 0, 0};
  std::string_view rest = trim(text);
  for (int axis = 0; axis < 3; ++axis) {
    std::size_t end = rest.find_first_of("xX");
    if (axis == 2) end = rest.size();
    if (end == std::string_view::npos) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "dims '{}': expected three sizes like 1429x1556x150", text);
    }
    const std::string_view item = rest.substr(0, end);
    const char* first = item.data();
    const char* last = item.data() + item.size();
    auto [ptr, ec] = std::from_chars(first, last, values[axis]);
    if (item.empty() || ec != std::errc() || ptr != last) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "dims '{}': '{}' is not a non-negative integer (expected e.g. 1429x1556x150)",
                       text, item);
    }
    if (values[axis] == 0) {
      throw make_error(ErrorCode::kInvalidArgument, "dims '{}': every size must be at least 1",
                       text);
    }
    rest = axis == 2 ? std::string_view{} : rest.substr(end + 1);
  }
  return Dims3{values[0], values[1], values[2]};
}

std::uint64_t parse_unsigned(std::string_view text, std::string_view what) {
  const std::string_view item = trim(text);
  std::uint64_t value = 0;
  const char* last = item.data() + item.size();
  auto [ptr, ec] = std::from_chars(item.data(), last, value);
  if (item.empty() || ec != std::errc() || ptr != last) {
    throw make_error(ErrorCode::kInvalidArgument, "{} '{}': expected a non-negative integer",
                     what, text);
  }
  return value;
}

std::vector<std::string> parse_variable_list(std::string_view text) {
  std::vector<std::string> names;
  std::string_view rest = text;
  if (trim(rest).empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "variable list is empty");
  }
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = trim(rest.substr(0, comma));
    if (item.empty()) {
      throw make_error(ErrorCode::kInvalidArgument, "variable list '{}' has an empty item", text);
    }
    sample_variable_from_name(item);  // throws on an unknown name
    names.emplace_back(item);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return names;
}

SampleModel parse_sample_model(std::string_view text) {
  const std::string_view name = trim(text);
  for (const SampleModel model : {SampleModel::kSample, SampleModel::kIcon, SampleModel::kIconCf,
                                  SampleModel::kSigmaPressure, SampleModel::kWrf,
                                  SampleModel::kCurvilinear}) {
    if (name == sample_model_name(model)) return model;
  }
  throw make_error(ErrorCode::kInvalidArgument,
                   "--model '{}': expected sample, icon, icon-cf, sigma-pressure, wrf or curvilinear", text);
}

}  // namespace strielad::synthetic
