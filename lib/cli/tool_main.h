// SPDX-License-Identifier: Apache-2.0
// The shared entry point of every strielad tool: parses flags with CLI11, configures
// spdlog, runs the chosen command and turns a strielad::Error into one line on stderr
// and the exit status of its ErrorCode (README, "Errors and exit status").
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace strielad::cli {

// What a subcommand leaves behind after parsing: the work to run (returns exit status).
using Action = std::function<int()>;

struct ToolSpec {
  std::string name;         // e.g. "strielad-convert"
  std::string description;  // one line for --help
  // Adds subcommands and flags; sets `action` in the callbacks of what was chosen.
  std::function<void(CLI::App& app, Action& action)> configure;
};

int run_tool(const ToolSpec& spec, int argc, char** argv);

}  // namespace strielad::cli
