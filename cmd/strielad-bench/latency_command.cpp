// SPDX-License-Identifier: Apache-2.0
// strielad-bench latency [--dims XxYxZ] [--threads N] [--cache-mib M] [--camera-path F]
//                        [--repeat N] [--clients N] [--quick] [--csv F] [--json F] ...
#include <fmt/ranges.h>

#include <iostream>
#include <memory>

#include "bench/latency_suite.h"
#include "bench/server_process.h"
#include "bench/table_writer.h"
#include "commands.h"
#include "suite_output.h"
#include "core/error.h"
#include "synthetic/sample_args.h"

namespace strielad::bench_cmd {
namespace {

struct LatencyFlags {
  std::string dims = "1429x1556x150";
  std::string vars = "clw,cli,qr,ta";
  std::string work = "/tmp/strielad-bench-latency";
  std::string camera_path, server;
  unsigned threads = 2;
  std::uint64_t cache_mib = 1024;
  std::uint32_t brick = build::kDefaultBrick;
  int repeat = 3, clients = 32;
  double fly_seconds = 20, fps = 60, rapid_seconds = 10, rapid_interval_ms = 50,
         clients_seconds = 60;
  bool quick = false, in_process = false, no_evict = false;
  std::uint64_t seed = 1;
  std::string csv, json, command_line;
  CLI::App* sub = nullptr;
};

bool given(const LatencyFlags& f, const char* name) { return f.sub->count(name) > 0; }

int run(const LatencyFlags& f) {
  bench::LatencySuiteOptions o;
  if (f.quick) o = bench::quick_latency_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  if (!f.quick || given(f, "--brick")) o.brick = f.brick;
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  if (!f.quick || given(f, "--clients")) o.clients = f.clients;
  if (!f.quick || given(f, "--clients-seconds")) o.clients_seconds = f.clients_seconds;
  if (!f.quick || given(f, "--fly-seconds")) o.fly_seconds = f.fly_seconds;
  if (!f.quick || given(f, "--fps")) o.fps = f.fps;
  if (!f.quick || given(f, "--rapid-seconds")) o.rapid_seconds = f.rapid_seconds;
  if (!f.quick || given(f, "--cache-mib")) o.cache_mib = f.cache_mib;
  if (f.no_evict) o.evict = false;
  o.rapid_interval_ms = f.rapid_interval_ms;
  o.variables = synthetic::parse_variable_list(f.vars);
  o.work = f.work;
  o.seed = f.seed;
  o.threads = f.threads;
  o.camera_path = f.camera_path;
  if (!f.in_process) {
    o.server_binary = f.server.empty() ? bench::find_serve_binary() : std::filesystem::path(f.server);
    if (o.server_binary.empty()) {
      throw make_error(ErrorCode::kNotFound,
                       "no strielad-serve next to strielad-bench: pass --server PATH or --in-process");
    }
  }
  o.command_line = f.command_line;

  const bench::LatencySuiteReport report = bench::run_latency_suite(o);
  const auto tables = bench::latency_report_tables(report);
  const std::string header = fmt::format(
      "strielad-bench latency: {}x{}x{}, {}, {} steps, brick {}, server {} with {} workers and a "
      "{} MiB cache; suite took {:.0f} s (generate {:.0f} s, convert {:.0f} s); {} cores, load "
      "average {:.1f} at the end",
      o.dims.x, o.dims.y, o.dims.z, fmt::join(o.variables, ","), o.steps, o.brick,
      o.server_binary.empty() ? std::string("in-process") : std::string("process"), o.threads,
      o.cache_mib, report.seconds, report.input.generate_seconds, report.convert_seconds,
      report.machine.value("cores", 0u), report.machine.value("load_average_1min_end", -1.0));
  emit_suite_report(header, tables, f.csv, f.json, o.work,
                    [&] { return bench::latency_report_json(report, tables); });
  return 0;
}

}  // namespace

void register_latency(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<LatencyFlags>();
  auto* sub = app.add_subcommand(
      "latency",
      "A simulated viewer (the LOD cut) against strielad-serve over loopback: fly-in, time to "
      "first/50/90/100 % of the cut after scene and time changes (prefetch on/off), rapid time "
      "changes, concurrent clients and server memory");
  f->sub = sub;
  sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated input (2 time steps)")
      ->capture_default_str();
  sub->add_option("--vars", f->vars, "Sample variables (the scenes need clw, cli, qr, ta)")
      ->capture_default_str();
  sub->add_option("--work", f->work, "Scratch directory; input and store are reused when unchanged")
      ->capture_default_str();
  sub->add_option("--brick", f->brick, "Brick size of the store")->capture_default_str();
  sub->add_option("--threads", f->threads, "Server extraction workers")->capture_default_str();
  sub->add_option("--cache-mib", f->cache_mib, "Server brick-cache budget")->capture_default_str();
  sub->add_option("--camera-path", f->camera_path,
                  "Camera path JSON (formats/camera-path.md); default: a fly-in over the domain");
  sub->add_option("--fly-seconds", f->fly_seconds, "Duration of the default fly-in")->capture_default_str();
  sub->add_option("--fps", f->fps, "Frames per second of the simulated viewer")->capture_default_str();
  sub->add_option("--repeat", f->repeat, "Rounds of the cold/scene/time phases per prefetch mode")
      ->capture_default_str();
  sub->add_option("--rapid-seconds", f->rapid_seconds, "Duration of the rapid time changes")
      ->capture_default_str();
  sub->add_option("--rapid-interval-ms", f->rapid_interval_ms, "Interval of the rapid time changes")
      ->capture_default_str();
  sub->add_option("--clients", f->clients, "Concurrent clients")->capture_default_str();
  sub->add_option("--clients-seconds", f->clients_seconds, "Duration of the concurrent clients")
      ->capture_default_str();
  sub->add_option("--server", f->server, "strielad-serve binary (default: next to this tool)");
  sub->add_flag("--in-process", f->in_process, "Run the server inside the benchmark process");
  sub->add_flag("--no-evict", f->no_evict, "Do not drop the store from the page cache before cold starts");
  sub->add_option("--seed", f->seed, "Seed of the sample data")->capture_default_str();
  sub->add_flag("--quick", f->quick, "Tiny grid, short phases: checks the harness (CI)");
  sub->add_option("--csv", f->csv, "Write the tables as tidy CSV (table,row,column,value)");
  sub->add_option("--json", f->json, "Write the tables, targets and machine info as JSON");
  f->command_line = std::move(command_line);
  sub->callback([&action, f] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
