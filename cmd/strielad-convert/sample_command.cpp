// SPDX-License-Identifier: Apache-2.0
#include "commands.h"

namespace strielad::convert_cmd {
void register_sample(CLI::App& app, cli::Action& action) {
  auto* sub = app.add_subcommand("sample", "Write a deterministic CF-NetCDF-4 sample dataset");
  sub->callback([&action] { action = [] { return 0; }; });
}
}  // namespace strielad::convert_cmd
