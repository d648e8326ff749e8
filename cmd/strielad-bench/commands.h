// SPDX-License-Identifier: Apache-2.0
// The suites of strielad-bench; each registers its subcommand from its own file.
#pragma once

#include <string>

#include "cli/tool_main.h"

namespace strielad::bench_cmd {

// `command_line`: how the tool was invoked, quoted into reports.
void register_io(CLI::App& app, cli::Action& action, std::string command_line);
void register_extract(CLI::App& app, cli::Action& action, std::string command_line);
void register_lossy(CLI::App& app, cli::Action& action, std::string command_line);
void register_latency(CLI::App& app, cli::Action& action, std::string command_line);
void register_view(CLI::App& app, cli::Action& action, std::string command_line);
void register_view_fade(CLI::App& app, cli::Action& action, std::string command_line);
void register_advect(CLI::App& app, cli::Action& action, std::string command_line);
void register_robustness(CLI::App& app, cli::Action& action, std::string command_line);
void register_scene(CLI::App& app, cli::Action& action, std::string command_line);
void register_grib(CLI::App& app, cli::Action& action, std::string command_line);
void register_geometry(CLI::App& app, cli::Action& action, std::string command_line);
void register_scaling(CLI::App& app, cli::Action& action, std::string command_line);
void register_soak(CLI::App& app, cli::Action& action, std::string command_line);
void register_report(CLI::App& app, cli::Action& action, std::string command_line);

}  // namespace strielad::bench_cmd
