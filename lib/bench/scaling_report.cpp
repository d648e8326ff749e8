// SPDX-License-Identifier: Apache-2.0
// The scaling suite's tables and JSON (bench/scaling_suite.h).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "bench/scaling_suite.h"

namespace strielad::bench {
namespace {

std::string grid_name(Dims3 d) { return fmt::format("{}x{}x{}", d.x, d.y, d.z); }

double cells(Dims3 d) { return double(d.x) * double(d.y) * double(d.z); }

// "min-max" of a spread in the given unit (1 = seconds, 1000 = ms).
std::string range_text(const Summary& s, double unit, int decimals) {
  if (s.count == 0) return "-";
  return fmt::format("{:.{}f}-{:.{}f}", s.min * unit, decimals, s.max * unit, decimals);
}

Cell value(const Summary& s, double unit, int decimals) {
  return s.count ? Cell(s.p50 * unit, decimals) : Cell("-");
}

const ThreadRun* fastest(const std::vector<ThreadRun>& runs) {
  const ThreadRun* best = nullptr;
  for (const auto& r : runs) {
    if (!best || r.threads > best->threads) best = &r;
  }
  return best;
}

double ratio(double a, double b) { return b > 0 ? a / b : 0; }

Table grid_table(const ScalingSuiteReport& r) {
  Table t;
  t.name = "scaling_grid";
  t.title = "Cost against grid size: conversion, the whole full-resolution level, one view's cut";
  t.columns = {"grid",          "M cells",       "input MB",   "store MB",     "leaves",
               "threads",       "convert s",     "convert range", "x cells",   "x convert",
               "level 0 s",     "level 0 range", "x level 0", "extracted",    "level MB sent",
               "cut nodes",     "cut s",         "x cut",     "cut MB sent"};
  const GridScaling* base = r.grids.empty() ? nullptr : &r.grids.front();
  for (const GridScaling& g : r.grids) {
    const ThreadRun* convert = fastest(g.convert);
    const ThreadRun* level = fastest(g.level);
    const ThreadRun* base_convert = fastest(base->convert);
    const ThreadRun* base_level = fastest(base->level);
    t.add({grid_name(g.dims), Cell(cells(g.dims) / 1e6, 1), Cell(g.input_bytes / 1e6, 0),
           Cell(g.store_bytes / 1e6, 1), Cell::integer(double(g.leaves)),
           Cell::integer(convert ? convert->threads : 0),
           convert ? value(convert->seconds, 1, 2) : Cell("-"),
           convert ? range_text(convert->seconds, 1, 2) : "-",
           Cell(ratio(cells(g.dims), cells(base->dims)), 2),
           Cell(convert && base_convert ? ratio(convert->seconds.p50, base_convert->seconds.p50) : 0, 2),
           level ? value(level->seconds, 1, 3) : Cell("-"),
           level ? range_text(level->seconds, 1, 3) : "-",
           Cell(level && base_level ? ratio(level->seconds.p50, base_level->seconds.p50) : 0, 2),
           Cell::integer(double(g.level_cost.extracted)), Cell(g.level_cost.bytes_sent / 1e6, 1),
           Cell::integer(double(g.cut_cost.nodes)), value(g.cut_seconds, 1, 3),
           Cell(ratio(g.cut_seconds.p50, base->cut_seconds.p50), 2),
           Cell(g.cut_cost.bytes_sent / 1e6, 1)});
  }
  const auto& o = r.options;
  t.notes = {
      fmt::format("grids: {} of the cells of {} (both horizontal axes scaled by the square "
                  "root), one generated time step, variables {}, brick {}",
                  fmt::join(o.fractions, ", "), grid_name(o.dims), fmt::join(o.variables, ","),
                  o.brick),
      "convert s = strielad-convert's conversion in process (NetCDF reads from the page cache, "
      "store written and fsynced, finalized), at the most threads of the list",
      "level 0 = every full-resolution node of the clouds scene (clw >= 1e-5, cli >= 1e-6, "
      "shaded by ta) through the server's node task, fresh store and brick cache, bricks from "
      "the page cache; MB sent = the NodeResult frames a client would receive",
      "cut = the viewer's LOD cut of an overview camera (16:9, 45 degrees) extracted the same "
      "way; x = against the smallest grid; median of the rounds, range = min-max",
  };
  return t;
}

Table threads_table(const ScalingSuiteReport& r) {
  Table t;
  t.name = "scaling_threads";
  t.title = "Threads: conversion and the whole full-resolution level at 1 and 2 threads";
  t.columns = {"grid", "work", "threads", "median s", "range s", "speed-up", "efficiency %"};
  for (const GridScaling& g : r.grids) {
    for (const auto* runs : {&g.convert, &g.level}) {
      double one = 0;
      for (const ThreadRun& run : *runs) {
        if (run.threads == 1) one = run.seconds.p50;
      }
      for (const ThreadRun& run : *runs) {
        const double speedup = ratio(one, run.seconds.p50);
        t.add({grid_name(g.dims), runs == &g.convert ? "convert" : "level 0",
               Cell::integer(run.threads), value(run.seconds, 1, 3),
               range_text(run.seconds, 1, 3), Cell(speedup, 2),
               Cell(run.threads > 0 ? 100 * speedup / run.threads : 0, 0)});
      }
    }
  }
  t.notes = {"speed-up = median at 1 thread / median at this count; efficiency = speed-up / "
             "threads; the machine's cores are in the report's header"};
  return t;
}

Table ranks_table(const ScalingSuiteReport& r) {
  Table t;
  t.name = "scaling_ranks";
  t.title = "strielad-serve on MPI ranks against the threaded server: a cold cut and a scene change";
  t.columns = {"ranks",       "threads/rank", "extracting threads", "cut nodes",
               "first ms",    "50 % ms",      "100 % ms",           "100 % range ms",
               "scene change 100 % ms", "complete", "note"};
  for (const ServerScaling& s : r.servers) {
    const int workers = s.layout.ranks > 1 ? s.layout.ranks - 1 : 1;
    t.add({Cell::integer(s.layout.ranks), Cell::integer(s.layout.threads),
           Cell::integer(workers * s.layout.threads), Cell::integer(double(s.cut)),
           value(s.cold_first, 1000, 1), value(s.cold_half, 1000, 1), value(s.cold_all, 1000, 1),
           range_text(s.cold_all, 1000, 1), value(s.scene_all, 1000, 1),
           s.skipped.empty() ? fmt::format("{}/{}", s.complete, s.rounds) : std::string("-"),
           s.skipped.empty() ? (s.layout.ranks > 1 ? "mpirun --oversubscribe" : "threaded")
                             : s.skipped});
  }
  const std::string grid = r.grids.empty() ? "-" : grid_name(r.grids.front().dims);
  t.notes = {
      fmt::format("the smallest grid ({}); a fresh server per round, the store's pages evicted "
                  "before it starts; the client is the viewer's cut code over loopback with the "
                  "overview camera; clouds scene, then a scene change to rain in warm air and a "
                  "cold layer (warm brick cache)", grid),
      "under MPI rank 0 serves and ranks 1..N-1 extract, so 2 ranks extract on one rank; "
      "ranks beyond the cores share them (--oversubscribe): on a 2-core machine this measures "
      "the cost of the MPI path, not a speed-up",
  };
  return t;
}

Table subvolumes_table(const ScalingSuiteReport& r) {
  Table t;
  t.name = "scaling_subvolumes";
  t.title = "Cost against the number of sub-volumes in the scene (whole full-resolution level)";
  t.columns = {"sub-volumes", "median s", "range s",  "x one",   "s per sub-volume",
               "extracted",   "bricks",   "MB read",  "MB sent", "variables"};
  const double one = r.subvolumes.empty() ? 0 : r.subvolumes.front().seconds.p50;
  for (const SubvolumeScaling& s : r.subvolumes) {
    t.add({Cell::integer(s.count), value(s.seconds, 1, 3), range_text(s.seconds, 1, 3),
           Cell(ratio(s.seconds.p50, one), 2), Cell(ratio(s.seconds.p50, s.count), 3),
           Cell::integer(double(s.cost.extracted)), Cell::integer(double(s.cost.bricks)),
           Cell(s.cost.bytes_read / 1e6, 1), Cell(s.cost.bytes_sent / 1e6, 1),
           Cell::integer(double(s.cost.variables_read))});
  }
  const std::string grid = r.grids.empty() ? "-" : grid_name(r.grids.front().dims);
  t.notes = {fmt::format(
      "the smallest grid ({}), every level-0 node, {} thread(s); the scene holds the first N "
      "of: cloud water, cloud ice, rain in warm air, a cold layer, thick cloud in the west "
      "half, ice in cold air, drizzle in the south half, a freezing layer in a box; a node "
      "reads each variable's brick once for all its sub-volumes",
      grid, r.options.threads.empty() ? 0 : *std::max_element(r.options.threads.begin(),
                                                             r.options.threads.end()))};
  return t;
}

nlohmann::json spread_json(const Summary& s) {
  return {{"median", s.p50}, {"min", s.min}, {"max", s.max}, {"runs", s.count}};
}

nlohmann::json cost_json(const NodeBatchCost& c) {
  return {{"nodes", c.nodes},           {"extracted", c.extracted}, {"skipped", c.skipped},
          {"bricks", c.bricks},         {"bytes_read", c.bytes_read},
          {"bytes_sent", c.bytes_sent}, {"variables_read", c.variables_read}};
}

nlohmann::json runs_json(const std::vector<ThreadRun>& runs) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& r : runs) j.push_back({{"threads", r.threads}, {"seconds", spread_json(r.seconds)}});
  return j;
}

}  // namespace

std::vector<Table> scaling_tables(const ScalingSuiteReport& r) {
  if (r.grids.empty()) return {};
  return {grid_table(r), threads_table(r), ranks_table(r), subvolumes_table(r)};
}

nlohmann::json scaling_json(const ScalingSuiteReport& r, const std::vector<Table>& tables) {
  const auto& o = r.options;
  nlohmann::json j;
  j["suite"] = "scaling";
  j["command"] = o.command_line;
  j["machine"] = r.machine;
  j["seconds"] = r.seconds;
  j["options"] = {{"dims", {o.dims.x, o.dims.y, o.dims.z}},
                  {"fractions", o.fractions},
                  {"variables", o.variables},
                  {"brick", o.brick},
                  {"repeat", o.repeat},
                  {"threads", o.threads},
                  {"subvolume_counts", o.subvolume_counts},
                  {"server", o.server_binary.string()},
                  {"mpirun", o.mpirun.string()}};
  for (const auto& g : r.grids) {
    j["grids"].push_back({{"fraction", g.fraction},
                          {"dims", {g.dims.x, g.dims.y, g.dims.z}},
                          {"input_bytes", g.input_bytes},
                          {"store_bytes", g.store_bytes},
                          {"octree_nodes", g.octree_nodes},
                          {"leaves", g.leaves},
                          {"convert", runs_json(g.convert)},
                          {"level", runs_json(g.level)},
                          {"level_cost", cost_json(g.level_cost)},
                          {"cut_seconds", spread_json(g.cut_seconds)},
                          {"cut_cost", cost_json(g.cut_cost)}});
  }
  for (const auto& s : r.servers) {
    j["servers"].push_back({{"ranks", s.layout.ranks},
                            {"threads", s.layout.threads},
                            {"skipped", s.skipped},
                            {"cut", s.cut},
                            {"cold_first", spread_json(s.cold_first)},
                            {"cold_half", spread_json(s.cold_half)},
                            {"cold_all", spread_json(s.cold_all)},
                            {"scene_all", spread_json(s.scene_all)},
                            {"complete", s.complete},
                            {"rounds", s.rounds}});
  }
  for (const auto& s : r.subvolumes) {
    j["subvolumes"].push_back(
        {{"count", s.count}, {"seconds", spread_json(s.seconds)}, {"cost", cost_json(s.cost)}});
  }
  nlohmann::json t = nlohmann::json::object();
  for (const auto& table : tables) t[table.name] = table_json(table);
  j["tables"] = t;
  return j;
}

}  // namespace strielad::bench
