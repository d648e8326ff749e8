// SPDX-License-Identifier: Apache-2.0
// The view suite (declared in view_bench.h): the cut update on the paper's octree, then
// a generated store served in-process, each view rendered complete with the LOD cut and
// with every visible leaf, and time-step changes (the report: view_bench_report.cpp).
#include "bench/view_bench.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>

#include "bench/latency_stats.h"
#include "bench/machine_info.h"
#include "bench/stopwatch.h"
#include "bench/targets.h"
#include "core/error.h"
#include "lod/camera_path.h"
#include "lod/lod_cut.h"
#include "lod/world_frame.h"
#include "octree/octree_layout.h"
#include "render/complete_frame.h"
#include "render/headless_context.h"
#include "render/offscreen_target.h"
#include "synthetic/sample_grid.h"
#include "serve/server.h"
#include "view/default_scene.h"
#include "view/local_server.h"
#include "view/orbit_camera.h"
#include "view/view_controller.h"
#include "view/view_link.h"

namespace strielad::bench {

namespace {

using SteadyClock = std::chrono::steady_clock;

constexpr const char* kStoreName = "store";
// How long a view may take to complete (extraction of every leaf on few cores).
constexpr std::chrono::seconds kCompleteTimeout{600};

double ms_since(SteadyClock::time_point start) {
  return std::chrono::duration<double, std::milli>(SteadyClock::now() - start).count();
}

// ---------------------------------------------------------------------------------
// 1. The cut update on the paper's octree.

// Axes of the sample atmosphere (lib/synthetic/sample_grid.h) on `grid`: the octree and
// world frame of a store of that size, without its data.
format::Manifest octree_only_manifest(Dims3 grid, std::uint32_t brick) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "",
             synthetic::uniform_axis(grid.x, synthetic::kLonMin, synthetic::kLonMax)};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "",
             synthetic::uniform_axis(grid.y, synthetic::kLatMin, synthetic::kLatMax)};
  m.z = Axis{"height", AxisKind::kHeight, "m", "height", "", "up",
             synthetic::stretched_heights(grid.z)};
  m.time = TimeAxis{"time", "hours since 2013-04-26 00:00:00", "standard", {0}};
  m.brick = brick;
  return m;
}

std::size_t segment_of(const lod::CameraPath& path, double t) {
  std::size_t k = 0;
  while (k + 2 < path.keyframes.size() && path.keyframes[k + 1].t <= t) ++k;
  return k;
}

CutUpdateBench run_cut_updates(const ViewSuiteOptions& o) {
  const format::Manifest manifest = octree_only_manifest(o.cut_grid, o.cut_brick);
  const OctreeLayout layout(manifest.dims(), manifest.brick);
  const lod::WorldFrame frame(manifest);
  const std::vector<lod::WorldBox> boxes = lod::node_world_boxes(layout, frame);
  const lod::CameraPath path = lod::default_fly_in_path(frame, o.fly_seconds);
  const lod::WorldCameraPath world(path, frame, "default fly-in");
  const double aspect = double(o.width) / double(o.height);

  std::vector<lod::Camera> cameras;
  std::vector<std::size_t> segment;
  const auto count = static_cast<std::size_t>(std::floor(o.fly_seconds * o.fps + 1e-9)) + 1;
  for (std::size_t i = 0; i < count; ++i) {
    const double t = world.start_time() + double(i) / o.fps;
    cameras.push_back(lod::pose_camera(world.sample(t), aspect, frame.domain()));
    segment.push_back(segment_of(path, t));
  }

  CutUpdateBench b;
  b.grid = manifest.dims();
  b.brick = manifest.brick;
  b.octree_nodes = layout.node_count();
  b.updates_per_pass = count;
  b.passes = o.repeat;
  b.min_nodes = SIZE_MAX;
  const std::size_t segments = path.keyframes.size() - 1;
  std::vector<std::vector<double>> segment_us(segments);
  std::vector<CutUpdateSegment> seg(segments);
  for (std::size_t k = 0; k < segments; ++k) {
    seg[k].from_s = path.keyframes[k].t;
    seg[k].to_s = path.keyframes[k + 1].t;
    seg[k].min_nodes = SIZE_MAX;
  }
  std::vector<double> all_us;
  for (int pass = 0; pass < o.repeat; ++pass) {
    lod::LodCut cut(layout, boxes);
    std::vector<double> pass_us;
    for (std::size_t i = 0; i < count; ++i) {
      const auto t0 = SteadyClock::now();
      const lod::CutDiff diff = cut.update(cameras[i]);
      const double us = std::chrono::duration<double, std::micro>(SteadyClock::now() - t0).count();
      const std::size_t nodes = cut.nodes().size();
      pass_us.push_back(us);
      CutUpdateSegment& s = seg[segment[i]];
      segment_us[segment[i]].push_back(us);
      ++s.updates;
      s.min_nodes = std::min(s.min_nodes, nodes);
      s.max_nodes = std::max(s.max_nodes, nodes);
      s.mean_changes += double(diff.added.size() + diff.removed.size() + diff.reprioritized.size());
      b.min_nodes = std::min(b.min_nodes, nodes);
      b.max_nodes = std::max(b.max_nodes, nodes);
      b.capped_updates += cut.stats().capped ? 1 : 0;
    }
    b.final_nodes = cut.nodes().size();
    b.pass_median_us.push_back(median(pass_us));
    all_us.insert(all_us.end(), pass_us.begin(), pass_us.end());
  }
  for (std::size_t k = 0; k < segments; ++k) {
    if (seg[k].updates == 0) continue;
    seg[k].mean_changes /= double(seg[k].updates);
    seg[k].micros = spread_of(std::move(segment_us[k]));
    b.segments.push_back(seg[k]);
  }
  b.micros = spread_of(std::move(all_us));
  return b;
}

// ---------------------------------------------------------------------------------
// 2-4. Renders of a generated store.

struct StoreView {
  std::string name;
  lod::Camera camera;
};

lod::LodOptions every_leaf_options(const OctreeLayout& octree) {
  // Every visible node above level 0 covers more than 0 sr and is split; no cap short of
  // the whole octree refuses a split: the cut is every visible leaf (lod/lod_cut.h).
  lod::LodOptions options;
  options.split_solid_angle_sr = 0;
  options.max_nodes = octree.node_count();
  return options;
}

// Waits until the server has nothing queued or running and its prefetching stopped
// making progress, so that the timed renders have the cores to themselves.
void wait_server_idle(const serve::Server& server, double limit_s) {
  const serve::ServerCounters& c = server.counters();
  const Stopwatch clock;
  std::uint64_t last = ~0ull;
  int stable = 0;
  while (clock.seconds() < limit_s) {
    const bool idle = c.queued.load() == 0 && c.running.load() == 0;
    const std::uint64_t prefetched = c.prefetch_nodes.load();
    stable = idle && prefetched == last ? stable + 1 : 0;
    if (stable >= 4) return;
    last = prefetched;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

class StoreBench {
 public:
  StoreBench(const ViewSuiteOptions& o, const std::filesystem::path& store)
      : o_(o),
        connection_(view::open_local_store(
            store, view::LocalServerOptions{o.threads, o.cache_mib << 20, o.prefetch})),
        link_(std::make_unique<view::ViewLink>(std::move(connection_.client))),
        scene_(view::default_scene(link_->manifest(), 0)),
        controller_(std::make_unique<view::ViewController>(*link_, scene_)),
        lod_options_(controller_->options().lod),
        full_options_(every_leaf_options(link_->octree())),
        renderer_(render_settings(o)),
        target_(o.width, o.height) {
    std::vector<std::uint32_t> ids;
    for (const auto& s : scene_.subvolumes) ids.push_back(s.id);
    const render::ShaderUpdate layout = renderer_.set_scene_layout(ids, scene_.attributes);
    if (!layout.ok) throw make_error(ErrorCode::kInternal, "view suite: {}", layout.error);
  }
  ~StoreBench() {
    controller_.reset();
    link_.reset();  // says Goodbye before the server stops
  }
  StoreBench(const StoreBench&) = delete;
  StoreBench& operator=(const StoreBench&) = delete;

  const OctreeLayout& octree() const { return link_->octree(); }

  std::vector<StoreView> views() const {
    const lod::WorldFrame& frame = controller_->frame();
    const double aspect = double(o_.width) / double(o_.height);
    std::vector<StoreView> out{{"home", view::OrbitCamera(frame.domain()).camera(aspect)}};
    const lod::CameraPath path = lod::default_fly_in_path(frame, o_.fly_seconds);
    const lod::WorldCameraPath world(path, frame, "default fly-in");
    for (std::size_t k : o_.fly_in_keyframes) {
      const double t = path.keyframes.at(k).t;
      out.push_back({fmt::format("fly-in key {} (t {:g} s)", k, t),
                     lod::pose_camera(world.sample(t), aspect, frame.domain())});
    }
    return out;
  }

  RenderedView render_view(const StoreView& v, bool full) {
    controller_->set_lod_options(full ? full_options_ : lod_options_);
    const render::FrameInputs in = inputs(v.camera);
    const render::CompleteFrame frame = complete(in);
    RenderedView r;
    r.view = v.name;
    r.full = full;
    r.cut_nodes = frame.cut_nodes;
    r.nodes_with_mesh = frame.nodes_with_mesh;
    r.ready_ms = frame.wait_ms;
    wait_server_idle(*connection_.server, 120);
    std::vector<double> wall, opaque, geometry, resolve;
    for (int i = 0; i < o_.repeat; ++i) {
      const auto t0 = SteadyClock::now();
      r.stats = renderer_.render(in, target_.framebuffer(), target_.width(), target_.height());
      render::VolumeRenderer::read_pixels(target_.framebuffer(), target_.width(), target_.height());
      wall.push_back(ms_since(t0));
      opaque.push_back(r.stats.opaque_ms);
      geometry.push_back(r.stats.geometry_ms);
      resolve.push_back(r.stats.resolve_ms);
    }
    r.triangles = r.stats.triangles_drawn;
    r.render_ms = spread_of(wall);
    r.opaque_ms = spread_of(opaque);
    r.geometry_ms = spread_of(geometry);
    r.resolve_ms = spread_of(resolve);
    return r;
  }

  // The LOD view complete at the current step, then `repeat` changes of the step.
  TimeChangeBench time_changes(const StoreView& v) {
    controller_->set_lod_options(lod_options_);
    TimeChangeBench tc;
    tc.view = v.name;
    tc.cut_nodes = complete(inputs(v.camera)).cut_nodes;
    const auto steps = static_cast<std::uint32_t>(link_->manifest().time.values.size());
    std::vector<double> first, all, picture;
    for (int i = 0; i < o_.repeat; ++i) {
      wait_server_idle(*connection_.server, 120);
      ++tc.changes;
      const auto start = SteadyClock::now();
      controller_->set_time((controller_->time_step() + 1) % steps);
      const render::FrameInputs in = inputs(v.camera);
      if (!wait_first_result(in.camera, start)) continue;
      const double before = ms_since(start);
      first.push_back(before);
      try {
        const render::CompleteFrame frame = complete(in);
        all.push_back(before + frame.wait_ms);
        picture.push_back(ms_since(start));
        ++tc.completed;
      } catch (const Error& e) {
        if (e.code() != ErrorCode::kCancelled) throw;
        spdlog::warn("bench: {}: time-step change {}: {}", v.name, i + 1, e.what());
      }
    }
    tc.first_ms = spread_of(first);
    tc.complete_ms = spread_of(all);
    tc.picture_ms = spread_of(picture);
    return tc;
  }

 private:
  static render::RenderSettings render_settings(const ViewSuiteOptions& o) {
    render::RenderSettings s;
    s.max_fragment_bytes = o.max_fragment_mib << 20;
    return s;
  }

  render::FrameInputs inputs(const lod::Camera& camera) const {
    render::FrameInputs in = render::frame_inputs(*controller_, camera);
    in.time_seconds = view::seconds_since_first_step(link_->manifest(), controller_->time_step());
    return in;
  }

  render::CompleteFrame complete(const render::FrameInputs& in) {
    render::CompleteFrameOptions options;
    options.timeout = kCompleteTimeout;
    return render::render_complete_frame(*controller_, renderer_, target_, in, options);
  }

  // Polls the controller until a node of the new request is answered (or the request
  // completes with an empty cut). False after the timeout.
  bool wait_first_result(const lod::Camera& camera, SteadyClock::time_point start) {
    while (true) {
      const view::FrameCounters counters = controller_->update(camera);
      if (controller_->connection_lost()) {
        throw make_error(ErrorCode::kIo, "view suite: {}",
                         controller_->last_error().value_or("connection to the server lost"));
      }
      const auto& meshes = controller_->meshes();
      if (meshes.pending() < meshes.size() || controller_->complete()) return true;
      if (SteadyClock::now() - start > kCompleteTimeout) return false;
      if (counters.events == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }

  const ViewSuiteOptions& o_;
  view::LocalConnection connection_;
  std::unique_ptr<view::ViewLink> link_;
  Scene scene_;
  std::unique_ptr<view::ViewController> controller_;
  lod::LodOptions lod_options_, full_options_;
  render::VolumeRenderer renderer_;
  render::OffscreenTarget target_;
};

void validate_options(const ViewSuiteOptions& o) {
  if (o.repeat < 1 || !(o.fps > 0) || !(o.fly_seconds > 0)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "view suite: repeat, fps and the fly-in duration must be > 0");
  }
  if (o.width < 16 || o.height < 16 || o.width > 16384 || o.height > 16384) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "view suite: image {}x{}: each side must be 16 to 16384", o.width, o.height);
  }
  if (o.steps < 2) {
    throw make_error(ErrorCode::kInvalidArgument, "view suite: needs at least 2 time steps");
  }
  if (o.max_fragment_mib < 1) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "view suite: the fragment pool needs at least 1 MiB");
  }
  // The number of keyframes does not depend on the grid.
  const lod::WorldFrame any_frame(octree_only_manifest({2, 2, 2}, 2));
  const std::size_t keys = lod::default_fly_in_path(any_frame).keyframes.size();
  for (std::size_t k : o.fly_in_keyframes) {
    if (k >= keys) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "view suite: fly-in keyframe {} does not exist (the path has {}: 0 to {})",
                       k, keys, keys - 1);
    }
  }
}

bool is_software_gl(const std::string& description) {
  for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "software"}) {
    if (description.find(name) != std::string::npos) return true;
  }
  return false;
}

}  // namespace

Spread spread_of(std::vector<double> values) {
  Spread s;
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  s.count = values.size();
  s.min = values.front();
  s.max = values.back();
  s.p10 = percentile_sorted(values, 0.10);
  s.median = percentile_sorted(values, 0.50);
  s.p90 = percentile_sorted(values, 0.90);
  s.p99 = percentile_sorted(values, 0.99);
  return s;
}

ViewSuiteOptions quick_view_options(ViewSuiteOptions o) {
  o.dims = {96, 104, 20};
  o.brick = 8;
  o.width = 320;
  o.height = 180;
  o.repeat = 2;
  o.cache_mib = 64;
  return o;
}

ViewSuiteReport run_view_suite(const ViewSuiteOptions& o) {
  validate_options(o);
  const Stopwatch suite;
  ViewSuiteReport report;
  report.options = o;
  std::filesystem::create_directories(o.work);
  report.machine = machine_info(o.work);

  spdlog::info("bench: cut updates along the fly-in on a {}x{}x{} octree (brick {}), {} passes",
               o.cut_grid.x, o.cut_grid.y, o.cut_grid.z, o.cut_brick, o.repeat);
  report.cut = run_cut_updates(o);

  report.input = ensure_sample_input({o.dims, o.steps, o.variables, o.seed}, o.work / "input");
  const Stopwatch convert_clock;
  const auto store = o.work / kStoreName;
  spdlog::info("bench: converting into {} (brick {})", store.string(), o.brick);
  convert_sample_store(report.input, o.variables, o.brick, o.convert_threads, store);
  report.convert_seconds = convert_clock.seconds();

  const auto context = render::HeadlessContext::create();
  report.gl = render::current_gl_description();
  report.software_gl = is_software_gl(report.gl);
  spdlog::info("bench: rendering with {}", report.gl);
  StoreBench bench(o, store);
  report.store_nodes = bench.octree().node_count();
  report.store_leaves = bench.octree().level(0).node_count();
  for (const StoreView& v : bench.views()) {
    spdlog::info("bench: {}: LOD cut", v.name);
    report.frames.push_back(bench.render_view(v, false));
    spdlog::info("bench: {}: every leaf", v.name);
    report.frames.push_back(bench.render_view(v, true));
    spdlog::info("bench: {}: {} time-step changes", v.name, o.repeat);
    report.time_changes.push_back(bench.time_changes(v));
  }
  report.machine["load_average_1min_end"] = load_average_1min();
  report.targets = evaluate_view_targets(report);
  report.seconds = suite.seconds();
  return report;
}

}  // namespace strielad::bench
