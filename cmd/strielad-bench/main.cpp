// SPDX-License-Identifier: Apache-2.0
#include <string>
#include <vector>

#include "bench/process_runner.h"
#include "cli/tool_main.h"
#include "commands.h"

int main(int argc, char** argv) {
  using namespace strielad;
  const std::string command_line = bench::shell_command(std::vector<std::string>(argv, argv + argc));
  const cli::ToolSpec spec{
      "strielad-bench",
      "Benchmark suites for STRIELAD (io, extract, latency, view, advect, robustness, "
      "scene, scaling, soak, grib, geometry) and the report that runs them all",
      [&command_line](CLI::App& app, cli::Action& action) {
        bench_cmd::register_io(app, action, command_line);
        bench_cmd::register_extract(app, action, command_line);
        bench_cmd::register_latency(app, action, command_line);
        bench_cmd::register_lossy(app, action, command_line);
        bench_cmd::register_view(app, action, command_line);
        bench_cmd::register_view_fade(app, action, command_line);
        bench_cmd::register_advect(app, action, command_line);
        bench_cmd::register_robustness(app, action, command_line);
        bench_cmd::register_scene(app, action, command_line);
        bench_cmd::register_scaling(app, action, command_line);
        bench_cmd::register_grib(app, action, command_line);
        bench_cmd::register_geometry(app, action, command_line);
        bench_cmd::register_soak(app, action, command_line);
        bench_cmd::register_report(app, action, command_line);
      }};
  return cli::run_tool(spec, argc, argv);
}
