// SPDX-License-Identifier: Apache-2.0
// Fuzzes the scene parser (formats/scene.md) and resolution against a fixed manifest: they
// must reject with strielad::Error, never crash. A scene that parses must survive the
// canonical round trip unchanged; anything else is a bug and aborts.
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/error.h"
#include "format/manifest.h"
#include "fuzz/fuzz_target.h"
#include "scene/scene.h"

using namespace strielad;

namespace {

const format::Manifest& fuzz_manifest() {
  static const format::Manifest m = [] {
    format::Manifest m;
    m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "", "", "", {4.5, 9.5, 14.5}};
    m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "", "", "", {54.5, 47.5}};
    m.z = Axis{"height", AxisKind::kHeight, "m", "", "", "up", {21000, 20}};
    m.time = TimeAxis{"time", "", "", {0, 300}};
    for (const char* name : {"clw", "cli", "qr", "ta", "ua"}) {
      format::StoreVariable v;
      v.name = name;
      m.variables.push_back(v);
    }
    return m;
  }();
  return m;
}

std::vector<std::uint8_t> bytes_of(std::string_view s) { return {s.begin(), s.end()}; }

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {
      bytes_of(R"({"format_version": 1, "time": 0, "subvolumes": [
        {"id": 1, "name": "cloud ice", "limits": [{"var": "cli", "min": 1e-6}],
         "domain": {"lon": [5.0, 15.0], "lat": [47.0, 55.0], "height": [0, 12000]}},
        {"id": 2, "name": "rain in warm air",
         "limits": [{"var": "qr", "min": 1e-5}, {"var": "ta", "min": 273.15, "max": 320}]}],
        "attributes": ["ta", "ua"]})"),
      bytes_of(R"({"time":1,"subvolumes":[{"id":65535,"name":"box","limits":[],"domain":{"height":[20,20]}}]})"),
      bytes_of(R"({"subvolumes":[{"id":3,"limits":[{"var":"clw","max":-0.0},{"var":"ta","min":-1e308,"max":5e-324}]}],"attributes":[]})"),
      bytes_of(R"({"format_version":2,"slices":[{"axis":"lat","at":50}],"subvolumes":[{"id":1,"style":{},"limits":[{"var":"x","min":"nan"}]}]})"),
      bytes_of("\xEF\xBB\xBF{\"subvolumes\":[{\"id\":1,\"name\":\"W\\u00f6lke \xE2\x82\xAC\",\"domain\":{\"lon\":[1e999,-1]}}],\"time\":[[[[]]]]}"),
  };
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Scene scene;
  try {
    scene = parse_scene(text, "fuzz");
  } catch (const Error&) {
    return 0;
  }
  // A parsed scene is valid: its canonical form must parse back to the same scene and be
  // written identically again.
  try {
    const std::string canonical = scene_to_json(scene);
    const Scene back = parse_scene(canonical, "canonical");
    if (!(back == scene) || scene_to_json(back) != canonical) std::abort();
  } catch (const Error&) {
    std::abort();
  }
  try {
    resolve_scene(scene, fuzz_manifest(), "fuzz");
  } catch (const Error&) {
  }
  return 0;
}
