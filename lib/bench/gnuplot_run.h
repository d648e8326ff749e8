// SPDX-License-Identifier: Apache-2.0
// Running a benchmark's gnuplot script (the suites write their plots' data and script
// next to the PNG, so a reader can re-plot them).
#pragma once

#include <filesystem>
#include <string>

namespace strielad::bench {

// Runs `gnuplot script` in the PNG's folder (the script names its files relative to
// it). Returns "written", or what went wrong: no gnuplot on PATH (the script stays for
// later) or its exit status (logged with its output). Never throws for a failed plot.
std::string run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& png);

}  // namespace strielad::bench
