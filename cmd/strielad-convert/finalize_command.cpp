// SPDX-License-Identifier: Apache-2.0
#include <spdlog/spdlog.h>

#include <iostream>
#include <memory>

#include "convert/converter.h"
#include "commands.h"

namespace strielad::convert_cmd {

void register_finalize(CLI::App& app, cli::Action& action) {
  auto* sub = app.add_subcommand(
      "finalize", "Check that every time step is converted and mark the store complete");
  auto store = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("store", *store, "Store directory")->required();
  sub->add_flag("--json", *json, "Print the summary as JSON on stdout");
  sub->callback([&action, store, json] {
    action = [store, json] {
      const auto summary = build::finalize_store(*store);
      spdlog::info("{} is complete: {:.1f} MB of step files", *store,
                   summary.value("store_bytes", 0.0) / 1e6);
      if (*json) std::cout << summary.dump(2) << "\n";
      return 0;
    };
  });
}

}  // namespace strielad::convert_cmd
