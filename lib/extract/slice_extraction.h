// SPDX-License-Identifier: Apache-2.0
// Slices inside one octree node (formats/scene.md, "Slices"): the part of an
// axis-aligned plane or of a variable's iso-level that lies in the node's box, as a
// triangle mesh at the node's own resolution, so that slices get the same level of
// detail as sub-volumes. Each vertex carries the colouring variable's field there.
//
// Axis planes: the plane meets the node's sample lattice in a grid whose vertices are
// the node's sample coordinates along the two other axes and exactly the plane's
// value along its own; two triangles per grid cell. The value at a vertex is the
// linear interpolation between the two sample planes around it (the trilinear field
// there): exactly the sample when the plane passes through a sample plane, NaN when a
// sample it uses is missing. Neighbouring nodes share their boundary samples, so their
// slices share the boundary vertices bit for bit: no cracks. A plane on the face
// between two nodes is drawn once, by the node it is the lower face of (the node whose
// upper face it is skips it), or by the last node when it is the grid's edge.
//
// Iso-levels: the sub-volume kernel's region {level variable >= value} (node_extractor.h),
// of which only the limit faces (on the iso-surface) are kept; the kernel's crossings
// are canonical, so neighbouring nodes' surfaces meet without cracks. Where the level
// variable is missing the surface stops short: triangles with a vertex in a cell
// touching a missing sample are left out (the kernel's faces along missing data
// too). Normals are the field's gradient, pointing to decreasing values (for a
// pressure level: up).
#pragma once

#include <cstdint>
#include <string>

#include "extract/mesh.h"
#include "extract/node_extraction.h"
#include "extract/node_mesh_scratch.h"
#include "extract/node_samples.h"
#include "scene/scene.h"

namespace strielad {

class Store;

struct SliceRequest {
  std::uint32_t slice_id = 0;
  int axis = -1;                   // 0..2: the plane coords[axis] = value; -1: iso-level
  std::uint32_t level_field = 0;   // iso-level: index into NodeSamples::fields
  double value = 0;                // the plane's coordinate, or the level's value
  std::uint32_t colour_field = 0;  // index into NodeSamples::fields
  std::string colour_name{};       // the mesh's one attribute name
};

// The slice's mesh in the node (face kind kSlice only, one attribute; empty when the
// plane or level misses the node). Axis planes are drawn when the plane lies within the
// node's lattice (boundaries included: skipping a shared face is skip_slice's job).
// \error kInvalidArgument for a field index or axis the samples do not have. An
// iso-level works in `scratch` (extract_node_mesh).
Mesh extract_slice_mesh(const NodeSamples& samples, const SliceRequest& request,
                        NodeMeshScratch& scratch);

// The same in this thread's scratch (this_thread_scratch()).
Mesh extract_slice_mesh(const NodeSamples& samples, const SliceRequest& request);

// Whether the slice can be decided without reading bricks, from the node's sample
// coordinates and the index entries of its variables: fills `result` (id, outcome,
// reason) and returns true when it is skipped; returns false (result's id set) when the
// slice must be extracted. No brick is read either way.
bool skip_slice(const Store& store, const ResolvedSlice& slice, std::uint32_t step,
                const NodeGeometry& geometry, NodeId node, SliceResult& result);

// The value of `field` at lattice position `p` (fractional sample indices), trilinear
// in the cell holding p (clamped to the node): corners of weight 0 are not used, so a
// sample point gives the sample exactly and a missing sample only matters where it
// contributes (NaN then).
double field_at_lattice(const NodeSamples& samples, std::uint32_t field,
                        const std::array<double, 3>& p);

}  // namespace strielad
