// SPDX-License-Identifier: Apache-2.0
// strielad-bench view [--dims XxYxZ] [--size WxH] [--repeat N] [--threads N] [--work DIR]
//                     [--quick] [--csv F] [--json F] ...
#include <fmt/ranges.h>

#include <memory>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "cli/image_size.h"
#include "commands.h"
#include "bench/view_bench.h"
#include "synthetic/sample_args.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct ViewFlags {
  std::string dims = "572x624x60";
  std::string vars = "clw,cli,qr,ta";
  std::string work = "/tmp/strielad-bench-view";
  std::string size = "1280x720";
  std::string cut_grid = "1429x1556x150";
  std::vector<std::size_t> keyframes{4, 6, 8};
  unsigned threads = 0;
  std::uint64_t cache_mib = 1024;
  std::size_t max_fragment_mib = render::kDefaultMaxFragmentBytes >> 20;
  std::uint32_t brick = build::kDefaultBrick, cut_brick = 20;
  int repeat = 5;
  double fly_seconds = 20, fps = 60;
  bool quick = false, no_prefetch = false;
  std::uint64_t seed = 1;
  std::string csv, json, command_line;
  CLI::App* sub = nullptr;
};

bool given(const ViewFlags& f, const char* name) { return f.sub->count(name) > 0; }

std::string describe(const bench::ViewSuiteReport& r) {
  const auto& o = r.options;
  return fmt::format(
      "strielad-bench view: {}{}\nstore {}x{}x{}, {}, {} steps, brick {} ({} nodes, {} "
      "leaves), in-process server ({} workers{}, {} MiB cache, prefetch {}); image {}x{}, {} "
      "repeats; suite took {:.0f} s (generate {:.0f} s, convert {:.0f} s); {} cores, load "
      "average {:.1f} at the end",
      r.gl, r.software_gl ? " -- software rendering on the CPU (Mesa llvmpipe), not a GPU" : "",
      o.dims.x, o.dims.y, o.dims.z, fmt::join(o.variables, ","), o.steps, o.brick, r.store_nodes,
      r.store_leaves, o.threads ? o.threads : std::thread::hardware_concurrency(),
      o.threads ? "" : ": one per core",
      o.cache_mib, o.prefetch ? "on" : "off", o.width, o.height, o.repeat, r.seconds,
      r.input.generate_seconds, r.convert_seconds, r.machine.value("cores", 0u),
      r.machine.value("load_average_1min_end", -1.0));
}

int run(const ViewFlags& f) {
  bench::ViewSuiteOptions o;
  if (f.quick) o = bench::quick_view_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  if (!f.quick || given(f, "--brick")) o.brick = f.brick;
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  if (!f.quick || given(f, "--cache-mib")) o.cache_mib = f.cache_mib;
  if (!f.quick || given(f, "--size")) std::tie(o.width, o.height) = cli::parse_image_size(f.size);
  o.variables = synthetic::parse_variable_list(f.vars);
  o.work = f.work;
  o.seed = f.seed;
  o.threads = f.threads;
  o.prefetch = !f.no_prefetch;
  o.max_fragment_mib = f.max_fragment_mib;
  o.fly_in_keyframes = f.keyframes;
  o.cut_grid = synthetic::parse_dims(f.cut_grid);
  o.cut_brick = f.cut_brick;
  o.fly_seconds = f.fly_seconds;
  o.fps = f.fps;
  o.command_line = f.command_line;

  const bench::ViewSuiteReport report = bench::run_view_suite(o);
  const auto tables = bench::view_report_tables(report);
  emit_suite_report(describe(report), tables, f.csv, f.json, o.work,
                    [&] { return bench::view_report_json(report, tables); });
  return 0;
}

}  // namespace

void register_view(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<ViewFlags>();
  auto* sub = app.add_subcommand(
      "view",
      "The viewer's frame: LOD cut update per frame on the paper's octree, frame time of the "
      "LOD cut against every leaf at full resolution, A-buffer fragments per pixel, and the "
      "time from a time-step change to a complete picture (headless OpenGL)");
  f->sub = sub;
  sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated store (2 time steps)")
      ->capture_default_str();
  sub->add_option("--vars", f->vars, "Sample variables (the view's scene uses clw, cli, qr, ta)")
      ->capture_default_str();
  sub->add_option("--work", f->work, "Scratch directory; input and store are reused when unchanged")
      ->capture_default_str();
  sub->add_option("--brick", f->brick, "Brick size of the store")->capture_default_str();
  sub->add_option("--size", f->size, "Image WIDTHxHEIGHT")->capture_default_str();
  sub->add_option("--repeat", f->repeat,
                  "Timed renders per view, time-step changes per view and passes along the fly-in")
      ->capture_default_str();
  sub->add_option("--threads", f->threads, "Server extraction workers (0: one per core)")
      ->capture_default_str();
  sub->add_option("--cache-mib", f->cache_mib, "Server brick-cache budget")->capture_default_str();
  sub->add_flag("--no-prefetch", f->no_prefetch,
                "Do not let the server prefetch the next time step");
  sub->add_option("--max-fragment-mib", f->max_fragment_mib, "Bound of the A-buffer fragment pool")
      ->capture_default_str();
  sub->add_option("--keyframes", f->keyframes,
                  "Keyframes of the default fly-in rendered besides the home view (0-8)")
      ->capture_default_str();
  sub->add_option("--cut-grid", f->cut_grid, "Grid of the octree the cut update runs on")
      ->capture_default_str();
  sub->add_option("--cut-brick", f->cut_brick, "Brick of that octree")->capture_default_str();
  sub->add_option("--fly-seconds", f->fly_seconds, "Duration of the default fly-in")
      ->capture_default_str();
  sub->add_option("--fps", f->fps, "Frames per second along the fly-in")->capture_default_str();
  sub->add_option("--seed", f->seed, "Seed of the sample data")->capture_default_str();
  sub->add_flag("--quick", f->quick, "Tiny grid and image, two repeats: checks the harness (CI)");
  sub->add_option("--csv", f->csv, "Write the tables as tidy CSV (table,row,column,value)");
  sub->add_option("--json", f->json, "Write the tables, targets and machine info as JSON");
  f->command_line = std::move(command_line);
  sub->callback([&action, f] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
