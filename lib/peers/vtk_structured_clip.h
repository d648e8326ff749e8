// SPDX-License-Identifier: Apache-2.0
// A reference for regions on bent lattices (terrain-following levels, curvilinear grids),
// measured by VTK alone: the samples as a vtkStructuredGrid whose points are their true
// positions in whatever frame the caller chose, the region that scalar limits select cut
// out of it by VTK's clip tables, and its volume and boundary area as VTK integrates them.
// VTK types stay inside vtk_structured_clip.cpp.
//
//   points and point fields -> vtkStructuredGrid (double points, float scalars)
//     -> per bound of every limit, chained: vtkTableBasedClipDataSet by that field's
//        point scalars (min: keep >= min; max: InsideOut, keep <= max), double points
//     -> vtkIntegrateAttributes: the clipped cells' volume
//     -> vtkDataSetSurfaceFilter -> vtkTriangleFilter: their outer surface as a Mesh
//        (faces outward from their cells), whose area vtkIntegrateAttributes integrates
//        and whose open and non-manifold edges vtkFeatureEdges counts.
// A box in the lattice's own coordinates (a longitude range, a level range) is a limit on
// a field holding that coordinate at every point: its faces are then exactly where the
// lattice's edges reach the bound, as the clip interpolates linearly along edges.
//
// VTK cuts each cell by its own tables and integrates a hexahedron's volume over its
// triangulation into tetrahedra: on a bent lattice (non-planar cell faces) this is one
// piecewise-linear reading of the region, not the only one, so other extractions of the
// same samples differ from it by the cells' twist.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "extract/mesh.h"
#include "peers/vtk_paper_pipeline.h"

namespace strielad::peers {

// ni x nj x nk points, i fastest, then j, then k. The lattice should be right-handed in the
// frame (i, j, k along east, north, up, say) so that VTK's cells have positive volume and
// the surface faces point outward.
struct StructuredPoints {
  std::array<std::size_t, 3> dims{};
  std::vector<std::array<double, 3>> positions;
  std::vector<std::vector<double>> fields;  // one value per point each
};

struct StructuredClipMeasures {
  double volume = 0;        // of the clipped cells, in the positions' units cubed
  double surface_area = 0;  // of their outer surface
  Mesh surface;             // that surface: triangles, positions (normals all +z)
  std::uint64_t cells = 0;  // cells the clips left
  // Edges of `surface` used by one triangle, and by more than two (vtkFeatureEdges).
  std::uint64_t boundary_edges = 0, non_manifold_edges = 0;
};

// \error kInvalidArgument when `limits` is empty, a dimension is below 2, the positions or
// a field do not have one entry per point, a limit names no field, is NaN or has
// min > max, or a field value or position is not finite.
// \error kInternal if a VTK filter reports an error (the message is VTK's).
StructuredClipMeasures clip_structured_grid(const StructuredPoints& grid,
                                            const std::vector<ScalarLimit>& limits);

}  // namespace strielad::peers
