// SPDX-License-Identifier: Apache-2.0
#include "export/vtp_writer.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnsignedIntArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"
#include "export/vtk_error_capture.h"

namespace strielad {
namespace {

// Which triangles and vertices of one mesh go into the file.
struct MeshSelection {
  std::vector<std::uint32_t> triangles;      // indices into mesh.triangles
  std::vector<std::uint32_t> vertices;       // indices into mesh.positions, in file order
  std::vector<std::uint32_t> vertex_to_out;  // mesh vertex -> file-local index (or max)
};

void check_mesh(const std::filesystem::path& path, const NodeMeshRef& ref) {
  if (ref.mesh == nullptr) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: node {}: mesh is null", path.string(),
                     ref.node_id);
  }
  const Mesh& m = *ref.mesh;
  const std::size_t nv = m.positions.size();
  auto bad = [&](std::string_view what, std::size_t have, std::size_t want) {
    return make_error(ErrorCode::kInvalidArgument,
                      "{}: node {} sub-volume {}: {} has {} entries, expected {}", path.string(),
                      ref.node_id, m.subvolume_id, what, have, want);
  };
  if (m.normals.size() != nv) throw bad("normals", m.normals.size(), nv);
  if (!m.face_kinds.empty() && m.face_kinds.size() != m.triangles.size())
    throw bad("face_kinds", m.face_kinds.size(), m.triangles.size());
  if (m.attributes.size() != m.attribute_names.size())
    throw bad("attributes", m.attributes.size(), m.attribute_names.size());
  for (std::size_t a = 0; a < m.attributes.size(); ++a) {
    if (m.attributes[a].size() != nv) throw bad("attribute " + m.attribute_names[a], m.attributes[a].size(), nv);
  }
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    for (std::uint32_t v : m.triangles[t]) {
      if (v >= nv) {
        throw make_error(ErrorCode::kInvalidArgument,
                         "{}: node {} sub-volume {}: triangle {} uses vertex {} of {}",
                         path.string(), ref.node_id, m.subvolume_id, t, v, nv);
      }
    }
  }
}

MeshSelection select(const Mesh& m, bool drop_node_boundary_faces) {
  MeshSelection s;
  s.vertex_to_out.assign(m.positions.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (drop_node_boundary_faces && !m.face_kinds.empty() &&
        m.face_kinds[t] == FaceKind::kNodeBoundary) {
      continue;
    }
    s.triangles.push_back(std::uint32_t(t));
  }
  if (!drop_node_boundary_faces) {
    s.vertices.resize(m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      s.vertices[v] = std::uint32_t(v);
      s.vertex_to_out[v] = std::uint32_t(v);
    }
    return s;
  }
  for (std::uint32_t t : s.triangles) {
    for (std::uint32_t v : m.triangles[t]) {
      if (s.vertex_to_out[v] == std::numeric_limits<std::uint32_t>::max()) {
        s.vertex_to_out[v] = std::uint32_t(s.vertices.size());
        s.vertices.push_back(v);
      }
    }
  }
  return s;
}

// The attribute names of all meshes, each once, in the order they first appear.
std::vector<std::string> all_attribute_names(std::span<const NodeMeshRef> meshes) {
  std::vector<std::string> names;
  for (const NodeMeshRef& ref : meshes) {
    for (const auto& name : ref.mesh->attribute_names) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  return names;
}

// The output's arrays, sized for every selected vertex and triangle; attributes a mesh
// lacks stay NaN.
struct PolyArrays {
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  std::vector<std::string> attribute_names;
  std::vector<vtkSmartPointer<vtkFloatArray>> attributes;  // one per name
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  vtkNew<vtkUnsignedIntArray> subvolume_ids, node_ids;
  vtkNew<vtkUnsignedCharArray> face_kinds;
  vtkIdType point_base = 0, cell = 0;  // filled so far

  PolyArrays(std::uint64_t n_points, std::uint64_t n_triangles, std::vector<std::string> names,
             bool float32_points)
      : attribute_names(std::move(names)) {
    if (float32_points) {
      points->SetDataTypeToFloat();
    } else {
      points->SetDataTypeToDouble();
    }
    points->SetNumberOfPoints(vtkIdType(n_points));
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(vtkIdType(n_points));
    for (const auto& name : attribute_names) {
      auto array = vtkSmartPointer<vtkFloatArray>::New();
      array->SetName(name.c_str());
      array->SetNumberOfTuples(vtkIdType(n_points));
      array->FillValue(std::numeric_limits<float>::quiet_NaN());
      attributes.push_back(array);
    }
    offsets->SetNumberOfTuples(vtkIdType(n_triangles + 1));
    connectivity->SetNumberOfTuples(vtkIdType(3 * n_triangles));
    subvolume_ids->SetName("subvolume_id");
    subvolume_ids->SetNumberOfTuples(vtkIdType(n_triangles));
    node_ids->SetName("node_id");
    node_ids->SetNumberOfTuples(vtkIdType(n_triangles));
    face_kinds->SetName("face_kind");
    face_kinds->SetNumberOfTuples(vtkIdType(n_triangles));
    offsets->SetValue(0, 0);
  }

  // The selected part of one node's mesh, after those appended before.
  void append(const NodeMeshRef& ref, const MeshSelection& s) {
    const Mesh& m = *ref.mesh;
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
      const auto& p = m.positions[s.vertices[v]];
      const auto& n = m.normals[s.vertices[v]];
      const vtkIdType id = point_base + vtkIdType(v);
      points->SetPoint(id, p.data());
      normals->SetTypedTuple(id, n.data());
    }
    for (std::size_t a = 0; a < m.attribute_names.size(); ++a) {
      const auto it = std::find(attribute_names.begin(), attribute_names.end(), m.attribute_names[a]);
      vtkFloatArray* array = attributes[std::size_t(it - attribute_names.begin())];
      for (std::size_t v = 0; v < s.vertices.size(); ++v) {
        array->SetValue(point_base + vtkIdType(v), m.attributes[a][s.vertices[v]]);
      }
    }
    for (std::uint32_t t : s.triangles) {
      for (int c = 0; c < 3; ++c) {
        connectivity->SetValue(3 * cell + c, point_base + s.vertex_to_out[m.triangles[t][c]]);
      }
      offsets->SetValue(cell + 1, 3 * (cell + 1));
      subvolume_ids->SetValue(cell, m.subvolume_id);
      node_ids->SetValue(cell, ref.node_id);
      face_kinds->SetValue(cell, m.face_kinds.empty() ? std::uint8_t(FaceKind::kLimit)
                                                      : std::uint8_t(m.face_kinds[t]));
      ++cell;
    }
    point_base += vtkIdType(s.vertices.size());
  }
};

vtkSmartPointer<vtkPolyData> build_polydata(std::span<const NodeMeshRef> meshes,
                                   const std::vector<MeshSelection>& selections,
                                   const VtpOptions& options) {
  std::uint64_t n_points = 0, n_triangles = 0;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    n_points += selections[i].vertices.size();
    n_triangles += selections[i].triangles.size();
  }
  PolyArrays arrays(n_points, n_triangles, all_attribute_names(meshes), options.float32_points);
  for (std::size_t i = 0; i < meshes.size(); ++i) arrays.append(meshes[i], selections[i]);

  vtkNew<vtkCellArray> polys;
  polys->SetData(arrays.offsets, arrays.connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(arrays.points);
  poly->SetPolys(polys);
  poly->GetCellData()->AddArray(arrays.subvolume_ids);
  poly->GetCellData()->AddArray(arrays.node_ids);
  if (options.face_kind_array) poly->GetCellData()->AddArray(arrays.face_kinds);
  poly->GetPointData()->SetNormals(arrays.normals);
  for (const auto& array : arrays.attributes) poly->GetPointData()->AddArray(array);
  for (const auto& [name, text] : options.field_data) {
    vtkNew<vtkStringArray> value;
    value->SetName(name.c_str());
    value->InsertNextValue(text);
    poly->GetFieldData()->AddArray(value);
  }
  return poly;
}

}  // namespace

VtpSummary write_vtp(const std::filesystem::path& path, std::span<const NodeMeshRef> meshes,
                     const VtpOptions& options) {
  if (options.compression_level < 1 || options.compression_level > 9) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: zlib compression level {} is outside 1..9",
                     path.string(), options.compression_level);
  }
  VtpSummary summary;
  std::vector<MeshSelection> selections;
  selections.reserve(meshes.size());
  for (const NodeMeshRef& ref : meshes) {
    check_mesh(path, ref);
    selections.push_back(select(*ref.mesh, options.drop_node_boundary_faces));
    summary.points += selections.back().vertices.size();
    summary.triangles += selections.back().triangles.size();
    summary.dropped_triangles += ref.mesh->triangles.size() - selections.back().triangles.size();
  }
  if (summary.points > std::numeric_limits<std::uint32_t>::max()) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: {} points are more than 2^32",
                     path.string(), summary.points);
  }
  vtkSmartPointer<vtkPolyData> poly = build_polydata(meshes, selections, options);

  std::string bytes;
  {
    vtkNew<vtk_support::ErrorCapture> errors;
    vtkNew<vtkXMLPolyDataWriter> writer;
    errors->watch(writer);
    writer->SetInputData(poly);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw binary, not base64
    writer->SetCompressorTypeToZLib();
    writer->SetCompressionLevel(options.compression_level);
    writer->SetHeaderTypeToUInt64();  // blocks over 4 GiB
    writer->WriteToOutputStringOn();  // then written atomically below
    if (writer->Write() != 1 || errors->failed()) {
      throw make_error(ErrorCode::kInternal, "{}: vtkXMLPolyDataWriter failed: {}", path.string(),
                       errors->failed() ? errors->message() : "no message");
    }
    bytes = writer->GetOutputString();  // VTK 9.1 hands out a copy; the writer's dies here
  }
  poly = nullptr;
  try {
    AtomicOutputFile out(path);
    out.append(std::as_bytes(std::span(bytes.data(), bytes.size())));
    out.commit();
  } catch (const Error& e) {
    throw e.with_context(path.string() + ": writing VTK PolyData");
  }
  summary.bytes = bytes.size();
  return summary;
}

}  // namespace strielad
