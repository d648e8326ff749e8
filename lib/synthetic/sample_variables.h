// SPDX-License-Identifier: Apache-2.0
// The variables the sample generator can write, with their CF metadata. Names follow
// the ICON-LEM files of the SciVis 2017 data (clw, cli, qr, ta, pres, ua, va, wa).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace strielad::synthetic {

enum class SampleVariable { kClw, kCli, kQr, kTa, kPres, kUa, kVa, kWa };

struct SampleVariableInfo {
  SampleVariable id;
  std::string_view name;
  std::string_view units;
  std::string_view long_name;
  std::string_view standard_name;  // CF standard name; empty where none exists
  bool sparse;                     // mostly exactly zero (hydrometeors)
};

// All variables in their canonical order.
std::span<const SampleVariableInfo> sample_variable_table() noexcept;
const SampleVariableInfo& sample_variable_info(SampleVariable variable) noexcept;

// Throws kInvalidArgument naming `name` and listing the known names.
SampleVariable sample_variable_from_name(std::string_view name);

// "clw", "cli", "qr", "ta", "pres", "ua", "va", "wa".
std::vector<std::string> all_sample_variable_names();

}  // namespace strielad::synthetic
