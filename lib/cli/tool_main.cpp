// SPDX-License-Identifier: Apache-2.0
#include "cli/tool_main.h"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <iostream>

#include "core/error.h"
#include "core/version.h"

namespace strielad::cli {

int run_tool(const ToolSpec& spec, int argc, char** argv) {
  CLI::App app{spec.description, spec.name};
  app.set_version_flag("--version", std::string(kToolVersion));
  int verbosity = 0;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbosity, "More log output (repeat for debug detail)");
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors in the log");
  app.fallthrough();  // subcommands inherit this: global flags work after a subcommand too
  Action action;
  spec.configure(app, action);
  app.require_subcommand(0, 1);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    // One line and the documented status for bad flags (README "Errors and exit
    // status"), not CLI11's own exit codes.
    std::cerr << spec.name << ": error: " << e.what() << " (--help lists the flags)\n";
    return exit_status_for(ErrorCode::kInvalidArgument);
  }

  auto logger = spdlog::stderr_color_mt(spec.name);
  logger->set_pattern("%^[%Y-%m-%d %H:%M:%S.%e %l]%$ %v");
  logger->set_level(quiet ? spdlog::level::warn
                          : verbosity >= 2 ? spdlog::level::trace
                          : verbosity == 1 ? spdlog::level::debug
                                           : spdlog::level::info);
  spdlog::set_default_logger(logger);

  if (!action) {  // neither inputs nor a subcommand: the help, and a usage error
    std::cerr << app.help();
    return exit_status_for(ErrorCode::kInvalidArgument);
  }
  try {
    return action();
  } catch (const Error& e) {
    std::cerr << spec.name << ": error: " << e.what() << "\n";
    return exit_status_for(e.code());
  } catch (const std::exception& e) {
    std::cerr << spec.name << ": internal error: " << e.what() << "\n";
    return exit_status_for(ErrorCode::kInternal);
  }
}

}  // namespace strielad::cli
