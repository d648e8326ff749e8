// SPDX-License-Identifier: Apache-2.0
// A suite's targets (bench/io_suite.h, Target) as a report table and as JSON.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "bench/io_suite.h"
#include "bench/table_writer.h"

namespace strielad::bench {

// Columns target, measured, met ("yes", "NO" or "not measured").
Table targets_table(std::string title, const std::vector<Target>& targets,
                    std::vector<std::string> notes = {});
nlohmann::json targets_json(const std::vector<Target>& targets);

}  // namespace strielad::bench
