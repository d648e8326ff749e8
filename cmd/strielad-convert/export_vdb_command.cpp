// SPDX-License-Identifier: Apache-2.0
#include <spdlog/spdlog.h>

#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "format/geometry_field.h"
#include "geo/time_axis_dates.h"
#include "vdb/level_grid.h"

namespace strielad::convert_cmd {
namespace {

struct ExportFlags {
  std::string store, var, out;
  std::uint32_t step = 0, level = 0;
  double background = 0;
  bool json = false;
};

}  // namespace

void register_export_vdb(CLI::App& app, cli::Action& action) {
  auto* sub = app.add_subcommand(
      "export-vdb", "Write one variable, time step and octree level as a standard .vdb file");
  auto f = std::make_shared<ExportFlags>();
  sub->add_option("store", f->store, "Store directory")->required();
  sub->add_option("--var", f->var,
                  "Variable name (geometry_height or geometry_pressure: the grid geometry's "
                  "field of a terrain-following store)")
      ->required();
  sub->add_option("--time", f->step, "Time-step index")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--level", f->level, "Octree level (0 = full resolution)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--background", f->background,
                  "Value left inactive (sparse) in the VDB; fill is always inactive")
      ->capture_default_str();
  sub->add_option("-o,--output", f->out, "Output .vdb file")->required();
  sub->add_flag("--json", f->json, "Print a summary as JSON on stdout");
  sub->callback([&action, f] {
    action = [f] {
      const auto store = Store::open(f->store);
      const auto& m = store->manifest();
      const auto var = f->var == format::geometry_field_name(m) && !f->var.empty()
                           ? *format::geometry_field_variable(m)
                           : static_cast<std::uint32_t>(m.variable_index(f->var));
      const auto s = vdb::write_level_vdb(*store, f->step, var, f->level, f->out,
                                          vdb::LevelGridOptions{f->background});
      spdlog::info("wrote {}: {} active voxels from {} bricks ({} skipped), values {} .. {}",
                   f->out, s.active_voxels, s.bricks_read, s.bricks_skipped, s.min, s.max);
      if (f->json) {
        std::cout << nlohmann::json{{"file", f->out},
                                    {"time", geo::time_step_json(store->manifest().time, f->step)},
                                    {"active_voxels", s.active_voxels},
                                    {"bricks_read", s.bricks_read},
                                    {"bricks_skipped", s.bricks_skipped},
                                    {"min", s.min},
                                    {"max", s.max}}
                         .dump(2)
                  << "\n";
      }
      return 0;
    };
  });
}

}  // namespace strielad::convert_cmd
