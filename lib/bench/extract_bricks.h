// SPDX-License-Identifier: Apache-2.0
// Per-brick extraction comparison of `strielad-bench extract`: level-0 nodes of a store
// whose value range straddles a case's threshold, each node's samples loaded once into
// NodeSamples, then this project's kernel (extract_node_mesh), the paper's VTK clip
// pipeline, vtkFlyingEdges3D and OpenVDB volumeToMesh run on the very same samples, one
// thread each, taking turns, several rounds per brick.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "extract/extract_request.h"
#include "extract/node_samples.h"
#include "octree/octree_layout.h"

namespace strielad {
class Store;
}

namespace strielad::bench {

// One scalar limit of a case: min <= var <= max (an infinite bound is open).
struct CaseLimit {
  std::string var;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

// A sub-volume measured on bricks (and over levels): its limits; bricks are level-0
// nodes whose exact [min, max] from the store's index straddles the finite bound of
// limits[select] (min < bound < max), so that limit really cuts them.
struct ExtractCase {
  std::string name;   // short key, e.g. "cloud"
  std::string label;  // e.g. "clw >= 1e-05"
  std::vector<CaseLimit> limits;
  std::size_t select = 0;
  bool one_limit() const { return limits.size() == 1; }
  // The finite bound of limits[select] (min if finite, else max).
  double threshold() const;
};

// cloud: clw >= 1e-5; dense: ta <= 260 (the generator's 260 K surface is a sheet at about
// 4.3 km that crosses every column); three: clw >= 1e-5, ta <= 273.15, ua >= 0 on nodes
// that clw cuts.
std::vector<ExtractCase> default_brick_cases();
// cloud and dense.
std::vector<ExtractCase> default_level_cases();

// "clw >= 1e-05 and ta <= 273.15".
std::string case_label(const std::vector<CaseLimit>& limits);

inline constexpr int kReferenceSubsamples = 8;

inline constexpr const char* kKernel = "strielad kernel";
inline constexpr const char* kPaper = "paper VTK pipeline";
inline constexpr const char* kFlyingEdges = "vtkFlyingEdges3D";
inline constexpr const char* kOpenVdb = "OpenVDB volumeToMesh";

// One brick: per contender (BrickGroup::contenders order) the median of the rounds and
// what the first round produced.
struct BrickRun {
  NodeId node = 0;
  std::uint64_t cells = 0;      // (nx-1)(ny-1)(nz-1)
  double node_volume = 0;       // of the node's box, in axis units (for per-brick errors)
  std::vector<double> seconds;  // median over rounds
  // The same on the same brick with nothing to extract (the case's field set to one
  // value outside the region: see no_surface_samples), for the kernel and
  // vtkFlyingEdges3D on one-limit cases; NaN for the other contenders. What a contender
  // costs before it makes a triangle (FlyingEdges: building its vtkImageData and
  // classifying every edge).
  std::vector<double> no_surface_seconds;
  std::vector<std::vector<double>> rounds;  // every round's seconds
  std::vector<std::uint64_t> triangles;
  std::vector<std::uint64_t> limit_triangles;  // on the limit surface (no node faces)
  // Enclosed volume in axis units; NaN where the contender's surface cannot be closed
  // (OpenVDB: half a cell short of the node's faces). vtkFlyingEdges3D's open
  // iso-surface is closed with the paper pipeline's node-face triangles.
  std::vector<double> volume;
  // The exact region's volume (every limit on the trilinearly interpolated field, the
  // issue's definition), by the midpoint rule on kReferenceSubsamples^3 points per cut
  // cell; cells whose corners are all inside or all outside count exactly (a trilinear
  // field's extremes over a cell are at its corners).
  double reference_volume = 0;
  bool kernel_clean = false;  // check_mesh(kernel mesh).clean()
  ExtractStats kernel_stats;
};

struct BrickGroup {
  ExtractCase extract_case;
  std::uint32_t brick = 0;
  std::vector<std::string> contenders;  // kernel first, then the paper pipeline, ...
  std::size_t candidates = 0;           // full-size level-0 nodes the threshold cuts
  std::vector<BrickRun> runs;           // in node order
  int repeat = 0;
  double seconds = 0;  // wall time of the whole group

  std::size_t index_of(std::string_view contender) const;  // npos when absent
};

struct BrickGroupOptions {
  std::size_t bricks = 200;
  int repeat = 5;
  std::uint64_t seed = 42;
  bool openvdb = true;
};

// `samples` with field `field` set to one value on the far side of `iso` from the region
// (region_is_above: the region is field >= iso), so that no cell is cut and nothing is
// inside.
NodeSamples no_surface_samples(const NodeSamples& samples, std::size_t field, double iso,
                               bool region_is_above);

// The volume of the region where every limit of `request` holds on the trilinear
// interpolant of the samples (missing samples: outside), by the midpoint rule on
// subsamples^3 points per cell that the region's boundary may cross.
double trilinear_region_volume(const NodeSamples& samples, const ExtractRequest& request,
                               int subsamples);

// Picks the bricks (only full (B+1)^3 nodes, so every brick of a group costs the same
// cells) and measures them. \error kNotFound for a case variable the store lacks.
BrickGroup run_brick_group(const Store& store, const ExtractCase& extract_case,
                           const BrickGroupOptions& options);

}  // namespace strielad::bench
