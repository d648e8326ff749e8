// SPDX-License-Identifier: Apache-2.0
// The structured-grid clip reference (vtk_structured_clip.h): the one translation unit that
// builds vtkStructuredGrid pipelines.
#include "peers/vtk_structured_clip.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkFeatureEdges.h>
#include <vtkFloatArray.h>
#include <vtkIntegrateAttributes.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStructuredGrid.h>
#include <vtkTableBasedClipDataSet.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "export/vtk_error_capture.h"

namespace strielad::peers {
namespace {

constexpr std::string_view kWho = "structured-grid clip reference";

std::string field_name(std::size_t field) { return fmt::format("f{}", field); }

void check_grid(const StructuredPoints& g, const std::vector<ScalarLimit>& limits) {
  std::size_t n = 1;
  for (std::size_t d : g.dims) {
    if (d < 2) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: dimensions {}x{}x{}, each must be >= 2",
                       kWho, g.dims[0], g.dims[1], g.dims[2]);
    }
    n *= d;
  }
  if (g.positions.size() != n) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: {} positions for {} points", kWho,
                     g.positions.size(), n);
  }
  for (std::size_t p = 0; p < n; ++p) {
    for (double c : g.positions[p]) {
      if (!std::isfinite(c)) {
        throw make_error(ErrorCode::kInvalidArgument, "{}: position of point {} is not finite",
                         kWho, p);
      }
    }
  }
  for (std::size_t f = 0; f < g.fields.size(); ++f) {
    if (g.fields[f].size() != n) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: field {} has {} values for {} points",
                       kWho, f, g.fields[f].size(), n);
    }
    for (double v : g.fields[f]) {
      if (!std::isfinite(v)) {
        throw make_error(ErrorCode::kInvalidArgument, "{}: field {} has a value that is not finite",
                         kWho, f);
      }
    }
  }
  if (limits.empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: no limit to clip by", kWho);
  }
  for (const ScalarLimit& l : limits) {
    if (l.field >= g.fields.size()) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: a limit names field {} of {}", kWho,
                       l.field, g.fields.size());
    }
    if ((l.min && std::isnan(*l.min)) || (l.max && std::isnan(*l.max)) ||
        (l.min && l.max && *l.min > *l.max)) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: the limit on field {} is [{}, {}]", kWho,
                       l.field, l.min.value_or(-INFINITY), l.max.value_or(INFINITY));
    }
  }
}

vtkSmartPointer<vtkStructuredGrid> make_grid(const StructuredPoints& g) {
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(int(g.dims[0]), int(g.dims[1]), int(g.dims[2]));
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(g.positions.size()));
  for (std::size_t p = 0; p < g.positions.size(); ++p) {
    points->SetPoint(vtkIdType(p), g.positions[p].data());
  }
  grid->SetPoints(points);
  for (std::size_t f = 0; f < g.fields.size(); ++f) {
    // float, as the store keeps samples; the limits are compared in double by the clip.
    vtkNew<vtkFloatArray> array;
    array->SetName(field_name(f).c_str());
    array->SetNumberOfTuples(vtkIdType(g.fields[f].size()));
    for (std::size_t p = 0; p < g.fields[f].size(); ++p) {
      array->SetValue(vtkIdType(p), static_cast<float>(g.fields[f][p]));
    }
    grid->GetPointData()->AddArray(array);
  }
  return grid;
}

// The sum of cell array `name` of vtkIntegrateAttributes' one-cell output (0 when the input
// had nothing of that dimension).
double integrated(vtkIntegrateAttributes* integrate, const char* name) {
  vtkUnstructuredGrid* out = integrate->GetOutput();
  vtkDataArray* a = out != nullptr ? out->GetCellData()->GetArray(name) : nullptr;
  return a != nullptr && a->GetNumberOfTuples() > 0 ? a->GetTuple1(0) : 0.0;
}

Mesh to_mesh(vtkPolyData* poly) {
  Mesh mesh;
  mesh.positions.resize(std::size_t(poly->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < poly->GetNumberOfPoints(); ++p) {
    poly->GetPoint(p, mesh.positions[std::size_t(p)].data());
  }
  mesh.normals.assign(mesh.positions.size(), {0, 0, 1});
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);) {
    if (count != 3) continue;
    mesh.triangles.push_back({std::uint32_t(ids[0]), std::uint32_t(ids[1]), std::uint32_t(ids[2])});
    mesh.face_kinds.push_back(FaceKind::kLimit);
  }
  return mesh;
}

}  // namespace

StructuredClipMeasures clip_structured_grid(const StructuredPoints& g,
                                            const std::vector<ScalarLimit>& limits) {
  check_grid(g, limits);
  vtkNew<vtk_support::ErrorCapture> errors;
  const auto throw_if_failed = [&] {
    if (errors->failed()) {
      throw make_error(ErrorCode::kInternal, "{}: VTK reported: {}", kWho, errors->message());
    }
  };
  const vtkSmartPointer<vtkStructuredGrid> grid = make_grid(g);
  vtkSmartPointer<vtkAlgorithm> last;  // the chain of clips, each reading the one before
  for (const ScalarLimit& limit : limits) {
    for (int side = 0; side < 2; ++side) {
      const std::optional<double>& bound = side == 0 ? limit.min : limit.max;
      if (!bound) continue;
      auto clip = vtkSmartPointer<vtkTableBasedClipDataSet>::New();
      errors->watch(clip);
      if (last) {
        clip->SetInputConnection(last->GetOutputPort());
      } else {
        clip->SetInputData(grid);
      }
      clip->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                   field_name(limit.field).c_str());
      clip->SetValue(*bound);
      clip->SetInsideOut(side == 1);  // min: keep >= min; max: keep <= max
      clip->GenerateClipScalarsOff();
      clip->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      last = clip;
    }
  }
  const vtkSmartPointer<vtkAlgorithm> clipped = last;
  clipped->Update();
  throw_if_failed();

  StructuredClipMeasures m;
  vtkDataSet* cells = vtkDataSet::SafeDownCast(clipped->GetOutputDataObject(0));
  m.cells = cells != nullptr ? std::uint64_t(cells->GetNumberOfCells()) : 0;
  if (m.cells == 0) return m;

  vtkNew<vtkIntegrateAttributes> volume;
  errors->watch(volume.Get());
  volume->SetInputConnection(clipped->GetOutputPort());
  volume->Update();
  throw_if_failed();
  m.volume = integrated(volume, "Volume");

  vtkNew<vtkDataSetSurfaceFilter> surface;
  errors->watch(surface.Get());
  surface->SetInputConnection(clipped->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  errors->watch(triangles.Get());
  triangles->SetInputConnection(surface->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  vtkNew<vtkIntegrateAttributes> area;
  errors->watch(area.Get());
  area->SetInputConnection(triangles->GetOutputPort());
  vtkNew<vtkFeatureEdges> edges;
  errors->watch(edges.Get());
  edges->SetInputConnection(triangles->GetOutputPort());
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOff();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  area->Update();
  edges->Update();
  throw_if_failed();
  m.surface_area = integrated(area, "Area");
  m.surface = to_mesh(triangles->GetOutput());
  m.boundary_edges = std::uint64_t(edges->GetOutput()->GetNumberOfLines());
  edges->BoundaryEdgesOff();
  edges->NonManifoldEdgesOn();
  edges->Update();
  throw_if_failed();
  m.non_manifold_edges = std::uint64_t(edges->GetOutput()->GetNumberOfLines());
  return m;
}

}  // namespace strielad::peers
