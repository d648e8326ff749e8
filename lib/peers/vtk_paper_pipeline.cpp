// SPDX-License-Identifier: Apache-2.0
// The library's only translation unit running VTK filters (the .vtp writer and reader
// are in lib/export). See vtk_paper_pipeline.h for the pipeline and its conventions.
#include "peers/vtk_paper_pipeline.h"

#include <tbb/task_arena.h>
#include <vtkCellArray.h>
#include <vtkDataObject.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFeatureEdges.h>
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkTableBasedClipDataSet.h>
#include <vtkThreshold.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string>

#include "core/error.h"
#include "export/vtk_error_capture.h"
#include "extract/mesh_metrics.h"
#include "peers/peer_mesh.h"
#include "peers/peer_input.h"

namespace strielad::peers {
namespace {

constexpr std::string_view kPaperWho = "paper pipeline";
constexpr std::string_view kFlyingEdgesWho = "vtkFlyingEdges3D peer";

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs `f` in a oneTBB arena of `threads` threads (0: the caller's arena). VTK 9.1's SMP
// backend is oneTBB, whose parallel loops stay inside the arena they are called from.
template <typename F>
auto run_in_arena(unsigned threads, F&& f) {
  if (threads == 0) return f();
  tbb::task_arena arena(static_cast<int>(threads), threads == 1 ? 1 : 0);
  return arena.execute(f);
}

std::uint64_t lattice_cells(const NodeSamples& s) {
  const auto d = s.dims();
  return std::uint64_t(d[0] - 1) * (d[1] - 1) * (d[2] - 1);
}

// fmt, not operator+: GCC 12 at -O3 warns falsely (-Wrestrict, PR 105651) on the latter.
std::string field_array_name(std::size_t field) { return fmt::format("f{}", field); }

void throw_if_failed(const vtk_support::ErrorCapture& errors, std::string_view who) {
  if (errors.failed()) {
    throw make_error(ErrorCode::kInternal, "{}: VTK reported: {}", who, errors.message());
  }
}

void check_subvolume(const NodeSamples& samples, const PaperSubvolume& sv,
                     const PaperPipelineOptions& options) {
  check_node_samples(samples, kPaperWho);
  for (const auto& limit : sv.limits) {
    check_field_index(samples, limit.field, kPaperWho);
    if ((limit.min && std::isnan(*limit.min)) || (limit.max && std::isnan(*limit.max))) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: limit on field {} is NaN", kPaperWho,
                       limit.field);
    }
    if (limit.min && limit.max && *limit.min > *limit.max) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: limit on field {} has min {} > max {}",
                       kPaperWho, limit.field, *limit.min, *limit.max);
    }
  }
  if (sv.domain) {
    for (int a = 0; a < 3; ++a) {
      if (std::isnan(sv.domain->lo[a]) || std::isnan(sv.domain->hi[a]) ||
          sv.domain->lo[a] > sv.domain->hi[a]) {
        throw make_error(ErrorCode::kInvalidArgument, "{}: domain box axis {} is [{}, {}]",
                         kPaperWho, a, sv.domain->lo[a], sv.domain->hi[a]);
      }
    }
  }
  for (const auto& attribute : options.attributes) {
    check_field_index(samples, attribute.field, kPaperWho);
  }
}

// The value NaN samples of `field` become: far outside the first limit on that field.
// NaN when the field has no limit (an attribute keeps its NaN).
float nan_replacement(const PaperSubvolume& sv, std::size_t field) {
  for (const auto& limit : sv.limits) {
    if (limit.field != field) continue;
    if (limit.min) return static_cast<float>(far_below(*limit.min));
    if (limit.max) return static_cast<float>(far_above(*limit.max));
  }
  return std::numeric_limits<float>::quiet_NaN();
}

// The node's samples as a vtkRectilinearGrid with ascending coordinates: a descending
// axis is mirrored (coordinates and samples reversed), which is the same geometry and
// keeps VTK's cells positively oriented so that surface faces point outward.
vtkSmartPointer<vtkRectilinearGrid> make_rectilinear_grid(
    const NodeSamples& samples, const std::vector<std::size_t>& fields,
    const std::vector<float>& nan_values, bool add_valid_mask) {
  const auto dims = samples.dims();
  std::array<bool, 3> flip{};
  auto grid = vtkSmartPointer<vtkRectilinearGrid>::New();
  grid->SetDimensions(int(dims[0]), int(dims[1]), int(dims[2]));
  for (int a = 0; a < 3; ++a) {
    const auto& c = samples.coords[a];
    flip[a] = c[1] < c[0];
    vtkNew<vtkDoubleArray> coords;
    coords->SetNumberOfTuples(vtkIdType(c.size()));
    for (std::size_t i = 0; i < c.size(); ++i) {
      coords->SetValue(vtkIdType(i), flip[a] ? c[c.size() - 1 - i] : c[i]);
    }
    if (a == 0) grid->SetXCoordinates(coords);
    if (a == 1) grid->SetYCoordinates(coords);
    if (a == 2) grid->SetZCoordinates(coords);
  }
  const std::size_t n = samples.sample_count();
  // Source index of VTK point `p`, which is x fastest in ascending order.
  std::vector<std::size_t> source(n);
  {
    std::size_t p = 0;
    for (std::size_t k = 0; k < dims[2]; ++k) {
      const std::size_t sk = flip[2] ? dims[2] - 1 - k : k;
      for (std::size_t j = 0; j < dims[1]; ++j) {
        const std::size_t sj = flip[1] ? dims[1] - 1 - j : j;
        const std::size_t row = (sk * dims[1] + sj) * dims[0];
        for (std::size_t i = 0; i < dims[0]; ++i) {
          source[p++] = row + (flip[0] ? dims[0] - 1 - i : i);
        }
      }
    }
  }
  vtkNew<vtkFloatArray> valid;
  if (add_valid_mask) {
    valid->SetName("strielad_valid");
    valid->SetNumberOfTuples(vtkIdType(n));
    valid->FillValue(1.0f);
  }
  for (std::size_t fi = 0; fi < fields.size(); ++fi) {
    const auto& values = samples.fields[fields[fi]];
    const float nan_value = nan_values[fi];
    const bool is_limit_field = !std::isnan(nan_value);
    vtkNew<vtkFloatArray> array;
    array->SetName(field_array_name(fields[fi]).c_str());
    array->SetNumberOfTuples(vtkIdType(n));
    float* out = array->GetPointer(0);
    for (std::size_t p = 0; p < n; ++p) {
      const float v = values[source[p]];
      out[p] = sanitize_sample(v, nan_value);
      if (add_valid_mask && is_limit_field && std::isnan(v)) valid->SetValue(vtkIdType(p), 0.0f);
    }
    grid->GetPointData()->AddArray(array);
  }
  if (add_valid_mask) grid->GetPointData()->AddArray(valid);
  return grid;
}

// Converts a triangulated vtkPolyData to a Mesh (positions as VTK computed them).
Mesh to_mesh(vtkPolyData* poly, const std::vector<AttributeField>& attributes) {
  Mesh mesh;
  const vtkIdType np = poly->GetNumberOfPoints();
  mesh.positions.resize(std::size_t(np));
  for (vtkIdType p = 0; p < np; ++p) {
    poly->GetPoint(p, mesh.positions[std::size_t(p)].data());
  }
  if (vtkDataArray* normals = poly->GetPointData()->GetNormals()) {
    mesh.normals.resize(std::size_t(np));
    for (vtkIdType p = 0; p < np; ++p) {
      double n[3];
      normals->GetTuple(p, n);
      mesh.normals[std::size_t(p)] = {float(n[0]), float(n[1]), float(n[2])};
    }
  }
  vtkCellArray* polys = poly->GetPolys();
  mesh.triangles.reserve(std::size_t(polys->GetNumberOfCells()));
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);) {
    if (count != 3) continue;  // vtkTriangleFilter / FlyingEdges give triangles only
    mesh.triangles.push_back(
        {std::uint32_t(ids[0]), std::uint32_t(ids[1]), std::uint32_t(ids[2])});
  }
  mesh.face_kinds.assign(mesh.triangles.size(), FaceKind::kLimit);
  for (const auto& attribute : attributes) {
    mesh.attribute_names.push_back(attribute.name);
    std::vector<float> values(std::size_t(np), std::numeric_limits<float>::quiet_NaN());
    if (vtkDataArray* array =
            poly->GetPointData()->GetArray(field_array_name(attribute.field).c_str())) {
      for (vtkIdType p = 0; p < np; ++p) values[std::size_t(p)] = float(array->GetTuple1(p));
    }
    mesh.attributes.push_back(std::move(values));
  }
  return mesh;
}

// True when all three vertices of `t` have coordinate `value` on axis `a` (within tol).
bool triangle_on_plane(const Mesh& mesh, const std::array<std::uint32_t, 3>& t, int a,
                       double value, double tol) {
  for (std::uint32_t v : t) {
    if (!(std::abs(mesh.positions[v][a] - value) <= tol)) return false;
  }
  return true;
}

// `float_points`: VTK computed the positions in float (else double).
void classify_faces(Mesh& mesh, const NodeSamples& samples, const std::optional<AxisBox>& box,
                    bool float_points) {
  std::array<double, 3> lo{}, hi{}, tol{};
  for (int a = 0; a < 3; ++a) {
    const auto& c = samples.coords[a];
    lo[a] = std::min(c.front(), c.back());
    hi[a] = std::max(c.front(), c.back());
    // Points on one plane agree to the rounding of VTK's point type.
    const double eps = float_points ? 4.0 * std::numeric_limits<float>::epsilon() : 1e-12;
    tol[a] = eps * (std::max(std::abs(lo[a]), std::abs(hi[a])) + (hi[a] - lo[a]));
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    FaceKind kind = FaceKind::kLimit;
    for (int a = 0; a < 3 && kind == FaceKind::kLimit; ++a) {
      // A box side on the node's face is a domain face: the neighbour has nothing there.
      if (box && std::isfinite(box->lo[a]) && triangle_on_plane(mesh, tri, a, box->lo[a], tol[a]))
        kind = FaceKind::kDomainBox;
      else if (box && std::isfinite(box->hi[a]) &&
               triangle_on_plane(mesh, tri, a, box->hi[a], tol[a]))
        kind = FaceKind::kDomainBox;
    }
    for (int a = 0; a < 3 && kind == FaceKind::kLimit; ++a) {
      if (triangle_on_plane(mesh, tri, a, lo[a], tol[a]) ||
          triangle_on_plane(mesh, tri, a, hi[a], tol[a]))
        kind = FaceKind::kNodeBoundary;
    }
    mesh.face_kinds[t] = kind;
  }
}

void measure_with_vtk(vtkPolyData* surface, PeerResult& result,
                      vtk_support::ErrorCapture& errors) {
  vtkNew<vtkMassProperties> mass;
  errors.watch(mass);
  mass->SetInputData(surface);
  mass->Update();
  result.mass_properties_volume = mass->GetVolume();
  vtkNew<vtkFeatureEdges> boundary;
  errors.watch(boundary);
  boundary->SetInputData(surface);
  boundary->BoundaryEdgesOn();
  boundary->NonManifoldEdgesOff();
  boundary->FeatureEdgesOff();
  boundary->ManifoldEdgesOff();
  boundary->Update();
  result.boundary_edges = std::uint64_t(boundary->GetOutput()->GetNumberOfLines());
  vtkNew<vtkFeatureEdges> non_manifold;
  errors.watch(non_manifold);
  non_manifold->SetInputData(surface);
  non_manifold->BoundaryEdgesOff();
  non_manifold->NonManifoldEdgesOn();
  non_manifold->FeatureEdgesOff();
  non_manifold->ManifoldEdgesOff();
  non_manifold->Update();
  result.non_manifold_edges = std::uint64_t(non_manifold->GetOutput()->GetNumberOfLines());
}

// The fields VTK needs (those with limits, then attributes), each with the value its NaN
// samples become (NaN: kept), and whether a limit's field has a NaN to replace.
struct VtkFields {
  std::vector<std::size_t> fields;
  std::vector<float> nan_values;
  bool limit_field_has_nan = false;
};

VtkFields vtk_fields(const NodeSamples& samples, const PaperSubvolume& sv,
                     const PaperPipelineOptions& options) {
  VtkFields out;
  auto add_field = [&](std::size_t f) {
    if (std::find(out.fields.begin(), out.fields.end(), f) == out.fields.end()) {
      out.fields.push_back(f);
    }
  };
  for (const auto& limit : sv.limits) add_field(limit.field);
  for (const auto& attribute : options.attributes) add_field(attribute.field);
  for (std::size_t f : out.fields) {
    out.nan_values.push_back(nan_replacement(sv, f));
    if (!std::isnan(out.nan_values.back())) {
      for (float v : samples.fields[f]) {
        if (std::isnan(v)) {
          out.limit_field_has_nan = true;
          break;
        }
      }
    }
  }
  return out;
}

// A linear VTK pipeline on one grid: each filter reads the one before it.
class FilterChain {
 public:
  FilterChain(vtkSmartPointer<vtkRectilinearGrid> grid, vtk_support::ErrorCapture& errors)
      : grid_(std::move(grid)), errors_(errors) {}

  void append(vtkSmartPointer<vtkAlgorithm> filter) {
    errors_.watch(filter);
    if (chain_.empty()) {
      filter->SetInputDataObject(grid_);
    } else {
      filter->SetInputConnection(chain_.back()->GetOutputPort());
    }
    chain_.push_back(std::move(filter));
  }

 private:
  vtkSmartPointer<vtkRectilinearGrid> grid_;
  vtk_support::ErrorCapture& errors_;
  std::vector<vtkSmartPointer<vtkAlgorithm>> chain_;
};

// Keeps only the cells whose points are all valid (make_rectilinear_grid's
// "strielad_valid" array).
void append_valid_cells(FilterChain& chain) {
  auto threshold = vtkSmartPointer<vtkThreshold>::New();
  threshold->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                                    "strielad_valid");
  threshold->SetLowerThreshold(0.5);
  threshold->SetUpperThreshold(1.5);
  threshold->SetThresholdFunction(vtkThreshold::THRESHOLD_BETWEEN);
  threshold->SetAllScalars(1);  // a cell is kept when all its points are valid
  threshold->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  chain.append(threshold);
}

// One scalar clip per bound of every limit.
void append_limit_clips(FilterChain& chain, const PaperSubvolume& sv) {
  for (const auto& limit : sv.limits) {
    const std::string name = field_array_name(limit.field);
    for (int side = 0; side < 2; ++side) {
      const std::optional<double>& bound = side == 0 ? limit.min : limit.max;
      if (!bound) continue;
      auto clip = vtkSmartPointer<vtkTableBasedClipDataSet>::New();
      clip->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name.c_str());
      clip->SetValue(*bound);
      clip->SetInsideOut(side == 1);  // min: keep >= min; max: keep <= max
      clip->GenerateClipScalarsOff();
      clip->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      chain.append(clip);
    }
  }
}

// One plane clip per side of the sub-volume's box that cuts the node.
void append_domain_clips(FilterChain& chain, const NodeSamples& samples, const AxisBox& domain) {
  for (int a = 0; a < 3; ++a) {
    const auto& c = samples.coords[a];
    const double node_lo = std::min(c.front(), c.back());
    const double node_hi = std::max(c.front(), c.back());
    for (int side = 0; side < 2; ++side) {
      const double bound = side == 0 ? domain.lo[a] : domain.hi[a];
      // A side with the whole node on its inside changes nothing: no clip.
      if (side == 0 ? !(bound > node_lo) : !(bound < node_hi)) continue;
      vtkNew<vtkPlane> plane;
      double origin[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
      origin[a] = bound;
      normal[a] = side == 0 ? 1.0 : -1.0;  // function >= 0 inside the box
      plane->SetOrigin(origin);
      plane->SetNormal(normal);
      auto clip = vtkSmartPointer<vtkTableBasedClipDataSet>::New();
      clip->SetClipFunction(plane);
      clip->SetValue(0.0);
      clip->InsideOutOff();
      clip->GenerateClipScalarsOff();
      clip->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      chain.append(clip);
    }
  }
}

// The clipped cells' outer surface as triangles with consistent point normals; the last
// filter of the chain.
vtkSmartPointer<vtkPolyDataNormals> append_surface(FilterChain& chain) {
  chain.append(vtkSmartPointer<vtkDataSetSurfaceFilter>::New());
  auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  chain.append(triangles);
  // The surface filter emits each boundary face with its cell's outward orientation
  // (VTK cell faces are outward and the grid is ascending), so Consistency keeps every
  // connected piece outward; AutoOrientNormals would turn the inner wall of a shell
  // (a cavity) the wrong way. No splitting: one closed vertex-sharing surface.
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->ComputePointNormalsOn();
  normals->ComputeCellNormalsOff();
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();
  normals->NonManifoldTraversalOff();
  chain.append(normals);
  return normals;
}

// The pipeline's surface as result.mesh, its faces classified, and its edges counted.
void take_surface(vtkPolyData* surface, const NodeSamples& samples, const PaperSubvolume& sv,
                  const PaperPipelineOptions& options, vtk_support::ErrorCapture& errors,
                  PeerResult& result) {
  result.mesh = to_mesh(surface, options.attributes);
  result.mesh.subvolume_id = sv.id;
  const bool float_points =
      surface->GetPoints() != nullptr && surface->GetPoints()->GetDataType() == VTK_FLOAT;
  classify_faces(result.mesh, samples, sv.domain, float_points);
  result.divergence_volume = enclosed_volume(result.mesh);
  if (options.measure && !result.mesh.empty()) {
    measure_with_vtk(surface, result, errors);
    throw_if_failed(errors, kPaperWho);
  } else {
    const EdgeCounts edges = count_open_edges(result.mesh);
    result.boundary_edges = edges.boundary;
    result.non_manifold_edges = edges.non_manifold;
  }
  result.closed = !result.mesh.empty() && result.boundary_edges == 0 &&
                  result.non_manifold_edges == 0;
}

PeerResult paper_pipeline(const NodeSamples& samples, const PaperSubvolume& sv,
                          const PaperPipelineOptions& options) {
  PeerResult result;
  result.cells = lattice_cells(samples);
  const VtkFields fields = vtk_fields(samples, sv, options);
  const bool drop_nan_cells =
      options.nan_policy == NanPolicy::kDropCells && fields.limit_field_has_nan;

  vtkNew<vtk_support::ErrorCapture> errors;
  const auto start = Clock::now();
  FilterChain chain(
      make_rectilinear_grid(samples, fields.fields, fields.nan_values, drop_nan_cells), *errors);
  if (drop_nan_cells) append_valid_cells(chain);
  append_limit_clips(chain, sv);
  if (sv.domain) append_domain_clips(chain, samples, *sv.domain);
  const auto normals = append_surface(chain);
  normals->Update();
  result.seconds = seconds_since(start);
  throw_if_failed(*errors, kPaperWho);
  take_surface(normals->GetOutput(), samples, sv, options, *errors, result);
  return result;
}

// vtkFlyingEdges3D orients its triangles and gradient normals towards smaller values;
// the peers' convention (vtk_paper_pipeline.h) is towards larger values.
constexpr bool kFlyingEdgesPointsToSmallerValues = true;

PeerResult flying_edges(const NodeSamples& samples, std::size_t field, double iso) {
  PeerResult result;
  result.cells = lattice_cells(samples);
  const auto dims = samples.dims();
  const auto& values = samples.fields[field];
  const float nan_value = static_cast<float>(far_below(iso));

  vtkNew<vtk_support::ErrorCapture> errors;
  const auto start = Clock::now();
  vtkNew<vtkImageData> image;
  image->SetDimensions(int(dims[0]), int(dims[1]), int(dims[2]));
  image->SetOrigin(0, 0, 0);
  image->SetSpacing(1, 1, 1);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("f");
  scalars->SetNumberOfTuples(vtkIdType(values.size()));
  float* out = scalars->GetPointer(0);
  for (std::size_t p = 0; p < values.size(); ++p) out[p] = sanitize_sample(values[p], nan_value);
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkFlyingEdges3D> contour;
  errors->watch(contour);
  contour->SetInputData(image);
  contour->SetValue(0, iso);
  contour->ComputeNormalsOn();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->InterpolateAttributesOff();
  contour->Update();
  result.seconds = seconds_since(start);
  throw_if_failed(*errors, kFlyingEdgesWho);

  result.mesh = to_mesh(contour->GetOutput(), {});
  if (kFlyingEdgesPointsToSmallerValues) {
    for (auto& t : result.mesh.triangles) std::swap(t[1], t[2]);
    for (auto& n : result.mesh.normals) n = {-n[0], -n[1], -n[2]};
  }
  map_index_mesh_to_axes(result.mesh, samples);
  result.divergence_volume = enclosed_volume(result.mesh);
  const EdgeCounts edges = count_open_edges(result.mesh);
  result.boundary_edges = edges.boundary;
  result.non_manifold_edges = edges.non_manifold;
  result.closed = !result.mesh.empty() && edges.closed();
  return result;
}

}  // namespace

PeerResult run_paper_pipeline(const NodeSamples& samples, const PaperSubvolume& subvolume,
                              const PaperPipelineOptions& options) {
  check_subvolume(samples, subvolume, options);
  return run_in_arena(options.threads,
                      [&] { return paper_pipeline(samples, subvolume, options); });
}

PeerResult run_paper_pipeline(const NodeSamples& samples, const ExtractRequest& request,
                              PaperPipelineOptions options) {
  PaperSubvolume sv;
  sv.id = request.subvolume_id;
  for (const ExtractLimit& limit : request.limits) {
    ScalarLimit l;
    l.field = limit.field;
    if (limit.min != -kUnbounded) l.min = limit.min;  // NaN is kept, to be refused
    if (limit.max != kUnbounded) l.max = limit.max;
    sv.limits.push_back(l);
  }
  AxisBox box;
  bool bounded = false;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = request.box[a][0];
    box.hi[a] = request.box[a][1];
    bounded = bounded || !std::isinf(box.lo[a]) || !std::isinf(box.hi[a]);
  }
  if (bounded) sv.domain = box;
  if (request.attribute_fields.size() != request.attribute_names.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: {} attribute fields but {} attribute names", kPaperWho,
                     request.attribute_fields.size(), request.attribute_names.size());
  }
  options.attributes.clear();
  for (std::size_t a = 0; a < request.attribute_fields.size(); ++a) {
    options.attributes.push_back({request.attribute_names[a], request.attribute_fields[a]});
  }
  return run_paper_pipeline(samples, sv, options);
}

PeerResult run_flying_edges(const NodeSamples& samples, std::size_t field, double iso,
                            const IsoSurfaceOptions& options) {
  check_node_samples(samples, kFlyingEdgesWho);
  check_field_index(samples, field, kFlyingEdgesWho);
  if (!std::isfinite(iso)) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: iso value {} is not finite",
                     kFlyingEdgesWho, iso);
  }
  return run_in_arena(options.threads, [&] { return flying_edges(samples, field, iso); });
}

}  // namespace strielad::peers
