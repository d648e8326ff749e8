// SPDX-License-Identifier: Apache-2.0
#include "bench/gnuplot_run.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "bench/process_runner.h"

namespace strielad::bench {

std::string run_gnuplot(const std::filesystem::path& script, const std::filesystem::path& png) {
  if (!find_program("gnuplot")) {
    spdlog::warn("bench: gnuplot not found on PATH; wrote {} but no {}", script.string(),
                 png.string());
    return "gnuplot not found: script written, no PNG";
  }
  auto log = png;
  log.replace_extension(".gnuplot.log");
  const auto dir = png.has_parent_path() ? png.parent_path() : std::filesystem::path(".");
  const ProcessResult p = run_process(
      {"sh", "-c", fmt::format("cd '{}' && gnuplot '{}'", dir.string(), script.filename().string())},
      log);
  if (p.exit_status != 0) {
    spdlog::warn("bench: gnuplot failed (exit {}): {}", p.exit_status, p.output_tail);
    return fmt::format("gnuplot failed (exit {})", p.exit_status);
  }
  std::error_code ec;
  std::filesystem::remove(log, ec);
  spdlog::info("bench: wrote {}", png.string());
  return "written";
}

}  // namespace strielad::bench
