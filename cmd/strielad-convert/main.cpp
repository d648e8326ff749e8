// SPDX-License-Identifier: Apache-2.0
#include "cli/tool_main.h"
#include "commands.h"

int main(int argc, char** argv) {
  using namespace strielad;
  const cli::ToolSpec spec{
      "strielad-convert",
      "Convert CF-NetCDF or GRIB output into a STRIELAD sparse-brick octree store, and inspect stores",
      [](CLI::App& app, cli::Action& action) {
        convert_cmd::register_convert(app, action);
        convert_cmd::register_info(app, action);
        convert_cmd::register_verify(app, action);
        convert_cmd::register_finalize(app, action);
        convert_cmd::register_export_vdb(app, action);
      }};
  return cli::run_tool(spec, argc, argv);
}
