// SPDX-License-Identifier: Apache-2.0
// Each subcommand of strielad-convert registers itself on the CLI11 app; its logic lives
// in lib/ so that it is testable without the tool.
#pragma once

#include "cli/tool_main.h"

namespace strielad::convert_cmd {

void register_convert(CLI::App& app, cli::Action& action);     // INPUT... -o STORE
void register_info(CLI::App& app, cli::Action& action);        // info STORE [--json]
void register_verify(CLI::App& app, cli::Action& action);      // verify STORE
void register_finalize(CLI::App& app, cli::Action& action);    // finalize STORE
void register_export_vdb(CLI::App& app, cli::Action& action);  // export-vdb STORE ...

}  // namespace strielad::convert_cmd
