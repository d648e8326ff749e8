// SPDX-License-Identifier: Apache-2.0
// Each subcommand of strielad-serve registers itself on the CLI11 app; its logic lives
// in lib/ so that it is testable without the tool.
#pragma once

#include "cli/tool_main.h"

namespace strielad::serve_cmd {

void register_extract(CLI::App& app, cli::Action& action);  // extract --store --scene -o OUT
void register_serve(CLI::App& app, cli::Action& action);    // --root DIR: the server

}  // namespace strielad::serve_cmd
