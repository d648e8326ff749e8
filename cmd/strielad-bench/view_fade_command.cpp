// SPDX-License-Identifier: Apache-2.0
// strielad-bench view-fade [--dims XxYxZ] [--size WxH] [--fps N] [--from S] [--to S]
//                          [--fade-ms MS] [--work DIR] [--json F]
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>
#include <tuple>

#include "bench/lod_fade_bench.h"
#include "cli/image_size.h"
#include "commands.h"
#include "bench/table_writer.h"
#include "synthetic/sample_args.h"

namespace strielad::bench_cmd {
namespace {

struct FadeFlags {
  std::string dims = "286x312x60";
  std::string size = "480x270";
  std::string work = "/tmp/strielad-bench-view-fade";
  std::uint32_t brick = 24;
  double fps = 30, from_s = 0, to_s = 20, fly_seconds = 20, fade_ms = 300;
  unsigned threads = 0;
  std::string json, command_line;
};

int run(const FadeFlags& f) {
  bench::FadeBenchOptions o;
  o.dims = synthetic::parse_dims(f.dims);
  std::tie(o.width, o.height) = cli::parse_image_size(f.size);
  o.work = f.work;
  o.brick = f.brick;
  o.fps = f.fps;
  o.from_s = f.from_s;
  o.to_s = f.to_s;
  o.fly_seconds = f.fly_seconds;
  o.fade_ms = f.fade_ms;
  o.threads = f.threads;
  o.command_line = f.command_line;
  const auto report = bench::run_fade_bench(o);
  std::cout << bench::fade_report_text(report) << std::flush;
  if (!f.json.empty()) {
    bench::write_text_file(f.json, bench::fade_report_json(report).dump(1) + "\n");
  }
  return 0;
}

}  // namespace

void register_view_fade(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<FadeFlags>();
  auto* sub = app.add_subcommand(
      "view-fade",
      "Level-of-detail pops along the default fly-in: the largest per-pixel change between "
      "consecutive frames with the cross-fade off and on (headless OpenGL)");
  sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated store (1 time step)")
      ->capture_default_str();
  sub->add_option("--brick", f->brick, "Brick size of the store")->capture_default_str();
  sub->add_option("--size", f->size, "Image WIDTHxHEIGHT")->capture_default_str();
  sub->add_option("--fps", f->fps, "Frames per second (simulated time per frame 1/fps)")
      ->capture_default_str();
  sub->add_option("--fly-seconds", f->fly_seconds, "Duration of the default fly-in")
      ->capture_default_str();
  sub->add_option("--from", f->from_s, "Start of the stretch rendered, s")->capture_default_str();
  sub->add_option("--to", f->to_s, "End of the stretch rendered, s")->capture_default_str();
  sub->add_option("--fade-ms", f->fade_ms, "Cross-fade time of the second run")
      ->capture_default_str();
  sub->add_option("--threads", f->threads, "Server extraction workers (0: one per core)")
      ->capture_default_str();
  sub->add_option("--work", f->work, "Scratch directory; input and store are reused")
      ->capture_default_str();
  sub->add_option("--json", f->json, "Write the numbers, per frame included, as JSON");
  f->command_line = std::move(command_line);
  sub->callback([&action, f] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
