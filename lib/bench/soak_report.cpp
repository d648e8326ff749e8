// SPDX-License-Identifier: Apache-2.0
// The soak suite's tables and JSON.
#include <fmt/format.h>

#include "bench/soak_suite.h"

namespace strielad::bench {

namespace {

double mib(double bytes) { return bytes / double(1 << 20); }
// -1 (a key the server does not report) stays -1.
Cell count(std::int64_t n) { return Cell::integer(double(n)); }

}  // namespace

std::vector<Table> soak_report_tables(const SoakSuiteReport& r) {
  const SoakSuiteOptions& o = r.options;
  Table samples{"soak_samples",
                fmt::format("The server over time: {} clients, {} slow readers, {} tricklers "
                            "(a byte every {} s); limits {} clients, {} handshakes, {} s "
                            "handshake, {} MiB send queue",
                            o.clients, o.slow_readers, o.tricklers, o.trickle_interval_s,
                            o.max_clients, o.max_handshakes, o.handshake_timeout_s,
                            o.send_queue_mib),
                {"t_s", "rss_mib", "clients", "handshakes", "readers_paused", "send_queue_mib",
                 "handshakes_dropped", "rounds", "answers", "errors", "refused"},
                {},
                {}};
  for (const SoakSample& s : r.samples) {
    samples.add({Cell(s.t, 0), Cell(mib(double(s.rss_bytes)), 1), count(s.clients),
                 count(s.handshakes), count(s.readers_paused),
                 Cell(s.send_queue_bytes < 0 ? -1.0 : mib(double(s.send_queue_bytes)), 1),
                 count(s.handshakes_dropped), Cell::integer(double(s.rounds)),
                 Cell::integer(double(s.answers)), Cell::integer(double(s.errors)),
                 Cell::integer(double(s.refused))});
  }
  samples.notes.push_back(
      "clients and handshakes: the server's slots in use (Stats; the monitor is one client); "
      "rounds, answers, errors, refused: the normal clients so far; -1: not reported");
  if (!r.memory_measured) samples.notes.push_back("in-process server: RSS is the whole benchmark's");

  Table summary{"soak_summary", "Memory and slots over the run", {"measure", "value"}, {}, {}};
  summary.add({"RSS at start (MiB)", Cell(mib(double(r.rss_start)), 1)});
  summary.add({"RSS max (MiB)", Cell(mib(double(r.rss_max)), 1)});
  summary.add({"RSS at end (MiB)", Cell(mib(double(r.rss_end)), 1)});
  summary.add({"RSS growth over the second half (MiB)", Cell(mib(double(r.rss_second_half_growth)), 1)});
  summary.add({"most client slots used", count(r.max_clients_used)});
  summary.add({"client slots", Cell::integer(double(o.max_clients))});
  summary.add({"most handshake slots used", count(r.max_handshakes_used)});
  summary.add({"handshake slots", Cell::integer(double(o.max_handshakes))});

  Table kinds{"soak_clients",
              "What each kind of client got",
              {"kind", "count", "connections", "rounds", "answers", "requests", "refused",
               "errors", "closed_by_server"},
              {},
              {}};
  for (const SoakKindTotals& k : r.kinds) {
    kinds.add({k.kind, Cell::integer(k.count), Cell::integer(double(k.connections)),
               Cell::integer(double(k.rounds)), Cell::integer(double(k.answers)),
               Cell::integer(double(k.requests)), Cell::integer(double(k.refused)),
               Cell::integer(double(k.errors)), Cell::integer(double(k.closed_by_server))});
  }
  kinds.notes.push_back(
      "normal: a round is connect, open, scene, the whole octree answered, Stats, Goodbye; "
      "slow readers write requests and never read; tricklers never finish their Hello");
  return {samples, summary, kinds};
}

nlohmann::json soak_report_json(const SoakSuiteReport& r, const std::vector<Table>& tables) {
  const SoakSuiteOptions& o = r.options;
  nlohmann::json j = {
      {"suite", "soak"},
      {"command", o.command_line},
      {"options",
       {{"dims", {o.dims.x, o.dims.y, o.dims.z}},
        {"steps", o.steps},
        {"variables", o.variables},
        {"brick", o.brick},
        {"threads", o.threads},
        {"cache_mib", o.cache_mib},
        {"server", o.server_binary.empty() ? "in-process" : o.server_binary.string()},
        {"max_clients", o.max_clients},
        {"max_handshakes", o.max_handshakes},
        {"handshake_timeout_s", o.handshake_timeout_s},
        {"send_queue_mib", o.send_queue_mib},
        {"clients", o.clients},
        {"slow_readers", o.slow_readers},
        {"tricklers", o.tricklers},
        {"trickle_interval_s", o.trickle_interval_s},
        {"seconds", o.seconds},
        {"sample_seconds", o.sample_seconds}}},
      {"machine", r.machine},
      {"seconds", r.seconds},
      {"octree_nodes", r.octree_nodes},
      {"memory_measured", r.memory_measured},
      {"rss", {{"start", r.rss_start}, {"max", r.rss_max}, {"end", r.rss_end},
               {"second_half_growth", r.rss_second_half_growth}}},
      {"max_clients_used", r.max_clients_used},
      {"max_handshakes_used", r.max_handshakes_used},
  };
  nlohmann::json t = nlohmann::json::object();
  for (const auto& table : tables) t[table.name] = table_json(table);
  j["tables"] = t;
  return j;
}

}  // namespace strielad::bench
