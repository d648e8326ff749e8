// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench scene` suite ("Scene economy"): what a scene and a view
// cost against the whole time step. For a few typical scenes and camera positions on a
// generated time step, the viewer's own level-of-detail cut (lib/lod) is extracted node
// by node through the server's node task (serve/node_executor.h, the code a server runs),
// and counted: bytes the store fetched from disk (compressed bricks plus index), bricks
// decompressed, nodes extracted and skipped, and bytes of the NodeResult frames a client
// would receive. Two references per scene: the same scene at every leaf (no view: the
// whole step at full resolution, value-range and domain skipping still on), and the
// whole step itself (every variable's bricks of every node: what a tool that reads the
// step has to fetch).
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/table_writer.h"
#include "convert/converter.h"
#include "grid/axis.h"
#include "lod/camera.h"
#include "lod/world_frame.h"
#include "octree/octree_layout.h"

namespace strielad {
class Store;
}

namespace strielad::bench {

struct SceneEconomyOptions {
  Dims3 dims{512, 512, 150};
  std::vector<std::string> variables{"clw", "cli", "qr", "ta", "pres", "ua", "va", "wa"};
  std::uint64_t seed = 1;
  std::filesystem::path work = "/tmp/strielad-bench-scene";
  std::uint32_t brick = build::kDefaultBrick;
  int convert_threads = 0;
  double aspect = 16.0 / 9.0;
  std::string command_line;
};

// The views the suite measures: an overview of the whole domain, a low oblique view over
// its centre, and a close view straight down on a point off the centre.
struct NamedCamera {
  std::string name;
  lod::Camera camera;
};
std::vector<NamedCamera> typical_cameras(const lod::WorldFrame& frame, double aspect);

// The nodes of the viewer's level-of-detail cut (lib/lod, default options) for a camera.
std::vector<NodeId> cut_nodes(const Store& store, const lod::WorldFrame& frame,
                              const lod::Camera& camera);

// A small grid: seconds, for CI (checks the harness).
SceneEconomyOptions quick_scene_economy_options(SceneEconomyOptions base);

// What one (scene, view) pair costs.
struct SceneCost {
  std::string scene;
  std::string view;            // a camera name, "every leaf" or "whole step"
  std::size_t nodes = 0;       // in the cut (or leaves, or every node of the step)
  std::size_t extracted = 0;   // nodes with some sub-volume read and extracted
  std::size_t skipped = 0;     // nodes every sub-volume skipped from the index alone
  std::uint64_t bricks = 0;    // bricks read from disk and decompressed
  std::uint64_t bytes_read = 0;  // compressed bricks and index bytes fetched
  std::uint64_t bytes_sent = 0;  // NodeResult frames (0 for "whole step")
  std::size_t variables_read = 0;  // distinct variables with a brick read
  double seconds = 0;          // one thread, cold cache (the page cache is not dropped)
};

struct SceneEconomyReport {
  std::vector<SceneCost> costs;
  std::vector<std::string> scene_json;  // the scenes, canonical
  std::uint64_t step_file_bytes = 0;
  double seconds = 0;
  nlohmann::json machine;
  SceneEconomyOptions options;
};

// \error what generating, converting or extracting throws.
SceneEconomyReport run_scene_economy(const SceneEconomyOptions& options);

std::vector<Table> scene_economy_tables(const SceneEconomyReport& report);
nlohmann::json scene_economy_json(const SceneEconomyReport& report,
                                  const std::vector<Table>& tables);

}  // namespace strielad::bench
