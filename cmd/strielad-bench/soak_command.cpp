// SPDX-License-Identifier: Apache-2.0
// strielad-bench soak [--clients N] [--slow-readers N] [--tricklers N] [--seconds S]
//                     [--server PATH | --in-process] [--quick] [--csv F] [--json F] ...
#include <fmt/format.h>

#include <memory>

#include "bench/server_process.h"
#include "bench/soak_suite.h"
#include "commands.h"
#include "core/error.h"
#include "synthetic/sample_args.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct SoakFlags {
  std::string dims = "96x96x40";
  std::string work = "/tmp/strielad-bench-soak";
  std::string server;
  bench::SoakSuiteOptions o;
  bool quick = false, in_process = false;
  std::string csv, json, command_line;
  CLI::App* sub = nullptr;
};

int run(SoakFlags& f) {
  bench::SoakSuiteOptions o = f.o;
  if (f.quick) {
    // Quick values, except where a flag was given.
    const bench::SoakSuiteOptions q = bench::quick_soak_options(o);
    auto keep = [&](const char* flag, auto& field, const auto& quick_value) {
      if (f.sub->count(flag) == 0) field = quick_value;
    };
    keep("--dims", o.dims, q.dims);
    o.brick = q.brick;
    keep("--cache-mib", o.cache_mib, q.cache_mib);
    keep("--clients", o.clients, q.clients);
    keep("--slow-readers", o.slow_readers, q.slow_readers);
    keep("--tricklers", o.tricklers, q.tricklers);
    keep("--max-handshakes", o.max_handshakes, q.max_handshakes);
    keep("--handshake-timeout", o.handshake_timeout_s, q.handshake_timeout_s);
    keep("--trickle-interval", o.trickle_interval_s, q.trickle_interval_s);
    keep("--send-queue-mib", o.send_queue_mib, q.send_queue_mib);
    keep("--seconds", o.seconds, q.seconds);
    keep("--sample-seconds", o.sample_seconds, q.sample_seconds);
  }
  if (!f.quick || f.sub->count("--dims")) o.dims = synthetic::parse_dims(f.dims);
  o.work = f.work;
  if (!f.in_process) {
    o.server_binary = f.server.empty() ? bench::find_serve_binary() : std::filesystem::path(f.server);
    if (o.server_binary.empty()) {
      throw make_error(ErrorCode::kNotFound,
                       "no strielad-serve next to strielad-bench: pass --server PATH or --in-process");
    }
  }
  o.command_line = f.command_line;
  const bench::SoakSuiteReport report = bench::run_soak_suite(o);
  const auto tables = bench::soak_report_tables(report);
  const std::string header = fmt::format(
      "strielad-bench soak: {}x{}x{} ({} nodes), server {} with {} workers; {} clients, {} slow "
      "readers, {} tricklers for {:.0f} s; RSS {:.1f} -> max {:.1f} -> {:.1f} MiB; suite took "
      "{:.0f} s; {} cores, load average {:.1f} at the end",
      o.dims.x, o.dims.y, o.dims.z, report.octree_nodes,
      o.server_binary.empty() ? std::string("in-process") : std::string("process"), o.threads,
      o.clients, o.slow_readers, o.tricklers, o.seconds, double(report.rss_start) / (1 << 20),
      double(report.rss_max) / (1 << 20), double(report.rss_end) / (1 << 20), report.seconds,
      report.machine.value("cores", 0u), report.machine.value("load_average_1min_end", -1.0));
  emit_suite_report(header, tables, f.csv, f.json, o.work,
                    [&] { return bench::soak_report_json(report, tables); });
  return 0;
}

}  // namespace

void register_soak(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<SoakFlags>();
  auto* sub = app.add_subcommand(
      "soak",
      "strielad-serve under normal clients, slow readers that never read and tricklers that "
      "never finish their handshake: the server's RSS and slot use over time");
  f->sub = sub;
  bench::SoakSuiteOptions& o = f->o;
  sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated input")->capture_default_str();
  sub->add_option("--work", f->work, "Scratch directory; input and store are reused when unchanged")
      ->capture_default_str();
  sub->add_option("--threads", o.threads, "Server extraction workers")->capture_default_str();
  sub->add_option("--cache-mib", o.cache_mib, "Server brick-cache budget")->capture_default_str();
  sub->add_option("--clients", o.clients, "Normal clients (connect, extract the whole octree, "
                  "leave, again)")->capture_default_str();
  sub->add_option("--slow-readers", o.slow_readers, "Clients that send requests and never read")
      ->capture_default_str();
  sub->add_option("--tricklers", o.tricklers, "Connections sending one handshake byte at a time")
      ->capture_default_str();
  sub->add_option("--trickle-interval", o.trickle_interval_s, "Seconds between a trickler's bytes")
      ->capture_default_str();
  sub->add_option("--seconds", o.seconds, "Duration")->capture_default_str();
  sub->add_option("--sample-seconds", o.sample_seconds, "Interval of the RSS and Stats samples")
      ->capture_default_str();
  sub->add_option("--max-clients", o.max_clients, "Server --max-clients")->capture_default_str();
  sub->add_option("--max-handshakes", o.max_handshakes, "Server --max-handshakes")->capture_default_str();
  sub->add_option("--handshake-timeout", o.handshake_timeout_s, "Server --handshake-timeout (s)")
      ->capture_default_str();
  sub->add_option("--send-queue-mib", o.send_queue_mib, "Server --max-send-queue-mib")
      ->capture_default_str();
  sub->add_option("--server", f->server, "strielad-serve binary (default: next to this tool)");
  sub->add_flag("--in-process", f->in_process, "Run the server inside the benchmark process");
  sub->add_flag("--quick", f->quick, "Tiny grid, few clients, a few seconds: checks the harness (CI)");
  sub->add_option("--csv", f->csv, "Write the tables as tidy CSV (table,row,column,value)");
  sub->add_option("--json", f->json, "Write the samples, totals and machine info as JSON");
  f->command_line = std::move(command_line);
  sub->callback([&action, f] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
