// SPDX-License-Identifier: Apache-2.0
// Runs a competitor tool (nccopy, ...) as a real child process and times it from spawn
// to exit. Its stdout and stderr go to a log file so a failure can be quoted.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace strielad::bench {

struct ProcessResult {
  int exit_status = -1;  // exit code, or 128 + signal number
  double seconds = 0;    // wall time, spawn to exit
  double cpu_seconds = 0;  // user + system time of the child
  std::string output_tail;  // last lines of stdout+stderr
};

// The absolute path of `program` found on PATH; empty when absent.
std::optional<std::filesystem::path> find_program(const std::string& program);

// Runs argv[0] (searched on PATH) with the arguments; output goes to `log`.
// Throws kIo when it cannot be started; a non-zero exit is returned, not thrown.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& log);

// "nccopy -k nc4 ..." with arguments quoted where the shell would need it.
std::string shell_command(const std::vector<std::string>& argv);

}  // namespace strielad::bench
