// SPDX-License-Identifier: Apache-2.0
// The STRIELAD paper's extraction pipeline, run with VTK 9.1 on one node's samples, and
// vtkFlyingEdges3D on the same samples: the references this project's kernel is tested
// and benchmarked against. VTK types stay inside vtk_paper_pipeline.cpp.
//
// Paper pipeline, per node and sub-volume:
//   samples -> vtkRectilinearGrid (axes as stored; a descending axis is mirrored into
//              ascending order, which is the same geometry)
//           -> per scalar limit, chained: vtkTableBasedClipDataSet by that field's
//              point scalars (min: keep >= min; max: InsideOut, keep <= max)
//           -> per side of the domain box that cuts the node: vtkTableBasedClipDataSet
//              by a vtkPlane (exact on a rectilinear lattice, unlike vtkBox distances)
//           -> vtkDataSetSurfaceFilter -> vtkTriangleFilter
//           -> vtkPolyDataNormals (point normals; consistency on; no auto-orient: the
//              surface filter already emits every face outward, from its cell, and
//              auto-orient would turn a cavity's wall (a shell's inside) the wrong
//              way; no splitting, so the surface stays one closed vertex-sharing mesh)
// Clips compute points in double precision (OutputPointsPrecision), matching Mesh.
// Normals are averages of the adjacent polygons' normals (not field gradients).
// The paper's ICON-LEM grid has a stretched height axis, so a vtkRectilinearGrid is what
// it needs; it is used for uniform axes too, to keep one code path.
//
// Missing samples. The paper's data had none; this project's rule is "fill/NaN samples
// are outside". VTK's clip would compare NaN as neither inside nor outside, so NaN samples
// of a field that has limits are replaced, in the copy given to VTK, by a value far
// outside the first of its limits (min - 1e6 (|min| + 1), or max + 1e6 (|max| + 1),
// peers/peer_input.h). A clip edge from a valid sample to a NaN sample is then cut
// about 1e-6 of a cell or less from the valid sample: the surface runs through the NaN
// sample's valid neighbours (NanPolicy::kFarOutside). NanPolicy::kDropCells instead removes every cell with a NaN
// corner first (vtkThreshold, all points valid), which is the strict reading of
// "trilinear interpolation of a NaN corner is NaN". ±Inf samples of limit fields are
// clamped to ±1e37 so that interpolation stays finite. Fields used only as attributes
// keep their NaN, which interpolates to NaN ("missing at that point").
//
// vtkFlyingEdges3D needs vtkImageData, i.e. uniform spacing: it runs in index space
// (origin 0, spacing 1) and every output point is then mapped to the real axes piecewise
// linearly (exact, since its vertices lie on lattice edges); normals are mapped with the
// inverse transpose of the local spacing.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "extract/extract_request.h"
#include "extract/node_samples.h"
#include "peers/peer_result.h"

namespace strielad::peers {

// One scalar limit: the region where min <= field <= max (either side may be open).
struct ScalarLimit {
  std::size_t field = 0;  // index into NodeSamples::fields
  std::optional<double> min{};
  std::optional<double> max{};
};

// An axis-aligned box in axis coordinates (the manifest's x, y, z); infinite sides are
// open. lo[a] <= hi[a] is required.
struct AxisBox {
  std::array<double, 3> lo{-std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()};
  std::array<double, 3> hi{std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::infinity()};
};

// The region of one sub-volume: every limit holds and the point is inside the domain.
struct PaperSubvolume {
  std::uint32_t id = 0;  // copied to Mesh::subvolume_id
  std::vector<ScalarLimit> limits;
  std::optional<AxisBox> domain;
};

enum class NanPolicy {
  kFarOutside,  // NaN replaced by a value far outside a limit (see above)
  kDropCells,   // cells with a NaN corner in a limit field removed before clipping
};

// A field carried to the mesh as a per-vertex attribute (interpolated by the clips).
struct AttributeField {
  std::string name;
  std::size_t field = 0;
};

struct PaperPipelineOptions {
  std::vector<AttributeField> attributes;
  NanPolicy nan_policy = NanPolicy::kFarOutside;
  // 1: VTK runs in a one-thread oneTBB arena (VTK 9.1's SMP backend here is TBB), giving
  // per-core figures; 0: the caller's arena (all cores); n: n.
  unsigned threads = 1;
  // Run vtkMassProperties and vtkFeatureEdges on the result (not timed).
  bool measure = true;
};

// Runs the paper pipeline. `seconds` covers building the vtkRectilinearGrid and running
// the filters up to the normals (not the conversion to Mesh nor the measures).
// face_kinds: kDomainBox for triangles whose three vertices lie on one side of the
// domain box (also where that side is on the node's face), else kNodeBoundary for those
// on one face of the node's lattice, else kLimit. Attributes of a limit's own field
// read the NaN replacement's interpolation near NaN samples. An empty region gives an
// empty mesh (closed == false).
// \error kInvalidArgument if the samples are malformed (an axis with fewer than 2
//        values or not strictly monotonic, a field of the wrong size), a field index is
//        out of range, a limit is NaN or has min > max, or the box has lo > hi or NaN.
// \error kInternal if a VTK filter reports an error (the message is VTK's).
PeerResult run_paper_pipeline(const NodeSamples& samples, const PaperSubvolume& subvolume,
                              const PaperPipelineOptions& options = {});

// The same for the kernel's request (extract/extract_request.h), so both run on one
// input: infinite limit bounds are open sides, the box is the domain when a side is
// finite, and attribute_fields/attribute_names replace options.attributes.
// \error kInvalidArgument also if attribute_fields and attribute_names differ in length.
PeerResult run_paper_pipeline(const NodeSamples& samples, const ExtractRequest& request,
                              PaperPipelineOptions options = {});

struct IsoSurfaceOptions {
  // As PaperPipelineOptions::threads.
  unsigned threads = 1;
};

// vtkFlyingEdges3D of field `field` at `iso` (`seconds`: building the vtkImageData and
// contouring, with gradient normals): an open iso-surface (cut off at the node's
// boundary). Triangles are counter-clockwise seen from the side of larger values and
// normals (from the field's gradient) point towards larger values, i.e. outward of the
// region field <= iso. NaN samples are replaced by a value far below iso (missing counts
// as "no cloud"); ±Inf clamped to ±1e37. face_kinds are all kLimit.
// \error kInvalidArgument as run_paper_pipeline, or if iso is not finite.
PeerResult run_flying_edges(const NodeSamples& samples, std::size_t field, double iso,
                            const IsoSurfaceOptions& options = {});

}  // namespace strielad::peers
