// SPDX-License-Identifier: Apache-2.0
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/progress_bar.h"
#include "commands.h"
#include "core/error.h"
#include "export/vtp_writer.h"
#include "extract/level_extraction.h"
#include "extract/output_frame.h"
#include "geo/time_axis_dates.h"
#include "scene/scene.h"
#include "store/store.h"
#include "vdb/level_grid.h"

namespace strielad::serve_cmd {

namespace {

struct ExtractArgs {
  std::string store, scene, output;
  std::optional<std::uint32_t> time;
  std::uint32_t level = 0;
  int threads = 0;
  bool seamless = false;
  bool json = false;
  std::string frame = "axis";
  std::optional<std::string> height_var;
};

// The transform of .vtp positions into --frame (none for the axis frame), heights placed
// by --height-var or the store's choice. \error kInvalidArgument for --height-var in the
// axis frame.
std::optional<FrameTransform> output_transform(const ExtractArgs& args, const Store& store,
                                               OutputFrame frame) {
  const format::Manifest& manifest = store.manifest();
  if (args.height_var && frame == OutputFrame::kAxis) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--height-var {}: the axis frame keeps the vertical axis as it is; give "
                     "--frame lonlat, metric or ecef",
                     *args.height_var);
  }
  std::optional<FrameTransform> transform;
  if (frame != OutputFrame::kAxis) {
    transform.emplace(store, frame, choose_vertical_placement(manifest, args.height_var));
    spdlog::info("frame {}: heights from the {}", output_frame_name(frame),
                 transform->vertical().description);
  }
  return transform;
}

// The scene file at --time, resolved against the store. A height variable or the grid
// geometry's field travels with the meshes as an attribute (the placement reads it).
ResolvedScene scene_to_extract(const ExtractArgs& args, const format::Manifest& manifest,
                               const std::optional<FrameTransform>& transform) {
  Scene scene = load_scene_file(args.scene);
  if (args.time) scene.time = *args.time;
  if (transform) {
    const VerticalPlacement& v = transform->vertical();
    const std::string& placing = v.kind == VerticalPlacement::Kind::kGeometry ? v.attribute : v.variable;
    if (!placing.empty() &&
        std::find(scene.attributes.begin(), scene.attributes.end(), placing) == scene.attributes.end()) {
      scene.attributes.push_back(placing);
    }
  }
  return resolve_scene(scene, manifest, args.scene);
}

// .vdb output: one fog volume per sub-volume, in index space. \error kInvalidArgument
// for any frame but the axis frame.
int write_vdb_output(const ExtractArgs& args, const Store& store, const ResolvedScene& resolved,
                     OutputFrame frame) {
  if (frame != OutputFrame::kAxis) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--frame {}: only .vtp output is transformed; a .vdb grid stays in index "
                     "space with its axes in the grid metadata",
                     args.frame);
  }
  const auto grids = vdb::write_subvolume_vdb(store, resolved, args.level, args.output);
  nlohmann::json j = nlohmann::json::array();
  for (const auto& g : grids) {
    j.push_back({{"subvolume_id", g.subvolume_id}, {"active_voxels", g.active_voxels},
                 {"nodes_skipped", g.nodes_skipped}, {"bricks_read", g.bricks_read}});
    if (!args.json) {
      spdlog::info("sub-volume {}: {} active voxels ({} nodes skipped, {} bricks read)",
                   g.subvolume_id, g.active_voxels, g.nodes_skipped, g.bricks_read);
    }
  }
  if (args.json) {
    const auto time = geo::time_step_json(store.manifest().time, resolved.time);
    std::cout << nlohmann::json{{"output", args.output}, {"time", time}, {"grids", j}}.dump(2)
              << "\n";
  }
  return 0;
}

// Every node of the level, with a progress bar over the nodes.
LevelExtraction extract_with_progress(const Store& store, const ResolvedScene& resolved,
                                      LevelExtractionOptions options) {
  std::unique_ptr<cli::ProgressBar> bar;
  std::mutex bar_mutex;
  options.progress = [&](std::uint64_t done, std::uint64_t total) {
    std::lock_guard lock(bar_mutex);
    if (!bar) bar = std::make_unique<cli::ProgressBar>("extracting", total, "nodes");
    (void)done;
    bar->advance();
  };
  LevelExtraction result = extract_level(store, resolved, options);
  if (bar) bar->finish();
  return result;
}

// The meshes, moved into the output frame, as one .vtp file that names its frame.
VtpSummary write_vtp_output(const ExtractArgs& args, const format::Manifest& manifest,
                            OutputFrame frame, const std::optional<FrameTransform>& transform,
                            LevelExtraction& result) {
  std::vector<NodeMeshRef> meshes;
  for (NodeExtraction& n : result.nodes) {
    for (SubVolumeResult& r : n.results) {
      if (r.outcome != NodeOutcome::kMesh) continue;
      if (transform) transform->apply(r.mesh);
      meshes.push_back({static_cast<std::uint32_t>(n.node), &r.mesh});
    }
  }
  VtpOptions vtp;
  vtp.drop_node_boundary_faces = args.seamless;
  vtp.field_data.emplace_back("frame", std::string(output_frame_name(frame)));
  if (transform) vtp.field_data.emplace_back("vertical_placement", transform->vertical().description);
  if (manifest.grid_mapping) {
    vtp.field_data.emplace_back(
        "grid_mapping", fmt::format("{} ({}): {}", manifest.grid_mapping->variable,
                                    manifest.grid_mapping->name, manifest.grid_mapping->proj));
  }
  return write_vtp(args.output, meshes, vtp);
}

// The --json report: what was extracted, what it cost, and what the file holds.
nlohmann::json extract_report(const ExtractArgs& args, const format::Manifest& manifest,
                              const LevelExtractionOptions& options, OutputFrame frame,
                              const std::optional<FrameTransform>& transform,
                              const LevelExtractionTotals& t, const VtpSummary& written) {
  nlohmann::json j;
  j["store"] = args.store;
  j["scene"] = args.scene;
  j["output"] = args.output;
  j["time_step"] = options.step;
  j["time"] = geo::time_step_json(manifest.time, options.step);
  j["frame"] = std::string(output_frame_name(frame));
  if (transform) j["vertical_placement"] = transform->vertical().description;
  j["level"] = options.level;
  j["nodes"] = t.nodes;
  nlohmann::json outcomes;
  for (std::size_t i = 0; i < t.outcomes.size(); ++i) {
    outcomes[std::string(node_outcome_name(static_cast<NodeOutcome>(i)))] = t.outcomes[i];
  }
  j["node_subvolumes"] = outcomes;
  j["bricks_used"] = t.bricks_used;
  j["bricks_read_from_disk"] = t.chunks_read;
  j["chunk_bytes_read"] = t.chunk_bytes;
  j["cells_extracted"] = t.cells;
  j["cut_cells"] = t.cut_cells;
  j["triangles"] = t.triangles;
  j["vertices"] = t.vertices;
  j["extract_seconds"] = t.seconds;
  j["file_triangles"] = written.triangles;
  j["file_points"] = written.points;
  j["dropped_boundary_triangles"] = written.dropped_triangles;
  j["file_bytes"] = written.bytes;
  return j;
}

int run_extract(const ExtractArgs& args) {
  const auto store = Store::open(args.store);
  const format::Manifest& manifest = store->manifest();
  const OutputFrame frame = parse_output_frame(args.frame);
  const std::optional<FrameTransform> transform = output_transform(args, *store, frame);
  const ResolvedScene resolved = scene_to_extract(args, manifest, transform);
  if (args.output.ends_with(".vdb")) return write_vdb_output(args, *store, resolved, frame);

  LevelExtractionOptions options;
  options.step = resolved.time;
  options.level = args.level;
  options.threads = args.threads;
  options.merge_face_squares = !transform || transform->affine();
  options.axis_normals = !transform || !transform->replaces_normals();
  LevelExtraction result = extract_with_progress(*store, resolved, options);
  const VtpSummary written = write_vtp_output(args, manifest, frame, transform, result);
  const LevelExtractionTotals& t = result.totals;
  if (args.json) {
    std::cout << extract_report(args, manifest, options, frame, transform, t, written).dump(2)
              << "\n";
  } else {
    spdlog::info(
        "extracted level {} of step {}: {} nodes x {} sub-volumes: {} meshes, {} empty, {} "
        "skipped by value range, {} by domain, {} without data; {} bricks ({} from disk, {:.1f} "
        "MB); {} triangles in {:.2f} s",
        options.level, options.step, t.nodes, resolved.subvolumes.size(), t.outcomes[0],
        t.outcomes[1], t.outcomes[2], t.outcomes[3], t.outcomes[4], t.bricks_used, t.chunks_read,
        static_cast<double>(t.chunk_bytes) / 1e6, t.triangles, t.seconds);
    spdlog::info("wrote {} ({} triangles, {} points, {:.1f} MB)", args.output, written.triangles,
                 written.points, static_cast<double>(written.bytes) / 1e6);
  }
  return 0;
}

}  // namespace

void register_extract(CLI::App& app, cli::Action& action) {
  auto* sub = app.add_subcommand(
      "extract", "Extract every node of a level that a scene needs into one .vtp file (ParaView)");
  auto args = std::make_shared<ExtractArgs>();
  sub->add_option("--store", args->store, "Store directory")->required();
  sub->add_option("--scene", args->scene, "Scene JSON (formats/scene.md)")->required();
  sub->add_option("-o,--output", args->output,
                  "Output: .vtp (meshes for ParaView) or .vdb (one fog volume per sub-volume)")
      ->required();
  sub->add_option("--time", args->time, "Time step (overrides the scene's \"time\")");
  sub->add_option("--level", args->level, "Octree level (0 = full resolution)")
      ->capture_default_str();
  sub->add_option("--threads", args->threads, "Worker threads (0 = all cores)")
      ->check(CLI::Range(0, 1024));
  sub->add_flag("--seamless", args->seamless,
                "Leave out the faces on shared node boundaries (one seamless surface)");
  sub->add_flag("--json", args->json, "Print counts and timings as JSON on stdout");
  sub->add_option("--frame", args->frame,
                  "Positions of .vtp output: axis (the grid's axes as stored), lonlat (true "
                  "longitude, latitude, height in m), metric (metres on the plane tangent at "
                  "the domain's centre) or ecef (WGS84 geocentric metres)")
      ->capture_default_str();
  sub->add_option("--height-var", args->height_var,
                  "Variable giving each sample's height or geopotential for --frame lonlat, "
                  "metric or ecef on pressure or model levels (default: zg, gh, z, phi ... "
                  "when the store has one, else the standard atmosphere of a pressure axis)");
  sub->callback([&action, args] {
    action = [args] {
      if (!args->output.ends_with(".vtp") && !args->output.ends_with(".vdb")) {
        throw make_error(ErrorCode::kInvalidArgument,
                         "--output {}: give a .vtp (meshes) or .vdb (fog volumes) file",
                         args->output);
      }
      return run_extract(*args);
    };
  });
}

}  // namespace strielad::serve_cmd
