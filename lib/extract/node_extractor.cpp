// SPDX-License-Identifier: Apache-2.0
#include "extract/node_extractor.h"

#include "core/error.h"
#include "extract/cell_kernel.h"
#include "extract/cell_sweep.h"
#include "extract/collapsed_triangles.h"
#include "extract/collinear_slivers.h"
#include "extract/conditions.h"
#include "extract/lattice_to_axis.h"

namespace strielad {

namespace {

void check_attribute_fields(const NodeSamples& samples, const ExtractRequest& request) {
  if (request.attribute_fields.size() != request.attribute_names.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sub-volume {}: {} attribute fields but {} names", request.subvolume_id,
                     request.attribute_fields.size(), request.attribute_names.size());
  }
  for (std::uint32_t f : request.attribute_fields) {
    if (f >= samples.fields.size() || samples.fields[f].size() != samples.sample_count()) {
      throw make_error(ErrorCode::kInvalidArgument, "sub-volume {}: attribute field {} missing",
                       request.subvolume_id, f);
    }
  }
}

// Vertices the lattice keeps apart but axis coordinates merge, and sheets without
// volume: where a limit has min = max, or surfaces pass through samples
// (`corner_crossings` of the extraction).
void remove_degenerate_triangles(const ExtractRequest& request, std::uint64_t corner_crossings,
                                 bool rounded_onto_sample, bool clipped, Mesh& mesh) {
  bool equal_bounds = false;
  for (const ExtractLimit& limit : request.limits) equal_bounds = equal_bounds || limit.min == limit.max;
  const bool sheets = equal_bounds || corner_crossings != 0;
  // The general clipper's points on the line where two conditions meet (two box planes:
  // a domain box's vertical edge) come from different lattice elements and can differ by
  // an ulp on the lattice while mapping to one axis position (54 zero-area triangles on a
  // box with a limit over three axes at level 1, robustness case box-on-integer-hpa).
  if (sheets || rounded_onto_sample || clipped) remove_collapsed_triangles(mesh, sheets);
  // Rounding onto samples, and the clipper's points along such a line, can also leave three
  // distinct vertices on one line.
  if (rounded_onto_sample || clipped) split_collinear_slivers(mesh);
}

}  // namespace

Mesh extract_node_mesh(const NodeSamples& samples, const ExtractRequest& request, NodeMeshScratch& scratch,
                       ExtractStats* stats) {
  const auto dims = samples.dims();
  ConditionSet& set = scratch.set;
  build_conditions(samples, request, set);
  check_attribute_fields(samples, request);
  Mesh mesh;
  mesh.subvolume_id = request.subvolume_id;
  mesh.attribute_names = request.attribute_names;
  mesh.attributes.resize(request.attribute_fields.size());
  ExtractStats local;
  local.cells = (dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1);
  local.conditions = set.conditions.size();
  local.empty_by_condition = set.empty;
  if (set.empty) {
    if (stats) *stats = local;
    return mesh;
  }

  const auto side_group = static_cast<std::uint32_t>(set.conditions.size());  // + 2 * axis + side
  scratch.begin(samples.sample_count(), dims);
  CellKernel kernel(scratch, set, dims, side_group);
  sweep_cells(set, dims, scratch, kernel, local);
  kernel.inside_rectangles(request.merge_face_squares);

  const bool clipped = local.clipped_tets > 0;
  const bool rounded_onto_sample =
      lattice_mesh_to_axis(samples, set, request.attribute_fields, clipped, request.axis_normals,
                           scratch, mesh);
  remove_degenerate_triangles(request, scratch.corner_crossings, rounded_onto_sample, clipped, mesh);
  if (stats) *stats = local;
  return mesh;
}

Mesh extract_node_mesh(const NodeSamples& samples, const ExtractRequest& request, ExtractStats* stats) {
  return extract_node_mesh(samples, request, this_thread_scratch().mesh, stats);
}

}  // namespace strielad
