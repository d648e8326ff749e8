// SPDX-License-Identifier: Apache-2.0
// What to extract from one node: one sub-volume (the intersection of scalar limits
// and an axis-aligned domain box) and the attributes its vertices carry
// (formats/scene.md, "Extraction").
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace strielad {

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

// min <= value <= max on the interpolated field of NodeSamples::fields[field]; an
// infinite bound is open.
struct ExtractLimit {
  std::uint32_t field = 0;
  double min = -kUnbounded;
  double max = kUnbounded;
};

struct ExtractRequest {
  std::uint32_t subvolume_id = 0;
  std::vector<ExtractLimit> limits;
  // Domain box per axis x, y, z in axis coordinates, {lo, hi} with lo <= hi whatever
  // the axis direction; infinite = unbounded.
  std::array<std::array<double, 2>, 3> box{{{-kUnbounded, kUnbounded},
                                            {-kUnbounded, kUnbounded},
                                            {-kUnbounded, kUnbounded}}};
  // Further half-space conditions given per sample (NodeSamples order, x fastest; inside
  // where >= 0), bounding the region like the box: a geographic box on a mapped grid
  // (extract/geographic_conditions.h). Their faces are domain-box faces.
  std::vector<std::vector<double>> sample_conditions;
  // Whole cell squares of the node's faces merged into rectangles (fewer triangles);
  // false keeps one square per cell, for output frames that are not affine on the grid
  // (geocentric, or through a map projection), where a rectangle's long edges would
  // become chords far from the curved face.
  bool merge_face_squares = true;
  // Unit normals in axis coordinates (a condition's gradient, a side's fixed normal);
  // false for a caller that replaces every normal (an output frame placing vertices by
  // a field: FrameTransform::replaces_normals()), which spares their cost: the mesh then
  // carries +z for each.
  bool axis_normals = true;
  std::vector<std::uint32_t> attribute_fields;  // indices into NodeSamples::fields
  std::vector<std::string> attribute_names;     // same length as attribute_fields
};

// What the kernel did for one node (for --json output and the benchmarks).
struct ExtractStats {
  std::uint64_t cells = 0;          // cells of the node
  std::uint64_t inside_cells = 0;   // cells wholly inside the region
  std::uint64_t cut_cells = 0;      // cells the region's boundary passes through
  std::uint64_t table_cells = 0;    // cut cells crossed by one condition (loops by table)
  std::uint64_t simple_tets = 0;    // tetrahedra of the other cut cells crossed by one condition
  std::uint64_t clipped_tets = 0;   // tetrahedra clipped by the general polytope clipper
  std::uint64_t conditions = 0;     // half-space conditions left after trivial ones
  bool empty_by_condition = false;  // some condition excludes the whole node
  friend bool operator==(const ExtractStats&, const ExtractStats&) = default;
};

}  // namespace strielad
