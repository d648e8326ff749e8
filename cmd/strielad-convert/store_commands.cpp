// SPDX-License-Identifier: Apache-2.0
// The subcommands that work on an existing store: info, verify and finalize.

#include <functional>
#include <iostream>
#include <memory>

#include <spdlog/spdlog.h>

#include "cli/progress_bar.h"
#include "commands.h"
#include "convert/converter.h"
#include "core/error.h"
#include "store/store_info.h"
#include "store/store_verifier.h"

namespace strielad::convert_cmd {
namespace {

// `strielad-convert NAME STORE [--json]`: `run(store, json)` is the action.
void register_store_command(CLI::App& app, cli::Action& action, const std::string& name,
                            const std::string& help, const std::string& json_help,
                            std::function<int(const std::string& store, bool json)> run) {
  auto* sub = app.add_subcommand(name, help);
  auto store = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("store", *store, "Store directory")->required();
  sub->add_flag("--json", *json, json_help);
  sub->callback([&action, store, json, run = std::move(run)] {
    action = [store, json, run] { return run(*store, *json); };
  });
}

int run_info(const std::string& store, bool json) {
  const auto s = Store::open(store, StoreOpenOptions{.allow_incomplete = true});
  if (json) {
    std::cout << store_info_json(*s).dump(2) << "\n";
  } else {
    describe_store(*s, std::cout);
  }
  return 0;
}

int run_verify(const std::string& store, bool json) {
  std::unique_ptr<cli::ProgressBar> bar;
  const VerifyReport r = verify_store(store, [&](std::uint64_t done, std::uint64_t total) {
    if (!bar) bar = std::make_unique<cli::ProgressBar>("verifying", total, "steps");
    if (done > 0) bar->advance();
  });
  if (bar) bar->finish();
  if (json) {
    std::cout << r.to_json().dump(2) << "\n";
  } else if (r.ok()) {
    std::cout << "OK: " << r.steps_checked << " steps, " << r.bricks_checked << " bricks, "
              << r.chunk_bytes_checked << " chunk bytes checked\n";
  } else {
    for (const auto& p : r.problems) std::cout << "PROBLEM: " << p << "\n";
    std::cout << r.problems.size() << " problems found\n";
  }
  return r.ok() ? 0 : exit_status_for(ErrorCode::kCorrupt);
}

int run_finalize(const std::string& store, bool json) {
  const auto summary = build::finalize_store(store);
  spdlog::info("{} is complete: {:.1f} MB of step files", store,
               summary.value("store_bytes", 0.0) / 1e6);
  if (json) std::cout << summary.dump(2) << "\n";
  return 0;
}

}  // namespace

void register_info(CLI::App& app, cli::Action& action) {
  register_store_command(app, action, "info",
                         "Describe a store: grid, axes, variables, octree, sizes",
                         "Print the manifest and file facts as JSON on stdout", run_info);
}

void register_verify(CLI::App& app, cli::Action& action) {
  register_store_command(app, action, "verify",
                         "Check every checksum and structural rule of a store; list what is wrong",
                         "Print the report as JSON on stdout", run_verify);
}

void register_finalize(CLI::App& app, cli::Action& action) {
  register_store_command(app, action, "finalize",
                         "Check that every time step is converted and mark the store complete",
                         "Print the summary as JSON on stdout", run_finalize);
}

}  // namespace strielad::convert_cmd
