// SPDX-License-Identifier: Apache-2.0
#include <iostream>
#include <memory>

#include "commands.h"
#include "store/store_info.h"

namespace strielad::convert_cmd {

void register_info(CLI::App& app, cli::Action& action) {
  auto* sub = app.add_subcommand("info", "Describe a store: grid, axes, variables, octree, sizes");
  auto store = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("store", *store, "Store directory")->required();
  sub->add_flag("--json", *json, "Print the manifest and file facts as JSON on stdout");
  sub->callback([&action, store, json] {
    action = [store, json] {
      const auto s = Store::open(*store, StoreOpenOptions{.allow_incomplete = true});
      if (*json) {
        std::cout << store_info_json(*s).dump(2) << "\n";
      } else {
        describe_store(*s, std::cout);
      }
      return 0;
    };
  });
}

}  // namespace strielad::convert_cmd
