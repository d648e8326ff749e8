// SPDX-License-Identifier: Apache-2.0
#include "readback/vtp_reader.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <new>
#include <stdexcept>
#include <system_error>

#include "core/error.h"
#include "core/file_io.h"
#include "export/vtk_error_capture.h"
#include "readback/bounded_string_polydata_reader.h"
#include "readback/vtp_declared_sizes.h"

namespace strielad {
namespace {

std::vector<VtpArray> read_arrays(vtkFieldData* data) {
  std::vector<VtpArray> arrays;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkDataArray* array = data->GetArray(i);
    if (array == nullptr) continue;  // string or other abstract arrays
    VtpArray out;
    out.name = array->GetName() != nullptr ? array->GetName() : "";
    out.type = array->GetDataTypeAsString();
    out.components = array->GetNumberOfComponents();
    const vtkIdType n = array->GetNumberOfTuples();
    out.values.resize(std::size_t(n) * std::size_t(out.components));
    for (vtkIdType t = 0; t < n; ++t) {
      for (int c = 0; c < out.components; ++c) {
        out.values[std::size_t(t) * std::size_t(out.components) + std::size_t(c)] =
            array->GetComponent(t, c);
      }
    }
    arrays.push_back(std::move(out));
  }
  return arrays;
}

const VtpArray* find_array(const std::vector<VtpArray>& arrays, std::string_view name) {
  for (const auto& a : arrays) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

}  // namespace

const VtpArray* VtpContents::point_array(std::string_view name) const {
  return find_array(point_arrays, name);
}

const VtpArray* VtpContents::cell_array(std::string_view name) const {
  return find_array(cell_arrays, name);
}

VtpContents read_vtp(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw make_error(ErrorCode::kNotFound, "{}: no such file", path.string());
  }
  const std::vector<std::byte> bytes = read_file_bytes(path);
  vtp::check_declared_sizes({reinterpret_cast<const char*>(bytes.data()), bytes.size()},
                            path.string());
  vtkNew<vtk_support::ErrorCapture> errors;
  vtkNew<vtp::BoundedStringPolyDataReader> reader;
  errors->watch(reader);
  reader->SetReaderErrorObserver(errors);  // its internal readers and XML parser
  reader->SetParserErrorObserver(errors);
  // VTK reads the very bytes checked above (a second open could see another file).
  reader->ReadFromInputStringOn();
  reader->SetInputString(std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  // VTK allocates what the file declares before it reads the data; sizes the bytes cannot
  // back are refused above, and a size that still cannot be allocated ends here.
  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: not a readable VTK XML PolyData file: it declares more data than can "
                     "be allocated",
                     path.string());
  } catch (const std::length_error&) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: not a readable VTK XML PolyData file: it declares more data than can "
                     "be allocated",
                     path.string());
  }
  vtkPolyData* poly = reader->GetOutput();
  if (errors->failed() || poly == nullptr) {
    throw make_error(ErrorCode::kInvalidInput, "{}: not a readable VTK XML PolyData file: {}",
                     path.string(), errors->failed() ? errors->message() : "no output");
  }
  VtpContents contents;
  const vtkIdType np = poly->GetNumberOfPoints();
  contents.points.resize(std::size_t(np));
  for (vtkIdType p = 0; p < np; ++p) {
    poly->GetPoint(p, contents.points[std::size_t(p)].data());
  }
  if (poly->GetPoints() != nullptr) {
    contents.points_type = poly->GetPoints()->GetData()->GetDataTypeAsString();
  }
  vtkCellArray* polys = poly->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);) {
    for (vtkIdType k = 0; k < count; ++k) {
      if (ids[k] < 0 || ids[k] >= np) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: not a readable VTK XML PolyData file: a polygon refers to point {} "
                         "of {}",
                         path.string(), ids[k], np);
      }
    }
    if (count == 3) {
      contents.triangles.push_back(
          {std::uint32_t(ids[0]), std::uint32_t(ids[1]), std::uint32_t(ids[2])});
    } else {
      ++contents.other_cells;
    }
  }
  contents.other_cells += std::uint64_t(poly->GetNumberOfVerts() + poly->GetNumberOfLines() +
                                        poly->GetNumberOfStrips());
  contents.point_arrays = read_arrays(poly->GetPointData());
  contents.cell_arrays = read_arrays(poly->GetCellData());
  vtkFieldData* field = poly->GetFieldData();
  for (int i = 0; i < field->GetNumberOfArrays(); ++i) {
    auto* strings = vtkStringArray::SafeDownCast(field->GetAbstractArray(i));
    if (strings == nullptr || strings->GetNumberOfValues() == 0) continue;
    contents.field_strings.emplace_back(strings->GetName() != nullptr ? strings->GetName() : "",
                                        strings->GetValue(0));
  }
  if (vtkDataArray* normals = poly->GetPointData()->GetNormals()) {
    contents.normals_name = normals->GetName() != nullptr ? normals->GetName() : "";
  }
  return contents;
}

}  // namespace strielad
