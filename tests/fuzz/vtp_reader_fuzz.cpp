// SPDX-License-Identifier: Apache-2.0
// Fuzzes the .vtp reader (readback/vtp_reader.h, read_vtp through VTK's XML PolyData reader)
// on the input written to a file: it must reject with strielad::Error or return contents
// whose triangles index its points and whose arrays hold whole tuples. Seeds: files
// written by write_vtp (zlib-compressed appended binary, float64 and float32 points) and
// one ASCII PolyData file.
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "readback/vtp_reader.h"
#include "export/vtp_writer.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/fuzz_target.h"

using namespace strielad;

namespace {

Mesh tetrahedron() {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.normals = {{-0.577f, -0.577f, -0.577f}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  m.face_kinds = {FaceKind::kLimit, FaceKind::kNodeBoundary, FaceKind::kDomainBox, FaceKind::kGridBoundary};
  m.attribute_names = {"T"};
  m.attributes = {{270, 271, 272, 273}};
  return m;
}

std::vector<std::uint8_t> written_vtp(bool float32_points) {
  return fuzz::bytes_written_by(".vtp", [&](const std::filesystem::path& path) {
    const Mesh m = tetrahedron();
    const NodeMeshRef ref{7, &m};
    VtpOptions options;
    options.float32_points = float32_points;
    options.field_data = {{"frame", "axis"}};
    write_vtp(path, std::span<const NodeMeshRef>(&ref, 1), options);
  });
}

std::vector<std::uint8_t> text(const std::string& s) { return {s.begin(), s.end()}; }

void check(const VtpContents& c) {
  for (const auto& t : c.triangles) {
    for (const std::uint32_t v : t) {
      if (v >= c.points.size()) std::abort();  // a triangle names a point that is not there
    }
  }
  for (const auto* arrays : {&c.point_arrays, &c.cell_arrays}) {
    for (const auto& a : *arrays) {
      if (a.components < 1 || a.values.size() % std::size_t(a.components) != 0) std::abort();
    }
  }
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {written_vtp(false), written_vtp(true),
          text("<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
               "<PolyData><Piece NumberOfPoints=\"4\" NumberOfPolys=\"2\">\n"
               "<PointData Normals=\"Normals\">\n"
               "<DataArray type=\"Float32\" Name=\"Normals\" NumberOfComponents=\"3\" format=\"ascii\">"
               "0 0 1 0 0 1 0 0 1 0 0 1</DataArray>\n"
               "<DataArray type=\"Float32\" Name=\"T\" format=\"ascii\">1 2 3 4</DataArray>\n"
               "</PointData>\n"
               "<CellData><DataArray type=\"UInt32\" Name=\"node_id\" format=\"ascii\">5 5</DataArray></CellData>\n"
               "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
               "0 0 0 1 0 0 1 1 0 0 1 0</DataArray></Points>\n"
               "<Polys><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 0 2 3</DataArray>\n"
               "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3 6</DataArray></Polys>\n"
               "</Piece></PolyData></VTKFile>\n")};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    check(read_vtp(fuzz::input_file(data, size, ".vtp")));
  } catch (const Error&) {
  }
  return 0;
}
