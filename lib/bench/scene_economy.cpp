// SPDX-License-Identifier: Apache-2.0
#include "bench/scene_economy.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bench/machine_info.h"
#include "view/level_heights.h"
#include "bench/node_batch.h"
#include "bench/sample_input.h"
#include "core/error.h"
#include "lod/camera.h"
#include "lod/lod_cut.h"
#include "lod/world_frame.h"
#include "scene/scene.h"
#include "store/store.h"

namespace strielad::bench {
namespace {

using Seconds = std::chrono::duration<double>;

struct NamedScene {
  std::string name;
  std::string json;
};

std::pair<double, double> axis_range(const Axis& axis) {
  const auto [lo, hi] = std::minmax_element(axis.values.begin(), axis.values.end());
  return {*lo, *hi};
}

// Typical questions: sparse clouds with a shading attribute, two limits on a sparse and
// a dense field, a sparse field inside a region, and a layer of a dense field.
std::vector<NamedScene> typical_scenes(const format::Manifest& m) {
  const auto [x0, x1] = axis_range(m.x);
  const auto [y0, y1] = axis_range(m.y);
  const double dx = (x1 - x0) / 3, dy = (y1 - y0) / 3;
  return {
      {"clouds", R"({"subvolumes":[{"id":1,"limits":[{"var":"clw","min":1e-5}]}],"attributes":["ta"]})"},
      {"rain in warm air",
       R"({"subvolumes":[{"id":1,"limits":[{"var":"qr","min":1e-5},{"var":"ta","min":273.15}]}]})"},
      {"ice in a region",
       fmt::format(R"({{"subvolumes":[{{"id":1,"limits":[{{"var":"cli","min":1e-6}}],)"
                   R"("domain":{{"{}":[{},{}],"{}":[{},{}]}}}}]}})",
                   m.x.name, x0 + dx, x1 - dx, m.y.name, y0 + dy, y1 - dy)},
      {"cold layer", R"({"subvolumes":[{"id":1,"limits":[{"var":"ta","min":250,"max":255}]}]})"},
  };
}

// An overview of the whole domain, a low oblique view over its centre, and a close view
// straight down on a point off the centre.
}  // namespace

std::vector<NamedCamera> typical_cameras(const lod::WorldFrame& frame, double aspect) {
  const lod::WorldBox& d = frame.domain();
  const Vec3 size = sub(d.hi, d.lo);
  const double width = std::max(size[0], size[1]);
  const Vec3 ground{d.lo[0] + 0.5 * size[0], d.lo[1] + 0.5 * size[1], d.lo[2]};
  const double fov = 45;
  const double elevation = 50 * std::acos(-1.0) / 180;
  const double distance = d.radius() / std::sin(0.5 * fov * std::acos(-1.0) / 180);
  const Vec3 overview_eye{ground[0], ground[1] - distance * std::cos(elevation),
                               ground[2] + distance * std::sin(elevation)};
  const double down = 25 * std::acos(-1.0) / 180;
  const Vec3 oblique_eye{ground[0], ground[1] - 0.12 * width,
                              ground[2] + 0.12 * width * std::tan(down)};
  const Vec3 spot{d.lo[0] + 0.3 * size[0], d.lo[1] + 0.6 * size[1], d.lo[2]};
  const Vec3 top_eye{spot[0], spot[1], spot[2] + 0.25 * width};
  return {
      {"overview", lod::look_at(overview_eye, d.center(), fov, aspect, d)},
      {"low oblique", lod::look_at(oblique_eye, ground, fov, aspect, d)},
      {"top-down close", lod::look_at(top_eye, spot, fov, aspect, d)},
  };
}

std::vector<NodeId> cut_nodes(const Store& store, const lod::WorldFrame& frame,
                              const lod::Camera& camera) {
  lod::LodCut cut(store.octree(), lod::node_world_boxes(store.octree(), frame));
  cut.update(camera);
  std::vector<NodeId> nodes;
  for (const auto& p : cut.nodes()) nodes.push_back(p.node);
  return nodes;
}

namespace {

SceneCost extract_nodes(const std::filesystem::path& store_dir, const Scene& scene,
                        const std::vector<NodeId>& nodes) {
  const NodeBatchCost batch = run_node_batch(store_dir, scene, nodes, 1);
  SceneCost cost;
  cost.nodes = batch.nodes;
  cost.extracted = batch.extracted;
  cost.skipped = batch.skipped;
  cost.bricks = batch.bricks;
  cost.bytes_read = batch.bytes_read;
  cost.bytes_sent = batch.bytes_sent;
  cost.variables_read = batch.variables_read;
  cost.seconds = batch.seconds;
  return cost;
}

SceneCost whole_step(const Store& store, std::uint32_t step) {
  SceneCost cost;
  cost.view = "whole step";
  cost.nodes = store.octree().node_count();
  for (std::uint32_t v = 0; v < store.variable_count(); ++v) {
    for (const auto& entry : store.index(step, v)) {
      cost.bricks += entry.kind == format::BrickKind::kData;
    }
  }
  cost.extracted = cost.nodes;
  cost.variables_read = store.variable_count();
  cost.bytes_read = std::filesystem::file_size(store.step_path(step));
  return cost;
}

double ratio(double part, double whole) { return whole > 0 ? part / whole : 0; }

}  // namespace

SceneEconomyOptions quick_scene_economy_options(SceneEconomyOptions o) {
  o.dims = {60, 56, 30};
  o.brick = 8;
  return o;
}

SceneEconomyReport run_scene_economy(const SceneEconomyOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  SceneEconomyReport report;
  report.options = o;
  const auto input = ensure_sample_input({o.dims, 1, o.variables, o.seed}, o.work / "input");
  const auto store_dir = o.work / "store";
  convert_sample_store(input, o.variables, o.brick, o.convert_threads, store_dir);
  const auto store = Store::open(store_dir);
  const lod::WorldFrame frame(
      store->manifest(),
      lod::WorldFrameOptions{}, view::representative_level_heights_m(*store),
      store->horizontal_coordinates());
  report.step_file_bytes = std::filesystem::file_size(store->step_path(0));
  const SceneCost step = whole_step(*store, 0);
  const auto all_leaves = level_nodes(store->octree(), 0);
  for (const NamedScene& named : typical_scenes(store->manifest())) {
    const Scene scene = parse_scene(named.json, named.name);
    report.scene_json.push_back(scene_to_json(scene));
    for (const NamedCamera& camera : typical_cameras(frame, o.aspect)) {
      SceneCost cost = extract_nodes(store_dir, scene, cut_nodes(*store, frame, camera.camera));
      cost.scene = named.name;
      cost.view = camera.name;
      report.costs.push_back(cost);
    }
    SceneCost every = extract_nodes(store_dir, scene, all_leaves);
    every.scene = named.name;
    every.view = "every leaf";
    report.costs.push_back(every);
    SceneCost whole = step;
    whole.scene = named.name;
    report.costs.push_back(whole);
  }
  report.machine = machine_info(o.work);
  report.seconds = Seconds(std::chrono::steady_clock::now() - t0).count();
  return report;
}

std::vector<Table> scene_economy_tables(const SceneEconomyReport& report) {
  Table t;
  t.name = "scene_economy";
  t.title = "What a scene and a view read, decompress, extract and send, against the whole step";
  t.columns = {"scene",      "view",        "nodes",     "extracted", "skipped",
               "bricks",     "MB read",     "MB sent",   "variables", "seconds",
               "bricks % step", "read % step", "sent % every leaf"};
  const SceneCost* step = nullptr;
  const SceneCost* every = nullptr;
  for (const SceneCost& c : report.costs) {
    if (c.view == "whole step") step = &c;
  }
  for (const SceneCost& c : report.costs) {
    every = nullptr;
    for (const SceneCost& e : report.costs) {
      if (e.scene == c.scene && e.view == "every leaf") every = &e;
    }
    const bool is_step = c.view == "whole step";
    t.add({c.scene, c.view, Cell::integer(double(c.nodes)),
           is_step ? Cell("-") : Cell::integer(double(c.extracted)),
           is_step ? Cell("-") : Cell::integer(double(c.skipped)), Cell::integer(double(c.bricks)),
           Cell(c.bytes_read / 1e6, 2), is_step ? Cell("-") : Cell(c.bytes_sent / 1e6, 2),
           Cell::integer(double(c.variables_read)), is_step ? Cell("-") : Cell(c.seconds, 3),
           Cell(100 * ratio(double(c.bricks), step ? double(step->bricks) : 0), 2),
           Cell(100 * ratio(double(c.bytes_read), step ? double(step->bytes_read) : 0), 2),
           is_step || !every ? Cell("-")
                             : Cell(100 * ratio(double(c.bytes_sent), double(every->bytes_sent)), 1)});
  }
  const auto& d = report.options.dims;
  t.notes = {
      fmt::format("one generated time step {}x{}x{}, {} variables ({}), brick {}; step file {:.1f} MB",
                  d.x, d.y, d.z, report.options.variables.size(),
                  fmt::join(report.options.variables, ","), report.options.brick,
                  report.step_file_bytes / 1e6),
      "views: the viewer's LOD cut (lib/lod, default options, 16:9, 45 degrees) for three "
      "cameras; 'every leaf' = the scene at full resolution without a view; 'whole step' = "
      "every brick of every variable and node",
      "bricks = chunks read from disk and decompressed; MB read = compressed chunks + index "
      "bytes the store fetched; MB sent = NodeResult frames; one thread, cold brick cache",
  };
  return {t};
}

nlohmann::json scene_economy_json(const SceneEconomyReport& report,
                                  const std::vector<Table>& tables) {
  nlohmann::json j;
  j["suite"] = "scene";
  j["machine"] = report.machine;
  j["seconds"] = report.seconds;
  j["command"] = report.options.command_line;
  j["dims"] = {report.options.dims.x, report.options.dims.y, report.options.dims.z};
  j["brick"] = report.options.brick;
  j["variables"] = report.options.variables;
  j["step_file_bytes"] = report.step_file_bytes;
  j["scenes"] = report.scene_json;
  for (const auto& c : report.costs) {
    j["costs"].push_back({{"scene", c.scene}, {"view", c.view}, {"nodes", c.nodes},
                          {"extracted", c.extracted}, {"skipped", c.skipped},
                          {"bricks", c.bricks}, {"bytes_read", c.bytes_read},
                          {"bytes_sent", c.bytes_sent}, {"variables_read", c.variables_read},
                          {"seconds", c.seconds}});
  }
  for (const auto& t : tables) j["tables"].push_back(table_json(t));
  return j;
}

}  // namespace strielad::bench
