// SPDX-License-Identifier: Apache-2.0
// Reads a VTK XML PolyData file (.vtp) back into plain arrays with vtkXMLPolyDataReader:
// for tests of the .vtp export and for tools that inspect it. VTK types stay inside
// vtp_reader.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace strielad {

struct VtpArray {
  std::string name;
  std::string type;  // VTK's data type name: "float", "unsigned int", "unsigned char", ...
  int components = 1;
  std::vector<double> values;  // tuples one after another
};

struct VtpContents {
  std::vector<std::array<double, 3>> points;
  std::string points_type;                              // "float" or "double"
  std::vector<std::array<std::uint32_t, 3>> triangles;  // the triangle Polys
  std::uint64_t other_cells = 0;  // verts, lines, strips and non-triangle polys
  std::vector<VtpArray> point_arrays;
  std::vector<VtpArray> cell_arrays;
  std::string normals_name;  // the point data's active normals, "" if none
  // The field data's string arrays: name and first value (write_vtp's text metadata).
  std::vector<std::pair<std::string, std::string>> field_strings;

  const VtpArray* point_array(std::string_view name) const;
  const VtpArray* cell_array(std::string_view name) const;
};

// \error kNotFound if the file does not exist.
// \error kInvalidInput (naming the file, with VTK's message) if VTK cannot read it.
VtpContents read_vtp(const std::filesystem::path& path);

}  // namespace strielad
