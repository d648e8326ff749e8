// SPDX-License-Identifier: Apache-2.0
#include "bench/geometry_bench.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>

#include "bench/conversion_bench.h"
#include "bench/cpu_time.h"
#include "bench/latency_stats.h"
#include "bench/machine_info.h"
#include "bench/stopwatch.h"
#include "convert/converter.h"
#include "core/error.h"
#include "extract/level_extraction.h"
#include "extract/output_frame.h"
#include "format/geometry_field.h"
#include "scene/scene.h"
#include "store/brick_cache.h"
#include "store/store.h"
#include "synthetic/model_like_files.h"
#include "synthetic/sample_dataset.h"

namespace strielad::bench {
namespace {

namespace fs = std::filesystem;

struct Input {
  std::string name;
  synthetic::SampleModel model;
  std::string temperature;  // the dense surface's variable
  std::vector<fs::path> files;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint64_t directory_bytes(const fs::path& dir) {
  std::uint64_t total = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) total += e.file_size();
  }
  return total;
}

// The three samples, reused when the stamp says they were made for the same grid.
std::vector<Input> ensure_inputs(const GeometryBenchOptions& o) {
  std::vector<Input> inputs{{"rectilinear", synthetic::SampleModel::kSample, "ta", {}},
                            {"icon", synthetic::SampleModel::kIcon, "temp", {}},
                            {"sigma-pressure", synthetic::SampleModel::kSigmaPressure, "t", {}},
                            {"curvilinear", synthetic::SampleModel::kCurvilinear, "temp", {}}};
  const fs::path dir = o.work / "input";
  const std::string stamp =
      fmt::format("{}x{}x{} steps {} seed 1\n", o.dims.x, o.dims.y, o.dims.z, o.steps);
  const bool reuse = read_text(dir / "stamp") == stamp;
  if (!reuse) {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  for (Input& in : inputs) {
    synthetic::SampleSpec spec;
    spec.dims = o.dims;
    spec.steps = o.steps;
    spec.file_per_step = false;
    const fs::path out = dir / in.name;
    if (reuse && fs::exists(out)) {
      for (const auto& e : fs::directory_iterator(out)) in.files.push_back(e.path());
      continue;
    }
    const synthetic::SampleResult r =
        in.model == synthetic::SampleModel::kSample
            ? synthetic::write_sample_dataset(spec, out)
            : synthetic::write_model_like_dataset(spec, in.model, out);
    for (const auto& f : r.files) in.files.push_back(f.path);
  }
  write_text_file(dir / "stamp", stamp);
  return inputs;
}

// The geometry's bytes: geometry.bricks and GEOMETRY, and section V of every step file.
std::uint64_t geometry_bytes(const fs::path& store_dir) {
  std::uint64_t bytes = 0;
  for (const char* name : {"geometry.bricks", "GEOMETRY"}) {
    if (fs::exists(store_dir / name)) bytes += fs::file_size(store_dir / name);
  }
  const auto store = Store::open(store_dir);
  const auto& m = store->manifest();
  if (format::has_geometry_field(m) && m.geometry->vertical.varies_in_time) {
    for (std::uint32_t s = 0; s < store->step_count(); ++s) {
      for (const auto& e : store->geometry_index(s)) bytes += e.chunk_size;
    }
  }
  return bytes;
}

struct Extraction {
  double seconds = 0, cpu_seconds = 0;
  std::uint64_t nodes = 0, triangles = 0, bricks = 0;
};

// Level 0 of step 0, one thread: `temperature` <= 260 K; placed: in the lonlat frame,
// the geometry carried and applied.
Extraction extract_once(const Store& store, const std::string& temperature, bool placed,
                        bool merge_face_squares = true, std::uint32_t step = 0,
                        BrickCache* cache = nullptr) {
  const format::Manifest& m = store.manifest();
  Scene scene;
  SubVolume cold;
  cold.id = 1;
  cold.limits.push_back(Limit{temperature, std::nullopt, 260.0});
  scene.subvolumes.push_back(cold);
  std::optional<FrameTransform> transform;
  if (placed) {
    transform.emplace(store, OutputFrame::kLonLat, choose_vertical_placement(m));
    const auto& v = transform->vertical();
    if (v.kind == VerticalPlacement::Kind::kGeometry && !v.attribute.empty()) {
      scene.attributes.push_back(v.attribute);
    }
  }
  const ResolvedScene resolved = resolve_scene(scene, m, "geometry bench scene");
  LevelExtractionOptions options;
  options.threads = 1;
  options.step = step;
  options.cache = cache;
  options.merge_face_squares = transform ? transform->affine() : merge_face_squares;
  options.axis_normals = !transform || !transform->replaces_normals();
  const Stopwatch clock;
  const double cpu0 = process_cpu_seconds();
  LevelExtraction level = extract_level(store, resolved, options);
  if (transform) {
    for (NodeExtraction& n : level.nodes) {
      for (SubVolumeResult& r : n.results) {
        if (r.outcome == NodeOutcome::kMesh) transform->apply(r.mesh);
      }
    }
  }
  const double seconds = clock.seconds();
  return {seconds, process_cpu_seconds() - cpu0, level.totals.nodes, level.totals.triangles,
          level.totals.bricks_used};
}

double ratio(const std::vector<double>& a, const std::vector<double>& b) {
  const double mb = median(b);
  return mb > 0 ? median(a) / mb : 0.0;
}

std::string spread(const std::vector<double>& v, int decimals) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return fmt::format("{:.{}f} ({:.{}f}-{:.{}f})", median(v), decimals, *lo, decimals, *hi,
                     decimals);
}

}  // namespace

GeometryBenchOptions quick_geometry_options(GeometryBenchOptions o) {
  o.dims = {40, 36, 16};
  o.repeat = 1;
  return o;
}

GeometryBenchReport run_geometry_bench(const GeometryBenchOptions& o) {
  const Stopwatch total;
  GeometryBenchReport report;
  report.options = o;
  std::vector<Input> inputs = ensure_inputs(o);
  for (const Input& in : inputs) {
    GeometryInputRuns runs;
    runs.name = in.name;
    for (const auto& f : in.files) runs.input_bytes += fs::file_size(f);
    report.inputs.push_back(std::move(runs));
  }
  for (int round = 0; round < o.repeat; ++round) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const fs::path store = o.work / "stores" / inputs[i].name;
      std::error_code ec;
      fs::remove_all(store, ec);
      evict_inputs(inputs[i].files);
      build::ConvertOptions co;
      co.inputs = inputs[i].files;
      co.store = store;
      co.brick = o.brick;
      co.threads = o.threads;
      const Stopwatch clock;
      build::convert(co);
      report.inputs[i].convert_seconds.push_back(clock.seconds());
    }
  }
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    GeometryInputRuns& runs = report.inputs[i];
    const fs::path store_dir = o.work / "stores" / inputs[i].name;
    const auto store = Store::open(store_dir);
    const auto& m = store->manifest();
    runs.samples = m.dims().count() * m.variables.size() * store->step_count();
    runs.store_bytes = directory_bytes(store_dir);
    runs.geometry_bytes = geometry_bytes(store_dir);
    if (format::has_geometry_field(m)) {
      const auto& v = m.geometry->vertical;
      runs.geometry = fmt::format(
          "{} field from {}, {}", format::vertical_quantity_name(v.quantity),
          v.formula == format::kGeometryFormulaVariable ? fmt::format("{}", fmt::join(v.sources, "+"))
                                                        : v.formula,
          v.varies_in_time ? "per step" : "stored once");
    } else {
      runs.geometry = fmt::format("height axis '{}'", m.z.name);
    }
    if (format::is_curvilinear(m)) {
      runs.geometry = fmt::format("2-D {}/{} (GEOMETRY), {}", m.geometry->horizontal.lon_variable,
                                  m.geometry->horizontal.lat_variable, runs.geometry);
    }
  }
  for (std::size_t i = 0; i < inputs.size(); ++i) {  // warm-up: files in the page cache
    const auto store = Store::open(o.work / "stores" / inputs[i].name);
    extract_once(*store, inputs[i].temperature, false);
    extract_once(*store, inputs[i].temperature, true);
  }
  for (int round = 0; round < o.repeat; ++round) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const auto store = Store::open(o.work / "stores" / inputs[i].name);
      GeometryInputRuns& runs = report.inputs[i];
      // Alternating which goes first, so that neither always follows the other.
      const bool axis_first = round % 2 == 0;
      Extraction axis, unmerged, placed;
      if (axis_first) {
        axis = extract_once(*store, inputs[i].temperature, false);
        unmerged = extract_once(*store, inputs[i].temperature, false, false);
      }
      placed = extract_once(*store, inputs[i].temperature, true);
      if (!axis_first) {
        unmerged = extract_once(*store, inputs[i].temperature, false, false);
        axis = extract_once(*store, inputs[i].temperature, false);
      }
      const auto& g = store->manifest().geometry;
      if (store->step_count() > 1 && format::has_geometry_field(store->manifest()) &&
          !g->vertical.varies_in_time) {
        BrickCache kept(256ull << 20);
        extract_once(*store, inputs[i].temperature, true, true, 1, &kept);  // geometry in
        const Extraction warm = extract_once(*store, inputs[i].temperature, true, true, 0, &kept);
        runs.placed_warm_seconds.push_back(warm.seconds);
        runs.placed_warm_cpu_seconds.push_back(warm.cpu_seconds);
      }
      runs.unmerged_seconds.push_back(unmerged.seconds);
      runs.unmerged_cpu_seconds.push_back(unmerged.cpu_seconds);
      runs.placed_cpu_seconds.push_back(placed.cpu_seconds);
      runs.triangles_unmerged = unmerged.triangles;
      runs.axis_seconds.push_back(axis.seconds);
      runs.placed_seconds.push_back(placed.seconds);
      runs.nodes = axis.nodes;
      runs.triangles_axis = axis.triangles;
      runs.triangles_placed = placed.triangles;
      runs.bricks_axis = axis.bricks;
      runs.bricks_placed = placed.bricks;
    }
  }
  report.seconds = total.seconds();
  return report;
}

std::vector<Table> geometry_tables(const GeometryBenchReport& report) {
  const auto& o = report.options;
  Table conversion;
  conversion.name = "conversion";
  conversion.title = fmt::format(
      "conversion of {}x{}x{}, {} steps ({} rounds, median (min-max))", o.dims.x, o.dims.y,
      o.dims.z, o.steps, o.repeat);
  conversion.columns = {"input", "levels placed by", "seconds", "M samples/s",
                        "store bytes/sample", "geometry MB", "geometry share %"};
  Table extraction;
  extraction.name = "extraction";
  extraction.title = "level 0, temperature <= 260 K, one thread: axis frame against placed (lonlat)";
  extraction.columns = {"input",           "nodes",         "axis s",
                        "axis unmerged s", "placed s",      "placed / axis",
                        "placed / axis unmerged", "placed / axis unmerged CPU",
                        "placed, geometry kept s", "kept / axis unmerged CPU",
                        "bricks axis", "bricks placed",
                        "triangles axis",  "triangles unmerged / placed"};
  for (const auto& r : report.inputs) {
    const double mps = static_cast<double>(r.samples) / 1e6 / median(r.convert_seconds);
    conversion.add({r.name, r.geometry, spread(r.convert_seconds, 2), Cell(mps, 1),
                    Cell(static_cast<double>(r.store_bytes) / static_cast<double>(r.samples), 3),
                    Cell(static_cast<double>(r.geometry_bytes) / 1e6, 2),
                    Cell(100.0 * static_cast<double>(r.geometry_bytes) /
                             static_cast<double>(r.store_bytes),
                         1)});
    extraction.add({r.name, Cell::integer(static_cast<double>(r.nodes)),
                    spread(r.axis_seconds, 3), spread(r.unmerged_seconds, 3),
                    spread(r.placed_seconds, 3), Cell(ratio(r.placed_seconds, r.axis_seconds), 2),
                    Cell(ratio(r.placed_seconds, r.unmerged_seconds), 2),
                    Cell(ratio(r.placed_cpu_seconds, r.unmerged_cpu_seconds), 2),
                    r.placed_warm_seconds.empty() ? Cell("-") : Cell(spread(r.placed_warm_seconds, 3)),
                    r.placed_warm_seconds.empty()
                        ? Cell("-")
                        : Cell(ratio(r.placed_warm_cpu_seconds, r.unmerged_cpu_seconds), 2),
                    Cell::integer(static_cast<double>(r.bricks_axis)),
                    Cell::integer(static_cast<double>(r.bricks_placed)),
                    Cell::integer(static_cast<double>(r.triangles_axis)),
                    fmt::format("{} / {}", r.triangles_unmerged, r.triangles_placed)});
  }
  conversion.notes.push_back(
      "samples: every variable and step (the models write different variables: rectilinear "
      "the sample's, icon and curvilinear temp qc u v w, sigma-pressure t q u v); the "
      "geometry is stored once (icon, curvilinear: its 2-D coordinates) or per step "
      "(sigma-pressure)");
  extraction.notes.push_back(
      "placed: the geometry field read as one more brick per node with triangles, carried as "
      "an attribute and applied with the frame transform (rectilinear: the height axis, no "
      "brick; curvilinear: the height axis and every vertex's longitude and latitude "
      "bilinear between its columns' coordinates); axis: the same scene in the axis frame, node-face squares merged into "
      "rectangles; axis unmerged: without merging, as every frame that bends the lattice "
      "extracts (a merged rectangle would cut through the terrain as a chord). placed / "
      "axis unmerged is the geometry map's own cost (wall and CPU seconds: on a shared "
      "machine CPU time varies less); target <= 1.3 on the terrain-following stores. "
      "placed, geometry kept: the same placed extraction of step 0 with a brick cache kept "
      "from an extraction of step 1, so the time-invariant geometry bricks are in it and "
      "the data bricks are not (a server stepping through time); '-' where the geometry "
      "has no bricks shared by the steps");
  return {conversion, extraction};
}

nlohmann::json geometry_json(const GeometryBenchReport& report, const std::vector<Table>& tables) {
  nlohmann::json j;
  j["suite"] = "geometry";
  j["command"] = report.options.command_line;
  j["machine"] = machine_info(report.options.work);
  j["seconds"] = report.seconds;
  for (const auto& t : tables) j["tables"].push_back(table_json(t));
  return j;
}

}  // namespace strielad::bench
