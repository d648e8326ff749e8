// SPDX-License-Identifier: Apache-2.0
// Domain boxes whose bounds are exactly sample coordinates (round numbers on a 2.5°
// grid, integer pressure levels): the seamless union of a level stays closed and encloses
// the box's volume, whether the bound falls inside a node or on the face two nodes share,
// on ascending, descending, non-uniform and integer-typed axes, at every level.
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

struct StoreCase {
  std::string name;
  std::shared_ptr<const Store> store;
  std::string limit;  // a limit that cuts the grid, as scene JSON
};

class BoxBoundsOnSamplePlanesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    // Lon ascending non-uniform, lat descending, lev hPa descending non-uniform.
    std::filesystem::create_directories(*dir_ / "small");
    const auto small = testing::write_small_dataset(*dir_ / "small", 33, 29, 17, 1);
    build::convert(testing::small_convert_options(small, *dir_ / "small.store", 8));
    // Real output: T42 Gaussian latitudes, 2.8125° longitudes, integer hPa levels.
    const auto real = testing::ncarg_file("cdf/nc4uvt.nc");
    if (std::filesystem::exists(real)) {
      build::ConvertOptions o;
      o.inputs = {real};
      o.store = *dir_ / "nc4uvt.store";
      o.scan.variables = {"T"};
      o.brick = 8;
      o.threads = 2;
      build::convert(o);
    }
  }
  static void TearDownTestSuite() { delete dir_; }

  static std::vector<StoreCase> stores() {
    std::vector<StoreCase> out;
    out.push_back({"small", Store::open(*dir_ / "small.store"),
                   R"({"var": "temp", "max": 270.0})"});
    if (std::filesystem::exists(*dir_ / "nc4uvt.store")) {
      out.push_back({"nc4uvt", Store::open(*dir_ / "nc4uvt.store"),
                     R"({"var": "T", "min": -40.0})"});
    }
    return out;
  }

  static testing::TempDir* dir_;
};
testing::TempDir* BoxBoundsOnSamplePlanesTest::dir_ = nullptr;

const Axis& axis_of(const format::Manifest& m, int a) { return a == 0 ? m.x : a == 1 ? m.y : m.z; }

// Sample index pairs along an axis of n samples with brick B: a box from a node face to
// a node face, from a node face to a sample inside a node, and between two samples
// inside nodes.
std::vector<std::pair<std::size_t, std::size_t>> bound_indices(std::size_t n, std::size_t brick) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  if (n > 2 * brick) out.push_back({brick, 2 * brick});
  if (n > brick + 3) out.push_back({brick, n - 3});
  if (n > 5) out.push_back({1, n - 2});
  return out;
}

std::string number(double v) { return fmt::format("{:.17g}", v); }

// Volume of [lo, hi] on every axis, cut to the grid's extent.
double box_volume(const format::Manifest& m, const std::array<std::array<double, 2>, 3>& box) {
  double v = 1;
  for (int a = 0; a < 3; ++a) {
    const auto& c = axis_of(m, a).values;
    const double lo = std::max(box[a][0], std::min(c.front(), c.back()));
    const double hi = std::min(box[a][1], std::max(c.front(), c.back()));
    v *= hi - lo;
  }
  return v;
}

TEST_F(BoxBoundsOnSamplePlanesTest, SeamlessUnionIsClosedAndEnclosesTheBox) {
  for (const StoreCase& sc : stores()) {
    const format::Manifest& m = sc.store->manifest();
    for (int a = 0; a < 3; ++a) {
      const Axis& axis = axis_of(m, a);
      for (const auto& [i, j] : bound_indices(axis.size(), m.brick)) {
        const double lo = std::min(axis.values[i], axis.values[j]);
        const double hi = std::max(axis.values[i], axis.values[j]);
        std::array<std::array<double, 2>, 3> box{{{-1e300, 1e300}, {-1e300, 1e300}, {-1e300, 1e300}}};
        box[a] = {lo, hi};
        const std::string domain = fmt::format(R"("domain": {{"{}": [{}, {}]}})", axis.name,
                                               number(lo), number(hi));
        const std::string json = fmt::format(
            R"({{"time": 0, "subvolumes": [{{"id": 1, "limits": [], {}}},
                {{"id": 2, "limits": [{}], {}}}]}})",
            domain, sc.limit, domain);
        const ResolvedScene scene = resolve_scene(parse_scene(json, "box"), m, "box");
        for (std::uint32_t level = 0; level < sc.store->octree().level_count(); ++level) {
          LevelExtractionOptions o;
          o.level = level;
          o.threads = 2;
          const LevelExtraction extraction = extract_level(*sc.store, scene, o);
          const std::string where = fmt::format("{}: {} in [{}, {}] (samples {}, {}), level {}",
                                                sc.name, axis.name, lo, hi, i, j, level);
          const Mesh box_only = seamless_union(extraction, 1);
          const MeshCheck c1 = check_mesh(box_only);
          EXPECT_TRUE(c1.clean()) << where << ": box only: " << c1.open_edges << " open edges";
          // Every level keeps the grid's first and last sample of every axis, but a bound
          // on a sample that a coarse level drops lies inside a coarse cell: the box is
          // exact at every level all the same (its planes cut cells exactly).
          const double expected = box_volume(m, box);
          EXPECT_NEAR(enclosed_volume(box_only), expected, 1e-9 * std::fabs(expected)) << where;

          const Mesh limited = seamless_union(extraction, 2);
          const MeshCheck c2 = check_mesh(limited);
          EXPECT_TRUE(c2.clean()) << where << ": with a limit: " << c2.open_edges << " open edges";
          EXPECT_GT(enclosed_volume(limited), 0.0) << where;
        }
      }
    }
  }
}

// The same region as the box with its bounds a millionth of a cell inside: the mesh on
// sample planes encloses the volume the neighbouring bounds converge to.
TEST_F(BoxBoundsOnSamplePlanesTest, VolumeIsContinuousInTheBound) {
  for (const StoreCase& sc : stores()) {
    const format::Manifest& m = sc.store->manifest();
    for (int a = 0; a < 3; ++a) {
      const Axis& axis = axis_of(m, a);
      for (const auto& [i, j] : bound_indices(axis.size(), m.brick)) {
        const double lo = std::min(axis.values[i], axis.values[j]);
        const double hi = std::max(axis.values[i], axis.values[j]);
        const double step = std::fabs(axis.values[1] - axis.values[0]) * 1e-6;
        auto volume = [&](double l, double h) {
          const std::string json = fmt::format(
              R"({{"time": 0, "subvolumes": [{{"id": 2, "limits": [{}],
                  "domain": {{"{}": [{}, {}]}}}}]}})",
              sc.limit, axis.name, number(l), number(h));
          const ResolvedScene scene = resolve_scene(parse_scene(json, "box"), m, "box");
          LevelExtractionOptions o;
          o.threads = 2;
          return enclosed_volume(seamless_union(extract_level(*sc.store, scene, o), 2));
        };
        const double on = volume(lo, hi), inside = volume(lo + step, hi - step);
        EXPECT_NEAR(on, inside, 1e-4 * std::fabs(inside))
            << sc.name << ": " << axis.name << " in [" << lo << ", " << hi << "]";
      }
    }
  }
}

}  // namespace
}  // namespace strielad
