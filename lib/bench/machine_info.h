// SPDX-License-Identifier: Apache-2.0
// What a benchmark ran on: CPU, cores, memory, kernel, the storage under the work
// directory, compiler and library versions, load average. Best effort: fields that
// cannot be read are "unknown".
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>

namespace strielad::bench {

nlohmann::json machine_info(const std::filesystem::path& work_dir);

// The 1-minute load average, or -1 when unavailable.
double load_average_1min();

}  // namespace strielad::bench
