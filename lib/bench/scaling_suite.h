// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench scaling` suite ("Scaling"): how cost grows
//  - with the grid: generated time steps of a quarter, half and the whole of a full grid
//    (the paper's 1429 x 1556 x 150 by default; the horizontal axes scaled alike), each
//    converted, then its full-resolution level and one view's LOD cut extracted;
//  - with threads: conversion and whole-level extraction at 1 and 2 threads;
//  - with MPI ranks: strielad-serve under mpirun (1 to 3 ranks, --oversubscribe) against
//    the threaded server, the time until a cold cut and a scene change are complete;
//  - with the number of sub-volumes in a scene (1, 2, 4, 8) on the smallest grid.
// Every figure is the median of repeated runs with the minimum and maximum beside it.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/latency_stats.h"
#include "bench/node_batch.h"
#include "bench/table_writer.h"
#include "convert/converter.h"
#include "grid/axis.h"

namespace strielad::bench {

struct ServerLayout {
  int ranks = 1;    // 1: the threaded server without mpirun
  int threads = 1;  // --threads of every rank
};

struct ScalingSuiteOptions {
  Dims3 dims{1429, 1556, 150};  // the whole grid; the others are fractions of its cells
  std::vector<double> fractions{0.25, 0.5, 1.0};
  std::vector<std::string> variables{"clw", "cli", "qr", "ta"};
  std::uint64_t seed = 1;
  std::filesystem::path work = "/tmp/strielad-bench-scaling";
  std::uint32_t brick = build::kDefaultBrick;
  int repeat = 3;
  std::vector<int> threads{1, 2};
  std::vector<int> subvolume_counts{1, 2, 4, 8};
  // Server rows need strielad-serve; rows with ranks > 1 need mpirun too. A layout that
  // cannot run is reported as such, not dropped silently.
  std::filesystem::path server_binary;
  std::filesystem::path mpirun;
  std::vector<ServerLayout> layouts{{1, 1}, {1, 2}, {2, 2}, {3, 1}, {3, 2}};
  std::uint64_t cache_mib = 1024;
  double aspect = 16.0 / 9.0;
  std::string command_line;
};

// A small grid, one round: seconds, for CI (checks the harness, not the figures).
ScalingSuiteOptions quick_scaling_options(ScalingSuiteOptions base);

// The grid of `fraction` of the cells of `full`: both horizontal axes scaled by its
// square root (rounded), the vertical axis kept.
Dims3 fraction_of_grid(Dims3 full, double fraction);

struct ThreadRun {
  int threads = 0;
  Summary seconds;
};

struct GridScaling {
  double fraction = 0;
  Dims3 dims;
  std::uint64_t input_bytes = 0;
  std::uint64_t store_bytes = 0;
  std::size_t octree_nodes = 0, leaves = 0;
  std::vector<ThreadRun> convert;  // per thread count
  std::vector<ThreadRun> level;    // whole level 0, per thread count
  NodeBatchCost level_cost;        // of the last level run
  Summary cut_seconds;              // the overview camera's cut, all threads of the list's max
  NodeBatchCost cut_cost;
};

struct ServerScaling {
  ServerLayout layout;
  std::string skipped;  // why the layout did not run; empty when it ran
  std::size_t cut = 0;
  Summary cold_first, cold_half, cold_all;  // seconds after the request, cold start
  Summary scene_all;                        // a scene change on the warm server
  int complete = 0, rounds = 0;            // rounds whose cuts all completed
};

struct SubvolumeScaling {
  int count = 0;
  Summary seconds;  // whole level 0, all threads of the list's max
  NodeBatchCost cost;
};

struct ScalingSuiteReport {
  ScalingSuiteOptions options;
  std::vector<GridScaling> grids;
  std::vector<ServerScaling> servers;
  std::vector<SubvolumeScaling> subvolumes;
  nlohmann::json machine;
  double seconds = 0;
};

// \error what generating, converting, serving or extracting throws.
ScalingSuiteReport run_scaling_suite(const ScalingSuiteOptions& options);

std::vector<Table> scaling_tables(const ScalingSuiteReport& report);
nlohmann::json scaling_json(const ScalingSuiteReport& report, const std::vector<Table>& tables);

}  // namespace strielad::bench
