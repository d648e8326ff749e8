// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench view` suite, side by side
// in one run:
//  1. LodCut::update per frame along the default fly-in on the paper's 51,393-node
//     octree (1429 x 1556 x 150, brick 20; built from the axes alone, no data);
//  2. the frame time of the complete LOD view against a cut of every visible level-0
//     node at full resolution, for the home view and keyframes of the fly-in, on a
//     generated store served in-process and rendered headless (render/complete_frame.h);
//  3. the A-buffer of those renders: fragments per covered pixel, the most in one pixel,
//     pixels over the K = 32 kept, dropped fragments, sort + resolve time;
//  4. the time from a time-step change to the first result and to a complete picture.
// It lives in the render library because it renders; its types are the benchmarks'.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/io_suite.h"
#include "bench/sample_input.h"
#include "bench/table_writer.h"
#include "convert/converter.h"
#include "grid/axis.h"
#include "render/volume_renderer.h"

namespace strielad::bench {

struct ViewSuiteOptions {
  // The generated store that is rendered (two steps: the time-step change needs them).
  Dims3 dims{572, 624, 60};
  std::size_t steps = 2;
  std::vector<std::string> variables{"clw", "cli", "qr", "ta"};
  std::uint64_t seed = 1;
  std::filesystem::path work = "/tmp/strielad-bench-view";
  std::uint32_t brick = build::kDefaultBrick;
  int convert_threads = 0;
  // The in-process server (view/local_server.h).
  unsigned threads = 0;  // extraction workers; 0 = one per hardware thread
  std::uint64_t cache_mib = 1024;
  bool prefetch = true;
  // The renders.
  int width = 1280, height = 720;
  std::size_t max_fragment_mib = render::kDefaultMaxFragmentBytes >> 20;
  // Timed renders per complete view, time-step changes per view and passes along the
  // fly-in for the cut update: the medians and spreads are over these.
  int repeat = 5;
  // Views besides the home view: keyframes of the default fly-in (0 = its start).
  std::vector<std::size_t> fly_in_keyframes{4, 6, 8};
  // The cut update: the octree it runs on and the path sampling.
  Dims3 cut_grid{1429, 1556, 150};
  std::uint32_t cut_brick = 20;
  double fly_seconds = 20;
  double fps = 60;
  std::string command_line;
};

// A small grid, a tiny image and two repeats: seconds, for CI (checks the harness).
ViewSuiteOptions quick_view_options(ViewSuiteOptions base);

// Order statistics of repeated measurements.
struct Spread {
  std::size_t count = 0;
  double min = 0, p10 = 0, median = 0, p90 = 0, p99 = 0, max = 0;
};
Spread spread_of(std::vector<double> values);

// Cut updates in one stretch of the fly-in (between two keyframes), all passes pooled.
struct CutUpdateSegment {
  double from_s = 0, to_s = 0;
  std::size_t updates = 0;
  std::size_t min_nodes = 0, max_nodes = 0;
  double mean_changes = 0;  // nodes added + removed + reprioritized per update
  Spread micros;
};

struct CutUpdateBench {
  Dims3 grid;
  std::uint32_t brick = 0;
  std::size_t octree_nodes = 0;
  std::size_t updates_per_pass = 0;
  int passes = 0;
  Spread micros;                      // every update of every pass
  std::vector<double> pass_median_us; // per pass
  std::size_t min_nodes = 0, max_nodes = 0, final_nodes = 0;
  std::size_t capped_updates = 0;     // updates where max_nodes refused a split
  std::vector<CutUpdateSegment> segments;
};

// One camera, one cut, rendered once complete and then `repeat` times more, timed.
struct RenderedView {
  std::string view;  // "home", "fly-in keyframe 4 (t = 10 s)"
  bool full = false; // every visible level-0 node instead of the LOD cut
  std::size_t cut_nodes = 0, nodes_with_mesh = 0, triangles = 0;
  double ready_ms = 0;  // from the camera (or cut) change to the complete cut
  Spread render_ms;     // wall: render + read-back
  Spread opaque_ms, geometry_ms, resolve_ms;  // GPU timer queries
  render::FrameStats stats;  // of the last timed render
};

// Time-step changes at one view (LOD cut), alternating the steps.
struct TimeChangeBench {
  std::string view;
  std::size_t cut_nodes = 0;
  int changes = 0, completed = 0;
  Spread first_ms;    // from set_time to the first node's result
  Spread complete_ms; // to every node of the cut answered
  Spread picture_ms;  // to the complete picture rendered and read back
};

struct ViewSuiteReport {
  ViewSuiteOptions options;
  nlohmann::json machine;
  std::string gl;          // render::current_gl_description()
  bool software_gl = false;  // llvmpipe, softpipe or another CPU rasterizer
  SampleInput input;
  double convert_seconds = 0;
  std::size_t store_nodes = 0, store_leaves = 0;
  CutUpdateBench cut;
  std::vector<RenderedView> frames;  // per view: the LOD cut, then every leaf
  std::vector<TimeChangeBench> time_changes;
  std::vector<Target> targets;
  double seconds = 0;
};

// Needs EGL (a headless OpenGL 4.3+ context); makes its context current on the calling
// thread. \error kInvalidArgument for options out of range; otherwise as the generator,
// the converter, the server, HeadlessContext and render_complete_frame.
ViewSuiteReport run_view_suite(const ViewSuiteOptions& options);

std::vector<Target> evaluate_view_targets(const ViewSuiteReport& report);
std::vector<Table> view_report_tables(const ViewSuiteReport& report);
nlohmann::json view_report_json(const ViewSuiteReport& report, const std::vector<Table>& tables);

}  // namespace strielad::bench
