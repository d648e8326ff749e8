// SPDX-License-Identifier: Apache-2.0
// Fuzzes the manifest decoder: frame, JSON and every content rule. The checksum is
// re-sealed so that mutations reach the JSON parser and the content checks.
#include <cstring>

#include "core/checksum.h"
#include "core/error.h"
#include "format/manifest.h"
#include "fuzz/fuzz_target.h"

using namespace strielad;
using namespace strielad::format;

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  Manifest m;
  m.tool_version = "fuzz";
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "", "", "", {1, 2, 3}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "", "", "", {5, 4}};
  m.z = Axis{"lev", AxisKind::kPressure, "hPa", "", "", "down", {1000, 500}};
  m.time = TimeAxis{"time", "hours since 2000-01-01", "standard", {0}};
  m.variables.push_back(StoreVariable{"T", "K", "", "", DType::kFloat32, "float", -999.0, {}, {}, {}, {}, {}});
  m.brick = 4;
  m.store_id = compute_store_id(m);
  const auto plain = encode_manifest(m);
  // Version 2 features: a store-wide predictor and a variable with its own codec.
  Manifest v2 = m;
  v2.codec.predictor = "lorenzo3";
  v2.variables.push_back(v2.variables[0]);
  v2.variables[1].name = "clw";
  v2.variables[1].codec = CodecSpec{"lz4", 5, "bit", "none"};
  v2.store_id = compute_store_id(v2);
  const auto predictors = encode_manifest(v2);
  // A version-1 manifest, as stores written before predictors have.
  Manifest v1 = m;
  v1.format_version = 1;
  v1.store_id = compute_store_id(v1);
  const auto version1 = encode_manifest(v1);
  // Version 5: a curvilinear grid with a time-varying height field and a surface.
  Manifest v5 = m;
  v5.x = Axis{"west_east", AxisKind::kIndex, "1", "", "", "", {0, 1, 2}};
  v5.y = Axis{"south_north", AxisKind::kIndex, "1", "", "", "", {0, 1}};
  GridGeometry g;
  g.horizontal = HorizontalGeometry{HorizontalGeometry::Kind::kCurvilinear, "XLONG", "XLAT", 7};
  g.vertical.kind = VerticalGeometry::Kind::kField;
  g.vertical.units = "m";
  g.vertical.formula = std::string(kGeometryFormulaVariable);
  g.vertical.sources = {"PH", "PHB"};
  g.vertical.varies_in_time = true;
  g.surface = SurfaceGeometry{"HGT", "m"};
  v5.geometry = g;
  v5.format_version = version_for_plan(v5);
  v5.store_id = compute_store_id(v5);
  const auto geometry = encode_manifest(v5);
  m.complete = true;
  m.steps = {StepRecord{0, step_file_name(0), 10, 1}};
  m.summary = {{"ratio", 2.0}};
  const auto complete = encode_manifest(m);
  std::vector<std::vector<std::uint8_t>> seeds;
  for (const auto* b : {&plain, &complete, &predictors, &version1, &geometry}) {
    seeds.emplace_back(reinterpret_cast<const std::uint8_t*>(b->data()),
                       reinterpret_cast<const std::uint8_t*>(b->data()) + b->size());
  }
  return seeds;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(data),
                               reinterpret_cast<const std::byte*>(data) + size);
  try {
    decode_manifest(bytes, "fuzz");
  } catch (const Error&) {
  }
  if (bytes.size() >= 32) {  // re-seal the checksum to reach the content rules
    const std::uint64_t sum = checksum64(std::span(bytes).first(bytes.size() - 8));
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    try {
      decode_manifest(bytes, "fuzz");
    } catch (const Error&) {
    }
  }
  return 0;
}
