// SPDX-License-Identifier: Apache-2.0
#include "cli/tool_main.h"
#include "commands.h"

int main(int argc, char** argv) {
  using namespace strielad;
  const cli::ToolSpec spec{
      "strielad-serve",
      "Serve sub-volume extraction from STRIELAD stores to clients (--root DIR), or extract in batch (extract)",
      [](CLI::App& app, cli::Action& action) {
        serve_cmd::register_serve(app, action);
        serve_cmd::register_extract(app, action);
      }};
  return cli::run_tool(spec, argc, argv);
}
