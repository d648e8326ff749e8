// SPDX-License-Identifier: Apache-2.0
// Valid protocol messages of every type for the protocol tests and the fuzz target's
// seeds, and a check that a decoded mesh is within the quantization error bounds of
// formats/protocol.md ("Mesh encoding") of the mesh that was encoded. Header-only and
// free of GoogleTest so that tests/fuzz can use it too.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "protocol/messages.h"

namespace strielad::protocol::samples {

// A mesh whose encoding is exact: every coordinate is at its box's lo or hi, normals
// point along the axes, attribute values are at their range's ends. Decoding its
// encoding gives it back unchanged (subvolume_id included, attribute_names empty).
inline Mesh exact_mesh(std::uint32_t subvolume_id) {
  Mesh m;
  m.subvolume_id = subvolume_id;
  m.positions = {{4.5, 47.5, 20.0}, {14.5, 47.5, 20.0}, {4.5, 54.5, 20.0}, {4.5, 47.5, 21000.0}};
  m.normals = {{-1, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  m.face_kinds = {FaceKind::kLimit, FaceKind::kNodeBoundary, FaceKind::kDomainBox,
                  FaceKind::kGridBoundary};
  m.attributes = {{250.0f, 300.0f, 300.0f, 250.0f}, {-1.5f, -1.5f, -1.5f, -1.5f}};
  return m;
}

// One or more messages of every type; every one compares equal (==) to the decoding of
// its encoding.
inline std::vector<Message> sample_messages() {
  const std::string scene =
      R"({"format_version":1,"time":0,"subvolumes":[{"id":1,"name":"cloud ice",)"
      R"("limits":[{"var":"cli","min":1e-06}]}],"attributes":["ta","ua"]})";
  NodeResult result{7, 51392, {}};
  result.subvolumes.push_back({1, NodeOutcome::kMesh, "", exact_mesh(1), {}});
  result.subvolumes.push_back({2, NodeOutcome::kEmpty, "", {}, {}});
  result.subvolumes.push_back(
      {65535, NodeOutcome::kSkippedValueRange, "cli: node range [0, 1e-07] misses [1e-06, inf]", {}, {}});
  result.subvolumes.push_back({4, NodeOutcome::kSkippedDomain, "lon", {}, {}});
  result.subvolumes.push_back({5, NodeOutcome::kSkippedNoData, "", {}, {}});
  const std::vector<std::byte> manifest{std::byte{'S'}, std::byte{'T'}, std::byte{0},
                                        std::byte{0xFF}};
  return {
      Hello{kProtocolVersion, "strielad-view 0.1.0", "s3cret"},
      Hello{7, "W\xC3\xB6lke \xE2\x82\xAC \xF0\x9F\x8C\xA7", ""},
      OpenDataset{"paper/step-one"},
      SetScene{1, scene},
      SetTime{2, 3},
      CutUpdate{3, {{0, 1.5f}, {17, -0.0f}, {51392, 3e38f}}, {5, 6}, {{9, -0.25f}}},
      CutUpdate{4, {}, {}, {}},
      StatsRequest{},
      Goodbye{},
      Welcome{kProtocolVersion, "strielad-serve 0.1.0", ServerLimits{}},
      Welcome{kProtocolVersion, "", ServerLimits{1, 1, 1, 1}},
      DatasetOpened{"paper/step-one", manifest},
      GenerationStarted{3, 1, scene},
      result,
      NodeResult{8, 0, {}},
      NodeFailed{7, 12, WireError::kCorrupt, "steps/step-000001.bricks: node 12: chunk checksum mismatch"},
      ErrorMessage{WireError::kOutOfOrder, false, "CutUpdate of generation 2, current is 3"},
      ErrorMessage{WireError::kUnauthorized, true, ""},
      Stats{R"({"clients":1,"generation":3,"cache":{"hit_rate":0.5},"ranks":1})"},
  };
}

// Whether `decoded` is what decoding the encoding of `original` may give: same
// topology, face kinds and sub-volume id; positions within half a quantization step
// (plus binary64 rounding); unit normals within 0.005 degrees; attributes missing
// exactly where the original's are and otherwise within half a step (plus binary32
// rounding). Attribute names are not compared (they are not sent).
inline bool mesh_within_bounds(const Mesh& original, const Mesh& decoded) {
  const std::size_t v = original.positions.size();
  if (decoded.subvolume_id != original.subvolume_id || decoded.positions.size() != v ||
      decoded.normals.size() != v || decoded.triangles != original.triangles ||
      decoded.face_kinds != original.face_kinds ||
      decoded.attributes.size() != original.attributes.size() || v == 0) {
    return false;
  }
  for (int a = 0; a < 3; ++a) {
    double lo = original.positions[0][a], hi = lo;
    for (const auto& p : original.positions) lo = std::min(lo, p[a]), hi = std::max(hi, p[a]);
    const double ulp = std::nextafter(std::max(std::abs(lo), std::abs(hi)),
                                      std::numeric_limits<double>::infinity()) -
                       std::max(std::abs(lo), std::abs(hi));
    const double bound = (hi - lo) / 131070 + 4 * ulp;
    for (std::size_t i = 0; i < v; ++i) {
      if (!(std::abs(decoded.positions[i][a] - original.positions[i][a]) <= bound)) return false;
    }
  }
  const double cos_bound = std::cos(0.005 * std::acos(-1.0) / 180);
  for (std::size_t i = 0; i < v; ++i) {
    const auto& n = original.normals[i];
    const auto& d = decoded.normals[i];
    const double ln = std::sqrt(double{n[0]} * n[0] + double{n[1]} * n[1] + double{n[2]} * n[2]);
    const double ld = std::sqrt(double{d[0]} * d[0] + double{d[1]} * d[1] + double{d[2]} * d[2]);
    if (!(std::abs(ld - 1) <= 1e-6)) return false;
    const double cosine = (double{n[0]} * d[0] + double{n[1]} * d[1] + double{n[2]} * d[2]) / (ln * ld);
    if (!(cosine >= cos_bound)) return false;
  }
  for (std::size_t a = 0; a < original.attributes.size(); ++a) {
    const auto& o = original.attributes[a];
    const auto& d = decoded.attributes[a];
    if (d.size() != v) return false;
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float x : o) {
      if (!std::isnan(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    }
    const float top = std::max(std::abs(lo), std::abs(hi));
    const double ulp = std::isfinite(top) ? double{std::nextafter(top, std::numeric_limits<float>::infinity())} - top : 0;
    const double bound = lo <= hi ? (double{hi} - lo) / 131068 + ulp : 0;
    for (std::size_t i = 0; i < v; ++i) {
      if (std::isnan(o[i]) != std::isnan(d[i])) return false;
      if (!std::isnan(o[i]) && !(std::abs(double{d[i]} - o[i]) <= bound)) return false;
    }
  }
  return true;
}

}  // namespace strielad::protocol::samples
